//--------------------------------------------------------------------------------------
// The read-write resources beside RWTexture2D, each written by one compute pass and read by a pixel shader
// through a view of it: an RWTexture1D ramp, an RWTexture3D volume, an RWTexture2DArray of single floats
// and an RWBuffer. The frame is four bands from the top, eight columns each; column c shows
//   band 0: Ramp[c] = (c / 7, 0, 0)
//   band 1: Volume[c % 4, c / 4, 3] = ((c % 4) / 3, (c / 4) / 3, 1)
//   band 2: Layers[c % 4, 0, c / 4 + 1] = (c / 4 + 2) / 4 in every channel
//   band 3: Values[c] = (0, 0, c / 7)
//--------------------------------------------------------------------------------------
RWTexture1D<float4> Ramp < int Width = 8; >;
RWTexture3D<float4> Volume < int Width = 4; int Height = 4; int Depth = 4; >;
RWTexture2DArray<float> Layers < int Width = 4; int Height = 4; int ArraySize = 3; >;
RWBuffer<float4> Values < int ElementCount = 8; >;

Texture1D RampView < string ViewOf = "Ramp"; >;
Texture3D VolumeView < string ViewOf = "Volume"; >;
Texture2DArray LayersView < string ViewOf = "Layers"; >;
Buffer<float4> ValuesView < string ViewOf = "Values"; >;

[numthreads(8, 4, 4)]
void Fill(uint3 id : SV_DispatchThreadID)
{
    if (id.y == 0 && id.z == 0)
    {
        Ramp[id.x] = float4(id.x / 7.0, 0, 0, 1);
        Values[id.x] = float4(0, 0, id.x / 7.0, 1);
    }
    if (id.x < 4)
        Volume[id] = float4(id / 3.0, 1);
    if (id.x < 4 && id.z < 3)
        Layers[id] = (id.z + 1) / 4.0;
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
    const uint column = min(uint(i.UV.x * 8), 7), band = min(uint(i.UV.y * 4), 3);
    if (band == 0)
        return RampView.Load(int2(column, 0));
    if (band == 1)
        return VolumeView.Load(int4(column % 4, column / 4, 3, 0));
    if (band == 2)
    {
        const float v = LayersView.Load(int4(column % 4, 0, column / 4 + 1, 0)).x;
        return float4(v, v, v, 1);
    }
    return ValuesView.Load(column);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Kinds < string Script = "Pass=Fill; Pass=Show;"; >
{
    pass Fill < string Script = "Dispatch=1,1,1;"; >
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
