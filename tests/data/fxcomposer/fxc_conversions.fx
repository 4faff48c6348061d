//-----------------------------------------------------------------------------
// HLSL that fxc compiled and glslang's HLSL front end refuses, in the styles of the DirectX 9 SDK's
// skinning and parallax samples and of FX Composer's shader library: vectors cast to arrays
// (`(float[4])v`, `(int[3])v`), an array of vectors initialized from a flat list of scalars,
// `unsigned int` and `unsigned`, the l-value constructor
// `float4(a, b) = e`, a vertex shader that writes a uniform parameter (D3DX9's compiler gave each shader
// its own modifiable copy), and `line` as a variable's name. The lit teapot's colour is
// Tint.rgb * lit * Gain, Gain doubled to 1: red up to full, half as much green, a quarter as much blue.
//-----------------------------------------------------------------------------

float4x4 WorldViewProj : WorldViewProjection;
float4x4 World : World;
float3 LightDir = {0.3f, 0.8f, 0.5f};
float4 Tint = {1.0f, 0.5f, 0.25f, 0.0f};
float Gain = 0.5f;  // doubled by the vertex shader, on its own copy

struct VS_INPUT
{
    float4 Pos    : POSITION;
    float3 Normal : NORMAL;
};

struct VS_OUTPUT
{
    float4 Pos   : POSITION;
    float4 Color : COLOR0;
};

float Lighting(float3 normal)
{
    // Reads the copy the vertex shader doubled, not the parameter; lit from both sides, at least half.
    return (0.5f + 0.5f * abs(dot(normal, normalize(LightDir)))) * Gain;
}

VS_OUTPUT VS(VS_INPUT i)
{
    VS_OUTPUT o;
    Gain *= 2.0f;
    // Cast the vectors to arrays for the loop below, as the SDK's skinning shaders do.
    float weights[4] = (float[4])Tint;
    int order[3] = (int[3])float3(0.0f, 1.0f, 2.0f);
    float3 n = normalize(mul(i.Normal, (float3x3)World));
    float lit = Lighting(n);
    unsigned int channels = 3;
    float3 c = 0;
    for (unsigned k = 0; k < channels; k++)
        c[k] = weights[order[k]];
    // An array of vectors from a flat list, as the SDK's PRT shaders start their sums.
    float4 scale[2] = { 1, 1, 1, 1, 0, 0, 0, 0 };
    o.Color = float4(c * lit, 1.0f) * scale[0] + scale[1];
    o.Pos = mul(i.Pos, WorldViewProj);
    return o;
}

float4 PS(VS_OUTPUT i) : COLOR0
{
    float2 rg, ba;
    float4(rg, ba) = i.Color;
    float line = 1.0f;
    return float4(rg, ba.x, line);
}

technique Conversions
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
