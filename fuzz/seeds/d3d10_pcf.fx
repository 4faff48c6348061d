// Fuzz seed in the style of D3D10 effects (fx_4_0): technique10, SetVertexShader(CompileShader(...)),
// SetGeometryShader(NULL), SV_ semantics, [unroll] loops, integer loop counters. The shadow map is a DX9
// sampler (what the effect compiler lowers); a Texture2D object would stop at the compile.
float4x4 g_mWorldViewProjection : WorldViewProjection;
float4x4 g_mWorld : World;
float4x4 g_mLightViewProj;
float3 g_vLightDir = {0.3, -1.0, 0.2};
float g_fDepthBias = 0.002;

texture g_txShadow : RENDERCOLORTARGET < float2 Dimensions = {1024, 1024}; string Format = "r32f"; >;
sampler2D g_samShadow = sampler_state {
    Texture = <g_txShadow>;
    AddressU = Clamp;
    AddressV = Clamp;
    MinFilter = Point;
    MagFilter = Point;
};

struct VS_INPUT {
    float4 Position : POSITION;
    float3 Normal : NORMAL;
    float2 TexCoord : TEXCOORD0;
};

struct VS_OUTPUT {
    float4 Position : SV_Position;
    float3 Normal : TEXCOORD0;
    float4 LightPos : TEXCOORD1;
};

VS_OUTPUT RenderSceneVS(VS_INPUT input) {
    VS_OUTPUT output;
    output.Position = mul(input.Position, g_mWorldViewProjection);
    output.Normal = normalize(mul(input.Normal, (float3x3)g_mWorld));
    output.LightPos = mul(mul(input.Position, g_mWorld), g_mLightViewProj);
    return output;
}

float4 RenderScenePS(VS_OUTPUT input) : SV_Target {
    float3 lp = input.LightPos.xyz / input.LightPos.w;
    float2 uv = lp.xy * float2(0.5, -0.5) + 0.5;
    float lit = 0;
    [unroll] for (int y = -1; y <= 1; ++y)
        [unroll] for (int x = -1; x <= 1; ++x)
            lit += (lp.z - g_fDepthBias) <= tex2Dlod(g_samShadow, float4(uv + float2(x, y) / 1024.0, 0, 0)).x;
    lit /= 9.0;
    float ndl = saturate(dot(normalize(input.Normal), -normalize(g_vLightDir)));
    return float4(lit * ndl.xxx + 0.1, 1);
}

float4 DepthVS(float4 pos : POSITION) : SV_Position {
    return mul(mul(pos, g_mWorld), g_mLightViewProj);
}

technique10 RenderScene {
    pass P0 {
        SetVertexShader(CompileShader(vs_4_0, RenderSceneVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, RenderScenePS()));
    }
}

technique10 RenderDepth {
    pass P0 {
        SetVertexShader(CompileShader(vs_4_0, DepthVS()));
        SetGeometryShader(NULL);
        SetPixelShader(NULL);
    }
}
