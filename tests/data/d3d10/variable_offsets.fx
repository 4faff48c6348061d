//--------------------------------------------------------------------------------------
// A texture sampled at offsets computed in a loop, as the SDK's HDR samples filter, with an `unsigned int`
// loop counter: GLSL takes only constant offsets, so shadowfx adds them to the coordinate. Pass Draw
// fills the target red left of its middle and green right of it; pass Show averages the texel under each
// pixel and the one Shift texels to its right. The frame is red, then Shift columns of (0.5, 0.5, 0) just
// left of the middle, then green.
//--------------------------------------------------------------------------------------
Texture2D Stripes : RENDERCOLORTARGET;
int Shift = 4;
float4 Black = {0, 0, 0, 1};

SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex v) { QuadOut o; o.Position = v.Position; o.UV = v.UV; return o; }

float4 Halves(QuadOut i) : SV_Target
{
    return i.UV.x < 0.5 ? float4(1, 0, 0, 1) : float4(0, 1, 0, 1);
}

float4 Shifted(QuadOut i) : SV_Target
{
    float4 c = 0;
    for (unsigned int k = 0; k < 2; k++)
        c += Stripes.Sample(PointClamp, i.UV, int2(Shift * (int)k, 0));
    return c / 2;
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
RasterizerState NoCulling { CullMode = NONE; };

technique10 Offsets < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Stripes; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, Halves()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, Shifted()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
    }
}
