// msm.fxh: moment shadow maps (Peters & Klein 2015, "Moment Shadow Mapping", I3D). The map stores the
// first four power moments b = (z, z^2, z^3, z^4) of the occluders' depth, filtered like colour; a receiver
// at depth z_f takes the sharpest lower bound on the fraction of occluders in front of it that any depth
// distribution with those four moments admits (the Hamburger 4MSM, their §4.1), so the shadow is
// never lighter than some distribution consistent with the filtered map allows.
//
// Two storages: 128 bits (four float32 channels) hold the moments as they are; 64 bits (four 16-bit
// normalized channels) hold them through the affine map of §4.3 ("optimized quantization"), which spreads
// the moments of depths in [0, 1] over [0, 1]^4 so that 16-bit rounding costs little. The map is affine, so
// blurring and mipmapping the quantized values equals quantizing the filtered moments: only the receiver
// converts back.
#ifndef SHADOWFX_MSM_FXH
#define SHADOWFX_MSM_FXH

float4 PowerMoments(float z)
{
    float z2 = z * z;
    return float4(z, z2, z2 * z, z2 * z2);
}

// §4.3's quantization, in HLSL's row-vector form (moments times matrix, then the offset on the first
// component), and its inverse. The constants are the paper's; tests check that the two matrices are
// inverses and that every depth in [0, 1] maps into [0, 1]^4.
static const float4x4 MsmQuantization = {
    -2.07224649,    13.7948857237,  0.105877704,   9.7924062118,
    32.23703778,    -59.4683975703, -1.9077466311, -33.7652110555,
    -68.571074599,  82.0359750338,  9.3496555107,  47.9456096605,
    39.3703274134,  -35.364903257,  -6.6543490743, -23.9728048165};
static const float4x4 MsmDequantization = {
    0.2227744146,   0.1549679261,   0.1451988946,  0.163127443,
    0.0771972861,   0.1394629426,   0.2120202157,  0.2591432266,
    0.7926986636,   0.7963415838,   0.7258694464,  0.6539092497,
    0.0319417555,   -0.1722823173,  -0.2758014811, -0.3376131734};
static const float MsmQuantizationOffset = 0.035955884801;

float4 QuantizeMoments(float4 moments)
{
    float4 q = mul(moments, MsmQuantization);
    q.x += MsmQuantizationOffset;
    return q;
}

float4 DequantizeMoments(float4 quantized)
{
    quantized.x -= MsmQuantizationOffset;
    return mul(quantized, MsmDequantization);
}

// The Hamburger 4MSM (Peters & Klein 2015, §4.1, with the authors' erratum: the last case returns
// 1 - w_1): the shadow intensity (fraction of light blocked)
// of a receiver at `zf` given filtered moments `b`. `momentBias` (their alpha) pulls b toward the moments
// of a uniform spread, (1 - alpha) b + alpha (0.5, 0.5, 0.5, 0.5), so that the Hankel matrix below stays
// positive definite after rounding; the 64-bit storage needs a larger alpha than the 128-bit one.
float Hamburger4MsmShadow(float4 b, float zf, float momentBias)
{
    b = lerp(b, float4(0.5, 0.5, 0.5, 0.5), momentBias);
    // Solve [1 b1 b2; b1 b2 b3; b2 b3 b4] c = (1, zf, zf^2) through its LDL^T (Cholesky) factorization.
    float d22 = b.y - b.x * b.x;
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = b.w - b.y * b.y - l32 * l32 * d22;
    float y2 = zf - b.x;
    float y3 = zf * zf - b.y - l32 * y2;
    float c3 = y3 / d33;
    float c2 = y2 / d22 - l32 * c3;
    float c1 = 1.0 - b.x * c2 - b.y * c3;
    // The roots z2 <= z3 of c3 z^2 + c2 z + c1: with zf, the support of the extremal distribution.
    float p = c2 / c3;
    float q = c1 / c3;
    float r = sqrt(max(p * p * 0.25 - q, 0.0));
    float z2 = -0.5 * p - r;
    float z3 = -0.5 * p + r;
    if (zf <= z2)
        return 0.0;
    if (zf <= z3)
        return saturate((zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2)));
    return saturate(1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3)));
}

#endif
