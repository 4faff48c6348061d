// light_size.fxh: the geometry of an area light seen from the shadow map, shared by the soft-shadow effects
// (pcss.fx, fractional_disk.fx): light-view distances from the map's z/w depths, the distance from a
// receiver to the light's disk, and world lengths on the receiver converted to shadow-map texels.
//
// The light is a disk of radius `LightAreaRadius` facing the receiver (runtime/measure/src/GroundTruth.cpp, the soft
// truth). A spot light's disk sits at its position, i.e. at the light view's origin. A directional light's
// disk sits `2 R + |scene centre|` from every receiver along the light direction (R: the scene radius), the
// distance the runtime places its view at (Light::view); R is read back from the orthographic projection
// (x scale 1 / R) and the scene centre from the view's eye (centre = eye + 2 R * direction).
// Include shadowscene.fxh first (the light matrices).
#ifndef SHADOWFX_LIGHT_SIZE_FXH
#define SHADOWFX_LIGHT_SIZE_FXH

float LightRadius : LightAreaRadius <string Object = "light0"; string UIWidget = "None";>;

bool LightIsOrthographic()
{
    return LightProjectionMatrix._34 == 0.0;
}

// Light-view z of a stored clip depth z/w: clip.z = zv P33 + P43 and clip.w = zv P34 + P44, solved for zv.
float LightViewDepth(float clipDepth)
{
    float4x4 P = LightProjectionMatrix;
    return (P._43 - clipDepth * P._44) / (clipDepth * P._34 - P._33);
}

// Light-view z of the near plane, the closest any occluder in the map can be to the light.
float LightNearDepth()
{
    return LightViewDepth(0.0);
}

// Distance from a receiver at light-view depth `receiverDepth` to the plane of the light's disk.
float ReceiverToLight(float receiverDepth)
{
    if (!LightIsOrthographic())
        return receiverDepth;
    float4x4 V = LightViewMatrix;
    // Eye position of a row-vector view matrix [R 0; t 1]: -t R^T.
    float3 eye = -float3(dot(V[3].xyz, V[0].xyz), dot(V[3].xyz, V[1].xyz), dot(V[3].xyz, V[2].xyz));
    float3 direction = float3(V._13, V._23, V._33);
    float sceneRadius = 1.0 / LightProjectionMatrix._11;
    return 2.0 * sceneRadius + length(eye + 2.0 * sceneRadius * direction);
}

// Shadow-map texels per world unit at the receiver (light clip w is 1 for orthographic lights, the depth
// for perspective ones): x scale P11 maps a world length to clip units, 2 clip units span the map.
float TexelsPerWorldUnit(float4 receiverClip, float mapSize)
{
    return 0.5 * mapSize * LightProjectionMatrix._11 / receiverClip.w;
}

// Penumbra radius, in world units on the receiver, of an occluder `receiverDepth - blockerDepth` in front of
// the receiver: Valient & de Boer 2004's q = (d2 / d1) r (eq. 1, Fig. 1b) with
// d2 the receiver's distance to the occluder and d1 the occluder's to the light; Fernando's PCSS estimate.
// A directional light's disk stays ReceiverToLight from every receiver (it has an angular size, r / D, not a
// position), so the cone from a receiver to it has radius r d2 / D at the occluder: q = r d2 / D.
float PenumbraRadiusWorld(float receiverDepth, float blockerDepth, float lightRadius)
{
    float d2 = max(receiverDepth - blockerDepth, 0.0);
    float d1 = LightIsOrthographic() ? ReceiverToLight(receiverDepth) : max(blockerDepth, 1e-4);
    return lightRadius * d2 / d1;
}

#endif
