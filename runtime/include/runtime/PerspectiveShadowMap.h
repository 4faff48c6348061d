// PerspectiveShadowMap: the PSM provider of LightParameterization (Stamminger & Drettakis 2002, with
// Kozlov's "care and feeding", seed 004 §14.2, /work/shared/seeds/004_803a1be93f8534eb.txt; seed 000 §2).
//
// The shadow map is rendered in the post-perspective space (PPS) of a virtual camera C, where a directional
// light becomes a point L' = C (-d, 0): an ordinary point in front of the camera when the light shines
// toward the viewer (L'.w > 0), an "inverted" point when it comes from behind the viewer (L'.w < 0), and a
// direction when it is perpendicular to the view (L'.w = 0). The light camera is a perspective from L'
// (seed 004 §14.2.2) whose rows x, y, w all vanish on L': in world space they do not change along the light
// direction, so clip w is constant along each world light ray and depth z / w, kept linear in the world
// distance along the light, orders casters correctly on both sides of the viewer. That is Kozlov's inverse
// projection (near -a, far a, §14.2.1) without the case split: the casters behind the viewer need no
// virtual camera shift, and L'.w can change sign without a jump.
//
// Care taken:
// - slide-back (§14.2.1): C's apex lies `slideBack` behind the eye and its near plane where B begins (the
//   nearest receiver, an automatic z_n), its far plane where B ends;
// - unit-cube clipping (§14.2.2): the light camera aims at B's receivers in PPS and its window is their
//   bounding rectangle, not the whole unit cube;
// - close to the unit cube (the case of §14.2.2's cube map, not built here): the light camera's w over B's
//   receivers ranges over w_min..w_max; a ratio above `maxWarpRatio` is capped by moving the light's w = 0
//   plane away from B (a weaker perspective), and as closeness = w_min / w_max falls from 0.02 to 0 (the
//   light touching B in PPS) the cap falls geometrically to 1 and the matrices blend continuously into the
//   Focused fit.
//
// Directional lights only; spot and point lights keep the uniform fit.
#pragma once

#include <runtime/LightParameterization.h>

#include <glm/glm.hpp>

namespace runtime {

// What the PSM fit found, for tests and tools.
struct PsmDetails {
    glm::dmat4 postPerspective{1.0};         // C: world -> the virtual camera's clip space (D3D, depth 0..1)
    glm::dvec4 lightPostPerspective{0.0};    // L' = C (-d, 0), homogeneous
    double slideBack = 0.0;                  // apex of C behind the eye, world units
    double nearPlane = 0.0, farPlane = 0.0;  // C's, measured from its apex
    double closeness = 1.0;      // w_min / w_max of the light camera over B's receivers, before the cap
    double focusedWeight = 0.0;  // 0: pure PSM; 1: the Focused fit
};

// The PSM fit of a directional light (fitLight(LightParameterization::PSM, ...) calls this); other lights,
// and a camera that sees nothing of the bounds, get the uniform fit.
LightFit fitPerspectiveShadowMap(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                 const Light& light, const LightTunables& tunables = {},
                                 PsmDetails* details = nullptr);

}  // namespace runtime
