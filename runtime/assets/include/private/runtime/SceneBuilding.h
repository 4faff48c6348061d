// SceneBuilding: what the built-in scene files (BuiltinScenes.cpp, PaperScenes.cpp, ForestScene.cpp,
// AssetScenes.cpp) share: placing shared meshes, fitting a directional light, the makers' table entries.
#pragma once

#include <runtime/Scene.h>

#include <fx/Diagnostics.h>

#include <memory>
#include <optional>
#include <utility>
#include <string>

namespace runtime {

// A generated mesh as the shared, immutable mesh objects (and their instances) point to.
inline std::shared_ptr<const Mesh> share(Mesh mesh) {
    return std::make_shared<const Mesh>(std::move(mesh));
}

inline SceneObject placeObject(std::string name, std::shared_ptr<const Mesh> mesh, const glm::mat4& world,
                               const glm::vec3& color, uint32_t id) {
    SceneObject object;
    object.name = std::move(name);
    object.mesh = std::move(mesh);
    object.world = world;
    object.color = color;
    object.id = id;
    return object;
}

// A directional light along `direction` whose (informative) position sits two bounding radii back from the
// scene's centre, where Light::view puts its eye.
inline Light fittedDirectionalLight(const glm::vec3& direction, const Bounds& bounds) {
    Light light;
    light.type = Light::Type::Directional;
    light.direction = glm::normalize(direction);
    light.position = bounds.center() - light.direction * (2.0f * bounds.radius());
    return light;
}

// The setups of the papers (PaperScenes.cpp, ForestScene.cpp) and the scenes of Debian-shipped meshes
// (AssetScenes.cpp; nullopt after reporting a missing file into `diagnostics`, which may be null).
Scene makeDualLScene();
Scene makeDoubleTorusScene();
Scene makeBehindScene();
Scene makeForestScene();
Scene makeForestFifthScene();  // the forest seen to 110 m: about a fifth of it in view
std::optional<Scene> makeBunnyScene(fx::DiagnosticSink* diagnostics);
std::optional<Scene> makeHorseScene(fx::DiagnosticSink* diagnostics);
std::optional<Scene> makeSpiderScene(fx::DiagnosticSink* diagnostics);
std::optional<Scene> makeEngineScene(fx::DiagnosticSink* diagnostics);

}  // namespace runtime
