// A state error inside a pass that a macro writes: reported at the macro's use, with a note at its
// definition.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
#define LIT_PASS(name) pass name { VertexShader = compile vs_3_0 VS(); \
                                   PixelShader = compile ps_3_0 PS(); CullMode = Sideways; }
technique t
{
    LIT_PASS(p0)
}
