// "forest": Scherzer's test scene (Scherzer 2005, §5: "an outdoor environment that contains 10.000 tree-like
// objects ... lit by one directional light source ... 512x512 pixel viewport ... 2048x2048 pixel shadow
// map ... field of view 60°, near plane 0.1, far plane 70").
//
// Terrain: a height field of a few sines. Trees: three meshes (two conifers, one broad-leaved; trunk and
// crown in one closed mesh), shared by 10,000 objects placed by a fixed-seed std::mt19937 (whose output
// sequence the standard fixes, unlike the distributions', so every platform gets the same forest).
#include <private/runtime/SceneBuilding.h>

#include <runtime/MeshImporter.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace runtime {

namespace {

constexpr float kTerrainSize = 200.0f;
constexpr int kTreeCount = 10000;
constexpr uint32_t kForestSeed = 20050101;

// Rolling hills a few metres high: long enough waves that the camera still sees along the forest floor.
float terrainHeight(float x, float z) {
    return 2.5f * std::sin(x * 0.045f) * std::cos(z * 0.035f) + 1.0f * std::sin(x * 0.11f + z * 0.07f + 1.3f);
}

// A tree with its trunk's foot at the origin: trunk cylinder plus crown (cone or sphere), overlapping a
// little so no light leaks between them.
Mesh makeTree(const char* name, float trunkRadius, float trunkHeight, bool conifer, float crownRadius,
              float crownHeight) {
    Mesh tree;
    tree.name = name;
    appendMesh(tree, makeCylinder(trunkRadius, trunkHeight, 8), glm::vec3(0.0f, 0.5f * trunkHeight, 0.0f));
    if (conifer) {
        appendMesh(tree, makeCone(crownRadius, crownHeight, 10),
                   glm::vec3(0.0f, 0.8f * trunkHeight + 0.5f * crownHeight, 0.0f));
    } else {
        appendMesh(tree, makeSphere(crownRadius, 12, 8),
                   glm::vec3(0.0f, trunkHeight + 0.6f * crownRadius, 0.0f));
    }
    tree.closed = true;
    return tree;
}

}  // namespace

Scene makeForestScene() {
    Scene scene;
    scene.name = "forest";
    scene.objects.reserve(kTreeCount + 1);
    scene.objects.push_back(placeObject(
        "terrain",
        std::make_shared<const Mesh>(makeHeightField(kTerrainSize, kTerrainSize, 128, terrainHeight)),
        glm::mat4(1.0f), glm::vec3(0.45f, 0.55f, 0.3f), 1));

    const std::shared_ptr<const Mesh> trees[] = {
        std::make_shared<const Mesh>(makeTree("fir", 0.15f, 1.2f, true, 1.0f, 3.5f)),
        std::make_shared<const Mesh>(makeTree("spruce", 0.12f, 1.5f, true, 0.75f, 5.0f)),
        std::make_shared<const Mesh>(makeTree("beech", 0.18f, 2.0f, false, 1.3f, 0.0f)),
    };
    const glm::vec3 colors[] = {{0.2f, 0.45f, 0.2f}, {0.15f, 0.38f, 0.22f}, {0.35f, 0.55f, 0.2f}};

    // The camera stands near one edge, eye height above the ground, looking along the forest; a clearing
    // around it keeps a trunk from filling the image.
    const glm::vec2 eye(0.0f, -0.42f * kTerrainSize);
    const glm::vec2 ahead(0.0f, eye.y + 30.0f);
    scene.camera.position = glm::vec3(eye.x, terrainHeight(eye.x, eye.y) + 1.8f, eye.y);
    scene.camera.target = glm::vec3(ahead.x, terrainHeight(ahead.x, ahead.y) + 1.5f, ahead.y);
    scene.camera.fovY = glm::radians(60.0f);
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 70.0f;
    scene.suggestedViewport = glm::ivec2(512, 512);
    scene.suggestedMapSize = 2048;

    std::mt19937 rng(kForestSeed);
    auto uniform = [&rng](float lo, float hi) {
        return lo + (hi - lo) * float(rng() >> 8) * (1.0f / 16777216.0f);
    };
    const float half = 0.5f * kTerrainSize - 2.0f;  // keep crowns over the terrain
    uint32_t id = 2;
    while (scene.objects.size() < size_t(kTreeCount) + 1) {
        const float x = uniform(-half, half), z = uniform(-half, half);
        const int kind = int(rng() % 3u);
        const float yaw = uniform(0.0f, 360.0f), scale = uniform(0.8f, 1.25f);
        if (glm::length(glm::vec2(x, z) - eye) < 4.0f) continue;  // the clearing
        // Sunk 0.2 into the ground so the trunk's foot never floats over a slope.
        const glm::mat4 world = composeTransform(glm::vec3(x, terrainHeight(x, z) - 0.2f, z),
                                                 glm::vec3(0.0f, yaw, 0.0f), glm::vec3(scale));
        scene.objects.push_back(
            placeObject("tree" + std::to_string(id - 1), trees[kind], world, colors[kind], id));
        ++id;
    }
    // A low afternoon sun, from the camera's left and behind it: long shadows across the line of sight.
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(0.55f, -0.6f, 0.45f), scene.bounds()));
    return scene;
}

Scene makeForestFifthScene() {
    // The leave-out measurement's viewpoint (docs/measurement.md, "Leave-out"): the same forest, seen to 110
    // m instead of 70, so that about a fifth of the trees lies in the view frustum (shadowfx render --stats
    // counts them: the scene pass's draws over its draws plus culled objects).
    Scene scene = makeForestScene();
    scene.name = "forest-fifth";
    scene.camera.farPlane = 110.0f;
    return scene;
}

}  // namespace runtime
