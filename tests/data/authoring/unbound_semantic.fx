// A parameter whose semantic no part of shadowfx binds (test_cli.cpp): it keeps its default value.
float4x4 WorldViewProjection : WorldViewProjection;
float4 MapSize : ShadowMapDimensions = {1024, 1024, 0, 0};
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR { return float4(MapSize.x / 2048.0, 0.5, 0.5, 1); }
technique main { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
