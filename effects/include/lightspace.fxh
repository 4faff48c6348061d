// lightspace.fxh: a shadow map whose light matrices come from a light-space parameterization
// (docs/techniques/light-space-parameterizations.md), tested with 2x2 bilinear PCF as in pcf.fx's `bilinear`.
// An effect defines LIGHT_PARAMETERIZATION (the provider's name, a string) and includes this file; the
// runtime fits light0's view and projection per frame, and RenderPort=light0 renders the map with the same
// matrices.
//
// Depth is the light clip-space z/w the depth pass writes (shadowscene.fxh): along one light ray w is
// constant, so depth order is kept under the perspective warp of LiSPSM too.
#ifndef SHADOWFX_LIGHTSPACE_FXH
#define SHADOWFX_LIGHTSPACE_FXH

#include "lighting.fxh"
#include "shadowmap.fxh"
#include "pcf.fxh"
#include "shadowscene.fxh"

// The largest depth change per texel the receiver-plane bias follows (NDC depth); beyond it the plane is
// taken for a silhouette, whose derivatives say nothing about the surface. An effect may define it first.
#ifndef LIGHTSPACE_RECEIVER_PLANE_CAP
#define LIGHTSPACE_RECEIVER_PLANE_CAP 0.01
#endif

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
    string Script = "Technique=bilinear;";
> = 0.8;

// [SECTION] Tweakables
// The depth bias follows the texel (see BiasedDepth; Kozlov 2004 §14.2.3 scales a world-space bias by the
// texel size): a focused or warped map has texels of very different sizes across the scene and depth
// ranges unlike the uniform map's, so a constant NDC bias (pcf.fx) is too small in one place and too large
// in another.
float Bias
<
    string UIWidget = "slider";
    string UIName = "Depth bias (texels)";
    float UIMin = 0.0;
    float UIMax = 4.0;
    float UIStep = 0.05;
> = 2.0;

float SlopeBias
<
    string UIWidget = "slider";
    string UIName = "Receiver-plane bias (texels)";
    float UIMin = 0.0;
    float UIMax = 4.0;
> = 1.5;

float2 ShadowMapSize <string UIWidget = "none";> = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};

// [SECTION] Textures and samplers
texture ShadowMap : RENDERCOLORTARGET
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

texture ShadowDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;
// The depth target itself, for LIGHTSPACE_HARDWARE_PASSES: tex2Dproj on it returns the depth comparison,
// bilinearly filtered over the 2x2 texels around the lookup (as NVIDIA's D3D9 hardware shadow maps did).
sampler ShadowDepthSampler = sampler_state
{
    Texture = <ShadowDepth>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
    MipFilter = NONE;
};

// The depth target read texel by texel: each of TangentPlaneHardwarePS's taps compares its own depth.
sampler ShadowDepthPointSampler = sampler_state
{
    Texture = <ShadowDepth>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MinFilter = POINT;
    MagFilter = POINT;
    MipFilter = NONE;
};

// [SECTION] Shaders
// SlopeBias times the receiver plane's depth change across one texel, from the screen derivatives of its
// map position and depth (receiver-plane depth bias, Isidoro 2006): exact for any parameterization, where a
// texel's size differs along u and v under a warp.
float ReceiverPlaneBias(SceneVertexOutput IN, float depth)
{
    float2 uvX = ddx(ShadowMapUV(IN.LP)) * ShadowMapSize;
    float2 uvY = ddy(ShadowMapUV(IN.LP)) * ShadowMapSize;
    float2 perTexel = DepthPerTexel(uvX, uvY, float2(ddx(depth), ddy(depth)));
    return SlopeBias * min(abs(perTexel.x) + abs(perTexel.y), LIGHTSPACE_RECEIVER_PLANE_CAP);
}

// The receiver's depth for the test, moved toward the light by
// - Bias texels of world size (ConstantBias): for a directional light every provider's clip w is
//   independent of the light-view depth z (1 for an orthographic fit, 1 + warp y for LiSPSM and TSM), so
//   NDC depth changes by _33 / w per world unit along the light, and one texel spans
//   2 w / (ShadowMapSize _11) world units across it (TSM's x row also has a y term, the slant of the
//   trapezoid's sides, which leaves the rate across x at _11 / w);
// - the receiver-plane bias (ReceiverPlaneBias).
float ConstantBias(SceneVertexOutput IN)
{
    float texelWorld = 2.0 * IN.LP.w / (ShadowMapSize.x * abs(LightProjectionMatrix._11));
    return Bias * texelWorld * LightProjectionMatrix._33 / IN.LP.w;
}

float BiasedDepth(SceneVertexOutput IN)
{
    float depth = IN.LP.z / IN.LP.w;
    return depth - ConstantBias(IN) - ReceiverPlaneBias(IN, depth);
}

float4 BilinearPS(SceneVertexOutput IN) : COLOR
{
    float2 uv = ShadowMapUV(IN.LP);
    float depth = BiasedDepth(IN);
    return ShadeOrVisibility(IN, ShadowTestBilinear(ShadowMapSampler, uv, depth, ShadowMapSize));
}

// The same test as BilinearPS by the hardware: the receiver's biased depth compared with the depth target
// (ShadowDepthSampler), the 2x2 comparisons bilinearly weighted in one lookup.
float4 HardwarePS(SceneVertexOutput IN) : COLOR
{
    float4 coord = float4(ShadowMapUV(IN.LP) * IN.LP.w, BiasedDepth(IN) * IN.LP.w, IN.LP.w);
    return ShadeOrVisibility(IN, tex2Dproj(ShadowDepthSampler, coord).x);
}
// Bilinear PCF under the adaptive depth bias (Dou et al. 2014): each tap compares the receiver's tangent
// plane, from its normal, at the tap's texel centre (TangentPlaneBilinearTaps), less Bias texels of world
// size, in place of BiasedDepth's receiver-plane bias. The plane follows any slope, where the screen
// derivatives' plane must be capped (LIGHTSPACE_RECEIVER_PLANE_CAP) against silhouettes: a 0.5 degree
// sun's ground changes depth by over 100 texels' width per texel.
float4 TangentPlanePS(SceneVertexOutput IN) : COLOR
{
    TangentPlaneTaps taps = TangentPlaneBilinearTaps(LightViewProjectionMatrix, IN.LP, normalize(IN.WNormal),
                                                     ShadowMapSize, ConstantBias(IN));
    float shadow = ShadowTestTaps(ShadowMapSampler, float4(0.0, 0.0, 1.0, 1.0), ShadowMapSize, taps);
    return ShadeOrVisibility(IN, shadow);
}

// TangentPlanePS's taps compared with the depth target in hardware (ShadowDepthPointSampler).
float4 TangentPlaneHardwarePS(SceneVertexOutput IN) : COLOR
{
    TangentPlaneTaps taps = TangentPlaneBilinearTaps(LightViewProjectionMatrix, IN.LP, normalize(IN.WNormal),
                                                     ShadowMapSize, ConstantBias(IN));
    float shadow = ShadowCompareTaps(ShadowDepthPointSampler, float4(0.0, 0.0, 1.0, 1.0), ShadowMapSize, taps);
    return ShadeOrVisibility(IN, shadow);
}

// [SECTION] Passes
// The shadow map from light0's port (the parameterization's matrices), then the scene from the camera. The
// map pass clamps depth instead of clipping (DepthClipEnable = false): with LightPancaking the fit's depth
// range holds only the receivers, and casters between them and the light land on the near plane, still
// nearer than every receiver; without it nothing lies outside the range and the state changes nothing.
// Its FilterReachTexels = 2: the 2x2 bilinear test reads one texel beyond a receiver's own, and leave-out
// culls casters outside that reach (the default 8 texels is up to 8 large far texels of a LiSPSM map).
// The scene pass shades with LIGHTSPACE_SCENE_PS (BilinearPS unless the effect defines its own before
// expanding the passes: psm.fx's own bias).
#ifndef LIGHTSPACE_SCENE_PS
#define LIGHTSPACE_SCENE_PS BilinearPS
#endif
#define LIGHTSPACE_PASSES                                                                                   \
    pass RenderShadowMap                                                                                    \
    <                                                                                                       \
        float FilterReachTexels = 2;                                                                        \
        string Script = "RenderColorTarget0=ShadowMap;"                                                     \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "ClearSetColor=NoOccluder;"                                                         \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Color;"                                                                      \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        DepthClipEnable = false;                                                                            \
        VertexShader = compile vs_3_0 RenderDepthVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix))); \
        PixelShader = compile ps_3_0 RenderDepthPS();                                                       \
    }                                                                                                       \
    pass RenderScene                                                                                        \
    <                                                                                                       \
        string Script = "RenderColorTarget0=;"                                                              \
                        "RenderDepthStencilTarget=;"                                                        \
                        "RenderPort=;"                                                                      \
                        "ClearSetColor=ClearColor;"                                                         \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Color;"                                                                      \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = CCW;                                                                                     \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));           \
        PixelShader = compile ps_3_0 LIGHTSPACE_SCENE_PS();                                                 \
    }

// The scene pass of the depth-only maps below: the receiver's depth compared in hardware with
// LIGHTSPACE_HARDWARE_SCENE_PS (HardwarePS unless the effect defines its own first: focused.fx's
// TangentPlaneHardwarePS, the hardware form of its LIGHTSPACE_SCENE_PS).
#ifndef LIGHTSPACE_HARDWARE_SCENE_PS
#define LIGHTSPACE_HARDWARE_SCENE_PS HardwarePS
#endif
#define LIGHTSPACE_HARDWARE_SCENE_PASS                                                                      \
    pass RenderScene                                                                                        \
    <                                                                                                       \
        string Script = "RenderColorTarget0=;"                                                              \
                        "RenderDepthStencilTarget=;"                                                        \
                        "RenderPort=;"                                                                      \
                        "ClearSetColor=ClearColor;"                                                         \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Color;"                                                                      \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = CCW;                                                                                     \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));           \
        PixelShader = compile ps_3_0 LIGHTSPACE_HARDWARE_SCENE_PS();                                        \
    }

// A depth-only map: the map pass writes the depth target alone (ColorWriteEnable = 0, no R32F colour target
// cleared or written) and the scene pass compares against it in hardware (HardwarePS): the same errors as
// BilinearPS, a cheaper frame on llvmpipe (docs/results/2026-12-05-peers-city-street.md).
#define LIGHTSPACE_HARDWARE_PASSES                                                                          \
    pass RenderShadowDepth                                                                                  \
    <                                                                                                       \
        float FilterReachTexels = 2;                                                                        \
        string Script = "RenderColorTarget0=ShadowMap;"                                                     \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        ColorWriteEnable = 0;                                                                               \
        DepthClipEnable = false;                                                                            \
        VertexShader = compile vs_3_0 RenderDepthVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix))); \
        PixelShader = compile ps_3_0 RenderDepthPS();                                                       \
    }                                                                                                       \
    LIGHTSPACE_HARDWARE_SCENE_PASS

// The same depth-only map drawn from the casters alone, the faces of the closed ones towards the light
// (shadowscene.fxh's CASTER_DEPTH_PASS): `hardware`'s map less the objects that cast nothing, for a fraction
// of its rasterization (docs/results/2026-12-06-plain-shadow-map.md).
#define LIGHTSPACE_CASTER_PASSES                                                                            \
    CASTER_DEPTH_PASS(RenderShadowDepth, "RenderColorTarget0=ShadowMap;"                                    \
                                         "RenderDepthStencilTarget=ShadowDepth;"                            \
                                         "RenderPort=light0;"                                               \
                                         "ClearSetDepth=ClearDepth;"                                        \
                                         "Clear=Depth;"                                                     \
                                         "Draw=Geometry;")                                                  \
    LIGHTSPACE_HARDWARE_SCENE_PASS

#endif
