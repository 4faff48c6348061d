// The technique's '}' is missing; another technique starts.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique a
{
    pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }

technique b
{
    pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
