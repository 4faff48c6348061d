// C++'s brace initialization of locals, which FX11 games' fxc builds accepted: `float rim{};` is zero,
// `float3 v{...}` and `Pair p{...}` take their values in order. The object's colour is made of all three,
// (0.25, 0.5, 0.75): (64, 128, 191) on the object's pixels only where each took its value.
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;

struct Pair
{
    float a;
    float b;
};

float4 VS(float3 p : POSITION) : SV_POSITION
{
    return mul(float4(p, 1), WorldViewProjection);
}

float4 PS() : SV_Target
{
    float rim{};
    rim += 0.25;
    float3 v{0.5, 1, 0.75};
    Pair p{rim, v.y};
    return float4(p.a, v.x, v.z * p.b, 1);
}

technique11 Braces
{
    pass P
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
