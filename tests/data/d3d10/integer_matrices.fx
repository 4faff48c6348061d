//--------------------------------------------------------------------------------------
// Integer and bool matrices as texture-compression compute shaders use them: int2x3 endpoints quantized
// by element-wise shifts, comparisons and selects through an inout parameter, bool2x3 masks, uint2x4
// rows from a static table of uint4x4 (its rows in braces), bit operations, compound assignments (one whose right side reads the matrix),
// abs/min/max/clamp, any/all, conversions, rows and elements indexed by constants and by variables, an
// int2x3 parameter in the $Global block, and |=, &=, ^= on a bool. Each of 64 threads writes eight words into a RWByteAddressBuffer; a
// pixel shader shows word k as the bytes of pixel (k % 128, k / 128). test_integer_matrices computes the
// same words on the CPU and compares them bit for bit.
//--------------------------------------------------------------------------------------
RWByteAddressBuffer Words < int ElementCount = 512; >;
ByteAddressBuffer WordView < string ViewOf = "Words"; >;
int2x3 Offsets = { 1, -2, 3, 4, 5, -6 };
uint Precision = 5;

// Rows in braces, not grouped by matrix: fxc flattened the list.
static const uint4x4 Rotations[2] = {
    {1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16},
    {0x100, 0x2000, 0x30000, 0x400000}, {17, 19, 23, 29}, {31, 37, 41, 43}, {47, 53, 59, 61},
};

// An endpoint quantization: elements at zero stay, the others are scaled by a shift.
void Quantize(inout int2x3 endPoint, uint precision)
{
    const int shift = asint(precision);
    endPoint = ((shift >= 15) | (endPoint == 0)) ? endPoint : ((endPoint << shift) + 0x40) >> 7;
}

int2x3 Mirrored(int2x3 m)
{
    return int2x3(m[1], m[0]);
}

uint RowSum(int3 row)
{
    return asuint(row.x) + 3 * asuint(row.y) + 5 * asuint(row.z);
}

[numthreads(64, 1, 1)]
void Compute(uint i : SV_GroupIndex)
{
    int2x3 e = int2x3(i, -(int)i, 3 * i, i ^ 5, 7 - (int)i, (int)i - 31) + Offsets;
    Quantize(e, Precision);
    const bool2x3 negative = e < 0;
    int2x3 a = abs(e);
    a &= 0x3f;
    const int2x3 n = (e < 0) ? -a : ~a;
    uint2x4 m = uint2x4(Rotations[i & 1][i % 4], Rotations[(i + 1) & 1][(i >> 2) % 4]);
    m = m ^ (m << (i % 7));
    m += 3;
    m ^= m._m00;  // the right side read before any row is written
    const uint2x3 s = e >= 0 ? 0 : 1;
    const uint2x3 c = clamp((uint2x3)a, 2, 40) + (min(s, 1) << 4) + max((uint2x3)a, 9);
    const int2x3 mirrored = Mirrored(e);

    const bool2x3 nonZero = n != 0;
    const bool2x3 atOffsets = e == Offsets;
    uint flags = 0;
    for (uint k = 0; k < 6; ++k)
        flags |= (negative[k / 3][k % 3] ? 1u : 0u) << k;
    flags |= (any(negative) ? 1u : 0u) << 6;
    flags |= (all(nonZero) ? 1u : 0u) << 7;
    flags |= (any(atOffsets) ? 1u : 0u) << 8;
    bool big = e[0].x > 8;
    big |= e[1].y > 1;
    big &= i > 3;
    big ^= (i & 4) != 0;
    flags |= (big ? 1u : 0u) << 9;

    const uint at = i * 32;
    Words.Store(at + 0, RowSum(e[0]));
    Words.Store(at + 4, RowSum(e[1]));
    Words.Store(at + 8, flags);
    Words.Store(at + 12, RowSum(n[0]) ^ (RowSum(n[1]) << 3));
    Words.Store(at + 16, m[0].x ^ (m[0].y * 7) ^ (m[0].z * 13) ^ (m[0].w * 17));
    Words.Store(at + 20, m._m10 ^ (m._m11 * 7) ^ (m._m12 * 13) ^ (m._m13 * 17));
    Words.Store(at + 24, s._m00 + 2 * s._m01 + 4 * s._m02 + 8 * s._m10 + 16 * s._m11 + 32 * s._m12 +
                         (asuint(e[i & 1][i % 3]) << 8));
    Words.Store(at + 28, RowSum(asint(c[0])) + 7 * RowSum(asint(c[1])) + 11 * RowSum(mirrored[0]));
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };

float4 QuadVS(QuadVertex v) : SV_Position
{
    return v.Position;
}

float4 Show(float4 position : SV_Position) : SV_Target
{
    const uint index = (uint)position.y * 128 + (uint)position.x;
    const uint word = index < 512 ? WordView.Load(index * 4) : 0;
    return float4(word & 0xff, (word >> 8) & 0xff, (word >> 16) & 0xff, word >> 24) / 255.0;
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 IntegerMatrices < string Script = "Pass=Compute; Pass=Show;"; >
{
    pass Compute < string Script = "Dispatch=1;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Compute()));
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
