// Layered render targets (docs/d3d10.md, "Layered render targets"): a geometry shader's
// SV_RenderTargetArrayIndex (gl_Layer) chooses the face, element or slice of a target bound whole. A cube
// map rendered in one pass as the SDK's samples render one, its application a host file; a Texture2DArray,
// a Texture2DMSArray and a Texture3D named by pass scripts. Each layer a pass draws shows its colour in
// the frame and each layer it does not draw shows the clear colour, so a blank target fails.
#include "effects/EffectHarness.h"

#include <fx/EffectFile.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/HostFileReader.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>

namespace shadowfx::test::test_layered_targets {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 32;

runtime::Scene boxes() {
    return std::move(*runtime::makeBuiltinScene("boxes", nullptr));
}

// The colour at the middle of band `band` of `bands` equal bands from left to right, on the middle row.
std::array<int, 3> bandColour(const runtime::FrameImage& frame, int band, int bands) {
    const int x = (2 * band + 1) * frame.width / (2 * bands);
    const uint8_t* p = frame.pixel(x, frame.height / 2);
    return {p[0], p[1], p[2]};
}

// Every pixel of band `band` is `colour` (within one 8-bit step).
::testing::AssertionResult bandIs(const runtime::FrameImage& frame, int band, int bands,
                                  std::array<int, 3> colour) {
    const int x0 = band * frame.width / bands, x1 = (band + 1) * frame.width / bands;
    for (int y = 0; y < frame.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(p[c] - colour[static_cast<size_t>(c)]) > 1)
                    return ::testing::AssertionFailure()
                           << "band " << band << " at (" << x << ", " << y << ") is (" << int(p[0]) << ", "
                           << int(p[1]) << ", " << int(p[2]) << ")";
        }
    return ::testing::AssertionSuccess();
}

// [SECTION] A cube map in one pass, through a host file

TEST(LayeredTargets, ACubeMapRenderedInOneGeometryShaderPassHasAllSixFaces) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/d3d10/cube_map_gs.fx"), {}, {}, diagnostics);
    std::shared_ptr<const fx::HostFile> host =
        runtime::loadHostFile(sourcePath("tests/data/d3d10/cube_map_gs.json"), diagnostics);
    ASSERT_TRUE(compiled && host) << diagnostics.str();
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer && renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    ASSERT_TRUE(render(*renderer, boxes(), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    // +X, -X, +Y, -Y, +Z, -Z: each face in the colour the geometry shader gave it; a face left blank is
    // black, and the pixel shader writes black where SV_RenderTargetArrayIndex is not the face drawn.
    const std::array<std::array<int, 3>, 6> faces = {
        {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {255, 0, 255}, {0, 255, 255}}};
    for (int face = 0; face < 6; ++face) EXPECT_TRUE(bandIs(frame, face, 6, faces[size_t(face)]));
}

::testing::AssertionResult reportedOnLine(const fx::DiagnosticList& diagnostics, fx::DiagId id, int line) {
    for (const fx::Diagnostic& d : diagnostics.items())
        if (d.id == id && d.loc.line == line) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "nothing of that id on line " << line << ":\n"
                                         << diagnostics.str();
}

TEST(LayeredTargets, HostTargetKindsAndLayersAreCheckedAtTheirLines) {
    const std::string text = R"({
  "targets": {"A": {"kind": "sphere"},
              "B": {"kind": "cube", "layers": 6},
              "C": {"kind": "array", "layers": 0}},
  "frame": [{"technique": "VisualizeCubeMap"}]
})";
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(runtime::parseHostJson(text, "h.json", diagnostics));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostTargetKindInvalid, 2));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostTargetLayersWithoutLayers, 3));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostTargetLayersInvalid, 4));
}

TEST(LayeredTargets, AHostTargetOfAnotherKindThanItsTextureIsAnErrorAtItsLine) {
    const std::string text = R"({
  "targets": {"EnvMap": {"kind": "array", "layers": 6, "texture": "g_txEnvMap"}},
  "frame": [{"technique": "VisualizeCubeMap", "draw": "quad"}]
})";
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::HostFile> host = runtime::parseHostJson(text, "h.json", diagnostics);
    sharedContext();
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/d3d10/cube_map_gs.fx"), {}, {}, diagnostics);
    ASSERT_TRUE(compiled && host) << diagnostics.str();
    EXPECT_FALSE(fx::checkHostFile(*host, *compiled, diagnostics));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostTargetTextureKindMismatch, 2));
}

// [SECTION] Arrays, multisample arrays and volumes named by pass scripts

// Four elements cleared to black, element 2 drawn green with its index in blue by the geometry shader's
// SV_RenderTargetArrayIndex; red is GetDimensions' element count / 4.
TEST(LayeredTargets, TheGeometryShaderChoosesTheTexture2DArrayElementDrawnInto) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/layered_targets.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, boxes(), kWidth, kHeight, "ArrayLayer"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(bandIs(frame, 0, 4, {255, 0, 0}));
    EXPECT_TRUE(bandIs(frame, 1, 4, {255, 0, 0}));
    EXPECT_TRUE(bandIs(frame, 2, 4, {255, 255, 128}));
    EXPECT_TRUE(bandIs(frame, 3, 4, {255, 0, 0}));
}

// Two elements of four samples cleared to blue, element 1 drawn: red is sample 3 of element 1, blue
// sample 0 of element 0, green GetDimensions' 2 elements of 4 samples.
TEST(LayeredTargets, ATexture2DMSArrayIsDrawnByLayerAndLoadedBySample) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/layered_targets.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, boxes(), kWidth, kHeight, "MultisampleArray"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_EQ(countPixelsOfColour(frame, kWidth, kHeight, 255, 255, 255), kWidth * kHeight)
        << "middle pixel: " << bandColour(frame, 0, 1)[0] << ", " << bandColour(frame, 0, 1)[1] << ", "
        << bandColour(frame, 0, 1)[2];
}

// A 16x16x4 volume cleared to black, slice 2 drawn: the frame's third band green with blue 0.5.
TEST(LayeredTargets, TheGeometryShaderChoosesTheTexture3DSliceDrawnInto) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/layered_targets.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, boxes(), kWidth, kHeight, "VolumeSlice"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(bandIs(frame, 0, 4, {0, 0, 0}));
    EXPECT_TRUE(bandIs(frame, 1, 4, {0, 0, 0}));
    EXPECT_TRUE(bandIs(frame, 2, 4, {255, 128, 0}));
    EXPECT_TRUE(bandIs(frame, 3, 4, {0, 0, 0}));
}

// [SECTION] Several viewports and primitive ids

// The effect through a host file's frame: the file's text, or viewport_index.json.
runtime::FrameImage hostFrame(const std::string& hostText) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::loadEffectFile(sourcePath("tests/data/d3d10/viewport_index.fx"), {}, {}, diagnostics);
    std::shared_ptr<const fx::HostFile> host =
        hostText.empty()
            ? runtime::loadHostFile(sourcePath("tests/data/d3d10/viewport_index.json"), diagnostics)
            : runtime::parseHostJson(hostText, "h.json", diagnostics);
    EXPECT_TRUE(compiled && host) << diagnostics.str();
    if (!compiled || !host) return {};
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    EXPECT_TRUE(renderer && renderer->setHostFile(host, diagnostics)) << diagnostics.str();
    if (!renderer) return {};
    EXPECT_TRUE(render(*renderer, boxes(), kWidth, kHeight));
    return renderer->readFrame();
}

// Every pixel of the rectangle [x0, x1) x [y0, y1) is `colour`.
::testing::AssertionResult rectIs(const runtime::FrameImage& frame, int x0, int y0, int x1, int y1,
                                  std::array<int, 3> colour) {
    if (frame.width != kWidth || frame.height != kHeight) return ::testing::AssertionFailure() << "no frame";
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(p[c] - colour[static_cast<size_t>(c)]) > 1)
                    return ::testing::AssertionFailure() << "(" << x << ", " << y << ") is (" << int(p[0])
                                                         << ", " << int(p[1]) << ", " << int(p[2]) << ")";
        }
    return ::testing::AssertionSuccess();
}

// Two viewports, the left half and the upper right quarter: the geometry shader draws the full-screen quad
// red into viewport 0 and green into viewport 1 (SV_ViewportArrayIndex), so the left half is red, the upper
// right green and the lower right keeps the clear colour. Without the viewports both copies would cover
// the frame; without the index both would go to viewport 0.
TEST(LayeredTargets, TheGeometryShaderChoosesTheViewportEachPrimitiveIsDrawnInto) {
    const runtime::FrameImage frame = hostFrame("");
    EXPECT_TRUE(rectIs(frame, 0, 0, kWidth / 2, kHeight, {255, 0, 0}));
    EXPECT_TRUE(rectIs(frame, kWidth / 2, 0, kWidth, kHeight / 2, {0, 255, 0}));
    EXPECT_TRUE(rectIs(frame, kWidth / 2, kHeight / 2, kWidth, kHeight, {0, 0, 0}));
}

TEST(LayeredTargets, HostViewportsAreCheckedAtTheirLine) {
    const std::string text = R"({
  "frame": [{"technique": "BothViewports",
             "viewports": [[0, 0, 48, 0]]},
            {"technique": "BothViewports", "viewports": [[0, 0, 48]]}]
})";
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(runtime::parseHostJson(text, "h.json", diagnostics));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostStepViewportsInvalid, 3));
    EXPECT_TRUE(reportedOnLine(diagnostics, fx::DiagId::HostStepViewportsInvalid, 4));
}

// The full-screen quad's first triangle (upper left, upper right, lower right) is primitive 0, its second
// primitive 1: the pixel shader colours them red and green by SV_PrimitiveID.
TEST(LayeredTargets, ThePixelShaderTellsPrimitivesApartBySvPrimitiveId) {
    const runtime::FrameImage frame = hostFrame(
        R"({"frame": [{"technique": "PrimitiveColours", "draw": "quad", "clear": {"color": [0, 0, 0, 1], "depth": 1}}]})");
    EXPECT_TRUE(rectIs(frame, kWidth - 8, 0, kWidth, 2, {255, 0, 0}));
    EXPECT_TRUE(rectIs(frame, 0, kHeight - 2, 8, kHeight, {0, 255, 0}));
}

// The geometry shader writes SV_PrimitiveID (each triangle the other's id) and the pixel shader reads what it
// wrote: the colours of the test above, swapped.
TEST(LayeredTargets, ThePixelShaderReadsTheSvPrimitiveIdTheGeometryShaderWrote) {
    const runtime::FrameImage frame = hostFrame(
        R"({"frame": [{"technique": "GeometryPrimitiveIds", "draw": "quad", "clear": {"color": [0, 0, 0, 1], "depth": 1}}]})");
    EXPECT_TRUE(rectIs(frame, kWidth - 8, 0, kWidth, 2, {0, 255, 0}));
    EXPECT_TRUE(rectIs(frame, 0, kHeight - 2, 8, kHeight, {255, 0, 0}));
}

}  // namespace
}  // namespace shadowfx::test::test_layered_targets
