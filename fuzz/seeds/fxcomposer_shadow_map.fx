// Fuzz seed in the style of NVIDIA FX Composer 2.5 effects: SAS annotations, a render-target depth map
// drawn from the light, a shadowed pass sampling it with tex2Dproj, Script-driven passes.
float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

float4x4 WorldITXf : WorldInverseTranspose < string UIWidget = "None"; >;
float4x4 WvpXf : WorldViewProjection < string UIWidget = "None"; >;
float4x4 WorldXf : World < string UIWidget = "None"; >;
float4x4 ViewIXf : ViewInverse < string UIWidget = "None"; >;
float4x4 LampViewXf : View < string Object = "SpotLight0"; string UIWidget = "None"; >;
float4x4 LampProjXf : Projection < string Object = "SpotLight0"; string UIWidget = "None"; >;

float3 SpotLamp0Pos : Position < string Object = "SpotLight0"; string UIName = "Lamp 0 Position";
    string Space = "World"; > = {-0.5f, 2.0f, 1.25f};
float3 Lamp0Color : Specular < string UIName = "Lamp 0"; string Object = "Spotlight0";
    string UIWidget = "Color"; > = {1.0f, 1.0f, 1.0f};
float ShadBias < string UIWidget = "slider"; float UIMin = 0.0; float UIMax = 1.3;
    float UIStep = 0.0001; string UIName = "Shadow Bias"; > = 0.01;
float4 ClearColor < string UIWidget = "color"; string UIName = "Background"; > = {0.1, 0.1, 0.1, 0.0};
float ClearDepth < string UIWidget = "none"; > = 1.0;

#define SHADOW_SIZE 512

texture ShadMap : RENDERCOLORTARGET < float2 Dimensions = {SHADOW_SIZE, SHADOW_SIZE};
    string Format = "r32f"; string UIWidget = "None"; >;
sampler2D ShadSampler = sampler_state {
    texture = <ShadMap>;
    AddressU = Clamp; AddressV = Clamp;
    MipFilter = None; MinFilter = Point; MagFilter = Point;
};
texture ShadDepthTarget : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {SHADOW_SIZE, SHADOW_SIZE};
    string Format = "D24S8"; string UIWidget = "None"; >;

struct appdata {
    float3 Position : POSITION;
    float4 UV : TEXCOORD0;
    float4 Normal : NORMAL;
};

struct ShadowingVertexOutput {
    float4 HPosition : POSITION;
    float4 LightPos : TEXCOORD1;
    float3 WNormal : TEXCOORD2;
    float3 LightVec : TEXCOORD3;
};

struct JustShadowVertexOutput {
    float4 HPosition : POSITION;
    float4 LP : TEXCOORD0;
};

JustShadowVertexOutput shadVS(appdata IN, uniform float4x4 ShadowViewProjXf) {
    JustShadowVertexOutput OUT = (JustShadowVertexOutput)0;
    float4 Po = float4(IN.Position.xyz, (float)1.0);
    float4 Pw = mul(Po, WorldXf);
    float4 Pl = mul(Pw, ShadowViewProjXf);
    OUT.HPosition = Pl;
    OUT.LP = Pl;
    return OUT;
}

float4 shadPS(JustShadowVertexOutput IN) : COLOR {
    return float4(IN.LP.zzz / IN.LP.w, 1);
}

ShadowingVertexOutput mainCamVS(appdata IN, uniform float4x4 ShadowViewProjXf) {
    ShadowingVertexOutput OUT = (ShadowingVertexOutput)0;
    OUT.WNormal = mul(IN.Normal, WorldITXf).xyz;
    float4 Po = float4(IN.Position.xyz, (float)1.0);
    float4 Pw = mul(Po, WorldXf);
    OUT.LightVec = SpotLamp0Pos - Pw.xyz;
    float4 Pl = mul(Pw, ShadowViewProjXf);
    OUT.LightPos = Pl;
    OUT.HPosition = mul(Po, WvpXf);
    return OUT;
}

float4 useShadowPS(ShadowingVertexOutput IN) : COLOR {
    float3 Nn = normalize(IN.WNormal);
    float3 Ln = normalize(IN.LightVec);
    float ldn = max(0, dot(Ln, Nn));
    float4 lp = IN.LightPos;
    float2 uv = lp.xy / lp.w * float2(0.5, -0.5) + 0.5;
    float stored = tex2D(ShadSampler, uv).x;
    float lit = (lp.z / lp.w - ShadBias) > stored ? 0.0 : 1.0;
    return float4(Lamp0Color * ldn * lit, 1);
}

technique Main < string Script = "Pass=MakeShadow;" "Pass=UseShadow;"; > {
    pass MakeShadow < string Script = "RenderColorTarget0=ShadMap;"
                                      "RenderDepthStencilTarget=ShadDepthTarget;"
                                      "RenderPort=SpotLight0;"
                                      "ClearSetColor=ClearColor;"
                                      "ClearSetDepth=ClearDepth;"
                                      "Clear=Color;"
                                      "Clear=Depth;"
                                      "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 shadVS(mul(LampViewXf, LampProjXf));
        ZEnable = true; ZWriteEnable = true; ZFunc = LessEqual;
        CullMode = None;
        PixelShader = compile ps_3_0 shadPS();
    }
    pass UseShadow < string Script = "RenderColorTarget0=;"
                                     "RenderDepthStencilTarget=;"
                                     "RenderPort=;"
                                     "ClearSetColor=ClearColor;"
                                     "ClearSetDepth=ClearDepth;"
                                     "Clear=Color;"
                                     "Clear=Depth;"
                                     "Draw=geometry;"; > {
        VertexShader = compile vs_3_0 mainCamVS(mul(LampViewXf, LampProjXf));
        ZEnable = true; ZWriteEnable = true; ZFunc = LessEqual;
        CullMode = None;
        PixelShader = compile ps_3_0 useShadowPS();
    }
}
