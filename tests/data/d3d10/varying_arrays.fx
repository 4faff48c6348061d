//--------------------------------------------------------------------------------------
// Varyings as an array under one free name, as the SDK's subdivision-surface samples passed control points
// (`float4 Points[16] : POINTS`), beside vertex inputs by free names of their own. POINTS0..23 take 24
// varying locations; the vertex inputs are attributes and take none (Extra's twelve names would make 36,
// over GL's 32). Every element carries i / 24: the objects are (Points[6], Points[23], Points[12]) =
// (0.25, 0.958, 0.5), which only a linkage that keeps each element in its place draws.
//--------------------------------------------------------------------------------------
float4x4 WorldViewProj : WorldViewProjection;

struct VsIn
{
    float3 Pos : POS;
    float4 Extra[12] : CONTROLPOINTS;  // no mesh has these: a constant
};

struct VsOut
{
    float4 Position : SV_Position;
    float4 Points[24] : POINTS;
};

VsOut VS(VsIn v)
{
    VsOut o;
    o.Position = mul(float4(v.Pos, 1), WorldViewProj);
    for (int i = 0; i < 24; i++)
        o.Points[i] = float4(i / 24.0, 0, 0, 0) + 0 * v.Extra[i % 12];
    return o;
}

float4 PS(VsOut i) : SV_Target
{
    return float4(i.Points[6].x, i.Points[23].x, i.Points[12].x, 1);
}

technique10 Arrays
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
