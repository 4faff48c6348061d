//--------------------------------------------------------------------------------------
// One pass that sets a compute shader and graphics shaders, as FX11 allowed: its script dispatches the
// compute stage, which adds (0.1, 0.2) to the colour kept in a RWStructuredBuffer, and then draws the frame
// with the pixel shader reading that colour through a StructuredBuffer view. After n dispatches the frame
// is (0.1 n, 0.2 n, 0.5) everywhere.
//--------------------------------------------------------------------------------------
RWStructuredBuffer<float4> Accumulated < int ElementCount = 1; >;
StructuredBuffer<float4> Shade < string ViewOf = "Accumulated"; >;

[numthreads(1, 1, 1)]
void Step()
{
    Accumulated[0] += float4(0.1, 0.2, 0, 0);
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };

float4 QuadVS(QuadVertex v) : SV_Position
{
    return v.Position;
}

float4 Show() : SV_Target
{
    return float4(Shade[0].xy, 0.5, 1);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 StepAndShow
{
    pass Both < string Script = "Dispatch=1; RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Step()));
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
