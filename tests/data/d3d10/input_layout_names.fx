//--------------------------------------------------------------------------------------
// Vertex inputs by the names D3D10 applications gave their input layouts: "POS", "NORM", "TEXTURE0" are
// matched to the mesh's position, normal and texture-coordinate streams; "INST0" (an instance stream the
// scene has no data for) reads 0, a bool "VISIBLE" reads false (GL takes no bool attributes: a float
// attribute converted), and a per-instance "mTransform" matrix reads the identity. Technique Rows
// assembles its per-instance transform from four float4 rows at TEXCOORD1..4, as game projects' instancing
// layouts carry it: the rows read the identity's rows (technique Frame builds a matrix of the mesh's own
// streams, which keep their data). Techniques Layout and Rows therefore draw exactly
// the frame of technique Named, which spells the D3D9 names: the normal in red, u in green, and blue 0
// unless a constant input went wrong.
//--------------------------------------------------------------------------------------
float4x4 g_mWorldViewProjection;

struct VS_INPUT_LAYOUT
{
    float3 Pos       : POS;
    float3 Norm      : NORM;
    float2 Tex       : TEXTURE0;
    float4 Instance  : INST0;
    bool   Visible   : VISIBLE;
    float4x4 mTransform : mTransform;
};

struct VS_INPUT_NAMED
{
    float3 Pos  : POSITION;
    float3 Norm : NORMAL;
    float2 Tex  : TEXCOORD0;
};

struct VS_INPUT_ROWS
{
    float3 vPosition    : POSITION;
    float3 vNormal      : NORMAL;
    float2 vTexUV       : TEXCOORD0;
    float4 vRight       : TEXCOORD1;
    float4 vUp          : TEXCOORD2;
    float4 vLook        : TEXCOORD3;
    float4 vTranslation : TEXCOORD4;
};

struct PS_INPUT
{
    float4 Pos   : SV_POSITION;
    float4 Color : COLOR0;
};

PS_INPUT LayoutVS(VS_INPUT_LAYOUT input)
{
    PS_INPUT output;
    output.Pos = mul(mul(float4(input.Pos, 1), input.mTransform), g_mWorldViewProjection);
    output.Color = float4(abs(input.Norm.x), input.Tex.x, input.Instance.x + (input.Visible ? 1 : 0), 1);
    return output;
}

PS_INPUT NamedVS(VS_INPUT_NAMED input)
{
    PS_INPUT output;
    output.Pos = mul(float4(input.Pos, 1), g_mWorldViewProjection);
    output.Color = float4(abs(input.Norm.x), input.Tex.x, 0, 1);
    return output;
}

PS_INPUT RowsVS(VS_INPUT_ROWS In)
{
    PS_INPUT Out = (PS_INPUT)0;
    matrix TransformMatrix = matrix(In.vRight, In.vUp, In.vLook, In.vTranslation);
    vector vPosition = mul(vector(In.vPosition, 1.f), TransformMatrix);
    Out.Pos = mul(vPosition, g_mWorldViewProjection);
    Out.Color = float4(abs(In.vNormal.x), In.vTexUV.x, 0, 1);
    return Out;
}

struct VS_INPUT_FRAME
{
    float4 Position : POSITION;
    float4 Normal   : NORMAL;
    float4 Tangent  : TANGENT;
    float4 Binormal : BINORMAL;
    float4 Tex      : TEXCOORD0;
};

PS_INPUT FrameVS(VS_INPUT_FRAME In)
{
    PS_INPUT Out = (PS_INPUT)0;
    float4x4 frame = float4x4(In.Tangent, In.Binormal, In.Normal, In.Tex);
    Out.Pos = mul(float4(In.Position.xyz, 1), g_mWorldViewProjection);
    Out.Color = abs(mul(float4(0, 0, 1, 0), frame));
    return Out;
}

float4 PS(PS_INPUT input) : SV_Target
{
    return input.Color;
}

technique10 Layout
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, LayoutVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}

technique10 Named
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, NamedVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}

technique10 Rows
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, RowsVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}

technique10 Frame
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, FrameVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
