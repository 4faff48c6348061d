// NonFiniteScan: where a frame went wrong numerically: the first texture or parameter of an effect that
// holds NaN or Inf after a render (what `shadowfx check` and `shadowfx stress` report).
#pragma once

#include <runtime/EffectRenderer.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace runtime {

struct NonFiniteTexels {
    std::string texture;  // the texture parameter's name
    size_t count = 0;     // non-finite values in it (channels counted one by one)
    int x = 0, y = 0;     // the first texel holding one
};

enum class TextureScan { RenderTargets, AllTextures };

// The first allocated texture (level 0) holding NaN or Inf, in the effect's texture order; nullopt if none.
std::optional<NonFiniteTexels> findNonFiniteTexels(const EffectRenderer& renderer, TextureScan scan);
// The first parameter with a NaN or Inf component, by name; nullopt if none.
std::optional<std::string> findNonFiniteParameter(const EffectRenderer& renderer);
bool isFinite(const glm::mat4& matrix);

}  // namespace runtime
