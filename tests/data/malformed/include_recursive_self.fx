// The file includes itself.
#include "include_recursive_self.fx"
float Bias = 0.01;
