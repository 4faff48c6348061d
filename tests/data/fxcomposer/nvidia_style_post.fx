/*********************************************************************NVMH3****
An effect written the way NVIDIA's FX Composer 2 shader library wrote them (the usual header, SAS
annotations, macros from an include, a scene pass into an off-screen target and a Draw=Buffer
post-process pass whose sampler is handed over as a `uniform` argument of the compile expression).
Written for shadowfx's tests: it exercises what real files use, not what our own effects happen to.
******************************************************************************/

#include <include\\quad.fxh>

#define COLOR_WIDGET "Color"

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Technique?Main:Fallback;";
> = 0.8;

// [ untweakables ]
float4x4 WorldITXf : WorldInverseTranspose < string UIWidget="None"; >;
float4x4 WvpXf : WorldViewProjection < string UIWidget="None"; >;
float4x4 WorldXf : World < string UIWidget="None"; >;
float4x4 ViewIXf : ViewInverse < string UIWidget="None"; >;

// [ tweakables ]
float3 Lamp0Dir : Direction <
    string Object = "light0";
    string UIName = "Lamp 0 Direction";
    string Space = "World";
> = {0.0f, -1.0f, 0.0f};

float3 Lamp0Color : Specular <
    string UIName = "Lamp 0";
    string Object = "Pointlight0";
    string UIWidget = "Color";
> = {1.0f, 1.0f, 1.0f};

float Kd <
    string UIWidget = "slider";
    float UIMin = 0.0;
    float UIMax = 1.0;
    float UIStep = 0.01;
    string UIName = "Diffuse Strength";
> = 0.9;

float4 ClearColor <
    string UIWidget = (COLOR_WIDGET);
    string UIName = "Background";
    int width = 64, height = 64;
> = {0.2, 0.3, 0.6, 1.0};

float ClearDepth < string UIWidget = "None"; > = 1.0;

texture ColorTexture : DIFFUSE <
    string ResourceName = "default_color.dds";
    string UIName = "Diffuse Texture";
    string ResourceType = "2D";
>;

sampler2D ColorSampler = sampler_state {
    Texture = <ColorTexture>;
    FILTER = MIN_MAG_MIP_LINEAR;
    AddressU = Wrap;
    AddressV = Wrap;
};

textureCUBE EnvTexture : ENVIRONMENT <
    string ResourceName = "default_reflection.dds";
    string UIName = "Environment";
    string ResourceType = "Cube";
>;

samplerCUBE EnvSampler = sampler_state {
    Texture = <EnvTexture>;
    Filter = MIN_MAG_MIP_LINEAR;
    AddressU = Clamp;
    AddressV = Clamp;
    AddressW = Clamp;
};

DECLARE_QUAD_TEXTURE(SceneTexture, SceneSampler, A8R8G8B8)
DECLARE_QUAD_DEPTH_BUFFER(DepthBuffer, D24S8)

struct appdata {
    float3 Position : POSITION;
    float4 UV       : TEXCOORD0;
    float4 Normal   : NORMAL;
};

struct vertexOutput {
    float4 HPosition : POSITION;
    float2 UV        : TEXCOORD0;
    float3 WorldNormal : TEXCOORD1;
    float3 WorldView : TEXCOORD2;
};

vertexOutput std_VS(appdata IN,
    uniform float4x4 WorldITXf,
    uniform float4x4 WorldXf,
    uniform float4x4 ViewIXf,
    uniform float4x4 WvpXf)
{
    vertexOutput OUT = (vertexOutput)0;
    OUT.WorldNormal = mul(IN.Normal, WorldITXf).xyz;
    float4 Po = float4(IN.Position.xyz, 1);
    float3 Pw = mul(Po, WorldXf).xyz;
    OUT.UV = IN.UV.xy;
    OUT.WorldView = normalize(ViewIXf[3].xyz - Pw);
    OUT.HPosition = mul(Po, WvpXf);
    return OUT;
}

float4 std_PS(vertexOutput IN,
    uniform sampler2D ColorSampler,
    uniform samplerCUBE EnvSampler,
    uniform float Kd) : COLOR
{
    float3 Nn = normalize(IN.WorldNormal);
    float ldn = max(dot(-normalize(Lamp0Dir), Nn), 0.0);
    float3 diffuse = Kd * ldn * Lamp0Color * tex2D(ColorSampler, IN.UV).rgb;
    float3 env = texCUBE(EnvSampler, reflect(-IN.WorldView, Nn)).rgb;
    return float4(0.1 * env + diffuse * float3(0.9, 0.6, 0.3), 1);
}

// The post-process pass swaps red and blue: what the test checks to know it ran on the scene target.
float4 SwapPS(QuadVertexOutput IN, uniform sampler2D Source, uniform float Strength) : COLOR
{
    float4 c = tex2D(Source, IN.UV);
    return float4(lerp(c.rgb, c.bgr, Strength), 1);
}

technique Main <
    string Script =
        "RenderColorTarget0=SceneTexture;"
        "RenderDepthStencilTarget=DepthBuffer;"
        "ClearSetColor=ClearColor;"
        "ClearSetDepth=ClearDepth;"
        "Clear=Color;"
        "Clear=Depth;"
        "ScriptExternal=color;"
        "Pass=Lit;"
        "RenderColorTarget0=;"
        "RenderDepthStencilTarget=;"
        "Pass=Post;";
> {
    pass Lit <
        string Script = "Draw=geometry;";
    > {
        VertexShader = compile vs_3_0 std_VS(WorldITXf, WorldXf, ViewIXf, WvpXf);
        ZEnable = true;
        ZWriteEnable = true;
        ZFunc = LessEqual;
        AlphaBlendEnable = false;
        CullMode = None;
        PixelShader = compile ps_3_0 std_PS(ColorSampler, EnvSampler, Kd);
    }
    pass Post <
        string Script = "Draw=Buffer;";
    > {
        VertexShader = compile vs_3_0 ScreenQuadVS();
        AlphaBlendEnable = false;
        ZEnable = false;
        PixelShader = compile ps_3_0 SwapPS(SceneSampler, 1.0);
    }
}

technique Fallback {
    pass p0 {
        VertexShader = compile vs_2_0 std_VS(WorldITXf, WorldXf, ViewIXf, WvpXf);
        PixelShader = compile ps_2_0 std_PS(ColorSampler, EnvSampler, Kd);
    }
}
