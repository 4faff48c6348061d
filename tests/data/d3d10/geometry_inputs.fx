// Geometry shaders whose input primitive is not a triangle. Each writes pixels addressed by its
// SV_PrimitiveID in a 64 x 64 frame, so that a test can count exactly what the draws fed it:
// `Sprites`: `point` input, one primitive per mesh vertex; each becomes a 2 x 2 pixel quad (a sprite) in
// the vertex shader's colour at block id of a 32 x 32 grid of blocks.
// `Silhouettes`: `triangleadj` input, one primitive per triangle with the vertices across its edges; a
// triangle facing the light marks pixel 3 id + i for each edge i whose neighbour faces away (the
// silhouette test of the DirectX SDK's ShadowVolume10 sample).
// `Edges`: `line` input, one primitive per edge of the mesh; each marks pixel id.

cbuffer Inputs
{
    float3 LightDirection = {0.6, -0.7, 0.4};  // object space, the way the light travels
    float4 SpriteColor = {0, 1, 0, 1};
};

struct VsOut
{
    float4 Position : SV_Position;
    float3 Object : TEXCOORD0;
    float4 Color : COLOR0;
};

struct GsOut
{
    float4 Position : SV_Position;
    float4 Color : COLOR0;
};

VsOut VS(float3 p : POSITION)
{
    VsOut o;
    o.Position = float4(p, 1);
    o.Object = p;
    o.Color = SpriteColor;
    return o;
}

// The quad covering `size` x `size` pixels of a 64 x 64 frame from pixel (x, y), y from the top.
void EmitQuad(uint x, uint y, uint size, float4 color, inout TriangleStream<GsOut> stream)
{
    for (uint k = 0; k < 4; ++k)
    {
        GsOut v;
        const float2 corner = float2(x + (k & 1) * size, y + (k >> 1) * size) / 32.0 - 1.0;
        v.Position = float4(corner.x, -corner.y, 0.5, 1);
        v.Color = color;
        stream.Append(v);
    }
    stream.RestartStrip();
}

[maxvertexcount(4)]
void Sprite(point VsOut vertex[1], uint id : SV_PrimitiveID, inout TriangleStream<GsOut> stream)
{
    EmitQuad(2 * (id % 32), 2 * (id / 32), 2, vertex[0].Color, stream);
}

[maxvertexcount(12)]
void Silhouette(triangleadj VsOut v[6], uint id : SV_PrimitiveID, inout TriangleStream<GsOut> stream)
{
    const float3 toLight = -LightDirection;
    const float3 n = cross(v[2].Object - v[0].Object, v[4].Object - v[0].Object);
    if (dot(n, toLight) <= 0)
        return;
    for (uint i = 0; i < 3; ++i)
    {
        const float3 a = v[2 * i].Object;
        const float3 across = v[2 * i + 1].Object;
        const float3 b = v[(2 * i + 2) % 6].Object;
        // The neighbour (b, a, across) in its own winding.
        if (dot(cross(across - a, b - a), toLight) <= 0)
        {
            const uint k = 3 * id + i;
            EmitQuad(k % 64, k / 64, 1, float4(1, 1, 1, 1), stream);
        }
    }
}

[maxvertexcount(4)]
void Edge(line VsOut v[2], uint id : SV_PrimitiveID, inout TriangleStream<GsOut> stream)
{
    EmitQuad(id % 64, id / 64, 1, float4(1, 1, 1, 1), stream);
}

float4 PS(GsOut i) : SV_Target
{
    return i.Color;
}

RasterizerState NoCulling { CullMode = NONE; };
DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Sprites
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(CompileShader(gs_4_0, Sprite()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
        SetRasterizerState(NoCulling);
        SetDepthStencilState(NoDepth, 0);
    }
}

technique11 Silhouettes
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(CompileShader(gs_4_0, Silhouette()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
        SetRasterizerState(NoCulling);
        SetDepthStencilState(NoDepth, 0);
    }
}

technique11 Edges
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(CompileShader(gs_4_0, Edge()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
        SetRasterizerState(NoCulling);
        SetDepthStencilState(NoDepth, 0);
    }
}
