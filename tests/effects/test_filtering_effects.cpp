// The shadow-filtering effects (effects/pcf.fx, vsm.fx, esm.fx, evsm.fx, msm.fx) against the ray-cast
// ground truth and against independent computations: every technique stays under the misclassification
// bound its `ExpectMisclassifiedBelow` annotation asserts (the measured value it came from is the comment
// beside it in the effect), PCF filters at shadow edges but not inside the umbra, the light-space noise of
// `jittered_noise` stays on the surface when the camera moves, VSM's visibility is the Chebyshev bound of
// its own moments map computed on the CPU, the minimum-variance guard keeps a flat receiver clean, and the
// moment shadow maps' quantization and bound agree with what the moments of known depths require.
#include "VisibilityHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/SceneFile.h>
#include <runtime/ShadowMetrics.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowfx::test::test_filtering_effects {
namespace {

constexpr int kWidth = 320;  // the size the effects' bounds were measured at
constexpr int kHeight = 240;

std::vector<float> renderVisibility(runtime::EffectRenderer& renderer, const runtime::Scene& scene,
                                    const std::string& technique, int width = kWidth, int height = kHeight) {
    if (!render(renderer, scene, width, height, technique)) return {};
    return runtime::visibilityFromFrame(renderer.readFrame());
}

const SceneTruth& truthOf(const std::string& name) {
    static std::map<std::string, SceneTruth> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    return cache.emplace(name, computeSceneTruth(*runtime::makeBuiltinScene(name, nullptr), kWidth, kHeight))
        .first->second;
}

// [SECTION] Conformance with the ground truth

void expectUnderAnnotatedBound(const std::string& effectPath) {
    auto renderer = loadVisibilityEffect(effectPath);
    ASSERT_TRUE(renderer);
    for (const char* sceneName : {"dual-l", "teapot"}) {
        const SceneTruth& t = truthOf(sceneName);
        const std::vector<float> lit(t.truth.visibility.size(), 1.0f);
        const double blank =
            runtime::compareVisibility(t.truth.visibility, lit, t.receivers).misclassifiedPercent;
        for (const fx::CompiledTechnique& technique : renderer->effect().techniques) {
            SCOPED_TRACE(effectPath + " " + technique.name + " on " + sceneName);
            const float bound =
                techniqueAnnotationNumber(renderer->effect(), technique.name, "ExpectMisclassifiedBelow");
            ASSERT_LT(bound * 4, blank) << "a blank (all lit) image must fail the bound by far";
            const std::vector<float> visibility = renderVisibility(*renderer, t.scene, technique.name);
            const runtime::ShadowErrors errors =
                runtime::compareVisibility(t.truth.visibility, visibility, t.receivers);
            EXPECT_LT(errors.misclassifiedPercent, bound);
            const std::vector<float> dark(t.truth.visibility.size(), 0.0f);
            EXPECT_LT(bound * 4,
                      runtime::compareVisibility(t.truth.visibility, dark, t.receivers).misclassifiedPercent);
        }
    }
}

TEST(FilteringEffects, PcfTechniquesStayUnderTheirAnnotatedBounds) {
    expectUnderAnnotatedBound("effects/pcf.fx");
}

TEST(FilteringEffects, VsmTechniquesStayUnderTheirAnnotatedBounds) {
    expectUnderAnnotatedBound("effects/vsm.fx");
}

TEST(FilteringEffects, EsmTechniquesStayUnderTheirAnnotatedBounds) {
    expectUnderAnnotatedBound("effects/esm.fx");
}

TEST(FilteringEffects, EvsmTechniquesStayUnderTheirAnnotatedBounds) {
    expectUnderAnnotatedBound("effects/evsm.fx");
}

TEST(FilteringEffects, MsmTechniquesStayUnderTheirAnnotatedBounds) {
    expectUnderAnnotatedBound("effects/msm.fx");
}

// [SECTION] PCF filters edges, not the umbra

// Receiver pixels whose whole (2r+1)^2 neighbourhood is shadowed in truth: deep inside the umbra.
std::vector<size_t> umbraPixels(const SceneTruth& t, int r) {
    std::vector<size_t> pixels;
    for (int y = r; y < t.gbuffer.height - r; ++y) {
        for (int x = r; x < t.gbuffer.width - r; ++x) {
            bool deep = true;
            for (int dy = -r; dy <= r && deep; ++dy)
                for (int dx = -r; dx <= r && deep; ++dx) {
                    const size_t j = t.gbuffer.index(x + dx, y + dy);
                    deep = t.receivers[j] && t.truth.visibility[j] >= 0.0f && t.truth.visibility[j] < 0.5f;
                }
            if (deep) pixels.push_back(t.gbuffer.index(x, y));
        }
    }
    return pixels;
}

TEST(FilteringEffects, PcfGivesFractionsAtShadowEdgesButNotInTheUmbra) {
    // A coarse map (256²: a texel spans several pixels) makes the filtered band wide enough to count.
    auto renderer = loadVisibilityEffect("effects/pcf.fx", {{"SHADOWFX_SHADOW_MAP_SIZE", "256"}});
    ASSERT_TRUE(renderer);
    const SceneTruth& t = truthOf("dual-l");
    const std::vector<size_t> umbra = umbraPixels(t, 3);
    ASSERT_GT(umbra.size(), 300u);
    for (const std::string technique : {"bilinear", "hardware", "jittered4x4", "jittered_noise", "poisson"}) {
        SCOPED_TRACE(technique);
        const std::vector<float> v = renderVisibility(*renderer, t.scene, technique);
        ASSERT_FALSE(v.empty());
        size_t fractional = 0;
        for (size_t i = 0; i < v.size(); ++i) fractional += t.receivers[i] && v[i] > 0.1f && v[i] < 0.9f;
        std::cerr << technique << ": " << fractional << " fractional pixels, umbra " << umbra.size() << "\n";
        EXPECT_GT(fractional, 100u) << "no filtering at the shadow's edges";
        size_t umbraLit = 0;
        for (size_t i : umbra) umbraLit += v[i] > 0.02f;
        EXPECT_EQ(umbraLit, 0u) << "of " << umbra.size() << " umbra pixels";
    }
}

// [SECTION] The noise stays put

// jittered_noise addresses its noise by light-space position: a camera that moves a little sees the same
// shadow value at the same world point, where noise addressed in screen space would crawl over the
// surface. Pixels of the two frames are paired when their surface points (from the G-buffers) lie in the
// same shadow-map texel (one noise texel each) within 0.25 texel of each other, so only the noise's
// address can make their values differ by more than a sample or two.
TEST(FilteringEffects, LightSpaceNoisePatternStaysPutWhenTheCameraMoves) {
    constexpr int kMap = 128;  // coarse: a texel spans a few pixels, so pairs are plentiful
    auto renderer =
        loadVisibilityEffect("effects/pcf.fx", {{"SHADOWFX_SHADOW_MAP_SIZE", std::to_string(kMap)}});
    ASSERT_TRUE(renderer);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("KernelRadius", "4", diagnostics));
    runtime::Scene first = *runtime::makeBuiltinScene("dual-l", nullptr);
    runtime::Scene second = first;
    second.camera.position += glm::vec3(0.21f, 0.13f, -0.17f);
    second.camera.target += glm::vec3(0.21f, 0.13f, -0.17f);
    const std::vector<float> a = renderVisibility(*renderer, first, "jittered_noise");
    const std::vector<float> b = renderVisibility(*renderer, second, "jittered_noise");
    ASSERT_FALSE(a.empty() || b.empty());
    ASSERT_NE(a, b) << "the camera moved: the images must differ";

    fx::DiagnosticList gbufferDiagnostics;
    const runtime::GBuffer firstView = *runtime::renderGBuffer(first, kWidth, kHeight, gbufferDiagnostics);
    const runtime::GBuffer secondView = *runtime::renderGBuffer(second, kWidth, kHeight, gbufferDiagnostics);
    const runtime::Bounds bounds = first.bounds();
    const glm::mat4 lightClip = first.lights[0].projection(bounds) * first.lights[0].view(bounds);
    auto texel = [&](const glm::vec3& p) {
        const glm::vec4 clip = lightClip * glm::vec4(p, 1.0f);
        return glm::vec2(0.5f * clip.x / clip.w + 0.5f, -0.5f * clip.y / clip.w + 0.5f) * float(kMap);
    };
    int compared = 0, same = 0;
    double differenceSum = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (firstView.objectId[i] != 1 || a[i] <= 0.1f || a[i] >= 0.9f) continue;  // ground penumbra
        const glm::vec3 p = firstView.position[i];
        const std::optional<glm::vec3> pixel = runtime::projectToPixel(second, p, kWidth, kHeight);
        if (!pixel) continue;
        const size_t j = secondView.index(int(pixel->x), int(pixel->y));
        if (secondView.objectId[j] != 1) continue;
        const glm::vec2 ta = texel(p), tb = texel(secondView.position[j]);
        if (glm::floor(ta) != glm::floor(tb) || glm::length(ta - tb) > 0.25f) continue;
        ++compared;
        differenceSum += std::abs(a[i] - b[j]);
        same += std::abs(a[i] - b[j]) < 0.5f / 16.0f;
    }
    std::cerr << "noise: " << compared << " pairs, mean difference " << differenceSum / compared << ", same "
              << same << "\n";
    ASSERT_GT(compared, 100);
    // Measured: 343 pairs, mean difference 0.028, 62 % within half a sample (1/32). With the noise
    // addressed through the view direction instead (NoiseAddress(uv) + IN.WView.xy * 40, i.e. crawling with
    // the camera): mean 0.064, 28 % the same.
    EXPECT_LT(differenceSum / compared, 0.045);
    EXPECT_GT(same * 2, compared);
}

// [SECTION] VSM

// Bilinear sample of an RG float image at texture coordinates `uv` (texel centres at (i + 0.5) / size,
// clamped at the border), as GL's LINEAR filter does.
glm::vec2 bilinear(const std::vector<float>& image, int width, int height, int channels, glm::vec2 uv) {
    const glm::vec2 texel = uv * glm::vec2(width, height) - 0.5f;
    const glm::vec2 base = glm::floor(texel);
    const glm::vec2 f = texel - base;
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
        return glm::vec2(image[i], image[i + 1]);
    };
    const int x = int(base.x), y = int(base.y);
    return glm::mix(glm::mix(at(x, y), at(x + 1, y), f.x), glm::mix(at(x, y + 1), at(x + 1, y + 1), f.x),
                    f.y);
}

// p_max = sigma^2 / (sigma^2 + (t - mu)^2) for t > mu (Lehőcz 2007, "Szórásnégyzet shadow map-ek"), computed
// here from the moments the effect rendered and the G-buffer's world points.
TEST(FilteringEffects, VsmVisibilityIsTheChebyshevBoundOfItsMoments) {
    // A 256² map: its bilinear filtering spreads the bound's fractional values over more pixels.
    auto renderer = loadVisibilityEffect("effects/vsm.fx", {{"SHADOWFX_SHADOW_MAP_SIZE", "256"}});
    ASSERT_TRUE(renderer);
    const SceneTruth& t = truthOf("dual-l");
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("LightBleedReduction", "0", diagnostics));
    const float minVariance = renderer->parameter(*renderer->findParameter("MinVariance")).asFloat();
    const std::vector<float> v = renderVisibility(*renderer, t.scene, "vsm");
    int width = 0, height = 0, channels = 0;
    const auto moments = renderer->readTarget("Moments", &width, &height, &channels);
    ASSERT_TRUE(moments);
    ASSERT_EQ(channels, 2);

    const runtime::Bounds bounds = t.scene.bounds();
    const glm::mat4 lightClip = t.scene.lights[0].projection(bounds) * t.scene.lights[0].view(bounds);
    int checked = 0, agree = 0, partial = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        if (!t.receivers[i]) continue;
        const glm::vec4 clip = lightClip * glm::vec4(t.gbuffer.position[i], 1.0f);
        const glm::vec2 uv(0.5f * clip.x / clip.w + 0.5f, -0.5f * clip.y / clip.w + 0.5f);
        const float depth = clip.z / clip.w;
        const glm::vec2 m = bilinear(*moments, width, height, channels, uv);
        float expected = 1.0f;
        if (depth > m.x) {
            const float variance = std::max(m.y - m.x * m.x, minVariance);
            expected = variance / (variance + (depth - m.x) * (depth - m.x));
        }
        ++checked;
        partial += expected > 0.05f && expected < 0.95f;
        agree += std::abs(expected - v[i]) < 0.02f;  // 8-bit frame, float32 G-buffer positions
    }
    ASSERT_GT(checked, kWidth * kHeight / 4);
    EXPECT_GT(partial, 100) << "the comparison must include fractional values, not only 0 and 1";
    std::cerr << "chebyshev: " << agree << " of " << checked << " agree, " << partial << " partial\n";
    EXPECT_GT(agree, checked * 99 / 100) << agree << " of " << checked;
}

// A receiver facing the light exactly (a ground plane under a light straight above) stores moments whose
// variance is pure float32 round-off: E[z^2] - E[z]^2 of equal depths. Without the floor the bound there is
// 0 or NaN wherever the receiver's depth rounds above the stored mean (acne); MinVariance removes it.
TEST(FilteringEffects, MinimumVarianceKeepsAFlatReceiverLit) {
    fx::DiagnosticList diagnostics;
    std::optional<runtime::Scene> scene = runtime::parseSceneJson(R"({
        "objects": [
            {"name": "ground", "mesh": {"primitive": "plane", "size": [20, 20], "divisions": 1}},
            {"name": "box", "mesh": {"primitive": "box", "size": [1, 1, 1]}, "translate": [0, 2, 0]}],
        "camera": {"position": [0, 8, -8], "target": [0, 0, 0], "fov": 60},
        "lights": [{"name": "light0", "type": "directional", "direction": [0.0001, -1, 0]}]
    })",
                                                                  "flat.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.str();
    auto renderer = loadVisibilityEffect("effects/vsm.fx");
    ASSERT_TRUE(renderer);
    fx::DiagnosticList gbufferDiagnostics;
    const runtime::GBuffer gbuffer = *runtime::renderGBuffer(*scene, kWidth, kHeight, gbufferDiagnostics);
    const runtime::GroundTruth truth = runtime::ShadowRayCaster(*scene).compute(gbuffer, scene->lights[0]);
    const std::vector<uint8_t> receivers = runtime::receiverMask(gbuffer, scene->lights[0]);

    const std::vector<float> guarded = renderVisibility(*renderer, *scene, "vsm");
    const runtime::ShadowErrors withGuard = runtime::compareVisibility(truth.visibility, guarded, receivers);
    ASSERT_TRUE(renderer->setParameterFromText("MinVariance", "0", diagnostics));
    const std::vector<float> unguarded = renderVisibility(*renderer, *scene, "vsm");
    const runtime::ShadowErrors withoutGuard =
        runtime::compareVisibility(truth.visibility, unguarded, receivers);
    std::cerr << "flat receiver false shadow: " << withGuard.falseShadowPercent << "% with MinVariance, "
              << withoutGuard.falseShadowPercent << "% without\n";
    EXPECT_LT(withGuard.falseShadowPercent, 0.5) << "acne on the flat receiver despite MinVariance";
    EXPECT_GT(withoutGuard.falseShadowPercent, 10 * withGuard.falseShadowPercent + 1.0)
        << "the scene must show the problem the guard solves";
}

// [SECTION] Moment shadow maps against independent computations

// A Draw=Buffer pass of one row, `width` pixels wide: pixel i runs `body` with `z` = (i + 0.5) / width and
// returns its float4. The shader includes effects/include/msm.fxh. Values come back through an RGBA8 frame.
runtime::FrameImage runMsmRow(const std::string& body, int width) {
    const std::string source = R"(#include "include/msm.fxh"
float W = 0.5;
float Z1 = 0.3;
float Z2 = 0.6;
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { float z = uv.x; )" +
                               body + R"( }
technique t { pass p < string Script = "RenderColorTarget0=; Draw=Buffer;"; > {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
    auto renderer = loadEffect(source, false, sourcePath("effects/msm_check.fx"));
    if (!renderer) return {};
    static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes", nullptr);
    EXPECT_TRUE(render(*renderer, scene, width, 1));
    return renderer->readFrame();
}

// Peters & Klein 2015's quantization: its two matrices are inverses (a dequantized texel is the moments
// computed directly, to 1e-5 of their range), and the moments of every depth in [0, 1] land in [0, 1]^4 (to
// float32 rounding: the map is as wide as the range, touching 0 and 1), so that 16-bit normalized storage
// holds them.
TEST(FilteringEffects, MsmQuantizationIsInvertibleAndFitsNormalizedStorage) {
    const int width = 256;
    const runtime::FrameImage roundTrip = runMsmRow(
        "float4 b = PowerMoments(z); float4 e = saturate(abs(DequantizeMoments(QuantizeMoments(b)) - b) * "
        "1e5); "
        "return float4(e.x, e.y, max(e.z, e.w), 1);",
        width);
    ASSERT_EQ(roundTrip.width, width);
    for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(roundTrip.pixel(x, 0)[c], 255) << "pixel " << x << " channel " << c;
    // In range: 1 where every component is in [0, 1], else 0.
    const runtime::FrameImage range = runMsmRow(
        "float4 q = QuantizeMoments(PowerMoments(z)); float inside = all(q >= -1e-5) && all(q <= 1 + 1e-5) ? "
        "1.0 : 0.0; "
        "return float4(inside, inside, inside, 1);",
        width);
    for (int x = 0; x < width; ++x) EXPECT_EQ(range.pixel(x, 0)[0], 255) << "depth " << (x + 0.5) / width;
}

// The Hamburger 4MSM on the moments of two occluder depths, weight W at Z1 = 0.3 and 1 - W at Z2 = 0.6: four
// moments determine such a distribution exactly, so the sharpest lower bound is the distribution's own
// fraction in front of the receiver: 0 in front of Z1, W between, 1 behind Z2 (to the moment bias). The
// expectation comes from the distribution, not from the algorithm.
TEST(FilteringEffects, Hamburger4MsmRecoversATwoDepthDistribution) {
    const int width = 100;
    const runtime::FrameImage image = runMsmRow(
        "float4 b = W * PowerMoments(Z1) + (1 - W) * PowerMoments(Z2); float g = Hamburger4MsmShadow(b, z, "
        "3e-6); "
        "return float4(g, g, g, 1);",
        width);
    ASSERT_EQ(image.width, width);
    ASSERT_TRUE(notConstant(image));
    for (int x = 0; x < width; ++x) {
        const double z = (x + 0.5) / width;
        if (std::abs(z - 0.3) < 0.03 || std::abs(z - 0.6) < 0.03) continue;  // the bound ramps at the atoms
        const double expected = z < 0.3 ? 0.0 : z < 0.6 ? 0.5 : 1.0;
        EXPECT_NEAR(image.pixel(x, 0)[0] / 255.0, expected, 0.03) << "receiver depth " << z;
    }
}

// [SECTION] The light's size

// `LightAreaRadius` (alias `LightSize`) binds the named light's areaRadius, for filters sized by the light.
TEST(FilteringEffects, LightAreaRadiusSemanticGivesTheLightsAreaRadius) {
    auto renderer = loadEffect(R"(
float Radius : LightAreaRadius < string Object = "light0"; >;
float Size : LightSize;
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
float4 PS(Quad IN) : COLOR { return float4(Radius, Size * 0.5, 0, 1); }
technique t { pass p < string Script = "Draw=Buffer;"; > { VertexShader = compile vs_3_0 VS();
                                                           PixelShader = compile ps_3_0 PS(); } }
)",
                               false);
    ASSERT_TRUE(renderer);
    runtime::Scene scene = *runtime::makeBuiltinScene("dual-l", nullptr);
    scene.lights.at(0).areaRadius = 0.75f;
    ASSERT_TRUE(render(*renderer, scene, 4, 4));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_NEAR(frame.pixel(1, 1)[0], 0.75f * 255, 1.0f);
    EXPECT_NEAR(frame.pixel(1, 1)[1], 0.375f * 255, 1.0f);
}

}  // namespace
}  // namespace shadowfx::test::test_filtering_effects
