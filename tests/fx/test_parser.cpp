// Parser tests: every effect construct, field by field.
#include <fx/EffectParser.h>
#include <fx/SasScript.h>

#include <gtest/gtest.h>

#include <map>

namespace test_parser {

using namespace fx;

namespace {

std::shared_ptr<Effect> parse(const std::string& source, DiagnosticList& diags,
                              const std::map<std::string, std::string>& files = {}) {
    ParseOptions options;
    options.readFile = [files](const std::string& path) -> std::optional<std::string> {
        auto found = files.find(path);
        if (found == files.end()) return std::nullopt;
        return found->second;
    };
    return parseEffectSource(source, "test.fx", options, diags);
}

std::shared_ptr<Effect> parseOk(const std::string& source) {
    DiagnosticList diags;
    auto effect = parse(source, diags);
    EXPECT_TRUE(effect) << diags.str();
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    return effect;
}

const StateAssignment* findState(const std::vector<StateAssignment>& states, const std::string& name) {
    for (const auto& s : states)
        if (s.name == name) return &s;
    return nullptr;
}

// The model effect: FX Composer listing of Lehőcz 2007 (page-break damage repaired), abridged bodies.
const char* kThesisEffect = R"(const float2 SHADOW_SIZE;
#define ZMaxValue 130944/16.0
#define ShadowRange 12000.0
#define ShadowRangeMultiplier (ZMaxValue/ShadowRange)

const bool JITTER=false;
float Bias = 0.01;
bool bFlip=false;
float4 ClearColor = {0, 0, 0, 0};
float ClearDepth
<
    string UIWidget = "none";
> = 1.0;
float4 ShadowClearColor = {ZMaxValue, ZMaxValue, ZMaxValue, ZMaxValue};
float4x4 WorldViewProjectionMatrix : WorldViewProjection <string UIWidget="None";>;
float4x4 WorldMatrix : World <string UIWidget="None";>;
float4x4 LightViewMatrix : View
<
    string frustum = "light0";
>;
float4x4 LightProjectionMatrix : Projection < string frustum = "light0"; >;
float3 LightColor : Diffuse = {1.0, 1.0, 1.0};
texture DiffuseTexture : Diffuse0;
sampler DiffuseSampler = sampler_state
{
    texture = <DiffuseTexture>;
    AddressU = WRAP;
    AddressV = WRAP;
    MIPFILTER = LINEAR;
    MINFILTER = ANISOTROPIC;
    MAGFILTER = LINEAR;
};
texture ShadowMap : RENDERCOLORTARGET;
sampler ShadowMapSampler = sampler_state
{
    texture = <ShadowMap>;
    AddressU = CLAMP;
    MipFilter = NONE;
};
texture ShadDepthTarget : RENDERDEPTHSTENCILTARGET;
struct VertexFormat
{
    float4 Position      : POSITION;
    float4 UV            : TEXCOORD0;
    float4 Normal: NORMAL;
};
struct RenderShadowMapVertexOutput
{
    float4 Position      : POSITION;
    float  Z             : TEXCOORD0;
};
RenderShadowMapVertexOutput RenderShadowMapVS(VertexFormat IN, uniform float4x4
WorldViewProjectionMatrix)
{
    RenderShadowMapVertexOutput OUT;
    OUT.Position = mul(float4(IN.Position.xyz, 1.0), WorldViewProjectionMatrix);
    OUT.Z = OUT.Position.z;
    return OUT;
}
float4 RenderShadowMapPS(RenderShadowMapVertexOutput IN) : COLOR
{
    return float4(IN.Z*ShadowRangeMultiplier, 1, 1, 1);
}
float4 ClearVS(float4 p : POSITION) : POSITION { return p; }
float4 ClearPS() : COLOR { return float4(ZMaxValue, ZMaxValue, ZMaxValue, ZMaxValue); }
technique main
<
    string Script =      "Pass=ClearShadowMap;"
                        "Pass=RenderShadowMap;";
>
{
    pass ClearShadowMap
    <
        string Script =      "RenderColorTarget0=ShadowMap;"
                            "RenderDepthStencilTarget=ShadDepthTarget;"
                            "RenderPort=light0;"
                            "Draw=geometry;";
    >
    {
        CullMode = None;
        AlphaBlendEnable=false;
        ZEnable = false;
        VertexShader = compile vs_2_0 ClearVS();
        PixelShader = compile ps_2_0 ClearPS();
    }
    pass RenderShadowMap
    {
        AlphaBlendEnable=true;
        SrcBlend=one;
        DestBlend=one;
        BlendOp=min;
        ZFunc = LessEqual;
        VertexShader = compile vs_2_0 RenderShadowMapVS(mul(WorldMatrix,
mul(LightViewMatrix, LightProjectionMatrix)));
        PixelShader = compile ps_2_0 RenderShadowMapPS();
    }
}
)";

}  // namespace

TEST(Parser, ThesisEffectParameters) {
    auto effect = parseOk(kThesisEffect);
    ASSERT_TRUE(effect);
    const Parameter* size = effect->findParameter("SHADOW_SIZE");
    ASSERT_TRUE(size);
    EXPECT_TRUE(size->isConst);
    EXPECT_EQ(size->type.shape, Shape::Vector);
    EXPECT_EQ(size->type.cols, 2);
    EXPECT_EQ(size->loc.line, 1);
    EXPECT_EQ(size->loc.column, 14);

    const Parameter* clearDepth = effect->findParameter("ClearDepth");
    ASSERT_TRUE(clearDepth);
    ASSERT_TRUE(clearDepth->annotation("uiwidget"));
    EXPECT_EQ(clearDepth->annotation("UIWidget")->value.text, "none");
    ASSERT_TRUE(clearDepth->initializer);
    EXPECT_EQ(clearDepth->initializer->number, 1.0);

    const Parameter* shadowClear = effect->findParameter("ShadowClearColor");
    ASSERT_TRUE(shadowClear && shadowClear->initializer);
    EXPECT_EQ(shadowClear->initializer->kind, Expr::Kind::InitList);
    ASSERT_EQ(shadowClear->initializer->args.size(), 4u);
    EXPECT_EQ(shadowClear->initializer->args[0].str(), "130944 / 16.0");

    const Parameter* wvp = effect->findParameter("WorldViewProjectionMatrix");
    ASSERT_TRUE(wvp);
    EXPECT_EQ(wvp->semantic, "WorldViewProjection");
    EXPECT_EQ(wvp->type.hlslName(), "float4x4");
    EXPECT_EQ(wvp->type.componentCount(), 16);
    EXPECT_EQ(effect->findParameter("LightViewMatrix")->annotation("frustum")->value.text, "light0");

    const Parameter* shadowMap = effect->findParameter("ShadowMap");
    ASSERT_TRUE(shadowMap);
    EXPECT_EQ(shadowMap->type.base, BaseType::Texture);
    EXPECT_EQ(shadowMap->semantic, "RENDERCOLORTARGET");
    EXPECT_EQ(effect->findParameter("ShadDepthTarget")->semantic, "RENDERDEPTHSTENCILTARGET");

    const Parameter* sampler = effect->findParameter("DiffuseSampler");
    ASSERT_TRUE(sampler);
    EXPECT_EQ(sampler->type.base, BaseType::Sampler);
    ASSERT_EQ(sampler->samplerState.size(), 6u);
    EXPECT_EQ(sampler->samplerState[0].value.kind, Expr::Kind::TextureRef);
    EXPECT_EQ(sampler->samplerState[0].value.text, "DiffuseTexture");
    EXPECT_EQ(sampler->samplerState[1].value.kind, Expr::Kind::Number);
    EXPECT_EQ(sampler->samplerState[1].value.number, 1);  // WRAP
    EXPECT_EQ(sampler->samplerState[4].name, "MINFILTER");
    EXPECT_EQ(sampler->samplerState[4].value.number, 3);  // ANISOTROPIC
    EXPECT_EQ(findState(effect->findParameter("ShadowMapSampler")->samplerState, "AddressU")->value.number,
              3);
    EXPECT_EQ(findState(effect->findParameter("ShadowMapSampler")->samplerState, "MipFilter")->value.number,
              0);
}

TEST(Parser, ThesisEffectStructsAndFunctions) {
    auto effect = parseOk(kThesisEffect);
    ASSERT_TRUE(effect);
    const StructDecl* vf = effect->findStruct("VertexFormat");
    ASSERT_TRUE(vf);
    ASSERT_EQ(vf->members.size(), 3u);
    EXPECT_EQ(vf->members[1].name, "UV");
    EXPECT_EQ(vf->members[1].semantic, "TEXCOORD0");
    EXPECT_EQ(vf->members[2].semantic, "NORMAL");
    EXPECT_EQ(vf->hlslText.substr(0, 19), "struct VertexFormat");
    EXPECT_EQ(vf->hlslText.back(), ';');

    auto vs = effect->findFunctions("RenderShadowMapVS");
    ASSERT_EQ(vs.size(), 1u);
    EXPECT_EQ(vs[0]->returnType.structName, "RenderShadowMapVertexOutput");
    ASSERT_EQ(vs[0]->params.size(), 2u);
    EXPECT_FALSE(vs[0]->params[0].isUniform);
    EXPECT_EQ(vs[0]->params[0].type.structName, "VertexFormat");
    EXPECT_TRUE(vs[0]->params[1].isUniform);
    EXPECT_EQ(vs[0]->params[1].name, "WorldViewProjectionMatrix");
    EXPECT_EQ(vs[0]->params[1].loc.line, 53);
    EXPECT_EQ(vs[0]->hlslText.back(), '}');
    auto ps = effect->findFunctions("RenderShadowMapPS");
    ASSERT_EQ(ps.size(), 1u);
    EXPECT_EQ(ps[0]->returnSemantic, "COLOR");
    // Macros are expanded in the HLSL text.
    EXPECT_NE(ps[0]->hlslText.find("(130944 / 16.0 / 12000.0)"), std::string::npos) << ps[0]->hlslText;
    auto clearVS = effect->findFunctions("ClearVS");
    ASSERT_EQ(clearVS.size(), 1u);
    EXPECT_EQ(clearVS[0]->params[0].semantic, "POSITION");
    EXPECT_EQ(clearVS[0]->returnSemantic, "POSITION");
}

TEST(Parser, ThesisEffectTechnique) {
    auto effect = parseOk(kThesisEffect);
    ASSERT_TRUE(effect);
    const Technique* main = effect->findTechnique("main");
    ASSERT_TRUE(main);
    ASSERT_EQ(main->passes.size(), 2u);
    const Annotation* script = main->annotation("Script");
    ASSERT_TRUE(script);
    EXPECT_EQ(script->value.text, "Pass=ClearShadowMap;Pass=RenderShadowMap;");
    ASSERT_EQ(script->value.stringPieces.size(), 2u);

    const Pass& clear = main->passes[0];
    EXPECT_EQ(clear.name, "ClearShadowMap");
    DiagnosticList diags;
    auto commands = parseSasScript(clear.annotation("Script")->value, diags);
    EXPECT_FALSE(diags.hasErrors()) << diags.str();
    ASSERT_EQ(commands.size(), 4u);
    EXPECT_EQ(commands[0].kind, ScriptCommand::Kind::RenderColorTarget);
    EXPECT_EQ(commands[0].value, "ShadowMap");
    EXPECT_EQ(commands[3].kind, ScriptCommand::Kind::Draw);
    EXPECT_EQ(commands[3].draw, ScriptCommand::DrawWhat::Geometry);
    EXPECT_EQ(commands[3].loc.line, 77);
    EXPECT_EQ(commands[3].loc.column, 30);

    EXPECT_EQ(findState(clear.states, "CullMode")->value.number, 1);  // None
    EXPECT_EQ(findState(clear.states, "AlphaBlendEnable")->value.kind, Expr::Kind::Bool);
    const StateAssignment* vs = findState(clear.states, "VertexShader");
    ASSERT_TRUE(vs);
    EXPECT_EQ(vs->value.kind, Expr::Kind::Compile);
    EXPECT_EQ(vs->value.profile, "vs_2_0");
    EXPECT_EQ(vs->value.text, "ClearVS");

    const Pass& shadow = main->passes[1];
    EXPECT_EQ(findState(shadow.states, "SrcBlend")->value.number, 2);  // one
    EXPECT_EQ(findState(shadow.states, "BlendOp")->value.number, 4);   // min
    EXPECT_EQ(findState(shadow.states, "ZFunc")->value.number, 4);     // LessEqual
    const StateAssignment* shadowVs = findState(shadow.states, "VertexShader");
    ASSERT_TRUE(shadowVs);
    ASSERT_EQ(shadowVs->value.args.size(), 1u);
    EXPECT_EQ(shadowVs->value.args[0].str(), "mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix))");
}

TEST(Parser, DeclarationOrder) {
    auto effect = parseOk(R"(
float a;
struct S { float x; };
static const float k = 2;
float f(S s) { return s.x * k; }
typedef float4 color;
cbuffer cb { float4 q; };
float b;
)");
    ASSERT_TRUE(effect);
    ASSERT_EQ(effect->order.size(), 7u);
    EXPECT_EQ(effect->order[0].kind, DeclRef::Kind::Parameter);
    EXPECT_EQ(effect->order[1].kind, DeclRef::Kind::Struct);
    EXPECT_EQ(effect->order[2].kind, DeclRef::Kind::Parameter);
    EXPECT_EQ(effect->order[3].kind, DeclRef::Kind::Function);
    EXPECT_EQ(effect->order[4].kind, DeclRef::Kind::Verbatim);
    EXPECT_EQ(effect->order[5].kind, DeclRef::Kind::Parameter);  // a cbuffer's member is a parameter
    EXPECT_EQ(effect->order[6].kind, DeclRef::Kind::Parameter);
    EXPECT_EQ(effect->verbatim[0].hlslText, "typedef float4 color;");
    EXPECT_EQ(effect->parameters[effect->order[5].index].name, "q");
    const Parameter* k = effect->findParameter("k");
    ASSERT_TRUE(k);
    EXPECT_TRUE(k->isStatic);
    EXPECT_TRUE(k->isConst);
    EXPECT_EQ(k->hlslText, "static const float k = 2;");
    EXPECT_EQ(k->hlslLoc.line, 4);
    EXPECT_EQ(k->hlslLoc.column, 1);
    EXPECT_TRUE(effect->findParameter("a")->hlslText.empty());
}

TEST(Parser, TypesAndStorage) {
    auto effect = parseOk(R"(
row_major float3x4 m;
vector<float, 3> v3;
matrix<half, 2, 3> m23;
float4 arr[3];
float2 grid[2][4];
uniform shared extern float u;
int i = 0x10;
uint ui = 3u;
double d = 1e3;
bool flags[2] = { true, FALSE };
Texture2D t2;
texture2D t2b;
textureCUBE tc;
TextureCube tc2;
texture3D t3;
sampler2D s2;
samplerCUBE sc;
SamplerComparisonState cmp { Filter = COMPARISON_MIN_MAG_LINEAR_MIP_POINT; ComparisonFunc = LESS; };
)");
    ASSERT_TRUE(effect);
    const Parameter* m = effect->findParameter("m");
    EXPECT_TRUE(m->type.rowMajor);
    EXPECT_EQ(m->type.rows, 3);
    EXPECT_EQ(m->type.cols, 4);
    EXPECT_EQ(effect->findParameter("v3")->type.hlslName(), "float3");
    EXPECT_EQ(effect->findParameter("m23")->type.hlslName(), "half2x3");
    EXPECT_EQ(effect->findParameter("arr")->type.arrayDims, std::vector<int>{3});
    EXPECT_EQ(effect->findParameter("arr")->type.componentCount(), 12);
    EXPECT_EQ(effect->findParameter("grid")->type.arrayDims, (std::vector<int>{2, 4}));
    const Parameter* u = effect->findParameter("u");
    EXPECT_TRUE(u->isUniform && u->isShared && u->isExtern);
    EXPECT_EQ(effect->findParameter("i")->initializer->number, 16);
    EXPECT_TRUE(effect->findParameter("ui")->initializer->isInteger);
    EXPECT_EQ(effect->findParameter("d")->initializer->number, 1000);
    EXPECT_FALSE(effect->findParameter("d")->initializer->isInteger);
    EXPECT_EQ(effect->findParameter("flags")->initializer->args[1].kind, Expr::Kind::Bool);
    EXPECT_EQ(effect->findParameter("t2")->type.base, BaseType::Texture2D);
    EXPECT_EQ(effect->findParameter("t2b")->type.base, BaseType::Texture2D);
    EXPECT_EQ(effect->findParameter("tc")->type.base, BaseType::TextureCube);
    EXPECT_EQ(effect->findParameter("tc2")->type.base, BaseType::TextureCube);
    EXPECT_EQ(effect->findParameter("t3")->type.base, BaseType::Texture3D);
    EXPECT_EQ(effect->findParameter("s2")->type.base, BaseType::Sampler2D);
    EXPECT_EQ(effect->findParameter("sc")->type.hlslName(), "samplerCUBE");
    const Parameter* cmp = effect->findParameter("cmp");
    ASSERT_EQ(cmp->samplerState.size(), 2u);
    EXPECT_EQ(cmp->samplerState[0].value.number, 0x94);
    EXPECT_EQ(cmp->samplerState[1].value.number, 2);
}

TEST(Parser, AnnotationsAndScriptHeader) {
    auto effect = parseOk(R"(#define SCRIPT_TEXT "Technique=Technique?" "a:b;"
float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string Script = "Technique=main;";
> = 0.8;
texture RT : RENDERCOLORTARGET <
    float2 ViewPortRatio = {1.0, 1.0};
    int MipLevels = 1;
    string Format = "A8R8G8B8";
    int width = 64, height = 32;
    string ResourceName = "default_color.dds";
    string Tip = (SCRIPT_TEXT);
    float UIMin = -1.5;
>;
)");
    ASSERT_TRUE(effect);
    const Parameter* script = effect->findParameter("Script");
    EXPECT_EQ(script->semantic, "STANDARDSGLOBAL");
    EXPECT_EQ(script->annotations.size(), 4u);
    EXPECT_EQ(script->annotation("ScriptClass")->value.text, "scene");
    EXPECT_EQ(script->initializer->number, 0.8);
    const Parameter* rt = effect->findParameter("RT");
    EXPECT_EQ(rt->annotation("ViewPortRatio")->value.args.size(), 2u);
    EXPECT_EQ(rt->annotation("ViewPortRatio")->type.cols, 2);
    EXPECT_EQ(rt->annotation("width")->value.number, 64);
    EXPECT_EQ(rt->annotation("height")->value.number, 32);
    EXPECT_EQ(rt->annotation("height")->type.base, BaseType::Int);
    EXPECT_EQ(rt->annotation("Tip")->value.text, "Technique=Technique?a:b;");
    EXPECT_EQ(rt->annotation("UIMin")->value.number, -1.5);
    EXPECT_EQ(rt->annotation("Format")->loc.line, 11);
}

TEST(Parser, SamplerStateForms) {
    auto effect = parseOk(R"(
texture T;
sampler2D a = sampler_state { Texture = <T>; };
sampler2D b = sampler_state { texture = (T); AddressU = D3DTADDRESS_MIRROR; };
sampler2D c = sampler_state { Texture = T; Filter = MIN_MAG_LINEAR_MIP_POINT; };
SamplerState d { AddressS = clamp; MinFilter = d3dtexf_linear; };
)");
    ASSERT_TRUE(effect);
    for (const char* name : {"a", "b", "c"}) {
        const Parameter* p = effect->findParameter(name);
        ASSERT_TRUE(p) << name;
        EXPECT_EQ(p->samplerState[0].value.kind, Expr::Kind::TextureRef) << name;
        EXPECT_EQ(p->samplerState[0].value.text, "T") << name;
    }
    EXPECT_EQ(effect->findParameter("b")->samplerState[1].value.number, 2);
    EXPECT_EQ(effect->findParameter("c")->samplerState[1].value.number, 0x14);
    const Parameter* d = effect->findParameter("d");
    EXPECT_EQ(d->type.base, BaseType::SamplerState);
    EXPECT_EQ(d->samplerState[0].value.number, 3);
    EXPECT_EQ(d->samplerState[1].value.number, 2);
}

TEST(Parser, StructMembersAndFunctionParams) {
    auto effect = parseOk(R"(
struct VSOut {
    float4 pos : SV_Position;
    nointerpolation float2 uv : TEXCOORD0;
    centroid float3 n, t : NORMAL;
};
void VS(in float4 p : POSITION, out VSOut o, inout float x, uniform float4x4 wvp, float scale = 2.0)
{
    [unroll] for (int i = 0; i < 2; ++i) x += 1;
    o = (VSOut)0;
}
float4 proto(float a);
[numthreads(8, 8, 1)]
void CS() {}
)");
    ASSERT_TRUE(effect);
    const StructDecl* s = effect->findStruct("VSOut");
    ASSERT_EQ(s->members.size(), 4u);
    EXPECT_EQ(s->members[1].interpolation, "nointerpolation");
    EXPECT_EQ(s->members[1].semantic, "TEXCOORD0");
    EXPECT_EQ(s->members[2].interpolation, "centroid");
    EXPECT_EQ(s->members[3].name, "t");
    EXPECT_EQ(s->members[3].semantic, "NORMAL");
    const FunctionDecl* vs = effect->findFunctions("VS")[0];
    ASSERT_EQ(vs->params.size(), 5u);
    EXPECT_EQ(vs->returnType.base, BaseType::Void);
    EXPECT_EQ(vs->params[0].direction, FunctionParam::Direction::In);
    EXPECT_EQ(vs->params[1].direction, FunctionParam::Direction::Out);
    EXPECT_EQ(vs->params[2].direction, FunctionParam::Direction::InOut);
    EXPECT_TRUE(vs->params[3].isUniform);
    ASSERT_TRUE(vs->params[4].defaultValue);
    EXPECT_EQ(vs->params[4].defaultValue->number, 2.0);
    EXPECT_EQ(vs->hlslLoc.line, 7);
    const FunctionDecl* proto = effect->findFunctions("proto")[0];
    EXPECT_FALSE(proto->hasBody);
    const FunctionDecl* cs = effect->findFunctions("CS")[0];
    EXPECT_EQ(cs->hlslText, "[numthreads(8, 8, 1)]\nvoid CS(){ }");
}

TEST(Parser, PassStatesAndD3D10Forms) {
    auto effect = parseOk(R"(
float4 VS() : SV_Position { return 0; }
float4 PS() : SV_Target { return 1; }
vertexshader vsVar = compile vs_3_0 VS();
bool blend = true;
technique10 T10 < string Script = "Pass=p0;"; > {
    pass p0 {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
technique T9 {
    pass {
        cullmode = ccw;
        ColorWriteEnable = RED|GREEN|BLUE;
        ColorWriteEnable1 = 0;
        ZFunc = D3DCMP_GREATER;
        AlphaBlendEnable = blend;
        StencilEnable = TRUE;
        SrcBlend = blend ? SrcAlpha : One;
        VertexShader = (vsVar);
        PixelShader = NULL;
    }
}
)");
    ASSERT_TRUE(effect);
    const Technique* t10 = effect->findTechnique("T10");
    ASSERT_TRUE(t10);
    const Pass& p0 = t10->passes[0];
    // The shaders, after D3D10's default states (test_d3d10_syntax).
    ASSERT_TRUE(findState(p0.states, "VertexShader"));
    EXPECT_EQ(findState(p0.states, "VertexShader")->value.kind, Expr::Kind::Compile);
    EXPECT_EQ(findState(p0.states, "VertexShader")->value.profile, "vs_4_0");
    ASSERT_TRUE(findState(p0.states, "PixelShader"));
    EXPECT_EQ(findState(p0.states, "PixelShader")->value.text, "PS");
    EXPECT_EQ(findState(p0.states, "ZFunc")->value.number, 2);
    EXPECT_EQ(effect->findParameter("vsVar")->type.base, BaseType::VertexShader);
    EXPECT_EQ(effect->findParameter("vsVar")->initializer->kind, Expr::Kind::Compile);

    const Pass& p = effect->findTechnique("T9")->passes[0];
    EXPECT_EQ(p.name, "");
    EXPECT_EQ(findState(p.states, "cullmode")->value.number, 3);
    EXPECT_EQ(findState(p.states, "cullmode")->value.kind, Expr::Kind::Number);
    EXPECT_EQ(findState(p.states, "cullmode")->value.loc.column, 20);
    EXPECT_EQ(findState(p.states, "ColorWriteEnable")->value.number, 7);
    EXPECT_EQ(findState(p.states, "ZFunc")->value.number, 5);
    EXPECT_EQ(findState(p.states, "AlphaBlendEnable")->value.kind, Expr::Kind::Identifier);
    EXPECT_EQ(findState(p.states, "StencilEnable")->value.kind, Expr::Kind::Bool);
    const Expr& ternary = findState(p.states, "SrcBlend")->value;
    EXPECT_EQ(ternary.str(), "blend ? 5 : 2");
    EXPECT_EQ(findState(p.states, "VertexShader")->value.text, "vsVar");
    EXPECT_EQ(findState(p.states, "PixelShader")->value.text, "NULL");
}

// D3DX read the effect keywords, states and values in any case (fxc's strict mode warned, X3086), and
// MonoGame's ColorWriteEnable takes All, None, true and false. The HLSL text glslang reads gets the
// keywords spelled as HLSL spells them.
TEST(Parser, CaseBlindEffectGrammar) {
    auto effect = parseOk(R"(
shared MATRIX Wvp : WORLDVIEWPROJECTION;
static const int N = 3;
float4 Lights[3 * N - 1];
static const int2 Grid = int2(2, 3);
float4 Cells[Grid.x * Grid.y + max(N, 1) - abs(-3)];
Matrix Identity(Matrix m) { return m; }
float4 VS(float4 p : POSITION) : POSITION { return mul(p, Identity(Wvp)); }
float4 PS() : COLOR { return 1; }
VERTEXSHADER vsVar = COMPILE vs_3_0 VS();
TECHNIQUE T {
    PASS P0 {
        VertexShader = vsVar;
        pixelshader = Compile ps_3_0 PS();
        ZENABLE = TRUE;
        cullmode = NONE;
        COLORWRITEENABLE = true;
        ColorWriteEnable1 = None;
        ColorWriteEnable2 = all;
        ColorWriteEnable3 = false;
        FogTableMode = NONE;
        FOGVERTEXMODE = D3DFOG_LINEAR;
        FogColor = 0x00336699;
        RangeFogEnable = FALSE;
    }
}
Technique11 T11 { Pass { SetPixelShader(CompileShader(ps_4_0, PS())); } }
)");
    ASSERT_TRUE(effect);
    const Parameter* wvp = effect->findParameter("Wvp");
    ASSERT_TRUE(wvp);
    EXPECT_TRUE(wvp->isShared);
    EXPECT_EQ(wvp->type.shape, Shape::Matrix);
    EXPECT_EQ(effect->findParameter("Lights")->type.arrayDims, std::vector<int>{8});
    EXPECT_EQ(effect->findParameter("Cells")->type.arrayDims, std::vector<int>{6});
    EXPECT_EQ(effect->findParameter("vsVar")->type.base, BaseType::VertexShader);
    EXPECT_EQ(effect->findParameter("vsVar")->initializer->kind, Expr::Kind::Compile);
    ASSERT_FALSE(effect->findFunctions("Identity").empty());
    EXPECT_EQ(effect->findFunctions("Identity").front()->hlslText.rfind("matrix Identity(matrix m)", 0), 0u);
    const Technique* t = effect->findTechnique("T");
    ASSERT_TRUE(t);
    ASSERT_EQ(t->passes.size(), 1u);
    const Pass& p = t->passes[0];
    EXPECT_EQ(p.name, "P0");
    EXPECT_EQ(findState(p.states, "PixelShader")->value.kind, Expr::Kind::Compile);
    EXPECT_EQ(findState(p.states, "cullmode")->value.number, 1);
    EXPECT_EQ(findState(p.states, "COLORWRITEENABLE")->value.number, 15);
    EXPECT_EQ(findState(p.states, "ColorWriteEnable1")->value.number, 0);
    EXPECT_EQ(findState(p.states, "ColorWriteEnable2")->value.number, 15);
    EXPECT_EQ(findState(p.states, "ColorWriteEnable3")->value.number, 0);
    EXPECT_EQ(findState(p.states, "FOGVERTEXMODE")->value.number, 3);
    ASSERT_TRUE(effect->findTechnique("T11"));
    EXPECT_TRUE(effect->findTechnique("T11")->d3d10);
}

// Script names match declarations case-blind, in the compiler's checks as in the runtime.
TEST(Parser, ScriptNamesMatchCaseBlind) {
    EXPECT_TRUE(scriptNameMatches("p0", "P0"));
    EXPECT_TRUE(scriptNameMatches("Blur_Pass", "BLUR_PASS"));
    EXPECT_FALSE(scriptNameMatches("p0", "p01"));
}

TEST(Parser, ExpressionsPrecedenceAndForms) {
    auto effect = parseOk(R"(
float4x4 M;
float a = 1 + 2 * 3 - 4 / 2;
float b = (1 < 2) ? 3 : 4 || 0;
float3 c = (float3)M[0].xyz;
float d = M._11 + -M._22;
float e = 1 << 2 | 3 & 1 ^ 2;
float f = !true && ~1 != 2;
float4 g = float4(1, 2, 3, 4).wzyx;
)");
    ASSERT_TRUE(effect);
    EXPECT_EQ(effect->findParameter("a")->initializer->str(), "(1 + (2 * 3)) - (4 / 2)");
    EXPECT_EQ(effect->findParameter("b")->initializer->str(), "(1 < 2) ? 3 : (4 || 0)");
    const Expr& c = *effect->findParameter("c")->initializer;
    EXPECT_EQ(c.kind, Expr::Kind::Cast);
    EXPECT_EQ(c.castType.hlslName(), "float3");
    EXPECT_EQ(c.str(), "(float3)M[0].xyz");
    EXPECT_EQ(effect->findParameter("d")->initializer->str(), "M._11 + -M._22");
    EXPECT_EQ(effect->findParameter("e")->initializer->str(), "(1 << 2) | ((3 & 1) ^ 2)");
    EXPECT_EQ(effect->findParameter("f")->initializer->str(), "!true && (~1 != 2)");
    EXPECT_EQ(effect->findParameter("g")->initializer->str(), "float4(1, 2, 3, 4).wzyx");
}

TEST(Parser, HlslTextSpansIncludeDirective) {
    DiagnosticList diags;
    auto effect = parse("struct S {\n#include \"m.fxh\"\n};\n", diags, {{"m.fxh", "float4 p : POSITION;\n"}});
    ASSERT_TRUE(effect) << diags.str();
    const StructDecl* s = effect->findStruct("S");
    ASSERT_EQ(s->members.size(), 1u);
    EXPECT_EQ(s->members[0].loc.file, "m.fxh");
    EXPECT_EQ(s->members[0].loc.line, 1);
    EXPECT_NE(s->hlslText.find("#line 1 \"m.fxh\""), std::string::npos) << s->hlslText;
    EXPECT_NE(s->hlslText.find("#line 3 \"test.fx\""), std::string::npos) << s->hlslText;
}

TEST(Parser, ColumnRecoveryWithCollapsedWhitespace) {
    auto effect = parseOk("float      spaced   =    1.0;\nstatic    const float   k2 =  3;\n");
    ASSERT_TRUE(effect);
    const Parameter* p = effect->findParameter("spaced");
    EXPECT_EQ(p->loc.column, 12);
    EXPECT_EQ(p->initializer->loc.column, 26);
    const Parameter* k = effect->findParameter("k2");
    EXPECT_EQ(k->loc.column, 25);
    // hlslLoc keeps the preprocessed column; the source map gives the user's back.
    EXPECT_EQ(k->hlslLoc.column, 1);
    EXPECT_EQ(k->hlslText, "static const float k2 = 3;");
    SourceLoc mapped = effect->sourceMap.map(SourceLoc{"test.fx", 2, 20});  // "k2" in preprocessed text
    EXPECT_EQ(mapped.column, 25);
}

TEST(Parser, MacroExpansionColumnsFallBack) {
    auto effect = parseOk("#define VAL (2.0 * 3.0)\nfloat x = VAL;\n");
    ASSERT_TRUE(effect);
    const Expr& init = *effect->findParameter("x")->initializer;
    EXPECT_EQ(init.str(), "2.0 * 3.0");
    EXPECT_EQ(init.loc.line, 2);
    EXPECT_GE(init.loc.column, 11);
}
}  // namespace test_parser
