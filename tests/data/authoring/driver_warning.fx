// A pixel shader that reads a static never assigned (test_cli.cpp): the GL driver warns about the
// generated GLSL, with the GLSL's line numbers; render prints it with --driver-log only, at the pass.
float4x4 WorldViewProjection : WorldViewProjection;
static float Gain;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR { return float4(Gain, 0.5, 0.5, 1); }
technique main
{
    pass lit
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
