// shadow_scene.fxh: the camera pass of a shadow-map effect, shared by the depth-bias and depth-layer
// effects (bias.fx, back_faces.fx, depth_formats.fx, midpoint.fx, dual_depth.fx, id_buffer.fx): the
// bindings and shading of scene_bindings.fxh, the shadow map's depth buffer and the receiver vertex shader
// (docs/scoring.md, "Measurement hooks").
//
// Depth convention of these effects: a shadow map stores the light's clip depth z/w in [0, 1] (the light's
// projection is fitted to the scene bounds, so 1 is the far plane) and is cleared to 1 (NoOccluder). A
// receiver is lit where the stored depth is not in front of its own (ShadowTest in shadowmap.fxh).
#ifndef SHADOWFX_SHADOW_SCENE_FXH
#define SHADOWFX_SHADOW_SCENE_FXH

#include "lighting.fxh"
#include "scene_bindings.fxh"
#include "shadowmap.fxh"

#ifdef SHADOWFX_SHADOW_MAP_SIZE
#define SHADOW_MAP_SIZE SHADOWFX_SHADOW_MAP_SIZE
#else
#define SHADOW_MAP_SIZE 1024
#endif

// The depth buffer bound with a shadow map: a framebuffer's attachments must share the map's size even
// where the pass tests no depth (the frame's own depth buffer would clip the map to the frame's size).
texture MapDepthBuffer : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

// [SECTION] Receiver pass
struct SceneVertex
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct ReceiverVertexOutput
{
    float4 HPosition : POSITION;
    float3 LightVec  : TEXCOORD0;
    float3 WNormal   : TEXCOORD1;
    float3 WView     : TEXCOORD2;
    float4 LP        : TEXCOORD3;  // light clip space
    float  LightZ    : TEXCOORD4;  // light view-space z, for linear depth (LinearLightDepth)
};

ReceiverVertexOutput ReceiverVS(SceneVertex IN)
{
    ReceiverVertexOutput OUT;
    float4 Pos = float4(IN.Position.xyz, 1.0);
    float4 Pw = mul(Pos, WorldMatrix);
    float4 Pl = mul(Pw, LightViewMatrix);
    OUT.WNormal = mul(IN.Normal, (float3x3)WorldITMatrix);
    OUT.LP = mul(Pl, LightProjectionMatrix);
    OUT.LightZ = Pl.z;
    OUT.WView = normalize(ViewIMatrix[3].xyz - Pw.xyz);
    OUT.HPosition = mul(Pos, WorldViewProjectionMatrix);
    OUT.LightVec = DirectionToLight();
    return OUT;
}

// The receiver's light clip depth z/w, what the shadow maps of these effects store.
float ReceiverDepth(ReceiverVertexOutput IN)
{
    return IN.LP.z / IN.LP.w;
}

// The final pass's colour: shaded, or under SHADOWFX_VISIBILITY the shadow factor (1 lit, 0 shadowed).
float4 ReceiverColor(ReceiverVertexOutput IN, float lit)
{
    return ShadedOrVisibility(IN.WNormal, IN.WView, IN.LightVec, lit);
}

#endif
