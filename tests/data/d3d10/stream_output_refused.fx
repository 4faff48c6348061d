//--------------------------------------------------------------------------------------
// In the style of the DirectX SDK's particle samples: a geometry shader with stream output held by a
// variable (ConstructGSWithSO) advances the particles, another technique draws the scene. shadowfx has no
// transform feedback: technique AdvanceParticles is left out with a warning at the pass that sets the
// variable, and RenderScene still runs.
//--------------------------------------------------------------------------------------
float4x4 g_mWorldViewProj;
float g_fElapsedTime;

struct VSParticleIn
{
    float3 pos   : POSITION;
    float3 vel   : NORMAL;
    float  Timer : TIMER;
};

VSParticleIn VSPassThrough(VSParticleIn input)
{
    return input;
}

[maxvertexcount(1)]
void GSAdvance(point VSParticleIn input[1], inout PointStream<VSParticleIn> ParticleOutputStream)
{
    VSParticleIn output = input[0];
    output.pos += output.vel * g_fElapsedTime;
    output.Timer -= g_fElapsedTime;
    ParticleOutputStream.Append(output);
}

GeometryShader gsStreamOut = ConstructGSWithSO(CompileShader(gs_4_0, GSAdvance()),
                                               "POSITION.xyz; NORMAL.xyz; TIMER.x");

struct PSSceneIn
{
    float4 pos   : SV_Position;
    float4 color : COLOR0;
};

PSSceneIn VSScene(float3 pos : POSITION, float3 norm : NORMAL)
{
    PSSceneIn output;
    output.pos = mul(float4(pos, 1), g_mWorldViewProj);
    output.color = float4(norm * 0.5 + 0.5, 1);
    return output;
}

float4 PSScene(PSSceneIn input) : SV_Target
{
    return input.color;
}

DepthStencilState DisableDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };

technique10 AdvanceParticles
{
    pass p0
    {
        SetVertexShader(CompileShader(vs_4_0, VSPassThrough()));
        SetGeometryShader(gsStreamOut);
        SetPixelShader(NULL);
        SetDepthStencilState(DisableDepth, 0);
    }
}

technique10 RenderScene
{
    pass p0
    {
        SetVertexShader(CompileShader(vs_4_0, VSScene()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PSScene()));
    }
}
