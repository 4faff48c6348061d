// glslang 12's HLSL front end crashes (HlslParseContext::handleFunctionArgument) on the half-typed
// post-decrement of a read-only value below; the compile workers turn the crash into an error at PS.
float4x4 WorldViewProj : WorldViewProjection;

struct VSOut {
    float4 Pos : POSITION;
    float3 WorldNorm : TEXCOORD0;
};

VSOut VS(float4 P : POSITION, float3 N : NORMAL) {
    VSOut OUT;
    OUT.Pos = mul(P, WorldViewProj);
    OUT.WorldNorm = N;
    return OUT;
}

float4 PS(const VSOut IN) : COLOR {
    float3 Nn = normalize(IN.WorldNorm--);
    return float4(Nn * 0.5 + 0.5, 1.0);
}

technique Main {
    pass P0 {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
