//--------------------------------------------------------------------------------------
// A cube map rendered in one pass, as the DirectX SDK's samples render one: the geometry shader sends
// each triangle to all six faces of a cube render target through SV_RenderTargetArrayIndex, beside an
// array output (the SDK's environment-mapping shader hands six normals on so). The
// application (here a host file, cube_map_gs.json) creates the cube, binds it whole and gives it to
// g_txEnvMap; a second technique shows the six faces side by side.
//--------------------------------------------------------------------------------------

cbuffer cbPerCubeRender
{
    float4 g_vFaceColor[6] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 },
                               { 1, 1, 0, 1 }, { 1, 0, 1, 1 }, { 0, 1, 1, 1 } };
};

TextureCube g_txEnvMap;

SamplerState g_samPoint
{
    Filter = MIN_MAG_MIP_POINT;
    AddressU = Clamp;
    AddressV = Clamp;
};

RasterizerState RasNoCull
{
    CullMode = None;
};

DepthStencilState DepthLess
{
    DepthEnable = TRUE;
    DepthFunc = LESS;
};

struct VS_QUAD_IN
{
    float4 Pos : POSITION;
    float2 Tex : TEXCOORD0;
};

struct GS_CUBEMAP_IN
{
    float4 Pos : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

struct PS_CUBEMAP_IN
{
    float4 Pos : SV_POSITION;
    float4 Face[2] : FACEDATA;    // the face's colour, then its index in x
    uint RTIndex : SV_RenderTargetArrayIndex;
};

GS_CUBEMAP_IN VS_CubeMap( VS_QUAD_IN input )
{
    GS_CUBEMAP_IN output = (GS_CUBEMAP_IN)0.0f;
    output.Pos = input.Pos;
    output.Tex = input.Tex;
    return output;
}

[maxvertexcount(18)]
void GS_CubeMap( triangle GS_CUBEMAP_IN input[3], inout TriangleStream<PS_CUBEMAP_IN> CubeMapStream )
{
    for( int f = 0; f < 6; ++f )
    {
        PS_CUBEMAP_IN output;
        output.RTIndex = f;
        output.Face[0] = g_vFaceColor[f];
        output.Face[1] = float4( f, 0, 0, 1 );
        for( int v = 0; v < 3; v++ )
        {
            output.Pos = input[v].Pos;
            CubeMapStream.Append( output );
        }
        CubeMapStream.RestartStrip();
    }
}

// The face's colour where the face the pixel shader reads (gl_Layer) is the one the geometry shader
// wrote, by colour and by index; black where they disagree.
float4 PS_CubeMap( PS_CUBEMAP_IN input ) : SV_Target
{
    const bool same = all( abs( input.Face[0] - g_vFaceColor[input.RTIndex] ) < 0.01 ) &&
                      abs( input.Face[1].x - input.RTIndex ) < 0.01;
    return same ? input.Face[0] : float4( 0, 0, 0, 1 );
}

struct VS_OUTPUT_VISUALIZE
{
    float4 Pos : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

VS_OUTPUT_VISUALIZE VS_Visualize( VS_QUAD_IN input )
{
    VS_OUTPUT_VISUALIZE output;
    output.Pos = input.Pos;
    output.Tex = input.Tex;
    return output;
}

// Six bands from left to right, each the centre of one face: +X, -X, +Y, -Y, +Z, -Z.
float4 PS_Visualize( VS_OUTPUT_VISUALIZE input ) : SV_Target
{
    const float3 axes[6] = { float3( 1, 0, 0 ), float3( -1, 0, 0 ), float3( 0, 1, 0 ),
                             float3( 0, -1, 0 ), float3( 0, 0, 1 ), float3( 0, 0, -1 ) };
    const int face = min( (int)( input.Tex.x * 6 ), 5 );
    return g_txEnvMap.SampleLevel( g_samPoint, axes[face], 0 );
}

technique10 RenderCubeMap
{
    pass p0
    {
        SetVertexShader( CompileShader( vs_4_0, VS_CubeMap() ) );
        SetGeometryShader( CompileShader( gs_4_0, GS_CubeMap() ) );
        SetPixelShader( CompileShader( ps_4_0, PS_CubeMap() ) );
        SetRasterizerState( RasNoCull );
        SetDepthStencilState( DepthLess, 0 );
    }
}

technique10 VisualizeCubeMap
{
    pass p0
    {
        SetVertexShader( CompileShader( vs_4_0, VS_Visualize() ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, PS_Visualize() ) );
        SetRasterizerState( RasNoCull );
    }
}
