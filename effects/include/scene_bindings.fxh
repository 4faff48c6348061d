// scene_bindings.fxh: what every shadow-map effect here binds from the runtime and how it shades, shared
// by the two families' camera passes (shadow_scene.fxh: bias and depth layers; shadowscene.fxh: filtering,
// soft shadows and light-space parameterizations): the object and light matrices, the light's colour, the
// clear values and Blinn-Phong shading with a shadow factor, with the SHADOWFX_VISIBILITY measurement hook
// (docs/scoring.md, "Measurement hooks"). Include lighting.fxh first.
#ifndef SHADOWFX_SCENE_BINDINGS_FXH
#define SHADOWFX_SCENE_BINDINGS_FXH

// [SECTION] Matrices and lights bound by the runtime
float4x4 WorldITMatrix : WorldInverseTranspose <string UIWidget = "None";>;
float4x4 WorldViewProjectionMatrix : WorldViewProjection <string UIWidget = "None";>;
float4x4 WorldMatrix : World <string UIWidget = "None";>;
float4x4 ViewIMatrix : ViewInverse <string UIWidget = "None";>;
// LIGHT_PARAMETERIZATION (a string: "Uniform", "Focused", "LiSPSM", "TSM", "PSM", "Cascaded"), defined
// before this include, chooses the provider of light0's matrices
// (docs/techniques/light-space-parameterizations.md); the default is Uniform.
#ifndef LIGHT_PARAMETERIZATION
#define LIGHT_PARAMETERIZATION "Uniform"
#endif
float4x4 LightViewMatrix : View
<string frustum = "light0"; string Parameterization = LIGHT_PARAMETERIZATION; string UIWidget = "None";>;
float4x4 LightProjectionMatrix : Projection
<string frustum = "light0"; string Parameterization = LIGHT_PARAMETERIZATION; string UIWidget = "None";>;
// Their product (world to light clip space), for the adaptive bias's tangent-plane depths (shadowmap.fxh).
float4x4 LightViewProjectionMatrix : ViewProjection
<string frustum = "light0"; string Parameterization = LIGHT_PARAMETERIZATION; string UIWidget = "None";>;
float3 LightColor : LightColor <string Object = "light0"; string UIWidget = "none";> = {1.0, 1.0, 1.0};
float3 AmbientLightColor : Ambient <string UIWidget = "color";> = {0.15, 0.15, 0.15};
float3 SurfaceColor : Diffuse <string UIWidget = "none";> = {0.8, 0.8, 0.8};

// Shading, not shadowing: `shadowfx tune` leaves it as it is (Tune = false).
float SpecularPower <string UIWidget = "slider"; float UIMin = 1.0; float UIMax = 128.0; bool Tune = false;> = 32.0;
float SpecularFactor = 0.4;
float4 ClearColor <string UIWidget = "color";> = {0.32, 0.36, 0.42, 1.0};
float ClearDepth <string UIWidget = "none";> = 1.0;
// What an empty shadow-map texel holds: depth 1, the far plane (and depth² 1 for moments maps), no
// occluder in front of anything.
float4 NoOccluder <string UIWidget = "none";> = {1.0, 1.0, 1.0, 1.0};

// [SECTION] Shading
// The direction to the light: a light looks along its view's z axis, the third column of a row-vector
// view matrix.
float3 DirectionToLight()
{
    return float3(-LightViewMatrix._13, -LightViewMatrix._23, -LightViewMatrix._33);
}

// Blinn-Phong with the light scaled by `shadow` (1 lit, 0 shadowed); the vectors in world space.
float4 ShadeWithShadow(float3 worldNormal, float3 worldView, float3 lightVec, float shadow)
{
    float3 N = normalize(worldNormal);
    float3 V = normalize(worldView);
    float3 L = normalize(lightVec);
    float4 terms = BlinnPhongTerms(N, V, L, SpecularPower);
    float3 ambient = SurfaceColor * AmbientLightColor;
    float3 lit = (terms.y * SurfaceColor + terms.z * SpecularFactor) * LightColor;
    return float4(shadow * lit + ambient, 1);
}

// The final pass's colour: shaded, or under SHADOWFX_VISIBILITY the shadow factor itself.
float4 ShadedOrVisibility(float3 worldNormal, float3 worldView, float3 lightVec, float shadow)
{
#ifdef SHADOWFX_VISIBILITY
    return float4(shadow.xxx, 1);
#else
    return ShadeWithShadow(worldNormal, worldView, lightVec, shadow);
#endif
}

#endif
