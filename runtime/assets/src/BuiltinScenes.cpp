// The built-in scenes: small, fixed, and chosen so that every shadow method has something to show (a
// ground plane that receives, closed casters for back-face methods, curved casters for acne).
#include <runtime/BuiltinScenes.h>
#include <runtime/Scene.h>

#include <private/runtime/SceneBuilding.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <utility>

namespace runtime {

namespace {

// Ground planes are tessellated (not one quad) so vertex-lit and per-vertex-depth effects still work.
SceneObject makeGround(float size, uint32_t id) {
    return placeObject("ground", share(makePlane(size, size, 10)), glm::mat4(1.0f),
                       glm::vec3(0.75f, 0.75f, 0.7f), id);
}

// Translation that rests a mesh's lowest point on y = 0 at (x, z).
glm::mat4 restingOnGround(const Mesh& mesh, float x, float z) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(x, -mesh.boundsMin().y, z));
}

Scene makeBoxes() {
    Scene scene;
    scene.name = "boxes";
    scene.objects.push_back(makeGround(20.0f, 1));
    scene.objects.push_back(placeObject("box", share(makeBox(glm::vec3(2.0f))),
                                        glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f, 1.0f, 0.0f)),
                                        glm::vec3(0.85f, 0.3f, 0.25f), 2));
    scene.objects.push_back(placeObject("sphere", share(makeSphere(1.2f, 32, 16)),
                                        glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, 1.2f, 1.0f)),
                                        glm::vec3(0.25f, 0.45f, 0.85f), 3));
    scene.camera.position = glm::vec3(1.0f, 10.0f, -10.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 1.0f);
    // From above and to the right: the shadows fall to the objects' left (-x), beside them as the camera
    // (high, looking down at 45 degrees) sees them rather than hidden behind them, and the faces the camera
    // sees (-z) turn away from the light instead of catching it at a grazing angle (constant-bias acne).
    // That face stays ambient-only by N.L, so the default image shows shadows, not acne.
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(-0.8f, -1.0f, 0.3f), scene.bounds()));
    return scene;
}

Scene makeTorusScene() {
    Scene scene;
    scene.name = "torus";
    scene.objects.push_back(makeGround(12.0f, 1));
    const float majorRadius = 1.5f, minorRadius = 0.5f;
    // Stood up: rotated about x so the ring faces the camera, its lowest point on the plane.
    glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, majorRadius + minorRadius, 0.0f)) *
                      glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    scene.objects.push_back(placeObject("torus", share(makeTorus(majorRadius, minorRadius, 48, 24)), world,
                                        glm::vec3(0.9f, 0.65f, 0.2f), 2));
    scene.camera.position = glm::vec3(0.0f, 5.0f, -10.0f);
    scene.camera.target = glm::vec3(0.0f, 1.5f, 0.0f);

    const Bounds bounds = scene.bounds();
    Light light;
    light.type = Light::Type::Spot;
    light.position = glm::vec3(6.0f, 14.0f, -7.0f);
    light.direction = glm::normalize(bounds.center() - light.position);
    // The cone is made just wide enough for its shadow map to cover the whole scene: the half-angle of the
    // cone tangent to the bounding sphere, plus a margin.
    light.spotAngle =
        2.0f * std::asin(std::min(bounds.radius() / glm::length(bounds.center() - light.position), 1.0f)) *
        1.05f;
    scene.lights.push_back(light);
    return scene;
}

Scene makeTeapotScene() {
    Scene scene;
    scene.name = "teapot";
    scene.objects.push_back(makeGround(20.0f, 1));
    Mesh teapot = makeTeapot(4.0f, 8);
    const glm::mat4 world = restingOnGround(teapot, 0.0f, 0.0f);
    scene.objects.push_back(
        placeObject("teapot", share(std::move(teapot)), world, glm::vec3(0.8f, 0.8f, 0.85f), 2));
    // Lehőcz 2007's figures: the teapot seen from the front, a little from above and to the spout's side.
    scene.camera.position = glm::vec3(2.5f, 4.0f, -7.0f);
    scene.camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(-0.5f, -1.0f, 0.35f), scene.bounds()));
    return scene;
}

// A maker that cannot fail, as one that can (the asset scenes, whose files may be missing).
template <Scene (*make)()>
std::optional<Scene> always(fx::DiagnosticSink*) {
    return make();
}

// One table: the order here is builtinSceneNames()'s order.
const std::pair<const char*, std::optional<Scene> (*)(fx::DiagnosticSink*)> kScenes[] = {
    {"boxes", always<makeBoxes>},
    {"torus", always<makeTorusScene>},
    {"teapot", always<makeTeapotScene>},
    {"dual-l", always<makeDualLScene>},
    {"double-torus", always<makeDoubleTorusScene>},
    {"forest", always<makeForestScene>},
    {"forest-fifth", always<makeForestFifthScene>},
    {"behind", always<makeBehindScene>},
    {"bunny", makeBunnyScene},
    {"horse", makeHorseScene},
    {"spider", makeSpiderScene},
    {"engine", makeEngineScene},
};

}  // namespace

std::vector<std::string> builtinSceneNames() {
    std::vector<std::string> names;
    for (const auto& [name, make] : kScenes) names.emplace_back(name);
    return names;
}

std::optional<Scene> makeBuiltinScene(std::string_view name) {
    return makeBuiltinScene(name, nullptr);
}

std::optional<Scene> makeBuiltinScene(std::string_view name, fx::DiagnosticSink* diagnostics) {
    for (const auto& [sceneName, make] : kScenes)
        if (name == sceneName) return make(diagnostics);
    if (diagnostics) {
        std::string known;
        for (const auto& [sceneName, make] : kScenes)
            known += (known.empty() ? "" : ", ") + std::string(sceneName);
        diagnostics->report(fx::DiagId::UnknownScene, fx::SourceLoc{}, {std::string(name), known});
    }
    return std::nullopt;
}

}  // namespace runtime
