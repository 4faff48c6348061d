// Trapezoidal shadow maps (runtime/TrapezoidalShadowMap.h), no GL: the 80% rule against the 1D projective
// map solved independently, the trapezoid enclosing the focus body with every edge touching it, its corners
// landing on the square's, the focus point P_L on the 80% line, and the fade into the focused fit as the
// light turns parallel to the view. (The grid of test_light_parameterizations.cpp checks TSM's finite
// matrices and the clip volume containing B for 4 x 17 camera and light directions.)
#include "LightFitScenes.h"

#include <runtime/TrapezoidalShadowMap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace test_trapezoidal_shadow_map {

using namespace runtime;

namespace {

using namespace shadowfx::test;  // terrain, fromAngles, finite (LightFitScenes.h)
constexpr float kAspect = kLightFitAspect;

glm::vec2 ndc(const LightFit& fit, const glm::vec3& world) {
    const glm::vec4 clip = fit.projection * fit.view * glm::vec4(world, 1.0f);
    return glm::vec2(clip) / clip.w;
}

// Light directions well outside the view cone (γ from 45° to 90°: the full 80% rule), from the side, from
// behind the viewer and against it.
struct Configuration {
    std::string name;
    glm::vec3 view;
    glm::vec3 light;
};

std::vector<Configuration> outsideTheViewCone() {
    return {
        {"level/straight-down", fromAngles(0.0f, 0.0f), {0.0f, -1.0f, 0.0f}},
        {"level/side-45", fromAngles(0.0f, 0.0f), fromAngles(-45.0f, 90.0f)},
        {"level/behind-60", fromAngles(0.0f, 0.0f), fromAngles(-60.0f, 0.0f)},
        {"level/against-50", fromAngles(0.0f, 0.0f), fromAngles(-50.0f, 180.0f)},
        {"down-30/low-side", fromAngles(-30.0f, 20.0f), fromAngles(-10.0f, 135.0f)},
    };
}

}  // namespace

// Lehőcz 2007 : the focus point maps to the 80% line. Along the
// centre line N_T is the 1D projective map fixed by q -> ∞, top -> +1, base -> -1 (the paper's ends); solved
// here in double as v(t) = A + B / t from the two ends, it must send the focus point, δ' below the top, to ξ.
TEST(TrapezoidalShadowMap, WarpPutsTheFocusPointOnTheEightyPercentLine) {
    EXPECT_FLOAT_EQ(kTsmXi, 1.0f - 0.8f * 2.0f);
    for (double lambda : {1.0, 37.0, 250.0})
        for (double fraction : {0.05, 0.2, 0.5, 0.7}) {
            const double delta = fraction * lambda;
            const double eta = 1.0 / tsmWarp(float(lambda), float(delta));
            // A + B / η = 1, A + B / (η + λ) = -1
            const double b = 2.0 / (1.0 / eta - 1.0 / (eta + lambda));
            const double a = 1.0 - b / eta;
            EXPECT_NEAR(a + b / (eta + delta), kTsmXi, 1e-4) << lambda << " " << fraction;
        }
    // From 80% of the height on, the focus region is the whole map already: no warp (a rectangle).
    EXPECT_EQ(tsmWarp(10.0f, 8.0f), 0.0f);
    EXPECT_EQ(tsmWarp(10.0f, 9.5f), 0.0f);
    EXPECT_GT(tsmWarp(10.0f, 7.9f), 0.0f);
}

// Every point of the focus body (B and its extrusion) lies inside the trapezoid, and each of its four edges
// touches one of them: the trapezoid bounds the body's 2D convex hull tightly. The corners land on the
// square's corners (up to the fit's 10⁻³ margin).
TEST(TrapezoidalShadowMap, TrapezoidEnclosesTheBodyAndMapsOntoTheSquare) {
    for (const Configuration& c : outsideTheViewCone()) {
        const Scene scene = terrain(c.view, c.light);
        const Bounds bounds = scene.bounds();
        const std::optional<TrapezoidalFit> tsm = fitTrapezoid(scene, bounds, kAspect, scene.lights[0]);
        ASSERT_TRUE(tsm.has_value()) << c.name;
        EXPECT_GT(tsm->fit.warp, 0.0f) << c.name;  // a real trapezoid, not the rectangle
        const auto& corner = tsm->corners;
        float size = 0.0f;
        for (int i = 0; i < 4; ++i) size = std::max(size, glm::length(corner[(i + 1) % 4] - corner[i]));
        float nearest[4] = {1e30f, 1e30f, 1e30f, 1e30f};
        for (const glm::vec3& p : focusBody(scene.camera, kAspect, bounds, scene.lights[0].direction)) {
            const glm::vec2 q(tsm->fit.view * glm::vec4(p, 1.0f));
            for (int i = 0; i < 4; ++i) {
                // Distance inside the edge from corner i to corner i+1 (the corners run counterclockwise in
                // light-view x, y: top left, top right, base right, base left, the top at the smaller y).
                const glm::vec2 edge = glm::normalize(corner[(i + 1) % 4] - corner[i]);
                const float inside = edge.x * (q.y - corner[i].y) - edge.y * (q.x - corner[i].x);
                EXPECT_GE(inside, -1e-4f * size) << c.name << " edge " << i;
                nearest[i] = std::min(nearest[i], inside);
            }
        }
        for (int i = 0; i < 4; ++i) EXPECT_LT(nearest[i], 1e-4f * size) << c.name << " edge " << i;

        const glm::mat4 lightToWorld = glm::inverse(tsm->fit.view);
        const glm::vec2 square[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
        for (int i = 0; i < 4; ++i) {
            const glm::vec3 world(lightToWorld * glm::vec4(corner[i], 0.0f, 1.0f));
            const glm::vec2 mapped = ndc(tsm->fit, world);
            EXPECT_NEAR(mapped.x, square[i].x, 3e-3f) << c.name << " corner " << i;
            EXPECT_NEAR(mapped.y, square[i].y, 3e-3f) << c.name << " corner " << i;
        }
        // Lines of equal light-view y stay lines of equal map y: the top and base edges are straight rows.
        EXPECT_FLOAT_EQ(corner[0].y, corner[1].y);
        EXPECT_FLOAT_EQ(corner[2].y, corner[3].y);
    }
}

// P_L, recomputed here from the camera and B: the point TSMFocus of B's depth past its nearest point (the
// near plane: the camera is inside the bounds) on the view's centre line maps to the 80% line. The fit
// puts the viewer's side at -1, the paper at +1, so the line is y = -ξ = 0.6 here; the focused fit (no
// warp) leaves P_L much nearer the top.
TEST(TrapezoidalShadowMap, FocusPointLandsOnTheEightyPercentLine) {
    for (float focus : {0.1f, 0.3f, 0.5f})
        for (const Configuration& c : outsideTheViewCone()) {
            const Scene scene = terrain(c.view, c.light);
            const Bounds bounds = scene.bounds();
            const Camera& camera = scene.camera;
            const glm::vec3 viewDir = glm::normalize(camera.target - camera.position);
            const std::vector<glm::vec3> body = focusBody(camera, kAspect, bounds, scene.lights[0].direction);
            float nearest = 1e30f, farthest = 0.0f;  // B's vertices come first, then their extrusions
            for (size_t i = 0; i < body.size() / 2; ++i) {
                nearest = std::min(nearest, glm::dot(body[i] - camera.position, viewDir));
                farthest = std::max(farthest, glm::dot(body[i] - camera.position, viewDir));
            }
            const float depth = farthest - nearest;
            const glm::vec3 focusPoint = camera.position + viewDir * (nearest + focus * depth);

            LightTunables tunables;
            tunables.tsmFocus = focus;
            const std::optional<TrapezoidalFit> tsm =
                fitTrapezoid(scene, bounds, kAspect, scene.lights[0], tunables);
            ASSERT_TRUE(tsm.has_value()) << c.name;
            const std::string what = c.name + " focus " + std::to_string(focus);
            ASSERT_FLOAT_EQ(tsm->strength, 1.0f) << what;
            EXPECT_LT(glm::length(tsm->focusPoint - focusPoint), 1e-3f * depth) << what;
            if (tsm->fit.warp == 0.0f) continue;  // P_L at or past the 80% line already: the rectangle
            EXPECT_NEAR(ndc(tsm->fit, focusPoint).y, -kTsmXi, 3e-3f) << what;
            const LightFit focused =
                fitLight(LightParameterization::Focused, scene, bounds, kAspect, scene.lights[0]);
            EXPECT_LT(ndc(focused, focusPoint).y, -kTsmXi - 0.1f) << what;
        }
}

// As γ -> 0 the warp fades out smoothly: the strength falls monotonically to 0, the map moves continuously
// (halving the step in γ halves the largest move of any point of B in the map, which a jump would not),
// and at γ = 10⁻⁴° the map is the focused fit's.
TEST(TrapezoidalShadowMap, FadesIntoFocusedAsLightTurnsParallel) {
    const glm::vec3 view = fromAngles(-30.0f, 0.0f);
    const glm::vec3 side = glm::normalize(glm::cross(view, glm::vec3(0.0f, 1.0f, 0.0f)));
    auto sceneAt = [&](float gammaDegrees) {
        const float g = glm::radians(gammaDegrees);
        return terrain(view, std::cos(g) * view + std::sin(g) * side);
    };
    const Scene first = sceneAt(60.0f);
    const std::vector<glm::vec3> body =
        focusBody(first.camera, kAspect, first.bounds(), first.lights[0].direction);
    // The largest move of B's vertices (B does not depend on the light) between neighbouring γ of a sweep
    // from 60° down to `step`; the strength of the last fit.
    auto sweep = [&](float step, float& lastStrength) {
        std::vector<glm::vec2> previous;
        float previousStrength = 2.0f, largestMove = 0.0f;
        for (int i = 0; 60.0f - float(i) * step > 0.5f * step; ++i) {
            const float gamma = 60.0f - float(i) * step;
            const Scene scene = sceneAt(gamma);
            const std::optional<TrapezoidalFit> tsm =
                fitTrapezoid(scene, scene.bounds(), kAspect, scene.lights[0]);
            EXPECT_TRUE(tsm.has_value()) << gamma;
            if (!tsm) return 1e30f;
            EXPECT_LE(tsm->strength, previousStrength) << gamma;
            previousStrength = tsm->strength;
            std::vector<glm::vec2> mapped;
            for (size_t v = 0; v < body.size() / 2; ++v) mapped.push_back(ndc(tsm->fit, body[v]));
            for (size_t v = 0; v < previous.size(); ++v)
                largestMove = std::max(largestMove, glm::length(mapped[v] - previous[v]));
            previous = mapped;
        }
        lastStrength = previousStrength;
        return largestMove;
    };
    float strength = 1.0f;
    const float coarse = sweep(0.25f, strength);
    EXPECT_LT(strength, 1e-2f);  // at γ = 0.25°
    const float fine = sweep(0.125f, strength);
    EXPECT_LT(coarse, 0.25f);
    EXPECT_LT(fine, 0.6f * coarse);

    const Scene almost = sceneAt(1e-4f);
    const Bounds bounds = almost.bounds();
    const std::optional<TrapezoidalFit> tsm = fitTrapezoid(almost, bounds, kAspect, almost.lights[0]);
    ASSERT_TRUE(tsm.has_value());
    EXPECT_LT(tsm->fit.warp, 1e-7f);
    const LightFit focused =
        fitLight(LightParameterization::Focused, almost, bounds, kAspect, almost.lights[0]);
    for (const glm::vec3& p : focusBody(almost.camera, kAspect, bounds, almost.lights[0].direction)) {
        EXPECT_NEAR(ndc(tsm->fit, p).x, ndc(focused, p).x, 1e-3f);
        EXPECT_NEAR(ndc(tsm->fit, p).y, ndc(focused, p).y, 1e-3f);
    }
}

// Spot and point lights keep the uniform fit, as with Focused and LiSPSM.
TEST(TrapezoidalShadowMap, SpotLightsKeepTheUniformFit) {
    Scene scene = terrain(fromAngles(0.0f, 0.0f), {0.0f, -1.0f, 0.0f});
    scene.lights[0].type = Light::Type::Spot;
    scene.lights[0].position = {0.0f, 60.0f, 0.0f};
    const Bounds bounds = scene.bounds();
    EXPECT_FALSE(fitTrapezoid(scene, bounds, kAspect, scene.lights[0]).has_value());
    const LightFit uniform =
        fitLight(LightParameterization::Uniform, scene, bounds, kAspect, scene.lights[0]);
    const LightFit tsm = fitLight(LightParameterization::TSM, scene, bounds, kAspect, scene.lights[0]);
    EXPECT_EQ(uniform.view, tsm.view);
    EXPECT_EQ(uniform.projection, tsm.projection);
}
}  // namespace test_trapezoidal_shadow_map
