// A parameter without its ';': reported after its value; the next one is still declared, so nothing
// follows from it.
float Bias = 0.01
float Other = 1;
float4 VS(float4 p : POSITION) : POSITION { return p * Other; }
float4 PS() : COLOR { return Bias; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
