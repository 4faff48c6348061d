//--------------------------------------------------------------------------------------
// A particle system in the style of the DirectX SDK's ParticlesGS sample: pass `advance` streams the
// particles out of a geometry shader (ConstructGSWithSO, NULL pixel shader) and draws what it captured
// the frame before (DrawAuto, seeded with one zero vertex: the launcher); pass `draw` draws this frame's
// capture as quads. The launcher (TYPE 0) counts frames in TIMER and emits one particle a frame; a
// particle (TYPE 1) moves by its velocity and ages by one a frame, so frame n shows n particles on the
// diagonal from (-0.8, 0.8), the newest there. Everything is in clip space: no camera is involved.
//--------------------------------------------------------------------------------------
float g_fStep = 1.0;  // one frame's time step
float4 Black = {0, 0, 0, 1};

struct Particle
{
    float3 pos   : POSITION;
    float3 vel   : NORMAL;
    float  Timer : TIMER;
    uint   Type  : TYPE;
};

Particle VSPassThrough(Particle input)
{
    return input;
}

[maxvertexcount(2)]
void GSAdvance(point Particle input[1], inout PointStream<Particle> ParticleOutputStream)
{
    Particle p = input[0];
    if (p.Type == 0)
    {
        Particle born;
        born.pos = float3(-0.8, 0.8, 0.5);
        born.vel = float3(0.15, -0.15, 0);
        born.Timer = 0;
        born.Type = 1;
        ParticleOutputStream.Append(born);
        p.Timer += g_fStep;
        ParticleOutputStream.Append(p);
    }
    else if (p.Timer < 12)
    {
        p.pos += p.vel * g_fStep;
        p.Timer += g_fStep;
        ParticleOutputStream.Append(p);
    }
}

GeometryShader gsStreamOut = ConstructGSWithSO(CompileShader(gs_4_0, GSAdvance()),
                                               "POSITION.xyz; NORMAL.xyz; TIMER.x; TYPE.x");

struct DrawIn
{
    float4 pos  : SV_Position;
    float  age  : TIMER;
    float  kind : TYPE;
};

DrawIn VSDraw(Particle input)
{
    DrawIn output;
    output.pos = float4(input.pos, 1);
    output.age = input.Timer;
    output.kind = (float)input.Type;
    return output;
}

struct PSIn
{
    float4 pos   : SV_Position;
    float4 color : COLOR0;
};

[maxvertexcount(4)]
void GSQuad(point DrawIn input[1], inout TriangleStream<PSIn> SpriteStream)
{
    if (input[0].kind < 0.5)
        return;  // the launcher is not drawn
    PSIn output;
    output.color = float4(1, input[0].age / 10, 0, 1);
    const float size = 0.06;
    for (int i = 0; i < 4; i++)
    {
        float2 corner = float2(i % 2 == 0 ? -size : size, i < 2 ? size : -size);
        output.pos = float4(input[0].pos.xy + corner, 0.5, 1);
        SpriteStream.Append(output);
    }
    SpriteStream.RestartStrip();
}

float4 PSQuad(PSIn input) : SV_Target
{
    return input.color;
}

DepthStencilState DisableDepth { DepthEnable = FALSE; DepthWriteMask = ZERO; };
RasterizerState NoCull { CullMode = NONE; };

technique10 Particles < string Script = "Pass=advance; Pass=draw;"; >
{
    pass advance < string Script = "ClearSetColor=Black; Clear=Color; Draw=Geometry;";
                   string DrawAuto = "advance"; int StreamOutVertices = 64; >
    {
        SetVertexShader(CompileShader(vs_4_0, VSPassThrough()));
        SetGeometryShader(gsStreamOut);
        SetPixelShader(NULL);
        SetDepthStencilState(DisableDepth, 0);
    }
    pass draw < string DrawAuto = "advance"; >
    {
        SetVertexShader(CompileShader(vs_4_0, VSDraw()));
        SetGeometryShader(CompileShader(gs_4_0, GSQuad()));
        SetPixelShader(CompileShader(ps_4_0, PSQuad()));
        SetDepthStencilState(DisableDepth, 0);
        SetRasterizerState(NoCull);
    }
}
