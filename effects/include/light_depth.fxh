// light_depth.fxh: the shadow-map (light) pass of the depth-bias and depth-layer effects: the vertex
// shader that carries the light depth to the pixel shader, and the depth a map texel receives under each
// biasing scheme. Include after shadow_scene.fxh (it uses its matrices and SceneVertex).
#ifndef SHADOWFX_LIGHT_DEPTH_FXH
#define SHADOWFX_LIGHT_DEPTH_FXH

struct LightDepthVertexOutput
{
    float4 Position : POSITION;
    // x, y: the light's clip z and w (divided per pixel, so perspective lights stay exact);
    // z: light view-space z, for linear depth.
    float3 Depth    : TEXCOORD0;
};

LightDepthVertexOutput LightDepthVS(SceneVertex IN, uniform float4x4 WorldLightView)
{
    LightDepthVertexOutput OUT;
    float4 Pl = mul(float4(IN.Position.xyz, 1.0), WorldLightView);
    OUT.Position = mul(Pl, LightProjectionMatrix);
    OUT.Depth = float3(OUT.Position.z, OUT.Position.w, Pl.z);
    return OUT;
}

// The light clip depth z/w in [0, 1]: what ReceiverDepth (shadow_scene.fxh) compares with.
float LightDepth(LightDepthVertexOutput IN)
{
    return IN.Depth.x / IN.Depth.y;
}

// Linear depth (Scherzer 2005, §4.2, after TSM; Lehőcz 2007, "Megoldások az önárnyékolás problémára": a light-space
// bias suits near casters but not far ones when the stored depth is z/w): view-space z mapped linearly
// from the light's near plane (0) to its far plane (1). A D3D LH perspective projection has _33 = f/(f-n),
// _43 = -n f/(f-n) and _34 = 1; an orthographic one (_34 = 0) is linear already, so its clip z is returned.
float LinearLightDepth(float viewZ, float clipZ)
{
    if (LightProjectionMatrix._34 == 0.0)
        return clipZ;
    float zNear = -LightProjectionMatrix._43 / LightProjectionMatrix._33;
    float zFar = LightProjectionMatrix._33 * zNear / (LightProjectionMatrix._33 - 1.0);
    return (viewZ - zNear) / (zFar - zNear);
}

// Slope-scale bias computed in the shader (Lehőcz 2007: m = max(|dz/dx|, |dz/dy|), the depth slope per
// shadow-map texel; "in practice the total bias is m times a factor plus a constant"): what D3D's
// SlopeScaleDepthBias + DepthBias and OpenGL's glPolygonOffset(factor, units) add in the rasterizer.
float SlopeScaledDepth(float z, float constantBias, float slopeScale)
{
    float m = max(abs(ddx(z)), abs(ddy(z)));
    return z + constantBias + slopeScale * m;
}

// The dual shadow map's depth (Weiskopf & Ertl 2003, eq. 2 and 4): z_dual = z1 + min((z2 - z1) / 2, z_offset). With an
// infinite offset this is Woo's midpoint map (Weiskopf & Ertl 2003, §3). A second layer in front of the first (the
// single-pass variant where the nearest surface faces away from the light) gets no bias rather than a
// negative one.
float DualDepth(float z1, float z2, float zOffset)
{
    return z1 + min(max(z2 - z1, 0.0) * 0.5, zOffset);
}

#endif
