// shadowscene.fxh: what every shadow-filtering effect here shares besides its shadow test: the bindings
// and shading of scene_bindings.fxh (the same shading as thesis_fxcomposer.fx) and the vertex shaders of
// the shadow-map and scene passes. Include lighting.fxh first.
//
// The shadow-map pass writes light clip-space depth z/w in [0, 1] (for directional lights, whose projection
// is orthographic, w = 1 and z is linear in distance; for spot lights the division is per pixel, since
// z/w does not interpolate linearly: `shadowfx stress`, case spot-inside-bounds). The scene pass hands its
// pixel shader the receiver's light clip position (LP), its world normal and the direction to the light.
#ifndef SHADOWFX_SHADOWSCENE_FXH
#define SHADOWFX_SHADOWSCENE_FXH

#include "scene_bindings.fxh"

struct VertexFormat
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct DepthVertexOutput
{
    float4 Position : POSITION;
    float2 ZW       : TEXCOORD0;
};

DepthVertexOutput RenderDepthVS(VertexFormat IN, uniform float4x4 WorldLightViewProjection)
{
    DepthVertexOutput OUT;
    OUT.Position = mul(float4(IN.Position.xyz, 1.0), WorldLightViewProjection);
    OUT.ZW = OUT.Position.zw;
    return OUT;
}

// The light clip depth z/w of a shadow-map pixel.
float LightDepth(DepthVertexOutput IN)
{
    return IN.ZW.x / IN.ZW.y;
}

float4 RenderDepthPS(DepthVertexOutput IN) : COLOR
{
    return float4(LightDepth(IN), 0, 0, 1);
}

// A depth-only map pass of the casters alone, named `name`, whose Script is `script` (its targets, port and
// clears, then "Draw=Geometry;"): the objects the scene says cast shadows (CastersOnly; a ground that only
// receives no longer covers the map, as osgShadow's casters mask leaves it out) and, of the closed ones, the
// faces towards the light (CullMode = CCW with CullClosedOnly: open meshes drawn whole). With the light
// outside every closed caster the nearest surface along a light ray is a face towards it, so the map is
// that of every object's both faces less the non-casters, for a fraction of its rasterization
// (docs/results/2026-12-06-plain-shadow-map.md). Depth is clamped, not clipped (DepthClipEnable = false:
// casters before a pancaked depth range land on its near plane), and FilterReachTexels = 2 lets leave-out
// cull the casters beyond the one texel a 2x2 bilinear test reads past a receiver's own.
#define CASTER_DEPTH_PASS(name, script)                                                                     \
    pass name                                                                                               \
    <                                                                                                       \
        float FilterReachTexels = 2;                                                                        \
        bool CastersOnly = true;                                                                            \
        bool CullClosedOnly = true;                                                                         \
        string Script = script;                                                                             \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = CCW;                                                                                     \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        ColorWriteEnable = 0;                                                                               \
        DepthClipEnable = false;                                                                            \
        VertexShader = compile vs_3_0 RenderDepthVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix))); \
        PixelShader = compile ps_3_0 RenderDepthPS();                                                       \
    }

struct SceneVertexOutput
{
    float4 HPosition : POSITION;
    float3 LightVec  : TEXCOORD0;
    float3 WNormal   : TEXCOORD1;
    float3 WView     : TEXCOORD2;
    float4 LP        : TEXCOORD3;
};

SceneVertexOutput RenderSceneVS(VertexFormat IN, uniform float4x4 ShadowViewProjectionMatrix)
{
    SceneVertexOutput OUT;
    float4 Pos = float4(IN.Position.xyz, 1.0);
    float4 Pw = mul(Pos, WorldMatrix);
    OUT.WNormal = mul(IN.Normal, (float3x3)WorldITMatrix);
    OUT.LP = mul(Pw, ShadowViewProjectionMatrix);
    OUT.WView = normalize(ViewIMatrix[3].xyz - Pw.xyz);
    OUT.HPosition = mul(Pos, WorldViewProjectionMatrix);
    OUT.LightVec = DirectionToLight();
    return OUT;
}

// tan of the angle between the surface and the direction to the light, capped: how fast the receiver's
// light depth changes across the shadow map, for biases that grow with the filter's footprint.
float ReceiverSlope(SceneVertexOutput IN)
{
    float cosine = saturate(dot(normalize(IN.WNormal), normalize(IN.LightVec)));
    return min(sqrt(1 - cosine * cosine) / max(cosine, 1e-3), 10.0);
}

// The measurement hook (docs/scoring.md, "Measurement hooks"): the shadow factor itself under
// SHADOWFX_VISIBILITY.
float4 ShadeOrVisibility(SceneVertexOutput IN, float shadow)
{
    return ShadedOrVisibility(IN.WNormal, IN.WView, IN.LightVec, shadow);
}

#endif
