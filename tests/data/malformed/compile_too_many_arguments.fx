// More arguments than uniform parameters.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(1, 2); PixelShader = compile ps_3_0 PS(); } }
