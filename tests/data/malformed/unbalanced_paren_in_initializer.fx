// A missing ')' in a parameter initializer.
float Scale = (1.0 + (2.0 * 3.0);
