//--------------------------------------------------------------------------------------
// Two read-write buffers of one element type in one shader: the compute shader writes 64 into First and
// 192 into Second. The pixel shader reads both (red: First, green: Second) and the vertex shader Second
// alone (blue), so that one stage's GLSL declares one of the two blocks and the other's both. Buffers
// that reached one another would show one value in two channels.
//--------------------------------------------------------------------------------------
RWStructuredBuffer<uint> First < int ElementCount = 4; >;
RWStructuredBuffer<uint> Second < int ElementCount = 4; >;

[numthreads(4, 1, 1)]
void Fill(uint index : SV_GroupIndex)
{
    First[index] = 64;
    Second[index] = 192;
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct ShowVertex
{
    float4 Position : SV_Position;
    nointerpolation float Blue : TEXCOORD0;
};

ShowVertex QuadVS(QuadVertex v)
{
    ShowVertex OUT;
    OUT.Position = v.Position;
    OUT.Blue = Second[1] / 255.0;
    return OUT;
}

float4 Show(ShowVertex IN) : SV_Target
{
    return float4(First[2] / 255.0, Second[3] / 255.0, IN.Blue, 1);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 SameType < string Script = "Pass=Fill; Pass=Show;"; >
{
    pass Fill < string Script = "Dispatch=1;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Fill()));
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
