// A state error inside a pass that a header's macro writes: the note names the header's line.
#include "include/passes.fxh"
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { SHADED_PASS }
