// A geometry-shader profile compiled for the pixel stage.
float4 VS(float3 p : POSITION) : SV_Position { return float4(p, 1); }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(gs_5_0, PS())); } }
