// The only technique streams its output (transform feedback): nothing is left to run.
float4 VS(float3 p : POSITION) : SV_Position { return float4(p, 1); }
technique10 Streamed
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw"));
        SetPixelShader(NULL);
    }
}
