// vs_9_9 is not a shader profile.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_9_9 VS(); PixelShader = compile ps_3_0 PS(); } }
