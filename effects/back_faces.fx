// back_faces.fx: second-depth shadow mapping (Wang & Molnar; Lehőcz 2007, "Hátoldalak rajzolása"; Weiskopf & Ertl 2003,
// §2; Scherzer 2005, Fig. 6 bottom row): only the faces turned away from the light go into the map, so the
// depth a lit surface is tested against is the far side of its own solid, and self-shadowing moves to
// the far side, which its own shading darkens anyway. It needs closed objects; open ones (the ground
// plane) are drawn without culling through the pass annotation CullClosedOnly (docs/compiled-effect.md), and
// a small constant Bias keeps those from shadowing themselves.
//
// Measurement hooks: SHADOWFX_SHADOW_MAP_SIZE and SHADOWFX_VISIBILITY (include/shadow_scene.fxh).

#include "include/shadow_scene.fxh"
#include "include/light_depth.fxh"

float Script : STANDARDSGLOBAL
<
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=main;";
> = 0.8;

float Bias
<
    string UIWidget = "slider";
    string UIName = "Constant bias (open objects' acne)";
    float UIMin = 0.0;
    float UIMax = 0.02;
    float UIStep = 0.0001;
> = 0.003;

texture ShadowMap : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R32F";
    string UIWidget = "None";
>;

sampler ShadowMapSampler = sampler_state
{
    texture = <ShadowMap>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

float4 DepthPS(LightDepthVertexOutput IN) : COLOR
{
    return float4(LightDepth(IN), 0, 0, 1);
}

float4 BackFaceShadowPS(ReceiverVertexOutput IN) : COLOR
{
    return ReceiverColor(IN, ShadowTest(ShadowMapSampler, ShadowMapUV(IN.LP), ReceiverDepth(IN) - Bias));
}

technique main
<
    // Measured by `shadowfx stress` (docs/measurement.md, "shadowfx stress"); reported as xfail.
    string StressExpectedFailures = "grazing [ordinary]: the open ground stays in the back-face map "
                                    "(CullClosedOnly), under a constant bias";
    string Script = "Pass=ClearShadowMap;"
                    "Pass=RenderBackFaces;"
                    "Pass=RenderScene;";
    string ExpectScenes = "dual-l,double-torus";
    float ExpectMisclassifiedBelow = 0.4;  // measured 0.07 % dual-l, 0.19 % double-torus
    int ExpectMapSize = 256;   // heavily undersampled, as in Weiskopf & Ertl 2003, Fig. 5-6
>
{
    pass ClearShadowMap
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=MapDepthBuffer;"
                        "RenderPort=light0;"
                        "ClearSetColor=NoOccluder;"
                        "Clear=Color;";
    >
    {
    }

    pass RenderBackFaces
    <
        string Script = "RenderColorTarget0=ShadowMap;"
                        "RenderDepthStencilTarget=MapDepthBuffer;"
                        "RenderPort=light0;"
                        "Draw=geometry;";
        bool CullClosedOnly = true;  // the open ground plane is drawn whole
    >
    {
        CullMode = CW;  // cull D3D's front faces: the light sees the back faces
        AlphaBlendEnable = true;
        SrcBlend = one;
        DestBlend = one;
        BlendOp = min;
        ZEnable = false;
        ZWriteEnable = false;
        VertexShader = compile vs_3_0 LightDepthVS(mul(WorldMatrix, LightViewMatrix));
        PixelShader = compile ps_3_0 DepthPS();
    }

    pass RenderScene
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = CCW;
        AlphaBlendEnable = false;
        ZEnable = true;
        ZWriteEnable = true;
        ZFunc = LessEqual;
        VertexShader = compile vs_3_0 ReceiverVS();
        PixelShader = compile ps_3_0 BackFaceShadowPS();
    }
}
