// A post-decrement of a read-only parameter, as a call's argument: glslang's HLSL front end crashed on it
// (the operand it cannot decrement left a null the call read).
struct VSOut {
    float4 Pos : POSITION;
    float3 WorldNorm : TEXCOORD0;
};

float4 PS(const VSOut IN) : COLOR {
    float3 Nn = normalize(IN.WorldNorm--);
    return float4(Nn * 0.5 + 0.5, 1.0);
}

technique Main { pass P0 { PixelShader = compile ps_3_0 PS(); } }
