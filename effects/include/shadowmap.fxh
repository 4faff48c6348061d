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

// The same two tests in Direct3D 10's form: the map a Texture2D read through a (point) SamplerState.
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

#endif
