// A geometry shader in Direct3D 10's form: each draw's first triangle (SV_PrimitiveID 0) becomes one
// screen-space quad of half-size HalfSize around the centre of the frame, the rest emit nothing. The quad
// carries the vertex shader's colour through the geometry stage (linked by semantic) and a float2 UV
// across it, so what it renders pins the stage: a quad covering (2 HalfSize)² / 4 of the frame in the
// vertex colour, its blue channel the UV's u from left to right. HalfSize is a cbuffer member the geometry
// stage reads from its own uniform block.

cbuffer Sprite
{
    float4x4 Wvp : WorldViewProjection;
    float HalfSize = 0.5;
    float4 SpriteColor = {0, 1, 0, 1};
};

struct VsOut
{
    float4 Position : SV_Position;
    float3 Color : COLOR0;
};

struct GsOut
{
    float4 Position : SV_Position;
    float3 Color : COLOR0;
    float2 UV : TEXCOORD0;
};

VsOut VS(float3 p : POSITION)
{
    VsOut o;
    o.Position = mul(float4(p, 1), Wvp);
    o.Color = SpriteColor.rgb;
    return o;
}

[maxvertexcount(4)]
void Sprite(triangle VsOut tri[3], uint id : SV_PrimitiveID, inout TriangleStream<GsOut> stream)
{
    if (id != 0)
        return;
    for (int i = 0; i < 4; ++i)
    {
        GsOut v;
        v.UV = float2(i & 1, i >> 1);
        v.Position = float4((v.UV * 2 - 1) * float2(HalfSize, -HalfSize), 0.5, 1);
        v.Color = tri[0].Color;
        stream.Append(v);
    }
    stream.RestartStrip();
}

float4 PS(GsOut IN) : SV_Target
{
    return float4(IN.Color.rg, IN.UV.x, 1);
}

float4 MeshPS(VsOut IN) : SV_Target
{
    return float4(IN.Color, 1);
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

// The same pass without its geometry shader draws the meshes themselves.
technique11 NoSprites
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, MeshPS()));
        SetRasterizerState(NoCulling);
        SetDepthStencilState(NoDepth, 0);
    }
}
