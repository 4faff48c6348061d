// An instance ID carried from the vertex shader to the geometry shader and on to the pixel shader, as FX11
// trail and particle effects carry it: every stage's SV_InstanceID but the vertex shader's input is a flat
// varying. The vertex shader writes its own instance ID (0: the draw has one instance) plus 3; the
// geometry shader draws a quad only where it read 3, and writes twice that on; the pixel shader colours
// the quad by what it read, (6 / 8, 1, 0.25): (191, 255, 64) on pixels only where every stage passed it.
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;

struct VS_IN
{
    float3 Position : POSITION;
    uint InstanceID : SV_InstanceID;
};

struct VS_OUT
{
    float4 Position : POSITION;
    uint InstanceID : SV_InstanceID;
};

struct GS_OUT
{
    float4 Position : SV_POSITION;
    uint InstanceID : SV_InstanceID;
};

VS_OUT VS(VS_IN i)
{
    VS_OUT o;
    o.Position = mul(float4(i.Position, 1), WorldViewProjection);
    o.InstanceID = i.InstanceID + 3;
    return o;
}

[maxvertexcount(4)]
void GS(point VS_OUT input[1], inout TriangleStream<GS_OUT> stream)
{
    if (input[0].InstanceID != 3)
        return;
    GS_OUT o;
    o.InstanceID = input[0].InstanceID * 2;
    // A twentieth of clip space either side of the point, in x and y, clockwise (front-facing).
    const float extent = 0.05 * input[0].Position.w;
    for (int k = 0; k < 4; ++k)
    {
        o.Position = input[0].Position + float4((k & 2) ? extent : -extent, (k & 1) ? extent : -extent, 0, 0);
        stream.Append(o);
    }
}

float4 PS(GS_OUT i) : SV_Target
{
    return float4(i.InstanceID / 8.0, 1, 0.25, 1);
}

technique11 Trail
{
    pass P
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(CompileShader(gs_5_0, GS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
