// LoopByCount without LoopEnd.
int Count = 4;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t < string Script = "LoopByCount=Count; Pass=p;"; >
{
    pass p
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
