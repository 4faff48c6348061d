//--------------------------------------------------------------------------------------
// Arrays of state objects as FX11 effects declared them (`RasterizerState g_rasterizerState[2] { { ... },
// { ... } };`) and chose their elements in passes, by a constant or by a parameter
// (`SetRasterizerState(g_rasterizerState[g_fillMode])`).
// Blended: a grey of 0.25 drawn over a clear of dark red with Blends[0] (no blending), then again with
// Blends[1] (ONE + ONE): the frame is 0.5 grey.
// Filled: a white quad over the middle of the frame, filled under Fills[0] and in wireframe under Fills[1],
// as FillChoice says.
//--------------------------------------------------------------------------------------
BlendState Blends[2] =
{
    { BlendEnable[0] = FALSE; },
    { BlendEnable[0] = TRUE; SrcBlend = ONE; DestBlend = ONE; BlendOp = ADD; }
};
RasterizerState Fills[2]
{
    { FillMode = SOLID; CullMode = NONE; },
    { FillMode = WIREFRAME; CullMode = NONE; }
};
DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
int FillChoice = 0;
float4 Black = {0, 0, 0, 1};
float4 DarkRed = {0.5, 0, 0, 1};

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };

float4 FullVS(QuadVertex v) : SV_Position
{
    return v.Position;
}

float4 MiddleVS(QuadVertex v) : SV_Position
{
    return float4(v.Position.xy * 0.5, v.Position.zw);
}

float4 Grey() : SV_Target
{
    return float4(0.25, 0.25, 0.25, 1);
}

float4 White() : SV_Target
{
    return 1;
}

technique11 Blended < string Script = "Pass=Base; Pass=Add;"; >
{
    pass Base < string Script = "RenderColorTarget0=; ClearSetColor=DarkRed; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, FullVS()));
        SetPixelShader(CompileShader(ps_5_0, Grey()));
        SetBlendState(Blends[0], float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(Fills[0]);
    }
    pass Add < string Script = "Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, FullVS()));
        SetPixelShader(CompileShader(ps_5_0, Grey()));
        SetBlendState(Blends[1], float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(Fills[0]);
    }
}

technique11 Filled < string Script = "Pass=Quad;"; >
{
    pass Quad < string Script = "RenderColorTarget0=; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, MiddleVS()));
        SetPixelShader(CompileShader(ps_5_0, White()));
        SetRasterizerState(Fills[FillChoice]);
        SetDepthStencilState(NoDepth, 0);
    }
}
