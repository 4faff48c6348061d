// VisibleSamples: the reduction of the visible samples and the fit inputs made from it (see the header).
#include <runtime/VisibleSamples.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

namespace {

// A relative margin of the range plus an absolute one of the scene's size: float positions read back from a
// render target are the fragments' own, and the fits round their products in float.
constexpr float kRelativeMargin = 1e-3f;

}  // namespace

std::optional<VisibleSamples> reduceVisibleSamples(const std::vector<float>& positions,
                                                   const Camera& camera) {
    const glm::vec3 viewDir = glm::normalize(camera.target - camera.position);
    VisibleSamples samples;
    samples.nearDepth = std::numeric_limits<float>::max();
    samples.farDepth = std::numeric_limits<float>::lowest();
    samples.box = {glm::vec3(std::numeric_limits<float>::max()),
                   glm::vec3(std::numeric_limits<float>::lowest())};
    for (size_t i = 0; i + 3 < positions.size(); i += 4) {
        if (!(positions[i + 3] > 0.0f)) continue;
        const glm::vec3 p(positions[i], positions[i + 1], positions[i + 2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
        const float depth = glm::dot(p - camera.position, viewDir);
        samples.nearDepth = std::min(samples.nearDepth, depth);
        samples.farDepth = std::max(samples.farDepth, depth);
        samples.box.min = glm::min(samples.box.min, p);
        samples.box.max = glm::max(samples.box.max, p);
        ++samples.count;
    }
    if (samples.count == 0) return std::nullopt;
    return samples;
}

Camera cameraOverSamples(const Camera& camera, const VisibleSamples& samples) {
    const float margin = kRelativeMargin * (samples.farDepth - samples.nearDepth) +
                         kRelativeMargin * std::max(samples.farDepth, camera.nearPlane);
    Camera fitted = camera;
    fitted.nearPlane = std::clamp(samples.nearDepth - margin, camera.nearPlane, camera.farPlane);
    // A frustum needs far > near; samples at one depth (a wall seen head-on) still get a thin slab.
    fitted.farPlane = std::clamp(samples.farDepth + margin, fitted.nearPlane * (1.0f + kRelativeMargin),
                                 std::max(camera.farPlane, fitted.nearPlane * (1.0f + kRelativeMargin)));
    return fitted;
}

Bounds receiverBoundsOverSamples(const Bounds& sceneBounds, const VisibleSamples& samples) {
    const glm::vec3 margin = glm::vec3(kRelativeMargin * 2.0f * sceneBounds.radius());
    Bounds receivers{glm::max(sceneBounds.min, samples.box.min - margin),
                     glm::min(sceneBounds.max, samples.box.max + margin)};
    // Samples outside the scene bounds (they are the bounds' own surfaces, up to rounding) keep the bounds.
    receivers.max = glm::max(receivers.max, receivers.min);
    return receivers;
}

}  // namespace runtime
