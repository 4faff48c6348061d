// Ground truth (runtime/GroundTruth.h) on an analytic case: a 2x2 square one unit above a plane, a
// directional light straight down. The exact shadow is the square's footprint |x| < 1, |z| < 1 on the
// plane; every G-buffer pixel whose neighbourhood lies on one side of that outline must be classified as
// the closed form says. The G-buffer's positions themselves are checked against the camera ray through
// each pixel centre.
#include "GlTestSupport.h"

#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/Scene.h>

#include <fx/Diagnostics.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace test_ground_truth {

namespace {

constexpr int kWidth = 200;
constexpr int kHeight = 150;

runtime::Scene squareOverPlane(float height) {
    runtime::Scene scene;
    scene.name = "square-over-plane";
    runtime::SceneObject plane;
    plane.name = "plane";
    plane.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(12.0f, 12.0f));
    scene.objects.push_back(plane);
    runtime::SceneObject square;
    square.name = "square";
    square.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(2.0f, 2.0f));
    square.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, height, 0.0f));
    scene.objects.push_back(square);
    scene.camera.position = glm::vec3(1.5f, 7.0f, -6.0f);
    scene.camera.target = glm::vec3(0.0f);
    runtime::Light light;
    light.type = runtime::Light::Type::Directional;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    scene.lights.push_back(light);
    return scene;
}

bool inSquareShadow(const glm::vec3& p) {
    return std::abs(p.x) < 1.0f && std::abs(p.z) < 1.0f;
}

class GroundTruthSquare : public ::testing::Test {
protected:
    void SetUp() override {
        testsupport::sharedContext();
        scene = squareOverPlane(squareHeight());
        fx::DiagnosticList diagnostics;
        std::optional<runtime::GBuffer> rendered =
            runtime::renderGBuffer(scene, kWidth, kHeight, diagnostics);
        ASSERT_TRUE(rendered) << diagnostics.str();
        gbuffer = std::move(*rendered);
    }
    // The plane's pixels more than a pixel from the outline `inShadow` draws (a neighbour across it, or on
    // the square, is skipped), each ray-cast shadow compared with `inShadow`; the first five that differ are
    // reported as failures.
    struct PlaneComparison {
        size_t compared = 0, shadowed = 0, wrong = 0;
    };
    template <typename InShadow>
    PlaneComparison compareThePlane(const runtime::GroundTruth& truth, InShadow inShadow) const {
        PlaneComparison c;
        for (int y = 1; y + 1 < kHeight; ++y) {
            for (int x = 1; x + 1 < kWidth; ++x) {
                const size_t i = gbuffer.index(x, y);
                if (gbuffer.objectId[i] != 1) continue;
                const bool expected = inShadow(gbuffer.position[i]);
                bool nearOutline = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const size_t j = gbuffer.index(x + dx, y + dy);
                        nearOutline = nearOutline || gbuffer.objectId[j] != 1 ||
                                      inShadow(gbuffer.position[j]) != expected;
                    }
                if (nearOutline) continue;
                ++c.compared;
                c.shadowed += expected;
                const bool rayShadowed = truth.visibility[i] == 0.0f;
                if (rayShadowed != expected && ++c.wrong <= 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") at (" << gbuffer.position[i].x << ", "
                                  << gbuffer.position[i].z << "): ray cast says "
                                  << (rayShadowed ? "shadow" : "lit");
            }
        }
        return c;
    }
    virtual float squareHeight() const { return 1.0f; }
    runtime::Scene scene;
    runtime::GBuffer gbuffer;
};

// The square 0.3 above the plane: its shadow under a light 4 degrees up falls on the plane (1 above, it
// would fall 14 away, past the plane's edge).
class GroundTruthLowSquare : public GroundTruthSquare {
protected:
    float squareHeight() const override { return 0.3f; }
};

TEST_F(GroundTruthSquare, GBufferPositionsLieOnTheCameraRayThroughEachPixelCentre) {
    const glm::mat4 inverse =
        glm::inverse(scene.camera.projection(float(kWidth) / kHeight) * scene.camera.view());
    size_t planePixels = 0, squarePixels = 0, checked = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = gbuffer.index(x, y);
            if (gbuffer.objectId[i] == 2) ++squarePixels;
            if (gbuffer.objectId[i] != 1) continue;
            ++planePixels;
            // Pixel centre -> NDC (D3D: y up in NDC, row 0 at the top) -> a ray, intersected with y = 0.
            const glm::vec2 ndc((x + 0.5f) / kWidth * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kHeight * 2.0f);
            glm::vec4 nearPoint = inverse * glm::vec4(ndc, 0.0f, 1.0f),
                      farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
            const glm::vec3 hit = a + (b - a) * (a.y / (a.y - b.y));
            ++checked;
            EXPECT_LT(glm::length(hit - gbuffer.position[i]), 0.01f) << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(gbuffer.normal[i].y, 1.0f, 1e-4f);
            if (::testing::Test::HasFailure()) return;
        }
    }
    EXPECT_GT(planePixels, size_t(kWidth * kHeight / 3));
    EXPECT_GT(squarePixels, 100u);
    EXPECT_GT(checked, 0u);
}

TEST_F(GroundTruthSquare, HardShadowMatchesTheClosedFormAwayFromTheOutline) {
    const runtime::ShadowRayCaster caster(scene);
    const runtime::GroundTruth truth = caster.compute(gbuffer, scene.lights[0]);
    EXPECT_FALSE(truth.soft);
    EXPECT_EQ(truth.samplesPerPixel, 1);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = gbuffer.index(x, y);
            if (!gbuffer.covered(i)) {
                EXPECT_EQ(truth.visibility[i], -1.0f);
            } else if (gbuffer.objectId[i] == 2) {  // the square's top: nothing above it
                EXPECT_EQ(truth.visibility[i], 1.0f) << "square pixel (" << x << ", " << y << ")";
            }
        }
    }
    const PlaneComparison plane = compareThePlane(truth, inSquareShadow);
    EXPECT_EQ(plane.wrong, 0u) << "of " << plane.compared;
    EXPECT_GT(plane.shadowed, 100u)
        << "the square's shadow (partly hidden behind the square) should be visible";
    EXPECT_GT(plane.compared - plane.shadowed, 1000u);
}

// A light 45 degrees up moves the square's shadow off its footprint; the rays' start, however far off the
// plane (here 5e-2 of the scene's radius, 0.42: about six pixels of ground), must not move the
// outline: every pixel more than a pixel from it is classified as the closed form says. A start lifted along
// the normal moved the outline by the lift / tan(elevation) into the shadow, so that a map's exact shadow
// scored false shadow along each edge.
TEST_F(GroundTruthSquare, TheRaysStartLeavesASlantedShadowsOutlineWhereItIs) {
    runtime::Light light = scene.lights[0];
    light.direction = glm::vec3(-1.0f, -1.0f, -0.3f);
    const glm::vec3 toLight = -glm::normalize(light.direction);
    // The point of y = 1 straight towards the light from a point of the plane.
    auto inSlantedShadow = [&](const glm::vec3& p) { return inSquareShadow(p + toLight / toLight.y); };
    runtime::GroundTruthOptions options;
    options.normalOffset = 5e-2f;
    const runtime::GroundTruth truth = runtime::ShadowRayCaster(scene).compute(gbuffer, light, options);
    const PlaneComparison plane = compareThePlane(truth, inSlantedShadow);
    EXPECT_EQ(plane.wrong, 0u) << "of " << plane.compared;
    EXPECT_GT(plane.shadowed, 100u);
    EXPECT_GT(plane.compared - plane.shadowed, 1000u);
}

// A light 4 degrees up meets the plane at N.L = 0.07, below the cosine (0.1) at which the rays' start stops
// walking along the ray (10 times the offset at most) and the normal makes up the rest of the height: that
// part moves the outline by (1 - 10 N.L) offset / tan(elevation), 4.3 offsets. At the default offset (1e-4
// of the scene's radius, 8.5e-4 units here) that is 3.7e-3 units, a twentieth of a pixel, inside the pixel
// the comparison leaves out around the outline. A start lifted along the normal alone would move it 3.3
// times as far.
TEST_F(GroundTruthLowSquare, TheRaysStartUnderAGrazingLightLeavesTheOutlineWhereItIs) {
    runtime::Light light = scene.lights[0];
    const float elevation = glm::radians(4.0f);
    light.direction = -glm::vec3(std::cos(elevation), std::sin(elevation), 0.0f);
    const glm::vec3 toLight = -light.direction;
    ASSERT_LT(toLight.y, 0.1f);
    auto inGrazingShadow = [&](const glm::vec3& p) {
        return inSquareShadow(p + toLight * (0.3f / toLight.y));
    };
    const runtime::GroundTruth truth = runtime::ShadowRayCaster(scene).compute(gbuffer, light, {});
    const PlaneComparison plane = compareThePlane(truth, inGrazingShadow);
    EXPECT_EQ(plane.wrong, 0u) << "of " << plane.compared;
    EXPECT_GT(plane.shadowed, 100u) << "the square's shadow, 4.3 units towards -x, should be in view";
    EXPECT_GT(plane.compared - plane.shadowed, 1000u);
}

TEST_F(GroundTruthSquare, AreaLightGivesUmbraPenumbraAndRecordsItsSamples) {
    runtime::Light light = scene.lights[0];
    // A directional light's disk sits two scene radii (~17 units) away: radius 4 gives a ~0.5-unit penumbra.
    light.areaRadius = 4.0f;
    runtime::GroundTruthOptions options;
    options.areaSamples = 256;
    const runtime::ShadowRayCaster caster(scene);
    const runtime::GroundTruth truth = caster.compute(gbuffer, light, options);
    EXPECT_TRUE(truth.soft);
    EXPECT_EQ(truth.samplesPerPixel, 256);
    size_t umbra = 0, lit = 0, penumbra = 0;
    for (size_t i = 0; i < gbuffer.pixelCount(); ++i) {
        if (gbuffer.objectId[i] != 1) continue;
        const glm::vec3 p = gbuffer.position[i];
        const float v = truth.visibility[i];
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
        if (std::abs(p.x) < 0.5f && std::abs(p.z) < 0.5f) {  // deep inside: the whole disk is hidden
            EXPECT_EQ(v, 0.0f);
            ++umbra;
        } else if (std::abs(p.x) > 1.5f || std::abs(p.z) > 1.5f) {  // far outside: all of it is visible
            EXPECT_EQ(v, 1.0f);
            ++lit;
        } else if (v > 0.05f && v < 0.95f) {
            ++penumbra;
        }
    }
    EXPECT_GT(umbra, 20u);
    EXPECT_GT(lit, 1000u);
    EXPECT_GT(penumbra, 100u);
}

TEST(ShadowRayCaster, SegmentQueriesAgreeWithTheBruteForceReference) {
    runtime::Scene scene = squareOverPlane(1.0f);
    const runtime::ShadowRayCaster caster(scene);
    for (float x = -2.0f; x <= 2.0f; x += 0.37f) {
        for (float z = -2.0f; z <= 2.0f; z += 0.41f) {
            const glm::vec3 from(x, 0.01f, z), to(x * 0.5f, 5.0f, z);
            EXPECT_EQ(caster.occluded(from, to - from, 1.0f), runtime::segmentOccluded(scene, from, to))
                << x << ", " << z;
        }
    }
}

}  // namespace
}  // namespace test_ground_truth
