// pcf.fxh: percentage-closer filtering kernels (Reeves 1987) over a point-sampled depth map, shared by the
// shadow effects. Each returns the lit fraction of its samples: 1 lit, 0 shadowed.
//
// `shadowMap` holds light clip-space depth in its red channel and must be point-sampled (MinFilter and
// MagFilter POINT): filtering the depths before the test would average occluder depths, not results.
// Kernel sizes are in shadow-map texels; each tap tests the receiver's plane at its own texel (ReceiverPlane).
// Include shadowmap.fxh first.
#ifndef SHADOWFX_PCF_FXH
#define SHADOWFX_PCF_FXH

// The 4x4 jitter matrix of Weiskopf & Ertl 2003 (Weiskopf & Ertl, §4: "a filtering by a 4x4 jitter matrix ... based
// on an ATI shadow demo" ): one sample per cell of a 4x4 grid
// over [-1, 1]^2, each moved by a fixed offset inside its cell so that the samples do not line up in rows
// and columns (stratified sampling). Offsets in cell units, from a fixed table (no runtime randomness).
static const float2 kJitter4x4[16] = {
    float2(0.28, 0.61), float2(0.83, 0.17), float2(0.44, 0.92), float2(0.07, 0.36),
    float2(0.69, 0.48), float2(0.13, 0.79), float2(0.95, 0.66), float2(0.52, 0.05),
    float2(0.31, 0.24), float2(0.88, 0.93), float2(0.04, 0.57), float2(0.61, 0.33),
    float2(0.76, 0.72), float2(0.19, 0.08), float2(0.47, 0.41), float2(0.92, 0.29)};

// Centre of grid cell `i` (row-major 4x4 over [-1, 1]^2) moved by `jitter` (in cell units, [0, 1)^2).
float2 GridSample4x4(int i, float2 jitter)
{
    float2 cell = float2(i % 4, i / 4);
    return (cell + jitter) * 0.5 - 1.0;
}

// 16 point tests on the jittered 4x4 grid spanning `radius` texels around `uv` (Weiskopf & Ertl 2003).
float ShadowTestJittered4x4(sampler2D shadowMap, float2 uv, ReceiverPlane plane, float2 mapSize, float radius)
{
    float lit = 0;
    for (int i = 0; i < 16; ++i)
        lit += ShadowTestPlane(shadowMap, uv + GridSample4x4(i, kJitter4x4[i]) * radius / mapSize, mapSize, plane);
    return lit / 16.0;
}

// The same 4x4 grid with per-sample offsets read from a noise texture addressed by the receiver's
// light-space position (Lehőcz 2007, "Percentage closer filtering": "address the noise texture in light space
// by x, y, so two consecutive frames get the same random number at the same place"; animated noise draws
// attention to the shadow's edges ). `noiseUV` is that
// light-space address; each sample reads its own texel by a fixed step through the texture.
float ShadowTestNoiseJittered(sampler2D shadowMap, sampler2D noise, float2 uv, float2 noiseUV,
                              ReceiverPlane plane, float2 mapSize, float radius)
{
    float lit = 0;
    for (int i = 0; i < 16; ++i) {
        float2 jitter = tex2D(noise, noiseUV + float2(i * 0.1234, i * 0.3457)).xy;
        lit += ShadowTestPlane(shadowMap, uv + GridSample4x4(i, jitter) * radius / mapSize, mapSize, plane);
    }
    return lit / 16.0;
}

// A Poisson disk of 32 points in the unit disk, by dart throwing (Python's random, seeds 5 and 7): the first
// 16 keep a minimum distance of 0.40 and are a Poisson disk of their own, the other 16 fill in with a
// minimum distance of 0.26, so `count` 16 or 32 both cover the disk evenly.
static const float2 kPoissonDisk[32] = {
    float2(-0.041, -0.788), float2(0.834, -0.315), float2(-0.166, 0.037), float2(-0.576, -0.782),
    float2(0.719, 0.620), float2(0.015, 0.685), float2(-0.659, -0.330), float2(0.689, -0.712),
    float2(0.422, -0.164), float2(-0.898, 0.109), float2(0.977, 0.141), float2(-0.359, 0.464),
    float2(-0.718, 0.676), float2(0.214, 0.213), float2(0.378, 0.908), float2(0.016, -0.323),
    float2(0.332, 0.462), float2(0.725, 0.355), float2(0.303, -0.577), float2(-0.228, 0.898),
    float2(-0.370, -0.209), float2(-0.741, 0.362), float2(-0.354, -0.591), float2(0.047, 0.417),
    float2(-0.481, 0.046), float2(0.178, -0.932), float2(0.145, -0.046), float2(-0.308, -0.877),
    float2(0.586, 0.108), float2(-0.943, -0.287), float2(-0.847, -0.531), float2(0.567, -0.437)};

// `count` (1..32) point tests on the Poisson disk of `radius` texels, rotated by `angle` (radians; from a
// light-space noise texture, so the pattern stays put between frames).
float ShadowTestPoisson(sampler2D shadowMap, float2 uv, ReceiverPlane plane, float2 mapSize, float radius,
                        int count, float angle)
{
    float2x2 rotation = float2x2(cos(angle), sin(angle), -sin(angle), cos(angle));
    int n = clamp(count, 1, 32);
    float lit = 0;
    for (int i = 0; i < n; ++i)
        lit += ShadowTestPlane(shadowMap, uv + mul(kPoissonDisk[i], rotation) * radius / mapSize, mapSize, plane);
    return lit / n;
}

#endif
