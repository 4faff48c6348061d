// The only technique's compute pass also sets a vertex shader: shadowfx keeps a pass dispatched or drawn,
// so nothing is left to run.
float4 VS(float4 p : POSITION) : SV_Position { return p; }
[numthreads(1, 1, 1)] void CS() {}
technique11 Computed
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetComputeShader(CompileShader(cs_5_0, CS()));
    }
}
