// Perspective shadow maps (runtime/PerspectiveShadowMap.h, Kozlov 2004 §14.2),
// without GL: the light's post-perspective position against
// a far point pushed through an independently built camera projection; casters behind the viewer inside
// the map and in front of their receivers (the inverse projection); clip x, y, w constant along every light
// ray for a dense sweep of light directions; the warp-ratio cap and the slide-back tunable; and no jump in
// the matrices where the fit crosses its thresholds (into the Focused fallback, and L'.w changing sign).
#include "LightFitScenes.h"

#include <runtime/PerspectiveShadowMap.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace test_perspective_shadow_map {

using namespace runtime;

namespace {

using namespace shadowfx::test;  // terrain, fromAngles, finite (LightFitScenes.h)
constexpr float kAspect = kLightFitAspect;

glm::dvec4 clipOf(const LightFit& fit, const glm::vec3& p) {
    return glm::dmat4(fit.projection) * glm::dmat4(fit.view) * glm::dvec4(glm::dvec3(p), 1.0);
}

// focusBody's first half: B's vertices, the receivers. They depend on the camera only, not on the light.
std::vector<glm::vec3> receiversOf(const Scene& scene) {
    const std::vector<glm::vec3> body =
        focusBody(scene.camera, kAspect, scene.bounds(), scene.lights[0].direction);
    return {body.begin(), body.begin() + static_cast<long>(body.size() / 2)};
}

// The largest change of any receiver's light NDC x, y between the fits at two light directions.
double largestMove(const Scene& a, const Scene& b, const std::vector<glm::vec3>& points) {
    const LightFit fa = fitLight(LightParameterization::PSM, a, a.bounds(), kAspect, a.lights[0]);
    const LightFit fb = fitLight(LightParameterization::PSM, b, b.bounds(), kAspect, b.lights[0]);
    double move = 0.0;
    for (const glm::vec3& p : points) {
        const glm::dvec4 ca = clipOf(fa, p), cb = clipOf(fb, p);
        move = std::max({move, std::abs(ca.x / ca.w - cb.x / cb.w), std::abs(ca.y / ca.w - cb.y / cb.w)});
    }
    return move;
}

// Sweeps the light direction `light(angle)` over [from, to] and checks that the fit is continuous:
// consecutive steps move the receivers' light NDC by little, and the largest step shrinks when its
// interval is cut into four (a jump would not).
void expectContinuousSweep(const glm::vec3& view, const std::function<glm::vec3(float)>& light, float from,
                           float to, float step) {
    const std::vector<glm::vec3> points = receiversOf(terrain(view, light(from)));
    double largest = 0.0;
    float where = from;
    for (float a = from; a + step <= to; a += step) {
        const double move = largestMove(terrain(view, light(a)), terrain(view, light(a + step)), points);
        if (move > largest) {
            largest = move;
            where = a;
        }
    }
    // The fade into Focused spans ~1 degree of light direction (closeness 0.02 -> 0) and moves receivers by
    // up to ~1.6 NDC: some 0.2 per 0.02 degree step at its steepest.
    EXPECT_LT(largest, 0.25) << "at " << where;
    double refined = 0.0;
    for (int i = 0; i < 4; ++i) {
        const float a = where + step * float(i) / 4.0f;
        refined = std::max(
            refined, largestMove(terrain(view, light(a)), terrain(view, light(a + step / 4.0f)), points));
    }
    EXPECT_LT(refined, 0.6 * largest + 1e-6) << "a jump at " << where << ": " << largest;
}

}  // namespace

// L' = C (-d, 0) (Kozlov 2004 §14.2.1): the light is where a point far along -d lands under the camera's
// projection. Built here independently in double precision: the virtual camera slid back by sqrt(z_n z_f)
// of B's receiver depths (the automatic slide-back), near plane at the nearest receiver.
TEST(PerspectiveShadowMap, LightInPostPerspectiveSpaceIsTheImageOfAFarPoint) {
    const glm::vec3 view = fromAngles(-30.0f, 20.0f);
    for (float elevation : {-10.0f, -45.0f, -80.0f})
        for (float azimuth : {0.0f, 60.0f, 150.0f, 200.0f, 300.0f}) {
            const Scene scene = terrain(view, fromAngles(elevation, azimuth));
            const Light& light = scene.lights[0];
            PsmDetails details;
            const LightFit fit =
                fitPerspectiveShadowMap(scene, scene.bounds(), kAspect, light, LightTunables{}, &details);
            ASSERT_TRUE(finite(fit.projection) && finite(fit.view));
            const std::string what = std::to_string(elevation) + "/" + std::to_string(azimuth);

            const glm::dvec3 eye(scene.camera.position), forward = glm::normalize(glm::dvec3(view));
            double zMin = 1e30, zMax = -1e30;
            for (const glm::vec3& p : receiversOf(scene)) {
                zMin = std::min(zMin, glm::dot(glm::dvec3(p) - eye, forward));
                zMax = std::max(zMax, glm::dot(glm::dvec3(p) - eye, forward));
            }
            zMin = std::max(zMin, double(scene.camera.nearPlane));
            const double slide = std::sqrt(zMin * zMax);
            EXPECT_NEAR(details.slideBack, slide, 1e-4 * slide) << what;
            EXPECT_NEAR(details.nearPlane, zMin + slide, 1e-4 * (zMin + slide)) << what;
            EXPECT_NEAR(details.farPlane, zMax + slide, 1e-4 * (zMax + slide)) << what;

            const glm::dvec3 apex = eye - slide * forward;
            const glm::dmat4 camera = glm::perspectiveLH_ZO(double(scene.camera.fovY), double(kAspect),
                                                            zMin + slide, zMax + slide) *
                                      glm::lookAtLH(apex, apex + forward, glm::dvec3(0.0, 1.0, 0.0));
            const glm::dvec4 far = camera * glm::dvec4(eye - 1e7 * glm::dvec3(light.direction), 1.0);
            const glm::dvec4& ours = details.lightPostPerspective;
            const glm::dvec3 expected = glm::dvec3(far) / far.w, actual = glm::dvec3(ours) / ours.w;
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(actual[axis], expected[axis], 1e-3 * (1.0 + std::abs(expected[axis]))) << what;
            // Inverted (w < 0) exactly when the light comes from behind the viewer.
            EXPECT_EQ(ours.w<0.0, glm::dot(glm::dvec3(light.direction), forward)> 0.0) << what;
        }
}

// Kozlov 2004 §14.2.1: casters behind the viewer, beyond infinity in post-perspective space, must still land
// in the map (Kozlov's inverse projection). The sun shines from behind and above the camera; the body's
// extrusion reaches back to the bounds 20 m behind the eye.
TEST(PerspectiveShadowMap, CastersBehindTheViewerLandInTheMapInFrontOfTheirReceivers) {
    const glm::vec3 view = fromAngles(-10.0f, 0.0f);
    for (const glm::vec3& lightDir :
         {fromAngles(-30.0f, 0.0f), fromAngles(-20.0f, 40.0f), fromAngles(-60.0f, -30.0f)}) {
        const Scene scene = terrain(view, lightDir);
        const Light& light = scene.lights[0];
        PsmDetails details;
        const LightFit fit =
            fitPerspectiveShadowMap(scene, scene.bounds(), kAspect, light, LightTunables{}, &details);
        EXPECT_LT(details.lightPostPerspective.w, 0.0);  // the light is inverted in post-perspective space
        EXPECT_LT(details.focusedWeight, 1.0);           // and PSM, not its fallback, maps it
        const std::vector<glm::vec3> body = focusBody(scene.camera, kAspect, scene.bounds(), light.direction);
        const size_t receivers = body.size() / 2;
        int behind = 0;
        for (size_t i = 0; i < receivers; ++i) {
            const glm::vec3& caster = body[receivers + i];
            if (glm::dot(caster - scene.camera.position, view) >= -1.0f) continue;
            ++behind;  // at least 1 m behind the eye: w < 0 under the camera's projection
            const glm::dvec4 c = clipOf(fit, caster), r = clipOf(fit, body[i]);
            ASSERT_GT(c.w, 0.0);
            EXPECT_LE(std::abs(c.x), c.w * (1.0 + 1e-6));
            EXPECT_LE(std::abs(c.y), c.w * (1.0 + 1e-6));
            EXPECT_GE(c.z, -1e-6 * c.w);
            EXPECT_LE(c.z, c.w * (1.0 + 1e-6));
            EXPECT_NEAR(c.x / c.w, r.x / r.w, 1e-4);  // the receiver's texel
            EXPECT_NEAR(c.y / c.w, r.y / r.w, 1e-4);
            EXPECT_LT(c.z / c.w, r.z / r.w);  // and nearer the light
        }
        EXPECT_GE(behind, 2);
    }
}

// For light directions every 10 degrees (poles, parallel and perpendicular to the view included) and three
// camera directions, straight down among them: finite matrices, the body inside the clip volume, and every
// caster on its receiver's texel and nearer the light (depth linear along the ray, w constant).
TEST(PerspectiveShadowMap, DenseSweepKeepsTheBodyInsideAndDepthOrderedAlongLightRays) {
    for (const glm::vec3& view :
         {fromAngles(0.0f, 0.0f), fromAngles(-30.0f, 20.0f), glm::vec3(0.0f, -1.0f, 0.0f)})
        for (float elevation = -90.0f; elevation <= 90.0f; elevation += 10.0f)
            for (float azimuth = 0.0f; azimuth < 360.0f; azimuth += 10.0f) {
                const Scene scene = terrain(view, fromAngles(elevation, azimuth));
                const Light& light = scene.lights[0];
                const LightFit fit =
                    fitLight(LightParameterization::PSM, scene, scene.bounds(), kAspect, light);
                const std::string what = std::to_string(elevation) + "/" + std::to_string(azimuth);
                ASSERT_TRUE(finite(fit.view) && finite(fit.projection)) << what;
                const std::vector<glm::vec3> body =
                    focusBody(scene.camera, kAspect, scene.bounds(), light.direction);
                const size_t receivers = body.size() / 2;
                for (size_t i = 0; i < body.size(); ++i) {
                    const glm::dvec4 c = clipOf(fit, body[i]);
                    ASSERT_GT(c.w, 0.0) << what;
                    EXPECT_LE(std::abs(c.x), c.w * (1.0 + 1e-5)) << what;
                    EXPECT_LE(std::abs(c.y), c.w * (1.0 + 1e-5)) << what;
                    EXPECT_GE(c.z, -1e-5 * c.w) << what;
                    EXPECT_LE(c.z, c.w * (1.0 + 1e-5)) << what;
                    if (i >= receivers) continue;
                    const glm::dvec4 e = clipOf(fit, body[receivers + i]);
                    EXPECT_NEAR(e.w, c.w, 1e-4 * c.w) << what;
                    EXPECT_NEAR(e.x / e.w, c.x / c.w, 5e-4) << what;  // float matrices
                    EXPECT_LE(e.z / e.w, c.z / c.w + 1e-6) << what;
                }
            }
}

// PSMMaxWarpRatio caps the ratio of the light clip w over B's receivers; PSMSlideBack sets the virtual
// camera, and a very long slide-back leaves an almost orthographic map (w nearly constant).
TEST(PerspectiveShadowMap, TunablesCapTheWarpAndSlideTheCameraBack) {
    const Scene scene = terrain(fromAngles(-10.0f, 0.0f), fromAngles(-45.0f, 90.0f));
    const std::vector<glm::vec3> receivers = receiversOf(scene);
    auto wRatio = [&](const LightTunables& tunables, PsmDetails& details) {
        const LightFit fit =
            fitPerspectiveShadowMap(scene, scene.bounds(), kAspect, scene.lights[0], tunables, &details);
        double lo = 1e30, hi = 0.0;
        for (const glm::vec3& p : receivers) {
            lo = std::min(lo, clipOf(fit, p).w);
            hi = std::max(hi, clipOf(fit, p).w);
        }
        return hi / lo;
    };
    PsmDetails details;
    const double automatic = wRatio(LightTunables{}, details);
    EXPECT_EQ(details.focusedWeight, 0.0);
    EXPECT_GT(automatic, 10.0);  // a real perspective: near receivers get many more texels than far ones
    LightTunables capped;
    capped.psmMaxWarpRatio = 4.0f;
    EXPECT_NEAR(wRatio(capped, details), 4.0, 1e-3);
    LightTunables longSlide;
    longSlide.psmSlideBack = 1e5f;
    EXPECT_LT(wRatio(longSlide, details), 1.01);
    EXPECT_DOUBLE_EQ(details.slideBack, 1e5);
    LightTunables noSlide;
    noSlide.psmSlideBack = 0.0f;
    wRatio(LightTunables{}, details);
    const double closeness = details.closeness;
    wRatio(noSlide, details);
    EXPECT_DOUBLE_EQ(details.slideBack, 0.0);
    // Without slide-back (z_n = 0.1 m, z_f ~ 180 m) the light sits ~1e-3 from the unit cube: far closer to
    // the receivers than with it (Kozlov 2004 §14.2.2), so close that the fit has faded into Focused.
    EXPECT_LT(details.closeness, 0.5 * closeness);
    EXPECT_GT(details.focusedWeight, 0.9);
}

// The fallback: where the light in post-perspective space comes so close to the receivers that w would
// reach 0 on them, the fit is exactly Focused's; between, it blends. Sweeping the light across that region
// (and across L'.w = 0, the light perpendicular to the view) moves no receiver's texel by a jump.
TEST(PerspectiveShadowMap, FallbackIntoFocusedAndLightWSignChangeHaveNoJump) {
    const glm::vec3 view = fromAngles(-30.0f, 0.0f);
    // The sun 10 degrees high from behind the viewer, 30 degrees aside: its post-perspective image lies just
    // beyond the far face of the unit cube, among the receivers' directions.
    const Scene close = terrain(view, fromAngles(-10.0f, 30.0f));
    PsmDetails details;
    const LightFit fallback =
        fitPerspectiveShadowMap(close, close.bounds(), kAspect, close.lights[0], LightTunables{}, &details);
    ASSERT_EQ(details.focusedWeight, 1.0);
    const LightFit focused =
        fitLight(LightParameterization::Focused, close, close.bounds(), kAspect, close.lights[0]);
    for (const glm::vec3& p : receiversOf(close)) {
        const glm::dvec4 a = clipOf(fallback, p), b = clipOf(focused, p);
        EXPECT_NEAR(a.x / a.w, b.x / b.w, 5e-3);
        EXPECT_NEAR(a.y / a.w, b.y / b.w, 5e-3);
    }
    const Scene open = terrain(view, fromAngles(-10.0f, 45.0f));
    fitPerspectiveShadowMap(open, open.bounds(), kAspect, open.lights[0], LightTunables{}, &details);
    ASSERT_EQ(details.focusedWeight, 0.0);
    expectContinuousSweep(
        view, [](float azimuth) { return fromAngles(-10.0f, azimuth); }, 30.0f, 45.0f, 0.02f);

    // L'.w changes sign at elevation -60, azimuth 180 (the light perpendicular to the view): a normal light
    // above it, an inverted one below.
    PsmDetails before, after;
    const Scene a = terrain(view, fromAngles(-55.0f, 180.0f)), b = terrain(view, fromAngles(-65.0f, 180.0f));
    fitPerspectiveShadowMap(a, a.bounds(), kAspect, a.lights[0], LightTunables{}, &before);
    fitPerspectiveShadowMap(b, b.bounds(), kAspect, b.lights[0], LightTunables{}, &after);
    ASSERT_LT(before.lightPostPerspective.w * after.lightPostPerspective.w, 0.0);
    expectContinuousSweep(
        view, [](float elevation) { return fromAngles(elevation, 180.0f); }, -65.0f, -55.0f, 0.02f);
}

// Spot and point lights keep their own perspective (the uniform fit).
TEST(PerspectiveShadowMap, SpotLightsKeepTheUniformFit) {
    Scene scene = terrain(fromAngles(0.0f, 0.0f), {0.0f, -1.0f, 0.0f});
    scene.lights[0].type = Light::Type::Spot;
    scene.lights[0].position = {0.0f, 60.0f, 0.0f};
    const LightFit uniform =
        fitLight(LightParameterization::Uniform, scene, scene.bounds(), kAspect, scene.lights[0]);
    const LightFit psm =
        fitLight(LightParameterization::PSM, scene, scene.bounds(), kAspect, scene.lights[0]);
    EXPECT_EQ(uniform.view, psm.view);
    EXPECT_EQ(uniform.projection, psm.projection);
}
}  // namespace test_perspective_shadow_map
