//--------------------------------------------------------------------------------------
// A texture sampled at offsets computed in a loop, as the SDK's HDR samples filter, with an `unsigned int`
// loop counter: GLSL takes only constant offsets, so shadowfx adds them to the coordinate (to the texel
// location for Load). Pass Draw fills the target red left of its middle and green right of it, and its
// depth target 0.25 left and 0.75 right; pass Show averages the texel under each pixel and the one Shift
// texels to its right, read by every method that takes an offset (the depth compared with 0.5: 0 left,
// 1 right, shown as red or green). The frame is red, then Shift columns of (0.5, 0.5, 0) just left of the
// middle, then green.
//--------------------------------------------------------------------------------------
Texture2D Stripes : RENDERCOLORTARGET;
Texture2D<float> StripesDepth : RENDERDEPTHSTENCILTARGET < string Format = "D24S8"; >;
int Shift = 4;
float4 Black = {0, 0, 0, 1};
float ClearDepth = 1.0;

SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };
SamplerComparisonState AboveHalf
{
    Filter = COMPARISON_MIN_MAG_MIP_POINT;
    AddressU = CLAMP;
    AddressV = CLAMP;
    ComparisonFunc = LESS;
};

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex v) { QuadOut o; o.Position = v.Position; o.UV = v.UV; return o; }

struct HalvesOut { float4 Color : SV_Target; float Depth : SV_Depth; };
HalvesOut Halves(QuadOut i)
{
    HalvesOut o;
    o.Color = i.UV.x < 0.5 ? float4(1, 0, 0, 1) : float4(0, 1, 0, 1);
    o.Depth = i.UV.x < 0.5 ? 0.25 : 0.75;
    return o;
}

float4 RedOrGreen(float right) { return float4(1 - right, right, 0, 1); }

float4 Shifted(QuadOut i) : SV_Target
{
    uint w, h;
    Stripes.GetDimensions(w, h);
    float4 c = 0;
    for (unsigned int k = 0; k < 2; k++)
    {
        int2 offset = int2(Shift * (int)k, 0);
        // Load reads 0 beyond the texture where the samplers clamp: its location stays Shift texels inside.
        int x = min((int)i.Position.x, (int)w - 1 - offset.x);
        c += Stripes.Sample(PointClamp, i.UV, int2(Shift * (int)k, 0));
        c += Stripes.SampleLevel(PointClamp, i.UV, 0, offset);
        c += Stripes.SampleBias(PointClamp, i.UV, 0, offset);
        c += Stripes.SampleGrad(PointClamp, i.UV, float2(0, 0), float2(0, 0), offset);
        c += Stripes.Load(int3(x, (int)i.Position.y, 0), offset);
        c += RedOrGreen(StripesDepth.SampleCmp(AboveHalf, i.UV, 0.5, offset));
        c += RedOrGreen(StripesDepth.SampleCmpLevelZero(AboveHalf, i.UV, 0.5, offset));
    }
    return c / 14;
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
DepthStencilState DepthAlways { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = ALWAYS; };
RasterizerState NoCulling { CullMode = NONE; };

technique10 Offsets < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Stripes; RenderDepthStencilTarget=StripesDepth;"
                                "ClearSetColor=Black; ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth;"
                                "Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, Halves()));
        SetDepthStencilState(DepthAlways, 0);
        SetRasterizerState(NoCulling);
    }
    pass Show < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, Shifted()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
    }
}
