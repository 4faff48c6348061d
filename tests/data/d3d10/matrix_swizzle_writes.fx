//--------------------------------------------------------------------------------------
// Writes through swizzles, as HLSL defines them: several matrix elements assigned through a swizzle of a
// matrix swizzle (`m._m00_m11.yx = v;`, compound ones too), a whole matrix swizzle passed to an `out` and
// to an `inout` parameter (`f(m._m01_m02)`, the elements copied out after the call, the call's value
// kept), a vector swizzle passed to an `inout` parameter (`f(v.zx)`), and the same on an int2x3. Each of
// 16 threads writes 32 words into a RWByteAddressBuffer (floats by their bits); a pixel shader shows word
// k as the bytes of pixel (k % 128, k / 128). test_matrix_swizzle_writes computes the same words on the
// CPU and compares them bit for bit.
//--------------------------------------------------------------------------------------
RWByteAddressBuffer Words < int ElementCount = 512; >;
ByteAddressBuffer WordView < string ViewOf = "Words"; >;
float4x4 Start = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16 };

void Twice(inout float2 v)
{
    v = v * 2 + float2(1, 3);
}

void Fill(out float3 v)
{
    v = float3(70, 80, 90);
}

float Rotate(inout float3 v)
{
    v = v.zxy;
    return v.x + 100;
}

void Bump(inout int2 v)
{
    v += int2(5, -3);
}

[numthreads(16, 1, 1)]
void Compute(uint i : SV_GroupIndex)
{
    float4x4 m = Start + (float)i;
    m._m00_m11.yx = float2(i, 2 * i);
    m._m22_m23_m32.zx += float2(10, 20);
    Twice(m._m01_m02);
    Fill(m._m30_m31_m33);
    const float rotated = Rotate(m._m10_m12_m13);
    float3 v = float3(i, i + 1, i + 2);
    Twice(v.zx);
    int2x3 e = int2x3(i, 2 * i, 3 * i, 4 * i, 5 * i, 6 * i);
    Bump(e._m02_m10);
    e._m11_m00_m12.zy = int2(-1, -2);

    const uint at = i * 128;
    for (uint k = 0; k < 16; ++k)
        Words.Store(at + 4 * k, asuint(m[k / 4][k % 4]));
    Words.Store(at + 64, asuint(rotated));
    Words.Store(at + 68, asuint(v.x));
    Words.Store(at + 72, asuint(v.y));
    Words.Store(at + 76, asuint(v.z));
    for (uint n = 0; n < 6; ++n)
        Words.Store(at + 80 + 4 * n, asuint(e[n / 3][n % 3]));
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

technique11 SwizzleWrites < string Script = "Pass=Compute; Pass=Show;"; >
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
