// Includes mutual_a.fxh, closing the cycle.
#include "mutual_a.fxh"
float FromB = 1;
