// Tessellation in Direct3D 11's form: a hull shader with its patch-constant function and a domain shader,
// linked to the vertex and pixel shaders by semantic.
//
// `Wire*`: the patch-constant function gives each draw's first triangle (SV_PrimitiveID 0) the factor
// TessFactor and every other triangle 0, which culls its patch; the domain shader places the domain
// triangle at fixed clip-space corners, so the frame shows one tessellated triangle in wireframe whatever
// the mesh. How many edges a scanline crosses grows with the factor: it pins the factor reaching the
// tessellator, and the two techniques its partitioning.
// `Corners`: the same triangle filled with half SV_DomainLocation plus half a patch constant (Tint) as its
// colour: u adds red at the first corner, v green at the second, w blue at the third.
// `Mesh`: the meshes themselves through VS -> HS -> DS -> PS, the control points carrying a float3
// POSITION and a NORMAL; at factor 1 it draws the frame of `Plain`. `QuadMesh`: the same through a quad
// domain, whose four control points a triangle gives with its third corner twice; the bilinear patch
// collapses onto the triangle, so it draws that frame too.

cbuffer Tessellation
{
    float4x4 Wvp : WorldViewProjection;
    float TessFactor = 1;
};

struct VsOut
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
};

struct HsOut
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
};

struct HsConstants
{
    float Edges[3] : SV_TessFactor;
    float Inside : SV_InsideTessFactor;
    float3 Tint : TEXCOORD3;
};

struct DsOut
{
    float4 Position : SV_Position;
    float3 Color : COLOR0;
};

VsOut VS(float3 p : POSITION, float3 n : NORMAL)
{
    VsOut o;
    o.Position = p;
    o.Normal = n;
    return o;
}

HsConstants OneTriangle(InputPatch<VsOut, 3> patch, uint id : SV_PrimitiveID)
{
    HsConstants c;
    const float f = id == 0 ? TessFactor : 0;
    c.Edges[0] = f;
    c.Edges[1] = f;
    c.Edges[2] = f;
    c.Inside = f;
    c.Tint = float3(0.25, 0.5, 0.75);
    return c;
}

HsConstants EveryTriangle(InputPatch<VsOut, 3> patch, const OutputPatch<HsOut, 3> points)
{
    HsConstants c;
    c.Edges[0] = TessFactor;
    c.Edges[1] = TessFactor;
    c.Edges[2] = TessFactor;
    c.Inside = TessFactor;
    c.Tint = normalize(points[0].Normal + points[1].Normal + patch[2].Normal) * 0.5 + 0.5;
    return c;
}

[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("OneTriangle")]
HsOut HS(InputPatch<VsOut, 3> patch, uint i : SV_OutputControlPointID)
{
    HsOut o;
    o.Position = patch[i].Position;
    o.Normal = patch[i].Normal;
    return o;
}

[domain("tri")]
[partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("OneTriangle")]
HsOut HSFractionalOdd(InputPatch<VsOut, 3> patch, uint i : SV_OutputControlPointID)
{
    HsOut o;
    o.Position = patch[i].Position;
    o.Normal = patch[i].Normal;
    return o;
}

[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("EveryTriangle")]
HsOut HSMesh(InputPatch<VsOut, 3> patch, uint i : SV_OutputControlPointID)
{
    HsOut o;
    o.Position = patch[i].Position;
    o.Normal = patch[i].Normal;
    return o;
}

[domain("tri")]
DsOut DSScreen(HsConstants c, float3 uvw : SV_DomainLocation)
{
    DsOut o;
    const float2 p = uvw.x * float2(-0.9, -0.9) + uvw.y * float2(0, 0.9) + uvw.z * float2(0.9, -0.9);
    o.Position = float4(p, 0.5, 1);
    o.Color = 0.5 * uvw + 0.5 * c.Tint;
    return o;
}

[domain("tri")]
DsOut DSMesh(HsConstants c, float3 uvw : SV_DomainLocation, const OutputPatch<HsOut, 3> patch)
{
    DsOut o;
    const float3 p = uvw.x * patch[0].Position + uvw.y * patch[1].Position + uvw.z * patch[2].Position;
    const float3 n = uvw.x * patch[0].Normal + uvw.y * patch[1].Normal + uvw.z * patch[2].Normal;
    o.Position = mul(float4(p, 1), Wvp);
    o.Color = normalize(n) * 0.5 + 0.5;
    return o;
}

struct QuadConstants
{
    float Edges[4] : SV_TessFactor;
    float Inside[2] : SV_InsideTessFactor;
};

QuadConstants EveryQuad(InputPatch<VsOut, 4> patch)
{
    QuadConstants c;
    c.Edges[0] = c.Edges[1] = c.Edges[2] = c.Edges[3] = TessFactor;
    c.Inside[0] = c.Inside[1] = TessFactor;
    return c;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("EveryQuad")]
HsOut HSQuad(InputPatch<VsOut, 4> patch, uint i : SV_OutputControlPointID)
{
    HsOut o;
    o.Position = patch[i].Position;
    o.Normal = patch[i].Normal;
    return o;
}

[domain("quad")]
DsOut DSQuad(QuadConstants c, float2 uv : SV_DomainLocation, const OutputPatch<HsOut, 4> quad)
{
    DsOut o;
    const float3 p = lerp(lerp(quad[0].Position, quad[1].Position, uv.x),
                          lerp(quad[2].Position, quad[3].Position, uv.x), uv.y);
    const float3 n = lerp(lerp(quad[0].Normal, quad[1].Normal, uv.x),
                          lerp(quad[2].Normal, quad[3].Normal, uv.x), uv.y);
    o.Position = mul(float4(p, 1), Wvp);
    o.Color = normalize(n) * 0.5 + 0.5;
    return o;
}

struct PlainOut
{
    float4 Position : SV_Position;
    float3 Color : COLOR0;
};

PlainOut PlainVS(float3 p : POSITION, float3 n : NORMAL)
{
    PlainOut o;
    o.Position = mul(float4(p, 1), Wvp);
    o.Color = normalize(n) * 0.5 + 0.5;
    return o;
}

float4 PS(DsOut i) : SV_Target
{
    return float4(i.Color, 1);
}

float4 White(DsOut i) : SV_Target
{
    return float4(1, 1, 1, 1);
}

RasterizerState Wireframe { FillMode = WIREFRAME; CullMode = NONE; };
RasterizerState Solid { CullMode = NONE; };
DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 WireInteger
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HS()));
        SetDomainShader(CompileShader(ds_5_0, DSScreen()));
        SetPixelShader(CompileShader(ps_5_0, White()));
        SetRasterizerState(Wireframe);
        SetDepthStencilState(NoDepth, 0);
    }
}

technique11 WireFractionalOdd
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HSFractionalOdd()));
        SetDomainShader(CompileShader(ds_5_0, DSScreen()));
        SetPixelShader(CompileShader(ps_5_0, White()));
        SetRasterizerState(Wireframe);
        SetDepthStencilState(NoDepth, 0);
    }
}

technique11 Corners
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HS()));
        SetDomainShader(CompileShader(ds_5_0, DSScreen()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
        SetRasterizerState(Solid);
        SetDepthStencilState(NoDepth, 0);
    }
}

// D3D10's default rasterizer state culls back faces: a tessellator that wound its triangles the other way
// would show the meshes' back faces here. The stages come from shader variables, FX11's other form, and
// the pass sets the blend state NULL (all defaults).
HullShader g_hsMesh = CompileShader(hs_5_0, HSMesh());
DomainShader g_dsMesh = CompileShader(ds_5_0, DSMesh());

technique11 Mesh
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(g_hsMesh);
        SetDomainShader(g_dsMesh);
        SetPixelShader(CompileShader(ps_5_0, PS()));
        SetBlendState(NULL, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
}

technique11 Plain
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, PlainVS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}

technique11 QuadMesh
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HSQuad()));
        SetDomainShader(CompileShader(ds_5_0, DSQuad()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
