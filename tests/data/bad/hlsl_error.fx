float4 VS(float4 p : POSITION) : POSITION { return p; }

float4 PS() : COLOR
{
    float3 color = float3(1, 0, 0);
    return color.xyzq;
}

technique t
{
    pass p
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
