float fromDisk : DISK;
#include "sub/inner.fxh"
