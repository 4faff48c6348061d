// Includes mutual_b.fxh, which includes this file again.
#include "mutual_b.fxh"
float FromA = 1;
