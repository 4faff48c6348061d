// vsm.fxh: variance shadow maps (Donnelly & Lauritzen 2006, as Lehőcz 2007 presents them: "Szórásnégyzet
// shadow map-ek" ). The map stores the first two moments of
// depth (E[z], E[z^2]) in RG32F — the thesis recommends two 32-bit float channels for numerical stability —
// so it can be filtered like a colour texture (bilinear, mipmaps, a separable blur). A receiver at depth t
// is lit at most with the one-tailed Chebyshev bound
//     P(x >= t) <= p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2),   sigma^2 = E[z^2] - E[z]^2,
// for t > mu, and fully lit for t <= mu.
#ifndef SHADOWFX_VSM_FXH
#define SHADOWFX_VSM_FXH

// The moments a depth-map texel stores. The second moment adds the depth's variance inside the pixel's
// footprint, from the depth's screen derivatives (Donnelly & Lauritzen, §3.2), so a sloped surface does
// not shadow itself once the map is filtered.
float2 DepthMoments(float z)
{
    float dx = ddx(z);
    float dy = ddy(z);
    return float2(z, z * z + 0.25 * (dx * dx + dy * dy));
}

// The Chebyshev upper bound for a receiver at depth `t` given filtered `moments`. `minVariance` is the
// numerical-stability guard: E[z^2] - E[z]^2 cancels catastrophically on a flat receiver (both terms
// ~ z^2, their difference at float32 rounding), which without a floor gives a variance of 0 or below and
// p_max of 0 (acne) or NaN (0/0) where t rounds to just above mu.
float ChebyshevUpperBound(float2 moments, float t, float minVariance)
{
    if (t <= moments.x)
        return 1.0;
    float variance = max(moments.y - moments.x * moments.x, minVariance);
    float d = t - moments.x;
    return variance / (variance + d * d);
}

// Light-bleeding reduction (Lauritzen, GPU Gems 3, ch. 8): where several occluders overlap, p_max stays
// above 0 in the umbra; cutting the tail below `amount` and rescaling [amount, 1] to [0, 1] removes that
// bleeding at the price of slightly harder penumbrae.
float ReduceLightBleeding(float pMax, float amount)
{
    return saturate((pMax - amount) / (1.0 - amount));
}

float VarianceShadow(float2 moments, float t, float minVariance, float bleedReduction)
{
    return ReduceLightBleeding(ChebyshevUpperBound(moments, t, minVariance), bleedReduction);
}

#endif
