// A uniform argument naming nothing.
float4 VS(float4 p : POSITION, uniform float scale) : POSITION { return p * scale; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(NoSuchParameter); PixelShader = compile ps_3_0 PS(); } }
