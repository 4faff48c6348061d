// Render targets bound whole, their layer chosen by the geometry shader's SV_RenderTargetArrayIndex: a
// Texture2DArray, a Texture2DMSArray and a Texture3D, each cleared, drawn into one layer by a first pass
// and read back element by element (sample by sample, slice by slice) by a second pass into the frame,
// an element or slice per band of four from left to right.

Texture2DArray Layers : RENDERCOLORTARGET < int ArraySize = 4; >;
Texture2DMSArray<float4, 4> SampledLayers : RENDERCOLORTARGET < int ArraySize = 2; >;
Texture3D Slices : RENDERCOLORTARGET < int3 Dimensions = { 16, 16, 4 }; >;

float4 Black = { 0, 0, 0, 1 };
float4 Blue = { 0, 0, 1, 1 };

struct QuadVertex
{
    float4 Position : POSITION;
    float2 UV : TEXCOORD0;
};

struct ClipVertex
{
    float4 Position : SV_Position;
    float2 UV : TEXCOORD0;
};

struct LayerVertex
{
    float4 Position : SV_Position;
    uint Layer : SV_RenderTargetArrayIndex;
};

ClipVertex QuadVS(QuadVertex v)
{
    ClipVertex o;
    o.Position = v.Position;
    o.UV = v.UV;
    return o;
}

[maxvertexcount(3)]
void ToLayer(triangle ClipVertex input[3], inout TriangleStream<LayerVertex> stream, uniform uint layer)
{
    LayerVertex v;
    v.Layer = layer;
    for (int i = 0; i < 3; ++i)
    {
        v.Position = input[i].Position;
        stream.Append(v);
    }
}

// Green, its blue the layer the pixel shader reads back from SV_RenderTargetArrayIndex, in quarters.
float4 LayerColor(LayerVertex v) : SV_Target
{
    return float4(0, 1, v.Layer / 4.0, 1);
}

int Band(float2 uv)
{
    return min((int)(uv.x * 4), 3);
}

float4 ShowLayers(ClipVertex v) : SV_Target
{
    uint w, h, elements, levels;
    Layers.GetDimensions(0, w, h, elements, levels);
    const float4 texel = Layers.Load(int4(v.Position.xy, Band(v.UV), 0));
    return float4(elements / 4.0, texel.gb, 1);
}

// Red: sample 3 of element 1 (drawn); blue: sample 0 of element 0 (cleared, never drawn); green where
// GetDimensions reports 2 elements of 4 samples.
float4 ShowSampledLayers(ClipVertex v) : SV_Target
{
    uint w, h, elements, samples;
    SampledLayers.GetDimensions(w, h, elements, samples);
    const int2 at = int2(v.Position.xy);
    const float4 drawn = SampledLayers.Load(int3(at, 1), 3);
    const float4 cleared = SampledLayers.Load(int3(at, 0), 0);
    return float4(drawn.g, elements == 2 && samples == 4 ? 1 : 0, cleared.b, 1);
}

float4 ShowSlices(ClipVertex v) : SV_Target
{
    const int3 at = int3(int2(v.UV * 16) % 16, Band(v.UV));
    return float4(Slices.Load(int4(at, 0)).gb, 0, 1);
}

DepthStencilState NoDepth { DepthEnable = FALSE; };
RasterizerState NoCull { CullMode = NONE; };

technique11 ArrayLayer < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Layers; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(CompileShader(gs_5_0, ToLayer(2)));
        SetPixelShader(CompileShader(ps_5_0, LayerColor()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, ShowLayers()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
}

technique11 MultisampleArray < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=SampledLayers; ClearSetColor=Blue; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(CompileShader(gs_5_0, ToLayer(1)));
        SetPixelShader(CompileShader(ps_5_0, LayerColor()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, ShowSampledLayers()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
}

technique11 VolumeSlice < string Script = "Pass=Draw; Pass=Show;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Slices; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(CompileShader(gs_5_0, ToLayer(2)));
        SetPixelShader(CompileShader(ps_5_0, LayerColor()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
    pass Show < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, ShowSlices()));
        SetDepthStencilState(NoDepth, 0);
        SetRasterizerState(NoCull);
    }
}
