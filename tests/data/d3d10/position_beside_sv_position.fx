//--------------------------------------------------------------------------------------
// A POSITION member beside an SV_POSITION one, as Frank Luna's D3D11 effects carry the world position to
// the pixel shader (`float4 PosH : SV_POSITION; float3 PosW : POSITION;`): under D3D10 the second is user
// data. The vertex shader writes (0.25, 0.5, 0.75) there, so the objects are (64, 128, 191); read as the
// fragment's position (D3D9's POSITION), every channel would be at least a pixel centre, 0.5 or more.
// A vertex shader's input struct keeps its POSITION as the mesh's position (technique MeshInput): read
// as user data, every vertex would lie at the origin and nothing would be drawn.
//--------------------------------------------------------------------------------------
float4x4 WorldViewProj : WorldViewProjection;

struct VertexOut
{
    float4 PosH : SV_POSITION;
    float3 PosW : POSITION;
};

VertexOut VS(float3 PosL : POSITION)
{
    VertexOut vout;
    vout.PosH = mul(float4(PosL, 1), WorldViewProj);
    vout.PosW = float3(0.25, 0.5, 0.75);
    return vout;
}

float4 PS(VertexOut pin) : SV_Target
{
    return float4(pin.PosW, 1);
}

technique11 WorldPosition
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}

struct MeshIn
{
    float4 Unused : SV_POSITION;
    float3 PosL : POSITION;
};

VertexOut VSMesh(MeshIn vin)
{
    VertexOut vout;
    vout.PosH = mul(float4(vin.PosL, 1), WorldViewProj);
    vout.PosW = float3(0.75, 0.5, 0.25);
    return vout;
}

technique11 MeshInput
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VSMesh()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
