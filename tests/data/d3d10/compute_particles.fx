//--------------------------------------------------------------------------------------
// Particles advanced by a compute shader, in the style of FX11 compute-particle effects: pass `Advance`
// dispatches one thread per particle over a RWStructuredBuffer that keeps the particles between frames;
// pass `Draw` reads them through a StructuredBuffer view of the same buffer and draws a dot at each. A
// particle starts at age 0 (the buffer's zeros), is placed on its column when first advanced and rises by
// its velocity every frame: after frame n, particle i stands at (-0.75 + 0.1 i, -0.8 + 0.1 n), its
// colour's green n / 10. Everything is in clip space: no camera is involved.
//--------------------------------------------------------------------------------------
struct Particle
{
    float2 Position;
    float2 Velocity;
    float  Age;
};

RWStructuredBuffer<Particle> ParticleState < int ElementCount = 16; >;
StructuredBuffer<Particle> Particles < string ViewOf = "ParticleState"; >;
int GroupCount = 1;  // 16 threads a group: one group advances every particle
float4 Black = {0, 0, 0, 1};

[numthreads(16, 1, 1)]
void Advance(uint3 id : SV_DispatchThreadID)
{
    Particle p = ParticleState[id.x];
    if (p.Age == 0)
    {
        p.Position = float2(-0.75 + 0.1 * id.x, -0.8);
        p.Velocity = float2(0, 0.1);
    }
    p.Position += p.Velocity;
    p.Age += 1;
    ParticleState[id.x] = p;
}

// A shader variable, as FX11 effects often hold their compute shaders.
ComputeShader AdvanceCS = CompileShader(cs_5_0, Advance());

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 Clip : TEXCOORD0; };

QuadOut QuadVS(QuadVertex v)
{
    QuadOut o;
    o.Position = v.Position;
    o.Clip = v.Position.xy;
    return o;
}

float4 DrawParticles(QuadOut i) : SV_Target
{
    uint count, stride;
    Particles.GetDimensions(count, stride);
    for (uint k = 0; k < count; k++)
    {
        const Particle p = Particles[k];
        if (p.Age > 0 && all(abs(i.Clip - p.Position) < 0.04))
            return float4(1, p.Age / 10, 0, 1);
    }
    return Black;
}

DepthStencilState NoDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique11 Particles < string Script = "Pass=Advance; Pass=Draw;"; >
{
    pass Advance < string Script = "Dispatch=GroupCount,1,1;"; >
    {
        SetComputeShader(AdvanceCS);
    }
    pass Draw < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, DrawParticles()));
        SetDepthStencilState(NoDepth, 0);
    }
}
