// thesis_fxcomposer.fx: the shadow-mapping effect of Lehőcz's thesis (Lehőcz 2007, "Forráskódok"), written
// for shadowfx in the form of that FX Composer 1.8 listing, which reached us with page-break damage.
//
// Technique `main` follows the listing: a float render target is cleared to ZMaxValue, the shadow map is
// rendered from light0 into it with BlendOp=min (no depth buffer: the blend keeps the nearest occluder),
// then the scene is rendered with the shadow test. `PCF` switches to bilinear percentage-closer filtering
// and `JITTER` adds the listing's noise-texture jitter. Technique `hardware` renders a depth target instead
// and samples it with depth comparison, as NVIDIA's D3D9 hardware shadow maps did. Technique `main11` is
// `main` in Direct3D 11's form (docs/d3d10.md): the runtime's matrices in a cbuffer, the maps Texture2Ds
// read with `.Sample` through SamplerStates, the pass states from state objects; it renders the same image.
//
// Depth conventions: the light's projection maps the scene into clip depth [0, 1]; the shadow map stores
// that depth times ZMaxValue (the listing's fixed-range scaling, with ShadowRange = 1 for this range).
//
// Measurement hooks (docs/scoring.md, "Measurement hooks"): SHADOWFX_SHADOW_MAP_SIZE overrides the shadow
// map's size, and SHADOWFX_VISIBILITY makes the scene passes write the shadow factor (1 lit, 0 shadowed)
// instead of the shaded colour, for `shadowfx bench`'s comparison with the ray-cast ground truth.

#include "include/lighting.fxh"
#include "include/shadowmap.fxh"

#define ZMaxValue 130944/16.0
#define ShadowRange 1.0
#define ShadowRangeMultiplier (ZMaxValue/ShadowRange)
#ifdef SHADOWFX_SHADOW_MAP_SIZE
#define SHADOW_MAP_SIZE SHADOWFX_SHADOW_MAP_SIZE
#else
#define SHADOW_MAP_SIZE 1024
#endif

float Script : STANDARDSGLOBAL
<
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=main;";
> = 0.8;

// [SECTION] Tweakables
bool JITTER
<
    string UIName = "Jittered lookups";
> = false;

bool PCF
<
    string UIName = "Bilinear PCF";
> = false;

float Bias
<
    string UIWidget = "slider";
    string UIName = "Depth bias";
    float UIMin = 0.0;
    float UIMax = 0.05;
    float UIStep = 0.0005;
> = 0.004;

float JITTER_AMOUNT
<
    string UIWidget = "slider";
    float UIMin = 0.0;
    float UIMax = 4.0;
> = 1.0;

float SpecularPower
<
    string UIWidget = "slider";
    float UIMin = 1.0;
    float UIMax = 128.0;
> = 32.0;

float SpecularFactor = 0.4;

float4 ClearColor
<
    string UIWidget = "color";
> = {0.32, 0.36, 0.42, 1.0};

float ClearDepth
<
    string UIWidget = "none";
> = 1.0;

float4 ShadowClearColor
<
    string UIWidget = "none";
> = {ZMaxValue, ZMaxValue, ZMaxValue, ZMaxValue};

float2 SHADOW_SIZE
<
    string UIWidget = "none";
> = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};

// [SECTION] Matrices and lights bound by the runtime
// A cbuffer for the D3D11 form; its members are parameters like any other, for the D3D9 techniques too.
cbuffer RuntimeMatrices
{
    float4x4 WorldITMatrix : WorldInverseTranspose <string UIWidget = "None";>;
    float4x4 WorldViewProjectionMatrix : WorldViewProjection <string UIWidget = "None";>;
    float4x4 WorldMatrix : World <string UIWidget = "None";>;
    float4x4 ViewIMatrix : ViewInverse <string UIWidget = "None";>;

    float4x4 LightViewMatrix : View
    <
        string frustum = "light0";
    >;

    float4x4 LightProjectionMatrix : Projection
    <
        string frustum = "light0";
    >;
};

float3 LightColor : LightColor
<
    string Object = "light0";
    string UIWidget = "none";
> = {1.0, 1.0, 1.0};

float3 AmbientLightColor : Ambient
<
    string UIWidget = "color";
> = {0.15, 0.15, 0.15};

float3 SurfaceColor : Diffuse
<
    string UIWidget = "none";
> = {0.8, 0.8, 0.8};

// [SECTION] Textures and samplers
Texture2D ShadowMap : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R32F";
    string UIWidget = "None";
>;

sampler ShadowMapSampler = sampler_state
{
    texture = <ShadowMap>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

texture ShadDepthTarget : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

sampler ShadowDepthSampler = sampler_state
{
    Texture = <ShadDepthTarget>;
    AddressU = Clamp;
    AddressV = Clamp;
    MinFilter = Linear;
    MagFilter = Linear;
    MipFilter = None;
};

Texture2D NoiseTexture : noise;

sampler NoiseSampler = sampler_state
{
    texture = <NoiseTexture>;
    AddressU = WRAP;
    AddressV = WRAP;
    MIPFILTER = NONE;
    MINFILTER = LINEAR;
    MAGFILTER = LINEAR;
};

// The same samplers for the D3D11 form, which samples a texture through a separate sampler object.
// D3D11 has no "no mip filter": a point mip filter with MaxLOD 0 reads level 0, as MipFilter = NONE does.
SamplerState ShadowMapPoint
{
    Filter = MIN_MAG_MIP_POINT;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MaxLOD = 0;
};

SamplerState NoiseWrap
{
    Filter = MIN_MAG_LINEAR_MIP_POINT;
    AddressU = WRAP;
    AddressV = WRAP;
    MaxLOD = 0;
};

// `main`'s pass states as D3D10 state objects: the shadow map keeps the nearest occluder by blending with
// min, without a depth buffer; the scene pass culls back faces (D3D10's default) and tests LESS_EQUAL.
RasterizerState NoCulling { CullMode = NONE; };
BlendState KeepNearest
{
    BlendEnable[0] = TRUE;
    SrcBlend = ONE;
    DestBlend = ONE;
    BlendOp = MIN;
    SrcBlendAlpha = ONE;
    DestBlendAlpha = ONE;
    BlendOpAlpha = MIN;
};
DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
DepthStencilState DepthLessEqual { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = LESS_EQUAL; };

// [SECTION] Shaders
struct VertexFormat
{
    float4 Position : POSITION;
    float4 UV       : TEXCOORD0;
    float3 Normal   : NORMAL;
};

struct RenderShadowMapVertexOutput
{
    float4 Position : POSITION;
    float2 ZW       : TEXCOORD0;
};

RenderShadowMapVertexOutput RenderShadowMapVS(VertexFormat IN, uniform float4x4 WorldLightViewProjection)
{
    RenderShadowMapVertexOutput OUT;
    float4 LightSpacePosition = mul(float4(IN.Position.xyz, 1.0), WorldLightViewProjection);
    OUT.Position = LightSpacePosition;
    // Depth in [0, 1] is z/w. The listing stored z alone, which is the same for its directional light
    // (w = 1) but runs up to the far distance for a spot light's perspective, past the cleared ZMaxValue:
    // everything beyond z = 1 came out shadowed (found by `shadowfx stress`, case spot-inside-bounds).
    // The division happens per pixel: z/w does not interpolate linearly.
    OUT.ZW = LightSpacePosition.zw;
    return OUT;
}

float4 RenderShadowMapPS(RenderShadowMapVertexOutput IN) : COLOR
{
    return float4(IN.ZW.x / IN.ZW.y * ShadowRangeMultiplier, 1, 1, 1);
}

struct VertexOutput
{
    float4 HPosition : POSITION;
    float3 LightVec  : TEXCOORD0;
    float3 WNormal   : TEXCOORD1;
    float3 WView     : TEXCOORD2;
    float4 LP        : TEXCOORD3;
    float2 UV        : TEXCOORD4;
};

VertexOutput RenderSceneVS(VertexFormat IN, uniform float4x4 ShadowViewProjectionMatrix)
{
    VertexOutput OUT;
    float4 Pos = float4(IN.Position.xyz, 1.0);
    float4 Pw = mul(Pos, WorldMatrix);
    OUT.WNormal = mul(IN.Normal, (float3x3)WorldITMatrix);
    OUT.LP = mul(Pw, ShadowViewProjectionMatrix);  // "P" in light coords, for the pixel shader's test
    OUT.WView = normalize(ViewIMatrix[3].xyz - Pw.xyz);
    OUT.HPosition = mul(Pos, WorldViewProjectionMatrix);
    // The light looks along its view's z axis: the third column of a row-vector view matrix.
    OUT.LightVec = float3(-LightViewMatrix._13, -LightViewMatrix._23, -LightViewMatrix._33);
    OUT.UV = IN.UV.xy;
    return OUT;
}

// The listing's lookup: the shadow-map position and the depth compared there, both jittered by `noise`
// under JITTER.
float3 ShadowLookup(float4 LP, float4 noise)
{
    float2 nuv = ShadowMapUV(LP);
    if (JITTER)
        nuv += JITTER_AMOUNT * (0.5 - noise.xy) / SHADOW_SIZE;

    float depth = (LP.z / LP.w / ShadowRange - Bias) * ZMaxValue;
    if (JITTER)
        depth -= (noise.z - 0.5) * 0.001 * ShadowRangeMultiplier;
    return float3(nuv, depth);
}

float GetShadow(float4 LP)
{
    float3 lookup = ShadowLookup(LP, tex2D(NoiseSampler, LP.xy * 64));
    if (PCF)
        return ShadowTestBilinear(ShadowMapSampler, lookup.xy, lookup.z, SHADOW_SIZE);
    return ShadowTest(ShadowMapSampler, lookup.xy, lookup.z);
}

// GetShadow in the D3D11 form: Texture2D.Sample through SamplerStates.
float GetShadow11(float4 LP)
{
    float3 lookup = ShadowLookup(LP, NoiseTexture.Sample(NoiseWrap, LP.xy * 64));
    if (PCF)
        return ShadowTestBilinear(ShadowMap, ShadowMapPoint, lookup.xy, lookup.z, SHADOW_SIZE);
    return ShadowTest(ShadowMap, ShadowMapPoint, lookup.xy, lookup.z);
}

float4 Shade(VertexOutput IN, float shadowed)
{
    float3 N = normalize(IN.WNormal);
    float3 V = normalize(IN.WView);
    float3 L = normalize(IN.LightVec);
    float4 terms = BlinnPhongTerms(N, V, L, SpecularPower);

    float3 ambient = SurfaceColor * AmbientLightColor;
    float3 diffuse = terms.y * SurfaceColor * LightColor;
    float3 specular = terms.z * SpecularFactor * LightColor;
    if (JITTER)  // the listing fades the shadow out where the surface turns away from the light
        shadowed *= 1 - max((1 - terms.y) - 0.8, 0) * 5;
    return float4(shadowed * (diffuse + specular) + ambient, 1);
}

float4 RenderScenePS(VertexOutput IN) : COLOR
{
#ifdef SHADOWFX_VISIBILITY
    return float4(GetShadow(IN.LP).xxx, 1);
#else
    return Shade(IN, GetShadow(IN.LP));
#endif
}

float4 RenderScene11PS(VertexOutput IN) : SV_Target
{
#ifdef SHADOWFX_VISIBILITY
    return float4(GetShadow11(IN.LP).xxx, 1);
#else
    return Shade(IN, GetShadow11(IN.LP));
#endif
}

// Hardware shadow map: tex2Dproj on a depth target returns the filtered depth comparison.
float4 RenderSceneHardwarePS(VertexOutput IN) : COLOR
{
    float4 lp = IN.LP;
    float2 uv = ShadowMapUV(lp);
    float4 coord = float4(uv * lp.w, lp.z - Bias * lp.w, lp.w);
#ifdef SHADOWFX_VISIBILITY
    return float4(tex2Dproj(ShadowDepthSampler, coord).xxx, 1);
#else
    return Shade(IN, tex2Dproj(ShadowDepthSampler, coord).x);
#endif
}

// [SECTION] Techniques
technique main
<
    // Conformance (shadowfx check, docs/measurement.md, "shadowfx check"): measured at 320x240 with a 1024²
    // map on llvmpipe, 0.057 % misclassified on dual-l and 0.076 % on teapot; bound 1.5x the teapot's 0.063 %
    // against the truth before its rays started along themselves (docs/scoring.md, "The ground truth").
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.095;
    int ExpectMapSize = 1024;
    string Script = "Pass=ClearShadowMap;"
                    "Pass=RenderShadowMap;"
                    "Pass=RenderScene;";
    // Known limitation `shadowfx stress` reports as xfail (docs/measurement.md, "shadowfx stress"): the
    // listing's constant bias cannot follow the ground's depth slope under a sun 0.5 degrees high (Lehőcz
    // 2007, "Slope-scale bias"). It stays as the thesis wrote it: this is the thesis's technique, and the
    // uniform map every method is held to.
    string StressExpectedFailures = "grazing [ordinary]: the thesis's constant bias as published (the "
                                    "uniform map every method is held to): a 0.5 degree sun's ground slopes "
                                    "away from it within a texel, acne";
>
{
    pass ClearShadowMap
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=ShadDepthTarget;"
                        "RenderPort=light0;"
                        "ClearSetColor=ShadowClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;";
    >
    {
    }

    pass RenderShadowMap
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=ShadDepthTarget;"
                        "RenderPort=light0;"
                        "Draw=geometry;";
    >
    {
        CullMode = None;
        AlphaBlendEnable = true;
        SrcBlend = one;
        DestBlend = one;
        BlendOp = min;
        ZEnable = false;
        ZWriteEnable = false;

        VertexShader = compile vs_3_0 RenderShadowMapVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix)));
        PixelShader = compile ps_3_0 RenderShadowMapPS();
    }

    pass RenderScene
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = CCW;
        AlphaBlendEnable = false;
        ZEnable = true;
        ZWriteEnable = true;
        ZFunc = LessEqual;

        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));
        PixelShader = compile ps_3_0 RenderScenePS();
    }
}

technique11 main11
<
    // `main` in the D3D11 form renders the same image: the same expectations and known limitations.
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.095;
    int ExpectMapSize = 1024;
    string Script = "Pass=ClearShadowMap;"
                    "Pass=RenderShadowMap;"
                    "Pass=RenderScene;";
    string StressExpectedFailures = "grazing [ordinary]: the thesis's constant bias as published (the "
                                    "uniform map every method is held to): a 0.5 degree sun's ground slopes "
                                    "away from it within a texel, acne";
>
{
    pass ClearShadowMap
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=ShadDepthTarget;"
                        "RenderPort=light0;"
                        "ClearSetColor=ShadowClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;";
    >
    {
    }

    pass RenderShadowMap
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=ShadDepthTarget;"
                        "RenderPort=light0;"
                        "Draw=geometry;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, RenderShadowMapVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix)))));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, RenderShadowMapPS()));
        SetRasterizerState(NoCulling);
        SetBlendState(KeepNearest, float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetDepthStencilState(NoDepth, 0);
    }

    pass RenderScene
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix))));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, RenderScene11PS()));
        SetBlendState(NULL, float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetDepthStencilState(DepthLessEqual, 0);  // and D3D10's default rasterizer state: back faces culled
    }
}

technique hardware
<
    // Conformance: measured at 320x240 with a 1024² map on llvmpipe, 0.018 % misclassified on dual-l and
    // 0.049 % on teapot; bound 1.5x the larger.
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.075;
    int ExpectMapSize = 1024;
    string Script = "Pass=RenderShadowDepth;"
                    "Pass=RenderScene;";
    // Known limitation `shadowfx stress` reports as xfail (docs/measurement.md, "shadowfx stress"): the
    // listing's constant bias cannot follow the ground's depth slope under a sun 0.5 degrees high (Lehőcz
    // 2007, "Slope-scale bias"). It stays as the thesis wrote it: this is the thesis's technique, and the
    // uniform map every method is held to.
    string StressExpectedFailures = "grazing [ordinary]: the thesis's constant bias as published, compared "
                                    "in hardware: a 0.5 degree sun's ground slopes away from it within a "
                                    "texel, acne";
>
{
    pass RenderShadowDepth
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=ShadDepthTarget;"
                        "RenderPort=light0;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = None;
        ZEnable = true;
        ZWriteEnable = true;
        ColorWriteEnable = 0;

        VertexShader = compile vs_3_0 RenderShadowMapVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix)));
        PixelShader = compile ps_3_0 RenderShadowMapPS();
    }

    pass RenderScene
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = CCW;
        ZEnable = true;
        ZWriteEnable = true;

        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));
        PixelShader = compile ps_3_0 RenderSceneHardwarePS();
    }
}
