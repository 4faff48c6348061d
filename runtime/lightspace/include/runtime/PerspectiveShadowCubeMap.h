// PerspectiveShadowCubeMap: the `PSMCube` light parameterization, the cube-map variant of perspective shadow
// maps (Kozlov, "Perspective Shadow Maps: Care and Feeding", Kozlov 2004 §14.2.2):
// in the camera's post-perspective space (PPS) the light is
// a point L', and close to the receivers no single perspective from L' holds them all at a useful
// resolution (the single-map PSM fades into Focused there, PerspectiveShadowMap.h). A cube map around L'
// does: each of its six faces is a 90-degree perspective from L', and a point's face is the dominant axis
// of its "texture coordinate", its position minus L' ("a cube map with displaced centre").
//
// Built on PSM's frame (virtual camera with slide-back, L' = C (-d, 0) = (ℓ, λ)) with these choices:
// - The cube's axes are PSM's light camera axes, n along λ c - ℓ (from L' toward the receivers' centre c)
//   and Focused's light x, y carried to c, not the unit cube's: a light far from the cube puts every
//   receiver into the front face, which then is PSM's single map (continuous as λ -> 0, where L' goes to
//   infinity), and a light close to the receivers spreads them over up to five faces (all six for a light
//   inside them).
// - The cube coordinates of a world point P, W = (k ex·(y - ω c), k ey·(y - ω c), n·(λ y - ω ℓ)) for
//   C (P, 1) = (y, ω), are λ y - ω ℓ = λ ω (p - L') in the cube frame (k = |λ|): Kozlov's "vertex position
//   minus light position", scaled by λ ω, which keeps it finite for an inverted light (λ < 0, the sun
//   behind the viewer, whose faces are then Kozlov's inverse projections) and for casters behind the eye
//   (ω < 0). W does not change along a world light ray, so a caster lands in its receivers' face at their
//   texel. k stays above 1e-9 |ℓ| so that W keeps its x, y as λ -> 0.
// - Unit-cube clipping per face (§14.2.2): each face's window is the bounding rectangle of the receivers
//   within it (their light-space hull clipped to the face's pyramid), so that a face spends its tile on
//   receivers only; a face no receiver uses gets matrices that cull every draw (clip w < 0) and
//   `serves = false`, and leave-out skips its passes. The used faces share the atlas (LightView::atlasRect):
//   one face gets all of it, two or three a column each, four a 2 x 2 grid, five or six a 3 x 2 grid, so
//   that the cube map has the texels of one map of the atlas's size however many faces it uses.
// - Depth is the world distance along the light over the face's w, fitted to [0, 1]: linear along each
//   light ray, as PSM's. Receivers closer to L' than 1e-4 of the face's farthest w (Kozlov's near plane
//   z_1) fall beyond depth 1.
//
// The fit's own view and projection (plain RenderPort=lightN) are PSM's fallback, the Focused fit; the
// faces are its sub-views, RenderPort=lightN.faceK (K = 2 i for +axis i, 2 i + 1 for -axis i; axis 2 is n,
// so face 4 is the front). Spot and point lights, and where PSM cannot work, get the fallback fit in face 4
// and every point selects face 4.
#pragma once

#include <runtime/LightParameterization.h>

#include <array>

namespace runtime {

constexpr int kCubeFaces = 6;

// What the cube fit found, for tests and tools.
struct CubeMapDetails {
    glm::dvec4 lightPostPerspective{0.0};  // L' = (ℓ, λ)
    std::array<bool, kCubeFaces> used{};   // faces holding receivers (= LightView::serves)
    int facesUsed = 0;
    bool fellBack = true;  // the fallback fit in face 4 (not a directional light, or PSM cannot work)
};

LightFit fitPerspectiveShadowCubeMap(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                     const Light& light, const LightTunables& tunables = {},
                                     CubeMapDetails* details = nullptr);

// The face the fit's faceSelect picks for a world point (the dominant axis of W, as psm_cube.fx does).
int cubeFaceOf(const LightFit& fit, const glm::vec3& world);

}  // namespace runtime
