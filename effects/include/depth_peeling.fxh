// depth_peeling.fxh: the two depth layers closest to the light, found by depth peeling as Weiskopf & Ertl 2003 (§5)
// describes for dual shadow maps: the first pass stores the nearest depth z1; the second renders the scene
// again and discards every fragment whose depth equals the stored z1 (up to PeelEpsilon), so that the
// min-blended target keeps z2, the nearest depth behind it; a full-screen pass then combines z1 and z2
// into the shadow map. Include after shadow_scene.fxh and light_depth.fxh.
#ifndef SHADOWFX_DEPTH_PEELING_FXH
#define SHADOWFX_DEPTH_PEELING_FXH

// The paper's "very small tolerance level" for equal depths: the same triangle rasterized twice by the
// same vertex shader gives the same depth, so this only has to absorb rounding at shared edges.
float PeelEpsilon
<
    string UIWidget = "none";
> = 1e-5;

texture FirstLayer : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R32F";
    string UIWidget = "None";
>;

texture SecondLayer : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R32F";
    string UIWidget = "None";
>;

sampler FirstLayerSampler = sampler_state
{
    texture = <FirstLayer>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

sampler SecondLayerSampler = sampler_state
{
    texture = <SecondLayer>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

// The map the scene pass tests against: z1 and z2 combined by CombineLayersPS.
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

float4 FirstLayerPS(LightDepthVertexOutput IN) : COLOR
{
    return float4(LightDepth(IN), 0, 0, 1);
}

// VPOS is the fragment's texel (top-left corner), so the lookup reads exactly the texel being written.
float4 SecondLayerPS(LightDepthVertexOutput IN, float2 texel : VPOS) : COLOR
{
    float z = LightDepth(IN);
    float z1 = tex2D(FirstLayerSampler, (texel + 0.5) / SHADOW_MAP_SIZE).x;
    if (z <= z1 + PeelEpsilon)
        discard;
    return float4(z, 0, 0, 1);
}

struct QuadVertex
{
    float4 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

QuadVertex QuadVS(QuadVertex IN)
{
    return IN;
}

float4 CombineLayersPS(QuadVertex IN, uniform float zOffset) : COLOR
{
    float z1 = tex2D(FirstLayerSampler, IN.UV).x;
    float z2 = tex2D(SecondLayerSampler, IN.UV).x;
    return float4(DualDepth(z1, z2, zOffset), 0, 0, 1);
}

// The bias is in the combined map: the test is the plain one (Weiskopf & Ertl 2003, eq. 3: z_frag < z_dual).
float4 LayeredShadowPS(ReceiverVertexOutput IN) : COLOR
{
    return ReceiverColor(IN, ShadowTest(ShadowMapSampler, ShadowMapUV(IN.LP), ReceiverDepth(IN)));
}

// The RenderScene pass's pixel shader: LayeredShadowPS unless the effect defines LAYERED_SCENE_PS before
// including this file, to test the combined map its own way (a function defined before its techniques).
#ifndef LAYERED_SCENE_PS
#define LAYERED_SCENE_PS LayeredShadowPS
#endif

// [SECTION] Passes: PEELING_PASSES(cull, closedOnly, zOffset) gives the passes ClearLayers,
// RenderFirstLayer, RenderSecondLayer, CombineLayers and RenderScene. `cull` is the layer passes' CullMode
// (None, or CCW for Weiskopf & Ertl 2003's back-face culling), `closedOnly` their CullClosedOnly annotation (open
// objects stay unculled), `zOffset` the dual map's offset (a huge one gives the midpoint map).
#define PEEL_LAYER_PASS(passName, target, pixelShader, cull, closedOnly) \
    pass passName \
    < \
        string Script = "RenderColorTarget0=" #target ";" \
                        "RenderDepthStencilTarget=MapDepthBuffer;" \
                        "RenderPort=light0;" \
                        "Draw=geometry;"; \
        bool CullClosedOnly = closedOnly; \
    > \
    { \
        CullMode = cull; \
        AlphaBlendEnable = true; \
        SrcBlend = one; \
        DestBlend = one; \
        BlendOp = min; \
        ZEnable = false; \
        ZWriteEnable = false; \
        VertexShader = compile vs_3_0 LightDepthVS(mul(WorldMatrix, LightViewMatrix)); \
        PixelShader = compile ps_3_0 pixelShader(); \
    }

#define PEELING_PASSES(cull, closedOnly, zOffset) \
    pass ClearLayers \
    < \
        string Script = "RenderDepthStencilTarget=MapDepthBuffer;" \
                        "RenderPort=light0;" \
                        "ClearSetColor=NoOccluder;" \
                        "RenderColorTarget0=FirstLayer;" \
                        "Clear=Color;" \
                        "RenderColorTarget0=SecondLayer;" \
                        "Clear=Color;"; \
    > \
    { \
    } \
    PEEL_LAYER_PASS(RenderFirstLayer, FirstLayer, FirstLayerPS, cull, closedOnly) \
    PEEL_LAYER_PASS(RenderSecondLayer, SecondLayer, SecondLayerPS, cull, closedOnly) \
    pass CombineLayers \
    < \
        string Script = "RenderColorTarget0=ShadowMap;" \
                        "RenderDepthStencilTarget=MapDepthBuffer;" \
                        "RenderPort=light0;" \
                        "Draw=Buffer;"; \
    > \
    { \
        CullMode = None; \
        ZEnable = false; \
        ZWriteEnable = false; \
        VertexShader = compile vs_3_0 QuadVS(); \
        PixelShader = compile ps_3_0 CombineLayersPS(zOffset); \
    } \
    pass RenderScene \
    < \
        string Script = "RenderColorTarget0=;" \
                        "RenderDepthStencilTarget=;" \
                        "RenderPort=;" \
                        "ClearSetColor=ClearColor;" \
                        "ClearSetDepth=ClearDepth;" \
                        "Clear=Color;" \
                        "Clear=Depth;" \
                        "Draw=Geometry;"; \
    > \
    { \
        CullMode = CCW; \
        AlphaBlendEnable = false; \
        ZEnable = true; \
        ZWriteEnable = true; \
        ZFunc = LessEqual; \
        VertexShader = compile vs_3_0 ReceiverVS(); \
        PixelShader = compile ps_3_0 LAYERED_SCENE_PS(); \
    }

#endif
