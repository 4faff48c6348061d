//--------------------------------------------------------------------------------------
// D3D10's BlendState per render target, and dual-source blending. Technique PerTarget clears three
// targets to 0.25 grey and draws 0.5 grey into all three through one BlendState: target 0 blends ONE + ONE
// (0.75), target 1 has no BlendEnable[1] and so does not blend (0.5), target 2 blends ZERO + ONE (keeps
// 0.25). Its last pass shows the targets side by side, thirds of the frame: 191, 128 and 64.
// Technique DualSource writes (1, 1, 0, 1) to SV_Target0 and (0.5, 0.25, 1, 1) to SV_Target1 and blends
// SRC1_COLOR * source + ZERO: the frame is (0.5, 0.25, 0) wherever it draws, black if the second output
// never reached the blender.
//--------------------------------------------------------------------------------------
Texture2D Target0 : RENDERCOLORTARGET;
Texture2D Target1 : RENDERCOLORTARGET;
Texture2D Target2 : RENDERCOLORTARGET;
float4 ClearGrey = {0.25, 0.25, 0.25, 1};
float4 Black = {0, 0, 0, 1};

SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex v) { QuadOut o; o.Position = v.Position; o.UV = v.UV; return o; }

struct Targets { float4 C0 : SV_Target0; float4 C1 : SV_Target1; float4 C2 : SV_Target2; };
Targets HalfGrey(QuadOut i)
{
    Targets o;
    o.C0 = float4(0.5, 0.5, 0.5, 1);
    o.C1 = o.C0;
    o.C2 = o.C0;
    return o;
}

float4 SideBySide(QuadOut i) : SV_Target
{
    if (i.UV.x < 1.0 / 3) return Target0.Sample(PointClamp, i.UV);
    if (i.UV.x < 2.0 / 3) return Target1.Sample(PointClamp, i.UV);
    return Target2.Sample(PointClamp, i.UV);
}

struct DualOut { float4 Color : SV_Target0; float4 Factor : SV_Target1; };
DualOut Dual(QuadOut i)
{
    DualOut o;
    o.Color = float4(1, 1, 0, 1);
    o.Factor = float4(0.5, 0.25, 1, 1);
    return o;
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
RasterizerState NoCulling { CullMode = NONE; };
BlendState PerTargetBlend
{
    BlendEnable[0] = TRUE;
    SrcBlend = ONE;
    DestBlend = ONE;
    BlendEnable[2] = TRUE;
    SrcBlend[2] = ZERO;
    DestBlend[2] = ONE;
};
BlendState NoBlending { BlendEnable[0] = FALSE; };
BlendState SecondSource { BlendEnable[0] = TRUE; SrcBlend = SRC1_COLOR; DestBlend = ZERO;
                          SrcBlendAlpha = ONE; DestBlendAlpha = ZERO; };

technique10 PerTarget < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Target0; RenderColorTarget1=Target1; RenderColorTarget2=Target2;"
                                "ClearSetColor=ClearGrey; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, HalfGrey()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
        SetBlendState(PerTargetBlend, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Show < string Script = "RenderColorTarget0=; RenderColorTarget1=; RenderColorTarget2=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, SideBySide()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
        SetBlendState(NoBlending, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
}

technique10 DualSource < string Script = "Pass=Blend;"; >
{
    pass Blend < string Script = "ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_4_0, QuadVS()));
        SetPixelShader(CompileShader(ps_4_0, Dual()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCulling);
        SetBlendState(SecondSource, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
}
