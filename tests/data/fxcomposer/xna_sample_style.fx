// An effect in the style of the XNA Game Studio samples: the pixel shader named `main`, as the sprite
// effects named theirs (D3DX compiled any function; GLSL keeps the name for its entry point), and the
// vertex output struct, point size included, reused as the pixel input, as the particle effects did.
float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float4x4 World : WORLD;

struct VS_OUTPUT
{
    float4 Position : POSITION0;
    float Size : PSIZE;
    float3 Normal : TEXCOORD0;
};

VS_OUTPUT ParticleVS(float4 position : POSITION0, float3 normal : NORMAL0)
{
    VS_OUTPUT output;
    output.Position = mul(position, WorldViewProj);
    output.Size = 4;
    output.Normal = mul(normal, (float3x3)World);
    return output;
}

float4 main(VS_OUTPUT input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float3 light = float3(1.0, 0.55, 0.25) * saturate(dot(n, normalize(float3(0.5, 1.0, 0.3)))) +
                   float3(0.15, 0.45, 1.0) * saturate(dot(n, normalize(float3(-0.6, 0.2, -0.8))));
    return float4((light + 0.05) * (1 - input.Size), 1);
}

technique Particle
{
    pass P0
    {
        VertexShader = compile vs_2_0 ParticleVS();
        PixelShader = compile ps_2_0 main();
    }
}
