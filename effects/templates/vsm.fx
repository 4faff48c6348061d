// $NAME.fx: a shadow technique of your own, started from shadowfx's `vsm` skeleton
// (`shadowfx new $NAME --from vsm`): a filterable map — the moments (z, z^2) of light depth, blurred by a
// separable box filter — and the Chebyshev bound of variance shadow maps (Donnelly & Lauritzen 2006) as
// the receiver's test. Put what your map stores in MapPS and how a receiver reads it in ShadowFactor: any
// method whose map can be blurred (exponential, moment or convolution maps) fits this frame.
//
// The loop, from this folder (docs/authoring.md):
//   shadowfx render $NAME.fx --scene teapot --out $NAME.png
//   shadowfx check $NAME.fx --update          golden images, written to golden/$NAME/ beside this file
//   shadowfx check $NAME.fx                   renders, the expectations below, the goldens
//   shadowfx bench --effects $NAME.fx --scenes dual-l,teapot --out bench
//   shadowfx stress $NAME.fx --reduced
//
// Measurement hooks (docs/scoring.md): SHADOWFX_SHADOW_MAP_SIZE sets the map's size, and under
// SHADOWFX_VISIBILITY the scene pass writes the shadow factor instead of the shaded colour
// (ShadeOrVisibility). The headers come from the effect library (docs/effect-library/README.md). The map
// is blurred every frame, so bench's steady state equals its full cost (docs/scoring.md).

#include "include/lighting.fxh"
#include "include/shadowmap.fxh"
#include "include/vsm.fxh"
#include "include/blur.fxh"
#include "include/shadowscene.fxh"

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

// [SECTION] Tweakables (sliders in `shadowfx view`; `--set BlurTaps=9` in render, bench and check)
int BlurTaps
<
    string UIWidget = "slider";
    string UIName = "Blur width (texels, odd)";
    int UIMin = 1;
    int UIMax = 31;
    int UIStep = 2;
> = 5;

float LightBleedReduction
<
    string UIWidget = "slider";
    string UIName = "Light-bleeding reduction";
    float UIMin = 0.0;
    float UIMax = 0.9;
    float UIStep = 0.05;
> = 0.3;

float MinVariance
<
    string UIWidget = "slider";
    string UIName = "Minimum variance";
    float UIMin = 0.0;
    float UIMax = 0.0001;
    float UIStep = 0.000001;
> = 0.00002;

float2 ShadowMapSize <string UIWidget = "none";> = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};

// [SECTION] Textures and samplers
// The map and the blur's intermediate target: two float channels, cleared to NoOccluder (depth 1).
texture Map : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "G32R32F";
    string UIWidget = "None";
>;

texture MapTemp : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "G32R32F";
    string UIWidget = "None";
>;

// The map pass's depth buffer, also bound (untested) by the blur passes: attachments share the map's size.
texture ShadowDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

// The receivers read the map filtered; the blur reads texel centres exactly.
sampler MapSampler = sampler_state
{
    Texture = <Map>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
};

sampler MapPointSampler = sampler_state
{
    Texture = <Map>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

sampler MapTempSampler = sampler_state
{
    Texture = <MapTemp>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

// [SECTION] Shaders
// What a map texel stores: here the two moments of the light depth z/w.
float4 MapPS(DepthVertexOutput IN) : COLOR
{
    return float4(DepthMoments(LightDepth(IN)), 0, 1);
}

float4 BlurXPS(BufferVertex IN) : COLOR
{
    return BoxBlur(MapPointSampler, IN.UV, float2(1.0 / ShadowMapSize.x, 0), BlurTaps);
}

float4 BlurYPS(BufferVertex IN) : COLOR
{
    return BoxBlur(MapTempSampler, IN.UV, float2(0, 1.0 / ShadowMapSize.y), BlurTaps);
}

// The shadow factor: 1 lit, 0 shadowed, between for partly lit. A pixel counts as shadowed below 0.5.
float ShadowFactor(SceneVertexOutput IN)
{
    float2 moments = tex2D(MapSampler, ShadowMapUV(IN.LP)).xy;
    return VarianceShadow(moments, IN.LP.z / IN.LP.w, MinVariance, LightBleedReduction);
}

float4 ScenePS(SceneVertexOutput IN) : COLOR
{
    return ShadeOrVisibility(IN, ShadowFactor(IN));
}

// [SECTION] Technique
technique main
<
    string Script = "Pass=RenderMap; Pass=BlurX; Pass=BlurY; Pass=RenderScene;";
    // Bounds for `shadowfx check` (docs/scoring.md): loose to start with. Run `shadowfx check $NAME.fx`,
    // read the measured values from its table, and set each bound at about 1.5x the larger one.
    // As written the skeleton measures 0.050 % on dual-l, 0.098 % on teapot (320x240, 1024² map, llvmpipe).
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.5;  // % of receiver pixels against the hard-shadow truth
    int ExpectMapSize = 1024;
    // Cases of `shadowfx stress` that are a known limitation of the method, with the reason.
    string StressExpectedFailures = "light-behind-viewer [ordinary, uniform]: uniform map, perspective "
                                    "aliasing; fov-1 [ordinary, uniform]: the blur widens shadows by its "
                                    "kernel, and a texel spans 33 pixels under a 1 degree lens";
>
{
    pass RenderMap
    <
        string Script = "RenderColorTarget0=Map;"
                        "RenderDepthStencilTarget=ShadowDepth;"
                        "RenderPort=light0;"
                        "ClearSetColor=NoOccluder;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = None;
        ZEnable = true;
        ZWriteEnable = true;
        VertexShader = compile vs_3_0 RenderDepthVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix)));
        PixelShader = compile ps_3_0 MapPS();
    }

    pass BlurX
    <
        string Script = "RenderColorTarget0=MapTemp;"
                        "RenderDepthStencilTarget=ShadowDepth;"
                        "RenderPort=light0;"
                        "Draw=Buffer;";
    >
    {
        CullMode = None;
        ZEnable = false;
        ZWriteEnable = false;
        VertexShader = compile vs_3_0 BufferVS();
        PixelShader = compile ps_3_0 BlurXPS();
    }

    pass BlurY
    <
        string Script = "RenderColorTarget0=Map;"
                        "RenderDepthStencilTarget=ShadowDepth;"
                        "RenderPort=light0;"
                        "Draw=Buffer;";
    >
    {
        CullMode = None;
        ZEnable = false;
        ZWriteEnable = false;
        VertexShader = compile vs_3_0 BufferVS();
        PixelShader = compile ps_3_0 BlurYPS();
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
        PixelShader = compile ps_3_0 ScenePS();
    }
}
