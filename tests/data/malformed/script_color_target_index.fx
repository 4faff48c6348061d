// RenderColorTarget4 does not exist (0..3).
texture Map : RENDERCOLORTARGET < float2 Dimensions = {64, 64}; >;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t < string Script = "RenderColorTarget4=Map; Pass=p;"; >
{
    pass p
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
