// The thesis-style FX Composer effect (effects/thesis_fxcomposer.fx) rendered headlessly: points of the
// ground plane that lie in an object's shadow, found by casting segments towards the light through the
// scene's triangles (independently of any shadow map), must be dark, and points that are lit must be lit.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace shadowfx::test::test_thesis_effect {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

struct PlaneSample {
    glm::vec3 world;
    glm::ivec2 pixel;
    bool shadowed;
};

// Ground-plane points (y = 0) that the camera sees and whose whole neighbourhood has the same exact
// visibility from the light, so that shadow-map resolution and filtering cannot change their answer.
std::vector<PlaneSample> classifyPlanePoints(const runtime::Scene& scene) {
    const glm::vec3 toLight = -glm::normalize(scene.lights.at(0).direction);
    auto shadowed = [&](const glm::vec3& p) {
        return runtime::segmentOccluded(scene, p, p + toLight * 100.0f);
    };
    std::vector<PlaneSample> samples;
    for (float x = -9.0f; x <= 9.0f; x += 0.25f) {
        for (float z = -9.0f; z <= 9.0f; z += 0.25f) {
            const glm::vec3 p(x, 0.0f, z);
            const std::optional<glm::vec3> pixel = runtime::projectToPixel(scene, p, kWidth, kHeight);
            if (!pixel || pixel->x < 2 || pixel->y < 2 || pixel->x > kWidth - 3 || pixel->y > kHeight - 3)
                continue;
            if (runtime::segmentOccluded(scene, scene.camera.position, p)) continue;
            const bool inShadow = shadowed(p);
            bool uniform = true;
            for (float dx : {-0.3f, 0.0f, 0.3f})
                for (float dz : {-0.3f, 0.0f, 0.3f})
                    uniform =
                        uniform && shadowed(p + glm::vec3(dx, 0.0f, dz)) == inShadow &&
                        !runtime::segmentOccluded(scene, scene.camera.position, p + glm::vec3(dx, 0.0f, dz));
            if (uniform) samples.push_back({p, glm::ivec2(*pixel), inShadow});
        }
    }
    return samples;
}

// Checks every classified plane point against the lighting the effect computes: ambient only in shadow,
// ambient plus a clear diffuse share in light.
void expectShadowsWhereGeometrySaysSo(const runtime::Scene& scene, const runtime::FrameImage& image) {
    ASSERT_TRUE(notConstant(image));
    const std::vector<PlaneSample> samples = classifyPlanePoints(scene);
    const size_t shadowCount = static_cast<size_t>(
        std::count_if(samples.begin(), samples.end(), [](auto& s) { return s.shadowed; }));
    ASSERT_GE(shadowCount, 20u) << "the scene no longer puts a visible shadow on the plane";
    ASSERT_GE(samples.size() - shadowCount, 100u);

    const runtime::SceneObject& plane = scene.objects.at(0);
    const glm::vec3 ambient = plane.color * scene.ambient;
    const float nDotL =
        std::max(0.0f, glm::dot(glm::vec3(0, 1, 0), -glm::normalize(scene.lights[0].direction)));
    const float ambientLuminance = 0.2126f * ambient.r + 0.7152f * ambient.g + 0.0722f * ambient.b;
    const float diffuseLuminance =
        nDotL * (0.2126f * plane.color.r + 0.7152f * plane.color.g + 0.0722f * plane.color.b);

    int wrong = 0;
    for (const PlaneSample& s : samples) {
        const float l = luminance(image.pixel(s.pixel.x, s.pixel.y));
        const bool ok = s.shadowed ? std::abs(l - ambientLuminance) < 0.06f
                                   : l > ambientLuminance + 0.5f * diffuseLuminance;
        if (!ok && ++wrong <= 5) {
            ADD_FAILURE() << (s.shadowed ? "shadowed" : "lit") << " point (" << s.world.x << ", " << s.world.z
                          << ") at pixel (" << s.pixel.x << ", " << s.pixel.y << ") has luminance " << l
                          << "; ambient " << ambientLuminance << ", diffuse " << diffuseLuminance;
        }
    }
    EXPECT_EQ(wrong, 0) << "of " << samples.size() << " points (" << shadowCount << " in shadow)";
}

class ThesisEffect : public ::testing::Test {
protected:
    void SetUp() override {
        renderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
        ASSERT_TRUE(renderer);
        scene = *runtime::makeBuiltinScene("boxes");
    }
    std::unique_ptr<runtime::EffectRenderer> renderer;
    runtime::Scene scene;
};

TEST_F(ThesisEffect, MainTechniqueShadowsExactlyTheOccludedPlanePoints) {
    ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight, "main"));
    expectShadowsWhereGeometrySaysSo(scene, renderer->readFrame());
}

TEST_F(ThesisEffect, BilinearPcfKeepsTheShadows) {
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("PCF", "true", diagnostics)) << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight, "main"));
    expectShadowsWhereGeometrySaysSo(scene, renderer->readFrame());
}

TEST_F(ThesisEffect, HardwareDepthComparisonTechniqueShadowsTheSamePoints) {
    ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight, "hardware"));
    expectShadowsWhereGeometrySaysSo(scene, renderer->readFrame());
}

TEST_F(ThesisEffect, ShadowMapHoldsTheMinimumDepthTimesZMax) {
    ASSERT_TRUE(render(*renderer, scene, kWidth, kHeight, "main"));
    int width = 0, height = 0, channels = 0;
    std::optional<std::vector<float>> map = renderer->readTarget("ShadowMap", &width, &height, &channels);
    ASSERT_TRUE(map);
    ASSERT_EQ(width, 1024);
    const float zMax = 130944 / 16.0f;
    float lowest = zMax;
    size_t cleared = 0;
    for (size_t i = 0; i < map->size(); i += static_cast<size_t>(channels)) {
        lowest = std::min(lowest, (*map)[i]);
        cleared += (*map)[i] == zMax;
    }
    // The light's frustum is fitted around the scene's bounding sphere: geometry covers part of the map,
    // never all of it, and every stored depth is in front of the far plane.
    EXPECT_GT(cleared, 0u);
    EXPECT_LT(cleared, map->size() / static_cast<size_t>(channels));
    EXPECT_GT(lowest, 0.0f);
    EXPECT_LT(lowest, zMax);
}

TEST_F(ThesisEffect, SettingAnUnknownParameterIsAnError) {
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(renderer->setParameterFromText("NoSuchParameter", "1", diagnostics));
    ASSERT_TRUE(diagnostics.hasErrors());
    EXPECT_EQ(diagnostics.items()[0].id, fx::DiagId::UnknownParameter);
}

}  // namespace
}  // namespace shadowfx::test::test_thesis_effect
