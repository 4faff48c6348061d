// TrapezoidalShadowMap: the TSM fit of a directional light (see the header). Lehőcz 2007
// (, "Trapéz shadow map-ek") gives the construction: the view
// frustum in light space, its centre line, the 2D convex hull, the top and base lines perpendicular to the
// centre line and touching the hull, the 80% rule, and N_T as a product of 8 matrices.
#include <runtime/TrapezoidalShadowMap.h>

#include "LightSpaceMath.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

namespace {

float smoothstep01(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

// The 80% rule (Lehőcz 2007: P_L, the point δ beyond the near plane on the view's centre line, maps to the
// 80% line of the map). Along the centre line N_T is a 1D projective map of the distance t from the
// projection centre q, which lies η before the top line: v(t) = A + B / t. With the paper's ends v(η) = +1
// (top) and v(η + λ) = -1 (base), B = 2 η (η + λ) / λ, and v(η + δ') = ξ gives
//   (1 - ξ) λ (η + δ') = 2 δ' (η + λ)   =>   η = λ δ' (1 + ξ) / (λ (1 - ξ) - 2 δ'),
// Martin & Tan's formula, with ξ = -0.6 the line 80% of the way from +1 to -1. 1/η goes to 0 (q at
// infinity, a rectangle) as δ' reaches (1 - ξ) / 2 · λ = 0.8 λ, and stays 0 past it.
float tsmWarp(float height, float focusOffset, float xi) {
    const float lambda = std::max(height, 1e-12f);
    // A focus point at or above the top line would put q on it (η = 0, a top edge of zero width): keep it
    // at least 1% of the height below.
    const float delta = std::max(focusOffset, 1e-2f * lambda);
    return std::max(lambda * (1.0f - xi) - 2.0f * delta, 0.0f) / (lambda * delta * (1.0f + xi));
}

std::optional<TrapezoidalFit> fitTrapezoid(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                           const Light& light, const LightTunables& tunables) {
    if (light.type != Light::Type::Directional || !(glm::dot(light.direction, light.direction) > 1e-12f))
        return std::nullopt;
    const glm::vec3 lightDir = glm::normalize(light.direction);
    const Camera& camera = scene.camera;
    const std::vector<glm::vec3> body = focusBody(camera, aspect, sceneBounds, lightDir);
    if (body.empty()) return std::nullopt;

    // The light view of the focused fit, y along V_P = (L x V) x L: the projection of the view's centre
    // line (near-plane centre to far-plane centre) into the light's (x, y) plane runs along +y through the
    // eye's x, so the paper's rotation R (top and base parallel to x) is already done.
    const glm::vec3 viewDir = glm::normalize(camera.target - camera.position);
    const AlignedLightView aligned = lightViewAcrossView(lightDir, viewDir, sceneBounds);
    const float sinGamma = aligned.sinGamma;
    const float radius = std::max(sceneBounds.radius(), 1e-3f);
    TrapezoidalFit result;
    LightFit& fit = result.fit;
    fit.view = aligned.view;
    auto lightSpace = [&](const glm::vec3& p) { return glm::vec3(fit.view * glm::vec4(p, 1.0f)); };

    // The trapezoid encloses the 2D convex hull of every point of the focus body, B and its extrusion
    // toward the light, not only of the view frustum as in the paper: a trapezoid fitted to the frustum
    // alone leaves out the casters the extrusion adds (they lie beyond its top when the light comes from
    // behind the viewer, beside it for a low sun), and every one must land in the map. The price is a
    // longer trapezoid, so a weaker warp, where the casters stick out. Top and base lines perpendicular to
    // the centre line touching the hull are the extremes of y over the points, and the side lines through q
    // touching it are their extreme slopes, so the hull itself never needs to be built.
    std::vector<glm::vec3> points;
    points.reserve(body.size());
    float top = std::numeric_limits<float>::max(), base = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : body) {
        points.push_back(lightSpace(p));
        top = std::min(top, points.back().y);
        base = std::max(base, points.back().y);
    }
    const float height = base - top;
    if (!(height > 1e-6f * radius)) return std::nullopt;  // B seen edge-on: nothing to fit a map to
    const float eyeX = lightSpace(camera.position).x;

    // The 80% rule: P_L lies `tsmFocus` of B's depth along the view's centre line past B's nearest point,
    // which is on the near plane (the paper's start) unless the camera stands outside the scene bounds:
    // measured from the near plane there, P_L could fall before B, above the top line. focusBody lists B's
    // vertices first, then their extrusions.
    float nearest = std::numeric_limits<float>::max(), farthest = 0.0f;
    for (size_t i = 0; i < body.size() / 2; ++i) {
        const float distance = glm::dot(body[i] - camera.position, viewDir);
        nearest = std::min(nearest, distance);
        farthest = std::max(farthest, distance);
    }
    nearest = std::max(nearest, camera.nearPlane);
    result.focusPoint = camera.position + viewDir * (nearest + std::clamp(tunables.tsmFocus, 0.0f, 1.0f) *
                                                                   std::max(farthest - nearest, 0.0f));
    // With the light inside the view cone (γ below its half-angle θ, the half-diagonal of the frustum) the
    // frustum's light-space hull surrounds the eye and the paper falls back to a square around it: there
    // is no "near side" to widen. Instead of switching there, the warp fades in smoothly with sin γ from 0
    // at γ = 0 (the rectangle: the focused fit) to the full 80% rule at γ = θ, so no threshold makes the
    // map jump.
    const float halfDiagonal = std::atan(std::tan(0.5f * camera.fovY) * std::sqrt(1.0f + aspect * aspect));
    result.strength = smoothstep01(sinGamma / std::sin(halfDiagonal));
    fit.warp = result.strength * tsmWarp(height, lightSpace(result.focusPoint).y - top);

    // Side lines through q (η = 1 / warp before the top line, on the centre line x = eyeX): each is
    // x = eyeX + c (1 + warp (y - top)), c its offset at the top; the extreme c over the points touch the
    // hull. warp = 0 gives the vertical lines of the bounding rectangle.
    float left = std::numeric_limits<float>::max(), right = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : points) {
        const float c = (p.x - eyeX) / (1.0f + fit.warp * (p.y - top));
        left = std::min(left, c);
        right = std::max(right, c);
    }
    if (!(right - left > 1e-6f * radius)) return std::nullopt;
    const float spread = 1.0f + fit.warp * height;  // base width / top width
    result.corners = {glm::vec2(eyeX + left, top), glm::vec2(eyeX + right, top),
                      glm::vec2(eyeX + right * spread, base), glm::vec2(eyeX + left * spread, base)};

    // N_T, the trapezoid-to-square map, as one projective map of (x, y) instead of the paper's product
    // T1 R T2 H S1 N T3 S2: R is the identity here, and the product's T2 moves the apex q to the origin,
    // which is at infinity for the rectangle that the fade above must reach continuously. In homogeneous
    // light-view coordinates, with s = y - top:
    //   w = 1 + warp s                                  (perspective along y only; 1 for the rectangle)
    //   x' = (2 (x - eyeX) - (left + right) w) / (right - left)    (the sides to x'/w = -1, +1)
    //   y' = (2 + warp λ) / λ · s - 1                   (the top to y'/w = -1, the base to +1)
    //   z' = z
    // Lines of equal y stay lines of equal y'/w, so P_L lands on -ξ wherever its x. w depends on y only:
    // along a light ray it is constant and depth z'/w stays monotonic, as with LiSPSM (the paper's linear
    // depth, Lehőcz 2007, which it notes a GPU can only have by multiplying z back by w in the shader).
    glm::mat4 trapezoid(0.0f);  // glm: trapezoid[column][row]
    const float width = right - left;
    trapezoid[0][0] = 2.0f / width;
    trapezoid[1][0] = -(left + right) * fit.warp / width;
    trapezoid[3][0] = (-2.0f * eyeX - (left + right) * (1.0f - fit.warp * top)) / width;
    const float ySlope = (2.0f + fit.warp * height) / height;
    trapezoid[1][1] = ySlope;
    trapezoid[3][1] = -ySlope * top - 1.0f;
    trapezoid[2][2] = 1.0f;
    trapezoid[1][3] = fit.warp;
    trapezoid[3][3] = 1.0f - fit.warp * top;

    // The unit-cube fit (x, y to [-1, 1], depth to [0, 1], D3D clip conventions) over the warped body, as
    // fitLight's: x and y are already at ±1 there up to rounding, and the margin keeps the boundary points
    // inside after the matrix products; depth gets its range here.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : points) {
        const glm::vec4 clip = trapezoid * glm::vec4(p, 1.0f);
        lo = glm::min(lo, glm::vec3(clip) / clip.w);
        hi = glm::max(hi, glm::vec3(clip) / clip.w);
    }
    for (int axis = 0; axis < 3; ++axis) {
        // x and y are in map units already ([-1, 1]); depth is still in world units (z / w).
        const float margin = 1e-3f * (hi[axis] - lo[axis]) + (axis == 2 ? 1e-6f * radius : 1e-6f);
        lo[axis] -= margin;
        hi[axis] += margin;
    }
    fit.projection = unitCubeFit(lo, hi) * trapezoid;
    if (!isFinite(fit.projection) || !isFinite(fit.view)) return std::nullopt;
    return result;
}

}  // namespace runtime
