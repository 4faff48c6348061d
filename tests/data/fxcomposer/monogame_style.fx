// An effect in the style of MonoGame's stock effects built for Direct3D 11: textures and samplers declared
// through macros (a `sampler` without sampler_state, sampled by the texture object), indexed system-value
// semantics, ColorWriteEnable with MonoGame's values, and a technique for the DXC-era profiles.
#define DECLARE_TEXTURE(Name, index) \
    Texture2D<float4> Name : register(t##index); \
    sampler Name##Sampler : register(s##index)
#define SAMPLE_TEXTURE(Name, texCoord) Name.Sample(Name##Sampler, texCoord)

DECLARE_TEXTURE(Texture, 0);

cbuffer Parameters : register(b0)
{
    float4x4 WorldViewProj : WORLDVIEWPROJECTION;
    float4x4 World : WORLD;
};

struct VSOutput
{
    float4 PositionPS : SV_Position0;
    float3 Normal : TEXCOORD0;
    float2 TexCoord : TEXCOORD1;
};

VSOutput VSBasic(float4 position : SV_Position0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VSOutput o;
    o.PositionPS = mul(position, WorldViewProj);
    o.Normal = mul(normal, (float3x3)World);
    o.TexCoord = texCoord;
    return o;
}

float4 PSBasic(VSOutput i) : SV_Target0
{
    float3 n = normalize(i.Normal);
    float3 light = float3(1.0, 0.55, 0.25) * saturate(dot(n, normalize(float3(0.5, 1.0, 0.3)))) +
                   float3(0.15, 0.45, 1.0) * saturate(dot(n, normalize(float3(-0.6, 0.2, -0.8))));
    return SAMPLE_TEXTURE(Texture, i.TexCoord) * float4(light + 0.05, 1);
}

technique BasicEffect
{
    pass
    {
        VertexShader = compile vs_4_0 VSBasic();
        PixelShader = compile ps_4_0 PSBasic();
        ColorWriteEnable = true;
    }
}

technique BasicEffect_SM6
{
    pass
    {
        VertexShader = compile vs_6_0 VSBasic();
        PixelShader = compile ps_6_0 PSBasic();
        ColorWriteEnable = All;
    }
}
