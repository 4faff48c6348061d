// A pass at the top level.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
pass p { VertexShader = compile vs_3_0 VS(); }
