// Exists, but includes a file that does not.
float Helper = 1;
#include "gone.fxh"
