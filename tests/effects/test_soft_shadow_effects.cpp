// The soft-shadow effects (effects/pcss.fx, effects/fractional_disk.fx, ...) against the geometry of a
// penumbra: the penumbra widens with the receiver-occluder distance as the similar triangles of Valient &
// de Boer 2004 say (q = (d2 / d1) r), measured on a plate held at two heights over a ground plane; the
// shader's q is the CPU's; fractional-disk's preprocessed map holds, per texel, an upper bound of the
// distance to the nearest edge that a brute-force CPU search finds; its early out is taken only where the
// truth is umbra or full light. Their annotated bounds under an area light (ExpectPenumbraMaeBelow with
// ExpectAreaRadius) are the CTest `check` tests' business.
#include "VisibilityHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/ShadowMetrics.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace shadowfx::test::test_soft_shadow_effects {
namespace {

constexpr int kWidth = 320;  // the size check renders at
constexpr int kHeight = 240;
constexpr float kAreaRadius = 2.0f;  // the effects' ExpectAreaRadius
constexpr int kAreaSamples = 36;     // few samples keep the truth fast

std::vector<float> renderVisibility(runtime::EffectRenderer& renderer, const runtime::Scene& scene,
                                    const std::string& technique) {
    if (!render(renderer, scene, kWidth, kHeight, technique)) return {};
    return runtime::visibilityFromFrame(renderer.readFrame());
}

SceneTruth computeTruth(runtime::Scene scene) {
    runtime::GroundTruthOptions options;
    options.areaSamples = kAreaSamples;
    return computeSceneTruth(std::move(scene), kWidth, kHeight, options);
}

// A built-in scene with its light0 turned into a disk of radius kAreaRadius, and its soft truth.
const SceneTruth& areaLitTruth(const std::string& name) {
    static std::map<std::string, SceneTruth> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    runtime::Scene scene = *runtime::makeBuiltinScene(name, nullptr);
    scene.lights.at(0).areaRadius = kAreaRadius;
    return cache.emplace(name, computeTruth(std::move(scene))).first->second;
}

// [SECTION] Contact hardening

constexpr float kPlateEdgeX = 0.0f;  // the plate covers x < 0; its shadow's edge runs along z
constexpr float kGroundHalf = 4.0f;

// A ground plane and a thin plate `height` above it, covering x in [-3, 0]; fixed bounds so that the light's
// frustum (and a directional light's disk distance) are the same at every height.
runtime::Scene plateScene(float height, runtime::Light light) {
    runtime::Scene scene;
    scene.name = "plate";
    runtime::SceneObject ground;
    ground.name = "ground";
    ground.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(2 * kGroundHalf, 2 * kGroundHalf));
    ground.id = 1;
    runtime::SceneObject plate;
    plate.name = "plate";
    plate.mesh = std::make_shared<runtime::Mesh>(runtime::makeBox({3.0f, 0.04f, 6.0f}));
    plate.world = glm::translate(glm::mat4(1.0f), glm::vec3(kPlateEdgeX - 1.5f, height, 0.0f));
    plate.id = 2;
    scene.objects = {ground, plate};
    scene.explicitBounds =
        runtime::Bounds{{-kGroundHalf, -0.1f, -kGroundHalf}, {kGroundHalf, 2.5f, kGroundHalf}};
    // Looking down at the edge from the lit side, close enough that a penumbra spans several pixels.
    scene.camera.position = {2.0f, 3.0f, -2.5f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.lights = {light};
    return scene;
}

// The 10-90 % width of the shadow edge on the ground along x, in world units: ground pixels in a strip
// around z = 0 binned by x, the mean visibility per bin, the x where it first reaches 0.1 and 0.9.
// Negative when the profile does not cross both levels.
float edgeWidth(const runtime::GBuffer& gbuffer, const std::vector<float>& visibility) {
    constexpr float kBin = 0.005f;
    constexpr float kFrom = -1.5f;
    constexpr int kBins = 600;
    std::vector<double> sum(kBins, 0.0);
    std::vector<int> count(kBins, 0);
    for (size_t i = 0; i < gbuffer.pixelCount(); ++i) {
        if (gbuffer.objectId[i] != 1 || visibility[i] < 0.0f) continue;
        const glm::vec3 p = gbuffer.position[i];
        if (std::abs(p.z) > 0.75f) continue;
        const int bin = static_cast<int>(std::floor((p.x - kFrom) / kBin));
        if (bin < 0 || bin >= kBins) continue;
        sum[bin] += visibility[i];
        ++count[bin];
    }
    int low = -1, high = -1;
    for (int b = 0; b < kBins; ++b) {
        if (count[b] == 0) continue;
        const double mean = sum[b] / count[b];
        if (low < 0 && mean >= 0.1) low = b;
        if (high < 0 && mean >= 0.9) high = b;
    }
    return low <= 0 || high <= low ? -1.0f : (high - low) * kBin;
}

// Ratio of the penumbra width at plate height 1.5 to that at 0.5, from the effect and from the truth,
// against the theory: width proportional to d2 / d1, d2 the plate's height above the ground, d1 the plate's
// distance from the light's disk: `lightDistance` from the ground less d2 for a spot light, `lightDistance`
// for a directional one (its disk keeps that distance from every receiver).
void expectContactHardening(const std::string& effectPath, const std::string& technique,
                            const runtime::Light& light, float lightDistance) {
    auto renderer = loadVisibilityEffect(effectPath);
    ASSERT_TRUE(renderer);
    const float heights[2] = {0.5f, 1.5f};
    float effectWidth[2], truthWidth[2];
    for (int k = 0; k < 2; ++k) {
        const SceneTruth t = computeTruth(plateScene(heights[k], light));
        const std::vector<float> visibility = renderVisibility(*renderer, t.scene, technique);
        ASSERT_EQ(visibility.size(), t.truth.visibility.size());
        effectWidth[k] = edgeWidth(t.gbuffer, visibility);
        truthWidth[k] = edgeWidth(t.gbuffer, t.truth.visibility);
        ASSERT_GT(effectWidth[k], 0.0f) << "no shadow edge at height " << heights[k];
        ASSERT_GT(truthWidth[k], 0.0f);
    }
    const bool spot = light.type == runtime::Light::Type::Spot;
    auto q = [&](float h) { return h / (spot ? lightDistance - h : lightDistance); };  // d2 / d1
    const float theory = q(heights[1]) / q(heights[0]);
    const float measured = effectWidth[1] / effectWidth[0];
    SCOPED_TRACE(technique + ": widths " + std::to_string(effectWidth[0]) + ", " +
                 std::to_string(effectWidth[1]) + " (truth " + std::to_string(truthWidth[0]) + ", " +
                 std::to_string(truthWidth[1]) + ")");
    EXPECT_NEAR(truthWidth[1] / truthWidth[0], theory, 0.25f * theory) << "the truth itself disagrees";
    EXPECT_NEAR(measured, theory, 0.25f * theory);
    EXPECT_NEAR(effectWidth[1], truthWidth[1], 0.2f * truthWidth[1]) << "absolute width at the larger height";
}

runtime::Light spotAbove() {
    runtime::Light light;
    light.type = runtime::Light::Type::Spot;
    light.position = {0.0f, 8.0f, 0.0f};
    light.direction = {0.0f, -1.0f, 0.0f};
    light.spotAngle = glm::radians(70.0f);
    light.areaRadius = 0.7f;
    return light;
}

runtime::Light directionalAbove() {
    runtime::Light light;
    light.type = runtime::Light::Type::Directional;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.areaRadius =
        1.5f;  // its disk stands further away than the spot's: a larger one, as wide a penumbra
    return light;
}

// The directional light's disk stands 2 R + |centre| from every receiver
// (runtime/measure/src/GroundTruth.cpp).
float directionalDiskDistance() {
    const runtime::Bounds bounds = plateScene(0.5f, directionalAbove()).bounds();
    return 2.0f * bounds.radius() + glm::length(bounds.center());
}

TEST(SoftShadowEffects, PcssPenumbraWidensWithTheOccluderDistanceUnderASpotLight) {
    expectContactHardening("effects/pcss.fx", "pcss", spotAbove(), 8.0f);
}

TEST(SoftShadowEffects, PcssPenumbraWidensWithTheOccluderDistanceUnderADirectionalLight) {
    expectContactHardening("effects/pcss.fx", "pcss", directionalAbove(), directionalDiskDistance());
}

TEST(SoftShadowEffects, FractionalDiskPenumbraWidensWithTheOccluderDistance) {
    expectContactHardening("effects/fractional_disk.fx", "preprocessed", spotAbove(), 8.0f);
    expectContactHardening("effects/fractional_disk.fx", "direct", spotAbove(), 8.0f);
}

// [SECTION] Eye-space blur (Scherzer 2005, §4.3)

// Receiver pixels with a fractional shadow term: how far the blur has spread the edges.
size_t fractionalPixels(const SceneTruth& t, const std::vector<float>& visibility) {
    size_t n = 0;
    for (size_t i = 0; i < visibility.size(); ++i)
        n += t.receivers[i] && visibility[i] > 0.05f && visibility[i] < 0.95f;
    return n;
}

// More iterations spread the edges further (Fig. 8), and the depth-dependent radius spreads them less.
TEST(SoftShadowEffects, EyeSpaceBlurWidensWithIterationsAndLessWithDepthDependence) {
    auto renderer = loadVisibilityEffect("effects/eye_space_blur.fx");
    ASSERT_TRUE(renderer);
    const SceneTruth& t = areaLitTruth("dual-l");
    auto spread = [&](int iterations, bool depthDependent) {
        fx::DiagnosticList diagnostics;
        EXPECT_TRUE(renderer->setParameterFromText("Iterations", std::to_string(iterations), diagnostics));
        EXPECT_TRUE(
            renderer->setParameterFromText("DepthDependent", depthDependent ? "true" : "false", diagnostics));
        return fractionalPixels(t, renderVisibility(*renderer, t.scene, "blur"));
    };
    const size_t one = spread(1, false), sixteen = spread(16, false), sixteenByDepth = spread(16, true);
    EXPECT_GT(one, 100u) << "even one iteration blurs the edges";
    EXPECT_GT(sixteen, 3 * one);
    EXPECT_LT(sixteenByDepth, sixteen);
}

// [SECTION] Blurred receiver channels (Kozlov 2004, §14.3.2)

// The ground (object 1) marked as a receiver gets blurred edges where the depth test gives hard ones, and a
// receiver in the second channel is blurred exactly as in the first.
TEST(SoftShadowEffects, BlurredReceiverChannelsSoftenTheMarkedReceiverInEitherChannel) {
    auto renderer = loadVisibilityEffect("effects/blurred_receivers.fx");
    ASSERT_TRUE(renderer);
    const SceneTruth& t = areaLitTruth("teapot");
    auto frame = [&](int first, int second) {
        fx::DiagnosticList diagnostics;
        EXPECT_TRUE(renderer->setParameterFromText("ReceiverId0", std::to_string(first), diagnostics));
        EXPECT_TRUE(renderer->setParameterFromText("ReceiverId1", std::to_string(second), diagnostics));
        return renderVisibility(*renderer, t.scene, "blurred");
    };
    const std::vector<float> depthTest = frame(0, 0), firstChannel = frame(1, 0), secondChannel = frame(0, 1);
    EXPECT_GT(fractionalPixels(t, firstChannel), 3 * fractionalPixels(t, depthTest) + 100);
    ASSERT_EQ(firstChannel.size(), secondChannel.size());
    size_t differing = 0;
    for (size_t i = 0; i < firstChannel.size(); ++i)
        differing += std::abs(firstChannel[i] - secondChannel[i]) > 1e-3f;
    EXPECT_EQ(differing, 0u);
}

// [SECTION] The disk radius

// PenumbraRadiusWorld (include/light_size.fxh) against q = (d2 / d1) r computed here: d2 the receiver's
// distance to the occluder, d1 the occluder's to the light's disk (for a spot light: the occluder's view
// depth; for a directional light, whose disk keeps its distance 2 R + |centre| from every receiver, that
// distance).
TEST(SoftShadowEffects, DiskRadiusIsD2OverD1TimesTheLightRadius) {
    auto renderer = loadEffect(R"(
#include "effects/include/lighting.fxh"
#include "effects/include/shadowscene.fxh"
#include "effects/include/light_size.fxh"
texture Result : RENDERCOLORTARGET < float2 Dimensions = {4, 1}; string Format = "R32F"; >;
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
float4 PS(Quad IN) : COLOR {
    int i = int(IN.UV.x * 4.0);
    float receiver = i < 2 ? 6.0 : 7.5;
    float blocker = i % 2 == 0 ? 5.0 : 2.0;
    return float4(PenumbraRadiusWorld(receiver, blocker, LightRadius), 0, 0, 1);
}
technique t { pass p < string Script = "RenderColorTarget0=Result; Draw=Buffer;"; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
                               false, sourcePath("inline.fx"));
    ASSERT_TRUE(renderer);
    const float receivers[4] = {6.0f, 6.0f, 7.5f, 7.5f};
    const float blockers[4] = {5.0f, 2.0f, 5.0f, 2.0f};
    for (const runtime::Light& light : {spotAbove(), directionalAbove()}) {
        const runtime::Scene scene = plateScene(1.0f, light);
        ASSERT_TRUE(render(*renderer, scene, 4, 1, "", {"Result"}));
        int width = 0, height = 0, channels = 0;
        const auto result = renderer->readTarget("Result", &width, &height, &channels);
        ASSERT_TRUE(result);
        const runtime::Bounds bounds = scene.bounds();
        for (int i = 0; i < 4; ++i) {
            const float d2 = receivers[i] - blockers[i];
            // A spot light's disk is at its position, blockers[i] from the occluder; a directional light's
            // stays 2 R + |centre| from the receiver, the cone to it has that length.
            const float d1 = light.type == runtime::Light::Type::Spot
                                 ? blockers[i]
                                 : 2.0f * bounds.radius() + glm::length(bounds.center());
            const float q = light.areaRadius * d2 / d1;
            EXPECT_NEAR((*result)[static_cast<size_t>(i) * channels], q, 1e-4f * (1.0f + q))
                << "sample " << i;
        }
    }
}

// [SECTION] Fractional-disk preprocessing and early out

// Brute force over the preprocessed map's own depths (R): the edge texels as the effect's EdgeThreshold
// defines them, and each texel's Chebyshev distance to the nearest; the map's B must be an upper bound of
// it, tight within the jump flooding's error, wherever the propagation reaches.
TEST(SoftShadowEffects, FractionalDiskMapHoldsTheDistanceToTheNearestEdge) {
    auto renderer = loadVisibilityEffect("effects/fractional_disk.fx");
    ASSERT_TRUE(renderer);
    const SceneTruth& t = areaLitTruth("dual-l");
    ASSERT_TRUE(render(*renderer, t.scene, kWidth, kHeight, "preprocessed", {"DiskMap"}));
    int w = 0, h = 0, channels = 0;
    const auto map = renderer->readTarget("DiskMap", &w, &h, &channels);
    ASSERT_TRUE(map);
    ASSERT_GE(channels, 3);
    auto at = [&](int x, int y, int c) { return (*map)[(static_cast<size_t>(y) * w + x) * channels + c]; };
    constexpr float kThreshold = 0.01f;  // EdgeThreshold's default
    constexpr int kReach = 15;           // 2 (2^3 - 1) + 1 texels: PropagationLoops' default, 3
    std::vector<uint8_t> edge(static_cast<size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float lo = at(x, y, 0), hi = lo;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const float d = at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1), 0);
                    lo = std::min(lo, d);
                    hi = std::max(hi, d);
                }
            edge[static_cast<size_t>(y) * w + x] = hi - lo > kThreshold;
        }
    int checked = 0, notBound = 0, loose = 0, edges = 0;
    for (int y = 0; y < h; y += 7)
        for (int x = 0; x < w; x += 7) {
            int exact = kReach + 1;
            for (int dy = -kReach; dy <= kReach; ++dy)
                for (int dx = -kReach; dx <= kReach; ++dx) {
                    const int ex = x + dx, ey = y + dy;
                    if (ex < 0 || ey < 0 || ex >= w || ey >= h || !edge[static_cast<size_t>(ey) * w + ex])
                        continue;
                    exact = std::min(exact, std::max(std::abs(dx), std::abs(dy)));
                }
            if (exact > kReach / 2) continue;  // the jump flooding is exact near edges, an upper bound beyond
            ++checked;
            edges += exact == 0;
            const float stored = at(x, y, 2);
            if (stored < exact - 1e-3f) ++notBound;
            if (stored > 2.0f * exact + 1.0f) ++loose;
        }
    ASSERT_GT(edges, 50) << "the map must have shadow boundaries to measure";
    EXPECT_EQ(notBound, 0) << "of " << checked;
    EXPECT_LT(loose, checked / 100 + 1) << "of " << checked;
}

// Where the preprocessed map says umbra or full light (-D FD_SHOW_EARLY_OUT), the truth agrees: the early
// out skips pixels, not penumbrae.
TEST(SoftShadowEffects, FractionalDiskEarlyOutIsTakenOutsideThePenumbra) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions options;
    options.defines = {{"FD_SHOW_EARLY_OUT", "1"}};
    auto effect = fx::parseEffectFile(sourcePath("effects/fractional_disk.fx"), options, diagnostics);
    auto compiled = effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    ASSERT_TRUE(compiled && !diagnostics.hasErrors()) << diagnostics.str();
    auto renderer = runtime::EffectRenderer::create(
        std::shared_ptr<const fx::CompiledEffect>(std::move(compiled)), diagnostics);
    ASSERT_TRUE(renderer);
    for (const char* sceneName : {"dual-l", "teapot"}) {
        SCOPED_TRACE(sceneName);
        const SceneTruth& t = areaLitTruth(sceneName);
        const std::vector<float> early = renderVisibility(*renderer, t.scene, "preprocessed");
        ASSERT_EQ(early.size(), t.truth.visibility.size());
        size_t receivers = 0, taken = 0, inPenumbra = 0;
        for (size_t i = 0; i < early.size(); ++i) {
            if (!t.receivers[i]) continue;
            ++receivers;
            if (early[i] < 0.5f) continue;
            ++taken;
            inPenumbra += t.truth.visibility[i] > 0.2f && t.truth.visibility[i] < 0.8f;
        }
        EXPECT_GT(taken, receivers / 2) << "most receivers are in umbra or full light";
        EXPECT_LT(taken, receivers) << "the penumbrae must be filtered";
        EXPECT_LT(inPenumbra, taken / 200 + 1) << "early out inside a penumbra, of " << taken;
    }
}

}  // namespace
}  // namespace shadowfx::test::test_soft_shadow_effects
