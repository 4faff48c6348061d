// A sampler whose Texture names nothing.
sampler S = sampler_state { Texture = <NoSuchTexture>; };
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
