// The include below does not exist.
#include "include/does_not_exist.fxh"
float4 PS() : COLOR { return 1; }
