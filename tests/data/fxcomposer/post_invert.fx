/*********************************************************************NVMH3****
A post-process effect in the style of FX Composer 2's library: ScriptClass "scene", the scene drawn
by the host (ScriptExternal=color) into a render target declared with ViewPortRatio only, then a
full-screen pass that inverts it. The effect draws no geometry of its own.
******************************************************************************/

#include <include\\PostQuad.fxh>

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

float4 ClearColor <
    string UIWidget = "color";
    string UIName = "Background";
> = {0,0,0,0};

float ClearDepth < string UIWidget = "None"; > = 1.0;

texture SceneTexture : RENDERCOLORTARGET <
    float2 ViewPortRatio = {1.0,1.0};
    int MipLevels = 1;
    string Format = "X8R8G8B8" ;
    string UIWidget = "None";
>;

sampler2D SceneSampler = sampler_state {
    texture = <SceneTexture>;
    AddressU = Clamp;
    AddressV = Clamp;
    Filter = MIN_MAG_LINEAR_MIP_POINT;
};

texture DepthBuffer : RENDERDEPTHSTENCILTARGET <
    float2 ViewPortRatio = {1.0,1.0};
    string Format = "D24S8";
    string UIWidget = "None";
>;

float Amount <
    string UIWidget = "slider";
    float UIMin = 0.0;
    float UIMax = 1.0;
    float UIStep = 0.01;
> = 1.0;

float4 invertPS(QuadVertexOutput IN) : COLOR {
    float4 scene = tex2D(SceneSampler, IN.UV);
    return float4(lerp(scene.rgb, 1.0 - scene.rgb, Amount), 1.0);
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
        "Pass=PostP0;";
> {
    pass PostP0 <
        string Script =
            "RenderColorTarget0=;"
            "RenderDepthStencilTarget=;"
            "Draw=Buffer;";
    > {
        VertexShader = compile vs_3_0 ScreenQuadVS();
        ZEnable = false;
        ZWriteEnable = false;
        AlphaBlendEnable = false;
        CullMode = None;
        PixelShader = compile ps_3_0 invertPS();
    }
}
