// plain_lit.fx: Blinn-Phong lighting from light0 without shadows; the reference every shadow effect is
// compared with, and the smallest complete effect for newcomers to copy.

#include "include/lighting.fxh"

float4x4 WorldViewProjection : WorldViewProjection <string UIWidget = "None";>;
float4x4 World : World <string UIWidget = "None";>;
float4x4 WorldIT : WorldInverseTranspose <string UIWidget = "None";>;
float4x4 ViewInverse : ViewInverse <string UIWidget = "None";>;

float3 LightDirection : Direction
<
    string Object = "light0";
    string UIWidget = "none";
> = {0.0, -1.0, 0.0};

float3 LightColor : LightColor <string Object = "light0"; string UIWidget = "none";> = {1.0, 1.0, 1.0};
float3 AmbientColor : Ambient <string UIWidget = "color";> = {0.15, 0.15, 0.15};
float3 SurfaceColor : Diffuse <string UIWidget = "none";> = {0.8, 0.8, 0.8};

float SpecularPower
<
    string UIWidget = "slider";
    float UIMin = 1.0;
    float UIMax = 128.0;
> = 32.0;

float4 ClearColor <string UIWidget = "color";> = {0.32, 0.36, 0.42, 1.0};

struct AppData
{
    float3 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VertexOutput
{
    float4 HPosition : POSITION;
    float3 WNormal   : TEXCOORD0;
    float3 WView     : TEXCOORD1;
};

VertexOutput LitVS(AppData IN)
{
    VertexOutput OUT;
    float4 Pw = mul(float4(IN.Position, 1.0), World);
    OUT.HPosition = mul(float4(IN.Position, 1.0), WorldViewProjection);
    OUT.WNormal = mul(IN.Normal, (float3x3)WorldIT);
    OUT.WView = ViewInverse[3].xyz - Pw.xyz;
    return OUT;
}

float4 LitPS(VertexOutput IN) : COLOR
{
    float3 N = normalize(IN.WNormal);
    float3 V = normalize(IN.WView);
    float3 L = -normalize(LightDirection);
    float4 terms = BlinnPhongTerms(N, V, L, SpecularPower);
    float3 color = SurfaceColor * (AmbientColor + terms.y * LightColor) + 0.3 * terms.z * LightColor;
    return float4(color, 1.0);
}

technique lit
<
    // Conformance (shadowfx check, docs/measurement.md, "shadowfx check"): no shadows, so only compile,
    // render, non-blank and golden checks.
    bool ExpectShadows = false;
    string ExpectScenes = "boxes,teapot";
    string Script = "ClearSetColor=ClearColor;"
                    "Clear=Color;"
                    "Clear=Depth;"
                    "Pass=p0;";
>
{
    pass p0
    {
        ZEnable = true;
        ZWriteEnable = true;
        CullMode = CCW;
        VertexShader = compile vs_3_0 LitVS();
        PixelShader = compile ps_3_0 LitPS();
    }
}
