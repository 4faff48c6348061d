// PerspectiveShadowMap: the PSM fit of a directional light (see the header; Kozlov 2004 §14.2).
// Computed in double precision: C of a camera with
// z_f / z_n ~ 1000 puts the light within ~1e-3 of the unit cube, and the light camera's rows are
// differences of nearly equal numbers there.
#include <runtime/PerspectiveShadowMap.h>

#include "LightSpaceMath.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace runtime {

namespace {

// A light camera's clip rows x, y, w as linear functionals on world homogeneous points (x, y, z, 1).
struct ClipRows {
    glm::dvec4 x, y, w;
};

// Scales and offsets rows x and y so that the NDC of `points` spans [-1, 1] (the bounding rectangle of
// unit-cube clipping, Kozlov 2004 §14.2.2), widened by a relative margin so that the rounding of the matrix
// products keeps boundary points inside. False if the points have no extent across the light.
bool fitRectangle(ClipRows& rows, const std::vector<glm::vec3>& points) {
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::vec3& p : points) {
        const glm::dvec4 h(glm::dvec3(p), 1.0);
        const glm::dvec2 ndc(glm::dot(rows.x, h) / glm::dot(rows.w, h),
                             glm::dot(rows.y, h) / glm::dot(rows.w, h));
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    for (int axis = 0; axis < 2; ++axis) {
        if (!(hi[axis] - lo[axis] > 1e-9 * (std::abs(hi[axis]) + std::abs(lo[axis])))) return false;
        const double margin = 1e-3 * (hi[axis] - lo[axis]);
        lo[axis] -= margin;
        hi[axis] += margin;
    }
    // ndc' = (ndc - centre) * 2 / extent, i.e. row' = (row - centre w) * 2 / extent.
    rows.x = (rows.x - 0.5 * (hi.x + lo.x) * rows.w) * (2.0 / (hi.x - lo.x));
    rows.y = (rows.y - 0.5 * (hi.y + lo.y) * rows.w) * (2.0 / (hi.y - lo.y));
    return true;
}

}  // namespace

std::optional<PsmFrame> psmFrame(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                 const Light& light, const LightTunables& tunables, LightFit& fallback) {
    // The Focused fit is PSM's fallback and lends it its light view (z along the light, y along V_P). Spot
    // and point lights keep the uniform fit, and where Focused falls back to it (an empty B), so does PSM.
    const LightFit uniform =
        fitLight(LightParameterization::Uniform, scene, sceneBounds, aspect, light, tunables);
    fallback = uniform;
    if (light.type != Light::Type::Directional) return std::nullopt;
    PsmFrame frame;
    frame.focused = fitLight(LightParameterization::Focused, scene, sceneBounds, aspect, light, tunables);
    if (frame.focused.view == uniform.view && frame.focused.projection == uniform.projection)
        return std::nullopt;
    const Camera& camera = scene.camera;
    const glm::vec3 lightDir = glm::normalize(light.direction);
    frame.body = focusBody(camera, aspect, sceneBounds, lightDir);
    if (frame.body.empty()) return std::nullopt;
    fallback = frame.focused;
    // focusBody: B's vertices (the receivers), then each moved toward the light (the casters).
    const std::vector<glm::vec3>& body = frame.body;
    frame.receivers.assign(body.begin(), body.begin() + static_cast<long>(body.size() / 2));
    const std::vector<glm::vec3>& receivers = frame.receivers;
    // The virtual camera C (Kozlov 2004 §14.2.1, Figure 14-6): slid back by s along the view, with its near
    // plane kept where B begins, z_n = the nearest receiver's depth (at least the camera's near plane, more
    // where the bounds begin farther away: "we should maximize the Z_n value by any means") and its far
    // plane where B ends. With the same field of view its frustum holds the camera's beyond z_n.
    const glm::dmat4 eyeView(camera.view());
    double zMin = std::numeric_limits<double>::max(), zMax = std::numeric_limits<double>::lowest();
    for (const glm::vec3& p : receivers) {
        const double z = (eyeView * glm::dvec4(glm::dvec3(p), 1.0)).z;
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
    }
    zMin = std::max(zMin, double(camera.nearPlane));
    zMax = std::max(zMax, zMin * (1.0 + 1e-6));
    // Automatic slide-back: the apex sqrt(z_n z_f) behind the eye, so that C's near plane lies
    // z_n + sqrt(z_n z_f) from it, the perspective LiSPSM finds optimal for a light perpendicular to the
    // view (Scherzer 2005 eq. 1, sin γ = 1): Kozlov's balance of near and far texels (§14.2.1).
    const double slideBack =
        tunables.psmSlideBack >= 0.0f ? double(tunables.psmSlideBack) : std::sqrt(zMin * zMax);
    const double nearPlane = zMin + slideBack, farPlane = zMax + slideBack;
    const glm::dmat4 postPerspective =
        glm::perspectiveLH_ZO(double(camera.fovY), double(aspect), nearPlane, farPlane) *
        glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, slideBack)) * eyeView;

    // The light in PPS: the image of the point at infinity it shines from. w > 0: a point in front of the
    // virtual camera (light toward the viewer); w < 0: an inverted point (light from behind the viewer).
    const glm::dvec4 lightPps = postPerspective * glm::dvec4(-glm::dvec3(lightDir), 0.0);
    const glm::dvec3 ell(lightPps);
    const double lambda = lightPps.w;

    // The light camera aims at c, the centre of the receivers' bounding box in PPS (unit-cube clipping:
    // the receivers, not the whole cube). Its axis n runs along λ c - ℓ, the PPS direction of the light ray
    // through c (from L' toward c, reversed for an inverted light), which tends to -ℓ as λ -> 0: the light
    // turns into a direction in PPS and the perspective into an orthographic projection without a jump.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::vec3& p : receivers) {
        const glm::dvec4 q = postPerspective * glm::dvec4(glm::dvec3(p), 1.0);
        lo = glm::min(lo, glm::dvec3(q) / q.w);
        hi = glm::max(hi, glm::dvec3(q) / q.w);
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const glm::dvec3 axisVector = lambda * centre - ell;
    if (!(glm::length(axisVector) > 1e-12 * (glm::length(ell) + std::abs(lambda) * glm::length(centre))))
        return std::nullopt;
    const glm::dvec3 axis = glm::normalize(axisVector);
    // The image plane's x and y: Focused's light-view axes carried into PPS at c (the Jacobian of C's
    // division there) and made orthonormal to the axis, so that PSM's map keeps Focused's orientation and
    // the two can blend. A world direction across the light never maps onto the light ray's tangent.
    const glm::dmat4 focusedView(frame.focused.view);
    const glm::dvec3 worldX(focusedView[0][0], focusedView[1][0], focusedView[2][0]);
    const glm::dvec3 worldY(focusedView[0][1], focusedView[1][1], focusedView[2][1]);
    const auto carried = [&](const glm::dvec3& u) {
        const glm::dvec4 q = postPerspective * glm::dvec4(u, 0.0);
        return glm::dvec3(q) - centre * q.w;
    };
    glm::dvec3 ey = carried(worldY);
    ey = glm::normalize(ey - glm::dot(ey, axis) * axis);
    glm::dvec3 ex = carried(worldX);
    ex = glm::normalize(ex - glm::dot(ex, axis) * axis - glm::dot(ex, ey) * ey);

    frame.postPerspective = postPerspective;
    frame.lightPostPerspective = lightPps;
    frame.slideBack = slideBack;
    frame.nearPlane = nearPlane;
    frame.farPlane = farPlane;
    frame.centre = centre;
    frame.axis = axis;
    frame.ex = ex;
    frame.ey = ey;
    return frame;
}

LightFit fitPerspectiveShadowMap(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                 const Light& light, const LightTunables& tunables, PsmDetails* details) {
    LightFit fallback;
    const std::optional<PsmFrame> frame = psmFrame(scene, sceneBounds, aspect, light, tunables, fallback);
    if (!frame) return fallback;
    const LightFit& focused = frame->focused;
    const std::vector<glm::vec3>& body = frame->body;
    const std::vector<glm::vec3>& receivers = frame->receivers;
    const glm::dmat4& postPerspective = frame->postPerspective;
    const glm::dvec4& lightPps = frame->lightPostPerspective;
    const glm::dvec3 ell(lightPps);
    const double lambda = lightPps.w;
    const glm::dvec3 &centre = frame->centre, &axis = frame->axis, &ex = frame->ex, &ey = frame->ey;
    const glm::dmat4 focusedView(focused.view);

    // The light camera's rows on PPS homogeneous points Y = (y, ω): x = ex·(y - ω c), y = ey·(y - ω c),
    // w = n·(λ y - ω ℓ). Each vanishes on L' = (ℓ, λ) (ex, ey ⊥ n ∥ λ c - ℓ), so x/w, y/w is the central
    // projection from L' and, in world space (the rows times C), x, y and w do not change along the light.
    // w > 0 on the receivers' side of the plane through L' normal to n, behind the viewer too: for Y with
    // ω < 0 (a caster behind the eye) w is that of its receiver, which is what the inverse projection of
    // §14.2.1 achieves with near -a, far a.
    const glm::dmat4 toWorld = glm::transpose(postPerspective);  // a PPS row times C
    ClipRows psm{toWorld * glm::dvec4(ex, -glm::dot(ex, centre)),
                 toWorld * glm::dvec4(ey, -glm::dot(ey, centre)),
                 toWorld * glm::dvec4(lambda * axis, -glm::dot(axis, ell))};

    // Close to the unit cube (§14.2.2): w spans w_min..w_max over the receivers, the ratio of their texel
    // densities along the warp. It is capped by moving the w = 0 plane away from B by Δ (a weaker warp, like
    // a larger n of LiSPSM). The cap is maxWarpRatio while closeness = w_min / w_max stays above
    // kFadeCloseness; below, where L' nears the receivers and w_min would reach 0 on them, the cap falls
    // smoothly (geometrically) to 1, no warp, and the fit blends into Focused's as closeness falls to 0 (a
    // convex combination of two maps that both hold B holds B).
    constexpr double kFadeCloseness = 0.02;
    double wMin = std::numeric_limits<double>::max(), wMax = std::numeric_limits<double>::lowest();
    for (const glm::vec3& p : receivers) {
        const double w = glm::dot(psm.w, glm::dvec4(glm::dvec3(p), 1.0));
        wMin = std::min(wMin, w);
        wMax = std::max(wMax, w);
    }
    const double closeness = wMax > 0.0 ? wMin / wMax : -1.0;
    const double t = std::clamp(closeness / kFadeCloseness, 0.0, 1.0);
    const double psmWeight = t * t * (3.0 - 2.0 * t);
    const double focusedWeight = 1.0 - psmWeight;
    // Geometric: the texel-density ratio grows by equal factors across the fade, not mostly at its end.
    const double maxRatio = std::pow(std::max(double(tunables.psmMaxWarpRatio), 1.0), psmWeight);
    ClipRows rows;
    const glm::dmat4 focusedMatrix = glm::dmat4(focused.projection) * focusedView;
    const auto row = [](const glm::dmat4& m, int r) {
        return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]);
    };
    rows.x = focusedWeight * row(focusedMatrix, 0);
    rows.y = focusedWeight * row(focusedMatrix, 1);
    rows.w = focusedWeight * row(focusedMatrix, 3);  // (0, 0, 0, 1): orthographic, w = 1
    if (psmWeight > 0.0) {
        // w_max + Δ = maxRatio (w_min + Δ); with maxRatio = 1 the rows turn orthographic (w constant).
        const double shift =
            maxRatio > 1.0 ? std::max(0.0, (wMax - maxRatio * wMin) / (maxRatio - 1.0)) : 1e6 * wMax;
        psm.w.w += shift;
        if (!fitRectangle(psm, body)) return focused;
        // Homogeneous rows blend point by point with weights in proportion to their w: scaled so that w is 1
        // at the geometric mean of the receivers' w, neither near nor far receivers follow one map alone.
        const double scale = 1.0 / std::sqrt((wMin + shift) * (wMax + shift));
        rows.x += psmWeight * scale * psm.x;
        rows.y += psmWeight * scale * psm.y;
        rows.w += psmWeight * scale * psm.w;
    }
    if (!fitRectangle(rows, body)) return focused;

    // Into Focused's light view (a row on world points times the inverse view), where the rows' z
    // coefficient is 0 up to rounding: set it so. Depth is the light-view z (world distance along the
    // light) over w, fitted to [0, 1] over the body: linear along each light ray, like LiSPSM's.
    const glm::dmat4 fromView = glm::transpose(glm::inverse(focusedView));
    glm::dvec4 x = fromView * rows.x, y = fromView * rows.y, w = fromView * rows.w;
    x.z = y.z = w.z = 0.0;
    double zLo = std::numeric_limits<double>::max(), zHi = std::numeric_limits<double>::lowest();
    for (const glm::vec3& p : body) {
        const glm::dvec4 v = focusedView * glm::dvec4(glm::dvec3(p), 1.0);
        const double depth = v.z / glm::dot(w, v);
        zLo = std::min(zLo, depth);
        zHi = std::max(zHi, depth);
    }
    if (!(zHi > zLo)) return focused;
    const double zMargin = 1e-3 * (zHi - zLo);
    zLo -= zMargin;
    zHi += zMargin;
    const glm::dvec4 z = (glm::dvec4(0.0, 0.0, 1.0, 0.0) - zLo * w) / (zHi - zLo);
    glm::dmat4 projection(0.0);  // glm: projection[column][row]
    for (int c = 0; c < 4; ++c) {
        projection[c][0] = x[c];
        projection[c][1] = y[c];
        projection[c][2] = z[c];
        projection[c][3] = w[c];
    }
    LightFit fit;
    fit.view = focused.view;
    fit.projection = glm::mat4(projection);
    if (!isFinite(fit.projection)) return focused;
    if (details) {
        details->postPerspective = postPerspective;
        details->lightPostPerspective = lightPps;
        details->slideBack = frame->slideBack;
        details->nearPlane = frame->nearPlane;
        details->farPlane = frame->farPlane;
        details->closeness = closeness;
        details->focusedWeight = focusedWeight;
    }
    return fit;
}

}  // namespace runtime
