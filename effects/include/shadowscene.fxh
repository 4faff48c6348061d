// shadowscene.fxh: what every shadow-filtering effect here shares besides its shadow test: the matrices
// and lights the runtime binds, the vertex shaders of the shadow-map and scene passes, and Blinn-Phong
// shading with a shadow factor (the same shading as thesis_fxcomposer.fx). Include lighting.fxh first.
//
// The shadow-map pass writes light clip-space depth z/w in [0, 1] (for directional lights, whose projection
// is orthographic, w = 1 and z is linear in distance; for spot lights the division is per pixel, since
// z/w does not interpolate linearly: `shadowfx stress`, case spot-inside-bounds). The scene pass hands its
// pixel shader the receiver's light clip position (LP), its world normal and the direction to the light.
#ifndef SHADOWFX_SHADOWSCENE_FXH
#define SHADOWFX_SHADOWSCENE_FXH

float4x4 WorldITMatrix : WorldInverseTranspose <string UIWidget = "None";>;
float4x4 WorldViewProjectionMatrix : WorldViewProjection <string UIWidget = "None";>;
float4x4 WorldMatrix : World <string UIWidget = "None";>;
float4x4 ViewIMatrix : ViewInverse <string UIWidget = "None";>;
// LIGHT_PARAMETERIZATION (a string: "Uniform", "Focused", "LiSPSM"), defined before this include, chooses
// the provider of light0's matrices (README, "Light-space parameterizations"); the default is Uniform.
#ifndef LIGHT_PARAMETERIZATION
#define LIGHT_PARAMETERIZATION "Uniform"
#endif
float4x4 LightViewMatrix : View
<string frustum = "light0"; string Parameterization = LIGHT_PARAMETERIZATION; string UIWidget = "None";>;
float4x4 LightProjectionMatrix : Projection
<string frustum = "light0"; string Parameterization = LIGHT_PARAMETERIZATION; string UIWidget = "None";>;
float3 LightColor : LightColor <string Object = "light0"; string UIWidget = "none";> = {1.0, 1.0, 1.0};
float3 AmbientLightColor : Ambient <string UIWidget = "color";> = {0.15, 0.15, 0.15};
float3 SurfaceColor : Diffuse <string UIWidget = "none";> = {0.8, 0.8, 0.8};

float SpecularPower <string UIWidget = "slider"; float UIMin = 1.0; float UIMax = 128.0;> = 32.0;
float SpecularFactor = 0.4;
float4 ClearColor <string UIWidget = "color";> = {0.32, 0.36, 0.42, 1.0};
float ClearDepth <string UIWidget = "none";> = 1.0;
// Clear value of depth and moments maps: depth 1 (and depth² 1), no occluder in front of anything.
float4 NoOccluder <string UIWidget = "none";> = {1.0, 1.0, 1.0, 1.0};

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
    // The light looks along its view's z axis: the third column of a row-vector view matrix.
    OUT.LightVec = float3(-LightViewMatrix._13, -LightViewMatrix._23, -LightViewMatrix._33);
    return OUT;
}

// tan of the angle between the surface and the direction to the light, capped: how fast the receiver's
// light depth changes across the shadow map, for biases that grow with the filter's footprint.
float ReceiverSlope(SceneVertexOutput IN)
{
    float cosine = saturate(dot(normalize(IN.WNormal), normalize(IN.LightVec)));
    return min(sqrt(1 - cosine * cosine) / max(cosine, 1e-3), 10.0);
}

float4 Shade(SceneVertexOutput IN, float shadow)
{
    float3 N = normalize(IN.WNormal);
    float3 V = normalize(IN.WView);
    float3 L = normalize(IN.LightVec);
    float4 terms = BlinnPhongTerms(N, V, L, SpecularPower);
    float3 ambient = SurfaceColor * AmbientLightColor;
    float3 lit = (terms.y * SurfaceColor + terms.z * SpecularFactor) * LightColor;
    return float4(shadow * lit + ambient, 1);
}

// The measurement hook (README, "Writing effects"): the shadow factor itself under SHADOWFX_VISIBILITY.
float4 ShadeOrVisibility(SceneVertexOutput IN, float shadow)
{
#ifdef SHADOWFX_VISIBILITY
    return float4(shadow.xxx, 1);
#else
    return Shade(IN, shadow);
#endif
}

#endif
