// Later HLSL in one pass: register/packoffset bindings, row_major, view variables, static const arrays,
// interpolation modifiers, SV_VertexID, Gather/Load, asuint, [unroll]/[branch], two render targets.
cbuffer cbPerFrame : register(b0) { row_major float4x4 gWorldViewProj : packoffset(c0); float4 gParams : packoffset(c4); };
RenderTargetView g_rtv;
DepthStencilView g_dsv;
Texture2D gTex : register(t0);
SamplerState gPoint : register(s0) { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };
static const int2 kOffsets[4] = { int2(0,0), int2(1,0), int2(0,1), int2(1,1) };
struct VSOut { float4 pos : SV_Position; nointerpolation uint id : ID; noperspective float2 uv : TEXCOORD0; linear centroid float3 n : NORMAL; };
VSOut VS(float3 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0, uint vid : SV_VertexID)
{
    VSOut o;
    o.pos = mul(float4(p, 1), gWorldViewProj);
    o.id = vid;
    o.uv = uv;
    o.n = n;
    return o;
}
struct PSOut { float4 c0 : SV_Target0; float4 c1 : SV_Target1; };
PSOut PS(VSOut i, bool front : SV_IsFrontFace)
{
    PSOut o;
    float4 g = gTex.GatherRed(gPoint, i.uv);
    float v = 0;
    [unroll] for (int k = 0; k < 4; ++k) v += gTex.Load(int3(kOffsets[k], 0)).r;
    uint bits = asuint(v) ^ (i.id & 7u);
    [branch] if (front) o.c0 = float4(saturate(normalize(i.n) * 0.5 + 0.5), 1);
    else o.c0 = float4(1, 0, 0, 1);
    o.c0.rgb *= (bits != 0u) ? 1.0 : 0.5;
    o.c1 = g;
    return o;
}
BlendState NoBlend { BlendEnable[0] = FALSE; };
technique11 Main < string Description = "mixed HLSL"; >
{
    pass P0 < string Info = "x"; >
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(NULL);
        SetDomainShader(NULL);
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, PS()));
        SetBlendState(NoBlend, float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetDepthStencilState(NULL, 0);
        SetRasterizerState(NULL);
    }
}
