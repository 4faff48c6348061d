// lightspace.fxh: a shadow map whose light matrices come from a light-space parameterization (README,
// "Light-space parameterizations"), tested with 2x2 bilinear PCF as in pcf.fx's `bilinear`. An effect
// defines LIGHT_PARAMETERIZATION (the provider's name, a string) and includes this file; the runtime fits
// light0's view and projection per frame, and RenderPort=light0 renders the map with the same matrices.
//
// Depth is the light clip-space z/w the depth pass writes (shadowscene.fxh): along one light ray w is
// constant, so depth order is kept under the perspective warp of LiSPSM too.
#ifndef SHADOWFX_LIGHTSPACE_FXH
#define SHADOWFX_LIGHTSPACE_FXH

#include "lighting.fxh"
#include "shadowmap.fxh"
#include "pcf.fxh"
#include "shadowscene.fxh"

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

// [SECTION] Shaders
float4 BilinearPS(SceneVertexOutput IN) : COLOR
{
    float2 uv = ShadowMapUV(IN.LP);
    float depth = IN.LP.z / IN.LP.w - Bias - SlopeBias * ReceiverSlope(IN) / ShadowMapSize.x;
    return ShadeOrVisibility(IN, ShadowTestBilinear(ShadowMapSampler, uv, depth, ShadowMapSize));
}

// [SECTION] Passes
// The shadow map from light0's port (the parameterization's matrices), then the scene from the camera.
#define LIGHTSPACE_PASSES                                                                                   \
    pass RenderShadowMap                                                                                    \
    <                                                                                                       \
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
        PixelShader = compile ps_3_0 BilinearPS();                                                          \
    }

#endif
