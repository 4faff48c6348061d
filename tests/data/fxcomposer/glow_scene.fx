/*********************************************************************NVMH3****
A scene effect in the style of FX Composer 2's post-processing library: the host draws the scene
(ScriptExternal=color) into a target declared with ViewPortRatio, two blur passes over targets declared
by a macro with a D3DFMT_ format name, a LoopByCount over the pair, and a final composite into the frame
that the script clears itself (so the host does not).
******************************************************************************/

#define DECLARE_TARGET(Tex, Samp, Fmt) \
texture Tex : RENDERCOLORTARGET < float2 ViewPortRatio = {0.5, 0.5}; int MipLevels = 1; string Format = Fmt; >; \
sampler2D Samp = sampler_state { texture = <Tex>; AddressU = Clamp; AddressV = Clamp; MinFilter = Linear; \
                                 MagFilter = Linear; MipFilter = Point; };

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

float4 gClearColor < string UIWidget = "Color"; > = {0, 0, 0, 0};
float gClearDepth < string UIWidget = "none"; > = 1.0;
float gGlow < string UIWidget = "slider"; float UIMin = 0; float UIMax = 2; > = 0.8;
int gPasses < string UIWidget = "none"; > = 2;
float2 gViewportSize : VIEWPORTPIXELSIZE < string UIWidget = "None"; >;

texture gScene : RENDERCOLORTARGET < float2 ViewPortRatio = {1.0, 1.0}; int MipLevels = 1; string Format = "D3DFMT_X8R8G8B8"; >;
sampler2D gSceneSamp = sampler_state { texture = <gScene>; AddressU = Clamp; AddressV = Clamp; MinFilter = Linear;
                                       MagFilter = Linear; MipFilter = Point; };
texture gDepth : RENDERDEPTHSTENCILTARGET < float2 ViewPortRatio = {1.0, 1.0}; string Format = "D24S8"; >;
DECLARE_TARGET(gBlurH, gBlurHSamp, "D3DFMT_A16B16G16R16F")
DECLARE_TARGET(gBlurV, gBlurVSamp, "A16B16G16R16F")

struct QuadOut { float4 Position : POSITION; float2 UV : TEXCOORD0; };
QuadOut quadVS(float3 Position : POSITION, float3 UV : TEXCOORD0) {
    QuadOut OUT;
    OUT.Position = float4(Position, 1);
    OUT.UV = UV.xy;
    return OUT;
}

float4 blur(sampler2D s, float2 uv, float2 step) {
    float4 sum = 0;
    for (int i = -3; i <= 3; i++) sum += tex2D(s, uv + i * step) * (4 - abs(i)) / 16.0;
    return sum;
}

float4 blurHPS(QuadOut IN, uniform sampler2D src) : COLOR { return blur(src, IN.UV, float2(2.0 / gViewportSize.x, 0)); }
float4 blurVPS(QuadOut IN) : COLOR { return blur(gBlurHSamp, IN.UV, float2(0, 2.0 / gViewportSize.y)); }
float4 compositePS(QuadOut IN) : COLOR {
    return float4(tex2D(gSceneSamp, IN.UV).rgb + gGlow * tex2D(gBlurVSamp, IN.UV).rgb, 1);
}

technique Main <
    string Script =
        "RenderColorTarget0=gScene;"
        "RenderDepthStencilTarget=gDepth;"
        "ClearSetColor=gClearColor;"
        "ClearSetDepth=gClearDepth;"
        "Clear=Color|Depth;"
        "ScriptExternal=color;"
        "Pass=BlurH;"
        "Pass=BlurV;"
        "LoopByCount=gPasses;"
        "Pass=BlurH2;"
        "Pass=BlurV;"
        "LoopEnd;"
        "Pass=Composite;";
> {
    pass BlurH < string Script = "RenderColorTarget0=gBlurH; RenderDepthStencilTarget=; Draw=Buffer;"; > {
        ZEnable = false; CullMode = None;
        VertexShader = compile vs_2_0 quadVS(); PixelShader = compile ps_3_0 blurHPS(gSceneSamp);
    }
    pass BlurH2 < string Script = "RenderColorTarget0=gBlurH; Draw=Buffer;"; > {
        ZEnable = false; CullMode = None;
        VertexShader = compile vs_2_0 quadVS(); PixelShader = compile ps_3_0 blurHPS(gBlurVSamp);
    }
    pass BlurV < string Script = "RenderColorTarget0=gBlurV; Draw=Buffer;"; > {
        ZEnable = false; CullMode = None;
        VertexShader = compile vs_2_0 quadVS(); PixelShader = compile ps_3_0 blurVPS();
    }
    pass Composite < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Clear=Color; Draw=Buffer;"; > {
        ZEnable = false; CullMode = None;
        VertexShader = compile vs_2_0 quadVS(); PixelShader = compile ps_3_0 compositePS();
    }
}
