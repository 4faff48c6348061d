//--------------------------------------------------------------------------------------
// Sparks appended by one compute pass and consumed by another, in the style of FX11 compute-particle
// effects that keep their live particles in an AppendStructuredBuffer: pass Emit appends eight sparks a
// frame (the even threads of sixteen, Tag 1..8), pass Take consumes one through a ConsumeStructuredBuffer
// view of the same buffer and keeps it in Taken, and pass Draw shows the buffer as an 8 x 8 grid of cells,
// row after row from the top left: cell k is lit (red, green Tag / 8) where element k holds a spark. The
// counter persists between frames and passes, so after frame n it stands at 7n and cells 0 .. 7n are lit
// (the consumed top element stays in the buffer until the next frame's sparks overwrite it). The last
// cell shows the consumed spark's Tag in blue. Everything is in clip space: no camera is involved.
//--------------------------------------------------------------------------------------
struct Spark
{
    float2 Position;
    float  Tag;
};

AppendStructuredBuffer<Spark> Live < int ElementCount = 64; >;
ConsumeStructuredBuffer<Spark> Spent < string ViewOf = "Live"; >;
StructuredBuffer<Spark> Sparks < string ViewOf = "Live"; >;
RWStructuredBuffer<Spark> Taken < int ElementCount = 1; >;
StructuredBuffer<Spark> TakenView < string ViewOf = "Taken"; >;

[numthreads(16, 1, 1)]
void Emit(uint3 id : SV_DispatchThreadID)
{
    if (id.x % 2 == 0)
    {
        Spark s;
        s.Position = float2(id.x, 0);
        s.Tag = 1 + id.x / 2;
        Live.Append(s);
    }
}

[numthreads(1, 1, 1)]
void Take()
{
    Taken[0] = Spent.Consume();
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };

QuadOut QuadVS(QuadVertex v)
{
    QuadOut o;
    o.Position = v.Position;
    o.UV = v.UV;
    return o;
}

float4 Show(QuadOut i) : SV_Target
{
    const uint column = min(uint(i.UV.x * 8), 7), row = min(uint(i.UV.y * 8), 7);
    const uint cell = row * 8 + column;
    if (cell == 63)
        return float4(0, 0, TakenView[0].Tag / 8, 1);
    const Spark s = Sparks[cell];
    return s.Tag > 0 ? float4(1, s.Tag / 8, 0, 1) : float4(0, 0, 0, 1);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Sparks < string Script = "Pass=Emit; Pass=Take; Pass=Draw;"; >
{
    pass Emit < string Script = "Dispatch=1,1,1;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Emit()));
    }
    pass Take < string Script = "Dispatch=1,1,1;"; >
    {
        SetComputeShader(CompileShader(cs_5_0, Take()));
    }
    pass Draw < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
