// PerspectiveShadowMap: the PSM provider of LightParameterization (Stamminger & Drettakis 2002, with
// Kozlov's "care and feeding", Kozlov 2004 §14.2 ; Scherzer 2005 §2).
//
// The shadow map is rendered in the post-perspective space (PPS) of a virtual camera C, where a directional
// light becomes a point L' = C (-d, 0): an ordinary point in front of the camera when the light shines
// toward the viewer (L'.w > 0), an "inverted" point when it comes from behind the viewer (L'.w < 0), and a
// direction when it is perpendicular to the view (L'.w = 0). The light camera is a perspective from L'
// (Kozlov §14.2.2) whose rows x, y, w all vanish on L': in world space they do not change along the light
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
// - close to the unit cube (§14.2.2's cube map, PerspectiveShadowCubeMap.h): the light camera's w
// over B's
//   receivers ranges over w_min..w_max; a ratio above `maxWarpRatio` is capped by moving the light's w = 0
//   plane away from B (a weaker perspective), and as closeness = w_min / w_max falls from 0.02 to 0 (the
//   light touching B in PPS) the cap falls geometrically to 1 and the matrices blend continuously into the
//   Focused fit. The cube-map variant, `PSMCube` (PerspectiveShadowCubeMap.h), needs no such fade.
//
// Directional lights only; spot and point lights keep the uniform fit.
#pragma once

#include <runtime/LightParameterization.h>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace runtime {

// What PSM's fits build on (the single map below and the cube map of PerspectiveShadowCubeMap.h): the
// virtual camera C, the light L' in its post-perspective space (PPS) and the light camera's axes there.
struct PsmFrame {
    LightFit focused;                      // the Focused fit, whose light view (z along the light) PSM keeps
    std::vector<glm::vec3> body;           // focusBody: B's vertices (the receivers), then the casters
    std::vector<glm::vec3> receivers;      // B's vertices
    glm::dmat4 postPerspective{1.0};       // C: world -> the virtual camera's clip space (D3D, depth 0..1)
    glm::dvec4 lightPostPerspective{0.0};  // L' = C (-d, 0) = (ℓ, λ)
    double slideBack = 0.0, nearPlane = 0.0, farPlane = 0.0;
    glm::dvec3 centre{0.0};       // c: the centre of the receivers' bounding box in PPS
    glm::dvec3 axis{0.0};         // n: along λ c - ℓ, the PPS direction of the light ray through c
    glm::dvec3 ex{0.0}, ey{0.0};  // Focused's light-view x and y carried into PPS at c, orthonormal to n
};

// The frame of a directional light; nullopt where PSM cannot work, with the fit to use instead in
// `fallback` (the uniform fit for spot and point lights or an empty B, else the Focused fit).
std::optional<PsmFrame> psmFrame(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                 const Light& light, const LightTunables& tunables, LightFit& fallback);

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
