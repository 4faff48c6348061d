// BuiltinScenes: the scenes the tools and tests know by name, built in code (BuiltinScenes.cpp,
// PaperScenes.cpp, ForestScene.cpp) or from meshes Debian ships (AssetScenes.cpp, through MeshImporter).
#pragma once

#include <runtime/Scene.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {
class DiagnosticSink;
}

namespace runtime {

// Built-in scenes: "boxes" (a ground plane with a box and a sphere, a directional light from above at an
// angle), "torus" (a torus standing on a plane, spot light), "teapot" (Newell's teapot on a plane), then
// the setups of the papers ("dual-l", "double-torus", "forest", "behind") and scenes of meshes Debian ships
// ("bunny", "horse", "spider", "engine"); docs/scenes.md says which paper each reproduces.
std::vector<std::string> builtinSceneNames();
std::optional<Scene> makeBuiltinScene(std::string_view name);
// The same, reporting why there is no scene: an unknown name, or a mesh file that is missing (naming the
// Debian package that ships it). `diagnostics` may be null.
std::optional<Scene> makeBuiltinScene(std::string_view name, fx::DiagnosticSink* diagnostics);

}  // namespace runtime
