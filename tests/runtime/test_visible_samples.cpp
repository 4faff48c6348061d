// Fits to what the camera sees (runtime/VisibleSamples.h; sample distribution shadow maps, Lauritzen et al.
// 2011): a position read-back made from a known depth buffer reduces to that buffer's depth range and box,
// computed here independently in double; the cascade splits divide the visible range by the practical split
// scheme; the focused, LiSPSM and cascaded fits hold every visible sample inside their clip volume and
// spend their texels on it (a finer map than the unfitted one where the camera sees a small part of B).
#include <runtime/CascadedShadowMaps.h>
#include <runtime/LightParameterization.h>
#include <runtime/VisibleSamples.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace test_visible_samples {

using namespace runtime;

namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr float kAspect = static_cast<float>(kWidth) / static_cast<float>(kHeight);

// A camera 2 m above a 200 m ground, looking level along +z at a wall 15 m away that hides the rest of the
// ground; B (view frustum ∩ bounds) reaches 100 m.
Scene wallScene() {
    Scene scene;
    scene.name = "wall";
    SceneObject ground;
    ground.mesh = std::make_shared<Mesh>(makePlane(200.0f, 200.0f));
    scene.objects.push_back(ground);
    SceneObject wall;
    wall.mesh = std::make_shared<Mesh>(makeBox(glm::vec3(80.0f, 30.0f, 1.0f)));
    wall.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 15.0f, 15.5f));
    scene.objects.push_back(wall);
    scene.camera.position = {0.0f, 2.0f, 0.0f};
    scene.camera.target = {0.0f, 1.5f, 10.0f};
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 500.0f;
    Light sun;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    scene.lights.push_back(sun);
    return scene;
}

// A depth buffer: each pixel's view depth, 0 for the background (the top rows).
float knownDepth(int x, int y) {
    if (y < kHeight / 4) return 0.0f;
    return 3.0f + 0.25f * static_cast<float>(x) + 0.125f * static_cast<float>(y);
}

// The read-back the pre-pass would give for knownDepth: each covered pixel's world position on its ray.
std::vector<float> positionsFromDepth(const Camera& camera) {
    const glm::mat4 toWorld = glm::inverse(camera.view());
    const float tanY = std::tan(0.5f * camera.fovY), tanX = tanY * kAspect;
    std::vector<float> positions;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float depth = knownDepth(x, y);
            const float u = 2.0f * (static_cast<float>(x) + 0.5f) / kWidth - 1.0f;
            const float v = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / kHeight;
            const glm::vec4 world = toWorld * glm::vec4(u * tanX * depth, v * tanY * depth, depth, 1.0f);
            positions.insert(positions.end(), {world.x, world.y, world.z, depth > 0.0f ? 1.0f : 0.0f});
        }
    return positions;
}

TEST(VisibleSamples, ReduceToTheDepthRangeAndBoxOfAKnownDepthBuffer) {
    Camera camera;
    camera.position = {1.0f, 4.0f, -3.0f};
    camera.target = {2.0f, 1.0f, 6.0f};
    const std::vector<float> positions = positionsFromDepth(camera);
    const std::optional<VisibleSamples> samples = reduceVisibleSamples(positions, camera);
    ASSERT_TRUE(samples);

    double nearest = std::numeric_limits<double>::max(), farthest = 0.0;
    size_t covered = 0;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double depth = knownDepth(x, y);
            if (depth <= 0.0) continue;
            ++covered;
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
            const size_t i = 4 * (static_cast<size_t>(y) * kWidth + static_cast<size_t>(x));
            const glm::dvec3 p(positions[i], positions[i + 1], positions[i + 2]);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    EXPECT_EQ(samples->count, covered);
    EXPECT_NEAR(samples->nearDepth, nearest, 1e-4 * farthest);  // 3 + 0.125 · 12 = 4.5
    EXPECT_NEAR(samples->farDepth, farthest, 1e-4 * farthest);  // 3 + 0.25 · 63 + 0.125 · 47
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(samples->box.min[axis], lo[axis], 1e-5);
        EXPECT_NEAR(samples->box.max[axis], hi[axis], 1e-5);
    }

    // The fits' camera brackets the range by a margin of 0.1 % of it, inside the camera's own planes.
    const Camera tight = cameraOverSamples(camera, *samples);
    EXPECT_LE(tight.nearPlane, samples->nearDepth);
    EXPECT_GT(tight.nearPlane, 0.99f * samples->nearDepth);
    EXPECT_GE(tight.farPlane, samples->farDepth);
    EXPECT_LT(tight.farPlane, 1.01f * samples->farDepth);
}

TEST(VisibleSamples, NothingSeenOrANonFinitePositionGivesNoSamples) {
    Camera camera;
    EXPECT_FALSE(reduceVisibleSamples(std::vector<float>(4 * 16, 0.0f), camera));
    std::vector<float> positions = {1.0f, 2.0f, 3.0f, 1.0f, std::nanf(""), 0.0f, 0.0f, 1.0f};
    EXPECT_FALSE(reduceVisibleSamples(positions, camera));
}

TEST(VisibleSamples, CascadeSplitsDivideTheVisibleDepthRange) {
    Scene scene = wallScene();
    const std::vector<float> positions = positionsFromDepth(scene.camera);
    const std::optional<VisibleSamples> samples = reduceVisibleSamples(positions, scene.camera);
    ASSERT_TRUE(samples);
    LightTunables tunables;
    tunables.cascadeCount = 4;
    tunables.cascadeSplitLambda = 0.5f;
    tunables.cascadeBlend = 0.0f;
    const LightFit fit = fitCascades(scene, scene.bounds(), kAspect, scene.lights[0], tunables, &*samples);
    ASSERT_EQ(fit.cascades.size(), 4u);
    // The range's ends: the visible range with its margin, rounded outward by at most one 2^(1/16) step.
    const double step = std::exp2(1.0 / 16.0);
    const double start = fit.cascades.front().splitNear, end = fit.cascades.back().splitFar;
    EXPECT_LE(start, samples->nearDepth);
    EXPECT_GE(start, samples->nearDepth / step * 0.99);
    EXPECT_GE(end, samples->farDepth);
    EXPECT_LE(end, samples->farDepth * step * 1.01);
    // Zhang et al. 2006's practical scheme between those ends, in double.
    for (int i = 1; i < 4; ++i) {
        const double t = i / 4.0;
        const double expected = 0.5 * start * std::pow(end / start, t) + 0.5 * (start + (end - start) * t);
        EXPECT_NEAR(fit.cascades[static_cast<size_t>(i) - 1].splitFar, expected, 1e-4 * end) << "split " << i;
    }
    // Unfitted, the splits run from the near plane to the bounds' far corner (beyond 100 m).
    const LightFit unfitted = fitCascades(scene, scene.bounds(), kAspect, scene.lights[0], tunables);
    EXPECT_GT(unfitted.cascades.back().splitFar, 100.0f);
    EXPECT_FLOAT_EQ(unfitted.cascades.front().splitNear, scene.camera.nearPlane);
}

// Points of `positions` (covered pixels) inside the clip volume of view x projection (D3D: |x|, |y| <= w,
// 0 <= z <= w), with a tolerance of 1e-4 w.
bool samplesInside(const std::vector<float>& positions, const glm::mat4& viewProjection) {
    for (size_t i = 0; i + 3 < positions.size(); i += 4) {
        if (!(positions[i + 3] > 0.0f)) continue;
        const glm::vec4 clip =
            viewProjection * glm::vec4(positions[i], positions[i + 1], positions[i + 2], 1.0f);
        const float tolerance = 1e-4f * std::abs(clip.w);
        if (!(clip.w > 0.0f) || std::abs(clip.x) > clip.w + tolerance ||
            std::abs(clip.y) > clip.w + tolerance || clip.z < -tolerance || clip.z > clip.w + tolerance)
            return false;
    }
    return true;
}

// The map's area in world units across the light (orthographic fits: the inverse of the x and y scales).
// The area of the light's map in world units², from its view and projection (a fit's or one cascade's).
double mapArea(const glm::mat4& view, const glm::mat4& projection) {
    const glm::mat4 m = projection * view;
    const double sx = glm::length(glm::vec3(m[0][0], m[1][0], m[2][0]));
    const double sy = glm::length(glm::vec3(m[0][1], m[1][1], m[2][1]));
    return (2.0 / sx) * (2.0 / sy);
}
double mapArea(const LightFit& fit) {
    return mapArea(fit.view, fit.projection);
}

TEST(VisibleSamples, FitsHoldEverySampleAndSpendTheMapOnThem) {
    Scene scene = wallScene();
    // The wall scene's own depth buffer: the ground to the wall, the wall itself (15 m) above it.
    std::vector<float> positions;
    {
        const Camera& camera = scene.camera;
        const glm::mat4 toWorld = glm::inverse(camera.view());
        const float tanY = std::tan(0.5f * camera.fovY), tanX = tanY * kAspect;
        const glm::vec3 eye = camera.position;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const float u = 2.0f * (static_cast<float>(x) + 0.5f) / kWidth - 1.0f;
                const float v = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / kHeight;
                const glm::vec3 direction = glm::vec3(toWorld * glm::vec4(u * tanX, v * tanY, 1.0f, 0.0f));
                const float toGround = direction.y < 0.0f ? -eye.y / direction.y : 1e9f;
                const float toWall = direction.z > 0.0f ? (15.0f - eye.z) / direction.z : 1e9f;
                const glm::vec3 p = eye + std::min(toGround, toWall) * direction;
                positions.insert(positions.end(), {p.x, p.y, p.z, 1.0f});
            }
    }
    const std::optional<VisibleSamples> samples = reduceVisibleSamples(positions, scene.camera);
    ASSERT_TRUE(samples);
    EXPECT_LT(samples->farDepth, 16.0f);
    for (LightParameterization method :
         {LightParameterization::Focused, LightParameterization::LiSPSM, LightParameterization::Cascaded}) {
        SCOPED_TRACE(lightParameterizationName(method));
        const LightFit fitted =
            fitLight(method, scene, scene.bounds(), kAspect, scene.lights[0], LightTunables{}, &*samples);
        const LightFit unfitted = fitLight(method, scene, scene.bounds(), kAspect, scene.lights[0]);
        EXPECT_TRUE(samplesInside(positions, fitted.projection * fitted.view));
        for (const LightView& cascade : fitted.cascades) {
            // Each cascade holds the samples of its slice of the view depth.
            std::vector<float> slice;
            const glm::vec3 viewDir = glm::normalize(scene.camera.target - scene.camera.position);
            for (size_t i = 0; i < positions.size(); i += 4) {
                const glm::vec3 p(positions[i], positions[i + 1], positions[i + 2]);
                const float depth = glm::dot(p - scene.camera.position, viewDir);
                if (depth >= cascade.splitNear && depth <= cascade.splitFar)
                    slice.insert(slice.end(), {p.x, p.y, p.z, 1.0f});
            }
            EXPECT_TRUE(samplesInside(slice, cascade.projection * cascade.view));
        }
        if (method == LightParameterization::Focused) {
            // B reaches the bounds 100 m out; the samples end at the wall: a map of a tenth of the area.
            EXPECT_LT(mapArea(fitted), 0.1 * mapArea(unfitted));
        }
        if (method == LightParameterization::Cascaded) {
            EXPECT_LT(mapArea(fitted.cascades.back().view, fitted.cascades.back().projection),
                      0.1 * mapArea(unfitted.cascades.back().view, unfitted.cascades.back().projection));
        }
    }
}

}  // namespace
}  // namespace test_visible_samples
