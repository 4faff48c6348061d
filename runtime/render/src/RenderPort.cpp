// RenderPort: see RenderPort.h.
#include "RenderPort.h"

#include <runtime/CascadedShadowMaps.h>

namespace runtime {

// A light port renders with the matrices the effect's parameterization of that light gives (`binder`).
bool portMatrices(const Scene& scene, const SemanticBinder& binder, const FrameOptions& options,
                  const std::string& light, int lightSlot, int cascade, RenderPortView& port,
                  RenderPortError* error) {
    port.lightIndex = port.cascade = -1;
    if (light.empty()) {
        const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
        port.view = scene.camera.view();
        port.projection = scene.camera.projection(aspect);
        return true;
    }
    const Light* found = binder.slotLight(lightSlot);
    if (!found) {
        if (error) *error = {fx::DiagId::RenderPortLightNotInScene, {light, scene.name}};
        return false;
    }
    const LightFit fit = binder.lightFit(*found);
    if (cascade >= static_cast<int>(fit.cascades.size())) {
        if (error)
            *error =
                fit.cascades.empty()
                    ? RenderPortError{fx::DiagId::RenderPortLightWithoutCascades,
                                      {std::to_string(cascade), light}}
                    : RenderPortError{fx::DiagId::RenderPortCascadeOutOfRange,
                                      {std::to_string(cascade), light, std::to_string(fit.cascades.size())}};
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
