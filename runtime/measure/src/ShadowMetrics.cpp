// ShadowMetrics: classification errors, error images and the texel-footprint aliasing measure.
#include <runtime/ShadowMetrics.h>

#include <runtime/CascadedShadowMaps.h>
#include <runtime/PerspectiveShadowCubeMap.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

namespace runtime {

std::vector<uint8_t> receiverMask(const GBuffer& gbuffer, const Light& light) {
    std::vector<uint8_t> mask(gbuffer.pixelCount(), 0);
    const glm::vec3 lightDir = glm::normalize(light.direction);
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!gbuffer.covered(i)) continue;
        const glm::vec3 toLight =
            light.type == Light::Type::Directional ? -lightDir : light.position - gbuffer.position[i];
        // Outside a spot light's cone nothing is lit, so nothing there can be scored.
        const bool inCone = light.type != Light::Type::Spot ||
                            glm::dot(glm::normalize(-toLight), lightDir) >= std::cos(0.5f * light.spotAngle);
        mask[i] = glm::dot(gbuffer.normal[i], toLight) > 0.0f && inCone ? 1 : 0;
    }
    return mask;
}

ShadowErrors compareVisibility(const std::vector<float>& truth, const std::vector<float>& effect,
                               const std::vector<uint8_t>& receivers) {
    ShadowErrors errors;
    std::vector<float> absolute;
    const size_t n = std::min({truth.size(), effect.size(), receivers.size()});
    double sum = 0.0, penumbraSum = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (!receivers[i] || truth[i] < 0.0f) continue;
        ++errors.receiverPixels;
        const bool litInTruth = truth[i] >= kShadowedBelow;
        const bool litByEffect = effect[i] >= kShadowedBelow;
        errors.falseShadowPixels += litInTruth && !litByEffect;
        errors.falseLightPixels += !litInTruth && litByEffect;
        const float e = std::abs(std::clamp(effect[i], 0.0f, 1.0f) - truth[i]);
        sum += e;
        absolute.push_back(e);
        if (truth[i] > kPenumbra && truth[i] < 1.0f - kPenumbra) {
            ++errors.penumbraPixels;
            penumbraSum += e;
        }
    }
    if (errors.penumbraPixels > 0)
        errors.penumbraMeanAbsoluteError = penumbraSum / static_cast<double>(errors.penumbraPixels);
    if (errors.receiverPixels == 0) return errors;
    const double total = static_cast<double>(errors.receiverPixels);
    errors.falseShadowPercent = 100.0 * static_cast<double>(errors.falseShadowPixels) / total;
    errors.falseLightPercent = 100.0 * static_cast<double>(errors.falseLightPixels) / total;
    errors.misclassifiedPercent = errors.falseShadowPercent + errors.falseLightPercent;
    errors.meanAbsoluteError = sum / total;
    // Nearest-rank percentile: the smallest error that at least 95% of the pixels do not exceed.
    const size_t rank = static_cast<size_t>(std::ceil(0.95 * total)) - 1;
    std::nth_element(absolute.begin(), absolute.begin() + static_cast<std::ptrdiff_t>(rank), absolute.end());
    errors.p95AbsoluteError = absolute[rank];
    return errors;
}

std::vector<float> visibilityFromFrame(const FrameImage& frame) {
    std::vector<float> visibility(static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height));
    for (size_t i = 0; i < visibility.size(); ++i) visibility[i] = frame.rgba[i * 4] / 255.0f;
    return visibility;
}

FrameImage errorImage(const FrameImage& frame, const std::vector<float>& truth,
                      const std::vector<float>& effect, const std::vector<uint8_t>& receivers) {
    FrameImage out = frame;
    const size_t n = std::min({truth.size(), effect.size(), receivers.size(), out.rgba.size() / 4});
    for (size_t i = 0; i < out.rgba.size() / 4; ++i) {
        uint8_t* p = &out.rgba[i * 4];
        // A dimmed grey keeps the scene readable under the saturated error colours.
        const auto grey = static_cast<uint8_t>(0.6f * (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]));
        p[0] = p[1] = p[2] = grey;
        p[3] = 255;
        if (i >= n || !receivers[i] || truth[i] < 0.0f) continue;
        const bool litInTruth = truth[i] >= kShadowedBelow;
        const bool litByEffect = effect[i] >= kShadowedBelow;
        if (litInTruth && !litByEffect) p[0] = 255, p[1] = 0, p[2] = 0;
        if (!litInTruth && litByEffect) p[0] = 0, p[1] = 64, p[2] = 255;
    }
    return out;
}

namespace {

// Texel coordinates of `position` in a map of `mapSize` texels (x right, v down as in shadowmap.fxh; the sign
// of v does not change the singular values); false behind a perspective light.
bool texelOf(const glm::mat4& lightViewProjection, const glm::vec3& position, float mapSize,
             glm::vec2& texel) {
    const glm::vec4 clip = lightViewProjection * glm::vec4(position, 1.0f);
    if (clip.w <= 0.0f) return false;
    texel = glm::vec2(0.5f * clip.x / clip.w + 0.5f, -0.5f * clip.y / clip.w + 0.5f) * mapSize;
    return true;
}

// Each pixel's texel coordinates in the map of its own (`map`: a cascade, a cube face; 0 for a single map).
struct TexelField {
    std::vector<glm::vec2> texel;
    std::vector<int> map;
};

TexelField perspectiveTexels(const GBuffer& gbuffer, const glm::mat4& lightViewProjection, int mapSize) {
    TexelField field{std::vector<glm::vec2>(gbuffer.pixelCount(), glm::vec2(0.0f)),
                     std::vector<int>(gbuffer.pixelCount(), 0)};
    for (size_t i = 0; i < field.texel.size(); ++i)
        if (gbuffer.covered(i))
            texelOf(lightViewProjection, gbuffer.position[i], float(mapSize), field.texel[i]);
    return field;
}

TexelField cascadedTexels(const GBuffer& gbuffer, const glm::mat4& cameraView,
                          const std::vector<LightView>& cascades, int atlasSize) {
    TexelField field{std::vector<glm::vec2>(gbuffer.pixelCount(), glm::vec2(0.0f)),
                     std::vector<int>(gbuffer.pixelCount(), 0)};
    const int count = static_cast<int>(cascades.size());
    for (size_t i = 0; i < field.texel.size(); ++i) {
        if (!gbuffer.covered(i)) continue;
        // The receiver's cascade, as cascades.fx picks it: the first whose split lies beyond its view depth.
        const float depth = (cameraView * glm::vec4(gbuffer.position[i], 1.0f)).z;
        int k = 0;
        while (k + 1 < count && depth > cascades[static_cast<size_t>(k)].splitFar) ++k;
        const LightView& cascade = cascades[static_cast<size_t>(k)];
        const float tile = static_cast<float>(cascadeViewport(k, count, atlasSize, atlasSize).z);
        texelOf(cascade.projection * cascade.view, gbuffer.position[i], tile, field.texel[i]);
        field.map[i] = k;
    }
    return field;
}

TexelField cubeFaceTexels(const GBuffer& gbuffer, const LightFit& fit, int atlasSize) {
    TexelField field{std::vector<glm::vec2>(gbuffer.pixelCount(), glm::vec2(0.0f)),
                     std::vector<int>(gbuffer.pixelCount(), 0)};
    const int count = static_cast<int>(fit.cascades.size());
    for (size_t i = 0; i < field.texel.size(); ++i) {
        if (!gbuffer.covered(i)) continue;
        const int face = std::min(cubeFaceOf(fit, gbuffer.position[i]), count - 1);
        const LightView& view = fit.cascades[static_cast<size_t>(face)];
        const glm::ivec4 tile = lightViewTile(view, face, count, atlasSize, atlasSize);
        const glm::vec4 clip = view.projection * view.view * glm::vec4(gbuffer.position[i], 1.0f);
        if (clip.w > 0.0f)
            field.texel[i] = glm::vec2(0.5f * clip.x / clip.w + 0.5f, -0.5f * clip.y / clip.w + 0.5f) *
                             glm::vec2(tile.z, tile.w);
        field.map[i] = face;
    }
    return field;
}

TexelField fitTexels(const GBuffer& gbuffer, const glm::mat4& cameraView, const LightFit& fit, int mapSize) {
    if (fit.cubeFaces) return cubeFaceTexels(gbuffer, fit, mapSize);
    if (!fit.cascades.empty()) return cascadedTexels(gbuffer, cameraView, fit.cascades, mapSize);
    return perspectiveTexels(gbuffer, fit.projection * fit.view, mapSize);
}

// The footprint measure over given texel coordinates per pixel; neighbours of another object or another
// map (a cascade, a face) give no derivative.
AliasingMeasure footprints(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                           const TexelField& field);

}  // namespace

AliasingMeasure perspectiveAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                    const glm::mat4& lightView, const glm::mat4& lightProjection,
                                    int mapSize) {
    return footprints(gbuffer, receivers, perspectiveTexels(gbuffer, lightProjection * lightView, mapSize));
}

AliasingMeasure cascadedAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                 const glm::mat4& cameraView, const std::vector<LightView>& cascades,
                                 int atlasSize) {
    if (cascades.empty()) return {};
    return footprints(gbuffer, receivers, cascadedTexels(gbuffer, cameraView, cascades, atlasSize));
}

AliasingMeasure cubeFaceAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                 const LightFit& fit, int atlasSize) {
    if (fit.cascades.empty()) return {};
    return footprints(gbuffer, receivers, cubeFaceTexels(gbuffer, fit, atlasSize));
}

namespace {

AliasingMeasure footprints(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                           const TexelField& field) {
    const std::vector<glm::vec2>& texel = field.texel;
    const std::vector<int>& map = field.map;
    AliasingMeasure measure;
    // Derivative along one screen axis: central difference where both neighbours lie on the same object,
    // else one-sided; none at an object's silhouette on both sides.
    auto derivative = [&](int x, int y, int dx, int dy, glm::vec2& d) {
        const size_t i = gbuffer.index(x, y);
        const uint32_t id = gbuffer.objectId[i];
        const auto same = [&](size_t j) { return gbuffer.objectId[j] == id && map[j] == map[i]; };
        const bool hasNext =
            x + dx < gbuffer.width && y + dy < gbuffer.height && same(gbuffer.index(x + dx, y + dy));
        const bool hasPrev = x - dx >= 0 && y - dy >= 0 && same(gbuffer.index(x - dx, y - dy));
        if (hasNext && hasPrev) {
            d = 0.5f * (texel[gbuffer.index(x + dx, y + dy)] - texel[gbuffer.index(x - dx, y - dy)]);
        } else if (hasNext) {
            d = texel[gbuffer.index(x + dx, y + dy)] - texel[i];
        } else if (hasPrev) {
            d = texel[i] - texel[gbuffer.index(x - dx, y - dy)];
        } else {
            return false;
        }
        return true;
    };
    double sum = 0.0;
    std::vector<double> footprints;
    for (int y = 0; y < gbuffer.height; ++y) {
        for (int x = 0; x < gbuffer.width; ++x) {
            const size_t i = gbuffer.index(x, y);
            if (i >= receivers.size() || !receivers[i]) continue;
            glm::vec2 ddx, ddy;
            if (!derivative(x, y, 1, 0, ddx) || !derivative(x, y, 0, 1, ddy)) continue;
            // Singular values of J = [ddx ddy] (2x2) from its Gram matrix's eigenvalues.
            const double a = glm::dot(ddx, ddx), b = glm::dot(ddx, ddy), c = glm::dot(ddy, ddy);
            const double mean = 0.5 * (a + c);
            const double root = std::sqrt(std::max(0.0, 0.25 * (a - c) * (a - c) + b * b));
            const double sigmaMin = std::sqrt(std::max(0.0, mean - root));
            if (sigmaMin <= 1e-9) continue;  // degenerate (a surface seen edge-on from the light)
            const double footprint = 1.0 / sigmaMin;
            measure.maxFootprint = std::max(measure.maxFootprint, footprint);
            sum += footprint;
            footprints.push_back(footprint);
            ++measure.pixels;
        }
    }
    if (measure.pixels > 0) {
        measure.meanFootprint = sum / static_cast<double>(measure.pixels);
        const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(footprints.size()))) - 1;
        std::nth_element(footprints.begin(), footprints.begin() + static_cast<std::ptrdiff_t>(rank),
                         footprints.end());
        measure.p95Footprint = footprints[rank];
    }
    return measure;
}

}  // namespace

AliasingMeasure fitAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                            const glm::mat4& cameraView, const LightFit& fit, int mapSize) {
    if (fit.cubeFaces) return cubeFaceAliasing(gbuffer, receivers, fit, mapSize);
    if (!fit.cascades.empty()) return cascadedAliasing(gbuffer, receivers, cameraView, fit.cascades, mapSize);
    return perspectiveAliasing(gbuffer, receivers, fit.view, fit.projection, mapSize);
}

double samplingLimitedError(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                            const std::vector<float>& truth, const glm::mat4& cameraView, const LightFit& fit,
                            int mapSize) {
    if (fit.cubeFaces && fit.cascades.empty()) return 0.0;
    const TexelField field = fitTexels(gbuffer, cameraView, fit, mapSize);
    struct Counts {
        size_t pixels = 0, shadowed = 0;
    };
    std::map<std::tuple<int, int64_t, int64_t>, Counts> texels;
    size_t receiverCount = 0;
    for (size_t i = 0; i < receivers.size() && i < truth.size(); ++i) {
        if (!receivers[i]) continue;
        ++receiverCount;
        const glm::vec2 t = glm::floor(field.texel[i]);
        Counts& counts = texels[{field.map[i], static_cast<int64_t>(t.x), static_cast<int64_t>(t.y)}];
        ++counts.pixels;
        counts.shadowed += truth[i] < kShadowedBelow ? 1 : 0;
    }
    if (receiverCount == 0) return 0.0;
    // A texel holds one occluder depth, taken at a point of it: where that point is uniformly placed, the
    // texel's pixels on the other side of the truth's shadow boundary, 2 s (n - s) / n of its n pixels in
    // expectation (s of them shadowed), are wrong.
    double expected = 0.0;
    for (const auto& [key, counts] : texels) {
        const double n = static_cast<double>(counts.pixels), s = static_cast<double>(counts.shadowed);
        expected += 2.0 * s * (n - s) / n;
    }
    return 100.0 * expected / static_cast<double>(receiverCount);
}

}  // namespace runtime
