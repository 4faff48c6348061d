// quad.fxh: in the manner of NVIDIA's shader library include of the same name: a full-screen quad vertex
// shader and the macros FX Composer effects use to declare post-processing targets.
#ifndef QUAD_FXH
#define QUAD_FXH

#define DECLARE_QUAD_TEXTURE(TexName, SampName, PixFmt) \
texture2D TexName : RENDERCOLORTARGET < \
    float2 ViewPortRatio = {1.0, 1.0}; \
    int MipLevels = 1; \
    string Format = #PixFmt; \
    string UIWidget = "None"; \
>; \
sampler2D SampName = sampler_state { \
    texture = <TexName>; \
    AddressU = Clamp; \
    AddressV = Clamp; \
    Filter = MIN_MAG_LINEAR_MIP_POINT; \
};

#define DECLARE_QUAD_DEPTH_BUFFER(TexName, PixFmt) \
texture TexName : RENDERDEPTHSTENCILTARGET < \
    float2 ViewPortRatio = {1.0, 1.0}; \
    string Format = #PixFmt; \
    string UIWidget = "None"; \
>;

struct QuadVertexOutput {
    float4 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

QuadVertexOutput ScreenQuadVS(float3 Position : POSITION, float3 TexCoord : TEXCOORD0)
{
    QuadVertexOutput OUT;
    OUT.Position = float4(Position, 1);
    OUT.UV = TexCoord.xy;
    return OUT;
}

#endif
