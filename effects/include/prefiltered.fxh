// prefiltered.fxh: the pass sequence of the shadow maps that are filtered before they are read (exponential,
// exponential variance and moment shadow maps: esm.fx, evsm.fx, msm.fx), after the order of Lauritzen &
// McCool 2008 and Peters & Klein 2015:
//
//   RenderDepth   light depth z/w into ShadowDepthMap (R32F, cleared to NoOccluder = far)
//   FilterX       a BlurTaps-wide box along x that turns each depth into what the method stores
//                 (StoredValue, defined by the effect) and averages it, into PREFIX##Temp
//   FilterY       the same box along y, into PREFIX##Map, a mipmapped target (MipLevels = 0: the runtime
//                 regenerates the chain after the pass) that the scene reads with trilinear filtering
//   RenderScene   the method's visibility from one filtered lookup
//
// Storing from depth in the first blur, rather than in the depth pass, keeps the depth pass the same for
// every method and clears the map with depth alone: a cleared texel becomes what an occluder at the far
// plane would store, whatever the method. Every stored quantity here is linear in what the blur averages,
// so blurring, mipmapping and bilinear filtering are all the same filter of the method's moments.
//
// An effect defines, before including this header: `float4 StoredValue(float z, int variant)` (what a
// texel holds for an occluder at depth z), BlurTaps (int, odd) and ShadowMapSize (float2), then declares its
// targets with PREFILTERED_TARGETS(PREFIX, "FORMAT") and its techniques with PREFILTERED_PASSES(PREFIX,
// variant, ScenePS). Include lighting.fxh, shadowmap.fxh, blur.fxh and shadowscene.fxh first.
#ifndef SHADOWFX_PREFILTERED_FXH
#define SHADOWFX_PREFILTERED_FXH

texture ShadowDepthMap : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R32F";
    string UIWidget = "None";
>;

texture ShadowDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

// The filter reads texel centres exactly: point sampling.
sampler DepthPointSampler = sampler_state
{
    texture = <ShadowDepthMap>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

// The first axis of the box filter: StoredValue of `taps` depths along `step`, averaged.
float4 StoreAndBlur(float2 uv, float2 step, int taps, int variant)
{
    int radius = clamp(taps, 1, 31) / 2;
    float4 sum = 0;
    for (int i = -radius; i <= radius; ++i)
        sum += StoredValue(tex2D(DepthPointSampler, uv + i * step).x, variant);
    return sum / (2 * radius + 1);
}

float4 FilterXPS(BufferVertex IN, uniform int variant) : COLOR
{
    return StoreAndBlur(IN.UV, float2(1.0 / ShadowMapSize.x, 0), BlurTaps, variant);
}

// The receiver's light depth.
float ReceiverDepth(SceneVertexOutput IN)
{
    return IN.LP.z / IN.LP.w;
}

// The filtered map at the receiver, its trilinear footprint narrowed to where the receiver's tangent plane
// changes by at most `depthSpan` across it. A filter of exponentials weighs each texel by how far from the
// light its occluder is, so a footprint over a receiver that slopes away from the light (the ground under a
// low sun: a depth change of many times 1 / c across a mip texel) lets its farthest, lit texels outweigh
// the shadowed ones: false light. The footprint's side in level-0 texels is the longer of the screen
// derivatives of the map position (the mip level's isotropic choice); the plane changes across such a
// square by at most its side times the sum of its slopes per texel (TangentPlaneDepthPerTexel). Where that
// stays within `depthSpan` the lookup is tex2D's own.
float4 PlaneLimitedLookup(sampler2D map, SceneVertexOutput IN, float depthSpan)
{
    float2 uv = ShadowMapUV(IN.LP);
    float2 dx = ddx(uv);
    float2 dy = ddy(uv);
    float side = max(length(dx * ShadowMapSize), length(dy * ShadowMapSize));
    float2 slope = abs(TangentPlaneDepthPerTexel(LightViewProjectionMatrix, IN.LP, normalize(IN.WNormal), ShadowMapSize));
    float change = side * (slope.x + slope.y);
    float narrowing = change > depthSpan ? depthSpan / change : 1.0;
    return tex2Dgrad(map, uv, dx * narrowing, dy * narrowing);
}

// Two targets of the stored quantities in `FORMAT`: the first blur's output and the mipmapped, filtered
// map, each with its sampler (PREFIX##TempSampler: point, PREFIX##MapSampler: trilinear).
#define PREFILTERED_TARGETS(PREFIX, FORMAT)                                                                 \
    texture PREFIX##Temp : RENDERCOLORTARGET                                                                \
    <                                                                                                       \
        float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};                                             \
        string Format = FORMAT;                                                                             \
        string UIWidget = "None";                                                                           \
    >;                                                                                                      \
    texture PREFIX##Map : RENDERCOLORTARGET                                                                 \
    <                                                                                                       \
        float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};                                             \
        string Format = FORMAT;                                                                             \
        int MipLevels = 0;                                                                                  \
        string UIWidget = "None";                                                                           \
    >;                                                                                                      \
    sampler PREFIX##TempSampler = sampler_state                                                             \
    {                                                                                                       \
        texture = <PREFIX##Temp>;                                                                           \
        AddressU = CLAMP;                                                                                   \
        AddressV = CLAMP;                                                                                   \
        MipFilter = NONE;                                                                                   \
        MinFilter = POINT;                                                                                  \
        MagFilter = POINT;                                                                                  \
    };                                                                                                      \
    sampler PREFIX##MapSampler = sampler_state                                                              \
    {                                                                                                       \
        texture = <PREFIX##Map>;                                                                            \
        AddressU = CLAMP;                                                                                   \
        AddressV = CLAMP;                                                                                   \
        MipFilter = LINEAR;                                                                                 \
        MinFilter = LINEAR;                                                                                 \
        MagFilter = LINEAR;                                                                                 \
    };                                                                                                      \
    float4 PREFIX##FilterYPS(BufferVertex IN) : COLOR                                                       \
    {                                                                                                       \
        return BoxBlur(PREFIX##TempSampler, IN.UV, float2(0, 1.0 / ShadowMapSize.y), BlurTaps);            \
    }

// The four passes of a technique; the technique's Script is
// "Pass=RenderDepth; Pass=FilterX; Pass=FilterY; Pass=RenderScene;". The filter passes keep the map-sized
// depth target bound (the frame's would clip them to the frame's size) with ZEnable off.
#define PREFILTERED_PASSES(PREFIX, VARIANT, SCENE_PS)                                                       \
    pass RenderDepth                                                                                        \
    <                                                                                                       \
        string Script = "RenderColorTarget0=ShadowDepthMap;"                                                \
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
    pass FilterX                                                                                            \
    <                                                                                                       \
        string Script = "RenderColorTarget0=" #PREFIX "Temp;"                                               \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "Draw=Buffer;";                                                                     \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = false;                                                                                    \
        ZWriteEnable = false;                                                                               \
        VertexShader = compile vs_3_0 BufferVS();                                                           \
        PixelShader = compile ps_3_0 FilterXPS(VARIANT);                                                    \
    }                                                                                                       \
    pass FilterY                                                                                            \
    <                                                                                                       \
        string Script = "RenderColorTarget0=" #PREFIX "Map;"                                                \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "Draw=Buffer;";                                                                     \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = false;                                                                                    \
        ZWriteEnable = false;                                                                               \
        VertexShader = compile vs_3_0 BufferVS();                                                           \
        PixelShader = compile ps_3_0 PREFIX##FilterYPS();                                                   \
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
        PixelShader = compile ps_3_0 SCENE_PS();                                                            \
    }

#endif
