//--------------------------------------------------------------------------------------
// A RWTexture2D written by a compute pass and sampled by a pixel shader through a Texture2D view of it:
// texel (x, y) of the 32 x 16 image holds (x / 31, y / 15, 0.5); the pixel pass stretches it over the
// frame with point sampling, so the frame's left edge is black-red, its right edge red, its top green 0
// and its bottom green 1.
//--------------------------------------------------------------------------------------
RWTexture2D<float4> Field < int Width = 32; int Height = 16; >;
Texture2D FieldView < string ViewOf = "Field"; >;
SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };

[numthreads(8, 8, 1)]
void Fill(uint3 id : SV_DispatchThreadID)
{
    Field[id.xy] = float4(id.x / 31.0, id.y / 15.0, 0.5, 1);
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
    return FieldView.Sample(PointClamp, i.UV);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Image < string Script = "Pass=Fill; Pass=Show;"; >
{
    pass Fill < string Script = "Dispatch=4,2;"; >
    {
        ComputeShader = compile cs_5_0 Fill();  // the D3D9 form of the same state
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Show()));
        SetDepthStencilState(NoDepth, 0);
    }
}
