// A D3DX9 effect in the style of a shipped game's core effect set: the effect keywords, the state names
// and their values in any case, shared parameters, an array sized by arithmetic on a static const, an
// include line with text after the file name, and a condition calling a macro nobody defined.
#include "include/game_platform.fxh" ;

shared Matrix WorldViewProj : WORLDVIEWPROJECTION;
shared float4x4 World : WORLD;

static const int LIGHT_COUNT = 2;
float4 LightColors[3 * LIGHT_COUNT - 4] = { { 1.0, 0.6, 0.2, 1.0 }, { 0.1, 0.5, 1.0, 1.0 } };

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Normal : TEXCOORD0;
};

VS_OUTPUT MainVS(float4 position : POSITION, float3 normal : NORMAL)
{
    VS_OUTPUT o;
    o.Position = mul(position, WorldViewProj);
    o.Normal = mul(normal, (float3x3)World);
    return o;
}

float4 MainPS(VS_OUTPUT i) : COLOR
{
    float3 n = normalize(i.Normal);
    // Two coloured lights from opposite sides: every channel varies over the surface.
    float3 c = LightColors[0].rgb * saturate(dot(n, normalize(float3(0.5, 1.0, 0.3)))) +
               LightColors[1].rgb * saturate(dot(n, normalize(float3(-0.6, 0.2, -0.8))));
    return float4(c + 0.05, 1);
}

#if PLATFORM_SUPPORTS(HDR)
#error a call to an undefined macro in a condition must read as 0
#endif

Technique Main
{
    Pass P0
    {
        VertexShader = Compile vs_3_0 MainVS();
        PIXELSHADER = compile PS_PROFILE MainPS();
        ZENABLE = TRUE;
        zwriteenable = true;
        CullMode = none;
        ALPHABLENDENABLE = FALSE;
        colorwriteenable = RED | green | Blue | ALPHA;
    }
}
