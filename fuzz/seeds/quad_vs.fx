// A fuzzing seed of the D3D10 post-processing forms: vertex shaders that hand the screen quad's position
// through (whole, by a constructor, a component at a time), one that transforms it, an untyped D3D9
// sampler read by texCUBE through a pass-through skybox.
Texture2D g_txScene;
SamplerState PointSampler { Filter = MIN_MAG_MIP_POINT; AddressU = Clamp; AddressV = Clamp; };
float4x4 g_mWorldViewProj;
texture g_EnvironmentTexture;
sampler EnvironmentSampler = sampler_state { Texture = (g_EnvironmentTexture); MinFilter = POINT; };
struct QuadIn { float3 Pos : POSITION; float2 Tex : TEXCOORD0; };
struct QuadOut { float4 Pos : SV_POSITION; float2 Tex : TEXCOORD0; };
QuadOut QuadVS(QuadIn I) {
    QuadOut O = (QuadOut)0;
    O.Pos.x = I.Pos.x;
    O.Pos.y = I.Pos.y;
    O.Pos.zw = float2(0.5, 1);
    O.Tex = I.Tex;
    return O;
}
QuadOut WideVS(QuadIn I) {
    QuadOut O;
    O.Pos = float4(I.Pos, 1);
    O.Tex = I.Tex;
    return O;
}
QuadOut SceneVS(QuadIn I) {
    QuadOut O;
    O.Pos = mul(float4(I.Pos, 1), g_mWorldViewProj);
    O.Tex = I.Tex;
    return O;
}
float4 GreyPS(QuadOut I) : SV_Target {
    return dot(g_txScene.Sample(PointSampler, I.Tex).rgb, float3(0.3, 0.59, 0.11)).xxxx;
}
float4 SkyboxVS(float4 Pos : POSITION, out float3 Dir : TEXCOORD0) : POSITION {
    Dir = Pos.xyz;
    return Pos;
}
float4 SkyboxPS(float3 Dir : TEXCOORD0) : COLOR { return texCUBE(EnvironmentSampler, Dir); }
technique10 Grey {
    pass p0 {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, GreyPS()));
    }
}
technique10 Wide {
    pass p0 {
        SetVertexShader(CompileShader(vs_4_0, WideVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, GreyPS()));
    }
}
technique10 Scene {
    pass p0 {
        SetVertexShader(CompileShader(vs_4_0, SceneVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, GreyPS()));
    }
}
technique Skybox { pass p0 { VertexShader = compile vs_2_0 SkyboxVS(); PixelShader = compile ps_2_0 SkyboxPS(); } }
