// Scenes of real meshes that Debian ships, read where the packages install them (scripts/install-deps.sh
// installs both): the Stanford bunny and the horse from glmark2-data, the spider (OBJ) and the two-cylinder
// engine (glTF 2, binary) from assimp-testmodels. Each stands on a plane, normalised to a few units, lit by
// a directional light from above at an angle. A missing file is reported with the package that ships it.
#include <private/runtime/SceneBuilding.h>

#include <runtime/MeshImporter.h>

#include <glm/gtc/matrix_transform.hpp>

namespace runtime {

namespace {

struct AssetSetup {
    const char* name;
    const char* path;
    MeshImportOptions options;
    glm::vec3 color;
};

std::optional<Scene> makeAssetScene(const AssetSetup& setup, fx::DiagnosticSink* diagnostics) {
    fx::DiagnosticList ignored;
    auto mesh = importMesh(setup.path, setup.options, diagnostics ? *diagnostics : ignored);
    if (!mesh) return std::nullopt;
    Scene scene;
    scene.name = setup.name;
    const float size = setup.options.normalizeSize;
    scene.objects.push_back(placeObject("ground",
                                        std::make_shared<const Mesh>(makePlane(4.0f * size, 4.0f * size, 16)),
                                        glm::mat4(1.0f), glm::vec3(0.75f, 0.75f, 0.7f), 1));
    // importMesh put the base's centre at the origin: the mesh stands on the plane.
    scene.objects.push_back(placeObject(setup.name, std::make_shared<const Mesh>(std::move(*mesh)),
                                        glm::mat4(1.0f), setup.color, 2));
    const Bounds bounds = scene.objects[1].mesh
                              ? Bounds{scene.objects[1].mesh->boundsMin(), scene.objects[1].mesh->boundsMax()}
                              : Bounds{};
    scene.camera.position = glm::vec3(0.35f * size, 0.9f * size, -1.6f * size);
    scene.camera.target = glm::vec3(0.0f, 0.4f * (bounds.max.y - bounds.min.y), 0.0f);
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(-0.6f, -1.0f, 0.4f), scene.bounds()));
    return scene;
}

MeshImportOptions normalizedTo(float size, glm::vec3 rotate = glm::vec3(0.0f), bool generateNormals = false) {
    MeshImportOptions options;
    options.generateNormals = generateNormals;
    options.normalizeSize = size;
    options.rotateDegrees = rotate;
    return options;
}

}  // namespace

std::optional<Scene> makeBunnyScene(fx::DiagnosticSink* diagnostics) {
    return makeAssetScene({"bunny", "/usr/share/glmark2/models/bunny.obj", normalizedTo(3.0f, {}, true),
                           glm::vec3(0.85f, 0.75f, 0.6f)},
                          diagnostics);
}

std::optional<Scene> makeHorseScene(fx::DiagnosticSink* diagnostics) {
    // glmark2's horse.3ds lies with its back towards -x (its torso pulls the centroid there, its legs are
    // thin towards +x): a -90 degree roll about z stands it on its hooves.
    return makeAssetScene({"horse", "/usr/share/glmark2/models/horse.3ds",
                           normalizedTo(3.0f, glm::vec3(0.0f, 0.0f, -90.0f)), glm::vec3(0.55f, 0.4f, 0.3f)},
                          diagnostics);
}

std::optional<Scene> makeSpiderScene(fx::DiagnosticSink* diagnostics) {
    return makeAssetScene({"spider", "/usr/share/assimp/models/OBJ/spider.obj", normalizedTo(3.0f, {}, true),
                           glm::vec3(0.4f, 0.35f, 0.3f)},
                          diagnostics);
}

std::optional<Scene> makeEngineScene(fx::DiagnosticSink* diagnostics) {
    return makeAssetScene(
        {"engine", "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
         normalizedTo(3.0f), glm::vec3(0.6f, 0.6f, 0.65f)},
        diagnostics);
}

}  // namespace runtime
