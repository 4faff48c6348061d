// 3ds Max's scripts name the target a Clear clears: `Clear=SV_TARGET0;` clears colour target 0 alone, with
// ClearSetColor's colour. Pass Draw clears Target0 to red and Target1 to green, each alone, and draws the
// object blue into both; pass Show puts Target0 on the frame's left half and Target1 on its right. Red shows
// around the object on the left and green on the right only where each clear cleared its target alone (a
// clear of every target would leave both green).
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
Texture2D Target0 : RENDERCOLORTARGET;
Texture2D Target1 : RENDERCOLORTARGET;
float4 Red = {1, 0, 0, 1};
float4 Green = {0, 1, 0, 1};

SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };

struct Targets { float4 C0 : SV_Target0; float4 C1 : SV_Target1; };
float4 ObjectVS(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), WorldViewProjection); }
Targets Blue()
{
    Targets o;
    o.C0 = float4(0, 0, 1, 1);
    o.C1 = o.C0;
    return o;
}

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex v) { QuadOut o; o.Position = v.Position; o.UV = v.UV; return o; }
float4 Halves(QuadOut i) : SV_Target
{
    return i.UV.x < 0.5 ? Target0.Sample(PointClamp, i.UV) : Target1.Sample(PointClamp, i.UV);
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Main < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0 = Target0;"
                                "RenderColorTarget1 = Target1;"
                                "ClearSetColor=Red;"
                                "Clear=SV_TARGET0;"
                                "ClearSetColor=Green;"
                                "Clear=sv_target1;"
                                "Draw=Geometry;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, ObjectVS()));
        SetPixelShader(CompileShader(ps_5_0, Blue()));
        SetDepthStencilState(NoDepth, 0);
    }
    pass Show < string Script = "RenderColorTarget0=; RenderColorTarget1=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, Halves()));
        SetDepthStencilState(NoDepth, 0);
    }
}
