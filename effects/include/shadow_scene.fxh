// shadow_scene.fxh: the camera pass of a shadow-map effect, shared by the depth-bias and depth-layer
// effects (bias.fx, back_faces.fx, depth_formats.fx, midpoint.fx, dual_depth.fx, id_buffer.fx): the
// matrices and light the runtime binds, the receiver vertex shader, Blinn-Phong shading and the
// SHADOWFX_VISIBILITY hook (README, "Writing effects").
//
// Depth convention of these effects: a shadow map stores the light's clip depth z/w in [0, 1] (the light's
// projection is fitted to the scene bounds, so 1 is the far plane) and is cleared to 1. A receiver is lit
// where the stored depth is not in front of its own (ShadowTest in shadowmap.fxh).
#ifndef SHADOWFX_SHADOW_SCENE_FXH
#define SHADOWFX_SHADOW_SCENE_FXH

#include "lighting.fxh"
#include "shadowmap.fxh"

#ifdef SHADOWFX_SHADOW_MAP_SIZE
#define SHADOW_MAP_SIZE SHADOWFX_SHADOW_MAP_SIZE
#else
#define SHADOW_MAP_SIZE 1024
#endif

// [SECTION] Matrices and lights bound by the runtime
float4x4 WorldITMatrix : WorldInverseTranspose <string UIWidget = "None";>;
float4x4 WorldViewProjectionMatrix : WorldViewProjection <string UIWidget = "None";>;
float4x4 WorldMatrix : World <string UIWidget = "None";>;
float4x4 ViewIMatrix : ViewInverse <string UIWidget = "None";>;

float4x4 LightViewMatrix : View
<
    string frustum = "light0";
    string UIWidget = "None";
>;

float4x4 LightProjectionMatrix : Projection
<
    string frustum = "light0";
    string UIWidget = "None";
>;

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

// What an empty shadow-map texel holds: the far plane.
float4 FarDepth
<
    string UIWidget = "none";
> = {1.0, 1.0, 1.0, 1.0};

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
    // The light looks along its view's z axis: the third column of a row-vector view matrix.
    OUT.LightVec = float3(-LightViewMatrix._13, -LightViewMatrix._23, -LightViewMatrix._33);
    return OUT;
}

// The receiver's light clip depth z/w, what the shadow maps of these effects store.
float ReceiverDepth(ReceiverVertexOutput IN)
{
    return IN.LP.z / IN.LP.w;
}

float4 Shade(ReceiverVertexOutput IN, float lit)
{
    float3 N = normalize(IN.WNormal);
    float3 V = normalize(IN.WView);
    float3 L = normalize(IN.LightVec);
    float4 terms = BlinnPhongTerms(N, V, L, SpecularPower);
    float3 ambient = SurfaceColor * AmbientLightColor;
    float3 diffuse = terms.y * SurfaceColor * LightColor;
    float3 specular = terms.z * SpecularFactor * LightColor;
    return float4(lit * (diffuse + specular) + ambient, 1);
}

// The final pass's colour: shaded, or under SHADOWFX_VISIBILITY the shadow factor (1 lit, 0 shadowed).
float4 ReceiverColor(ReceiverVertexOutput IN, float lit)
{
#ifdef SHADOWFX_VISIBILITY
    return float4(lit.xxx, 1);
#else
    return Shade(IN, lit);
#endif
}

#endif
