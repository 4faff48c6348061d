// Point sprites as FX11 particle systems drew them: the vertex shader writes each sprite's size under
// PSIZE, which SM4 carries to the geometry shader as user data, and the geometry shader expands the point
// into a quad of that size. The quad's colour is the size it read, (Size, 1): (0.25, 0.75, 1) on pixels
// only where the geometry shader read what the vertex shader wrote (a PSIZE read as 0 draws no quad).
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float2 Size = {0.25, 0.75};

struct VS_OUT
{
    float4 Position : POSITION;
    float2 Size : PSIZE;
};

struct GS_OUT
{
    float4 Position : SV_POSITION;
    float4 Color : COLOR0;
};

VS_OUT VS(float3 p : POSITION)
{
    VS_OUT o;
    o.Position = mul(float4(p, 1), WorldViewProjection);
    o.Size = Size;
    return o;
}

[maxvertexcount(4)]
void GS(point VS_OUT input[1], inout TriangleStream<GS_OUT> stream)
{
    GS_OUT o;
    o.Color = float4(input[0].Size, 1, 1);
    // A twentieth of the size in clip space either side of the point, in x and y, clockwise (front-facing).
    const float2 extent = input[0].Size * 0.05 * input[0].Position.w;
    for (int k = 0; k < 4; ++k)
    {
        o.Position = input[0].Position + float4((k & 2) ? extent.x : -extent.x, (k & 1) ? extent.y : -extent.y, 0, 0);
        stream.Append(o);
    }
}

float4 PS(GS_OUT i) : SV_Target
{
    return i.Color;
}

technique11 Sprites
{
    pass P
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(CompileShader(gs_5_0, GS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
