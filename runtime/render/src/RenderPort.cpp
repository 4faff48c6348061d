// RenderPort: see RenderPort.h.
#include "RenderPort.h"

#include <runtime/CascadedShadowMaps.h>

namespace runtime {

// A light port renders with the matrices the effect's parameterization of that light gives (`binder`).
bool portMatrices(const Scene& scene, const SemanticBinder& binder, const FrameOptions& options,
                  const std::string& light, int lightSlot, int cascade, RenderPortView& port,
                  std::string* error) {
    port.lightIndex = port.cascade = -1;
    if (light.empty()) {
        const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
        port.view = scene.camera.view();
        port.projection = scene.camera.projection(aspect);
        return true;
    }
    const Light* found = binder.slotLight(lightSlot);
    if (!found) {
        if (error) *error = "light '" + light + "', which scene '" + scene.name + "' does not have";
        return false;
    }
    const LightFit fit = binder.lightFit(*found);
    if (cascade >= static_cast<int>(fit.cascades.size())) {
        if (error)
            *error = "cascade " + std::to_string(cascade) + " of light '" + light + "', which has " +
                     (fit.cascades.empty()
                          ? std::string("no cascades (its Parameterization is not \"Cascaded\" or "
                                        "\"PSMCube\")")
                          : std::to_string(fit.cascades.size()) + " (CascadeCount)");
        return false;
    }
    port.view = cascade >= 0 ? fit.cascades[static_cast<size_t>(cascade)].view : fit.view;
    port.projection = cascade >= 0 ? fit.cascades[static_cast<size_t>(cascade)].projection : fit.projection;
    port.shinesIntoPositiveW = fit.shinesIntoPositiveW;
    if (cascade >= 0) {
        port.lightIndex = static_cast<int>(found - scene.lights.data());
        port.cascade = cascade;
    }
    return true;
}

glm::ivec4 portTile(const SemanticBinder& binder, const Scene& scene, const RenderPortView& port, int width,
                    int height) {
    const LightFit fit = binder.lightFit(scene.lights[static_cast<size_t>(port.lightIndex)]);
    return lightViewTile(fit.cascades[static_cast<size_t>(port.cascade)], port.cascade,
                         static_cast<int>(fit.cascades.size()), width, height);
}

}  // namespace runtime
