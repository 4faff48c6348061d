// The D3D9 effect forms FX Composer and the DirectX SDK accepted, on the fx side (no GL): files saved by
// Windows editors, includes as D3DX resolved them, technique selectors, D3D9 HLSL and effect syntax, the
// texture formats of Format annotations, and a located error for what stays refused (asm shaders).
#include <fx/CompiledEffect.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <fx/Preshader.h>
#include <fx/SasScript.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fx::test_fxcomposer_syntax {
namespace {

// A small complete effect: one pass with both shaders.
const char* kEffect = R"(float4x4 Wvp : WorldViewProjection;
float4 Tint = {1, 0.5, 0.25, 1};
float4 VS(float4 p : POSITION) : POSITION { return mul(p, Wvp); }
float4 PS() : COLOR { return Tint; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";

std::shared_ptr<const CompiledEffect> compile(const std::string& source, DiagnosticList& diagnostics,
                                              const std::string& name = "fxc.fx") {
    std::shared_ptr<Effect> effect = parseEffectSource(source, name, ParseOptions{}, diagnostics);
    if (!effect) return nullptr;
    return compileEffect(effect, CompileOptions{}, diagnostics);
}

int count(const DiagnosticList& diagnostics, DiagId id) {
    int n = 0;
    for (const Diagnostic& d : diagnostics.items()) n += d.id == id;
    return n;
}

std::string utf16(const std::string& ascii, bool bigEndian) {
    std::string out = bigEndian ? "\xFE\xFF" : "\xFF\xFE";
    for (char c : ascii) {
        if (bigEndian) out += '\0';
        out += c;
        if (!bigEndian) out += '\0';
    }
    return out;
}

std::string crlf(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n') out += '\r';
        out += c;
    }
    return out;
}

// [SECTION] Source encodings

TEST(FxComposerSyntax, ByteOrderMarksUtf16AndCrlfSourcesCompile) {
    for (const std::string& source : {"\xEF\xBB\xBF" + std::string(kEffect), utf16(kEffect, false),
                                      utf16(kEffect, true), crlf(kEffect), utf16(crlf(kEffect), false)}) {
        DiagnosticList diagnostics;
        auto compiled = compile(source, diagnostics);
        EXPECT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    }
}

TEST(FxComposerSyntax, ErrorColumnsStayRightInEveryEncoding) {
    // Line 2, column 11: the unknown identifier `Bogus` in the initializer.
    const std::string bad = "float4 A = {1, 1, 1, 1};\nfloat4 B = Bogus + A;\n";
    for (const std::string& source : {bad, "\xEF\xBB\xBF" + bad, utf16(bad, false), utf16(bad, true),
                                      crlf(bad), "\xEF\xBB\xBF" + crlf(bad)}) {
        DiagnosticList diagnostics;
        auto effect = parseEffectSource(source, "bad.fx", ParseOptions{}, diagnostics);
        if (effect) compileEffect(effect, CompileOptions{}, diagnostics);
        ASSERT_TRUE(diagnostics.hasErrors());
        const Diagnostic& first = diagnostics.items().front();
        EXPECT_EQ(first.loc.line, 2) << diagnostics.str();
        EXPECT_EQ(first.loc.column, 12) << diagnostics.str();
    }
    // On line 1, behind the byte-order mark: the mark is no column.
    const std::string first = "float4 A = Bogus;\n";
    for (const std::string& source : {first, "\xEF\xBB\xBF" + first, utf16(first, false)}) {
        DiagnosticList diagnostics;
        auto effect = parseEffectSource(source, "bad.fx", ParseOptions{}, diagnostics);
        if (effect) compileEffect(effect, CompileOptions{}, diagnostics);
        ASSERT_TRUE(diagnostics.hasErrors());
        EXPECT_EQ(diagnostics.items().front().loc.column, 12) << diagnostics.str();
    }
}

// [SECTION] Includes

class Includes : public ::testing::Test {
protected:
    void SetUp() override {
        mRoot = std::filesystem::temp_directory_path() /
                ("shadowfx_includes_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                 "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(mRoot);
        std::filesystem::create_directories(mRoot / "include");
    }
    void TearDown() override { std::filesystem::remove_all(mRoot); }
    void write(const std::string& relative, const std::string& text) {
        std::ofstream(mRoot / relative, std::ios::binary) << text;
    }
    std::filesystem::path mRoot;
};

// `#include <include\\Quad.fxh>` inside include/shadowMap.fxh: not include/include/Quad.fxh (beside the
// including file) but the root effect's include/Quad.fxh, as D3DX and FX Composer looked next.
TEST_F(Includes, BackslashIncludeResolvesBesideTheRootEffectAfterTheIncludingFile) {
    write("include/Quad.fxh", "float QuadMarker = 1;\n");
    write("include/shadowMap.fxh", "#include <include\\\\Quad.fxh>\nfloat ShadowMarker = 2;\n");
    write("effect.fx", "#include \"include\\shadowMap.fxh\"\n" + std::string(kEffect));
    DiagnosticList diagnostics;
    auto effect = parseEffectFile((mRoot / "effect.fx").string(), ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    EXPECT_TRUE(effect->findParameter("QuadMarker"));
    EXPECT_TRUE(effect->findParameter("ShadowMarker"));
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
}

TEST_F(Includes, NameThatDiffersOnlyInCaseIsFoundWithAWarning) {
    write("include/noise_2D.fxh", "float NoiseMarker = 1;\n");
    write("effect.fx", "#include \"include/noise_2d.fxh\"\n" + std::string(kEffect));
    DiagnosticList diagnostics;
    auto effect = parseEffectFile((mRoot / "effect.fx").string(), ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    EXPECT_TRUE(effect->findParameter("NoiseMarker"));
    ASSERT_EQ(count(diagnostics, DiagId::IncludeCaseMismatch), 1) << diagnostics.str();
    const Diagnostic& warning = diagnostics.items().front();
    EXPECT_EQ(warning.severity, Severity::Warning);
    EXPECT_EQ(warning.loc.line, 1);
    EXPECT_EQ(warning.loc.column, 10);
}

// [SECTION] Technique selectors

TEST(FxComposerSyntax, SelectorListsAnyNumberOfAlternatives) {
    DiagnosticList diagnostics;
    auto commands = parseSasScript("Technique=Technique?Simple:Simple10:Textured:Textured10;",
                                   SourceLoc{"s.fx", 1, 1}, diagnostics);
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].selectorCondition, "Technique");
    EXPECT_EQ(commands[0].selectorAlternatives,
              (std::vector<std::string>{"Simple", "Simple10", "Textured", "Textured10"}));
    EXPECT_FALSE(diagnostics.hasErrors());
}

TEST(FxComposerSyntax, SelectorNamingNoTechniqueWarnsAndNeverFails) {
    const std::string source = std::string(R"(float Script : STANDARDSGLOBAL <
    string ScriptClass = "object"; string Script = "Technique=Technique?Main10:Renamed;"; > = 0.8;
)") + kEffect;
    DiagnosticList diagnostics;
    auto compiled = compile(source, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    EXPECT_EQ(count(diagnostics, DiagId::ScriptUnknownTechnique), 2) << diagnostics.str();
    EXPECT_EQ(count(diagnostics, DiagId::ScriptTechniqueFallback), 1) << diagnostics.str();

    // A plain name (a technique a #define renamed) is no different.
    DiagnosticList plain;
    compiled = compile(
        std::string("float Script : STANDARDSGLOBAL < string Script = \"Technique=Missing;\"; > = 0.8;\n") +
            kEffect,
        plain);
    ASSERT_TRUE(compiled) << plain.str();
    EXPECT_FALSE(plain.hasErrors()) << plain.str();
    EXPECT_EQ(count(plain, DiagId::ScriptTechniqueFallback), 1) << plain.str();
}

// [SECTION] D3D9 HLSL and effect syntax

TEST(FxComposerSyntax, D3d9FormsCompile) {
    const char* source = R"(static const int COUNT = 3;
static const int TWICE = COUNT * 2 - 1;
float4x4 Wvp : WorldViewProjection;
float4 Colors[TWICE + (COUNT % 2)];
int Packed = 0xff202080;
int AllBits = 0xFFFFFFFF;
texture SideTarget < int2 RenderTargetDimensions = {32, 16}; string Format = "D3DFMT_A16B16G16R16F"; >;
texture RatioTarget < float2 ViewPortRatio = {0.5, 0.5}; string Format = "L8"; >;
struct In {
    float4 Pos : POSITION; float4 W : BLENDWEIGHT0; float4 I : BLENDINDICES0; float3 T1 : TANGENT1;
    float3 B1 : BINORMAL1; float4 C2 : COLOR2; float Size : PSIZE; float Fog : FOG;
};
struct V2P { float4 Pos : POSITION; float2 Uv : TEXCOORD0_centroid; float3x3 Frame : TEXCOORD1;
             float4 Pair[2] : TEXCOORD4; };
V2P VS(In i) {
    V2P o;
    o.Pos = mul(i.Pos, Wvp);
    o.Uv = i.W.xy + i.I.zw + i.T1.xy + i.B1.yz + i.C2.xy + float2(i.Size, i.Fog);
    o.Frame = float3x3(i.T1, i.B1, cross(i.T1, i.B1));
    o.Pair[0] = Colors[0];
    o.Pair[1] = Colors[4];
    return o;
}
float4 PS(V2P v) : COLOR { return float4(v.Uv, v.Frame[1].x, 1) + v.Pair[1]; }
technique T < string Script = "RenderColorTarget0=SideTarget; Clear=Color0; Clear=DepthStencil; Clear=color|depth;"
                              "RenderColorTarget0=RatioTarget; Clear=All; RenderColorTarget0=; Pass=P;"; > {
    pass P { VertexShader = compile vs_1_1 VS(); PixelShader = compile ps_3_0 PS(); GeometryShader = null; }
}
technique U { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = null; } }
)";
    DiagnosticList diagnostics;
    auto compiled = compile(source, diagnostics);
    ASSERT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    const CompiledEffect& effect = *compiled;
    ASSERT_TRUE(effect.findParameter("Colors"));
    EXPECT_EQ(effect.findParameter("Colors")->type.arrayDims, std::vector<int>{6});
    const size_t packed = static_cast<size_t>(effect.findParameter("Packed") - effect.parameters.data());
    const size_t all = static_cast<size_t>(effect.findParameter("AllBits") - effect.parameters.data());
    EXPECT_EQ(compiled->initialValues[packed].asInt(), static_cast<int32_t>(0xff202080u));
    EXPECT_EQ(compiled->initialValues[all].asInt(), -1);
    int targets = 0;
    for (const TextureDesc& t : compiled->textures) {
        targets += t.kind == TextureDesc::Kind::RenderColorTarget;
        if (effect.parameters[t.parameter].name == "SideTarget") {
            EXPECT_EQ(t.width, 32);
            EXPECT_EQ(t.height, 16);
            EXPECT_EQ(t.format, TextureFormat::RGBA16F);
        }
    }
    EXPECT_EQ(targets, 2);
    // Clear=Color0, DepthStencil (two), color|depth (two), All (three)
    const CompiledTechnique* t = compiled->findTechnique("T");
    ASSERT_TRUE(t);
    int clears = 0;
    for (const ScriptCommand& c : t->script) clears += c.kind == ScriptCommand::Kind::Clear;
    EXPECT_EQ(clears, 8);
}

TEST(FxComposerSyntax, EveryFormatNameFxComposerAcceptedParses) {
    for (const char* name : {"A16B16G16R16",
                             "A16B16G16R16F",
                             "A32B32G32R32F",
                             "R16F",
                             "G16R16F",
                             "R32F",
                             "X8R8G8B8",
                             "A8R8G8B8",
                             "L8",
                             "D24S8",
                             "D24X8",
                             "D16",
                             "D24S8_SHADOWMAP",
                             "G16R16",
                             "A8",
                             "R5G6B5",
                             "A2R10G10B10",
                             "R8G8B8A8_UNORM",
                             "R16G16B16A16_FLOAT",
                             "R32_FLOAT",
                             "D32_FLOAT",
                             "R11G11B10_FLOAT",
                             "B8G8R8A8_UNORM_SRGB"}) {
        EXPECT_TRUE(parseTextureFormat(name)) << name;
        EXPECT_TRUE(parseTextureFormat(std::string("D3DFMT_") + name) ||
                    parseTextureFormat(std::string("DXGI_FORMAT_") + name))
            << name;
    }
    EXPECT_EQ(parseTextureFormat("D3DFMT_D24S8_SHADOWMAP"), TextureFormat::D24S8);
    EXPECT_FALSE(parseTextureFormat("NOT_A_FORMAT"));
}

TEST(FxComposerSyntax, AsmShaderIsALocatedError) {
    const char* source = R"(technique T { pass P {
    VertexShader = asm { vs_1_1 dcl_position v0 mov oPos, v0 };
} }
)";
    DiagnosticList diagnostics;
    auto compiled = compile(source, diagnostics);
    ASSERT_TRUE(diagnostics.hasErrors());
    const Diagnostic& error = diagnostics.items().front();
    EXPECT_EQ(error.loc.line, 2) << diagnostics.str();
    EXPECT_EQ(error.loc.column, 20) << diagnostics.str();
    EXPECT_NE(error.message.find("asm"), std::string::npos) << diagnostics.str();
}

// [SECTION] Preshaders calling the effect's own functions

TEST(FxComposerSyntax, CompileArgumentCallingAUserFunctionIsEvaluatedOnTheHost) {
    const char* source = R"(float4x4 Wvp : WorldViewProjection;
float Level = 0.5;
float scaled(float x, float k) { float y = x * k; y += 0.25; return saturate(y); }
float4 VS(float4 p : POSITION) : POSITION { return mul(p, Wvp); }
float4 PS(uniform float gain) : COLOR { return gain; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(scaled(Level, 1.5));
                       AlphaRef = (int)(scaled(Level, 100.0) * 2.0); } }
)";
    DiagnosticList diagnostics;
    auto compiled = compile(source, diagnostics);
    ASSERT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    ASSERT_EQ(pass.arguments.size(), 1u);
    // The inlined call compiled to a preshader program over the parameter slots.
    EXPECT_FALSE(pass.arguments[0].value.isConstant());
    std::optional<Value> gain = pass.arguments[0].value.run(compiled->initialValues, &diagnostics);
    ASSERT_TRUE(gain) << diagnostics.str();
    EXPECT_FLOAT_EQ(gain->asFloat(), 1.0f);  // saturate(0.5 * 1.5 + 0.25)
}

// The four shapes of function D3DX's preshaders ran and the host once refused, in one compile argument:
// a `return` inside a loop, `out`/`inout` parameters, a local array indexed by a tweakable and struct
// values through functions. The program is run at the default and at another value of the tweakable.
TEST(FxComposerSyntax, HostEvaluatedFunctionsReturnInLoopsWriteOutParametersAndHoldArraysAndStructs) {
    const char* source = R"(float4x4 Wvp : WorldViewProjection;
float Level = 0.35;
struct Pair { float a; float2 b; };
float first_above(float x) {
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 1; j++)
            if (i * 0.125 >= x) return i * 0.1;
    return 1;
}
void split(float x, out float hi, inout float lo) { hi = x * 2; lo += x; }
float picked(float x) {
    float w[3] = {0.25, 0.5, 0.75};
    int k = x > 0.5 ? 2 : 1;
    w[k] += 0.125;
    return w[k];
}
Pair make_pair(float x) { Pair p = (Pair)0; p.b.y = x; p.a = 1; return p; }
float3 all_four(float x) {
    float hi, lo = 0.5;
    split(x, hi, lo);
    Pair p = make_pair(hi);
    Pair q = x > 0.5 ? p : make_pair(lo);
    return float3(first_above(x) + picked(x), q.b.y, p.a);
}
float4 VS(float4 p : POSITION) : POSITION { return mul(p, Wvp); }
float4 PS(uniform float3 v) : COLOR { return float4(v, 1); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(all_four(Level)); } }
)";
    DiagnosticList diagnostics;
    auto compiled = compile(source, diagnostics);
    ASSERT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    const CompiledPass& pass = compiled->techniques[0].passes[0];
    ASSERT_EQ(pass.arguments.size(), 1u);
    EXPECT_FALSE(pass.arguments[0].value.isConstant());
    std::vector<Value> values = compiled->initialValues;
    std::optional<Value> v = pass.arguments[0].value.run(values, &diagnostics);
    ASSERT_TRUE(v && v->data.size() == 3) << diagnostics.str();
    // 0.35: 0.3 + (0.5 + 0.125); lo = 0.85 chosen; a = 1.
    EXPECT_FLOAT_EQ(v->data[0], 0.925f);
    EXPECT_FLOAT_EQ(v->data[1], 0.85f);
    EXPECT_FLOAT_EQ(v->data[2], 1.0f);
    size_t level = 0;
    while (compiled->parameters[level].name != "Level") ++level;
    values[level] = Value::scalar(0.65f);
    v = pass.arguments[0].value.run(values, &diagnostics);
    ASSERT_TRUE(v && v->data.size() == 3) << diagnostics.str();
    // 0.65: 0.6 + (0.75 + 0.125); hi = 1.3 chosen.
    EXPECT_FLOAT_EQ(v->data[0], 1.475f);
    EXPECT_FLOAT_EQ(v->data[1], 1.3f);
    EXPECT_FLOAT_EQ(v->data[2], 1.0f);
}

}  // namespace
}  // namespace fx::test_fxcomposer_syntax
