//--------------------------------------------------------------------------------------
// Several viewports and primitive ids, as Direct3D 10 applications used them: the application sets two
// viewports (RSSetViewports; here the host file viewport_index.json, the left and the right half of the
// frame), and the geometry shader sends each triangle of a full-screen quad to both through
// SV_ViewportArrayIndex, red into viewport 0 and green into viewport 1. `PrimitiveColours`: the pixel
// shader tells the quad's two triangles apart by SV_PrimitiveID; `GeometryPrimitiveIds`: the geometry
// shader writes SV_PrimitiveID (the other triangle's id) and the pixel shader reads what it wrote.
//--------------------------------------------------------------------------------------

RasterizerState RasNoCull
{
    CullMode = None;
};

struct VS_QUAD_IN
{
    float4 Pos : POSITION;
};

struct VS_OUT
{
    float4 Pos : SV_POSITION;
};

struct GS_VIEWPORT_OUT
{
    float4 Pos : SV_POSITION;
    float4 Colour : COLOR0;
    uint Viewport : SV_ViewportArrayIndex;
};

struct GS_PRIMITIVE_OUT
{
    float4 Pos : SV_POSITION;
    uint Id : SV_PrimitiveID;
};

VS_OUT VS_Quad( VS_QUAD_IN input )
{
    VS_OUT output;
    output.Pos = input.Pos;
    return output;
}

[maxvertexcount(6)]
void GS_BothViewports( triangle VS_OUT input[3], inout TriangleStream<GS_VIEWPORT_OUT> stream )
{
    for( uint viewport = 0; viewport < 2; ++viewport )
    {
        GS_VIEWPORT_OUT output;
        output.Viewport = viewport;
        output.Colour = viewport == 0 ? float4( 1, 0, 0, 1 ) : float4( 0, 1, 0, 1 );
        for( int v = 0; v < 3; ++v )
        {
            output.Pos = input[v].Pos;
            stream.Append( output );
        }
        stream.RestartStrip();
    }
}

float4 PS_Colour( GS_VIEWPORT_OUT input ) : SV_Target
{
    return input.Colour;
}

// Primitive 0 red, primitive 1 green, any other blue.
float4 IdColour( uint id )
{
    return id == 0 ? float4( 1, 0, 0, 1 ) : id == 1 ? float4( 0, 1, 0, 1 ) : float4( 0, 0, 1, 1 );
}

float4 PS_PrimitiveColour( float4 pos : SV_POSITION, uint id : SV_PrimitiveID ) : SV_Target
{
    return IdColour( id );
}

[maxvertexcount(3)]
void GS_SwapIds( triangle VS_OUT input[3], uint id : SV_PrimitiveID,
                 inout TriangleStream<GS_PRIMITIVE_OUT> stream )
{
    for( int v = 0; v < 3; ++v )
    {
        GS_PRIMITIVE_OUT output;
        output.Pos = input[v].Pos;
        output.Id = 1 - id;
        stream.Append( output );
    }
}

float4 PS_WrittenId( GS_PRIMITIVE_OUT input ) : SV_Target
{
    return IdColour( input.Id );
}

technique10 BothViewports
{
    pass p0
    {
        SetVertexShader( CompileShader( vs_4_0, VS_Quad() ) );
        SetGeometryShader( CompileShader( gs_4_0, GS_BothViewports() ) );
        SetPixelShader( CompileShader( ps_4_0, PS_Colour() ) );
        SetRasterizerState( RasNoCull );
    }
}

technique10 PrimitiveColours
{
    pass p0
    {
        SetVertexShader( CompileShader( vs_4_0, VS_Quad() ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, PS_PrimitiveColour() ) );
        SetRasterizerState( RasNoCull );
    }
}

technique10 GeometryPrimitiveIds
{
    pass p0
    {
        SetVertexShader( CompileShader( vs_4_0, VS_Quad() ) );
        SetGeometryShader( CompileShader( gs_4_0, GS_SwapIds() ) );
        SetPixelShader( CompileShader( ps_4_0, PS_WrittenId() ) );
        SetRasterizerState( RasNoCull );
    }
}
