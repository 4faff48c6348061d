// End-to-end: effect text -> parser -> EffectCompiler -> GLSL + reflection; every GLSL program is also
// compiled by glslang as GLSL 4.50 (a GL-free sanity check).
#include "Glsl450.h"

#include <fx/CompileCache.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace fx::test_effect_compiler {
namespace {

using test::compilesAsGlsl450;

// The FX Composer listing of Lehőcz 2007 (page breaks repaired), with a hardware-shadow depth sampler added.
const char* kThesis = R"(float Script : STANDARDSGLOBAL <
    string ScriptClass = "scene"; string ScriptOrder = "standard"; string ScriptOutput = "color";
    string Script = "Technique=main;"; > = 0.8;
const float2 SHADOW_SIZE = {512, 512};
#define ZMaxValue 130944/16.0
#define ShadowRange 12000.0
#define ShadowRangeMultiplier (ZMaxValue/ShadowRange)
const bool JITTER=false;
float Bias = 0.01;
bool PCF=false;
bool bFlip=false;
float4 ShadowClearColor = {ZMaxValue, ZMaxValue, ZMaxValue, ZMaxValue};
float4x4 WorldViewProjectionMatrix : WorldViewProjection;
float4x4 WorldMatrix : World;
float4x4 LightViewMatrix : View < string frustum = "light0"; >;
float4x4 LightProjectionMatrix : Projection < string frustum = "light0"; >;
row_major float4x3 RowMat;
texture ShadowMap : RENDERCOLORTARGET < float2 ViewPortRatio = {1.0, 1.0}; string Format = "R32F"; >;
sampler ShadowMapSampler = sampler_state { texture = <ShadowMap>; AddressU = CLAMP; AddressV = CLAMP;
    MipFilter = NONE; MinFilter = POINT; MagFilter = POINT; };
texture ShadDepthTarget : RENDERDEPTHSTENCILTARGET < int2 Dimensions = {1024, 1024}; >;
sampler DepthSampler = sampler_state { texture = <ShadDepthTarget>; MinFilter = LINEAR; MagFilter = LINEAR; };
struct VertexFormat { float4 Position : POSITION; float4 UV : TEXCOORD0; float4 Normal : NORMAL; };
struct ShadowOut { float4 Position : POSITION; float Z : TEXCOORD0; };
ShadowOut RenderShadowMapVS(VertexFormat IN, uniform float4x4 WorldViewProjectionMatrix)
{
    ShadowOut OUT;
    float4 LightSpacePosition = mul(float4(IN.Position.xyz, 1.0), WorldViewProjectionMatrix);
    OUT.Position = LightSpacePosition;
    OUT.Z = LightSpacePosition.z;
    return OUT;
}
float4 RenderShadowMapPS(ShadowOut IN) : COLOR
{
    if(bFlip) return float4(-IN.Z*ShadowRangeMultiplier, 1, 1, 1);
    return float4(IN.Z*ShadowRangeMultiplier, 1, 1, 1);
}
struct SceneOut { float4 HPosition : POSITION; float3 WNormal : TEXCOORD1; float4 LP : TEXCOORD3; };
SceneOut RenderSceneVS(VertexFormat IN, uniform float4x4 ShadowViewProjectionMatrix)
{
    SceneOut OUT;
    float4 Pw = mul(float4(IN.Position.xyz, 1.0), WorldMatrix);
    OUT.WNormal = mul(IN.Normal, WorldMatrix).xyz + mul(float4(1,1,1,1), RowMat);
    OUT.LP = mul(Pw, ShadowViewProjectionMatrix);
    OUT.HPosition = mul(IN.Position, WorldViewProjectionMatrix);
    return OUT;
}
float GetShadow(float4 LP, uniform sampler S, uniform float ShadowBias, uniform bool usePcf)
{
    float2 nuv = float2(.5, -.5)*LP.xy/LP.w + float2(0.5, 0.5);
    float depth = (LP.z/ShadowRange - ShadowBias)*ZMaxValue;
    float hw = tex2D(DepthSampler, float4(nuv, LP.z / LP.w, 1)).x * tex2Dproj(DepthSampler, LP).x;
    if (usePcf) return hw;
    return (tex2D(S, nuv).x >= depth) * hw;
}
float4 RenderScenePS(SceneOut IN, float2 pix : VPOS, uniform bool usePcf) : COLOR
{
    return float4(GetShadow(IN.LP, ShadowMapSampler, Bias, usePcf) * normalize(IN.WNormal) + pix.x * 0.0, 1);
}
struct ClearIn { float4 Position : POSITION; float2 UV : TEXCOORD0; };
float4 ClearVS(ClearIn IN) : POSITION { return IN.Position; }
float4 ClearPS() : COLOR { return ShadowClearColor; }
technique main < string Script = "Pass=ClearShadowMap; Pass=RenderShadowMap; Pass=RenderScene;"; >
{
    pass ClearShadowMap < string Script = "RenderColorTarget0=ShadowMap;"
                                          "RenderDepthStencilTarget=ShadDepthTarget;"
                                          "RenderPort=light0; Draw=geometry;"; >
    {
        CullMode = None; ZEnable = false;
        VertexShader = compile vs_2_0 ClearVS();
        PixelShader = compile ps_2_0 ClearPS();
    }
    pass RenderShadowMap
    {
        AlphaBlendEnable = true; SrcBlend = one; DestBlend = one; BlendOp = min;
        VertexShader = compile vs_2_0 RenderShadowMapVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix)));
        PixelShader = compile ps_2_0 RenderShadowMapPS();
    }
    pass RenderScene
    {
        CullMode = CCW; ZEnable = true; ZFunc = LessEqual;
        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));
        PixelShader = compile ps_3_0 RenderScenePS(true);
    }
}
)";

std::shared_ptr<Effect> parse(const std::string& source, DiagnosticList& diags,
                              const std::string& path = "thesis.fx") {
    return parseEffectSource(source, path, ParseOptions{}, diags);
}

std::unique_ptr<CompiledEffect> compile(const std::string& source, DiagnosticList& diags,
                                        CompileCache* cache = nullptr) {
    auto effect = parse(source, diags);
    if (!effect) return nullptr;
    CompileOptions options;
    options.cache = cache;
    return compileEffect(effect, options, diags);
}

const UniformBinding* findUniform(const StageProgram& p, const std::string& name) {
    for (const UniformBinding& u : p.uniforms)
        if (u.name == name) return &u;
    return nullptr;
}

TEST(EffectCompiler, ThesisEffectCompilesEndToEnd) {
    DiagnosticList diags;
    auto fx = compile(kThesis, diags);
    ASSERT_TRUE(fx) << diags.str();
    ASSERT_EQ(fx->techniques.size(), 1u);
    const CompiledTechnique& t = fx->techniques[0];
    ASSERT_EQ(t.passes.size(), 3u);
    EXPECT_TRUE(t.hasScript);
    EXPECT_EQ(t.script.size(), 3u);
    EXPECT_TRUE(fx->hasGlobalScript);
    for (const CompiledPass& p : t.passes) {
        for (const StageProgram* s : {&p.vertex, &p.fragment}) {
            EXPECT_FALSE(s->glsl.empty()) << p.name;
            EXPECT_NE(s->glsl.find("#version 450"), std::string::npos);
            EXPECT_EQ(s->glsl.find("origin_upper_left"), std::string::npos) << s->glsl;
            EXPECT_TRUE(compilesAsGlsl450(*s)) << p.name;
        }
    }
    // RenderShadowMap: the non-literal argument became fx_arg0, evaluated by the runtime.
    const CompiledPass& shadow = t.passes[1];
    ASSERT_EQ(shadow.arguments.size(), 1u);
    EXPECT_EQ(shadow.arguments[0].memberName, "fx_arg0");
    // A preshader program over the three matrices' slots.
    std::vector<size_t> slots;
    for (const char* name : {"WorldMatrix", "LightViewMatrix", "LightProjectionMatrix"})
        for (size_t i = 0; i < fx->parameters.size(); ++i)
            if (fx->parameters[i].name == name) slots.push_back(i);
    std::sort(slots.begin(), slots.end());
    EXPECT_EQ(shadow.arguments[0].value.inputs(), slots);
    EXPECT_FALSE(shadow.arguments[0].value.isConstant());
    const UniformBinding* arg = findUniform(shadow.vertex, "fx_arg0");
    ASSERT_TRUE(arg) << shadow.vertex.glsl;
    EXPECT_EQ(arg->source, UniformBinding::Source::CompileArgument);
    EXPECT_EQ(arg->index, 0u);
    EXPECT_EQ(arg->size, 64u);
    EXPECT_EQ(shadow.vertex.uniformBlockName, "fx_VsGlobals");
    EXPECT_EQ(shadow.vertex.uniformBlockBinding, 0);
    EXPECT_NE(shadow.vertex.glsl.find("fx_VsGlobals"), std::string::npos);
    EXPECT_EQ(shadow.fragment.uniformBlockName, "fx_PsGlobals");
    EXPECT_EQ(shadow.fragment.uniformBlockBinding, 1);
    const UniformBinding* flip = findUniform(shadow.fragment, "bFlip");
    ASSERT_TRUE(flip);
    EXPECT_EQ(flip->source, UniformBinding::Source::Parameter);
    EXPECT_EQ(fx->parameters[flip->index].name, "bFlip");
    // Vertex inputs by semantic.
    std::vector<std::string> semantics;
    for (const VertexInput& in : shadow.vertex.inputs) semantics.push_back(in.semantic);
    EXPECT_EQ(semantics, (std::vector<std::string>{"POSITION", "NORMAL",
                                                   "TEXCOORD0"}));  // the whole input struct, used or not
    const CompiledPass& scene = t.passes[2];
    semantics.clear();
    for (const VertexInput& in : scene.vertex.inputs) {
        semantics.push_back(in.semantic);
        EXPECT_EQ(in.components, 4);
    }
    std::sort(semantics.begin(), semantics.end());
    EXPECT_EQ(semantics, (std::vector<std::string>{"NORMAL", "POSITION", "TEXCOORD0"}));
    // Varyings link by location: TEXCOORD1 -> 1, TEXCOORD3 -> 3 in both stages.
    EXPECT_NE(scene.vertex.glsl.find("layout(location = 3) out vec4"), std::string::npos)
        << scene.vertex.glsl;
    EXPECT_NE(scene.fragment.glsl.find("layout(location = 3) in vec4"), std::string::npos)
        << scene.fragment.glsl;
    // Literal uniform argument inlined: no fx_arg in the pixel stage.
    EXPECT_EQ(findUniform(scene.fragment, "fx_arg1"), nullptr);
    EXPECT_EQ(scene.arguments.size(), 1u);
    // Samplers: the colour one and the depth-compare one, on distinct units.
    ASSERT_EQ(scene.fragment.samplers.size(), 2u) << scene.fragment.glsl;
    const SamplerBinding *color = nullptr, *depth = nullptr;
    for (const SamplerBinding& s : scene.fragment.samplers) (s.depthCompare ? depth : color) = &s;
    ASSERT_TRUE(color && depth);
    EXPECT_EQ(color->glslName, "ShadowMapSampler");
    EXPECT_EQ(depth->glslName, "DepthSampler");
    EXPECT_NE(color->unit, depth->unit);
    EXPECT_EQ(fx->parameters[depth->samplerParameter].name, "DepthSampler");
    EXPECT_NE(scene.fragment.glsl.find("sampler2DShadow DepthSampler"), std::string::npos)
        << scene.fragment.glsl;
    EXPECT_NE(scene.fragment.glsl.find("gl_FragCoord"), std::string::npos);
    // Render states folded to literals.
    ASSERT_FALSE(shadow.states.empty());
    for (const RenderStateSetting& s : shadow.states) {
        EXPECT_TRUE(s.constant) << renderStateInfo(s.id).name;
        EXPECT_TRUE(s.value.empty());
    }
}

TEST(EffectCompiler, InitialValuesTexturesSamplers) {
    DiagnosticList diags;
    auto fx = compile(kThesis, diags);
    ASSERT_TRUE(fx) << diags.str();
    auto value = [&](const std::string& name) {
        for (size_t i = 0; i < fx->parameters.size(); ++i)
            if (fx->parameters[i].name == name) return fx->initialValues[i];
        return Value{};
    };
    EXPECT_EQ(value("ShadowClearColor").data, (std::vector<float>{8184, 8184, 8184, 8184}));
    EXPECT_FLOAT_EQ(value("Bias").asFloat(), 0.01f);
    EXPECT_FALSE(value("PCF").asBool());
    EXPECT_EQ(value("SHADOW_SIZE").data, (std::vector<float>{512, 512}));
    ASSERT_EQ(fx->textures.size(), 2u);
    EXPECT_EQ(fx->textures[0].kind, TextureDesc::Kind::RenderColorTarget);
    EXPECT_EQ(fx->textures[0].format, TextureFormat::R32F);
    EXPECT_EQ(fx->textures[1].kind, TextureDesc::Kind::RenderDepthStencilTarget);
    EXPECT_EQ(fx->textures[1].format, TextureFormat::D24S8);
    EXPECT_EQ(fx->textures[1].width, 1024);
    ASSERT_EQ(fx->samplers.size(), 2u);
    EXPECT_EQ(fx->samplers[0].addressU, 3);  // CLAMP
    EXPECT_EQ(fx->samplers[0].minFilter, 1);
    EXPECT_EQ(fx->samplers[1].minFilter, 2);
}

// The matrix-packing rule: the runtime writes Value::data (HLSL m[r][c]) into the std140 block with
// element (r, c) at offset + (hlslColumnsContiguous ? c*matrixStride + r*4 : r*matrixStride + c*4).
// Checked here by reading that memory back the way GLSL does for the member's declaration and
// evaluating what the generated GLSL computes (M_glsl * v for HLSL mul(v, M)).
TEST(EffectCompiler, MatrixPackingFollowsRowMajorDecoration) {
    DiagnosticList diags;
    auto fx = compile(kThesis, diags);
    ASSERT_TRUE(fx) << diags.str();
    const StageProgram& vs = fx->techniques[0].passes[2].vertex;
    const UniformBinding* cm = findUniform(vs, "WorldMatrix");
    const UniformBinding* rm = findUniform(vs, "RowMat");
    ASSERT_TRUE(cm && rm) << vs.glsl;
    EXPECT_TRUE(cm->hlslColumnsContiguous);   // HLSL column_major -> GLSL layout(row_major)
    EXPECT_FALSE(rm->hlslColumnsContiguous);  // HLSL row_major -> GLSL column-major
    EXPECT_NE(vs.glsl.find("layout(row_major) mat4 WorldMatrix"), std::string::npos) << vs.glsl;
    EXPECT_NE(vs.glsl.find("mat4x3 RowMat"), std::string::npos) << vs.glsl;
    EXPECT_EQ(rm->matrixStride, 16u);
    // HLSL float4x3 (4 rows, 3 cols) is GLSL mat4x3 (4 columns of 3): GLSL column j = HLSL row j.
    // Pack per the rule and read back GLSL column-major: M_glsl[col][row] at col*stride + row*4.
    float hlsl[4][3];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 3; ++c) hlsl[r][c] = static_cast<float>(r * 10 + c);
    std::vector<float> block(64, -1.0f);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 3; ++c) {
            uint32_t off =
                rm->hlslColumnsContiguous ? c * rm->matrixStride + r * 4 : r * rm->matrixStride + c * 4;
            block[off / 4] = hlsl[r][c];
        }
    // GLSL: (mat4x3 * vec4)[i] = sum_j M[j][i] * v[j] must equal HLSL mul(v, M)[i] = sum_j v[j] * M[j][i].
    float v[4] = {1, 2, 3, 4};
    for (int i = 0; i < 3; ++i) {
        float glsl = 0, ref = 0;
        for (int j = 0; j < 4; ++j) {
            glsl += block[(j * rm->matrixStride) / 4 + i] * v[j];
            ref += v[j] * hlsl[j][i];
        }
        EXPECT_FLOAT_EQ(glsl, ref);
    }
    // WorldMatrix is declared layout(row_major) mat4: GLSL M[col][row] at row*stride + col*4, and GLSL
    // `M * v` must equal HLSL mul(v, M).
    std::vector<float> block2(16);
    float w[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) w[r][c] = static_cast<float>(r * 4 + c + 1);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            uint32_t off =
                cm->hlslColumnsContiguous ? c * cm->matrixStride + r * 4 : r * cm->matrixStride + c * 4;
            block2[off / 4] = w[r][c];
        }
    for (int i = 0; i < 4; ++i) {
        float glsl = 0, ref = 0;
        for (int j = 0; j < 4; ++j) {
            float glslElem = block2[(i * cm->matrixStride) / 4 + j];  // row_major: GLSL row i contiguous
            glsl += glslElem * v[j];
            ref += v[j] * w[j][i];
        }
        EXPECT_FLOAT_EQ(glsl, ref);
    }
}

TEST(EffectCompiler, MissingEntryPoint) {
    DiagnosticList diags;
    std::string src = R"(float4 PS() : COLOR { return 1; }
technique t { pass p {
    PixelShader = compile ps_2_0 NoSuchPS();
} }
)";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    const Diagnostic& d = diags.items().back();
    EXPECT_EQ(d.id, DiagId::MissingEntryPoint) << diags.str();
    EXPECT_EQ(d.loc.line, 3);
}

TEST(EffectCompiler, UnsupportedProfile) {
    // D3DX's texture-shader profile names no stage a pass runs.
    DiagnosticList diags;
    std::string src =
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile tx_1_0 PS(); } }\n";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    EXPECT_EQ(diags.items().back().id, DiagId::UnsupportedProfile) << diags.str();
}

TEST(EffectCompiler, AnotherStagesProfileIsNamed) {
    DiagnosticList diags;
    std::string src =
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile cs_5_0 PS(); } }\n";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    EXPECT_EQ(diags.items().back().id, DiagId::ProfileOfOtherStage) << diags.str();
    EXPECT_NE(diags.str().find("'cs_5_0' is a compute-shader profile, used for the pixel shader"),
              std::string::npos)
        << diags.str();
}

TEST(EffectCompiler, HlslErrorAtUserLineAndColumn) {
    DiagnosticList diags;
    std::string src = R"(float4 Color = {1, 0, 0, 1};
float4 PS() : COLOR
{
    float4 c = Color;
    return c * undefinedThing;
}
technique t { pass p { PixelShader = compile ps_2_0 PS(); } }
)";
    EXPECT_FALSE(compile(src, diags));
    bool found = false;
    for (const Diagnostic& d : diags.items())
        if (d.id == DiagId::HlslError && d.loc.line == 5 && !found) {
            found = true;
            EXPECT_EQ(d.loc.file, "thesis.fx");
            EXPECT_EQ(d.loc.column, 16) << d.message;
            EXPECT_NE(d.message.find("undefinedThing"), std::string::npos) << d.message;
        }
    EXPECT_TRUE(found) << diags.str();
}

TEST(EffectCompiler, UnknownTextureFormat) {
    DiagnosticList diags;
    std::string src =
        "texture T : RENDERCOLORTARGET < string Format = \"X9Y9\"; >;\n"
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile ps_2_0 PS(); } }\n";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    EXPECT_EQ(diags.items()[0].id, DiagId::InvalidTextureFormat) << diags.str();
    EXPECT_EQ(diags.items()[0].loc.line, 1);
}

// The NOISE semantic is resolved here, case-blind: a 2D texture that nothing else fills is the runtime's
// noise texture by its kind (the runtime compares no semantic); a cube with it, or one a procedural
// annotation fills, is not.
TEST(EffectCompiler, NoiseSemanticIsATextureKind) {
    DiagnosticList diags;
    std::string src =
        "texture Untyped : noise;\n"
        "Texture2D Typed : NOISE;\n"
        "textureCUBE Cube : noise;\n"
        "texture Generated : noise < string Procedural = \"noise\"; >;\n"
        "texture Other : Diffuse;\n"
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile ps_2_0 PS(); } }\n";
    auto fx = compile(src, diags);
    ASSERT_TRUE(fx) << diags.str();
    ASSERT_EQ(fx->textures.size(), 5u);
    EXPECT_EQ(fx->textures[0].kind, TextureDesc::Kind::Noise);
    EXPECT_EQ(fx->textures[1].kind, TextureDesc::Kind::Noise);
    EXPECT_EQ(fx->textures[2].kind, TextureDesc::Kind::Runtime);
    EXPECT_EQ(fx->textures[3].kind, TextureDesc::Kind::Procedural);
    EXPECT_EQ(fx->textures[4].kind, TextureDesc::Kind::Runtime);
}

// A sampler's Texture naming a parameter that exists but is no texture says it is the wrong type, at the
// reference.
TEST(EffectCompiler, ASamplerTextureOfTheWrongTypeSaysSo) {
    DiagnosticList diags;
    std::string src =
        "float Exponent = 40;\n"
        "sampler S = sampler_state { Texture = <Exponent>; };\n"
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile ps_2_0 PS(); } }\n";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    EXPECT_EQ(diags.items()[0].id, DiagId::TextureStateNotTexture) << diags.str();
    EXPECT_EQ(diags.items()[0].loc.line, 2) << diags.str();
    EXPECT_EQ(diags.items()[0].loc.column, 39) << diags.str();  // at <Exponent>
    EXPECT_NE(diags.str().find("'Exponent' is a float parameter, not a texture"), std::string::npos)
        << diags.str();
}

TEST(EffectCompiler, RenderTargetSizeOutOfRange) {
    DiagnosticList diags;
    std::string src =
        "texture T : RENDERCOLORTARGET < int2 Dimensions = {0, 99999}; >;\n"
        "float4 PS() : COLOR { return 1; }\ntechnique t { pass p { PixelShader = compile ps_2_0 PS(); } }\n";
    EXPECT_FALSE(compile(src, diags));
    ASSERT_FALSE(diags.items().empty());
    EXPECT_EQ(diags.items()[0].id, DiagId::RenderTargetSizeOutOfRange) << diags.str();
}

TEST(EffectCompiler, ScriptUnknownPassAndTarget) {
    DiagnosticList diags;
    std::string src = R"(texture Color : RENDERCOLORTARGET;
float4 PS() : COLOR { return 1; }
technique t < string Script = "Pass=p; Pass=nope;"; >
{
    pass p < string Script = "RenderColorTarget0=Missing; Draw=Geometry;"; >
    { PixelShader = compile ps_2_0 PS(); }
}
)";
    EXPECT_FALSE(compile(src, diags));
    bool pass = false, target = false;
    for (const Diagnostic& d : diags.items()) {
        if (d.id == DiagId::ScriptUnknownPass) {
            pass = true;
            EXPECT_EQ(d.loc.line, 3);
        }
        if (d.id == DiagId::ScriptColorTargetNotTarget) {  // FX Composer warned and drew on
            target = true;
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_EQ(d.loc.line, 5);
        }
    }
    EXPECT_TRUE(pass && target) << diags.str();
}

// The pass annotations the runtime acts on arrive resolved on each CompiledPass, whichever technique is
// compiled: compiled alone, `b` keeps its own annotations, not those of the technique before it.
const char* kAnnotatedPasses = R"(
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return float4(1, 1, 1, 1); }
technique a
{
    pass p < bool CullClosedOnly = false; > { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
technique b
{
    pass p < bool CullClosedOnly = true; string LeaveOutWhen = "NoLightArea"; float FilterReachTexels = 0.5; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
)";

TEST(EffectCompiler, PassAnnotationsAreResolvedPerPass) {
    for (const std::string technique : {"", "b"}) {
        DiagnosticList diags;
        auto effect = parseEffectSource(kAnnotatedPasses, "annotated.fx", ParseOptions{}, diags);
        ASSERT_TRUE(effect) << diags.str();
        CompileOptions options;
        options.technique = technique;
        auto compiled = compileEffect(effect, options, diags);
        ASSERT_TRUE(compiled) << diags.str();
        const CompiledTechnique* b = compiled->findTechnique("b");
        ASSERT_TRUE(b);
        EXPECT_TRUE(b->passes[0].cullClosedOnly) << "technique '" << technique << "'";
        EXPECT_EQ(b->passes[0].leaveOutWhen, LeaveOutCondition::NoLightArea);
        EXPECT_FLOAT_EQ(b->passes[0].filterReachTexels, 1.0f);  // a texel at least
        if (const CompiledTechnique* a = compiled->findTechnique("a")) {
            EXPECT_FALSE(a->passes[0].cullClosedOnly);
            EXPECT_EQ(a->passes[0].leaveOutWhen, LeaveOutCondition::Never);
            EXPECT_EQ(a->passes[0].filterReachTexels, 0.0f);
        }
    }
}

// Pass= names a pass without regard to case, the first of equal names (scriptNameMatches); the compiler
// resolves it to the pass's index, which is all the runtime reads.
TEST(EffectCompiler, ScriptPassesAreResolvedToIndices) {
    const std::string source = std::string(R"(float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t < string Script = "Pass=second; Pass=P0; Pass=Twice;"; >
{
    pass p0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
    pass Second { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
    pass twice { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
    pass twice { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
)");
    DiagnosticList diags;
    auto effect = parseEffectSource(source, "passes.fx", ParseOptions{}, diags);
    ASSERT_TRUE(effect) << diags.str();
    auto compiled = compileEffect(effect, CompileOptions{}, diags);
    ASSERT_TRUE(compiled) << diags.str();
    const std::vector<ScriptCommand>& script = compiled->techniques[0].script;
    ASSERT_EQ(script.size(), 3u);
    EXPECT_EQ(script[0].pass, 1);
    EXPECT_EQ(script[1].pass, 0);
    EXPECT_EQ(script[2].pass, 2);
}

// Every operand a script names is resolved by the compiler: parameters and lights to indices, literals to
// values, the global selector to technique indices; the runtime reads these and looks up no name.
TEST(EffectCompiler, ScriptOperandsAreResolvedToIndicesAndValues) {
    const std::string source = R"(float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
float4x4 LightView : View < string frustum = "sun"; >;
bool UseFast = true;
int Count = 2;
int Index;
float4 Background = {0, 0, 0, 1};
texture Map : RENDERCOLORTARGET < float2 Dimensions = {64, 64}; >;
float Script : STANDARDSGLOBAL < string Script = "Technique=UseFast?fast:slow;"; > = 0.8;
technique slow { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
technique fast < string Script = "RenderColorTarget0=Map; RenderPort=lamp; ClearSetColor=Background; ClearSetDepth=0.5; ClearSetColor=1,0,0,1; LoopByCount=Count; LoopGetIndex=Index; Pass=p; LoopEnd=; RenderPort=sun; RenderPort=;"; >
{
    pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
)";
    DiagnosticList diags;
    auto effect = parseEffectSource(source, "operands.fx", ParseOptions{}, diags);
    ASSERT_TRUE(effect) << diags.str();
    auto compiled = compileEffect(effect, CompileOptions{}, diags);
    ASSERT_TRUE(compiled) << diags.str();
    const auto parameter = [&](const std::string& name) {
        return static_cast<int>(compiled->findParameter(name) - compiled->parameters.data());
    };
    // The parameters' lights first, then the scripts'.
    EXPECT_EQ(compiled->lights, (std::vector<std::string>{"sun", "lamp"}));

    ASSERT_EQ(compiled->globalScript.size(), 1u);
    const ScriptCommand& select = compiled->globalScript[0];
    EXPECT_EQ(select.selectorParameter, parameter("UseFast"));
    EXPECT_EQ(select.technique, 1);
    EXPECT_EQ(select.techniqueIfFalse, 0);

    const std::vector<ScriptCommand>& script = compiled->techniques[1].script;
    ASSERT_EQ(script.size(), 11u);
    EXPECT_EQ(script[0].parameter, parameter("Map"));
    EXPECT_EQ(script[1].light, 1);
    EXPECT_EQ(script[2].parameter, parameter("Background"));
    EXPECT_FALSE(script[2].literal);
    EXPECT_EQ(script[3].parameter, -1);
    ASSERT_TRUE(script[3].literal);
    EXPECT_EQ(script[3].literal->data, (std::vector<float>{0.5f}));
    ASSERT_TRUE(script[4].literal);
    EXPECT_EQ(script[4].literal->data, (std::vector<float>{1, 0, 0, 1}));
    EXPECT_EQ(script[5].parameter, parameter("Count"));
    EXPECT_EQ(script[6].parameter, parameter("Index"));
    EXPECT_EQ(script[7].pass, 0);
    EXPECT_EQ(script[9].light, 0);
    EXPECT_EQ(script[10].light, -1);
}

// Technique=A with a name the effect lacks, and FX Composer's alternatives, resolve to what runs.
TEST(EffectCompiler, TechniqueSelectorsResolveToTheTechniqueThatRuns) {
    const auto selected = [](const std::string& selector) {
        const std::string source = R"(float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
float Script : STANDARDSGLOBAL < string Script = ")" +
                                   selector + R"("; > = 0.8;
technique Simple { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
technique Textured { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
        DiagnosticList diags;
        auto effect = parseEffectSource(source, "selector.fx", ParseOptions{}, diags);
        auto compiled = effect ? compileEffect(effect, CompileOptions{}, diags) : nullptr;
        EXPECT_TRUE(compiled) << diags.str();
        return compiled ? compiled->globalScript.at(0).technique : -2;
    };
    EXPECT_EQ(selected("Technique=Textured;"), 1);
    EXPECT_EQ(selected("Technique=Missing;"), -1);  // the first technique runs
    EXPECT_EQ(selected("Technique=Technique?Simple10:Textured:Simple;"), 1);
    EXPECT_EQ(selected("Technique=Technique?Simple10:Textured10;"), -1);
}

// An invalid pass annotation the runtime acts on is an error at the annotation, on the pass's line (6),
// whose message names it.
void expectPassAnnotationError(const char* annotation, DiagId id, const char* name) {
    DiagnosticList diags;
    auto effect = parseEffectSource(
        std::string(R"(
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return float4(1, 1, 1, 1); }
technique t
{
    pass p < )") +
            annotation + R"(; > { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }
}
)",
        "annotation.fx", ParseOptions{}, diags);
    ASSERT_TRUE(effect) << diags.str();
    EXPECT_FALSE(compileEffect(effect, CompileOptions{}, diags));
    ASSERT_TRUE(diags.hasErrors());
    const Diagnostic& error = diags.items().back();
    EXPECT_EQ(error.id, id);
    EXPECT_EQ(error.loc.file, "annotation.fx");
    EXPECT_EQ(error.loc.line, 6);
    EXPECT_NE(error.message.find(name), std::string::npos) << error.message;
}

TEST(EffectCompiler, AnUnknownLeaveOutConditionIsALocatedError) {
    expectPassAnnotationError(R"(string LeaveOutWhen = "Sometimes")", DiagId::LeaveOutWhenInvalid,
                              "LeaveOutWhen");
}

// CastersOnly is a bool the compiler resolves into CompiledPass::castersOnly: a string is an error at the
// annotation, never read as false without a word.
TEST(EffectCompiler, AStringCastersOnlyIsALocatedError) {
    expectPassAnnotationError(R"(string CastersOnly = "true")", DiagId::AnnotationNumberExpected,
                              "CastersOnly");
}

// SPIRV-Cross's own words never reach the user alone: its failure names the shader of the effect and, for a
// D3D9 sampler handed to Texture2D.Sample, what in the effect caused it.
TEST(EffectCompiler, CrossCompileErrorSaysWhatInTheEffectCausedIt) {
    DiagnosticList diags;
    EXPECT_FALSE(compile(R"(Texture2D Tex;
sampler2D Samp;
float4 PS(float2 uv : TEXCOORD0) : SV_Target { return Tex.Sample(Samp, uv) + tex2D(Samp, uv); }
technique11 t { pass p { SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
                         diags));
    ASSERT_EQ(diags.errorCount(), 1u) << diags.str();
    const Diagnostic& d = diags.items().back();
    EXPECT_EQ(d.id, DiagId::CrossCompileCombinedSampler);
    EXPECT_EQ(d.loc.line, 4);
    EXPECT_NE(d.message.find("Sample or Gather method is given a D3D9 sampler"), std::string::npos)
        << d.message;
    EXPECT_NE(d.message.find("the pixel shader 'PS' (ps_4_0)"), std::string::npos) << d.message;
}

}  // namespace
}  // namespace fx::test_effect_compiler
