// Shadow metrics (runtime/ShadowMetrics.h) on synthetic images whose answers are known by construction.
#include <runtime/ShadowMetrics.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace test_shadow_metrics {

namespace {

TEST(ShadowMetrics, KnownFalseShadowAndFalseLightCountsGiveTheirPercentages) {
    // 200 receivers: 100 lit and 100 shadowed in truth; the effect darkens 7 lit ones and lights 3 shadowed.
    std::vector<float> truth(250, 1.0f), effect(250, 1.0f);
    std::vector<uint8_t> receivers(250, 1);
    for (size_t i = 100; i < 200; ++i) truth[i] = effect[i] = 0.0f;
    for (size_t i = 0; i < 7; ++i) effect[i] = 0.0f;
    for (size_t i = 100; i < 103; ++i) effect[i] = 1.0f;
    // 50 pixels that do not count: 40 non-receivers with wrong answers, 10 background (truth -1).
    for (size_t i = 200; i < 240; ++i) receivers[i] = 0, effect[i] = 0.0f;
    for (size_t i = 240; i < 250; ++i) truth[i] = -1.0f, effect[i] = 0.0f;

    const runtime::ShadowErrors e = runtime::compareVisibility(truth, effect, receivers);
    EXPECT_EQ(e.receiverPixels, 200u);
    EXPECT_EQ(e.falseShadowPixels, 7u);
    EXPECT_EQ(e.falseLightPixels, 3u);
    EXPECT_DOUBLE_EQ(e.falseShadowPercent, 3.5);
    EXPECT_DOUBLE_EQ(e.falseLightPercent, 1.5);
    EXPECT_DOUBLE_EQ(e.misclassifiedPercent, 5.0);
    EXPECT_DOUBLE_EQ(e.meanAbsoluteError, 10.0 / 200.0);
    EXPECT_EQ(e.p95AbsoluteError, 0.0);  // exactly 95% of the receivers are right
}

TEST(ShadowMetrics, SoftErrorsGiveMeanAndPercentile) {
    // Truth 0.5 everywhere; effect 0.5 + k/100 for k = 0..99: errors 0.00 .. 0.99.
    std::vector<float> truth(100, 0.5f), effect(100);
    std::vector<uint8_t> receivers(100, 1);
    for (size_t k = 0; k < 100; ++k) effect[k] = std::min(1.0f, 0.5f + k / 200.0f);
    const runtime::ShadowErrors e = runtime::compareVisibility(truth, effect, receivers);
    EXPECT_NEAR(e.meanAbsoluteError, 99.0 / 2.0 / 200.0, 1e-6);
    EXPECT_NEAR(e.p95AbsoluteError, 94.0 / 200.0, 1e-6);  // nearest rank: the 95th smallest of 100
    EXPECT_EQ(e.falseShadowPixels, 0u);                   // 0.5 counts as lit on both sides
}

// The penumbra MAE averages over the pixels whose truth is partly lit only: 10 penumbra pixels off by 0.3
// among 90 exact umbra and lit ones give 0.3 there, 0.03 over all receivers.
TEST(ShadowMetrics, PenumbraErrorCountsOnlyPartlyLitTruth) {
    std::vector<float> truth(100), effect(100);
    std::vector<uint8_t> receivers(100, 1);
    for (size_t k = 0; k < 100; ++k) {
        truth[k] = k < 45 ? 0.0f : (k < 90 ? 1.0f : 0.4f);
        effect[k] = k < 90 ? truth[k] : 0.7f;
    }
    const runtime::ShadowErrors e = runtime::compareVisibility(truth, effect, receivers);
    EXPECT_EQ(e.penumbraPixels, 10u);
    EXPECT_NEAR(e.penumbraMeanAbsoluteError, 0.3, 1e-6);
    EXPECT_NEAR(e.meanAbsoluteError, 0.03, 1e-6);
    // Truth within 1% of lit or shadowed is not penumbra.
    std::fill(truth.begin() + 90, truth.end(), 0.995f);
    EXPECT_EQ(runtime::compareVisibility(truth, effect, receivers).penumbraPixels, 0u);
}

TEST(ShadowMetrics, ErrorImagePaintsFalseShadowRedFalseLightBlueOverGrey) {
    runtime::FrameImage frame;
    frame.width = 3;
    frame.height = 1;
    frame.rgba = {200, 100, 50, 255, 200, 100, 50, 255, 200, 100, 50, 255};
    const std::vector<float> truth{1.0f, 0.0f, 1.0f}, effect{0.0f, 1.0f, 1.0f};
    const runtime::FrameImage image = runtime::errorImage(frame, truth, effect, {1, 1, 1});
    EXPECT_EQ(image.pixel(0, 0)[0], 255);
    EXPECT_EQ(image.pixel(0, 0)[2], 0);
    EXPECT_EQ(image.pixel(1, 0)[0], 0);
    EXPECT_EQ(image.pixel(1, 0)[2], 255);
    EXPECT_EQ(image.pixel(2, 0)[0], image.pixel(2, 0)[1]);  // grey
    EXPECT_EQ(image.pixel(2, 0)[1], image.pixel(2, 0)[2]);
}

TEST(ShadowMetrics, ReceiverMaskKeepsCoveredPixelsFacingTheLight) {
    runtime::GBuffer gbuffer;
    gbuffer.width = 3;
    gbuffer.height = 1;
    gbuffer.position.assign(3, glm::vec3(0.0f));
    gbuffer.normal = {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0, 1, 0)};
    gbuffer.objectId = {1, 1, 0};
    runtime::Light light;  // directional, straight down
    EXPECT_EQ(runtime::receiverMask(gbuffer, light), (std::vector<uint8_t>{1, 0, 0}));
}

// A 64 x 64 G-buffer of the plane y = 0 seen head-on: every pixel steps 0.1 world units in x and z, from
// -`half` to just under 6.4 - `half`.
runtime::GBuffer planeGrid(float half = 3.2f) {
    runtime::GBuffer gbuffer;
    gbuffer.width = gbuffer.height = 64;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            gbuffer.position.emplace_back(x * 0.1f - half, 0.0f, y * 0.1f - half);
            gbuffer.normal.emplace_back(0.0f, 1.0f, 0.0f);
            gbuffer.objectId.push_back(1);
        }
    return gbuffer;
}

// A plane seen head-on by an orthographic-like grid: every pixel steps 0.1 world units in x and z, and a
// directional light straight down maps 2 * radius world units onto mapSize texels. One texel therefore
// covers (2 * radius / mapSize) / 0.1 pixels in both directions.
TEST(ShadowMetrics, TexelFootprintOfAUniformGridIsTheRatioOfTexelToPixelSize) {
    const runtime::GBuffer gbuffer = planeGrid();
    runtime::Bounds bounds{glm::vec3(-10.0f, -1.0f, -10.0f), glm::vec3(10.0f, 1.0f, 10.0f)};
    runtime::Light light;
    const std::vector<uint8_t> receivers(gbuffer.pixelCount(), 1);
    const int mapSize = 256;
    const runtime::AliasingMeasure m = runtime::perspectiveAliasing(gbuffer, receivers, light.view(bounds),
                                                                    light.projection(bounds), mapSize);
    const double expected = (2.0 * bounds.radius() / mapSize) / 0.1;
    EXPECT_EQ(m.pixels, gbuffer.pixelCount());
    EXPECT_NEAR(m.meanFootprint, expected, 1e-3 * expected);
    EXPECT_NEAR(m.maxFootprint, expected, 1e-3 * expected);
}

// Cascades: each receiver is measured in its own cascade's tile. One cascade over the whole atlas is the
// single map; with four cascades (2 x 2 tiles of half the size) whose far half of the plane (view depth
// beyond 0) uses a map of twice the world extent, the near half's texels are twice and the far half's
// four times the single map's footprint.
TEST(ShadowMetrics, CascadedFootprintUsesEachReceiversCascade) {
    const runtime::GBuffer gbuffer = planeGrid();
    runtime::Bounds bounds{glm::vec3(-10.0f, -1.0f, -10.0f), glm::vec3(10.0f, 1.0f, 10.0f)};
    runtime::Light light;
    const std::vector<uint8_t> receivers(gbuffer.pixelCount(), 1);
    const int mapSize = 256;
    const glm::mat4 cameraView =
        glm::lookAtLH(glm::vec3(0.0f, 0.0f, -10.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const double single = (2.0 * bounds.radius() / mapSize) / 0.1;
    const runtime::LightView whole{light.view(bounds), light.projection(bounds), 0.1f, 100.0f};
    const runtime::AliasingMeasure one =
        runtime::cascadedAliasing(gbuffer, receivers, cameraView, {whole}, mapSize);
    EXPECT_NEAR(one.meanFootprint, single, 1e-3 * single);

    runtime::LightView near = whole, wide = whole;
    near.splitFar = 10.0f;  // the view depth of z = 0
    wide.projection = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f)) * whole.projection;
    const runtime::AliasingMeasure four =
        runtime::cascadedAliasing(gbuffer, receivers, cameraView, {near, wide, wide, wide}, mapSize);
    EXPECT_EQ(four.pixels, gbuffer.pixelCount());  // beside the split, the neighbour on its own side serves
    EXPECT_NEAR(four.maxFootprint, 4.0 * single, 1e-3 * single);
    EXPECT_NEAR(four.meanFootprint, 3.0 * single, 0.05 * single);
}

// Cube faces: each receiver is measured in the face that faceSelect picks for it. A selection by the sign
// of world x, face 1 (x < 0) with a map of twice the world extent: its half of the plane has twice the
// footprint of the other half, whose footprint is that of six equal faces.
TEST(ShadowMetrics, CubeFaceFootprintUsesEachReceiversFace) {
    const runtime::GBuffer gbuffer = planeGrid(3.15f);  // no pixel on x = 0, where the face changes
    runtime::Bounds bounds{glm::vec3(-10.0f, -1.0f, -10.0f), glm::vec3(10.0f, 1.0f, 10.0f)};
    runtime::Light light;
    const std::vector<uint8_t> receivers(gbuffer.pixelCount(), 1);
    runtime::LightFit fit;
    fit.cubeFaces = true;
    fit.faceSelect = glm::mat4(0.0f);
    fit.faceSelect[0][0] = 1.0f;  // W = (x, 0, 0): face 0 for x > 0, face 1 for x < 0
    const runtime::LightView whole{light.view(bounds), light.projection(bounds), 0.0f, 0.0f, true};
    fit.cascades.assign(6, whole);
    const runtime::AliasingMeasure same = runtime::cubeFaceAliasing(gbuffer, receivers, fit, 256);
    EXPECT_EQ(same.pixels, gbuffer.pixelCount());
    EXPECT_NEAR(same.maxFootprint, same.meanFootprint, 1e-3 * same.meanFootprint);
    fit.cascades[1].projection = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f)) * whole.projection;
    const runtime::AliasingMeasure wide = runtime::cubeFaceAliasing(gbuffer, receivers, fit, 256);
    EXPECT_NEAR(wide.maxFootprint, 2.0 * same.meanFootprint, 1e-3 * same.meanFootprint);
    EXPECT_NEAR(wide.meanFootprint, 1.5 * same.meanFootprint, 1e-2 * same.meanFootprint);
}

}  // namespace

// The sampling-limited error of a fit: on the plane grid under a light straight down, truth shadowed where
// x < 0.05 (a boundary between pixel columns). Uniform truth or texels smaller than a pixel leave nothing
// for one sample per texel to get wrong; coarse texels straddle the boundary, and coarser ones more so.
TEST(ShadowMetrics, SamplingLimitedErrorComesFromTexelsStraddlingTheTruthsBoundary) {
    const runtime::GBuffer gbuffer = planeGrid();
    const runtime::Bounds bounds{glm::vec3(-10.0f, -1.0f, -10.0f), glm::vec3(10.0f, 1.0f, 10.0f)};
    runtime::Light light;
    runtime::LightFit fit;
    fit.view = light.view(bounds);
    fit.projection = light.projection(bounds);
    const std::vector<uint8_t> receivers(gbuffer.pixelCount(), 1);
    std::vector<float> truth(gbuffer.pixelCount(), 1.0f);
    const glm::mat4 camera(1.0f);
    EXPECT_EQ(runtime::samplingLimitedError(gbuffer, receivers, truth, camera, fit, 16), 0.0);

    for (size_t i = 0; i < truth.size(); ++i) truth[i] = gbuffer.position[i].x < 0.05f ? 0.0f : 1.0f;
    // 4096 texels over 2 * 14.2 world units: 0.007 units, under a pixel's 0.1.
    EXPECT_EQ(runtime::samplingLimitedError(gbuffer, receivers, truth, camera, fit, 4096), 0.0);
    // 16 texels: 1.8 units, 18 pixel columns; the boundary's texel column holds 18 rows of 64 / 18 texels.
    const double coarse = runtime::samplingLimitedError(gbuffer, receivers, truth, camera, fit, 16);
    EXPECT_GT(coarse, 0.0);
    EXPECT_LE(coarse, 100.0 * 18.0 / 64.0);  // at most the straddling column's pixels
    EXPECT_GT(runtime::samplingLimitedError(gbuffer, receivers, truth, camera, fit, 8), coarse);
    // Pixels that are not receivers do not count.
    const std::vector<uint8_t> none(gbuffer.pixelCount(), 0);
    EXPECT_EQ(runtime::samplingLimitedError(gbuffer, none, truth, camera, fit, 16), 0.0);
}
}  // namespace test_shadow_metrics
