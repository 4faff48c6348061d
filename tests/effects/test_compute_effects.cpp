// Compute passes and read-write resources through the real pipeline (docs/d3d10.md, "Compute shaders and
// read-write resources"): a RWStructuredBuffer particle state advanced by a compute pass and drawn through a
// StructuredBuffer view of it, frame after frame, by the SAS host's Dispatch= and by the pass API's
// dispatch(); a RWTexture2D written by a compute pass and sampled by a pixel shader; a groupshared
// reduction into a RWByteAddressBuffer; an AppendStructuredBuffer and a ConsumeStructuredBuffer view of it
// whose counter persists between frames; RWTexture1D, RWTexture3D, RWTexture2DArray and RWBuffer read
// through their views; a host file's step dispatching a compute pass.
#include "EffectHarness.h"

#include <fx/EffectFile.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectPass.h>
#include <runtime/HostFileReader.h>

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace shadowfx::test::test_compute_effects {
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

// The same particles driven by a host file, as an FX11 application drives them: a step applies the compute
// pass and dispatches it, its group count from the parameter GroupCount, and a step draws; two frames put
// the particles two steps up. Without the dispatch they would never be born (age 0 draws nothing).
TEST(ComputeEffects, AHostFileStepDispatchesAComputePass) {
    const std::string text = R"({
  "frame": [{"technique": "Particles", "pass": "Advance", "dispatch": ["GroupCount", 1, 1]},
            {"technique": "Particles", "pass": "Draw", "draw": "nothing", "clear": {"color": [0, 0, 0, 1]}},
            {"technique": "Particles", "pass": "Draw", "draw": "quad"}]
})";
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host = runtime::parseHostJson(text, "h.json", diagnostics);
    ASSERT_TRUE(host) << diagnostics.str();
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_particles.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    for (int frame = 1; frame <= 2; ++frame) ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    for (int index : {0, 7, 15}) {
        const auto [x, y] = particlePixel(index, 2);
        EXPECT_EQ(frame.pixel(x, y)[0], 255) << "particle " << index;
        EXPECT_NEAR(frame.pixel(x, y)[1], 51, 1) << "particle " << index;
    }
}

TEST(ComputeEffects, AHostFileDispatchIsCheckedAtItsLineAndAgainstTheEffect) {
    const std::string text = R"({
  "frame": [{"technique": "Particles", "pass": "Advance",
             "dispatch": [1, 2, 3, 4]},
            {"technique": "Particles", "pass": "Advance", "dispatch": ["NoSuchCount"]}]
})";
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(runtime::parseHostJson(text, "h.json", diagnostics));
    ASSERT_EQ(countDiagnostics(diagnostics, fx::DiagId::HostStepDispatchInvalid), 1) << diagnostics.str();
    EXPECT_EQ(diagnostics.items()[0].loc.line, 3);
    fx::DiagnosticList checked;
    std::shared_ptr<const fx::HostFile> host = runtime::parseHostJson(
        R"({"frame": [{"technique": "Particles", "dispatch": ["NoSuchCount"]}]})", "h.json", checked);
    ASSERT_TRUE(host) << checked.str();
    sharedContext();
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/d3d10/compute_particles.fx"), {}, {}, checked);
    ASSERT_TRUE(compiled) << checked.str();
    EXPECT_FALSE(fx::checkHostFile(*host, *compiled, checked));
    EXPECT_EQ(countDiagnostics(checked, fx::DiagId::HostParameterUnknown), 1) << checked.str();
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

// Two RWStructuredBuffer<uint> written differently by one compute shader and read by one pixel shader
// (and one of them by the vertex shader): each reaches its own buffer, bound by its parameter (blocks of
// one element type share one SPIR-V type, whose GLSL names are not the buffers'). A frame that is blank,
// or whose buffers alias (one value in every channel), fails.
TEST(ComputeEffects, TwoReadWriteBuffersOfOneElementTypeInOneShaderReachTheirOwnBuffers) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_same_type_buffers.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    for (const auto& [x, y] : {std::pair{3, 3}, std::pair{kWidth / 2, kHeight / 2}}) {
        const uint8_t* p = frame.pixel(x, y);
        EXPECT_EQ(p[0], 64) << x << "," << y;
        EXPECT_EQ(p[1], 192) << x << "," << y;
        EXPECT_EQ(p[2], 192) << x << "," << y;
    }
}

// The centre of cell `cell` of tests/data/d3d10/compute_append_consume.fx's 8 x 8 grid.
const uint8_t* cellPixel(const runtime::FrameImage& frame, int cell) {
    return frame.pixel((cell % 8) * kWidth / 8 + kWidth / 16, (cell / 8) * kHeight / 8 + kHeight / 16);
}

// The cells of the first 63 whose element holds a spark (red on).
int sparkCells(const runtime::FrameImage& frame) {
    int lit = 0;
    for (int cell = 0; cell < 63; ++cell) lit += cellPixel(frame, cell)[0] == 255;
    return lit;
}

// Eight sparks appended and one consumed a frame, through a counter that persists: 7n + 1 cells lit
// after frame n, the lit ones first (a counter reset each frame lights 8 cells, one never decremented 8n);
// the consumed spark's Tag (1..8) shows in the last cell.
TEST(ComputeEffects, AppendAndConsumeBuffersKeepTheirCounterBetweenFrames) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_append_consume.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene teapot = scene("teapot");  // not drawn: the sparks are the buffer's
    for (int frame = 1; frame <= 3; ++frame) {
        ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
        const runtime::FrameImage image = renderer->readFrame();
        EXPECT_EQ(sparkCells(image), 7 * frame + 1) << "frame " << frame;
        EXPECT_EQ(cellPixel(image, 7 * frame)[0], 255) << "frame " << frame;
        EXPECT_TRUE(isBlack(cellPixel(image, 7 * frame + 1))) << "frame " << frame;
        const int tag = cellPixel(image, 63)[2] * 8 / 255;
        EXPECT_GE(tag, 1) << "frame " << frame;
        EXPECT_LE(tag, 8) << "frame " << frame;
    }
}

// An application's elements set the counter to their number (D3D11's initial count for the view it binds
// them through): three elements of Tag 0.5, then a frame appends eight after them and consumes one.
TEST(ComputeEffects, SettingAnAppendBufferSetsItsCounter) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_append_consume.fx"), true);
    ASSERT_TRUE(renderer);
    float sparks[3][3] = {{0, 0, 0.5f}, {0, 0, 0.5f}, {0, 0, 0.5f}};  // D3D's packing: 12 bytes
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(
        renderer->setBuffer(*renderer->findParameter("Live"), sparks, 3, sizeof sparks[0], diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage image = renderer->readFrame();
    EXPECT_EQ(sparkCells(image), 3 + 8);
    for (int cell = 0; cell < 3; ++cell) EXPECT_NEAR(cellPixel(image, cell)[1], 16, 1) << cell;
    EXPECT_GE(cellPixel(image, 3)[1], 31);  // an appended spark: Tag 1..8
}

// One compute pass writes an RWTexture1D, an RWTexture3D, an RWTexture2DArray and an RWBuffer; a pixel
// shader reads each through its view, a band of the frame per resource, eight columns a band.
TEST(ComputeEffects, ReadWriteTexturesOfEveryKindAndRWBuffersReachTheirViews) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_image_kinds.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(notConstant(frame));
    const auto expect = [&](int band, int column, float r, float g, float b) {
        const uint8_t* p = frame.pixel(column * kWidth / 8 + kWidth / 16, band * kHeight / 4 + kHeight / 8);
        EXPECT_NEAR(p[0], r * 255, 1) << "band " << band << " column " << column;
        EXPECT_NEAR(p[1], g * 255, 1) << "band " << band << " column " << column;
        EXPECT_NEAR(p[2], b * 255, 1) << "band " << band << " column " << column;
    };
    for (int c = 0; c < 8; ++c) {
        expect(0, c, c / 7.0f, 0, 0);
        expect(1, c, (c % 4) / 3.0f, (c / 4) / 3.0f, 1);
        const float layer = (c / 4 + 2) / 4.0f;
        expect(2, c, layer, layer, layer);
        expect(3, c, 0, 0, c / 7.0f);
    }
}

// A pass that sets both kinds of shader: its script's Dispatch= runs the compute stage and its Draw= the
// graphics stages, frame after frame; the application may dispatch it too (FX11's Apply, Dispatch) and
// still draw with it afterwards. The frame is the colour accumulated: (0.1 n, 0.2 n, 0.5) after n steps.
TEST(ComputeEffects, APassWithComputeAndGraphicsShadersDispatchesOneAndDrawsTheOther) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/compute_and_draw.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene teapot = scene("teapot");
    const auto expect = [&](int steps) {
        const runtime::FrameImage frame = renderer->readFrame();
        for (const auto& [x, y] : {std::pair{0, 0}, std::pair{kWidth / 2, kHeight / 2}}) {
            const uint8_t* p = frame.pixel(x, y);
            EXPECT_NEAR(p[0], 0.1 * steps * 255, 1) << steps << " steps";
            EXPECT_NEAR(p[1], 0.2 * steps * 255, 1) << steps << " steps";
            EXPECT_NEAR(p[2], 128, 1) << steps << " steps";
        }
    };
    ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    expect(1);
    ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    expect(2);
    runtime::EffectPass both = renderer->technique("StepAndShow").pass("Both");
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(both.apply(&diagnostics)) << diagnostics.str();
    ASSERT_TRUE(both.dispatch(1, 1, 1, &diagnostics)) << diagnostics.str();
    ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    expect(4);
}

}  // namespace
}  // namespace shadowfx::test::test_compute_effects
