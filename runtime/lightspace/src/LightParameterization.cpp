// LightParameterization: uniform, focused and LiSPSM fits of a directional light's matrices (see the header).
#include <runtime/LightParameterization.h>
#include <runtime/PerspectiveShadowMap.h>

#include <runtime/CascadedShadowMaps.h>
#include <runtime/PerspectiveShadowCubeMap.h>

#include <runtime/IntersectionBody.h>
#include "LightSpaceMath.h"

#include <runtime/TrapezoidalShadowMap.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace runtime {

namespace {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// Widens [lo, hi] by a relative and an absolute margin, so points on the boundary stay inside after the
// rounding of the matrix products that map them.
void widen(float& lo, float& hi, float absolute) {
    const float margin = 1e-3f * (hi - lo) + absolute;
    lo -= margin;
    hi += margin;
}

// Scherzer 2005 §4.4's "middle vector" of B: the direction from the eye into the middle of B's volume, found
// as the sum of the vectors from the eye to B's vertices (the first half of focusBody's points; the far ones
// weigh more, as the seed wants). The view direction where that sum vanishes (the eye inside a symmetric B).
glm::vec3 middleVector(const Camera& camera, const std::vector<glm::vec3>& body) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < body.size() / 2; ++i) sum += glm::dvec3(body[i] - camera.position);
    const glm::vec3 viewDir = glm::normalize(camera.target - camera.position);
    return glm::length(sum) > 1e-9 ? glm::vec3(glm::normalize(sum)) : viewDir;
}

// A spot light keeps its perspective and its depth range; Focused (and LiSPSM, without a warp) crop its
// window to the receivers of B clipped by the light frustum (Scherzer 2005 §4.1). Every caster of a shadow on
// a receiver lies on the segment from that receiver to the light, and the whole segment projects onto the
// receiver's map position, so the receivers' window holds all casters. The window is the tighter of two
// conservative ones: the light frustum ∩ B's bounding box, and, when all of B lies before the light's
// plane, B's own projection. The uniform fit where B misses the light frustum.
LightFit cropToReceivers(const LightFit& uniform, const std::vector<glm::vec3>& body) {
    const glm::mat4 viewProjection = uniform.projection * uniform.view;
    Bounds receiverBox{glm::vec3(std::numeric_limits<float>::max()),
                       glm::vec3(std::numeric_limits<float>::lowest())};
    for (size_t i = 0; i < body.size() / 2; ++i) {
        receiverBox.min = glm::min(receiverBox.min, body[i]);
        receiverBox.max = glm::max(receiverBox.max, body[i]);
    }
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    auto window = [&](const std::vector<glm::vec3>& points, size_t count, glm::vec2& wlo, glm::vec2& whi) {
        for (size_t i = 0; i < count; ++i) {
            const glm::vec4 clip = viewProjection * glm::vec4(points[i], 1.0f);
            if (!(clip.w > 1e-6f)) return false;
            wlo = glm::min(wlo, glm::vec2(clip) / clip.w);
            whi = glm::max(whi, glm::vec2(clip) / clip.w);
        }
        return count > 0;
    };
    const std::vector<glm::vec3> clipped = intersectionBodyPoints(viewProjection, receiverBox);
    if (!window(clipped, clipped.size(), lo, hi)) return uniform;
    glm::vec2 bodyLo(std::numeric_limits<float>::max()), bodyHi(std::numeric_limits<float>::lowest());
    if (window(body, body.size() / 2, bodyLo, bodyHi)) {
        lo = glm::max(lo, bodyLo);
        hi = glm::min(hi, bodyHi);
    }
    lo = glm::max(lo, glm::vec2(-1.0f));
    hi = glm::min(hi, glm::vec2(1.0f));
    if (!(hi.x - lo.x > 1e-5f && hi.y - lo.y > 1e-5f)) return uniform;
    widen(lo.x, hi.x, 1e-6f);
    widen(lo.y, hi.y, 1e-6f);
    glm::mat4 crop(1.0f);  // x' = sx x + ox w, y' likewise: the window [lo, hi] to [-1, 1]
    crop[0][0] = 2.0f / (hi.x - lo.x);
    crop[1][1] = 2.0f / (hi.y - lo.y);
    crop[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    crop[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    LightFit cropped;
    cropped.view = uniform.view;
    cropped.projection = crop * uniform.projection;
    return cropped;
}

}  // namespace

std::optional<LightParameterization> parseLightParameterization(std::string_view name) {
    for (LightParameterization method :
         {LightParameterization::Uniform, LightParameterization::Focused, LightParameterization::LiSPSM,
          LightParameterization::TSM, LightParameterization::PSM, LightParameterization::PSMCube,
          LightParameterization::Cascaded})
        if (equalsIgnoringCase(name, lightParameterizationName(method))) return method;
    return std::nullopt;
}

const char* lightParameterizationName(LightParameterization method) {
    switch (method) {
        case LightParameterization::Uniform:
            return "Uniform";
        case LightParameterization::Focused:
            return "Focused";
        case LightParameterization::LiSPSM:
            return "LiSPSM";
        case LightParameterization::TSM:
            return "TSM";
        case LightParameterization::PSM:
            return "PSM";
        case LightParameterization::PSMCube:
            return "PSMCube";
        case LightParameterization::Cascaded:
            return "Cascaded";
    }
    return "Uniform";
}

std::optional<LispsmN> parseLispsmN(std::string_view name) {
    for (LispsmN choice : {LispsmN::Scherzer2005, LispsmN::Wimmer2004, LispsmN::Lloyd2006})
        if (equalsIgnoringCase(name, lispsmNName(choice))) return choice;
    return std::nullopt;
}

const char* lispsmNName(LispsmN choice) {
    switch (choice) {
        case LispsmN::Scherzer2005:
            return "Scherzer2005";
        case LispsmN::Wimmer2004:
            return "Wimmer2004";
        case LispsmN::Lloyd2006:
            return "Lloyd2006";
    }
    return "Wimmer2004";
}

// Scherzer 2005 §4.4 eq. 1 with Δz = d · sin γ as in the LiSPSM
// reference code (Lehőcz 2007): 1 / n_opt = sin γ / (z_n + sqrt(z_n (z_n + Δz))).
float lispsmWarp(float nearPlane, float depthExtent, float sinGamma) {
    const float zn = std::max(nearPlane, 1e-6f);
    return std::max(sinGamma, 0.0f) / (zn + std::sqrt(zn * (zn + std::max(depthExtent, 0.0f))));
}

float lloydEta(float gamma, float halfFov) {
    constexpr float kRightAngle = glm::radians(90.0f);
    constexpr float kEtaB = -0.2f, kEtaC = 0.0f;
    const float gammaA = halfFov / 3.0f, gammaB = halfFov, gammaC = halfFov + 0.3f * (kRightAngle - halfFov);
    if (gamma < gammaA) return -1.0f;
    if (gamma < gammaB)
        return -1.0f + (kEtaB + 1.0f) * (1.0f - std::cos(kRightAngle * (gamma - gammaA) / (gammaB - gammaA)));
    if (gamma < gammaC)
        return kEtaB + (kEtaC - kEtaB) * std::sin(kRightAngle * (gamma - gammaB) / (gammaC - gammaB));
    return kEtaC;
}

float lloydWarp(float optimalWarp, float depthExtent, float eta) {
    if (!(optimalWarp > 0.0f) || !(depthExtent > 0.0f) || !(eta > -1.0f)) return 0.0f;
    // In the reciprocal form, so that no n' is infinite: with s = sqrt(α) = 1 + d / n_opt,
    // 1 / n = (α - 1)(η + 1) / (d (1 + s - η (α - 1))) for η < 0 and (s - 1)(η s + 1) / d =
    // (η s + 1) / n_opt for η >= 0 (so η = 0 is LiSPSM's n_opt to the bit).
    const double d = depthExtent, s = 1.0 + d * optimalWarp, alphaMinusOne = (s - 1.0) * (s + 1.0);
    const double warp = eta < 0.0f ? alphaMinusOne * (eta + 1.0) / (d * (1.0 + s - eta * alphaMinusOne))
                                   : optimalWarp * (eta * s + 1.0);
    return static_cast<float>(warp);
}

glm::vec2 bodyViewDepthRange(const Camera& camera, const std::vector<glm::vec3>& body) {
    const glm::vec3 viewDir = glm::normalize(camera.target - camera.position);
    glm::vec2 range(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
    for (size_t i = 0; i < body.size() / 2; ++i) {
        const float depth = glm::dot(body[i] - camera.position, viewDir);
        range = {std::min(range.x, depth), std::max(range.y, depth)};
    }
    range.x = std::max(range.x, camera.nearPlane);
    range.y = std::max(range.y, range.x);
    return range;
}

std::vector<glm::vec3> focusBody(const Camera& camera, float aspect, const Bounds& sceneBounds,
                                 const glm::vec3& lightDirection) {
    return focusBody(camera, aspect, sceneBounds, sceneBounds, lightDirection);
}

std::vector<glm::vec3> focusBody(const Camera& camera, float aspect, const Bounds& receiverBounds,
                                 const Bounds& sceneBounds, const glm::vec3& lightDirection) {
    // The frustum ends where the bounds do: a far plane beyond the farthest corner cuts nothing off B, and
    // a near/far ratio like 0.001/100000 would leave the inverse projection that finds B's corners without
    // float precision.
    Camera clamped = camera;
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? receiverBounds.max.x : receiverBounds.min.x,
                          corner & 2 ? receiverBounds.max.y : receiverBounds.min.y,
                          corner & 4 ? receiverBounds.max.z : receiverBounds.min.z);
        farthest = std::max(farthest, glm::length(p - camera.position));
    }
    clamped.farPlane = std::clamp(1.01f * farthest, camera.nearPlane * 1.01f,
                                  std::max(camera.farPlane, camera.nearPlane * 1.01f));
    std::vector<glm::vec3> body =
        intersectionBodyPoints(clamped.projection(aspect) * clamped.view(), receiverBounds);
    const size_t receivers = body.size();
    // Casters between a receiver and the light: extrude B toward the light (against its direction of travel).
    for (size_t i = 0; i < receivers; ++i)
        body.push_back(body[i] - lightDirection * exitDistance(body[i], -lightDirection, sceneBounds));
    return body;
}

LightFit fitLight(LightParameterization method, const Scene& scene, const Bounds& sceneBounds, float aspect,
                  const Light& light, const LightTunables& tunables, const VisibleSamples* visible) {
    if (method == LightParameterization::Cascaded)
        return fitCascades(scene, sceneBounds, aspect, light, tunables, visible);  // CascadedShadowMaps.cpp
    LightFit uniform;
    uniform.view = light.view(sceneBounds);
    uniform.projection = light.projection(sceneBounds, nearestDepthFrom(scene, light));
    if (method == LightParameterization::Uniform || !(glm::dot(light.direction, light.direction) > 1e-12f))
        return uniform;
    if (method == LightParameterization::TSM) {
        const std::optional<TrapezoidalFit> trapezoidal =
            fitTrapezoid(scene, sceneBounds, aspect, light, tunables);
        return trapezoidal ? trapezoidal->fit : uniform;
    }
    if (method == LightParameterization::PSM)
        return fitPerspectiveShadowMap(scene, sceneBounds, aspect, light, tunables);
    if (method == LightParameterization::PSMCube)
        return fitPerspectiveShadowCubeMap(scene, sceneBounds, aspect, light, tunables);
    const glm::vec3 lightDir = glm::normalize(light.direction);
    // Fitted to what the camera sees (Lauritzen et al. 2011): B shrinks to the samples' depth range and
    // box, so the map's texels, LiSPSM's z_n, z_f (Wimmer2004) and the depth range go to visible receivers.
    const Camera camera = visible ? cameraOverSamples(scene.camera, *visible) : scene.camera;
    const Bounds receivers = visible ? receiverBoundsOverSamples(sceneBounds, *visible) : sceneBounds;
    const std::vector<glm::vec3> body = focusBody(camera, aspect, receivers, sceneBounds, lightDir);
    if (body.empty()) return uniform;  // the camera sees nothing of the scene: nothing to focus on
    if (light.type != Light::Type::Directional) return cropToReceivers(uniform, body);

    // Light space with y along V_P = (L x V) x L, the view direction made perpendicular to the light
    // (Scherzer 2005 eq. 3), so that the warp below runs from the viewer's side of B to its far side.
    const glm::vec3 viewDir = method == LightParameterization::LiSPSM && tunables.lispsmMiddleVector
                                  ? middleVector(camera, body)
                                  : glm::normalize(camera.target - camera.position);
    const AlignedLightView aligned = lightViewAcrossView(lightDir, viewDir, sceneBounds);
    const float sinGamma = aligned.sinGamma;
    const float radius = std::max(sceneBounds.radius(), 1e-3f);
    LightFit fit;
    fit.view = aligned.view;

    float yMin = std::numeric_limits<float>::max(), yMax = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : body) {
        const float y = glm::vec3(fit.view * glm::vec4(p, 1.0f)).y;
        yMin = std::min(yMin, y);
        yMax = std::max(yMax, y);
    }
    if (method == LightParameterization::LiSPSM) {
        float zNear = camera.nearPlane, deltaZ = 0.0f;
        if (tunables.lispsmN == LispsmN::Scherzer2005) {
            deltaZ =
                tunables.lispsmDepthExtent > 0.0f ? tunables.lispsmDepthExtent : (yMax - yMin) * sinGamma;
        } else {
            const glm::vec2 depths = bodyViewDepthRange(camera, body);
            zNear = depths.x;
            deltaZ = depths.y - depths.x;
        }
        float warp = lispsmWarp(zNear, deltaZ, sinGamma);
        if (tunables.lispsmN == LispsmN::Lloyd2006) {
            // θ: the smaller half-angle of the view frustum (the vertical one unless the frame is taller
            // than wide).
            const float halfFov =
                std::min(0.5f * camera.fovY, std::atan(std::tan(0.5f * camera.fovY) * aspect));
            warp =
                lloydWarp(warp, yMax - yMin, lloydEta(std::asin(std::clamp(sinGamma, 0.0f, 1.0f)), halfFov));
        }
        fit.warp = warp / std::max(tunables.lispsmNScale, 1e-3f);
    }
    // The warp P: a perspective projection along +y whose projection centre lies n = 1 / warp before the
    // near side of B, at the eye's x. In homogeneous form w = 1 + warp (y - yMin), so warp = 0 is the
    // identity and the fit moves continuously into the focused one as sin γ -> 0 (no threshold to cross).
    // Depth stays z / w: monotonic along each light ray, where w is constant.
    const float eyeX = glm::vec3(fit.view * glm::vec4(camera.position, 1.0f)).x;
    glm::mat4 warp(1.0f);  // glm: warp[column][row]
    warp[3][0] = -eyeX;
    warp[3][1] = -yMin;
    warp[1][3] = fit.warp;
    warp[3][3] = 1.0f - fit.warp * yMin;

    // x, y cover B and its extrusion toward the light; depth too, unless pancaking fits it to B's receivers
    // (the first half of the body) alone.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (size_t i = 0; i < body.size(); ++i) {
        const glm::vec4 clip = warp * fit.view * glm::vec4(body[i], 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        const bool setsDepth = !tunables.pancaking || i < body.size() / 2;
        lo = glm::min(lo, setsDepth ? ndc : glm::vec3(ndc.x, ndc.y, lo.z));
        hi = glm::max(hi, setsDepth ? ndc : glm::vec3(ndc.x, ndc.y, hi.z));
    }
    for (int axis = 0; axis < 3; ++axis) {
        // A body without extent across the light (bounds that are a point, a plane seen edge-on) gives
        // nothing to fit a map to.
        if (axis < 2 && !(hi[axis] - lo[axis] > 1e-6f * (std::abs(hi[axis]) + std::abs(lo[axis]))))
            return uniform;
        widen(lo[axis], hi[axis], 1e-6f * radius);
    }
    // Unit-cube fit: x, y to [-1, 1], depth to [0, 1] (D3D clip conventions).
    fit.projection = unitCubeFit(lo, hi) * warp;
    if (!isFinite(fit.projection) || !isFinite(fit.view)) return uniform;
    return fit;
}

}  // namespace runtime
