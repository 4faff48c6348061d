//--------------------------------------------------------------------------------------
// Vertex outputs D3D9 and MonoGame's effect compiler passed to the pixel shader and a vertex input name
// written as an output: a float3x3 under TANGENT0, which takes TANGENT0..2 (one register per column, the
// last two in no D3D9 varying table), and a float3 under BLENDWEIGHT0. The objects are (Frame[0][0] +
// Weights.x, Frame[1][1], Frame[2][2]) = (0.75, 0.5, 1), which only the three columns and the weights
// crossing to the pixel shader draw.
//--------------------------------------------------------------------------------------
float4x4 WorldViewProj : WorldViewProjection;

struct VSOut
{
    float4 Position : POSITION0;
    float3x3 Frame : TANGENT0;
    float3 Weights : BLENDWEIGHT0;
};

VSOut VS(float4 pos : POSITION0, float3 n : NORMAL0)
{
    VSOut o;
    o.Position = mul(pos, WorldViewProj);
    // The normal times 0 keeps the rows per-vertex values without changing them.
    o.Frame = float3x3(float3(0.25, 0, 0) + 0 * n, float3(0, 0.5, 0), float3(0, 0, 1));
    o.Weights = float3(0.5, 0, 0);
    return o;
}

float4 PS(VSOut i) : COLOR0
{
    return float4(i.Frame[0][0] + i.Weights.x, i.Frame[1][1], i.Frame[2][2], 1);
}

technique MatrixVaryings
{
    pass P
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
