// ViewCommand: `shadowfx view` — the authoring loop. A GLFW window renders the effect continuously with an
// orbit camera and a movable light; saving the effect or one of its includes hot-reloads it
// (runtime/ReloadableEffect.h); a Dear ImGui panel shows the frame time, per-pass GPU times, the
// parameters (from their SAS annotations) and the render targets; a failed reload shows its errors in a
// red overlay while the last good effect keeps rendering.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kViewUsage;
int viewCommand(const Arguments& args);

}  // namespace shadowfx::cli
