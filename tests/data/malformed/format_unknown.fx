// A format D3D9 does not have.
texture Map : RENDERCOLORTARGET < float2 Dimensions = {256, 256}; string Format = "R7G7B7"; >;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
