// An HLSL error inside a macro's expansion: reported at the macro's use, with a note at its definition.
#define OPAQUE(c) float4((c).xyzq, 1)
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR
{
    float3 color = float3(1, 0, 0);
    return OPAQUE(color);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
