// Compute passes and read-write resources through the real pipeline (docs/d3d10.md, "Compute shaders and
// read-write resources"): a RWStructuredBuffer particle state advanced by a compute pass and drawn through a
// StructuredBuffer view of it, frame after frame, by the SAS host's Dispatch= and by the pass API's
// dispatch(); a RWTexture2D written by a compute pass and sampled by a pixel shader; a groupshared
// reduction into a RWByteAddressBuffer.
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPass.h>

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace shadowfx::test {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

runtime::Scene scene(const char* name) {
    auto s = runtime::makeBuiltinScene(name, nullptr);
    if (!s) throw std::runtime_error(std::string("no scene ") + name);
    return std::move(*s);
}

// Where tests/data/d3d10/compute_particles.fx draws particle `index` after `frames` dispatches.
std::pair<int, int> particlePixel(int index, int frames) {
    const float x = -0.75f + 0.1f * static_cast<float>(index), y = -0.8f + 0.1f * static_cast<float>(frames);
    return {static_cast<int>((x + 1) / 2 * kWidth), static_cast<int>((1 - y) / 2 * kHeight)};
}

bool isBlack(const uint8_t* p) {
    return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

// Frame 1 shows the sixteen particles one step above their start, green 0.1; frame 10 ten steps up, green
// 1.0, where frame 1 was black; every other pixel keeps the clear colour (a blank or constant frame fails).
TEST(ComputeEffects, AComputePassAdvancesParticlesThatAGraphicsPassDraws) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_particles.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene teapot = scene("teapot");  // not drawn: the particles are the buffer's
    ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    const runtime::FrameImage first = renderer->readFrame();
    for (int frame = 2; frame <= 10; ++frame) ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    const runtime::FrameImage tenth = renderer->readFrame();
    EXPECT_TRUE(notConstant(first));
    EXPECT_TRUE(notConstant(tenth));
    for (int index = 0; index < 16; ++index) {
        const auto [x1, y1] = particlePixel(index, 1);
        const uint8_t* early = first.pixel(x1, y1);
        EXPECT_EQ(early[0], 255) << "particle " << index << " in frame 1";
        EXPECT_NEAR(early[1], 26, 1) << "particle " << index << " in frame 1";
        EXPECT_TRUE(isBlack(tenth.pixel(x1, y1))) << "particle " << index << " left its frame-1 place";
        const auto [x10, y10] = particlePixel(index, 10);
        const uint8_t* late = tenth.pixel(x10, y10);
        EXPECT_EQ(late[0], 255) << "particle " << index << " in frame 10";
        EXPECT_EQ(late[1], 255) << "particle " << index << " in frame 10";
        EXPECT_TRUE(isBlack(first.pixel(x10, y10))) << "particle " << index << " was already up in frame 1";
    }
    int lit = 0;
    for (size_t i = 0; i + 3 < tenth.rgba.size(); i += 4) lit += !isBlack(&tenth.rgba[i]);
    EXPECT_GT(lit, 16 * 15);  // sixteen dots of about 6 x 5 pixels
    EXPECT_LT(lit, 16 * 45);
}

// The same particles through the pass API: the application applies the compute pass and dispatches it
// itself (FX11's Apply and Dispatch), then lets the SAS host draw; three dispatches put the particles
// three steps up. Dispatching a drawing pass is refused with a located error.
TEST(ComputeEffects, TheApplicationDispatchesAComputePassThroughThePassApi) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_particles.fx"), true);
    ASSERT_TRUE(renderer);
    runtime::EffectTechnique technique = renderer->technique("Particles");
    runtime::EffectPass advance = technique.pass("Advance");
    ASSERT_TRUE(advance.isValid());
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(advance.apply(&diagnostics)) << diagnostics.str();
    for (int step = 0; step < 3; ++step)
        ASSERT_TRUE(advance.dispatch(1, 1, 1, &diagnostics)) << diagnostics.str();
    EXPECT_FALSE(technique.pass("Draw").dispatch(1, 1, 1, &diagnostics));
    ASSERT_EQ(diagnostics.items().size(), 1u) << diagnostics.str();
    EXPECT_EQ(diagnostics.items()[0].id, fx::DiagId::DispatchNotCompute);
    EXPECT_GT(diagnostics.items()[0].loc.line, 0);
    // The host's frame dispatches once more: four steps.
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    for (int index : {0, 7, 15}) {
        const auto [x, y] = particlePixel(index, 4);
        EXPECT_EQ(frame.pixel(x, y)[0], 255) << "particle " << index;
        EXPECT_NEAR(frame.pixel(x, y)[1], 102, 1) << "particle " << index;
        const auto [x1, y1] = particlePixel(index, 1);
        EXPECT_TRUE(isBlack(frame.pixel(x1, y1))) << "particle " << index;
    }
}

// What a compute pass writes into a RWTexture2D, a pixel shader samples through a Texture2D view: the
// image's gradient across the frame, checked at its corners and its middle (a blank frame fails).
TEST(ComputeEffects, AComputePassWritesAnImageThatAPixelShaderSamples) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_image.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(notConstant(frame));
    // Point sampling: frame pixel (px, py) shows texel (px * 32 / W, py * 16 / H).
    const auto expect = [&](int px, int py) {
        const int tx = px * 32 / kWidth, ty = py * 16 / kHeight;
        const uint8_t* p = frame.pixel(px, py);
        EXPECT_NEAR(p[0], tx * 255 / 31, 1) << px << "," << py;
        EXPECT_NEAR(p[1], ty * 255 / 15, 1) << px << "," << py;
        EXPECT_NEAR(p[2], 128, 1) << px << "," << py;
    };
    expect(0, 0);
    expect(kWidth - 1, 0);
    expect(0, kHeight - 1);
    expect(kWidth - 1, kHeight - 1);
    expect(kWidth / 2 + 3, kHeight / 2 + 3);
}

// A groupshared reduction stored into a RWByteAddressBuffer, read by a pixel shader through a
// ByteAddressBuffer view: the sum's colour left of x = 8 (blue on) and right of it (blue off).
TEST(ComputeEffects, AGroupsharedReductionReachesAPixelShaderThroughAByteAddressBuffer) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_groupshared.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    for (const auto& [x, y, blue] : {std::tuple{2, 5, 255}, std::tuple{kWidth - 3, kHeight - 4, 0}}) {
        const uint8_t* p = frame.pixel(x, y);
        EXPECT_EQ(p[0], 255) << x << "," << y;
        EXPECT_NEAR(p[1], 128, 1) << x << "," << y;
        EXPECT_EQ(p[2], blue) << x << "," << y;
    }
}

}  // namespace
}  // namespace shadowfx::test
