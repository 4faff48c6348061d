// The only technique streams out part of a vertex shader's output, which GL cannot capture (it captures
// whole output variables): nothing is left to run.
struct VsOut { float4 pos : SV_Position; float2 uv : UV; };
VsOut VS(float3 p : POSITION) { VsOut o; o.pos = float4(p, 1); o.uv = p.xy; return o; }
technique10 Streamed
{
    pass
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "SV_POSITION.xyzw; UV.x"));
        SetPixelShader(NULL);
    }
}
