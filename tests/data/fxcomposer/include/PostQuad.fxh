// Full-screen quad helpers, as FX Composer's Quad.fxh declares them.
#ifndef _POSTQUAD_FXH
#define _POSTQUAD_FXH

float2 ViewportSize : VIEWPORTPIXELSIZE < string UIWidget = "None"; >;

struct QuadVertexOutput {
    float4 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

QuadVertexOutput ScreenQuadVS(float3 Position : POSITION, float3 TexCoord : TEXCOORD0) {
    QuadVertexOutput OUT;
    OUT.Position = float4(Position, 1);
    OUT.UV = TexCoord.xy;
    return OUT;
}

#endif
