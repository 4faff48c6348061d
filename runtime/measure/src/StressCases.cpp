// StressCases: the extreme configurations `shadowfx stress` runs, built from the built-in "boxes" and
// "behind" scenes. Every case changes one thing of an ordinary configuration, so a failure names its cause.
#include <runtime/BuiltinScenes.h>
#include <runtime/StressCases.h>

#include <private/runtime/SceneBuilding.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <utility>

namespace runtime {

namespace {

Scene boxes() {
    return *makeBuiltinScene("boxes");
}

glm::vec3 viewDirection(const Camera& camera) {
    return glm::normalize(camera.target - camera.position);
}

// The boxes scene's sun azimuth at `elevationDegrees` above the horizon.
glm::vec3 sunAt(float elevationDegrees) {
    const glm::vec2 azimuth = glm::normalize(glm::vec2(-0.8f, 0.3f));
    const float e = glm::radians(elevationDegrees);
    return {std::cos(e) * azimuth.x, -std::sin(e), std::cos(e) * azimuth.y};
}

void setSun(Scene& scene, const glm::vec3& direction) {
    const std::string name = scene.lights.at(0).name;
    scene.lights.at(0) = fittedDirectionalLight(direction, scene.bounds());
    scene.lights.at(0).name = name;
}

// `direction` turned by `degrees` about an axis perpendicular to it.
glm::vec3 tilted(const glm::vec3& direction, float degrees) {
    const glm::vec3 axis = glm::normalize(glm::cross(
        direction, std::abs(direction.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f)));
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis) * glm::vec4(direction, 0.0f));
}

// The whole configuration scaled by `factor` about the origin, near and far planes and light sizes too.
Scene scaled(Scene scene, float factor) {
    const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(factor));
    for (SceneObject& object : scene.objects) object.world = scale * object.world;
    scene.camera.position *= factor;
    scene.camera.target *= factor;
    scene.camera.nearPlane *= factor;
    scene.camera.farPlane *= factor;
    for (Light& light : scene.lights) {
        light.position *= factor;
        light.areaRadius *= factor;
    }
    if (scene.explicitBounds) {
        scene.explicitBounds->min *= factor;
        scene.explicitBounds->max *= factor;
    }
    return scene;
}

// A scene of one object whose single triangle has the given corners (collinear or coincident ones).
Scene oneTriangle(std::string name, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    Scene scene = boxes();
    scene.name = std::move(name);
    Mesh mesh;
    mesh.positions = {a, b, c};
    mesh.normals = std::vector<glm::vec3>(3, glm::vec3(0.0f, 1.0f, 0.0f));
    mesh.indices = {0, 1, 2};
    scene.objects = {placeObject("degenerate", share(std::move(mesh)), glm::mat4(1.0f), glm::vec3(0.8f), 1)};
    return scene;
}

StressCase ordinaryCase(std::string name, std::string description, Scene scene, bool reduced) {
    StressCase c;
    c.name = std::move(name);
    c.description = std::move(description);
    c.scene = std::move(scene);
    c.reduced = reduced;
    return c;
}

StressCase variant(std::string name, std::string description, std::string ordinary, Scene scene,
                   bool reduced) {
    StressCase c = ordinaryCase(std::move(name), std::move(description), std::move(scene), reduced);
    c.ordinary = std::move(ordinary);
    return c;
}

using CaseMaker = std::function<StressCase()>;

const std::vector<std::pair<std::string, CaseMaker>>& caseTable() {
    static const std::vector<std::pair<std::string, CaseMaker>> table = {
        {"ordinary",
         [] {
             return ordinaryCase("ordinary", "boxes as built in: sun 38 degrees up, camera 45 down", boxes(),
                                 true);
         }},
        {"low-sun",
         [] {
             Scene scene = boxes();
             setSun(scene, sunAt(15.0f));
             return ordinaryCase("low-sun", "boxes with the sun 15 degrees above the ground", scene, false);
         }},
        {"behind-ordinary",
         [] {
             Scene scene = *makeBuiltinScene("behind");
             setSun(scene, glm::vec3(0.25f, -0.35f, -1.0f));
             return ordinaryCase("behind-ordinary",
                                 "Kozlov 2004's scene with the light in front of the viewer, as low", scene,
                                 false);
         }},
        {"light-along-view",
         [] {
             Scene scene = boxes();
             setSun(scene, viewDirection(scene.camera));
             return variant("light-along-view",
                            "light exactly along the view direction, from behind the viewer", "ordinary",
                            scene, true);
         }},
        {"light-against-view",
         [] {
             Scene scene = boxes();
             setSun(scene, -viewDirection(scene.camera));
             return variant("light-against-view", "light exactly against the view direction (dueling frusta)",
                            "ordinary", scene, false);
         }},
        {"light-near-view",
         [] {
             Scene scene = boxes();
             setSun(scene, tilted(viewDirection(scene.camera), 0.01f));
             return variant("light-near-view", "light 0.01 degrees off the view direction", "ordinary", scene,
                            false);
         }},
        {"zenith-camera-down",
         [] {
             Scene scene = boxes();
             scene.camera.position = glm::vec3(0.0f, 20.0f, 0.0f);
             scene.camera.target = glm::vec3(0.0f);
             setSun(scene, glm::vec3(0.0f, -1.0f, 0.0f));
             return variant(
                 "zenith-camera-down",
                 "light straight down from overhead, camera looking straight down (up-vector degeneracy)",
                 "ordinary", scene, true);
         }},
        {"nadir-camera-down",
         [] {
             Scene scene = boxes();
             scene.camera.position = glm::vec3(0.0f, 20.0f, 0.0f);
             scene.camera.target = glm::vec3(0.0f);
             setSun(scene, glm::vec3(0.0f, 1.0f, 0.0f));
             return variant("nadir-camera-down", "light straight up from below, camera looking straight down",
                            "ordinary", scene, false);
         }},
        {"light-behind-viewer",
         [] {
             return variant(
                 "light-behind-viewer",
                 "Kozlov 2004's case: light and casters behind the viewer, shadows falling into view",
                 "behind-ordinary", *makeBuiltinScene("behind"), false);
         }},
        {"grazing",
         [] {
             Scene scene = boxes();
             setSun(scene, sunAt(0.5f));
             return variant("grazing", "sun 0.5 degrees above the ground plane", "low-sun", scene, true);
         }},
        {"near-far-huge",
         [] {
             Scene scene = boxes();
             scene.camera.nearPlane = 0.001f;
             scene.camera.farPlane = 100000.0f;
             return variant("near-far-huge", "camera near 0.001, far 100000", "ordinary", scene, true);
         }},
        {"near-far-thin",
         [] {
             Scene scene = boxes();
             // The ground 1 unit ahead: the 1e-4 thick slab between near and far cuts a band of it.
             scene.camera.position = glm::vec3(-4.0f, std::sqrt(0.5f), -3.0f - std::sqrt(0.5f));
             scene.camera.target = glm::vec3(-4.0f, 0.0f, -3.0f);
             scene.camera.nearPlane = 1.0f;
             scene.camera.farPlane = 1.0001f;
             return variant("near-far-thin", "camera near 1, far 1.0001", "ordinary", scene, false);
         }},
        {"fov-1",
         [] {
             Scene scene = boxes();
             scene.camera.fovY = glm::radians(1.0f);
             return variant("fov-1", "camera field of view 1 degree", "ordinary", scene, false);
         }},
        {"fov-170",
         [] {
             Scene scene = boxes();
             scene.camera.fovY = glm::radians(170.0f);
             return variant("fov-170", "camera field of view 170 degrees", "ordinary", scene, false);
         }},
        {"far-from-origin",
         [] {
             StressCase c = variant("far-from-origin", "the whole scene translated by (1e6, 1e6, 1e6)",
                                    "ordinary", boxes().translated(glm::vec3(1.0e6f)), true);
             c.truthScene = boxes();
             return c;
         }},
        {"scaled-1e-3",
         [] {
             return variant("scaled-1e-3", "the whole scene scaled by 1e-3", "ordinary",
                            scaled(boxes(), 1.0e-3f), false);
         }},
        {"scaled-1e4",
         [] {
             return variant("scaled-1e4", "the whole scene scaled by 1e4", "ordinary",
                            scaled(boxes(), 1.0e4f), false);
         }},
        {"empty",
         [] {
             Scene scene = boxes();
             scene.name = "empty";
             scene.objects.clear();
             return variant("empty", "no objects at all", "ordinary", scene, true);
         }},
        {"degenerate-triangle",
         [] {
             return variant("degenerate-triangle", "one zero-area triangle (collinear corners)", "ordinary",
                            oneTriangle("degenerate-triangle", glm::vec3(-1.0f, 0.0f, 0.0f),
                                        glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)),
                            false);
         }},
        {"point-bounds",
         [] {
             const glm::vec3 p(0.5f, 0.25f, 0.0f);
             return variant("point-bounds", "a scene whose bounds are a single point", "ordinary",
                            oneTriangle("point-bounds", p, p, p), true);
         }},
        {"camera-inside-occluder",
         [] {
             Scene scene = boxes();
             // Inside the 2-unit box at (-2, 1, 0), looking out over the ground.
             scene.camera.position = glm::vec3(-2.0f, 1.2f, 0.3f);
             scene.camera.target = glm::vec3(3.0f, 0.0f, 3.0f);
             return variant("camera-inside-occluder", "the camera inside the box", "ordinary", scene, false);
         }},
        {"spot-inside-bounds",
         [] {
             Scene scene = boxes();
             Light spot;
             spot.name = scene.lights.at(0).name;
             spot.type = Light::Type::Spot;
             spot.position = glm::vec3(0.5f, 4.0f, -0.5f);
             spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
             spot.spotAngle = glm::radians(100.0f);
             scene.lights.at(0) = spot;
             return variant("spot-inside-bounds", "a spot light inside the scene's bounds", "ordinary", scene,
                            false);
         }},
        {"camera-move",
         [] {
             StressCase c =
                 variant("camera-move", "60 frames of a slow orbit (0.1 degree a frame) around the target",
                         "ordinary", boxes(), false);
             const Camera start = c.scene.camera;
             for (int frame = 0; frame < 60; ++frame) {
                 Camera camera = start;
                 const glm::mat4 orbit = glm::rotate(glm::mat4(1.0f), glm::radians(0.1f * float(frame)),
                                                     glm::vec3(0.0f, 1.0f, 0.0f));
                 camera.position =
                     start.target + glm::vec3(orbit * glm::vec4(start.position - start.target, 0.0f));
                 c.cameraPath.push_back(camera);
             }
             return c;
         }},
    };
    return table;
}

}  // namespace

std::vector<std::string> stressCaseNames() {
    std::vector<std::string> names;
    for (const auto& [name, make] : caseTable()) names.push_back(name);
    return names;
}

std::vector<std::string> reducedStressCaseNames() {
    std::vector<std::string> names;
    for (const auto& [name, make] : caseTable())
        if (make().reduced) names.push_back(name);
    return names;
}

std::optional<StressCase> makeStressCase(std::string_view name) {
    for (const auto& [caseName, make] : caseTable())
        if (caseName == name) return make();
    return std::nullopt;
}

}  // namespace runtime
