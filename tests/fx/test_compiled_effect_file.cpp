// Compiled effect files (fx/CompiledEffectFile.h): every shipped effect survives a round trip with
// nothing lost, and a truncated, corrupt or newer file is a located error, never a crash.
#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>
#include <fx/RenderStates.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace fx::test_compiled_effect_file {
namespace {

std::vector<std::string> shippedEffects() {
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator("effects"))
        if (entry.path().extension() == ".fx") paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::shared_ptr<CompiledEffect> compileShipped(const std::string& path, DiagnosticList& diagnostics) {
    return loadEffectFile(path, ParseOptions{}, CompileOptions{}, diagnostics);
}

// `source` (named NAME.fx) compiled into `compiled`, and its file (NAME.sfxo) read back into `read`, which
// serializes to the same bytes.
void compileAndReadBack(const char* source, const std::string& name,
                        std::shared_ptr<CompiledEffect>& compiled, std::unique_ptr<CompiledEffect>& read) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(source, name + ".fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const std::string bytes = serializeCompiledEffect(*compiled);
    read = deserializeCompiledEffect(bytes, name + ".sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    EXPECT_EQ(serializeCompiledEffect(*read), bytes);
}

// The one error a read of `bytes` reports, as the CLI prints it.
std::string readError(std::string_view bytes, DiagId expected) {
    DiagnosticList diagnostics;
    std::unique_ptr<CompiledEffect> effect = deserializeCompiledEffect(bytes, "shadow.sfxo", diagnostics);
    EXPECT_FALSE(effect);
    EXPECT_EQ(diagnostics.items().size(), 1u) << diagnostics.str();
    if (diagnostics.items().empty()) return "";
    EXPECT_EQ(diagnostics.items()[0].id, expected) << diagnostics.str();
    return renderDiagnostic(diagnostics.items()[0], false);
}

// Serialize, read back, serialize again: the same bytes, for every shipped effect. A field the writer
// writes and the reader does not read (or reads differently) changes the second file.
TEST(CompiledEffectFile, EveryShippedEffectRoundTripsByteForByte) {
    const std::vector<std::string> effects = shippedEffects();
    ASSERT_GE(effects.size(), 10u);
    for (const std::string& path : effects) {
        SCOPED_TRACE(path);
        DiagnosticList diagnostics;
        std::shared_ptr<CompiledEffect> compiled = compileShipped(path, diagnostics);
        ASSERT_TRUE(compiled) << diagnostics.str();
        const std::string first = serializeCompiledEffect(*compiled);
        DiagnosticList readDiagnostics;
        std::unique_ptr<CompiledEffect> read = deserializeCompiledEffect(first, path + "o", readDiagnostics);
        ASSERT_TRUE(read) << readDiagnostics.str();
        EXPECT_EQ(serializeCompiledEffect(*read), first);
        // What the runtime and the tools read, compared with the original directly.
        ASSERT_EQ(read->techniques.size(), compiled->techniques.size());
        EXPECT_EQ(read->techniques[0].passes.at(0).fragment.glsl,
                  compiled->techniques[0].passes.at(0).fragment.glsl);
        ASSERT_EQ(read->parameters.size(), compiled->parameters.size());
        for (size_t i = 0; i < read->parameters.size(); ++i) {
            EXPECT_EQ(read->parameters[i].annotations.size(), compiled->parameters[i].annotations.size());
            EXPECT_EQ(read->initialValues[i].data, compiled->initialValues[i].data);
        }
        EXPECT_EQ(read->provenance.sourcePath, path);
    }
}

// A pass's sampler-register states (`AddressU[0] = CLAMP;`) are the compiled effect's pass samplers,
// which the bindings index: they survive the file too.
TEST(CompiledEffectFile, PassSamplerStatesRoundTrip) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(R"(
texture Noise < string Procedural = "noise"; float2 Dimensions = {16, 16}; >;
sampler WrapSampler = sampler_state { Texture = <Noise>; AddressU = WRAP; AddressV = WRAP; };
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(WrapSampler, uv); }
technique PassClamps { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS();
    AddressU[0] = Clamp; } }
)",
                                                       "pass_samplers.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    std::shared_ptr<CompiledEffect> compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->passSamplers.size(), 1u);
    const std::string bytes = serializeCompiledEffect(*compiled);
    std::unique_ptr<CompiledEffect> read =
        deserializeCompiledEffect(bytes, "pass_samplers.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    ASSERT_EQ(read->passSamplers.size(), 1u);
    EXPECT_EQ(read->passSamplers[0].addressU, compiled->passSamplers[0].addressU);
    EXPECT_EQ(read->techniques[0].passes[0].fragment.samplers.at(0).passSampler, 0);
    EXPECT_EQ(serializeCompiledEffect(*read), bytes);
}

// A preshader's intrinsics are opcodes resolved by the compiler: the program read from the file runs them
// without their names being looked up again, and gives the compiled program's value.
TEST(CompiledEffectFile, PreshaderIntrinsicsRoundTrip) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled;
    std::unique_ptr<CompiledEffect> read;
    ASSERT_NO_FATAL_FAILURE(compileAndReadBack(R"(
float Bias = 0.125;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique Biased { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS();
    DepthBias = max(Bias, 0.25) * sqrt(4.0) + abs(-Bias); } }
)",
                                               "bias", compiled, read));
    const RenderStateSetting& state = read->techniques.at(0).passes.at(0).states.at(0);
    ASSERT_FALSE(state.constant);
    std::vector<Value> values = read->initialValues;
    const ParameterInfo* bias = read->findParameter("Bias");
    ASSERT_TRUE(bias);
    values.at(static_cast<size_t>(bias - read->parameters.data())) = Value::scalar(0.5f);
    const std::optional<Value> value = state.value.run(values, &diagnostics);
    ASSERT_TRUE(value) << diagnostics.str();
    EXPECT_EQ(value->asFloat(), 0.5f * 2.0f + 0.5f);
}

// A swizzle and a matrix member are stored as their components, read from the letters when compiled: the
// program read from the file picks the same numbers.
TEST(CompiledEffectFile, MembersRoundTripAsComponents) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled;
    std::unique_ptr<CompiledEffect> read;
    ASSERT_NO_FATAL_FAILURE(compileAndReadBack(R"(
float4 Offset = {1, 2, 3, 4};
float4x4 Shift = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique Biased { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS();
    DepthBias = Offset.wy.x + Shift._m12 * Shift._23_11.y + Offset.b; } }
)",
                                               "members", compiled, read));
    const RenderStateSetting& state = read->techniques.at(0).passes.at(0).states.at(0);
    ASSERT_FALSE(state.constant);
    const std::optional<Value> value = state.value.run(read->initialValues, &diagnostics);
    ASSERT_TRUE(value) << diagnostics.str();
    // w = 4; row 1 column 2 (zero-based) = 7; ._11 one-based = 1; b = 3.
    EXPECT_EQ(value->asFloat(), 4.0f + 7.0f * 1.0f + 3.0f);
}

// A script operand the runtime would follow (a parameter, light or technique index) that points nowhere is
// a corrupt file, refused before the runtime sees it.
TEST(CompiledEffectFile, AScriptOperandOutOfRangeIsCorrupt) {
    DiagnosticList diagnostics;
    std::shared_ptr<Effect> effect = parseEffectSource(R"(
float4 Background = {0, 0, 0, 1};
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t < string Script = "ClearSetColor=Background; Clear=Color; RenderPort=sun; Pass=p;"; >
{ pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                                       "operands.fx", ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    std::shared_ptr<CompiledEffect> compiled = compileEffect(effect, CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    ASSERT_EQ(compiled->techniques.at(0).script.size(), 4u);
    {
        CompiledEffect damaged = *compiled;
        damaged.techniques[0].script[0].parameter = static_cast<int>(damaged.parameters.size());
        EXPECT_NE(readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectScriptParameterOutOfRange)
                      .find("a script names a parameter out of range"),
                  std::string::npos);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.techniques[0].script[2].light = 1;
        EXPECT_NE(readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectScriptLightOutOfRange)
                      .find("a script names a light out of range"),
                  std::string::npos);
    }
    for (int target : {4, 0x10000000, -2}) {
        CompiledEffect damaged = *compiled;
        damaged.techniques[0].script[0].clearTarget = target;
        EXPECT_NE(
            readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectScriptClearTargetOutOfRange)
                .find("a script clears a colour target out of range"),
            std::string::npos)
            << target;
    }
}

// What the runtime binds and enables by, resolved by the compiler (each parameter's semantic with its
// light, each stage's effects), survives the file; a light out of range, a kind out of the enum or more
// clip distances than GL has planes is a corrupt file.
TEST(CompiledEffectFile, SemanticsAndStageEffectsRoundTrip) {
    std::shared_ptr<CompiledEffect> compiled;
    std::unique_ptr<CompiledEffect> read;
    ASSERT_NO_FATAL_FAILURE(compileAndReadBack(R"(
float4x4 gWorldViewProj;
float4x4 SunMatrix : ViewProjectionInverse < string frustum = "sun"; >;
struct VOut { float4 Pos : POSITION; float4 Colour : COLOR0; float2 Clip : SV_ClipDistance0; };
VOut VS(float4 p : POSITION) { VOut o; o.Pos = mul(mul(p, gWorldViewProj), SunMatrix); o.Colour = p; o.Clip = p.xy; return o; }
float4 PS(float4 c : COLOR0) : COLOR { clip(c.x - 0.5); return c; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                                               "resolved", compiled, read));
    const SemanticBinding& sun = read->findParameter("SunMatrix")->standard;
    EXPECT_EQ(sun.kind, SemanticKind::ViewProjection);
    EXPECT_TRUE(sun.inverse && !sun.transpose && !sun.byName);
    ASSERT_GE(sun.light, 0);
    EXPECT_EQ(read->lights.at(static_cast<size_t>(sun.light)), "sun");
    EXPECT_TRUE(read->findParameter("gWorldViewProj")->standard.byName);
    const CompiledPass& pass = read->techniques.at(0).passes.at(0);
    EXPECT_EQ(pass.vertex.effects.clipDistances, 2);
    EXPECT_TRUE(pass.vertex.effects.writesDiffuse);
    EXPECT_TRUE(pass.fragment.effects.discards);

    const size_t sunIndex = static_cast<size_t>(read->findParameter("SunMatrix") - read->parameters.data());
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[sunIndex].standard.light = static_cast<int>(damaged.lights.size());
        EXPECT_NE(readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectParameterLightOutOfRange)
                      .find("parameter 'SunMatrix' is bound to a light out of range"),
                  std::string::npos);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[sunIndex].standard.kind = static_cast<SemanticKind>(99);
        readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectEnumeratorOutOfRange);
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.techniques[0].passes[0].vertex.effects.clipDistances = 9;
        EXPECT_NE(readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectClipDistancesOutOfRange)
                      .find("pass 'p': a stage writes clip distances out of range"),
                  std::string::npos);
    }
}

// The members of a light struct bound by their names survive the file; one bound outside its parameter's
// value, or to a light out of range, is a corrupt file (the runtime writes it into its place in the value).
TEST(CompiledEffectFile, StructMemberBindingsRoundTrip) {
    std::shared_ptr<CompiledEffect> compiled;
    std::unique_ptr<CompiledEffect> read;
    ASSERT_NO_FATAL_FAILURE(compileAndReadBack(R"(
struct PointLight { float4 Diffuse; float3 Position; float Range; };
struct DirectionalLight { float4 Diffuse; float3 Direction; float pad; };
cbuffer PerFrame { PointLight gLight; DirectionalLight gDirLights[2]; };
float4 PS() : SV_Target { return gLight.Diffuse * gLight.Range + gDirLights[1].Diffuse + gLight.Position.x; }
technique11 t { pass p { SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                                               "members", compiled, read));
    const std::vector<MemberBinding>& members = read->findParameter("gLight")->memberBindings;
    ASSERT_EQ(members.size(), 3u);
    EXPECT_EQ(members[2].member, "Range");
    EXPECT_EQ(members[2].standard.kind, SemanticKind::LightRange);
    EXPECT_EQ(members[2].firstComponent, 7u);
    EXPECT_EQ(read->findParameter("gDirLights")->memberBindings.size(), 2u);

    const size_t light = static_cast<size_t>(read->findParameter("gLight") - read->parameters.data());
    const auto refused = [](const CompiledEffect& damaged) {
        return readError(serializeCompiledEffect(damaged), DiagId::CompiledEffectMemberBindingOutOfRange)
                   .find("parameter 'gLight' binds a member outside its value or to a light out of range") !=
               std::string::npos;
    };
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[light].memberBindings[2].firstComponent = 8;
        EXPECT_TRUE(refused(damaged));
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[light].memberBindings[0].standard.light = static_cast<int>(damaged.lights.size());
        EXPECT_TRUE(refused(damaged));
    }
    {
        CompiledEffect damaged = *compiled;
        damaged.parameters[light].memberBindings[0].standard.eachLight = true;  // one light, no array
        EXPECT_TRUE(refused(damaged));
    }
}

// Stream output (the capture a pass makes and the DrawAuto pass that draws it) survives the file.
TEST(CompiledEffectFile, StreamOutputRoundTrips) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled =
        compileShipped("tests/data/d3d10/stream_output_particles.fx", diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const std::string bytes = serializeCompiledEffect(*compiled);
    std::unique_ptr<CompiledEffect> read = deserializeCompiledEffect(bytes, "particles.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    EXPECT_EQ(serializeCompiledEffect(*read), bytes);
    size_t captures = 0, drawAutos = 0;
    for (const CompiledTechnique& technique : read->techniques)
        for (const CompiledPass& pass : technique.passes) {
            captures += pass.streamOut && !pass.streamOut->varyings.empty();
            drawAutos += pass.drawAuto >= 0;
        }
    EXPECT_GT(captures, 0u);
    EXPECT_GT(drawAutos, 0u);
}

// Annotations are values in the compiled effect: the UI's and the tests' reads need no syntax tree.
TEST(CompiledEffectFile, AnnotationsAreValues) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compileShipped("effects/back_faces.fx", diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    bool found = false;
    for (const CompiledTechnique& technique : compiled->techniques) {
        const AnnotationValue* size = findAnnotation(technique.annotations, "expectmapsize");  // case-blind
        if (!size) continue;
        found = true;
        EXPECT_EQ(size->value.type.base, BaseType::Int);
        EXPECT_EQ(size->value.asInt(), 256);
    }
    EXPECT_TRUE(found);
    EXPECT_EQ(findAnnotation(compiled->techniques[0].annotations, "NoSuchAnnotation"), nullptr);
}

class DamagedFile : public ::testing::Test {
protected:
    void SetUp() override {
        DiagnosticList diagnostics;
        std::shared_ptr<CompiledEffect> compiled = compileShipped("effects/plain_lit.fx", diagnostics);
        ASSERT_TRUE(compiled) << diagnostics.str();
        mBytes = serializeCompiledEffect(*compiled);
    }
    std::string mBytes;
};

TEST_F(DamagedFile, EveryTruncationIsAnError) {
    // Every length up to the whole header, then a spread of lengths through the content.
    for (size_t size = 1; size < mBytes.size(); size += size < 64 ? 1 : mBytes.size() / 97 + 1) {
        SCOPED_TRACE(size);
        const std::string_view cut(mBytes.data(), size);
        const DiagId expected = size < 8    ? DiagId::NotCompiledEffect
                                : size < 28 ? DiagId::CompiledEffectHeaderTruncated
                                            : DiagId::CompiledEffectContentTruncated;
        const std::string error = readError(cut, expected);
        EXPECT_EQ(error.rfind("shadow.sfxo: error: ", 0), 0u) << error;
    }
}

TEST_F(DamagedFile, AFlippedByteIsCorrupt) {
    for (size_t at : {size_t{40}, mBytes.size() / 2, mBytes.size() - 1}) {
        std::string bytes = mBytes;
        bytes[at] = static_cast<char>(bytes[at] ^ 0x5a);
        EXPECT_EQ(
            readError(bytes, DiagId::CompiledEffectHashMismatch),
            "shadow.sfxo: error: the compiled effect file is corrupt: its content does not match its hash");
    }
}

TEST_F(DamagedFile, ANewerFormatVersionIsNamed) {
    std::string bytes = mBytes;
    bytes[8] = static_cast<char>(kCompiledEffectFormatVersion + 1);
    const std::string error = readError(bytes, DiagId::CompiledEffectNewerFormat);
    EXPECT_NE(error.find("format version " + std::to_string(kCompiledEffectFormatVersion + 1)),
              std::string::npos)
        << error;
    bytes[8] = 0;
    readError(bytes, DiagId::CompiledEffectOlderFormat);
}

// A file of the format before this one is refused with the way out, never read with other meanings: format
// 14 left the units of D3D10 pairs and images, what a pass reads and a Buffer<T>'s texels to the runtime,
// which found them by name and text.
TEST_F(DamagedFile, TheFormatBeforeThisOneIsOlder) {
    ASSERT_GT(kCompiledEffectFormatVersion, 14u);
    std::string bytes = mBytes;
    bytes[8] = static_cast<char>(14);
    EXPECT_EQ(readError(bytes, DiagId::CompiledEffectOlderFormat),
              "shadow.sfxo: error: the compiled effect file has format version 14, which this shadowfx no "
              "longer reads (it reads " +
                  std::to_string(kCompiledEffectFormatVersion) + "): compile the effect again");
}

TEST_F(DamagedFile, SourceTextIsNotACompiledEffect) {
    EXPECT_EQ(readError("float4 PS() : COLOR { return 1; }", DiagId::NotCompiledEffect),
              "shadow.sfxo: error: not a compiled effect file (shadowfx compile EFFECT.fx --out EFFECT.sfxo "
              "writes one)");
    EXPECT_FALSE(hasCompiledEffectMagic("SFXO"));
    EXPECT_TRUE(hasCompiledEffectMagic(mBytes));
}

// Render states are stored by name, so a state added to the table cannot change what an older file sets;
// a name this shadowfx does not know (a file from a newer one) is named in the error.
TEST(CompiledEffectFile, AnUnknownRenderStateNameIsNamed) {
    DiagnosticList diagnostics;
    std::shared_ptr<CompiledEffect> compiled = compileShipped("effects/thesis_fxcomposer.fx", diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const std::string file = serializeCompiledEffect(*compiled);
    std::string content = file.substr(28);

    const std::string name(renderStateInfo(RenderStateId::BlendOp).name);
    const std::string stored = std::string(1, static_cast<char>(name.size())) + std::string(3, '\0') + name;
    const size_t at = content.find(stored);
    ASSERT_NE(at, std::string::npos) << "BlendOp is not stored by its name";
    const std::string unknown(name.size(), 'Q');
    content.replace(at + 4, name.size(), unknown);

    const std::string error =
        readError(compiledEffectFileAround(content), DiagId::CompiledEffectEnumeratorUnknown);
    EXPECT_NE(error.find("corrupt: an enumerator this shadowfx does not know ('" + unknown + "') at byte " +
                         std::to_string(at + 4 + name.size()) + " of the content"),
              std::string::npos)
        << error;
}

TEST(CompiledEffectFile, DiagnosticIdsAreFoundByName) {
    for (DiagId id : {DiagId::NotCompiledEffect, DiagId::CompiledEffectEnumeratorUnknown})
        EXPECT_EQ(findDiagnostic(diagnosticName(id)), id);
    EXPECT_FALSE(findDiagnostic("NoSuchDiagnostic"));
}

TEST_F(DamagedFile, TrailingBytesAreCorrupt) {
    EXPECT_EQ(readError(mBytes + "x", DiagId::CompiledEffectTrailingBytes),
              "shadow.sfxo: error: the compiled effect file is corrupt: 1 bytes follow the content");
}

}  // namespace
}  // namespace fx::test_compiled_effect_file
