// The only technique sets a compute shader, which FX11 applications dispatch and no pass draws: nothing is
// left to run.
[numthreads(1, 1, 1)] void CS() {}
technique11 Computed
{
    pass
    {
        SetComputeShader(CompileShader(cs_5_0, CS()));
    }
}
