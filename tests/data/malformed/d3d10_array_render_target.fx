// A texture array as a render target: RenderColorTarget0 has no way to choose the element drawn into.
Texture2DArray Layers : RENDERCOLORTARGET < int ArraySize = 4; >;
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS() : SV_Target { return 1; }
technique11 T { pass p < string Script = "RenderColorTarget0=Layers; Draw=Buffer;"; >
{ SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
