// SceneFile: JSON → Scene. Feature list:
//   [SECTION] JSON values   — typed reads that report "key: what" instead of throwing
//   [SECTION] Meshes        — "meshes": file (assimp) or primitive; shared by name, imported once per file
//   [SECTION] Objects       — transforms, colour, flags, "instances" (one mesh, many transforms)
//   [SECTION] Camera, lights, bounds, hints
//   [SECTION] Entry points  — parse errors with line:column from nlohmann's byte offset
#include <runtime/BuiltinScenes.h>
#include <runtime/SceneFile.h>

#include "JsonLocations.h"

#include <runtime/MeshImporter.h>

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>

namespace runtime {

namespace {

using nlohmann::json;

class SceneFileReader {
public:
    SceneFileReader(std::string path, fx::DiagnosticSink& diagnostics)
        : mPath(std::move(path)), mDiagnostics(diagnostics) {
        mBaseDir = std::filesystem::path(mPath).parent_path();
    }

    std::optional<Scene> read(const json& root);

private:
    // [SECTION] JSON values
    void error(fx::DiagId id, const std::vector<std::string>& args) {
        mDiagnostics.report(id, fx::SourceLoc{mPath, 0, 0}, args);
        mFailed = true;
    }

    // Warns about keys outside `known`: a typo ("postion") would otherwise silently give a default.
    void checkKeys(const json& object, const std::string& key,
                   std::initializer_list<std::string_view> known) {
        for (const auto& [name, value] : object.items()) {
            bool found = false;
            for (auto k : known) found = found || name == k;
            if (!found)
                mDiagnostics.report(fx::DiagId::SceneUnknownKey, fx::SourceLoc{mPath, 0, 0}, {key, name});
        }
    }

    bool isObject(const json& value, const std::string& key) {
        if (value.is_object()) return true;
        error(fx::DiagId::SceneObjectExpected, {key, value.type_name()});
        return false;
    }

    std::optional<float> number(const json& value, const std::string& key) {
        if (value.is_number()) return value.get<float>();
        error(fx::DiagId::SceneNumberExpected, {key, value.type_name()});
        return std::nullopt;
    }

    // A number in [minimum, maximum], read into `out` if present.
    void readNumber(const json& parent, const char* name, const std::string& key, float& out,
                    float minimum = std::numeric_limits<float>::lowest(),
                    float maximum = std::numeric_limits<float>::max()) {
        auto it = parent.find(name);
        if (it == parent.end()) return;
        const std::string path = key + "." + name;
        if (auto v = number(*it, path)) {
            if (*v < minimum || *v > maximum) {
                error(fx::DiagId::SceneNumberOutOfRange,
                      {path, std::to_string(*v), std::to_string(minimum), std::to_string(maximum)});
            } else {
                out = *v;
            }
        }
    }

    void readInt(const json& parent, const char* name, const std::string& key, int& out, int minimum,
                 int maximum) {
        auto it = parent.find(name);
        if (it == parent.end()) return;
        const std::string path = key + "." + name;
        if (!it->is_number_integer() || it->get<long long>() < minimum || it->get<long long>() > maximum) {
            error(fx::DiagId::SceneIntegerExpected, {path, std::to_string(minimum), std::to_string(maximum)});
            return;
        }
        out = it->get<int>();
    }

    void readBool(const json& parent, const char* name, const std::string& key, bool& out) {
        auto it = parent.find(name);
        if (it == parent.end()) return;
        if (!it->is_boolean()) {
            error(fx::DiagId::SceneBoolExpected, {key + "." + name, it->type_name()});
            return;
        }
        out = it->get<bool>();
    }

    void readString(const json& parent, const char* name, const std::string& key, std::string& out) {
        auto it = parent.find(name);
        if (it == parent.end()) return;
        if (!it->is_string()) {
            error(fx::DiagId::SceneStringExpected, {key + "." + name, it->type_name()});
            return;
        }
        out = it->get<std::string>();
    }

    // [x, y, z]; with `allowScalar`, a single number s means [s, s, s] (uniform scale, grey colour).
    void readVec3(const json& parent, const char* name, const std::string& key, glm::vec3& out,
                  bool allowScalar = false) {
        auto it = parent.find(name);
        if (it == parent.end()) return;
        const std::string path = key + "." + name;
        if (allowScalar && it->is_number()) {
            out = glm::vec3(it->get<float>());
            return;
        }
        if (!it->is_array() || it->size() != 3 || !(*it)[0].is_number() || !(*it)[1].is_number() ||
            !(*it)[2].is_number()) {
            error(allowScalar ? fx::DiagId::SceneVectorOrNumberExpected : fx::DiagId::SceneVectorExpected,
                  {path, it->is_array() ? "an array of " + std::to_string(it->size()) + " values"
                                        : std::string(it->type_name())});
            return;
        }
        out = glm::vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
    }

    // [SECTION] Meshes
    std::shared_ptr<const Mesh> readMesh(const json& def, const std::string& key, const std::string& name);
    std::shared_ptr<const Mesh> meshFor(const json& ref, const std::string& key, std::optional<bool> closed);

    // [SECTION] Objects
    void readObject(const json& def, const std::string& key, Scene& scene);
    glm::mat4 readTransform(const json& def, const std::string& key) {
        glm::vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
        readVec3(def, "translate", key, translate);
        readVec3(def, "rotate", key, rotate);
        readVec3(def, "scale", key, scale, true);
        return composeTransform(translate, rotate, scale);
    }

    // [SECTION] Camera, lights, bounds, hints
    void readCamera(const json& def, Camera& camera);
    void readLight(const json& def, const std::string& key, Scene& scene);

    std::string mPath;
    std::filesystem::path mBaseDir;
    fx::DiagnosticSink& mDiagnostics;
    bool mFailed = false;
    std::map<std::string, std::shared_ptr<const Mesh>> mNamedMeshes;  // "meshes" by name
    std::map<std::string, std::shared_ptr<const Mesh>> mFileMeshes;   // imported once per file + options
    std::map<std::pair<const Mesh*, bool>, std::shared_ptr<const Mesh>> mClosedVariants;
};

std::shared_ptr<const Mesh> SceneFileReader::readMesh(const json& def, const std::string& key,
                                                      const std::string& name) {
    if (!isObject(def, key)) return nullptr;
    std::optional<bool> closed;
    if (auto it = def.find("closed"); it != def.end()) {
        bool value = false;
        readBool(def, "closed", key, value);
        closed = value;
    }
    if (def.contains("file")) {
        checkKeys(def, key, {"file", "normalize", "rotate", "closed", "generateNormals"});
        std::string file;
        readString(def, "file", key, file);
        if (file.empty()) {
            error(fx::DiagId::SceneMeshFileExpected, {key + ".file"});
            return nullptr;
        }
        MeshImportOptions options;
        options.closed = closed;
        readNumber(def, "normalize", key, options.normalizeSize, 0.0f);
        readVec3(def, "rotate", key, options.rotateDegrees);
        readBool(def, "generateNormals", key, options.generateNormals);
        const std::filesystem::path resolved =
            std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : mBaseDir / file;
        const std::string cacheKey = resolved.lexically_normal().string() + "|" + def.dump();
        if (auto it = mFileMeshes.find(cacheKey); it != mFileMeshes.end()) return it->second;
        auto mesh = importMesh(resolved.lexically_normal().string(), options, mDiagnostics,
                               fx::SourceLoc{mPath, 0, 0});
        if (!mesh) {
            mFailed = true;
            return nullptr;
        }
        if (!name.empty()) mesh->name = name;
        auto shared = std::make_shared<const Mesh>(std::move(*mesh));
        mFileMeshes[cacheKey] = shared;
        return shared;
    }
    auto primitiveIt = def.find("primitive");
    if (primitiveIt == def.end() || !primitiveIt->is_string()) {
        error(fx::DiagId::SceneMeshSourceMissing, {key});
        return nullptr;
    }
    const std::string primitive = primitiveIt->get<std::string>();
    Mesh mesh;
    if (primitive == "plane") {
        checkKeys(def, key, {"primitive", "size", "divisions", "closed"});
        glm::vec3 size(10.0f);  // x, unused, z
        if (auto it = def.find("size"); it != def.end() && it->is_array() && it->size() == 2 &&
                                        (*it)[0].is_number() && (*it)[1].is_number()) {
            size = glm::vec3((*it)[0].get<float>(), 0.0f, (*it)[1].get<float>());
        } else if (it != def.end() && it->is_number()) {
            size = glm::vec3(it->get<float>());
        } else if (it != def.end()) {
            error(fx::DiagId::ScenePlaneSizeInvalid, {key + ".size"});
        }
        int divisions = 10;
        readInt(def, "divisions", key, divisions, 1, 1024);
        mesh = makePlane(size.x, size.z, divisions);
    } else if (primitive == "box") {
        checkKeys(def, key, {"primitive", "size", "closed"});
        glm::vec3 size(1.0f);
        readVec3(def, "size", key, size, true);
        mesh = makeBox(size);
    } else if (primitive == "sphere") {
        checkKeys(def, key, {"primitive", "radius", "slices", "stacks", "closed"});
        float radius = 1.0f;
        int slices = 32, stacks = 16;
        readNumber(def, "radius", key, radius, 0.0f);
        readInt(def, "slices", key, slices, 3, 1024);
        readInt(def, "stacks", key, stacks, 2, 1024);
        mesh = makeSphere(radius, slices, stacks);
    } else if (primitive == "torus") {
        checkKeys(def, key,
                  {"primitive", "majorRadius", "minorRadius", "majorSegments", "minorSegments", "closed"});
        float major = 1.5f, minor = 0.5f;
        int majorSegments = 48, minorSegments = 24;
        readNumber(def, "majorRadius", key, major, 0.0f);
        readNumber(def, "minorRadius", key, minor, 0.0f);
        readInt(def, "majorSegments", key, majorSegments, 3, 1024);
        readInt(def, "minorSegments", key, minorSegments, 3, 1024);
        mesh = makeTorus(major, minor, majorSegments, minorSegments);
    } else if (primitive == "teapot") {
        checkKeys(def, key, {"primitive", "size", "tessellation", "closed"});
        float size = 4.0f;
        int tessellation = 8;
        readNumber(def, "size", key, size, 0.0f);
        readInt(def, "tessellation", key, tessellation, 1, 64);
        mesh = makeTeapot(size, tessellation);
    } else if (primitive == "cylinder" || primitive == "cone") {
        checkKeys(def, key, {"primitive", "radius", "height", "slices", "closed"});
        float radius = 0.5f, height = 1.0f;
        int slices = 16;
        readNumber(def, "radius", key, radius, 0.0f);
        readNumber(def, "height", key, height, 0.0f);
        readInt(def, "slices", key, slices, 3, 1024);
        mesh = primitive == "cone" ? makeCone(radius, height, slices) : makeCylinder(radius, height, slices);
    } else {
        error(fx::DiagId::SceneUnknownPrimitive, {key + ".primitive", primitive});
        return nullptr;
    }
    if (closed) mesh.closed = *closed;
    if (!name.empty()) mesh.name = name;
    return std::make_shared<const Mesh>(std::move(mesh));
}

// An object's "mesh": a name from "meshes" or an inline definition. An object's "closed" that differs from
// the mesh's gets one shared copy per (mesh, flag), so instancing still shares.
std::shared_ptr<const Mesh> SceneFileReader::meshFor(const json& ref, const std::string& key,
                                                     std::optional<bool> closed) {
    std::shared_ptr<const Mesh> mesh;
    if (ref.is_string()) {
        auto it = mNamedMeshes.find(ref.get<std::string>());
        if (it == mNamedMeshes.end()) {
            error(fx::DiagId::SceneUnknownMesh, {key, ref.get<std::string>()});
            return nullptr;
        }
        mesh = it->second;
    } else if (ref.is_object()) {
        mesh = readMesh(ref, key, "");
    } else {
        error(fx::DiagId::SceneMeshExpected, {key, ref.type_name()});
    }
    if (!mesh || !closed || mesh->closed == *closed) return mesh;
    auto& variant = mClosedVariants[{mesh.get(), *closed}];
    if (!variant) {
        Mesh copy = *mesh;
        copy.closed = *closed;
        variant = std::make_shared<const Mesh>(std::move(copy));
    }
    return variant;
}

void SceneFileReader::readObject(const json& def, const std::string& key, Scene& scene) {
    if (!isObject(def, key)) return;
    checkKeys(def, key,
              {"name", "mesh", "translate", "rotate", "scale", "color", "castsShadow", "receivesShadow",
               "closed", "instances"});
    SceneObject object;
    object.name = "object" + std::to_string(scene.objects.size() + 1);
    readString(def, "name", key, object.name);
    readVec3(def, "color", key, object.color, true);
    readBool(def, "castsShadow", key, object.castsShadow);
    readBool(def, "receivesShadow", key, object.receivesShadow);
    std::optional<bool> closed;
    if (def.contains("closed")) {
        bool value = false;
        readBool(def, "closed", key, value);
        closed = value;
    }
    auto meshIt = def.find("mesh");
    if (meshIt == def.end()) {
        error(fx::DiagId::SceneObjectWithoutMesh, {key});
        return;
    }
    object.mesh = meshFor(*meshIt, key + ".mesh", closed);
    const glm::mat4 world = readTransform(def, key);
    if (!object.mesh) return;

    auto instancesIt = def.find("instances");
    if (instancesIt == def.end()) {
        object.world = world;
        object.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(std::move(object));
        return;
    }
    // Instances: each its own SceneObject (own id, for ID-buffer methods) sharing the one Mesh; an
    // instance's transform is applied first, then the object's, which places the whole group.
    if (!instancesIt->is_array()) {
        error(fx::DiagId::SceneInstancesExpected, {key + ".instances", instancesIt->type_name()});
        return;
    }
    scene.objects.reserve(scene.objects.size() + instancesIt->size());
    for (size_t i = 0; i < instancesIt->size(); ++i) {
        const json& instance = (*instancesIt)[i];
        const std::string instanceKey = key + ".instances[" + std::to_string(i) + "]";
        if (!isObject(instance, instanceKey)) continue;
        checkKeys(instance, instanceKey, {"name", "translate", "rotate", "scale", "color"});
        SceneObject copy = object;
        copy.name = object.name + "[" + std::to_string(i) + "]";
        readString(instance, "name", instanceKey, copy.name);
        readVec3(instance, "color", instanceKey, copy.color, true);
        copy.world = world * readTransform(instance, instanceKey);
        copy.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(std::move(copy));
    }
}

void SceneFileReader::readCamera(const json& def, Camera& camera) {
    if (!isObject(def, "camera")) return;
    checkKeys(def, "camera", {"position", "target", "up", "fov", "near", "far"});
    readVec3(def, "position", "camera", camera.position);
    readVec3(def, "target", "camera", camera.target);
    readVec3(def, "up", "camera", camera.up);
    float fov = glm::degrees(camera.fovY);
    readNumber(def, "fov", "camera", fov, 1.0f, 179.0f);
    camera.fovY = glm::radians(fov);
    readNumber(def, "near", "camera", camera.nearPlane, 1e-6f);
    readNumber(def, "far", "camera", camera.farPlane, 1e-6f);
    if (camera.farPlane <= camera.nearPlane) error(fx::DiagId::SceneCameraFarNotBeyondNear, {});
    if (glm::length(camera.target - camera.position) <= 0.0f)
        error(fx::DiagId::SceneCameraTargetAtPosition, {});
}

void SceneFileReader::readLight(const json& def, const std::string& key, Scene& scene) {
    if (!isObject(def, key)) return;
    checkKeys(def, key, {"name", "type", "position", "direction", "target", "color", "angle", "areaRadius"});
    Light light;
    light.name = "light" + std::to_string(scene.lights.size());
    readString(def, "name", key, light.name);
    std::string type = "directional";
    readString(def, "type", key, type);
    if (type == "directional") {
        light.type = Light::Type::Directional;
    } else if (type == "spot") {
        light.type = Light::Type::Spot;
    } else if (type == "point") {
        light.type = Light::Type::Point;
    } else {
        error(fx::DiagId::SceneUnknownLightType, {key + ".type", type});
    }
    const bool hasPosition = def.contains("position");
    readVec3(def, "position", key, light.position);
    readVec3(def, "direction", key, light.direction);
    if (def.contains("target")) {
        glm::vec3 target(0.0f);
        readVec3(def, "target", key, target);
        light.direction = target - light.position;
    }
    if (glm::length(light.direction) <= 0.0f) {
        error(fx::DiagId::SceneLightDirectionZero, {key + ".direction"});
        light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    }
    light.direction = glm::normalize(light.direction);
    readVec3(def, "color", key, light.color, true);
    float angle = glm::degrees(light.spotAngle);
    readNumber(def, "angle", key, angle, 0.1f, 179.0f);
    light.spotAngle = glm::radians(angle);
    readNumber(def, "areaRadius", key, light.areaRadius, 0.0f);
    // A directional light's position only says where its view sits: as the built-in scenes place it.
    if (light.type == Light::Type::Directional && !hasPosition) light.position = glm::vec3(std::nanf(""));
    scene.lights.push_back(light);
}

std::optional<Scene> SceneFileReader::read(const json& root) {
    if (!isObject(root, "(top level)")) return std::nullopt;
    checkKeys(root, "(top level)",
              {"name", "meshes", "objects", "camera", "lights", "ambient", "bounds", "hints"});
    Scene scene;
    scene.name = std::filesystem::path(mPath).stem().string();
    readString(root, "name", "(top level)", scene.name);
    readVec3(root, "ambient", "(top level)", scene.ambient, true);

    if (auto it = root.find("meshes"); it != root.end() && isObject(*it, "meshes")) {
        for (const auto& [name, def] : it->items())
            if (auto mesh = readMesh(def, "meshes." + name, name)) mNamedMeshes[name] = mesh;
    }
    if (auto it = root.find("objects"); it != root.end()) {
        if (!it->is_array()) {
            error(fx::DiagId::SceneArrayExpected, {"objects", it->type_name()});
        } else {
            for (size_t i = 0; i < it->size(); ++i)
                readObject((*it)[i], "objects[" + std::to_string(i) + "]", scene);
        }
    }
    if (!mFailed && scene.objects.empty()) error(fx::DiagId::SceneWithoutObjects, {});
    if (auto it = root.find("camera"); it != root.end()) readCamera(*it, scene.camera);
    if (auto it = root.find("bounds"); it != root.end() && isObject(*it, "bounds")) {
        checkKeys(*it, "bounds", {"min", "max"});
        Bounds bounds;
        if (!it->contains("min") || !it->contains("max")) error(fx::DiagId::SceneBoundsIncomplete, {});
        readVec3(*it, "min", "bounds", bounds.min);
        readVec3(*it, "max", "bounds", bounds.max);
        if (glm::any(glm::greaterThan(bounds.min, bounds.max))) error(fx::DiagId::SceneBoundsInverted, {});
        scene.explicitBounds = bounds;
    }
    if (auto it = root.find("hints"); it != root.end() && isObject(*it, "hints")) {
        checkKeys(*it, "hints", {"viewport", "mapSize"});
        readInt(*it, "mapSize", "hints", scene.suggestedMapSize, 1, 65536);
        if (auto v = it->find("viewport"); v != it->end()) {
            if (v->is_array() && v->size() == 2 && (*v)[0].is_number_integer() &&
                (*v)[1].is_number_integer() && (*v)[0].get<int>() > 0 && (*v)[1].get<int>() > 0) {
                scene.suggestedViewport = glm::ivec2((*v)[0].get<int>(), (*v)[1].get<int>());
            } else {
                error(fx::DiagId::SceneViewportHintInvalid, {});
            }
        }
    }
    if (auto it = root.find("lights"); it != root.end()) {
        if (!it->is_array()) {
            error(fx::DiagId::SceneArrayExpected, {"lights", it->type_name()});
        } else {
            for (size_t i = 0; i < it->size(); ++i)
                readLight((*it)[i], "lights[" + std::to_string(i) + "]", scene);
        }
    }
    if (mFailed) return std::nullopt;
    if (scene.lights.empty()) {
        // Effects name "light0": a scene without lights gets the built-in scenes' default sun.
        Light sun;
        sun.direction = glm::normalize(glm::vec3(-0.5f, -1.0f, 0.35f));
        sun.position = glm::vec3(std::nanf(""));
        scene.lights.push_back(sun);
    }
    const Bounds bounds = scene.bounds();
    for (auto& light : scene.lights)
        if (std::isnan(light.position.x))
            light.position = bounds.center() - light.direction * (2.0f * bounds.radius());
    return scene;
}

}  // namespace

// [SECTION] Entry points
std::optional<Scene> parseSceneJson(const std::string& text, const std::string& path,
                                    fx::DiagnosticSink& diagnostics) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        JsonLocations::reportSyntaxError(path, text, e.byte, e.what(), diagnostics);
        return std::nullopt;
    } catch (const std::exception& e) {
        diagnostics.report(fx::DiagId::SceneSyntaxError, fx::SourceLoc{path, 0, 0}, {e.what()});
        return std::nullopt;
    }
    try {
        return SceneFileReader(path, diagnostics).read(root);
    } catch (const std::exception& e) {
        // The reader checks every type before reading it; this is the net under anything it missed.
        diagnostics.report(fx::DiagId::SceneReadFailed, fx::SourceLoc{path, 0, 0}, {e.what()});
        return std::nullopt;
    }
}

std::optional<Scene> loadSceneFile(const std::string& path, fx::DiagnosticSink& diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diagnostics.report(fx::DiagId::FileNotFound, fx::SourceLoc{path, 0, 0}, {path});
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseSceneJson(text.str(), path, diagnostics);
}

std::optional<Scene> loadScene(const std::string& nameOrPath, fx::DiagnosticSink& diagnostics) {
    const bool isFile = nameOrPath.size() > 5 && nameOrPath.compare(nameOrPath.size() - 5, 5, ".json") == 0;
    return isFile ? loadSceneFile(nameOrPath, diagnostics) : makeBuiltinScene(nameOrPath, &diagnostics);
}

}  // namespace runtime
