// The hand-written GL baseline of bench_per_draw_cost (benchmarks/HandWrittenFrame.h) must draw the frame
// shadowfx draws, or its ratios mean nothing: the same image byte for byte (its matrices are composed in
// the runtime's order) and the same objects drawn per pass, on several scenes; with batching on (the
// default), so the batched frame is held to the one drawn object by object too.
#include "HandWrittenFrame.h"
#include "effects/EffectHarness.h"
#include "LeaveOutFrames.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>

#include <gtest/gtest.h>

namespace test_handwritten_frame {

namespace {

using shadowfx::test::differingPixels;
using shadowfx::test::findPass;
using shadowfx::test::notConstant;
using shadowfx::test::sourcePath;

class HandWrittenFrame : public ::testing::TestWithParam<const char*> {};

TEST_P(HandWrittenFrame, DrawsTheFrameShadowfxDraws) {
    shadowfx::test::sharedContext();
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene(GetParam());
    ASSERT_TRUE(scene);
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parse;
    parse.defines = {{"SHADOWFX_SHADOW_MAP_SIZE", "512"}};
    auto effect = fx::parseEffectFile(sourcePath("effects/thesis_fxcomposer.fx"), parse, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    std::string error;
    auto hand = shadowfx::baseline::HandWrittenFrame::create(*compiled, *scene, 160, 120, error);
    ASSERT_TRUE(hand) << error;

    runtime::FrameOptions options;
    options.width = 160;
    options.height = 120;
    options.technique = "main";
    options.reuseTargets = false;  // the baseline draws its map every frame
    runtime::FrameStats stats;
    ASSERT_TRUE(renderer->render(*scene, options, diagnostics, &stats)) << diagnostics.str();
    const runtime::FrameImage expected = renderer->readFrame();
    hand->render(*scene);
    const runtime::FrameImage actual = hand->readFrame();

    EXPECT_TRUE(notConstant(actual));
    const size_t differing = differingPixels(expected, actual);
    EXPECT_EQ(differing, 0u) << "of " << expected.rgba.size() / 4 << " pixels";
    ASSERT_TRUE(findPass(stats, "RenderShadowMap") && findPass(stats, "RenderScene"));
    EXPECT_EQ(hand->shadowDraws(), findPass(stats, "RenderShadowMap")->objects);
    EXPECT_EQ(hand->sceneDraws(), findPass(stats, "RenderScene")->objects);
    EXPECT_GT(hand->shadowDraws(), 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, HandWrittenFrame, ::testing::Values("boxes", "teapot", "dual-l"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace test_handwritten_frame
