// The entry point names a parameter.
float Bias = 0.01;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 Bias(); PixelShader = compile ps_3_0 PS(); } }
