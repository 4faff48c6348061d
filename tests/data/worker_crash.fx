// Under the compile workers' crash hook (SHADOWFX_COMPILE_WORKER_TEST_CRASH=fx_test_crash_here) a worker
// dies of SIGSEGV on the pixel shader, which contains the marker, as glslang dies on text it crashes on.
float4x4 WorldViewProj : WorldViewProjection;

float4 VS(float4 P : POSITION) : POSITION {
    return mul(P, WorldViewProj);
}

float4 PS() : COLOR {
    float fx_test_crash_here = 1;
    return float4(fx_test_crash_here, 0, 0, 1);
}

technique Main {
    pass P0 {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
