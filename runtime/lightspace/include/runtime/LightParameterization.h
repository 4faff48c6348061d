// LightParameterization: the providers of a light's view and projection
// (docs/techniques/light-space-parameterizations.md). An effect chooses one per light through the annotation
// `string Parameterization = "..."` on its light matrices; RenderPort=lightN and every parameter annotated
// with that light then use the same fit, computed once per frame.
//
//   Uniform   the light's own matrices (Scene.h, Light::view/projection): the whole scene, view-independent
//   Focused   an orthographic fit to the intersection body B = view frustum ∩ scene bounds, extruded toward
//             the light to the scene bounds (Scherzer 2005 §4.1 )
//   LiSPSM    Focused followed by a perspective warp along V_P, the view direction (or B's middle vector)
//             made perpendicular to the light (Scherzer §4.4 eq. 1-3; Lehőcz), strength 1 / n_opt
//   TSM       trapezoidal shadow maps (Martin & Tan 2004; Lehőcz 2007): a trapezoid around B in light space,
//             warped onto the square with the 80% rule (TrapezoidalShadowMap.h)
//   PSM       perspective shadow maps: the light as a point in the camera's post-perspective space, with
//             Kozlov's inverse projection, slide-back and unit-cube clipping (Kozlov 2004 §14.2,
//             runtime/PerspectiveShadowMap.h)
//   PSMCube   PSM's cube-map variant (Kozlov §14.2.2): six faces around the light in PPS, rendered through
//             RenderPort=lightN.faceK into the tiles of one atlas (runtime/PerspectiveShadowCubeMap.h)
//   Cascaded  the Focused fit as view 0, plus one stabilized orthographic sub-view per slice of the view
//             depth range (cascaded / parallel-split shadow maps, runtime/CascadedShadowMaps.h), rendered
//             through RenderPort=lightN.cascadeK into the tiles of one atlas
//
// Focused, LiSPSM, TSM, PSM and Cascaded fit directional lights; for spot (and point) lights Focused and
// LiSPSM crop the light's own perspective window to the receivers of B, without a warp, and the others keep
// the uniform fit.
#pragma once

#include <runtime/Scene.h>
#include <runtime/VisibleSamples.h>

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace runtime {

enum class LightParameterization { Uniform, Focused, LiSPSM, TSM, PSM, PSMCube, Cascaded };

// "Uniform", "Focused", "LiSPSM", "TSM", "PSM", "PSMCube", "Cascaded" (case-insensitive); nullopt for
// anything else.
std::optional<LightParameterization> parseLightParameterization(std::string_view name);
const char* lightParameterizationName(LightParameterization method);

// Where LiSPSM's n_opt takes z_n and the depth extent from
// (docs/techniques/light-space-parameterizations.md). Both use n_opt = (z_n + sqrt(z_n z_f)) / sin γ; they
// differ in z_n and z_f:
//   Scherzer2005  z_n the camera's near plane, z_f = z_n + Δz with Δz = d sin γ (d: B's extent along V_P,
//                 as the reference code) or LiSPSMDepthExtent (Scherzer 2005 §4.4, eq. 1)
//   Wimmer2004    z_n, z_f the nearest and farthest view-space depth of B (Wimmer, Scherzer & Purgathofer
//                 2004, n_opt = z_n + sqrt(z_n z_f) for a light perpendicular to the view, over sin γ)
//   Lloyd2006     Lloyd, Tuft, Yoon & Manocha 2006's parameter η, which moves n from the uniform map
//                 (η = -1) through Wimmer2004's n_opt (η = 0) toward PSM's n = z_n (η = 1), and their
//                 choice of η by the angle γ between light and view (lloydEta, lloydWarp)
enum class LispsmN { Scherzer2005, Wimmer2004, Lloyd2006 };

// "Scherzer2005", "Wimmer2004", "Lloyd2006" (case-insensitive); nullopt for anything else.
std::optional<LispsmN> parseLispsmN(std::string_view name);
const char* lispsmNName(LispsmN choice);

// The tunables an effect sets through parameters with these semantics
// (docs/techniques/light-space-parameterizations.md).
struct LightTunables {
    // LiSPSMNScale: multiplies n_opt. 1 = the optimum (LiSPSMNOpt); larger weakens the warp (toward
    // Focused), smaller strengthens it.
    float lispsmNScale = 1.0f;
    // LiSPSMDepthExtent (Scherzer2005 only): Δz of eq. 1 in world units when > 0 (e.g. a far plane from a
    // visibility algorithm, Scherzer 2005 §4.4); 0 = the reference code's d · sin γ, d the extent of B along
    // V_P.
    float lispsmDepthExtent = 0.0f;
    // LiSPSMNOpt (a string): whose z_n and z_f n_opt takes, or Lloyd et al. 2006's η (LispsmN). Wimmer2004
    // measured best on the γ sweep, a city field and a street against the sun
    // (docs/results/2026-12-03-lispsm-n.md).
    LispsmN lispsmN = LispsmN::Wimmer2004;
    // LiSPSMMiddleVector: V_P from B's "middle vector" (Scherzer §4.4: the sum of the vectors from the eye
    // to B's vertices, which leans toward where B has volume) instead of the view direction of eq. 3.
    bool lispsmMiddleVector = false;
    // LightPancaking (Focused, LiSPSM): the map's depth range spans the receivers of B only; casters between
    // them and the light get depth < 0 and must be drawn with DepthClipEnable = false (depth clamp), which
    // flattens them onto the near plane (Scherzer 2005 §4.1). A tighter range for fixed-point depth maps.
    bool pancaking = false;
    // TSMFocus: TSM's focus distance δ (Lehőcz, the 80% rule) as a fraction of the depth of B along the
    // view: the nearest TSMFocus of what the camera sees gets 80% of the map's height.
    float tsmFocus = 0.3f;
    // PSMSlideBack: how far (world units) PSM's virtual camera slides back behind the eye, its near plane
    // staying where B begins (Kozlov 2004 §14.2.1); < 0 = automatic, sqrt(z_n z_f) of B's depth range.
    float psmSlideBack = -1.0f;
    // PSMMaxWarpRatio: the largest ratio of texel densities PSM may put between B's receivers (light clip
    // w, max / min); closer to the light in post-perspective space, PSM weakens and fades into Focused.
    float psmMaxWarpRatio = 100.0f;
    // CascadeCount: how many cascades split the view depth range (1..kMaxCascades, clamped).
    int cascadeCount = 4;
    // CascadeSplitLambda: the practical split scheme's blend, z_i = λ z_log + (1 - λ) z_uni: 0 = uniform,
    // 1 = logarithmic.
    float cascadeSplitLambda = 0.5f;
    // CascadeBlend: the share of each cascade's depth range, at its far end, across which the effect blends
    // it into the next one (0..0.5); the next cascade's fit starts that much earlier.
    float cascadeBlend = 0.1f;
    // LightFitVisibleSamples: fit Focused, LiSPSM and Cascaded to the samples the camera sees (a read-back
    // of the visible surfaces, runtime/VisibleSamples.h) instead of the whole intersection body B: their
    // depth range sets the cascade splits and bounds B, their box narrows it (Lauritzen et al. 2011).
    bool fitToVisibleSamples = false;
};

// One sub-view of a light (a cascade, or a face of PSMCube's cube map): its matrices and what it serves.
struct LightView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float splitNear = 0.0f;  // a cascade: where its fit starts, the blend band before its split included
    float splitFar = 0.0f;   // a cascade: its split: beyond this view depth the next cascade serves
    bool serves = true;      // false: no receiver of B uses it (a cube face): its passes are left out
    // A cube face: its tile of the atlas (u0, v0, du, dv; atlasViewport), the used faces sharing the atlas;
    // du = 0: the fixed grid of cascadeAtlasRect.
    glm::vec4 atlasRect{0.0f};
};

struct LightFit {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float warp = 0.0f;  // 1 / n of the LiSPSM or TSM warp (world units⁻¹): 0 for an orthographic fit
    // Cascaded: one sub-view per cascade, nearest first (RenderPort=lightN.cascadeK); PSMCube: the six
    // faces (RenderPort=lightN.faceK); empty otherwise.
    std::vector<LightView> cascades;
    // PSMCube: the sub-views are cube faces, and world -> the cube frame (xyz; w unused) whose dominant
    // axis picks a point's face: face 2 i for +axis i, 2 i + 1 for -axis i (semantic CubeFaceSelect).
    bool cubeFaces = false;
    glm::mat4 faceSelect{0.0f};
    // True when clip w > 0 is exactly the half-space the light shines into (a spot's own perspective, the
    // LiSPSM and TSM warps, whose centres lie before B along V_P while shadows run across it, PSM, whose w
    // is constant along each light ray, any orthographic fit): a caster wholly at w <= 0 shadows nothing in
    // the map, and leave-out drops it.
    bool shinesIntoPositiveW = true;
};

// Scherzer eq. 1: n_opt = (z_n + sqrt(z_n (z_n + Δz))) / sin γ. Returns its reciprocal, the warp strength,
// which goes to 0 (no warp: the focused fit) as sin γ -> 0 instead of dividing by zero. Wimmer et al. 2004's
// n_opt is the same expression with Δz = z_f - z_n.
float lispsmWarp(float nearPlane, float depthExtent, float sinGamma);

// Lloyd et al. 2006's choice of η for the angle γ between the light and the view direction (both in
// radians, γ in [0, π/2]) and the camera's half field of view θ (the smaller of its two half-angles):
// γ_a = θ/3, γ_b = θ, γ_c = θ + 0.3 (90° - θ), η_b = -0.2, η_c = 0;
//   η = -1                                                     γ < γ_a  (the uniform map: light along view)
//   η = -1 + (η_b + 1) (1 - cos(90° (γ - γ_a) / (γ_b - γ_a)))  γ_a <= γ < γ_b
//   η = η_b + (η_c - η_b) sin(90° (γ - γ_b) / (γ_c - γ_b))     γ_b <= γ < γ_c
//   η = η_c                                                    γ_c <= γ
// The second branch as printed reads (1 + cos ...), which jumps from -1 to 0.6 at γ_a; 1 - cos is the
// continuous curve from -1 at γ_a to η_b at γ_b that the branches around it meet.
float lloydEta(float gamma, float halfFov);

// The warp strength 1 / n of Lloyd et al. 2006's parameterization at η, for a body B whose extent along
// V_P in light space is `depthExtent` (d), anchored at `optimalWarp`, 1 / n_opt of LiSPSM (η = 0). With n' =
// n / d and sqrt(α) = 1 + d / n_opt (for a light across the view, α = z_f / z_n):
//   η < 0:  n' = (1 + sqrt(α) - η (α - 1)) / ((α - 1)(η + 1))   (n -> ∞, the uniform map, as η -> -1)
//   η >= 0: n' = 1 / ((sqrt(α) - 1)(η sqrt(α) + 1))             (n = d / (α - 1) = z_n, PSM's, at η = 1)
// 0 (no warp) where optimalWarp or d is 0 or η <= -1.
float lloydWarp(float optimalWarp, float depthExtent, float eta);

// The nearest and farthest view-space depth (along the camera's view direction) of B, the first half of
// focusBody's points, the nearest no closer than the camera's near plane: Wimmer et al. 2004's z_n, z_f.
glm::vec2 bodyViewDepthRange(const Camera& camera, const std::vector<glm::vec3>& body);

// Where receivers (B) and the casters that can shadow them lie, in world space: B's vertices, then the same
// vertices moved toward the light until they leave the scene bounds. Empty if the camera sees no part of
// the bounds.
std::vector<glm::vec3> focusBody(const Camera& camera, float aspect, const Bounds& sceneBounds,
                                 const glm::vec3& lightDirection);
// The same with B = view frustum ∩ `receiverBounds` (the receivers the camera sees, inside the scene
// bounds), its casters still extruded to the scene bounds.
std::vector<glm::vec3> focusBody(const Camera& camera, float aspect, const Bounds& receiverBounds,
                                 const Bounds& sceneBounds, const glm::vec3& lightDirection);

// The light's matrices under `method`. `aspect` is the camera's (frame width / height). `visible` (may be
// null): the samples the camera sees; Focused, LiSPSM and Cascaded then fit B to them
// (LightTunables::fitToVisibleSamples), the other methods ignore them.
LightFit fitLight(LightParameterization method, const Scene& scene, const Bounds& sceneBounds, float aspect,
                  const Light& light, const LightTunables& tunables = {},
                  const VisibleSamples* visible = nullptr);

}  // namespace runtime
