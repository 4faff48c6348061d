// NonFiniteScan: see NonFiniteScan.h.
#include <runtime/NonFiniteScan.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace runtime {

std::optional<NonFiniteTexels> findNonFiniteTexels(const EffectRenderer& renderer, TextureScan scan) {
    const fx::CompiledEffect& effect = renderer.effect();
    std::vector<float> texels;  // one buffer for every texture: they are up to tens of MB each
    for (const fx::TextureDesc& texture : effect.textures) {
        if (scan == TextureScan::RenderTargets && texture.kind != fx::TextureDesc::Kind::RenderColorTarget &&
            texture.kind != fx::TextureDesc::Kind::RenderDepthStencilTarget)
            continue;
        const std::string& name = effect.parameters[texture.parameter].name;
        int width = 0, height = 0, channels = 0;
        if (!renderer.readTarget(name, texels, &width, &height, &channels))
            continue;  // not allocated: the technique does not use it
        const auto first =
            std::find_if(texels.begin(), texels.end(), [](float v) { return !std::isfinite(v); });
        if (first == texels.end()) continue;
        NonFiniteTexels found;
        found.texture = name;
        found.count = static_cast<size_t>(
            std::count_if(first, texels.end(), [](float v) { return !std::isfinite(v); }));
        const size_t texel =
            static_cast<size_t>(first - texels.begin()) / static_cast<size_t>(std::max(channels, 1));
        found.x = static_cast<int>(texel % static_cast<size_t>(std::max(width, 1)));
        found.y = static_cast<int>(texel / static_cast<size_t>(std::max(width, 1)));
        return found;
    }
    return std::nullopt;
}

std::optional<std::string> findNonFiniteParameter(const EffectRenderer& renderer) {
    const auto& parameters = renderer.effect().parameters;
    for (size_t i = 0; i < parameters.size(); ++i)
        for (float value : renderer.parameter(i).data)
            if (!std::isfinite(value)) return parameters[i].name;
    return std::nullopt;
}

bool isFinite(const glm::mat4& matrix) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(matrix[c][r])) return false;
    return true;
}

}  // namespace runtime
