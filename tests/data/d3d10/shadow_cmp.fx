// An effect in Direct3D 11's form (what FX11 compiles with fx_5_0): hardware percentage-closer filtering,
// a depth target sampled through a SamplerComparisonState with SampleCmpLevelZero, the D3D10 way to do what
// the D3D9 `hardware` technique of effects/pcf.fx does with tex2Dproj on a depth sampler. Matrices and
// tweakables live in cbuffers and are bound by semantic; states come from state objects; the SAS scripts
// are those of a D3D9 technique (RenderPort=light0 renders the map from the light).

float Script : STANDARDSGLOBAL <
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=HardwarePcf;";
> = 0.8;

cbuffer PerObject : register(b0)
{
    float4x4 World : World;
    float4x4 WorldViewProjection : WorldViewProjection;
    float4x4 WorldInverseTranspose : WorldInverseTranspose;
};

cbuffer PerLight : register(b1)
{
    float4x4 LightView : View < string frustum = "light0"; >;
    float4x4 LightProjection : Projection < string frustum = "light0"; >;
    float3 LightColor : LightColor < string Object = "light0"; > = {1, 1, 1};
    float Bias < string UIName = "Depth bias"; float UIMin = 0; float UIMax = 0.02; > = 0.0005;
};

float4 ClearColor = {0.32, 0.36, 0.42, 1.0};
float ClearDepth = 1.0;
float4 NoOccluder = {1, 1, 1, 1};

Texture2D ShadowMap : RENDERCOLORTARGET < float2 Dimensions = {1024, 1024}; string Format = "R32F"; >;
Texture2D<float> ShadowDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {1024, 1024}; string Format = "D24S8"; >;

SamplerComparisonState ShadowCompare
{
    Filter = COMPARISON_MIN_MAG_LINEAR_MIP_POINT;
    AddressU = CLAMP;
    AddressV = CLAMP;
    ComparisonFunc = LESS_EQUAL;
};

// The shadow map's bias is the rasterizer's, as D3D10 shadow maps usually do it: a constant part in units of
// the smallest resolvable depth difference and a part that grows with the caster's depth slope.
RasterizerState ShadowCaster { CullMode = NONE; DepthBias = 4000; SlopeScaledDepthBias = 2.0; DepthBiasClamp = 0.01; };
DepthStencilState DepthLessEqual { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = LESS_EQUAL; };
BlendState Opaque { BlendEnable[0] = FALSE; RenderTargetWriteMask[0] = 0x0F; };

struct VertexInput
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
};

struct DepthOutput
{
    float4 Position : SV_Position;
    float2 Depth : LIGHTDEPTH;
};

DepthOutput DepthVS(VertexInput input)
{
    DepthOutput output;
    output.Position = mul(mul(float4(input.Position, 1), World), mul(LightView, LightProjection));
    output.Depth = output.Position.zw;
    return output;
}

float4 DepthPS(DepthOutput input) : SV_Target0
{
    return float4(input.Depth.x / input.Depth.y, 0, 0, 1);
}

struct SceneOutput
{
    float4 Position : SV_Position;
    float3 Normal : WORLDNORMAL;
    float4 LightClip : LIGHTCLIP;
};

SceneOutput SceneVS(VertexInput input)
{
    SceneOutput output;
    float4 world = mul(float4(input.Position, 1), World);
    output.Position = mul(float4(input.Position, 1), WorldViewProjection);
    output.Normal = mul(input.Normal, (float3x3)WorldInverseTranspose);
    output.LightClip = mul(world, mul(LightView, LightProjection));
    return output;
}

float4 ScenePS(SceneOutput input) : SV_Target
{
    float2 uv = float2(0.5, -0.5) * input.LightClip.xy / input.LightClip.w + 0.5;
    float depth = input.LightClip.z / input.LightClip.w - Bias;
    float lit = ShadowDepth.SampleCmpLevelZero(ShadowCompare, uv, depth);
#ifdef SHADOWFX_VISIBILITY
    return float4(lit, lit, lit, 1);
#else
    float3 toLight = float3(-LightView._13, -LightView._23, -LightView._33);
    float diffuse = saturate(dot(normalize(input.Normal), normalize(toLight)));
    return float4((0.15 + lit * diffuse) * LightColor * 0.8, 1);
#endif
}

technique11 HardwarePcf < string Script = "Pass=ShadowMap; Pass=Scene;"; >
{
    pass ShadowMap < string Script = "RenderColorTarget0=ShadowMap;"
                                     "RenderDepthStencilTarget=ShadowDepth;"
                                     "RenderPort=light0;"
                                     "ClearSetColor=NoOccluder;"
                                     "ClearSetDepth=ClearDepth;"
                                     "Clear=Color;"
                                     "Clear=Depth;"
                                     "Draw=Geometry;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, DepthVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, DepthPS()));
        SetRasterizerState(ShadowCaster);
        SetDepthStencilState(DepthLessEqual, 0);
        SetBlendState(Opaque, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Scene < string Script = "RenderColorTarget0=;"
                                 "RenderDepthStencilTarget=;"
                                 "RenderPort=;"
                                 "ClearSetColor=ClearColor;"
                                 "ClearSetDepth=ClearDepth;"
                                 "Clear=Color;"
                                 "Clear=Depth;"
                                 "Draw=Geometry;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, SceneVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, ScenePS()));
        SetRasterizerState(NULL);
        SetDepthStencilState(DepthLessEqual, 0);
        SetBlendState(Opaque, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
}
