// lighting.fxh: Blinn-Phong shading shared by the effects in this folder.
// Conventions: world-space vectors; L points from the surface towards the light.
#ifndef SHADOWFX_LIGHTING_FXH
#define SHADOWFX_LIGHTING_FXH

// Diffuse and specular terms of one light, as HLSL's lit() computes them (x: ambient 1, y: diffuse,
// z: specular, w: 1).
float4 BlinnPhongTerms(float3 N, float3 V, float3 L, float specularPower)
{
    float3 H = normalize(V + L);
    return lit(dot(N, L), dot(N, H), specularPower);
}

#endif
