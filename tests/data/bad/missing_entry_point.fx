float4 VS(float4 p : POSITION) : POSITION { return p; }
technique t
{
    pass p
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 NoSuchFunction();
    }
}
