// SceneFile: scenes described in JSON (meshes from files through assimp or built-in primitives, objects
// with transforms and instancing, camera, lights, bounds). docs/scenes.md shows the format;
// scenes/*.json are examples.
#pragma once

#include <runtime/Scene.h>

#include <fx/Diagnostics.h>

#include <optional>
#include <string>

namespace runtime {

// Reads the scene at `path`. Relative mesh paths resolve against the file's folder. Every problem is
// reported into `diagnostics` as "path:line:column: error: ..." (invalid JSON) or "path: error: key: what"
// (a value of the wrong kind, an unknown mesh, a missing mesh file with the Debian package that ships it);
// unknown keys are warnings. nullopt if there was any error; never throws.
std::optional<Scene> loadSceneFile(const std::string& path, fx::DiagnosticSink& diagnostics);

// The same for JSON already in memory; `path` names it in diagnostics and anchors relative mesh paths.
std::optional<Scene> parseSceneJson(const std::string& text, const std::string& path,
                                    fx::DiagnosticSink& diagnostics);

// What the command line's --scene takes: a path ending in ".json" is a scene file, anything else names a
// built-in scene (an unknown name or a missing asset is reported).
std::optional<Scene> loadScene(const std::string& nameOrPath, fx::DiagnosticSink& diagnostics);

}  // namespace runtime
