// A missing ')' in a function body.
float4 VS(float4 p : POSITION) : POSITION { return mul(p, float4x4(1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1); }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
