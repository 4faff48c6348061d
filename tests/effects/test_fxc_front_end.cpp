// The effect language as fxc, D3DX9, FX Composer and MonoGame read it, not as glslang does: effects written
// in the styles of shipped game sets, MonoGame's stock effects and FX Composer scripts
// (tests/data/fxcomposer/) load with the warnings those tools gave, and draw every colour channel.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <algorithm>

namespace shadowfx::test::test_fxc_front_end {
namespace {

// Fails on a blank or constant frame, and on one that lacks a channel: a colour mask read as red alone
// (`ColorWriteEnable = true` taken for 1) leaves green and blue at the clear colour everywhere.
::testing::AssertionResult drawsEveryChannel(const runtime::FrameImage& image) {
    if (::testing::AssertionResult varied = notConstant(image); !varied) return varied;
    int low[3] = {255, 255, 255}, high[3] = {0, 0, 0};
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            low[c] = std::min<int>(low[c], image.rgba[i + c]);
            high[c] = std::max<int>(high[c], image.rgba[i + c]);
        }
    for (int c = 0; c < 3; ++c)
        if (high[c] - low[c] < 64)
            return ::testing::AssertionFailure()
                   << "channel " << c << " spans only " << low[c] << ".." << high[c];
    return ::testing::AssertionSuccess();
}

// Keywords, states and values in any case, `shared` parameters, `float4 a[3 * N - 4]`, an include line
// with text after its file name and `#if MACRO(X)` on an undefined macro: one warning each, and the
// frame lit by both coloured lights.
TEST(FxcFrontEnd, GameCoreStyleEffect) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/game_core_style.fx");
    ASSERT_TRUE(loaded.renderer);
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::IncludeTrailingText), 1)
        << loaded.diagnostics.str();
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::UndefinedConditionCall), 1)
        << loaded.diagnostics.str();
    const fx::CompiledEffect& effect = loaded.renderer->effect();
    ASSERT_TRUE(effect.findParameter("WorldViewProj"));
    EXPECT_TRUE(effect.findParameter("WorldViewProj")->isShared);
    EXPECT_EQ(effect.findParameter("WorldViewProj")->type.shape, fx::Shape::Matrix);
    ASSERT_TRUE(effect.findParameter("LightColors"));
    EXPECT_EQ(effect.findParameter("LightColors")->type.arrayDims, std::vector<int>{2});
    ASSERT_TRUE(effect.findTechnique("Main"));
    EXPECT_EQ(effect.findTechnique("Main")->passes.size(), 1u);

    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72));
    EXPECT_TRUE(drawsEveryChannel(loaded.renderer->readFrame()));
}

// MonoGame's stock-effect macros: a `sampler` without sampler_state sampled by a Texture2D, SV_Position0
// and SV_Target0, ColorWriteEnable = true and All, and vs_6_0/ps_6_0: both techniques draw.
TEST(FxcFrontEnd, MonoGameStyleEffect) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/monogame_style.fx");
    ASSERT_TRUE(loaded.renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    for (const char* technique : {"BasicEffect", "BasicEffect_SM6"}) {
        SCOPED_TRACE(technique);
        ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72, technique));
        EXPECT_TRUE(drawsEveryChannel(loaded.renderer->readFrame()));
    }
}

// XNA samples' shapes: a pixel shader named `main` (a second main() in GLSL, which the GL driver refuses,
// unless renamed) and a pixel input with the point-size semantic, read as 0: were it the 4 the vertex
// shader writes, the teapot would be black.
TEST(FxcFrontEnd, XnaSampleStyleEffect) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/xna_sample_style.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72));
    EXPECT_TRUE(drawsEveryChannel(loaded.renderer->readFrame()));
}

// A float3x3 vertex output under TANGENT0 (TANGENT0..2, one per column) and a float3 under BLENDWEIGHT0,
// as XNA and MonoGame effects pass a tangent frame: the objects are (0.75, 0.5, 1), which only every column
// and the weights crossing to the pixel shader draw (a column or the weights lost reads 0 there).
TEST(FxcFrontEnd, MatrixAndVertexInputNamedVaryings) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/matrix_varyings.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    EXPECT_FALSE(loaded.diagnostics.hasErrors()) << loaded.diagnostics.str();
    ASSERT_TRUE(render(*loaded.renderer, *runtime::makeBuiltinScene("teapot"), 64, 48));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    EXPECT_GE(countPixelsOfColour(frame, 64, 48, 191, 128, 255), 64 * 48 / 20);
}

// MonoGame's macros for OpenGL and Direct3D 9: a sampler block naming a texture nothing declares declares
// it, and the teapot draws lit through it.
TEST(FxcFrontEnd, MonoGameSamplerNamesItsTexture) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/monogame_gl_style.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    EXPECT_FALSE(loaded.diagnostics.hasErrors()) << loaded.diagnostics.str();
    // Declared, and said so at the sampler (the line whose macro declares it).
    ASSERT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::SamplerTextureUndeclared), 1)
        << loaded.diagnostics.str();
    for (const fx::Diagnostic& d : loaded.diagnostics.items()) {
        if (d.id != fx::DiagId::SamplerTextureUndeclared) continue;
        EXPECT_EQ(d.severity, fx::Severity::Warning);
        EXPECT_EQ(d.loc.line, 14);
        EXPECT_EQ(
            d.message,
            "sampler 'diffuseTextureSampler' names texture 'diffuseTexture', which the effect does not "
            "declare: it is declared as a texture parameter, as MonoGame's effect compiler declared it");
    }
    const fx::ParameterInfo* texture = loaded.renderer->effect().findParameter("diffuseTexture");
    ASSERT_TRUE(texture);
    EXPECT_TRUE(texture->type.isTexture());
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72));
    EXPECT_TRUE(drawsEveryChannel(loaded.renderer->readFrame()));
}

// Vectors cast to arrays, `unsigned`, the l-value constructor, a vertex shader doubling a uniform on its
// own copy and `line` as a name, as the SDK and FX Composer wrote them: the lit teapot is Tint's colour
// (red, half as much green, a quarter as much blue) at full strength, which it reaches only with the
// uniform doubled, the channels in that order only through the casts and the constructor.
TEST(FxcFrontEnd, ImplicitConversionsGlslangRefuses) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/fxc_conversions.fx");
    ASSERT_TRUE(loaded.renderer);
    EXPECT_FALSE(loaded.diagnostics.hasErrors()) << loaded.diagnostics.str();
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    const uint8_t* brightest = frame.pixel(0, 0);
    for (int y = 0; y < 72; ++y)
        for (int x = 0; x < 96; ++x)
            if (frame.pixel(x, y)[0] > brightest[0]) brightest = frame.pixel(x, y);
    EXPECT_GT(brightest[0], 200);
    EXPECT_NEAR(brightest[1], brightest[0] / 2.0, 8.0);
    EXPECT_NEAR(brightest[2], brightest[0] / 4.0, 8.0);
}

// A vector passed to a scalar parameter of the effect's own function (a local, a swizzle, a parameter):
// each call receives the first component, with fxc's warning X3206 at the argument; the objects are
// (1, 0.5, 0.25), which any other component would change.
TEST(FxcFrontEnd, VectorArgumentsOfScalarParametersPassTheirFirstComponent) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/scalar_arguments.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    std::vector<int> columns;
    for (const fx::Diagnostic& d : loaded.diagnostics.items()) {
        EXPECT_EQ(d.id, fx::DiagId::ImplicitVectorTruncation) << loaded.diagnostics.str();
        EXPECT_EQ(d.loc.line, 22);
        columns.push_back(d.loc.column);
    }
    EXPECT_EQ(columns, (std::vector<int>{25, 42, 63})) << loaded.diagnostics.str();
    ASSERT_TRUE(render(*loaded.renderer, *runtime::makeBuiltinScene("teapot"), 64, 48));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_GE(countPixelsOfColour(frame, 64, 48, 255, 128, 64), 64 * 48 / 20);
}

// Offsets from a loop in Sample, SampleLevel, SampleBias, SampleGrad, SampleCmp, SampleCmpLevelZero and
// Load (GLSL takes constant offsets only; the driver refused to link the pass) and an `unsigned int`
// counter: the Shift columns left of the middle average red and green, none right of it; a method whose
// offset were lost would leave those columns nearer red.
TEST(FxcFrontEnd, SampleOffsetsFromVariables) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/d3d10/variable_offsets.fx");
    ASSERT_TRUE(loaded.renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    constexpr int kWidth = 96, kHeight = 8, kShift = 4;
    ASSERT_TRUE(render(*loaded.renderer, scene, kWidth, kHeight));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    auto isColour = [&](int x, int r, int g, int b) {
        const uint8_t* p = frame.pixel(x, kHeight / 2);
        return std::abs(p[0] - r) <= 2 && std::abs(p[1] - g) <= 2 && std::abs(p[2] - b) <= 2;
    };
    for (int x = 0; x < kWidth; ++x) {
        const bool mixed = x >= kWidth / 2 - kShift && x < kWidth / 2;
        EXPECT_TRUE(mixed            ? isColour(x, 128, 128, 0)
                    : x < kWidth / 2 ? isColour(x, 255, 0, 0)
                                     : isColour(x, 0, 255, 0))
            << "column " << x << ": " << int(frame.pixel(x, kHeight / 2)[0]) << ", "
            << int(frame.pixel(x, kHeight / 2)[1]) << ", " << int(frame.pixel(x, kHeight / 2)[2]);
    }
}

// `float4 Points[24] : POINTS` from the vertex to the pixel shader, each element its own varying, beside a
// free-named vertex input array that takes no varying location: the objects are (0.25, 0.958, 0.5).
TEST(FxcFrontEnd, VaryingArraysUnderOneFreeName) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/d3d10/varying_arrays.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    ASSERT_TRUE(render(*loaded.renderer, *runtime::makeBuiltinScene("teapot"), 64, 48));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_GE(countPixelsOfColour(frame, 64, 48, 64, 244, 128), 64 * 48 / 20);
}

// A POSITION member beside an SV_POSITION one is user data between the stages, with a note: the objects
// are the (0.25, 0.5, 0.75) the vertex shader wrote, not the fragment's position. A vertex shader's input
// struct keeps its POSITION: the mesh is drawn.
TEST(FxcFrontEnd, PositionBesideSvPositionIsAVarying) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/d3d10/position_beside_sv_position.fx");
    ASSERT_TRUE(loaded.renderer) << loaded.diagnostics.str();
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::PositionBesideSvPosition), 1)
        << loaded.diagnostics.str();
    ASSERT_TRUE(render(*loaded.renderer, *runtime::makeBuiltinScene("teapot"), 64, 48));
    const runtime::FrameImage frame = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    EXPECT_GE(countPixelsOfColour(frame, 64, 48, 64, 128, 191), 64 * 48 / 20);
    ASSERT_TRUE(render(*loaded.renderer, *runtime::makeBuiltinScene("teapot"), 64, 48, "MeshInput"));
    EXPECT_GE(countPixelsOfColour(loaded.renderer->readFrame(), 64, 48, 191, 128, 64), 64 * 48 / 20);
}

// ClearSetColor naming no parameter, `Clear=` and RenderColorTarget0 naming a plain texture: three
// warnings, and the pass (named `P0`, scripted `Pass=p0`) draws into the frame.
TEST(FxcFrontEnd, ScriptCommandsFxComposerTolerated) {
    LoadedEffect loaded = loadEffectWithDiagnostics("tests/data/fxcomposer/tolerated_script.fx");
    ASSERT_TRUE(loaded.renderer);
    const fx::DiagId ignored[] = {fx::DiagId::ScriptClearValueIgnored, fx::DiagId::ScriptClearNamesNoBuffer,
                                  fx::DiagId::ScriptColorTargetNotTarget};
    for (fx::DiagId id : ignored)
        EXPECT_EQ(countDiagnostics(loaded.diagnostics, id), 1) << loaded.diagnostics.str();
    for (const fx::Diagnostic& d : loaded.diagnostics.items())
        if (std::find(std::begin(ignored), std::end(ignored), d.id) != std::end(ignored)) {
            EXPECT_EQ(d.severity, fx::Severity::Warning);
            EXPECT_EQ(d.loc.file, "tests/data/fxcomposer/tolerated_script.fx");
            EXPECT_GE(d.loc.line, 28);
            EXPECT_LE(d.loc.line, 30);
        }
    const runtime::Scene scene = *runtime::makeBuiltinScene("teapot");
    ASSERT_TRUE(render(*loaded.renderer, scene, 96, 72));
    EXPECT_TRUE(drawsEveryChannel(loaded.renderer->readFrame()));
}

}  // namespace
}  // namespace shadowfx::test::test_fxc_front_end
