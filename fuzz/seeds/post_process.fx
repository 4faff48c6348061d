// A fuzzing seed of the D3D9 post-processing forms: passes with a pixel shader alone (the full-screen
// quad), whose samplers the effect gives no texture (a texture without contents, a bare sampler, a pass's
// `Texture[0] = <t>;`) or a texture of its own.
texture g_txSrcColor;
texture g_txBlurred < string Procedural = "noise"; >;
sampler2D g_samSrcColor = sampler_state { Texture = <g_txSrcColor>; MinFilter = Point; MagFilter = Point; };
sampler2D g_samBlurred = sampler_state { Texture = <g_txBlurred>; AddressU = Clamp; AddressV = Clamp; };
sampler2D Sprite : register(s1);
float2 TexelKernel[4] = { { 0, -1.5 }, { 0, -0.5 }, { 0, 0.5 }, { 0, 1.5 } };
float4 BlurPS(float2 uv : TEXCOORD0) : COLOR0 {
    float4 sum = 0;
    for (int i = 0; i < 4; i++) sum += tex2D(g_samSrcColor, uv + TexelKernel[i] / 512.0);
    return sum / 4;
}
float4 CombinePS(float2 uv : TEXCOORD0, float2 uv1 : TEXCOORD1) : COLOR0 {
    return lerp(tex2D(g_samSrcColor, uv), tex2D(g_samBlurred, uv1), 0.5) * tex2D(Sprite, uv).a;
}
technique PostProcess {
    pass Blur { VertexShader = null; PixelShader = compile ps_2_0 BlurPS(); ZEnable = false; }
    pass Combine { PixelShader = compile ps_2_0 CombinePS(); Texture[1] = <g_txBlurred>; MinFilter[1] = Linear; }
}
