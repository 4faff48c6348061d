// ParameterPanel: Dear ImGui widgets for an effect's tweakable parameters, generated from their SAS
// annotations as FX Composer's property panel did: `UIWidget` ("slider", "color", "none"), `UIMin`,
// `UIMax`, `UIStep`, `UIName`. Bools are checkboxes; parameters bound to a semantic (matrices, lights,
// render targets) are the runtime's and are not shown. Edits go through EffectRenderer::setParameter, so
// they are pinned and survive hot reloads.
#pragma once

#include <runtime/EffectRenderer.h>

namespace shadowfx::cli {

class ParameterPanel {
public:
    // Draws one widget per tweakable parameter into the current ImGui window. True if a value changed.
    static bool draw(runtime::EffectRenderer& renderer);
};

}  // namespace shadowfx::cli
