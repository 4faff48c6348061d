float4 PS() : COLOR { return 1; }
technique t
{
    pass p
    {
        PixelShader = compile ps_3_0 PS();
