// A vector passed to a scalar parameter of the effect's own function, as MonoGame-era deferred renderers
// passed a float4 depth to their shadow filters (`CalcShadowTermPCF(depthInLV, NdL, uv)`): fxc kept the
// first component with warning X3206. Three forms, one per channel: a local float4, a two-component
// swizzle of a parameter and a parameter itself. The objects are (First(Local), First(Levels.yz),
// First(Levels)) = (1, 0.5, 0.25); a call that received another component draws another colour.
float4x4 WorldViewProj : WorldViewProjection;
float3 Levels = {0.25, 0.5, 1.0};

float First(float level, float scale)
{
    return level * scale;
}

float4 VS(float4 position : POSITION) : POSITION
{
    return mul(position, WorldViewProj);
}

float4 PS() : COLOR
{
    float4 local = float4(1, 0, 0, 0);
    return float4(First(local, 1), First(Levels.yz, 1), First(Levels, 1), 1);
}

technique Truncated
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
