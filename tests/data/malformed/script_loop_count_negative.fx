// A negative literal loop count.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t < string Script = "LoopByCount=-3; Pass=p; LoopEnd=;"; >
{
    pass p
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
