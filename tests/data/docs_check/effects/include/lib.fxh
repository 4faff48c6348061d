// lib.fxh: one documented name, one not.
#ifndef SHADOWFX_LIB_FXH
#define SHADOWFX_LIB_FXH
float Documented(float x) { return x; }
float Undocumented(float x) { return x; }
#endif
