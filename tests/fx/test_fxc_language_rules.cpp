// The effect language as fxc reads it, both ways (no GL): what fxc accepts and glslang's HLSL front end or
// an older shadowfx refused (files without techniques, matrix-order modifiers on annotations), and what fxc
// refuses that would otherwise pass (duplicate or self-referring annotations, object-typed annotations,
// annotations on locals, objects in structs), each at its location, and a SPIRV-Cross refusal told in the
// effect's terms.
#include <fx/CompiledEffect.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fx::test_fxc_language_rules {
namespace {

std::shared_ptr<const CompiledEffect> compile(const std::string& source, DiagnosticList& diagnostics) {
    std::shared_ptr<Effect> effect = parseEffectSource(source, "rules.fx", ParseOptions{}, diagnostics);
    if (!effect) return nullptr;
    return compileEffect(effect, CompileOptions{}, diagnostics);
}

// The errors of `source` as "line:column id".
std::vector<std::string> errorsOf(const std::string& source) {
    DiagnosticList diagnostics;
    compile(source, diagnostics);
    std::vector<std::string> errors;
    for (const Diagnostic& d : diagnostics.items())
        if (d.severity == Severity::Error)
            errors.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " +
                             std::string(diagnosticName(d.id)));
    return errors;
}

const char* kTechnique = R"(
float4x4 Wvp : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, Wvp); }
float4 PS() : SV_Target { return float4(1, 0, 0, 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)";

TEST(FxcLanguageRules, AFileWithoutTechniquesCompilesWithItsParameters) {
    DiagnosticList diagnostics;
    std::shared_ptr<const CompiledEffect> pool = compile(R"(
shared float4 AmbientColor : AMBIENT < string UIName = "Ambient"; > = {0.1, 0.1, 0.1, 1};
shared float4x4 ViewProjection : VIEWPROJECTION;
)",
                                                         diagnostics);
    ASSERT_NE(pool, nullptr) << diagnostics.str();
    EXPECT_EQ(diagnostics.errorCount(), 0u) << diagnostics.str();
    EXPECT_TRUE(pool->techniques.empty());
    ASSERT_EQ(pool->parameters.size(), 2u);
    EXPECT_EQ(pool->parameters[0].name, "AmbientColor");

    // Naming a technique such a file does not have is still an error.
    DiagnosticList named;
    std::shared_ptr<Effect> effect = parseEffectSource("float4 X;", "rules.fx", ParseOptions{}, named);
    ASSERT_NE(effect, nullptr);
    CompileOptions options;
    options.technique = "Shadow";
    EXPECT_EQ(compileEffect(effect, options, named), nullptr);
    EXPECT_NE(named.str().find("no technique named 'Shadow'"), std::string::npos) << named.str();
}

TEST(FxcLanguageRules, MatrixOrderModifiersPrecedeAnAnnotationsType) {
    DiagnosticList diagnostics;
    std::shared_ptr<const CompiledEffect> effect = compile(
        "float Scale < row_major float2x2 Basis = {1, 0, 0, 1}; column_major float2x2 Other = {0, 1, 1, 0}; "
        "> "
        "= 1;" +
            std::string(kTechnique),
        diagnostics);
    ASSERT_NE(effect, nullptr) << diagnostics.str();
    EXPECT_EQ(diagnostics.errorCount(), 0u) << diagnostics.str();
}

TEST(FxcLanguageRules, AnAnnotationDeclaredTwiceInOneBlockIsARedefinition) {
    EXPECT_EQ(errorsOf("float A < string UIName = \"a\"; float UIMin = 0; string UIName = \"b\"; > = 1;" +
                       std::string(kTechnique)),
              std::vector<std::string>{"1:56 Redefinition"});
    // The same name on two parameters is no redefinition: each block is its own.
    EXPECT_TRUE(errorsOf("float A < string UIName = \"a\"; > = 1; float B < string UIName = \"a\"; > = 1;" +
                         std::string(kTechnique))
                    .empty());
}

TEST(FxcLanguageRules, AnAnnotationInitializedFromAnotherIsRefusedWhereItNamesIt) {
    EXPECT_EQ(
        errorsOf("float A < float UIMin = 0; float UIMax = UIMin + 1; > = 1;" + std::string(kTechnique)),
        std::vector<std::string>{"1:42 AnnotationNamesAnnotation"});
    // A name that is not an annotation of the block (a state value, a parameter) is not this rule's.
    EXPECT_TRUE(
        errorsOf("float A < float UIMin = 0; float UIMax = 2; > = 1;" + std::string(kTechnique)).empty());
}

TEST(FxcLanguageRules, ObjectTypedAnnotationsAreRefusedAtTheirName) {
    EXPECT_EQ(errorsOf("float A < DepthStencilState Depth { DepthEnable = false; }; > = 1;" +
                       std::string(kTechnique)),
              std::vector<std::string>{"1:29 ObjectAnnotation"});
    EXPECT_EQ(errorsOf("float A < texture Tex = 0; > = 1;" + std::string(kTechnique)),
              std::vector<std::string>{"1:19 ObjectAnnotation"});
}

TEST(FxcLanguageRules, AnnotationsOnALocalVariableAreRefused) {
    const std::string source = R"(
float4x4 Wvp : WorldViewProjection;
float4 VS(float4 p : POSITION) : SV_Position
{
    const float scale < int UIMin = 0; > = 2;
    bool nearer = p.z < scale;
    return mul(p, Wvp) * (nearer ? scale : 1);
}
float4 PS() : SV_Target { return float4(1, 0, 0, 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)";
    // The comparison two lines below is not taken for annotations.
    EXPECT_EQ(errorsOf(source), std::vector<std::string>{"5:23 LocalAnnotation"});
}

TEST(FxcLanguageRules, ObjectsInsideAStructAreRefusedAtTheMember) {
    EXPECT_EQ(errorsOf("struct Material { float4 Tint; Texture2D Albedo; SamplerState Filter; };" +
                       std::string(kTechnique)),
              (std::vector<std::string>{"1:42 ObjectInStruct", "1:63 ObjectInStruct"}));
}

// SPIRV-Cross refuses a D3D9 sampler given to a texture object's Sample (its words name one of its own
// calls); the error stands at the pass's compile expression and says, in the effect's terms, which shader
// and what in it.
TEST(FxcLanguageRules, ASpirvCrossRefusalSaysWhatInTheEffectCausedIt) {
    DiagnosticList diagnostics;
    EXPECT_EQ(compile(R"(float4x4 Wvp : WorldViewProjection;
Texture2D Tex;
sampler2D TexSampler = sampler_state { Texture = <Tex>; };
float4 VS(float3 p : POSITION, out float2 uv : TEXCOORD0) : POSITION { uv = p.xy; return mul(float4(p, 1), Wvp); }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return Tex.Sample(TexSampler, uv) + tex2D(TexSampler, uv); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                      diagnostics),
              nullptr);
    ASSERT_EQ(diagnostics.errorCount(), 1u) << diagnostics.str();
    const Diagnostic& error = diagnostics.items().back();
    EXPECT_EQ(error.loc.file, "rules.fx");
    EXPECT_EQ(error.loc.line, 6);
    EXPECT_EQ(error.loc.column, 74);
    EXPECT_NE(error.message.find("Sample or Gather method is given a D3D9 sampler"), std::string::npos)
        << error.message;
    EXPECT_NE(error.message.find("the pixel shader 'PS' (ps_3_0)"), std::string::npos) << error.message;
}

}  // namespace
}  // namespace fx::test_fxc_language_rules
