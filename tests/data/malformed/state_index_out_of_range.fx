// No indexed state goes beyond 15 (Sampler[15]).
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t
{
    pass p
    {
        ColorWriteEnable[99] = 15;
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
