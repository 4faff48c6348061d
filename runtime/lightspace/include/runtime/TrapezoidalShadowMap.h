// TrapezoidalShadowMap: the TSM provider of LightParameterization (Martin & Tan 2004, "Anti-aliasing and
// continuity with trapezoidal shadow maps", as retold in Lehőcz 2007,
//, "Trapéz shadow map-ek"). In the light view of the focused fit,
// whose y axis is V_P (the view direction made perpendicular to the light, so the centre line of the view
// frustum runs along +y), a trapezoid encloses the focus body; a 2D projective map N_T sends it onto the
// square, its top (the viewer's side) to y = -1 and its base to y = +1, with the focus point of the 80% rule
// on y = -ξ = 0.6.
#pragma once

#include <runtime/LightParameterization.h>

#include <glm/glm.hpp>

#include <array>
#include <optional>

namespace runtime {

// The paper's ξ: the line, in its N_T coordinates (top edge at +1, base at -1), that the focus point maps to.
// -0.6 is 80% of the way from the top (+1) to the base (-1): 1 - 0.8 · 2.
inline constexpr float kTsmXi = -0.6f;

// Lehőcz 2007 (the 80% rule, derived in TrapezoidalShadowMap.cpp): the distance η from the trapezoid's top
// line back to the projection centre q, for a trapezoid of height λ whose focus point lies δ' below the
// top line, returned as its reciprocal 1/η, the warp strength (0 = a rectangle: δ' at or past the 80% line).
float tsmWarp(float height, float focusOffset, float xi = kTsmXi);

struct TrapezoidalFit {
    LightFit fit;
    // The trapezoid in light-view (x, y): top left, top right, base right, base left. The top edge lies on
    // the viewer's side; the fit maps these to NDC (-1,-1), (1,-1), (1,1), (-1,1) up to the fit's margin.
    std::array<glm::vec2, 4> corners{};
    // The focus point P_L (world space) of the 80% rule, on the view's centre line.
    glm::vec3 focusPoint{0.0f};
    // How much of the 80% rule's warp is applied: 1 where the light is outside the view cone, fading to 0
    // (the rectangle, i.e. the focused fit) as the light turns parallel to the view.
    float strength = 0.0f;
};

// The TSM fit of a directional light, or nullopt where it cannot work (not directional, the camera sees
// nothing of the scene, B without extent across the light): fitLight then keeps the uniform fit.
std::optional<TrapezoidalFit> fitTrapezoid(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                           const Light& light, const LightTunables& tunables = {});

}  // namespace runtime
