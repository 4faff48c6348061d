// A function-like macro with a broken parameter list.
#define SCALE(a, 2.0 * a
float Bias = SCALE(1);
