// Host files (fx/HostFile.h, runtime/HostFileReader.h, docs/host-files.md): an effect written for an
// application, with no SAS script and no semantics, drawn as its application drew it: the host file's shadow
// map, matrices from the scene's camera and light, a shadow technique into the map and then a scene technique
// into the frame, through the pass API. Its shadow shows in the pixels and is scored against the ray-cast
// truth; a broken host file is an error at its line and column.
#include "effects/EffectHarness.h"

#include <fx/EffectFile.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectRenderer.h>
#include <runtime/HostFileReader.h>
#include <runtime/ShadowMeasurement.h>

#include <gtest/gtest.h>

namespace test_host_files {

namespace {

using shadowfx::test::luminance;
using shadowfx::test::notConstant;
using shadowfx::test::sharedContext;
using shadowfx::test::sourcePath;

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// The test effect, compiled as `bench` compiles its variants (fx/EffectFile.h records the definitions
// the host frame reads), with the host file set.
std::unique_ptr<runtime::EffectRenderer> hostedEffect(bool visibility) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parse;
    if (visibility) parse.defines = {{"SHADOWFX_VISIBILITY", "1"}};
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/host/app_shadow.fx"), parse, {}, diagnostics);
    std::shared_ptr<const fx::HostFile> host =
        runtime::loadHostFile(sourcePath("tests/data/host/app_shadow.json"), diagnostics);
    std::unique_ptr<runtime::EffectRenderer> renderer =
        compiled && host ? runtime::EffectRenderer::create(compiled, diagnostics) : nullptr;
    if (!renderer || !renderer->setHostFile(host, diagnostics) || diagnostics.hasErrors()) {
        ADD_FAILURE() << diagnostics.str();
        return nullptr;
    }
    return renderer;
}

// The truth of the torus scene (a spot light): which pixels are receivers and which of them are shadowed.
const runtime::SceneTruth& torusTruth() {
    static runtime::SceneTruth truth;
    static bool measured = false;
    if (!measured) {
        sharedContext();
        fx::DiagnosticList diagnostics;
        std::string error;
        EXPECT_TRUE(runtime::measureSceneTruth(truth, *runtime::makeBuiltinScene("torus"), kWidth, kHeight,
                                               {}, diagnostics, error))
            << error << diagnostics.str();
        measured = true;
    }
    return truth;
}

TEST(HostFiles, ShadowedReceiversAreDarkerThanLitOnes) {
    std::unique_ptr<runtime::EffectRenderer> renderer = hostedEffect(false);
    ASSERT_TRUE(renderer);
    const runtime::SceneTruth& t = torusTruth();
    ASSERT_TRUE(shadowfx::test::render(*renderer, t.scene, kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    ASSERT_TRUE(notConstant(frame));
    // The mean brightness of receivers the truth calls shadowed against those it calls lit: a blank or
    // constant frame gives the same for both, a frame without the shadow map nearly the same.
    double shadowed = 0.0, lit = 0.0;
    size_t shadowedCount = 0, litCount = 0;
    for (size_t i = 0; i < t.receivers.size(); ++i) {
        if (!t.receivers[i]) continue;
        const float y = luminance(&frame.rgba[i * 4]);
        if (t.truth.visibility[i] < runtime::kShadowedBelow) {
            shadowed += y;
            ++shadowedCount;
        } else {
            lit += y;
            ++litCount;
        }
    }
    ASSERT_GT(shadowedCount, 100u);
    ASSERT_GT(litCount, 100u);
    EXPECT_LT(shadowed / shadowedCount, 0.6 * (lit / litCount))
        << "shadowed " << shadowed / shadowedCount << ", lit " << lit / litCount;
}

TEST(HostFiles, VisibilityFrameScoresAgainstTheTruth) {
    std::unique_ptr<runtime::EffectRenderer> renderer = hostedEffect(true);
    ASSERT_TRUE(renderer);
    const runtime::SceneTruth& t = torusTruth();
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = kWidth;
    options.height = kHeight;
    const std::optional<runtime::VisibilityScore> score =
        runtime::scoreVisibility(*renderer, t, t.truth, options, diagnostics);
    ASSERT_TRUE(score) << diagnostics.str();
    // A frame lit everywhere misclassifies every shadowed receiver (2 % of them here); the host frame's
    // shadow factor gets all but a few contour pixels right.
    const runtime::ShadowErrors allLit = runtime::compareVisibility(
        t.truth.visibility, std::vector<float>(t.truth.visibility.size(), 1.0f), t.receivers);
    EXPECT_GT(allLit.misclassifiedPercent, 1.5);
    EXPECT_LT(score->errors.misclassifiedPercent, 0.25 * allLit.misclassifiedPercent)
        << score->errors.misclassifiedPercent;
}

// [SECTION] Errors at the host file's line and column

::testing::AssertionResult reportsAt(const fx::DiagnosticList& diagnostics, fx::DiagId id, int line,
                                     int column, const std::string& words) {
    for (const fx::Diagnostic& d : diagnostics.items())
        if (d.id == id && d.loc.line == line && d.loc.column == column &&
            d.message.find(words) != std::string::npos)
            return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "expected " << line << ":" << column << " '" << words << "', got:\n"
           << diagnostics.str();
}

TEST(HostFiles, InvalidJsonIsLocated) {
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(
        runtime::parseHostJson("{\n  \"frame\": [\n    {\"technique\": }\n  ]\n}\n", "h.json", diagnostics));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::SceneSyntaxError, 3, 19, "invalid JSON"));
}

TEST(HostFiles, WrongValuesAreLocatedAtTheValue) {
    const std::string text = R"({
  "targets": {"Map": {"format": "D24S8", "size": [512, 0]}},
  "parameters": {"g_m": "WorldViewSideways", "g_n": ["World", 1]},
  "frame": [
    {"technique": "T", "target": "Nowhere", "draw": "everything"}
  ]
})";
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(runtime::parseHostJson(text, "h.json", diagnostics));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostTargetFormatInvalid, 2, 33, "not a colour format"));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostTargetSizeInvalid, 2, 50, "whole numbers"));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostValueUnknown, 3, 25, "'WorldViewSideways' is not"));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostProductNotMatrix, 3, 63, "matrices only"));
    EXPECT_TRUE(
        reportsAt(diagnostics, fx::DiagId::HostStepUnknownTarget, 5, 34, "no target named 'Nowhere'"));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostStepDrawInvalid, 5, 53, "\"geometry\""));
}

TEST(HostFiles, NamesTheEffectLacksAreLocatedAtTheFile) {
    const std::string text = R"({
  "parameters": {"g_mWorld": "World", "g_missing": "World", "g_fBias": [1, 2]},
  "frame": [{"technique": "RenderScene"}, {"technique": "RenderNothing"}]
})";
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host = runtime::parseHostJson(text, "h.json", diagnostics);
    ASSERT_TRUE(host) << diagnostics.str();
    sharedContext();
    fx::ParseOptions parse;
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/host/app_shadow.fx"), parse, {}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    EXPECT_FALSE(renderer->setHostFile(host, diagnostics));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostParameterUnknown, 2, 52, "no parameter 'g_missing'"));
    EXPECT_TRUE(reportsAt(diagnostics, fx::DiagId::HostValueSizeMismatch, 2, 72, "does not fit"));
    EXPECT_TRUE(
        reportsAt(diagnostics, fx::DiagId::HostStepTechniqueUnknown, 3, 43, "no technique 'RenderNothing'"));
}

}  // namespace
}  // namespace test_host_files
