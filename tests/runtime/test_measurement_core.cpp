// The measurement core the shadowfx tools share (runtime/measure): the diagnostics log, number formats,
// the non-finite checks and the compiled variants of an effect.
#include "effects/EffectHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/NonFiniteScan.h>
#include <report/NumberFormat.h>
#include <runtime/ShadowMeasurement.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace test_measurement_core {

namespace {

fx::Diagnostic error(const std::string& message, int line) {
    return {fx::DiagId::PreprocessorError, fx::Severity::Error, {"a.fx", line, 3}, message};
}

TEST(DiagnosticLog, ShowsEachDistinctDiagnosticOnceAndKeepsErrorsSinceMark) {
    std::vector<std::string> shown;
    runtime::DiagnosticLog log([&](const std::string& text) { shown.push_back(text); });
    log.report(error("first", 1));
    log.report(error("first", 1));  // the same again: counted, not shown again
    log.report({fx::DiagId::PreprocessorError, fx::Severity::Note, {"a.fx", 2, 1}, "a note"});
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown[0], "a.fx:1:3: error: first");
    EXPECT_EQ(log.errors(), 2);
    EXPECT_TRUE(log.failed());
    EXPECT_EQ(log.firstError("none"), "a.fx:1:3: error: first");
    log.mark();
    EXPECT_FALSE(log.failed());
    EXPECT_EQ(log.firstError("none"), "none");
    EXPECT_EQ(log.errors(), 2);
}

TEST(DiagnosticLog, TakeErrorsJoinsTheFirstFourAndMarks) {
    runtime::DiagnosticLog log;
    for (int i = 1; i <= 6; ++i) log.report(error("e" + std::to_string(i), i));
    EXPECT_EQ(log.takeErrors(),
              "a.fx:1:3: error: e1; a.fx:2:3: error: e2; a.fx:3:3: error: e3; a.fx:4:3: error: e4");
    EXPECT_FALSE(log.failed());
    EXPECT_EQ(log.takeErrors(), "");
}

TEST(NumberFormat, FixedDigitsAndPercentPrecision) {
    EXPECT_EQ(report::formatFixed(0.125, 3), "0.125");
    EXPECT_EQ(report::formatFixed(2.0, 2), "2.00");
    EXPECT_EQ(report::formatPercent(0.0421), "0.042%");
    EXPECT_EQ(report::formatPercent(12.54), "12.5%");
}

TEST(NonFiniteScan, MatrixWithNanOrInfIsNotFinite) {
    glm::mat4 m(1.0f);
    EXPECT_TRUE(runtime::isFinite(m));
    m[2][3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(runtime::isFinite(m));
    m[2][3] = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(runtime::isFinite(m));
}

// The scan reads every texture into one buffer, the larger first here: the smaller one's infinite texel is
// found at its own coordinates, and nothing of the larger one's samples is read as the smaller one's.
TEST(NonFiniteScan, FindsTheInfiniteTexelOfASmallerTargetReadAfterALargerOne) {
    shadowfx::test::sharedContext();
    const std::string source = R"(float Divisor = 0.0;
texture Large : RENDERCOLORTARGET < float2 Dimensions = {64, 32}; string Format = "A32B32G32R32F"; >;
texture Small : RENDERCOLORTARGET < float2 Dimensions = {4, 2}; string Format = "R32F"; >;
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
float4 FinitePS(float2 uv : TEXCOORD0) : COLOR { return float4(uv, 1, 1); }
float4 CornerPS(float2 uv : TEXCOORD0) : COLOR { return uv.x > 0.75 && uv.y > 0.5 ? 1.0 / Divisor : 0.5; }
technique t {
    pass large < string Script = "RenderColorTarget0=Large; Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 FinitePS(); }
    pass small < string Script = "RenderColorTarget0=Small; Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 CornerPS(); }
})";
    auto renderer = shadowfx::test::loadEffect(source, false, "non_finite.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    ASSERT_TRUE(shadowfx::test::render(*renderer, scene, 16, 16, "", {"Large", "Small"}));
    const std::optional<runtime::NonFiniteTexels> found =
        runtime::findNonFiniteTexels(*renderer, runtime::TextureScan::RenderTargets);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->texture, "Small");
    EXPECT_EQ(found->count, 1u);
    EXPECT_EQ(found->x, 3);
    EXPECT_EQ(found->y, 1);

    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("Divisor", "2", diagnostics)) << diagnostics.str();
    ASSERT_TRUE(shadowfx::test::render(*renderer, scene, 16, 16, "", {"Large", "Small"}));
    EXPECT_FALSE(runtime::findNonFiniteTexels(*renderer, runtime::TextureScan::RenderTargets));
}

TEST(ShadowMeasurement, VisibilityVariantChangesTheFragmentShaderOfAnEffectThatExposesIt) {
    fx::DiagnosticList diagnostics;
    auto shaded = runtime::compileVariant("effects/pcf.fx", {}, {}, diagnostics, "bilinear");
    auto visibility = runtime::compileVariant("effects/pcf.fx", {}, {{"SHADOWFX_VISIBILITY", "1"}},
                                              diagnostics, "bilinear");
    ASSERT_TRUE(shaded && visibility);
    EXPECT_TRUE(runtime::sameFragmentShaders(*shaded, *shaded));
    EXPECT_FALSE(runtime::sameFragmentShaders(*shaded, *visibility));
    auto plain = runtime::compileVariant("effects/plain_lit.fx", {}, {}, diagnostics);
    auto plainVisibility =
        runtime::compileVariant("effects/plain_lit.fx", {}, {{"SHADOWFX_VISIBILITY", "1"}}, diagnostics);
    ASSERT_TRUE(plain && plainVisibility);
    EXPECT_TRUE(runtime::sameFragmentShaders(*plain, *plainVisibility));  // no shadow term to expose
}

}  // namespace
}  // namespace test_measurement_core
