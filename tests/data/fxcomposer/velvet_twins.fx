/*********************************************************************NVMH3****
A material in the style of FX Composer 2's library with D3D9/D3D10 twin techniques: the D3D10 ones sit
behind `#if DIRECT3D_VERSION >= 0xa00` and the selector names them anyway; a vertex-lit technique passes
its colours in COLOR0/COLOR1, a helper returns through `out` parameters, and the lamp is a
"PointLight0" position with the POSITION semantic.
******************************************************************************/

#ifndef FXCOMPOSER_VERSION
#define FXCOMPOSER_VERSION 180
#endif
#ifndef DIRECT3D_VERSION
#define DIRECT3D_VERSION 0x900
#endif
#define FLIP_TEXTURE_Y

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "object";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=Technique?VertexLit:VertexLit10:PixelLit:PixelLit10;";
> = 0.8;

float4x4 gWorldXf : World < string UIWidget="None"; >;
float4x4 gWorldITXf : WorldInverseTranspose < string UIWidget="None"; >;
float4x4 gWvpXf : WorldViewProjection < string UIWidget="None"; >;
float4x4 gViewIXf : ViewInverse < string UIWidget="None"; >;

float3 gLampPos : POSITION < string Object = "PointLight0"; string Space = "World"; > = {-0.5f, 2.0f, 1.25f};
float3 gSurface : DIFFUSE < string UIWidget = "Color"; > = {0.6f, 0.5f, 0.4f};
float3 gSheen < string UIWidget = "Color"; > = {0.7f, 0.7f, 0.75f};
float gRollOff < string UIWidget = "slider"; float UIMin = 0.0; float UIMax = 1.0; > = 0.3;

struct appdata { float3 Position : POSITION; float4 UV : TEXCOORD0; float4 Normal : NORMAL; };
struct litOut { float4 HPosition : POSITION; float2 UV : TEXCOORD0; float4 Diff : COLOR0; float4 Spec : COLOR1; };
struct pixOut { float4 HPosition : POSITION; float3 N : TEXCOORD1; float3 L : TEXCOORD2; float3 V : TEXCOORD3; };

void velvet(float3 Nn, float3 Ln, float3 Vn, float3 surface, uniform float3 sheen, uniform float rolloff,
            out float3 diffuse, out float3 specular)
{
    float ldn = dot(Ln, Nn);
    float sub = max(0.0, smoothstep(-rolloff, 1.0, ldn) - smoothstep(0.0, 1.0, ldn));
    diffuse = max(0, ldn) * surface + sub * float3(0.2, 0.2, 1.0);
    specular = (1.0 - abs(dot(Vn, Nn))) * sheen;
}

litOut vertexLitVS(appdata IN, uniform float3 LampPos) {
    litOut OUT;
    float3 Nn = normalize(mul(IN.Normal, gWorldITXf).xyz);
    float4 Po = float4(IN.Position.xyz, 1);
    float3 Pw = mul(Po, gWorldXf).xyz;
    float3 d, s;
    velvet(Nn, normalize(LampPos - Pw), normalize(gViewIXf[3].xyz - Pw), gSurface, gSheen, gRollOff, d, s);
    OUT.HPosition = mul(Po, gWvpXf);
#ifdef FLIP_TEXTURE_Y
    OUT.UV = float2(IN.UV.x, 1.0 - IN.UV.y);
#else
    OUT.UV = IN.UV.xy;
#endif
    OUT.Diff = float4(d, 1);
    OUT.Spec = float4(s, 1);
    return OUT;
}

float4 vertexLitPS(litOut IN) : COLOR { return float4((IN.Diff + IN.Spec).rgb, 1); }

pixOut pixelLitVS(appdata IN, uniform float3 LampPos) {
    pixOut OUT;
    float4 Po = float4(IN.Position.xyz, 1);
    float3 Pw = mul(Po, gWorldXf).xyz;
    OUT.HPosition = mul(Po, gWvpXf);
    OUT.N = mul(IN.Normal, gWorldITXf).xyz;
    OUT.L = LampPos - Pw;
    OUT.V = gViewIXf[3].xyz - Pw;
    return OUT;
}

float4 pixelLitPS(pixOut IN, uniform float3 Surface) : COLOR {
    float3 d, s;
    velvet(normalize(IN.N), normalize(IN.L), normalize(IN.V), Surface, gSheen, gRollOff, d, s);
    return float4(d + s, 1);
}

#if DIRECT3D_VERSION >= 0xa00
technique10 VertexLit10 < string Script = "Pass=p0;"; > {
    pass p0 < string Script = "Draw=geometry;"; > {
        SetVertexShader(CompileShader(vs_4_0, vertexLitVS(gLampPos)));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, vertexLitPS()));
    }
}
#endif

technique VertexLit < string Script = "Pass=p0;"; > {
    pass p0 < string Script = "Draw=geometry;"; > {
        VertexShader = compile vs_2_0 vertexLitVS(gLampPos);
        ZEnable = true; ZWriteEnable = true; ZFunc = LessEqual; AlphaBlendEnable = false; CullMode = None;
        PixelShader = compile ps_2_0 vertexLitPS();
    }
}

technique PixelLit < string Script = "Pass=p0;"; > {
    pass p0 < string Script = "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 pixelLitVS(gLampPos);
        ZEnable = true; ZWriteEnable = true; ZFunc = LessEqual; AlphaBlendEnable = false; CullMode = None;
        PixelShader = compile ps_3_0 pixelLitPS(gSurface);
    }
}
