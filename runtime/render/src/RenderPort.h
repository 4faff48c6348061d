// RenderPort: the view, projection and atlas tile a SAS RenderPort gives a pass: the camera (""), a light
// as the effect parameterizes it (RenderPort=lightN), or one cascade or cube face of it
// (RenderPort=lightN.cascadeK). What the frame plan's dry run and the frame executor both follow.
#pragma once

#include "SemanticBinder.h"

#include <fx/Diagnostics.h>
#include <runtime/EffectRenderer.h>
#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace runtime {

// Why a port cannot be rendered: a diagnostic of the RenderPort* ids and its arguments.
struct RenderPortError {
    fx::DiagId id;
    std::vector<std::string> args;
};

// The view and projection of the port ("" = the camera, else the light in `lightSlot`, the binder's slot of
// that name; `cascade` >= 0: that sub-view of the light) for a frame of `options`' size. False, with why in
// `error`, if the scene has no such light or the light no such cascade.
bool portMatrices(const Scene& scene, const SemanticBinder& binder, const FrameOptions& options,
                  const std::string& light, int lightSlot, int cascade, RenderPortView& port,
                  RenderPortError* error = nullptr);

// The tile of a `width` x `height` target that a cascade port (port.cascade >= 0) renders into: x, y, w, h
// in texels (lightViewTile).
glm::ivec4 portTile(const SemanticBinder& binder, const Scene& scene, const RenderPortView& port, int width,
                    int height);

}  // namespace runtime
