// blurred_receivers.fx: blurred colour channels for receivers (Kozlov, GPU Gems ch. 14, §14.3.2 "Blurring",
// Kozlov 2004): "use the color part of the shadow map render ...
// clear the color buffer with 1 ... draw 0 into the color buffer for every object except the landscape; for
// the landscape, draw 1 ... Blur the picture severely, using multiple passes ... render the landscape with
// the blurred texture instead of the shadow map, and render all other objects with the depth part of the
// shadow map." Receivers that need no self-shadowing (ground planes, walls) get soft shadows from a blurred
// mask; "because we have several color channels, we can blur shadows on several objects at the same time".
//
// Here the map is A32B32G32R32F: R light clip depth z/w, G 1 where receiver ReceiverId0 is the nearest
// surface to the light, B the same for ReceiverId1 (ids from the ObjectId semantic, 1-based; 0 = none).
// G and B are blurred by a separable 9-tap Gaussian (sigma BlurRadiusTexels / 2) into a G16R16F target,
// once, then BlurLoops more times (LoopByCount, ping-pong); the map-sized depth target stays bound in the
// blur passes (effects/vsm.fx). Every other object gets bilinear PCF of the depth. The blur's width is
// fixed: it does not follow the occluder distance, as Kozlov 2004 says ("adjust the blurring radius").
// Measurement hooks SHADOWFX_SHADOW_MAP_SIZE, SHADOWFX_VISIBILITY (docs/scoring.md, "Measurement hooks").

#include "include/lighting.fxh"
#include "include/shadowmap.fxh"
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
    string Script = "Technique=blurred;";
> = 0.8;

// [SECTION] Tweakables
int ReceiverId0
<
    string UIWidget = "slider";
    string UIName = "Receiver in the first channel (object id, 0 = none)";
    int UIMin = 0;
    int UIMax = 64;
> = 1;

int ReceiverId1
<
    string UIWidget = "slider";
    string UIName = "Receiver in the second channel (object id, 0 = none)";
    int UIMin = 0;
    int UIMax = 64;
> = 0;

float BlurRadiusTexels
<
    string UIWidget = "slider";
    string UIName = "Blur radius (texels)";
    float UIMin = 0.5;
    float UIMax = 16.0;
> = 4.0;

int BlurLoops
<
    string UIWidget = "slider";
    string UIName = "Extra blur passes (x and y each)";
    int UIMin = 0;
    int UIMax = 8;
> = 1;

float Bias
<
    string UIWidget = "slider";
    string UIName = "Depth bias";
    float UIMin = 0.0;
    float UIMax = 0.02;
    float UIStep = 0.0002;
> = 0.002;

float SlopeBias
<
    string UIWidget = "slider";
    string UIName = "Slope bias per texel";
    float UIMin = 0.0;
    float UIMax = 4.0;
> = 1.0;

float2 ShadowMapSize <string UIWidget = "none";> = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
float ObjectIndex : ObjectId <string UIWidget = "none";>;

// [SECTION] Textures and samplers
texture ShadowMap : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "A32B32G32R32F";
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

texture ShadowDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

texture BlurredMask : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "G16R16F";
    string UIWidget = "None";
>;

texture BlurredMaskTemp : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "G16R16F";
    string UIWidget = "None";
>;

sampler BlurredMaskSampler = sampler_state
{
    texture = <BlurredMask>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
};

sampler BlurredMaskTempSampler = sampler_state
{
    texture = <BlurredMaskTemp>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

// [SECTION] Shaders
// Step 1: depth in R, the receivers' marks in G and B (1: this receiver is what the light sees here).
float4 DepthAndMarksPS(DepthVertexOutput IN) : COLOR
{
    float id = ObjectIndex;
    float mark0 = ReceiverId0 > 0 && abs(id - ReceiverId0) < 0.5 ? 1.0 : 0.0;
    float mark1 = ReceiverId1 > 0 && abs(id - ReceiverId1) < 0.5 ? 1.0 : 0.0;
    return float4(LightDepth(IN), mark0, mark1, 1);
}

// Step 2: a 9-tap Gaussian (sigma = 2 taps) over `BlurRadiusTexels`, of the two mark channels `channels`
// selects from the source (xy of the blur targets, or gb of the map).
static const float kGauss9[5] = {0.2270, 0.1945, 0.1216, 0.0540, 0.0162};

float2 Gaussian(sampler2D source, float2 uv, float2 axis, bool fromMap)
{
    float2 step = axis * (BlurRadiusTexels / 4.0) / ShadowMapSize;
    float2 sum = 0;
    for (int i = -4; i <= 4; ++i) {
        float4 t = tex2D(source, uv + i * step);
        sum += kGauss9[abs(i)] * (fromMap ? t.yz : t.xy);
    }
    return sum;
}

float4 BlurMarksXPS(BufferVertex IN) : COLOR
{
    return float4(Gaussian(ShadowMapSampler, IN.UV, float2(1, 0), true), 0, 1);
}

float4 BlurXPS(BufferVertex IN) : COLOR
{
    return float4(Gaussian(BlurredMaskSampler, IN.UV, float2(1, 0), false), 0, 1);
}

float4 BlurYPS(BufferVertex IN) : COLOR
{
    return float4(Gaussian(BlurredMaskTempSampler, IN.UV, float2(0, 1), false), 0, 1);
}

// Step 3: the marked receivers read the blurred mask, everything else the depth test.
float4 BlurredPS(SceneVertexOutput IN) : COLOR
{
    float2 uv = ShadowMapUV(IN.LP);
    float shadow;
    if (ReceiverId0 > 0 && abs(ObjectIndex - ReceiverId0) < 0.5)
        shadow = tex2D(BlurredMaskSampler, uv).x;
    else if (ReceiverId1 > 0 && abs(ObjectIndex - ReceiverId1) < 0.5)
        shadow = tex2D(BlurredMaskSampler, uv).y;
    else {
        float depth = IN.LP.z / IN.LP.w - Bias - SlopeBias * ReceiverSlope(IN) / ShadowMapSize.x;
        shadow = ShadowTestBilinear(ShadowMapSampler, uv, depth, ShadowMapSize);
    }
    return ShadeOrVisibility(IN, shadow);
}

// [SECTION] Techniques
#define MAP_PASS(NAME, TARGET, PS)                                                                          \
    pass NAME                                                                                               \
    <                                                                                                       \
        string Script = "RenderColorTarget0=" #TARGET ";"                                                   \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "Draw=Buffer;";                                                                     \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = false;                                                                                    \
        ZWriteEnable = false;                                                                               \
        VertexShader = compile vs_3_0 BufferVS();                                                           \
        PixelShader = compile ps_3_0 PS();                                                                  \
    }

technique blurred
<
    // Measured by `shadowfx stress` (docs/measurement.md, "shadowfx stress"); reported as xfail.
    string StressExpectedFailures = "light-behind-viewer [ordinary, uniform]: the blurred receiver marks "
                                    "widen the edges of texels magnified up to 20 pixels, beyond the map's "
                                    "sampling-limited error and the uniform map's";
    string Script = "Pass=RenderShadowMap; Pass=BlurMarksX; Pass=BlurY;"
                    "LoopByCount=BlurLoops; Pass=BlurX; Pass=BlurY; LoopEnd=;"
                    "Pass=RenderScene;";
    string ExpectScenes = "dual-l,teapot";
    // measured 0.016 % on dual-l, 0.039 % on teapot (hard truth); 0.039 / 0.031 % against the area-light
    // truth's classification (--area-radius 2; 0.068 on dual-l against the tests' 36-sample truth)
    float ExpectMisclassifiedBelow = 0.1;
    // penumbra MAE 0.149 on dual-l, 0.122 on teapot (320x240, bench --area-radius 2)
    float ExpectPenumbraMaeBelow = 0.23;
    float ExpectAreaRadius = 2;  // the light size the penumbra bound holds for
    int ExpectMapSize = 1024;
>
{
    pass RenderShadowMap
    <
        // Light-pass culling keeps casters this far from a visible receiver (docs/measurement.md,
        // "Leave-out"): the receiver marks spread BlurRadiusTexels x (1 + BlurLoops), 8 by default; 40 leaves
        // room to tune.
        float FilterReachTexels = 40;
        string Script = "RenderColorTarget0=ShadowMap;"
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
        PixelShader = compile ps_3_0 DepthAndMarksPS();
    }

    MAP_PASS(BlurMarksX, BlurredMaskTemp, BlurMarksXPS)
    MAP_PASS(BlurY, BlurredMask, BlurYPS)
    MAP_PASS(BlurX, BlurredMaskTemp, BlurXPS)

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
        PixelShader = compile ps_3_0 BlurredPS();
    }
}
