// Light-space parameterizations (runtime/LightParameterization.h): for a grid of camera and light
// directions, degenerate ones included, every matrix is finite and every point of the focus body (B and
// its extrusion toward the light) lies inside the light's clip volume; LiSPSM's n_opt matches Scherzer 2005
// eq. 1 computed independently and fades into the focused fit as the light turns parallel to the view.
#include "LightFitScenes.h"

#include <runtime/CascadedShadowMaps.h>
#include <runtime/LightParameterization.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace test_light_parameterizations {

using namespace runtime;

namespace {

using namespace shadowfx::test;  // terrain, fromAngles, finite (LightFitScenes.h)
constexpr float kAspect = kLightFitAspect;
constexpr LightParameterization kMethods[] = {LightParameterization::Uniform, LightParameterization::Focused,
                                              LightParameterization::LiSPSM,  LightParameterization::TSM,
                                              LightParameterization::PSM,     LightParameterization::PSMCube,
                                              LightParameterization::Cascaded};

// The grid: camera directions (level, tilted down, straight down) x light directions (low, oblique,
// straight down, straight up, parallel and antiparallel to the view).
struct Configuration {
    std::string name;
    glm::vec3 view;
    glm::vec3 light;
};

std::vector<Configuration> grid() {
    std::vector<Configuration> cases;
    const std::vector<std::pair<std::string, glm::vec3>> views = {
        {"level", fromAngles(0.0f, 0.0f)},
        {"level-east", fromAngles(0.0f, 90.0f)},
        {"down-30", fromAngles(-30.0f, 20.0f)},
        {"straight-down", {0.0f, -1.0f, 0.0f}},
    };
    for (const auto& [viewName, view] : views) {
        std::vector<std::pair<std::string, glm::vec3>> lights = {
            {"straight-down", {0.0f, -1.0f, 0.0f}},
            {"straight-up", {0.0f, 1.0f, 0.0f}},
            {"parallel", view},
            {"antiparallel", -view},
            {"nearly-parallel", glm::normalize(view + glm::vec3(1e-4f, 0.0f, 0.0f))},
        };
        for (float elevation : {-10.0f, -45.0f, -80.0f})
            for (float azimuth : {0.0f, 90.0f, 135.0f, 180.0f})
                lights.push_back({"e" + std::to_string(int(elevation)) + "a" + std::to_string(int(azimuth)),
                                  fromAngles(elevation, azimuth)});
        for (const auto& [lightName, light] : lights)
            cases.push_back({viewName + "/" + lightName, view, light});
    }
    return cases;
}

}  // namespace

TEST(LightParameterizations, NamesParseCaseInsensitively) {
    EXPECT_EQ(parseLightParameterization("lispsm"), LightParameterization::LiSPSM);
    EXPECT_EQ(parseLightParameterization("Focused"), LightParameterization::Focused);
    EXPECT_EQ(parseLightParameterization("UNIFORM"), LightParameterization::Uniform);
    EXPECT_EQ(parseLightParameterization("tsm"), LightParameterization::TSM);
    EXPECT_EQ(parseLightParameterization("psm"), LightParameterization::PSM);
    EXPECT_EQ(parseLightParameterization("PSMcube"), LightParameterization::PSMCube);
    EXPECT_EQ(parseLightParameterization("cascaded"), LightParameterization::Cascaded);
    EXPECT_FALSE(parseLightParameterization("Trapezoidal").has_value());
}

TEST(LightParameterizations, FocusBodyLiesInsideEveryLightClipVolume) {
    for (const Configuration& c : grid()) {
        const Scene scene = terrain(c.view, c.light);
        const Bounds bounds = scene.bounds();
        const std::vector<glm::vec3> body =
            focusBody(scene.camera, kAspect, bounds, scene.lights[0].direction);
        ASSERT_FALSE(body.empty()) << c.name;
        for (LightParameterization method : kMethods) {
            const LightFit fit = fitLight(method, scene, bounds, kAspect, scene.lights[0]);
            const std::string what = c.name + " " + lightParameterizationName(method);
            ASSERT_TRUE(finite(fit.view) && finite(fit.projection)) << what;
            for (const glm::vec3& p : body) {
                const glm::vec4 clip = fit.projection * fit.view * glm::vec4(p, 1.0f);
                const float tolerance = 1e-5f * std::abs(clip.w);
                ASSERT_GT(clip.w, 0.0f) << what;
                EXPECT_LE(std::abs(clip.x), clip.w + tolerance) << what;
                EXPECT_LE(std::abs(clip.y), clip.w + tolerance) << what;
                EXPECT_GE(clip.z, -tolerance) << what;
                EXPECT_LE(clip.z, clip.w + tolerance) << what;
            }
        }
    }
}

// The focus must be tighter than the uniform fit: B's light-space area grows when it is focused on.
TEST(LightParameterizations, FocusingSpendsMoreOfTheMapOnB) {
    const Scene scene = terrain(fromAngles(0.0f, 0.0f), fromAngles(-45.0f, 90.0f));
    const Bounds bounds = scene.bounds();
    const std::vector<glm::vec3> body = focusBody(scene.camera, kAspect, bounds, scene.lights[0].direction);
    auto extent = [&](LightParameterization method) {
        const LightFit fit = fitLight(method, scene, bounds, kAspect, scene.lights[0]);
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& p : body) {
            const glm::vec4 clip = fit.projection * fit.view * glm::vec4(p, 1.0f);
            lo = glm::min(lo, glm::vec2(clip) / clip.w);
            hi = glm::max(hi, glm::vec2(clip) / clip.w);
        }
        return (hi.x - lo.x) * (hi.y - lo.y);
    };
    EXPECT_LT(extent(LightParameterization::Uniform), 0.5f * extent(LightParameterization::Focused));
    EXPECT_GT(extent(LightParameterization::Focused), 3.9f);  // B fills the map: [-1, 1]²
}

// Scherzer 2005 §4.4 eq. 1 , in double precision from z_n, z_f:
// n_opt = (z_n + sqrt(z_n z_f)) / sin γ with z_f = z_n + Δz.
TEST(LightParameterizations, LispsmWarpIsTheReciprocalOfNopt) {
    for (double zn : {0.1, 1.0, 5.0})
        for (double dz : {0.0, 10.0, 100.0})
            for (double gamma : {5.0, 45.0, 90.0}) {
                const double sinGamma = std::sin(gamma * glm::pi<double>() / 180.0);
                const double zf = zn + dz;
                const double nopt = (zn + std::sqrt(zn * zf)) / sinGamma;
                EXPECT_NEAR(lispsmWarp(float(zn), float(dz), float(sinGamma)), 1.0 / nopt, 1e-6 / nopt);
            }
    EXPECT_EQ(lispsmWarp(0.1f, 100.0f, 0.0f), 0.0f);  // γ = 0: no warp rather than n = ∞
}

// fitLight's warp is 1 / n_opt with d the extent of B along V_P and Δz = d sin γ (the reference code), all
// recomputed here from the body and the directions.
TEST(LightParameterizations, LispsmFitUsesNoptOfTheBody) {
    for (float elevation : {-20.0f, -60.0f}) {
        const glm::vec3 view = fromAngles(-10.0f, 0.0f);
        const Scene scene = terrain(view, fromAngles(elevation, 30.0f));
        const Bounds bounds = scene.bounds();
        const glm::vec3 light = scene.lights[0].direction;
        const glm::vec3 vp = glm::normalize(glm::cross(glm::cross(light, view), light));  // eq. 3
        const double sinGamma = glm::length(glm::cross(light, view));
        double lo = 1e30, hi = -1e30;
        for (const glm::vec3& p : focusBody(scene.camera, kAspect, bounds, light)) {
            lo = std::min(lo, double(glm::dot(p, vp)));
            hi = std::max(hi, double(glm::dot(p, vp)));
        }
        const double zn = scene.camera.nearPlane;
        const double nopt = (zn + std::sqrt(zn * (zn + (hi - lo) * sinGamma))) / sinGamma;
        LightTunables scherzer;
        scherzer.lispsmN = LispsmN::Scherzer2005;
        const LightFit fit =
            fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect, scene.lights[0], scherzer);
        EXPECT_NEAR(1.0 / fit.warp, nopt, 1e-3 * nopt) << elevation;
        LightTunables visible =
            scherzer;  // Δz from a visibility algorithm replaces d sin γ (Scherzer 2005 §4.4)
        visible.lispsmDepthExtent = 50.0f;
        const double noptVisible = (zn + std::sqrt(zn * (zn + 50.0))) / sinGamma;
        EXPECT_NEAR(
            1.0 / fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect, scene.lights[0], visible)
                      .warp,
            noptVisible, 1e-3 * noptVisible);
        LightTunables weaker = scherzer;
        weaker.lispsmNScale = 2.0f;
        EXPECT_NEAR(
            1.0 /
                fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect, scene.lights[0], weaker).warp,
            2.0 * nopt, 2e-3 * nopt);
    }
}

// LispsmN::Wimmer2004 (the default): Wimmer, Scherzer & Purgathofer 2004's n_opt = (z_n + sqrt(z_n z_f)) /
// sin γ with z_n, z_f the view-space depth range of B, recomputed here in double from the camera and B's
// vertices (the first half of focusBody). The camera stands 30 m outside the terrain box looking across it,
// so B begins far beyond the near plane and the two choices differ: Wimmer 2004's z_n is B's, and its warp is
// weaker.
TEST(LightParameterizations, LispsmWimmer2004UsesTheDepthRangeOfB) {
    for (float elevation : {-5.0f, -20.0f, -60.0f}) {
        const glm::vec3 view = fromAngles(-10.0f, 0.0f);
        Scene scene = terrain(view, fromAngles(elevation, 30.0f));
        scene.camera.position = {0.0f, 12.0f, -130.0f};
        scene.camera.target = scene.camera.position + view;
        scene.camera.farPlane = 150.0f;
        const Bounds bounds = scene.bounds();
        const glm::vec3 light = scene.lights[0].direction;
        const double sinGamma = glm::length(glm::cross(light, view));
        const std::vector<glm::vec3> body = focusBody(scene.camera, kAspect, bounds, light);
        double zn = 1e30, zf = -1e30;
        for (size_t i = 0; i < body.size() / 2; ++i) {
            const double depth = glm::dot(glm::dvec3(body[i] - scene.camera.position), glm::dvec3(view));
            zn = std::min(zn, depth);
            zf = std::max(zf, depth);
        }
        ASSERT_GT(zn, 20.0) << "the camera must see B begin far beyond its near plane";
        const double nopt = (zn + std::sqrt(zn * zf)) / sinGamma;
        const LightFit fit = fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect, scene.lights[0]);
        EXPECT_NEAR(1.0 / fit.warp, nopt, 1e-3 * nopt) << elevation;  // the default
        LightTunables scherzerTunables;
        scherzerTunables.lispsmN = LispsmN::Scherzer2005;
        const LightFit scherzer = fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect,
                                           scene.lights[0], scherzerTunables);
        EXPECT_GT(scherzer.warp, 2.0f * fit.warp) << elevation;
        // Still a fit: B and its extrusion inside the clip volume.
        for (const glm::vec3& p : body) {
            const glm::vec4 clip = fit.projection * fit.view * glm::vec4(p, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            for (int axis = 0; axis < 3; ++axis) {
                const float ndc = clip[axis] / clip.w;
                EXPECT_GE(ndc, axis == 2 ? -1e-3f : -1.0f - 1e-3f);
                EXPECT_LE(ndc, 1.0f + 1e-3f);
            }
        }
    }
    EXPECT_EQ(parseLispsmN("wimmer2004"), LispsmN::Wimmer2004);
    EXPECT_EQ(parseLispsmN("Scherzer2005"), LispsmN::Scherzer2005);
    EXPECT_EQ(parseLispsmN("lloyd2006"), LispsmN::Lloyd2006);
    EXPECT_FALSE(parseLispsmN("Lloyd"));
}

// Lloyd et al. 2006's parameterization, recomputed in double for a light across the view (γ = 90°, where
// d = z_f - z_n) from z_n and z_f directly, not through n_opt as lloydWarp does: n' = n / d with α = z_f /
// z_n is (1 + √α - η (α - 1)) / ((α - 1)(η + 1)) for η < 0 and 1 / ((√α - 1)(η √α + 1)) for η >= 0. Its
// anchors are the algorithms it moves between: Wimmer et al. 2004's n_opt = z_n + √(z_n z_f) at η = 0, PSM's
// projection centre at the eye (n = z_n) at η = 1, no warp (the uniform map) at η = -1.
TEST(LightParameterizations, LloydWarpMovesFromUniformThroughLispsmToPsm) {
    for (double zn : {0.1, 2.0, 10.0})
        for (double zf : {20.0, 80.0, 500.0}) {
            const double d = zf - zn, alpha = zf / zn, root = std::sqrt(alpha);
            const double nopt = zn + std::sqrt(zn * zf);
            const float optimalWarp = lispsmWarp(float(zn), float(d), 1.0f);
            for (double eta : {-0.9, -0.5, -0.2, 0.0, 0.3, 0.6, 1.0}) {
                const double nPrime = eta < 0.0
                                          ? (1.0 + root - eta * (alpha - 1.0)) / ((alpha - 1.0) * (eta + 1.0))
                                          : 1.0 / ((root - 1.0) * (eta * root + 1.0));
                const double n = d * nPrime;
                EXPECT_NEAR(lloydWarp(optimalWarp, float(d), float(eta)), 1.0 / n, 1e-4 / n)
                    << "z_n " << zn << ", z_f " << zf << ", η " << eta;
            }
            EXPECT_EQ(lloydWarp(optimalWarp, float(d), 0.0f), optimalWarp);
            EXPECT_NEAR(1.0 / lloydWarp(optimalWarp, float(d), 0.0f), nopt, 1e-4 * nopt);
            EXPECT_NEAR(1.0 / lloydWarp(optimalWarp, float(d), 1.0f), zn, 1e-3 * zn);
            EXPECT_EQ(lloydWarp(optimalWarp, float(d), -1.0f), 0.0f);
            float previous = 0.0f;  // the warp strengthens with η
            for (int step = -99; step <= 100; ++step) {
                const float warp = lloydWarp(optimalWarp, float(d), step / 100.0f);
                EXPECT_GT(warp, previous) << step;
                previous = warp;
            }
        }
    EXPECT_EQ(lloydWarp(0.0f, 10.0f, 0.5f), 0.0f);  // the light along the view: no warp to scale
}

// Lloyd et al. 2006's η over γ for a 60° field of view (θ = 30°): the uniform map up to γ_a = 10°, η_b = -0.2
// at γ_b = θ, LiSPSM's η_c = 0 from γ_c = 30° + 0.3 · 60° = 48° on; continuous and rising between.
TEST(LightParameterizations, LloydEtaRisesFromUniformToLispsmWithTheAngle) {
    const float theta = glm::radians(30.0f);
    EXPECT_EQ(lloydEta(0.0f, theta), -1.0f);
    EXPECT_EQ(lloydEta(glm::radians(9.9f), theta), -1.0f);
    EXPECT_NEAR(lloydEta(glm::radians(10.0f), theta), -1.0f, 1e-6f);
    EXPECT_NEAR(lloydEta(theta, theta), -0.2f, 1e-6f);
    EXPECT_NEAR(lloydEta(glm::radians(48.0f) - 1e-6f, theta), 0.0f, 1e-5f);
    EXPECT_EQ(lloydEta(glm::radians(48.0f), theta), 0.0f);
    EXPECT_EQ(lloydEta(glm::radians(90.0f), theta), 0.0f);
    float previous = -1.0f;
    for (int tenth = 0; tenth <= 900; ++tenth) {
        const float eta = lloydEta(glm::radians(tenth / 10.0f), theta);
        EXPECT_GE(eta, previous) << tenth / 10.0f << "°";
        EXPECT_LE(eta - previous, 0.02f) << "a jump at " << tenth / 10.0f << "°";
        previous = eta;
    }
}

// LispsmN::Lloyd2006 in the fit: with the light across the view (γ >= γ_c) its η is 0 and the fit is
// Wimmer2004's to the bit; with the light near the view (γ < θ / 3) it is the uniform end, no warp: Focused's
// fit.
TEST(LightParameterizations, LispsmLloyd2006IsWimmerAcrossTheViewAndFocusedAlongIt) {
    LightTunables lloyd;
    lloyd.lispsmN = LispsmN::Lloyd2006;
    const glm::vec3 view = fromAngles(-10.0f, 0.0f);
    const Scene across = terrain(view, fromAngles(-60.0f, 30.0f));
    const LightFit wimmer =
        fitLight(LightParameterization::LiSPSM, across, across.bounds(), kAspect, across.lights[0]);
    const LightFit lloydAcross =
        fitLight(LightParameterization::LiSPSM, across, across.bounds(), kAspect, across.lights[0], lloyd);
    ASSERT_GT(wimmer.warp, 0.0f);
    EXPECT_EQ(lloydAcross.warp, wimmer.warp);
    EXPECT_EQ(lloydAcross.projection, wimmer.projection);

    // 5° off the view direction, from behind the viewer: below γ_a = 10° for the 60° field of view.
    const glm::vec3 nearlyAlong = fromAngles(-15.0f, 0.0f);
    const Scene along = terrain(view, nearlyAlong);
    const LightFit lloydAlong =
        fitLight(LightParameterization::LiSPSM, along, along.bounds(), kAspect, along.lights[0], lloyd);
    EXPECT_EQ(lloydAlong.warp, 0.0f);
    EXPECT_GT(fitLight(LightParameterization::LiSPSM, along, along.bounds(), kAspect, along.lights[0]).warp,
              0.0f);
}

// With LiSPSMMiddleVector, V_P is Scherzer 2005 §4.4's middle vector: the sum of the eye-to-vertex vectors of
// B, made perpendicular to the light, recomputed here from B's vertices (intersectionBody of the clamped
// frustum = the first half of focusBody); the light view's y axis is V_P and n_opt uses its γ.
TEST(LightParameterizations, LispsmMiddleVectorIsTheSumOverB) {
    LightTunables middle;
    middle.lispsmMiddleVector = true;
    middle.lispsmN = LispsmN::Scherzer2005;  // n_opt recomputed below from eq. 1
    // Looking along the terrain's long side from near one edge: B leans toward the bounds' inside.
    const glm::vec3 view = glm::normalize(glm::vec3(0.6f, -0.05f, 1.0f));
    const Scene scene = terrain(view, fromAngles(-40.0f, 100.0f));
    const Bounds bounds = scene.bounds();
    const glm::vec3 light = scene.lights[0].direction;
    const std::vector<glm::vec3> body = focusBody(scene.camera, kAspect, bounds, light);
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < body.size() / 2; ++i) sum += glm::dvec3(body[i] - scene.camera.position);
    const glm::dvec3 m = glm::normalize(sum), l(light);
    const glm::dvec3 vp = glm::normalize(m - glm::dot(m, l) * l);
    const glm::dvec3 eq3 = glm::normalize(glm::cross(glm::cross(l, glm::dvec3(view)), l));
    ASSERT_LT(glm::dot(vp, eq3), 0.999) << "the case must tell the two vectors apart";

    const LightFit fit =
        fitLight(LightParameterization::LiSPSM, scene, bounds, kAspect, scene.lights[0], middle);
    const glm::dvec3 yAxis(fit.view[0][1], fit.view[1][1], fit.view[2][1]);
    EXPECT_GT(glm::dot(yAxis, vp), 1.0 - 1e-5);
    double lo = 1e30, hi = -1e30;
    for (const glm::vec3& p : body) {
        lo = std::min(lo, glm::dot(glm::dvec3(p), vp));
        hi = std::max(hi, glm::dot(glm::dvec3(p), vp));
    }
    const double sinGamma = glm::length(glm::cross(m, l));
    const double zn = scene.camera.nearPlane;
    const double nopt = (zn + std::sqrt(zn * (zn + (hi - lo) * sinGamma))) / sinGamma;
    EXPECT_NEAR(1.0 / fit.warp, nopt, 1e-3 * nopt);

    // And it keeps every point of the body in the clip volume over the whole grid.
    for (const Configuration& c : grid()) {
        const Scene s = terrain(c.view, c.light);
        const LightFit f =
            fitLight(LightParameterization::LiSPSM, s, s.bounds(), kAspect, s.lights[0], middle);
        ASSERT_TRUE(finite(f.view) && finite(f.projection)) << c.name;
        for (const glm::vec3& p : focusBody(s.camera, kAspect, s.bounds(), s.lights[0].direction)) {
            const glm::vec4 clip = f.projection * f.view * glm::vec4(p, 1.0f);
            const float tolerance = 1e-5f * std::abs(clip.w);
            ASSERT_GT(clip.w, 0.0f) << c.name;
            EXPECT_LE(std::abs(clip.x), clip.w + tolerance) << c.name;
            EXPECT_LE(std::abs(clip.y), clip.w + tolerance) << c.name;
            EXPECT_GE(clip.z, -tolerance) << c.name;
            EXPECT_LE(clip.z, clip.w + tolerance) << c.name;
        }
    }
}

// As γ -> 0 the warp goes to 0 continuously and LiSPSM's matrices become the focused fit's: no jump at any
// threshold. Every body point's light NDC moves by at most a bound proportional to the step in γ.
TEST(LightParameterizations, LispsmFadesIntoFocusedAsLightTurnsParallel) {
    const glm::vec3 view = fromAngles(-30.0f, 0.0f);
    const glm::vec3 side = glm::normalize(glm::cross(view, glm::vec3(0.0f, 1.0f, 0.0f)));
    auto sceneAt = [&](float gammaDegrees) {
        const float g = glm::radians(gammaDegrees);
        return terrain(view, std::cos(g) * view + std::sin(g) * side);
    };
    float previousWarp = -1.0f;
    for (float gamma = 2.0f; gamma >= 0.0f; gamma -= 0.25f) {
        const Scene scene = sceneAt(gamma);
        const LightFit fit =
            fitLight(LightParameterization::LiSPSM, scene, scene.bounds(), kAspect, scene.lights[0]);
        if (previousWarp >= 0.0f) {
            EXPECT_LT(fit.warp, previousWarp) << gamma;
        }
        previousWarp = fit.warp;
    }
    EXPECT_LT(previousWarp, 1e-5f);  // γ = 0 up to the rounding of the light direction

    // With z_n = 0.1 m and d = 200 m, n_opt = 0.22 m / sin γ: the warp fades only where sin γ << z_n / d.
    const Scene almost = sceneAt(1e-4f);
    const Bounds bounds = almost.bounds();
    const LightFit lispsm =
        fitLight(LightParameterization::LiSPSM, almost, bounds, kAspect, almost.lights[0]);
    const LightFit focused =
        fitLight(LightParameterization::Focused, almost, bounds, kAspect, almost.lights[0]);
    for (const glm::vec3& p : focusBody(almost.camera, kAspect, bounds, almost.lights[0].direction)) {
        const glm::vec4 a = lispsm.projection * lispsm.view * glm::vec4(p, 1.0f);
        const glm::vec4 b = focused.projection * focused.view * glm::vec4(p, 1.0f);
        EXPECT_NEAR(a.x / a.w, b.x / b.w, 1e-2f);
        EXPECT_NEAR(a.y / a.w, b.y / b.w, 1e-2f);
    }
}

// A spot light keeps its own perspective and depth range: Focused and LiSPSM crop its window to the
// receivers of B clipped by the light frustum. Every receiver inside the spot's frustum stays inside the
// cropped one, and the window is smaller than the uniform map when B is a small part of the cone.
TEST(LightParameterizations, SpotLightsAreCroppedToTheReceivers) {
    size_t checked = 0;
    for (const Configuration& c : grid()) {
        Scene scene = terrain(c.view, {0.0f, -1.0f, 0.0f});
        scene.lights[0].type = Light::Type::Spot;
        scene.lights[0].position = {10.0f, 60.0f, -40.0f};
        scene.lights[0].direction = glm::normalize(c.light - glm::vec3(0.0f, 2.0f, 0.0f));
        scene.lights[0].spotAngle = glm::radians(70.0f);
        const Bounds bounds = scene.bounds();
        const LightFit uniform =
            fitLight(LightParameterization::Uniform, scene, bounds, kAspect, scene.lights[0]);
        const std::vector<glm::vec3> body =
            focusBody(scene.camera, kAspect, bounds, scene.lights[0].direction);
        for (LightParameterization method : {LightParameterization::Focused, LightParameterization::LiSPSM}) {
            const LightFit fit = fitLight(method, scene, bounds, kAspect, scene.lights[0]);
            const std::string what = c.name + " " + lightParameterizationName(method);
            ASSERT_TRUE(finite(fit.projection)) << what;
            EXPECT_EQ(fit.view, uniform.view) << what;
            EXPECT_EQ(fit.warp, 0.0f) << what;
            for (size_t i = 0; i < body.size() / 2; ++i) {
                const glm::vec4 u = uniform.projection * uniform.view * glm::vec4(body[i], 1.0f);
                if (!(u.w > 0.0f) || std::abs(u.x) > u.w || std::abs(u.y) > u.w)
                    continue;  // outside the cone
                const glm::vec4 clip = fit.projection * fit.view * glm::vec4(body[i], 1.0f);
                const float tolerance = 1e-5f * std::abs(clip.w);
                ++checked;
                EXPECT_LE(std::abs(clip.x), clip.w + tolerance) << what;
                EXPECT_LE(std::abs(clip.y), clip.w + tolerance) << what;
                EXPECT_NEAR(clip.z / clip.w, u.z / u.w, 1e-6f) << what << ": depth is the spot's own";
            }
        }
    }
    EXPECT_GT(checked, 500u);
    // Seen from 2 m up, looking level, under a spot 60 m up pointing straight down: B's window in the spot's
    // map is a fraction of the cone.
    Scene scene = terrain(fromAngles(-20.0f, 0.0f), {0.0f, -1.0f, 0.0f});
    scene.camera.farPlane = 30.0f;
    scene.lights[0].type = Light::Type::Spot;
    scene.lights[0].position = {0.0f, 60.0f, -60.0f};
    scene.lights[0].spotAngle = glm::radians(90.0f);
    const Bounds bounds = scene.bounds();
    const LightFit uniform =
        fitLight(LightParameterization::Uniform, scene, bounds, kAspect, scene.lights[0]);
    const LightFit focused =
        fitLight(LightParameterization::Focused, scene, bounds, kAspect, scene.lights[0]);
    EXPECT_GT(focused.projection[0][0] * focused.projection[1][1],
              4.0f * uniform.projection[0][0] * uniform.projection[1][1])
        << "at least 4x the texels per area";
}

// [SECTION] Cascaded

namespace {

// Is `p` inside the D3D clip volume of `viewProjection` (with a relative tolerance)?
::testing::AssertionResult insideClip(const glm::mat4& viewProjection, const glm::vec3& p) {
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    const float tolerance = 1e-5f * std::abs(clip.w);
    if (clip.w > 0.0f && std::abs(clip.x) <= clip.w + tolerance && std::abs(clip.y) <= clip.w + tolerance &&
        clip.z >= -tolerance && clip.z <= clip.w + tolerance)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "clip (" << clip.x << ", " << clip.y << ", " << clip.z << ", " << clip.w << ")";
}

}  // namespace

// The split schemes against their definitions, computed here in double precision and from properties
// the formula must have: the logarithmic split keeps z_{i+1} / z_i constant (Lehőcz 2007,
//, "Kaszádolt shadow map-ek": each map covers twice the
// distance of the previous one, i.e. ratio 2 for n = 1, f = 16, N = 4), the uniform one z_{i+1} - z_i.
TEST(CascadedShadowMaps, SplitSchemesFollowTheirDefinitions) {
    const std::vector<float> doubling = cascadeSplitDepths(1.0f, 16.0f, 4, 1.0f);
    ASSERT_EQ(doubling.size(), 5u);
    for (int i = 0; i <= 4; ++i) EXPECT_NEAR(doubling[size_t(i)], std::pow(2.0, i), 1e-5) << i;
    const std::vector<float> uniform = cascadeSplitDepths(0.5f, 100.5f, 4, 0.0f);
    for (int i = 0; i <= 4; ++i) EXPECT_NEAR(uniform[size_t(i)], 0.5 + 25.0 * i, 1e-4) << i;
    for (double n : {0.001, 0.1, 2.0})
        for (double f : {10.0, 70.0, 5000.0})
            for (int count : {1, 2, 3, 4, 8})
                for (double lambda : {0.0, 0.25, 0.5, 1.0}) {
                    const std::vector<float> z = cascadeSplitDepths(float(n), float(f), count, float(lambda));
                    ASSERT_EQ(z.size(), size_t(count) + 1);
                    EXPECT_FLOAT_EQ(z.front(), float(n));
                    EXPECT_FLOAT_EQ(z.back(), float(f));
                    for (int i = 0; i <= count; ++i) {
                        const double t = double(i) / count;
                        const double expected =
                            lambda * n * std::exp(t * std::log(f / n)) + (1.0 - lambda) * (n + t * (f - n));
                        EXPECT_NEAR(z[size_t(i)], expected, 1e-5 * expected) << n << " " << f << " " << i;
                        if (i > 0) {
                            EXPECT_GT(z[size_t(i)], z[size_t(i) - 1]);
                        }
                    }
                }
}

TEST(CascadedShadowMaps, AtlasTilesPartitionTheAtlas) {
    EXPECT_EQ(cascadeAtlasGrid(1), glm::ivec2(1, 1));
    EXPECT_EQ(cascadeAtlasGrid(2), glm::ivec2(2, 1));
    EXPECT_EQ(cascadeAtlasGrid(4), glm::ivec2(2, 2));
    EXPECT_EQ(cascadeAtlasGrid(5), glm::ivec2(3, 2));
    EXPECT_EQ(cascadeAtlasGrid(8), glm::ivec2(3, 3));
    EXPECT_EQ(cascadeViewport(3, 4, 1024, 1024), glm::ivec4(512, 512, 512, 512));
    EXPECT_EQ(cascadeViewport(2, 4, 1024, 1024), glm::ivec4(0, 512, 512, 512));
    for (int count = 1; count <= kMaxCascades; ++count) {
        const glm::ivec2 grid = cascadeAtlasGrid(count);
        const int size = 720;  // a multiple of every grid's columns and rows
        std::vector<int> owner(size_t(size * size), -1);
        for (int k = 0; k < count; ++k) {
            const glm::ivec4 tile = cascadeViewport(k, count, size, size);
            const glm::vec4 rect = cascadeAtlasRect(k, count);
            EXPECT_NEAR(rect.x * size, tile.x, 1e-3);
            EXPECT_NEAR(rect.y * size, tile.y, 1e-3);
            EXPECT_NEAR(rect.z * size, tile.z, 1e-3);
            EXPECT_NEAR(rect.w * size, tile.w, 1e-3);
            EXPECT_EQ(tile.z, size / grid.x);
            for (int y = tile.y; y < tile.y + tile.w; ++y)
                for (int x = tile.x; x < tile.x + tile.z; ++x) {
                    ASSERT_TRUE(x < size && y < size) << count << " " << k;
                    EXPECT_EQ(owner[size_t(y * size + x)], -1) << "tiles overlap";
                    owner[size_t(y * size + x)] = k;
                }
        }
    }
}

// For the whole grid of cameras and lights: every cascade's matrices are finite, its splits are monotonic
// and cover [near, far end] without gaps (each starts, blend band included, before the previous ends), and
// every point of its slice of B (receivers: slice ∩ bounds; casters: their extrusion toward the light)
// lies inside its clip volume.
TEST(CascadedShadowMaps, EachSliceLiesInsideItsCascade) {
    for (const Configuration& c : grid()) {
        const Scene scene = terrain(c.view, c.light);
        const Bounds bounds = scene.bounds();
        for (int count : {1, 3, 4}) {
            LightTunables tunables;
            tunables.cascadeCount = count;
            const LightFit fit =
                fitLight(LightParameterization::Cascaded, scene, bounds, kAspect, scene.lights[0], tunables);
            const std::string what = c.name + " count " + std::to_string(count);
            ASSERT_EQ(fit.cascades.size(), size_t(count)) << what;
            EXPECT_FLOAT_EQ(fit.cascades.front().splitNear, scene.camera.nearPlane) << what;
            EXPECT_LE(fit.cascades.back().splitFar, scene.camera.farPlane) << what;
            for (size_t k = 0; k < fit.cascades.size(); ++k) {
                const LightView& cascade = fit.cascades[k];
                ASSERT_TRUE(finite(cascade.view) && finite(cascade.projection)) << what;
                ASSERT_LT(cascade.splitNear, cascade.splitFar) << what;
                if (k > 0) {
                    EXPECT_GT(cascade.splitFar, fit.cascades[k - 1].splitFar) << what;
                    EXPECT_LE(cascade.splitNear, fit.cascades[k - 1].splitFar) << what;
                }
                Camera slice = scene.camera;
                slice.nearPlane = cascade.splitNear;
                slice.farPlane = cascade.splitFar;
                const std::vector<glm::vec3> body =
                    focusBody(slice, kAspect, bounds, glm::normalize(scene.lights[0].direction));
                const glm::mat4 viewProjection = cascade.projection * cascade.view;
                for (const glm::vec3& p : body)
                    ASSERT_TRUE(insideClip(viewProjection, p)) << what << " cascade " << k;
            }
        }
    }
}

// The split range ends at the farthest corner of the bounds when that is nearer than the far plane (rounded
// up by at most one ladder step of 2^(1/16)), and the near cascades get smaller texels: each cascade's
// map spans at most the next one's world extent.
TEST(CascadedShadowMaps, SplitsEndAtTheSceneAndNearCascadesAreFiner) {
    Scene scene = terrain(fromAngles(-10.0f, 0.0f), fromAngles(-45.0f, 30.0f));
    scene.camera.farPlane = 1e5f;
    const LightFit fit =
        fitLight(LightParameterization::Cascaded, scene, scene.bounds(), kAspect, scene.lights[0]);
    ASSERT_EQ(fit.cascades.size(), 4u);
    float farthest = 0.0f;
    const glm::mat4 view = scene.camera.view();
    const Bounds bounds = scene.bounds();
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                          corner & 4 ? bounds.max.z : bounds.min.z);
        farthest = std::max(farthest, (view * glm::vec4(p, 1.0f)).z);
    }
    EXPECT_GE(fit.cascades.back().splitFar, farthest);
    EXPECT_LE(fit.cascades.back().splitFar, farthest * std::exp2(1.0f / 16.0f) * 1.0001f);
    for (size_t k = 1; k < fit.cascades.size(); ++k)
        EXPECT_GE(fit.cascades[k - 1].projection[0][0], fit.cascades[k].projection[0][0]) << k;
    EXPECT_GT(fit.cascades[0].projection[0][0], 4.0f * fit.cascades[3].projection[0][0]);
}

// Stabilization: as the camera moves a little, every cascade keeps its light view and extent, and its
// origin moves by whole texels of a 512² tile (so rasterized shadow edges stay where they are).
TEST(CascadedShadowMaps, ACameraMoveShiftsCascadesByWholeTexels) {
    const Scene start = terrain(fromAngles(-10.0f, 0.0f), fromAngles(-45.0f, 30.0f));
    const LightFit before =
        fitLight(LightParameterization::Cascaded, start, start.bounds(), kAspect, start.lights[0]);
    int moved = 0;
    for (int step = 1; step <= 20; ++step) {
        Scene scene = start;
        const glm::mat4 orbit =
            glm::rotate(glm::mat4(1.0f), glm::radians(0.1f * float(step)), glm::vec3(0, 1, 0));
        scene.camera.position =
            scene.camera.target +
            glm::vec3(orbit * glm::vec4(start.camera.position - start.camera.target, 0.0f));
        scene.camera.position.x += 0.05f * float(step);
        const LightFit after =
            fitLight(LightParameterization::Cascaded, scene, scene.bounds(), kAspect, scene.lights[0]);
        ASSERT_EQ(after.cascades.size(), before.cascades.size());
        for (size_t k = 0; k < after.cascades.size(); ++k) {
            const LightView &a = before.cascades[k], &b = after.cascades[k];
            EXPECT_EQ(a.view, b.view) << step << " " << k;
            if (a.projection[0][0] != b.projection[0][0]) continue;  // the extent stepped up the ladder
            const float texels = 256.0f;                             // clip units [-1, 1] -> 512 texels
            for (int axis = 0; axis < 2; ++axis) {
                const float shift = (b.projection[3][axis] - a.projection[3][axis]) * texels;
                EXPECT_NEAR(shift, std::round(shift), 2e-2f) << step << " cascade " << k << " axis " << axis;
                moved += std::round(shift) != 0.0f ? 1 : 0;
            }
        }
    }
    EXPECT_GT(moved, 0) << "the camera moved 1 m: some cascade must have followed it";
}

// Spot lights are not split: every cascade is Focused's window of the spot (its perspective cropped to the
// receivers), still one per cascade so that the effect's cascade passes run.
TEST(CascadedShadowMaps, SpotLightsUseTheFocusedWindowInEveryCascade) {
    Scene scene = terrain(fromAngles(-10.0f, 0.0f), fromAngles(-45.0f, 30.0f));
    scene.lights[0].type = Light::Type::Spot;
    scene.lights[0].position = {0.0f, 60.0f, -120.0f};
    const LightFit focused =
        fitLight(LightParameterization::Focused, scene, scene.bounds(), kAspect, scene.lights[0]);
    const LightFit fit =
        fitLight(LightParameterization::Cascaded, scene, scene.bounds(), kAspect, scene.lights[0]);
    ASSERT_EQ(fit.cascades.size(), 4u);
    for (const LightView& cascade : fit.cascades) {
        EXPECT_EQ(cascade.view, focused.view);
        EXPECT_EQ(cascade.projection, focused.projection);
    }
}
}  // namespace test_light_parameterizations
