//--------------------------------------------------------------------------------------
// A reduction through groupshared memory into a RWByteAddressBuffer: the 64 threads of one group store
// their index in a groupshared array, wait for each other, and the first sums them (2016) into word 0. A
// pixel shader reads the word through a ByteAddressBuffer view: red where the sum is right, green the sum
// over 4032 (one half).
//--------------------------------------------------------------------------------------
RWByteAddressBuffer Sums < int ElementCount = 4; >;
ByteAddressBuffer SumView < string ViewOf = "Sums"; >;
groupshared uint Partial[64];

[numthreads(64, 1, 1)]
void Reduce(uint index : SV_GroupIndex)
{
    Partial[index] = index;
    GroupMemoryBarrierWithGroupSync();
    if (index == 0)
    {
        uint sum = 0;
        for (uint k = 0; k < 64; k++)
            sum += Partial[k];
        Sums.Store(0, sum);
    }
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };

float4 QuadVS(QuadVertex v) : SV_Position
{
    return v.Position;
}

float4 Show(float4 position : SV_Position) : SV_Target
{
    const uint sum = SumView.Load(0);
    return float4(sum == 2016 ? 1 : 0, sum / 4032.0, position.x < 8 ? 1 : 0, 1);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Reduction < string Script = "Pass=Reduce; Pass=Show;"; >
{
    pass Reduce < string Script = "Dispatch=1;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Reduce()));
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
