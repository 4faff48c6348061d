// CascadedShadowMaps: split depths, atlas layout and the stabilized per-cascade fits (see the header).
#include <runtime/CascadedShadowMaps.h>

#include <runtime/IntersectionBody.h>
#include "LightSpaceMath.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace runtime {

namespace {

// A cascade's centre moves in steps of 1/kSnapSteps of its extent: a whole number of texels for every
// tile of kSnapSteps·k texels, so a moving camera shifts the map by whole texels only and the shadow edges
// it rasterizes stay where they were.
constexpr float kSnapSteps = 64.0f;
// Extents and the far end of the depth range grow in steps of these ratios: they change only when a slice
// outgrows a step, not with every small camera move (each change re-rasterizes the cascade's edges).
constexpr float kExtentStepsPerOctave = 8.0f;
constexpr float kFarStepsPerOctave = 16.0f;

// `value` rounded up to unit · 2^(k / stepsPerOctave) for a whole k.
float roundUpOnLadder(float value, float unit, float stepsPerOctave) {
    if (!(value > 0.0f) || !(unit > 0.0f)) return value;
    return unit * std::exp2(std::ceil(stepsPerOctave * std::log2(value / unit)) / stepsPerOctave);
}

// The far end of the split range: the camera's far plane, or the view depth of the farthest corner of the
// bounds if that is nearer, rounded up on a ladder (kFarStepsPerOctave) so the splits do not follow every
// camera move.
float splitRangeEnd(const Camera& camera, const Bounds& bounds) {
    const glm::mat4 view = camera.view();
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x, corner & 2 ? bounds.max.y : bounds.min.y,
                          corner & 4 ? bounds.max.z : bounds.min.z);
        farthest = std::max(farthest, (view * glm::vec4(p, 1.0f)).z);
    }
    const float nearPlane = std::max(camera.nearPlane, 1e-6f);
    const float laddered =
        roundUpOnLadder(std::max(farthest, nearPlane * 1.01f), nearPlane, kFarStepsPerOctave);
    return std::max(std::min(laddered, camera.farPlane), nearPlane * 1.01f);
}

// The split range over the visible samples (Lauritzen et al. 2011, §4: the tight z-range), its ends rounded
// outward on the far end's ladder so that the splits move only when the visible range outgrows a step.
std::pair<float, float> visibleSplitRange(const Camera& camera, const VisibleSamples& visible) {
    const Camera tight = cameraOverSamples(camera, visible);
    const float unit = std::max(camera.nearPlane, 1e-6f);
    const float start = unit * std::exp2(std::floor(kFarStepsPerOctave * std::log2(tight.nearPlane / unit)) /
                                         kFarStepsPerOctave);
    const float end = roundUpOnLadder(tight.farPlane, unit, kFarStepsPerOctave);
    return {std::max(start, camera.nearPlane),
            std::max(std::min(end, camera.farPlane), std::max(start, unit) * 1.01f)};
}

// The smallest-radius sphere around the slice [start, end] of the camera frustum in the family centred on
// its axis (its radius does not depend on where the camera is or looks): centre and radius.
std::pair<glm::vec3, float> sliceSphere(const Camera& camera, float aspect, float start, float end) {
    const float tanY = std::tan(0.5f * camera.fovY), tanX = tanY * aspect;
    // Squared half-diagonal of a cross section at depth z is k z²; the centre at depth c on the axis makes
    // the near and far corners equidistant: (c - s)² + k s² = (e - c)² + k e², clamped into [s, e].
    const float k = tanX * tanX + tanY * tanY;
    const float c = std::clamp(0.5f * (start + end) * (1.0f + k), start, end);
    const float radius = std::sqrt(
        std::max((c - start) * (c - start) + k * start * start, (end - c) * (end - c) + k * end * end));
    const glm::mat4 toWorld = glm::inverse(camera.view());
    return {glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, c, 1.0f)), radius};
}

}  // namespace

// Zhang et al. 2006 (parallel-split shadow maps; not among the seeds): the logarithmic split keeps the
// ratio z_{i+1} / z_i constant (Lehőcz 2007's "twice the distance" with ratio (f/n)^(1/N)), the uniform one
// the difference, and the practical scheme averages them with weight λ.
std::vector<float> cascadeSplitDepths(float nearPlane, float farPlane, int count, float lambda) {
    count = std::clamp(count, 1, kMaxCascades);
    lambda = std::clamp(lambda, 0.0f, 1.0f);
    const double n = std::max(nearPlane, 1e-6f), f = std::max(static_cast<double>(farPlane), n);
    std::vector<float> splits(static_cast<size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const double t = static_cast<double>(i) / count;
        const double logarithmic = n * std::pow(f / n, t);
        const double uniform = n + (f - n) * t;
        splits[static_cast<size_t>(i)] = static_cast<float>(lambda * logarithmic + (1.0 - lambda) * uniform);
    }
    splits.front() = static_cast<float>(n);  // exact ends, whatever pow rounds to
    splits.back() = static_cast<float>(f);
    return splits;
}

glm::ivec2 cascadeAtlasGrid(int count) {
    count = std::clamp(count, 1, kMaxCascades);
    const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    return {cols, (count + cols - 1) / cols};
}

glm::ivec4 cascadeViewport(int cascade, int count, int width, int height) {
    const glm::ivec2 grid = cascadeAtlasGrid(count);
    const int w = width / grid.x, h = height / grid.y;
    return {(cascade % grid.x) * w, (cascade / grid.x) * h, w, h};
}

glm::vec4 cascadeAtlasRect(int cascade, int count) {
    const glm::ivec2 grid = cascadeAtlasGrid(count);
    const glm::vec2 size(1.0f / static_cast<float>(grid.x), 1.0f / static_cast<float>(grid.y));
    return {static_cast<float>(cascade % grid.x) * size.x, static_cast<float>(cascade / grid.x) * size.y,
            size.x, size.y};
}

glm::ivec4 atlasViewport(const glm::vec4& rect, int width, int height) {
    const int w = static_cast<int>(std::floor(static_cast<float>(width) * rect.z + 1e-3f));
    const int h = static_cast<int>(std::floor(static_cast<float>(height) * rect.w + 1e-3f));
    return {static_cast<int>(std::lround(rect.x / rect.z)) * w,
            static_cast<int>(std::lround(rect.y / rect.w)) * h, w, h};
}

glm::ivec4 lightViewTile(const LightView& view, int index, int count, int width, int height) {
    if (view.atlasRect.z > 0.0f) return atlasViewport(view.atlasRect, width, height);
    return cascadeViewport(index, count, width, height);
}

LightFit fitCascades(const Scene& scene, const Bounds& sceneBounds, float aspect, const Light& light,
                     const LightTunables& tunables, const VisibleSamples* visible) {
    // View 0: the focused fit of the whole body (or the uniform fit where focusing cannot work).
    LightFit fit =
        fitLight(LightParameterization::Focused, scene, sceneBounds, aspect, light, tunables, visible);
    const Camera& camera = scene.camera;
    const int count = std::clamp(tunables.cascadeCount, 1, kMaxCascades);
    const float blend = std::clamp(tunables.cascadeBlend, 0.0f, 0.5f);
    const auto [rangeStart, rangeEnd] = visible
                                            ? visibleSplitRange(camera, *visible)
                                            : std::pair{camera.nearPlane, splitRangeEnd(camera, sceneBounds)};
    const Bounds receiverBounds = visible ? receiverBoundsOverSamples(sceneBounds, *visible) : sceneBounds;
    const std::vector<float> splits =
        cascadeSplitDepths(rangeStart, rangeEnd, count, tunables.cascadeSplitLambda);
    for (int i = 0; i < count; ++i) {
        LightView cascade{fit.view, fit.projection, splits[static_cast<size_t>(i)],
                          splits[static_cast<size_t>(i) + 1]};
        // The previous cascade blends into this one over the far `blend` share of its range: start there.
        if (i > 0)
            cascade.splitNear -=
                blend * (splits[static_cast<size_t>(i)] - splits[static_cast<size_t>(i) - 1]);
        fit.cascades.push_back(cascade);
    }
    if (light.type != Light::Type::Directional || !(glm::dot(light.direction, light.direction) > 1e-12f))
        return fit;

    const glm::vec3 lightDir = glm::normalize(light.direction);
    const glm::vec3 centre = sceneBounds.center();
    const float sceneRadius = std::max(sceneBounds.radius(), 1e-3f);
    const glm::mat4 lightView =
        glm::lookAtLH(centre - lightDir * (2.0f * sceneRadius), centre, fixedPerpendicular(lightDir));
    const glm::mat4 cameraView = camera.view();
    for (LightView& cascade : fit.cascades) {
        Camera slice = camera;
        slice.nearPlane = cascade.splitNear;
        slice.farPlane = cascade.splitFar;
        const std::vector<glm::vec3> receivers =
            intersectionBodyPoints(slice.projection(aspect) * cameraView, receiverBounds);
        if (receivers.empty()) continue;  // nothing seen in this slice: keep view 0's matrices

        // Across the light (x, y): the receivers' box, or the slice's bounding sphere, whichever is smaller.
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& p : receivers) {
            const glm::vec2 q(lightView * glm::vec4(p, 1.0f));
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        const float snapMargin = kSnapSteps / (kSnapSteps - 1.0f);  // room for the snap's half step
        glm::vec2 middle = 0.5f * (lo + hi);
        float half = roundUpOnLadder(0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * snapMargin, sceneRadius,
                                     kExtentStepsPerOctave);
        const auto [sphereCentre, sphereRadius] =
            sliceSphere(camera, aspect, slice.nearPlane, slice.farPlane);
        if (sphereRadius * snapMargin < half) {
            half = sphereRadius * snapMargin;
            middle = glm::vec2(lightView * glm::vec4(sphereCentre, 1.0f));
        }
        half = std::max(half, 1e-6f * sceneRadius);
        const float step = 2.0f * half / kSnapSteps;
        middle = glm::round(middle / step) * step;

        // Along the light: the receivers and their casters, up to where the bounds end toward the light.
        float zLo = std::numeric_limits<float>::max(), zHi = std::numeric_limits<float>::lowest();
        for (const glm::vec3& p : receivers) {
            const glm::vec3 caster = p - lightDir * exitDistance(p, -lightDir, sceneBounds);
            for (const glm::vec3& q : {p, caster}) {
                const float z = (lightView * glm::vec4(q, 1.0f)).z;
                zLo = std::min(zLo, z);
                zHi = std::max(zHi, z);
            }
        }
        const float zMargin = 1e-3f * (zHi - zLo) + 1e-6f * sceneRadius;
        zLo -= zMargin;
        zHi += zMargin;

        // Orthographic unit-cube fit (D3D: x, y to [-1, 1], depth to [0, 1]).
        glm::mat4 projection(1.0f);  // glm: [column][row]
        projection[0][0] = 1.0f / half;
        projection[1][1] = 1.0f / half;
        projection[2][2] = 1.0f / (zHi - zLo);
        projection[3][0] = -middle.x / half;
        projection[3][1] = -middle.y / half;
        projection[3][2] = -zLo / (zHi - zLo);
        bool finite = true;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(projection[c][r]);
        if (!finite) continue;
        cascade.view = lightView;
        cascade.projection = projection;
    }
    return fit;
}

}  // namespace runtime
