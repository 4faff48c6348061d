// shadowmap.fxh: shadow-map addressing and filtering shared by the shadow effects.
//
// Texture conventions (D3D10 and OpenGL, which shadowfx follows): texel centres lie at (i + 0.5) / size, and
// v = 0 is the top row of a render target. D3D9 put texel centres at integer coordinates, which is why the
// thesis listing (Lehőcz 2007, "Forráskódok") adds 0.5 / SHADOW_SIZE to its lookups; here that offset is gone.
#ifndef SHADOWFX_SHADOWMAP_FXH
#define SHADOWFX_SHADOWMAP_FXH

// Light clip space -> shadow-map texture coordinates (x right, v down).
float2 ShadowMapUV(float4 lightClip)
{
    return float2(0.5, -0.5) * lightClip.xy / lightClip.w + float2(0.5, 0.5);
}

// 1 where the stored occluder depth is not in front of `depth`, 0 where it is.
float ShadowTest(sampler2D shadowMap, float2 uv, float depth)
{
    return tex2D(shadowMap, uv).x >= depth ? 1.0 : 0.0;
}

// The receiver plane's depth change per shadow-map texel along u and v (receiver-plane depth bias, Isidoro
// 2006): (d depth / d screen) (d texel / d screen)^-1, from the change per screen pixel along x and y of the
// map position in texels (texelX, texelY) and of the depth (depthXY); a degenerate Jacobian (the plane seen
// edge-on) divides by 1e-12.
float2 DepthPerTexel(float2 texelX, float2 texelY, float2 depthXY)
{
    float determinant = texelX.x * texelY.y - texelX.y * texelY.x;
    return float2(depthXY.x * texelY.y - depthXY.y * texelX.y, depthXY.y * texelX.x - depthXY.x * texelY.x) /
           (abs(determinant) > 1e-12 ? determinant : 1e-12);
}

// DepthPerTexel from the screen derivatives of `texel` (the map position in texels) and `depth`.
float2 ReceiverPlaneDepthPerTexel(float2 texel, float depth)
{
    return DepthPerTexel(ddx(texel), ddy(texel), float2(ddx(depth), ddy(depth)));
}

// Adaptive depth bias (Dou et al. 2014, §3): the light depth z/w at which the ray through the map position
// `centre` (light NDC x, y: a texel's centre, where the map's rasterizer sampled the occluder) meets the
// receiver's tangent plane, the plane through the receiver (light clip position `clip`) with world normal
// `normal`. `toLightClip` maps world space to light clip space (row vectors). The ray is where the planes
// clip.x = centre.x clip.w and clip.y = centre.y clip.w of world space meet; the hit is the receiver moved
// by the world offset that Cramer's rule gives for the three planes, so orthographic and perspective lights
// alike are exact, and no world position is needed. A tangent plane that contains the ray (the light exactly
// edge-on) has no hit: the receiver's own depth.
float TangentPlaneDepth(float4x4 toLightClip, float4 clip, float3 normal, float2 centre)
{
    float3 w = float3(toLightClip._14, toLightClip._24, toLightClip._34);
    float3 planeX = float3(toLightClip._11, toLightClip._21, toLightClip._31) - centre.x * w;
    float3 planeY = float3(toLightClip._12, toLightClip._22, toLightClip._32) - centre.y * w;
    float offX = clip.x - centre.x * clip.w;
    float offY = clip.y - centre.y * clip.w;
    float3 ray = cross(planeX, planeY);
    float determinant = dot(normal, ray);
    if (abs(determinant) <= 1e-7 * length(normal) * length(ray))
        return clip.z / clip.w;
    float3 offset = -(offX * cross(planeY, normal) + offY * cross(normal, planeX)) / determinant;
    float4 hit = clip + mul(float4(offset, 0.0), toLightClip);
    return hit.z / hit.w;
}

// The depth a point test at the receiver (light clip position `clip`, world normal `normal`) compares: its
// tangent plane at the centre of the texel the lookup reads (TangentPlaneDepth), at most its own depth, less
// `bias`. Returns that texel's centre in texture coordinates (xy) and the depth (z).
float3 TangentPlaneTexelTest(float4x4 toLightClip, float4 clip, float3 normal, float2 mapSize, float bias)
{
    float2 centre = (floor(ShadowMapUV(clip) * mapSize) + 0.5) / mapSize;
    float planeDepth = TangentPlaneDepth(toLightClip, clip, normal, float2(2.0, -2.0) * centre + float2(-1.0, 1.0));
    return float3(centre, min(planeDepth, clip.z / clip.w) - bias);
}

// The receiver's tangent plane (TangentPlaneDepth) as a light depth per map texel: its change along u and v,
// from the plane's depth one texel away along each. A plane's z/w is affine in the map position, for
// orthographic and perspective lights alike, so the two differences are exact for any distance; 0 where the
// light meets the plane edge-on (TangentPlaneDepth's fallback).
float2 TangentPlaneDepthPerTexel(float4x4 toLightClip, float4 clip, float3 normal, float2 mapSize)
{
    float2 ndc = clip.xy / clip.w;
    return float2(TangentPlaneDepth(toLightClip, clip, normal, ndc + float2(2.0 / mapSize.x, 0.0)),
                  TangentPlaneDepth(toLightClip, clip, normal, ndc - float2(0.0, 2.0 / mapSize.y))) -
           clip.z / clip.w;
}

// A receiver as the filters of pcf.fxh test it: each tap compares the receiver's tangent plane at the centre
// of the texel it reads (where the map's rasterizer sampled the occluder), or the receiver's own depth where
// that is nearer the light, less `bias`. A kernel many texels wide crosses a sloped receiver's depth range
// tap by tap, where one depth for all taps needs a bias as large as the kernel's slope.
struct ReceiverPlane
{
    float2 texel;     // the receiver's map position in texels
    float depth;      // its light depth z/w
    float2 perTexel;  // TangentPlaneDepthPerTexel
    float bias;
};

ReceiverPlane TangentReceiverPlane(float4x4 toLightClip, float4 clip, float3 normal, float2 mapSize, float bias)
{
    ReceiverPlane plane;
    plane.texel = ShadowMapUV(clip) * mapSize;
    plane.depth = clip.z / clip.w;
    plane.perTexel = TangentPlaneDepthPerTexel(toLightClip, clip, normal, mapSize);
    plane.bias = bias;
    return plane;
}

// The depth `plane` compares at the texel whose centre is `centre` (in texels).
float PlaneDepthAt(ReceiverPlane plane, float2 centre)
{
    return min(plane.depth + dot(plane.perTexel, centre - plane.texel), plane.depth) - plane.bias;
}

// One point test at `uv` against the plane at the centre of the texel it reads.
float ShadowTestPlane(sampler2D shadowMap, float2 uv, float2 mapSize, ReceiverPlane plane)
{
    return ShadowTest(shadowMap, uv, PlaneDepthAt(plane, floor(uv * mapSize) + 0.5));
}

// The least of the plane's depths at the 2x2 texels a bilinear lookup at `uv` reads: one depth for a
// comparison sampler's four taps, nearer the light than each tap's own plane depth by at most one texel's
// slope.
float PlaneDepthBilinear(float2 uv, float2 mapSize, ReceiverPlane plane)
{
    float2 first = floor(uv * mapSize - 0.5) + 0.5;
    return min(min(PlaneDepthAt(plane, first), PlaneDepthAt(plane, first + float2(1.0, 0.0))),
               min(PlaneDepthAt(plane, first + float2(0.0, 1.0)), PlaneDepthAt(plane, first + 1.0)));
}

// Bilinear PCF under the adaptive bias: the 2x2 taps around the receiver (light clip position `clip`) in a
// map, or an atlas tile, `tileSize` texels wide whose light clip space `toLightClip` maps to. Each tap is
// compared at the receiver's tangent plane at its own texel centre (TangentPlaneDepth), or at the
// receiver's own depth where that is nearer the light (the plane never moves a receiver away from it), less
// `epsilon`. The taps stay inside the tile.
struct TangentPlaneTaps
{
    float2 first;   // tile texel coordinates of tap 00's centre; taps 10, 01, 11 lie one texel right, down
    float2 weight;  // the bilinear weights of taps 10 and 11 (x), 01 and 11 (y)
    float4 depths;  // the compared depths of taps 00, 10, 01, 11
};

TangentPlaneTaps TangentPlaneBilinearTaps(float4x4 toLightClip, float4 clip, float3 normal, float2 tileSize,
                                          float epsilon)
{
    TangentPlaneTaps taps;
    float2 position = ShadowMapUV(clip) * tileSize - 0.5;
    float2 first = clamp(floor(position), 0.0, tileSize - 2.0);
    taps.first = first + 0.5;
    taps.weight = saturate(position - first);
    // Tile texels -> light NDC (v down, y up).
    float2 ndc = float2(2.0, -2.0) * taps.first / tileSize + float2(-1.0, 1.0);
    float2 step = float2(2.0, -2.0) / tileSize;
    taps.depths = float4(TangentPlaneDepth(toLightClip, clip, normal, ndc),
                         TangentPlaneDepth(toLightClip, clip, normal, ndc + float2(step.x, 0.0)),
                         TangentPlaneDepth(toLightClip, clip, normal, ndc + float2(0.0, step.y)),
                         TangentPlaneDepth(toLightClip, clip, normal, ndc + step));
    taps.depths = min(taps.depths, clip.z / clip.w) - epsilon;
    return taps;
}

// The taps' bilinear PCF in the texture whose region `rect` (offset xy, size zw, in texture coordinates)
// holds the tile.
float ShadowTestTaps(sampler2D shadowMap, float4 rect, float2 tileSize, TangentPlaneTaps taps)
{
    float2 scale = rect.zw / tileSize;
    float2 uv = rect.xy + taps.first * scale;
    float s00 = ShadowTest(shadowMap, uv, taps.depths.x);
    float s10 = ShadowTest(shadowMap, uv + float2(scale.x, 0.0), taps.depths.y);
    float s01 = ShadowTest(shadowMap, uv + float2(0.0, scale.y), taps.depths.z);
    float s11 = ShadowTest(shadowMap, uv + scale, taps.depths.w);
    return lerp(lerp(s00, s10, taps.weight.x), lerp(s01, s11, taps.weight.x), taps.weight.y);
}

// ShadowTestTaps on a depth target: each tap compared in hardware by `depthSampler`, a point-filtered
// sampler of a RENDERDEPTHSTENCILTARGET texture (tex2D with the depth in z returns the comparison).
float ShadowCompareTaps(sampler2D depthSampler, float4 rect, float2 tileSize, TangentPlaneTaps taps)
{
    float2 scale = rect.zw / tileSize;
    float2 uv = rect.xy + taps.first * scale;
    float s00 = tex2D(depthSampler, float3(uv, taps.depths.x)).x;
    float s10 = tex2D(depthSampler, float3(uv + float2(scale.x, 0.0), taps.depths.y)).x;
    float s01 = tex2D(depthSampler, float3(uv + float2(0.0, scale.y), taps.depths.z)).x;
    float s11 = tex2D(depthSampler, float3(uv + scale, taps.depths.w)).x;
    return lerp(lerp(s00, s10, taps.weight.x), lerp(s01, s11, taps.weight.x), taps.weight.y);
}

// Bilinear percentage-closer filtering (Lehőcz 2007, "Percentage closer filtering"): the four nearest texels
// are compared with `depth` and the results are weighted by the fractional texel position of `uv`.
float ShadowTestBilinear(sampler2D shadowMap, float2 uv, float depth, float2 mapSize)
{
    float2 texel = uv * mapSize - 0.5;
    float2 weight = frac(texel);
    float2 base = (floor(texel) + 0.5) / mapSize;
    float2 step = 1.0 / mapSize;
    float s00 = ShadowTest(shadowMap, base, depth);
    float s10 = ShadowTest(shadowMap, base + float2(step.x, 0), depth);
    float s01 = ShadowTest(shadowMap, base + float2(0, step.y), depth);
    float s11 = ShadowTest(shadowMap, base + step, depth);
    return lerp(lerp(s00, s10, weight.x), lerp(s01, s11, weight.x), weight.y);
}

// The same tests in Direct3D 10's form: the map a Texture2D read through a (point) SamplerState.
float ShadowTest(Texture2D shadowMap, SamplerState pointSampler, float2 uv, float depth)
{
    return shadowMap.Sample(pointSampler, uv).x >= depth ? 1.0 : 0.0;
}

float ShadowTestBilinear(Texture2D shadowMap, SamplerState pointSampler, float2 uv, float depth, float2 mapSize)
{
    float2 texel = uv * mapSize - 0.5;
    float2 weight = frac(texel);
    float2 base = (floor(texel) + 0.5) / mapSize;
    float2 step = 1.0 / mapSize;
    float s00 = ShadowTest(shadowMap, pointSampler, base, depth);
    float s10 = ShadowTest(shadowMap, pointSampler, base + float2(step.x, 0), depth);
    float s01 = ShadowTest(shadowMap, pointSampler, base + float2(0, step.y), depth);
    float s11 = ShadowTest(shadowMap, pointSampler, base + step, depth);
    return lerp(lerp(s00, s10, weight.x), lerp(s01, s11, weight.x), weight.y);
}

float ShadowTestTaps(Texture2D shadowMap, SamplerState pointSampler, float4 rect, float2 tileSize,
                     TangentPlaneTaps taps)
{
    float2 scale = rect.zw / tileSize;
    float2 uv = rect.xy + taps.first * scale;
    float s00 = ShadowTest(shadowMap, pointSampler, uv, taps.depths.x);
    float s10 = ShadowTest(shadowMap, pointSampler, uv + float2(scale.x, 0.0), taps.depths.y);
    float s01 = ShadowTest(shadowMap, pointSampler, uv + float2(0.0, scale.y), taps.depths.z);
    float s11 = ShadowTest(shadowMap, pointSampler, uv + scale, taps.depths.w);
    return lerp(lerp(s00, s10, taps.weight.x), lerp(s01, s11, taps.weight.x), taps.weight.y);
}

#endif
