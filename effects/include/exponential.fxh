// exponential.fxh: the exponential filters of a shadow map's depth.
//
// Exponential shadow maps (Annen, Mertens, Seidel, Flerackers & Kautz 2008, "Exponential Shadow Maps"):
// the shadow test 1(z >= d) of a receiver at depth d against an occluder at z is approximated by
// exp(-c (d - z)), which is separable, exp(-c d) exp(c z): the map stores exp(c z) and may then be filtered
// like colour (blur, mipmaps). Where the approximation holds (d >= z, the receiver behind the occluder), the
// filtered visibility is E[exp(c z)] exp(-c d); receivers in front of the filtered occluder saturate to 1.
//
// Exponential variance shadow maps (Lauritzen & McCool 2008, "Layered Variance Shadow Maps"): the
// depth is warped by exp(c+ x) and -exp(-c- x), x = 2 d - 1, and each warp's first two moments are stored;
// Chebyshev's bound (vsm.fxh) on each warped distribution, the smaller of the two, bounds the visibility.
// The warps make the bound nearly tight where variance shadow maps leak light.
//
// What the exponents may be is set by the storage format (the "clamps" below): the largest stored value
// must not overflow, and for ESM the smallest must not underflow.
#ifndef SHADOWFX_EXPONENTIAL_FXH
#define SHADOWFX_EXPONENTIAL_FXH

#include "vsm.fxh"

// [SECTION] Exponential shadow maps

// Largest ESM exponent per storage format. The map stores exp(c (z - 1)) in (0, 1] rather than exp(c z), so
// that it clears to 1 like every other map here and never overflows; the limit is the smallest positive
// normal value at z = 0: exp(-c) >= 2^-126 (float32: c <= 87.3) or 2^-14 (float16: c <= 9.7).
static const float EsmMaxExponentFloat32 = 87.0;
static const float EsmMaxExponentFloat16 = 9.7;

// What an ESM texel stores for an occluder at light depth `z` (in [0, 1]).
float EsmOccluder(float z, float exponent)
{
    return exp(exponent * (z - 1.0));
}

// The visibility of a receiver at depth `d` from a filtered ESM texel: E[exp(c (z - 1))] exp(c (1 - d)),
// that is E[exp(-c (d - z))], at most 1.
float EsmVisibility(float filteredOccluder, float d, float exponent)
{
    return saturate(filteredOccluder * exp(exponent * (1.0 - d)));
}

// [SECTION] Exponential variance shadow maps

// Largest EVSM exponent per storage format: the second moment exp(2 c x) at x = 1, summed over a blur of up
// to 31 taps before the division, must stay below the largest finite value: 2 c <= ln(FLT_MAX / 31)
// (float32: c <= 42.6) or ln(65504 / 31) (float16: c <= 3.8).
static const float EvsmMaxExponentFloat32 = 42.0;
static const float EvsmMaxExponentFloat16 = 3.8;

// The warped depths (positive, negative) of light depth `d` in [0, 1].
float2 EvsmWarp(float d, float2 exponents)
{
    float x = 2.0 * d - 1.0;
    return float2(exp(exponents.x * x), -exp(-exponents.y * x));
}

// What an EVSM texel stores for an occluder at depth `z`: both warps' first two moments (EVSM4); EVSM2 keeps
// the first two components.
float4 EvsmMoments(float z, float2 exponents)
{
    float2 w = EvsmWarp(z, exponents);
    return float4(w.x, w.x * w.x, w.y, w.y * w.y);
}

// Chebyshev's bound on one warped distribution. `minVariance` is in units of depth squared; the warp
// stretches depth by dw/dd = 2 c w at the receiver, so the floor scales by its square.
float EvsmWarpedBound(float2 moments, float warpedDepth, float exponent, float minVariance)
{
    float stretch = 2.0 * exponent * warpedDepth;
    return ChebyshevUpperBound(moments, warpedDepth, minVariance * stretch * stretch);
}

// EVSM2: the positive warp alone.
float Evsm2Visibility(float2 moments, float d, float exponent, float minVariance, float bleedReduction)
{
    float w = EvsmWarp(d, float2(exponent, 0)).x;
    return ReduceLightBleeding(EvsmWarpedBound(moments, w, exponent, minVariance), bleedReduction);
}

// EVSM4: the smaller of the two warps' bounds.
float Evsm4Visibility(float4 moments, float d, float2 exponents, float minVariance, float bleedReduction)
{
    float2 w = EvsmWarp(d, exponents);
    float positive = EvsmWarpedBound(moments.xy, w.x, exponents.x, minVariance);
    float negative = EvsmWarpedBound(moments.zw, w.y, exponents.y, minVariance);
    return ReduceLightBleeding(min(positive, negative), bleedReduction);
}

#endif
