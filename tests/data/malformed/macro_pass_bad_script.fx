// A script error inside a pass that a macro writes: reported at the macro's use, with a note at its
// definition.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
#define DRAWN_PASS pass p < string Script = "Draw=Everything;"; > \
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
technique t < string Script = "Pass=p;"; >
{
    DRAWN_PASS
}
