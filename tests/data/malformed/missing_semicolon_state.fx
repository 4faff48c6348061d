// A state assignment without its ';': reported after it, and the pass parses on.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t
{
    pass p
    {
        CullMode = None
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
