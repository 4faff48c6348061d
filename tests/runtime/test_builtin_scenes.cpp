// Built-in scenes beyond boxes/torus/teapot (test_scene.cpp): every scene fits its light's frustum and
// shows something; the seeds' setups are what they claim (forest: 10,000 trees over a few shared meshes;
// behind: casters behind the camera whose shadows reach the visible ground); asset scenes load or say which
// package is missing.
#include <runtime/BuiltinScenes.h>
#include <runtime/MeshImporter.h>
#include <runtime/Scene.h>

#include <fx/Diagnostics.h>

#include <gtest/gtest.h>

#include <chrono>
#include <set>

namespace test_builtin_scenes {

using namespace runtime;

namespace {

glm::vec3 toWorld(const SceneObject& object, const glm::vec3& p) {
    return glm::vec3(object.world * glm::vec4(p, 1.0f));
}

Scene builtin(std::string_view name) {
    fx::DiagnosticList diagnostics;
    auto scene = makeBuiltinScene(name, &diagnostics);
    EXPECT_TRUE(scene.has_value()) << name << ": " << diagnostics.str();
    return scene ? std::move(*scene) : Scene{};
}

constexpr int kWidth = 512, kHeight = 512;

}  // namespace

TEST(BuiltinScenes, NamesAndUnknownScene) {
    const auto names = builtinSceneNames();
    for (const char* expected : {"boxes", "torus", "teapot", "dual-l", "double-torus", "forest", "behind",
                                 "bunny", "horse", "spider", "engine"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(makeBuiltinScene("no-such-scene", &diagnostics));
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].id, fx::DiagId::UnknownScene);
    EXPECT_NE(diagnostics.items()[0].message.find("forest"), std::string::npos);  // lists the known ones
    EXPECT_FALSE(makeBuiltinScene("no-such-scene", nullptr));
}

// Every vertex of every object inside the light's frustum (x, y in [-1, 1], z in [0, 1]), and the camera
// sees a good part of the scene's objects.
TEST(BuiltinScenes, FitTheLightAndShowSomething) {
    for (const auto& name : builtinSceneNames()) {
        Scene scene = builtin(name);
        ASSERT_FALSE(scene.objects.empty()) << name;
        ASSERT_FALSE(scene.lights.empty()) << name;
        const Bounds bounds = scene.bounds();
        std::set<uint32_t> ids;
        for (const auto& object : scene.objects)
            EXPECT_TRUE(ids.insert(object.id).second) << name << " duplicate id";
        for (const auto& light : scene.lights) {
            const glm::mat4 viewProjection = light.projection(bounds) * light.view(bounds);
            for (const auto& object : scene.objects) {
                const glm::vec3 lo = object.mesh->boundsMin(), hi = object.mesh->boundsMax();
                // The eight corners of the object's box bound every vertex: enough, and fast for 10,000
                // trees.
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::vec3 p(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                      corner & 4 ? hi.z : lo.z);
                    const glm::vec4 clip = viewProjection * glm::vec4(toWorld(object, p), 1.0f);
                    ASSERT_GT(clip.w, 0.0f);
                    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                    ASSERT_TRUE(std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && ndc.z >= 0.0f &&
                                ndc.z <= 1.0f)
                        << name << "/" << object.name << " (" << ndc.x << ", " << ndc.y << ", " << ndc.z
                        << ")";
                }
            }
        }
        size_t visibleObjects = 0;
        for (const auto& object : scene.objects) {
            const glm::vec3 centre =
                toWorld(object, (object.mesh->boundsMin() + object.mesh->boundsMax()) * 0.5f);
            if (projectToPixel(scene, centre, kWidth, kHeight)) ++visibleObjects;
        }
        EXPECT_GE(visibleObjects, std::min<size_t>(scene.objects.size() - 1, 2))
            << name << ": the camera sees too little";
    }
}

TEST(BuiltinScenes, ForestIsScherzersSetup) {
    const auto start = std::chrono::steady_clock::now();
    Scene scene = builtin("forest");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("load_seconds",
                   std::to_string(seconds));  // reported, not asserted (GUIDE.md: no timed tests)
    std::set<const Mesh*> treeMeshes;
    size_t trees = 0;
    for (const auto& object : scene.objects) {
        if (object.name == "terrain") continue;
        ++trees;
        treeMeshes.insert(object.mesh.get());
        EXPECT_TRUE(object.mesh->closed);
    }
    EXPECT_EQ(trees, 10000u);
    EXPECT_LE(treeMeshes.size(), 5u);
    EXPECT_GE(treeMeshes.size(), 2u);
    // Scherzer 2005, §5: fov 60°, near 0.1, far 70; 512² viewport, 2048² map.
    EXPECT_NEAR(glm::degrees(scene.camera.fovY), 60.0f, 1e-4f);
    EXPECT_FLOAT_EQ(scene.camera.nearPlane, 0.1f);
    EXPECT_FLOAT_EQ(scene.camera.farPlane, 70.0f);
    EXPECT_EQ(scene.suggestedViewport, glm::ivec2(512, 512));
    EXPECT_EQ(scene.suggestedMapSize, 2048);
    EXPECT_EQ(scene.lights.at(0).type, Light::Type::Directional);
    // The camera is inside the forest: trees all around within the far plane, and many in view.
    size_t inView = 0;
    for (const auto& object : scene.objects)
        if (object.name != "terrain" &&
            projectToPixel(scene, toWorld(object, glm::vec3(0, 1, 0)), kWidth, kHeight))
            ++inView;
    EXPECT_GT(inView, 100u);
    // Deterministic: the same seed gives the same forest.
    Scene again = builtin("forest");
    ASSERT_EQ(again.objects.size(), scene.objects.size());
    EXPECT_EQ(again.objects[5000].world, scene.objects[5000].world);
}

TEST(BuiltinScenes, BehindHasCastersBehindTheViewerShadowingTheView) {
    Scene scene = builtin("behind");
    const glm::mat4 view = scene.camera.view();
    const Light& light = scene.lights.at(0);
    // The light is behind the viewer too: it shines the way the camera looks.
    EXPECT_GT(glm::dot(light.direction, glm::normalize(scene.camera.target - scene.camera.position)), 0.5f);

    // Only the ground and the casters entirely behind the camera (view-space z < 0 at every vertex).
    Scene behindOnly = scene;
    behindOnly.objects.clear();
    const SceneObject* ground = nullptr;
    for (const auto& object : scene.objects) {
        if (object.name == "ground") {
            behindOnly.objects.push_back(object);
            ground = &object;
            continue;
        }
        bool behind = true;
        for (const auto& p : object.mesh->positions)
            behind = behind && (view * glm::vec4(toWorld(object, p), 1.0f)).z < 0.0f;
        if (behind) behindOnly.objects.push_back(object);
    }
    ASSERT_TRUE(ground);
    ASSERT_GE(behindOnly.objects.size(), 4u) << "too few casters behind the camera";

    // Ground points the camera sees, whose segment towards the light those casters block.
    size_t visible = 0, shadowed = 0;
    for (float z = -20.0f; z <= 20.0f; z += 1.0f) {
        for (float x = -14.0f; x <= 14.0f; x += 1.0f) {
            const glm::vec3 p(x, 0.0f, z);
            if (!projectToPixel(scene, p, kWidth, kHeight)) continue;
            ++visible;
            if (segmentOccluded(behindOnly, p, p - light.direction * 100.0f)) ++shadowed;
        }
    }
    EXPECT_GT(visible, 100u);
    EXPECT_GT(shadowed, 20u) << "of " << visible << " visible ground points";
}

TEST(BuiltinScenes, DualLIsAnLAboveAPlaneLitFromRightAbove) {
    Scene scene = builtin("dual-l");
    ASSERT_EQ(scene.objects.size(), 2u);
    const SceneObject& l = scene.objects[1];
    EXPECT_TRUE(l.mesh->closed);
    EXPECT_GT(toWorld(l, l.mesh->boundsMin()).y, 0.0f);  // above the plane
    const Light& light = scene.lights.at(0);
    EXPECT_LT(light.direction.x, 0.0f);   // from the right ...
    EXPECT_LT(light.direction.y, -0.7f);  // ... and above
    Scene torus = builtin("double-torus");
    EXPECT_TRUE(torus.objects.at(1).mesh->closed);
}

TEST(BuiltinScenes, AssetScenesStandOnTheirPlane) {
    for (const char* name : {"bunny", "horse", "spider", "engine"}) {
        Scene scene = builtin(name);
        ASSERT_EQ(scene.objects.size(), 2u) << name;
        const SceneObject& model = scene.objects[1];
        const glm::vec3 lo = toWorld(model, model.mesh->boundsMin()),
                        hi = toWorld(model, model.mesh->boundsMax());
        EXPECT_NEAR(lo.y, 0.0f, 1e-4f) << name;
        EXPECT_NEAR(std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}), 3.0f, 1e-3f) << name;
        EXPECT_GT(model.mesh->triangleCount(), 100u) << name;
    }
}

TEST(BuiltinScenes, MissingAssetNamesItsPackage) {
    EXPECT_EQ(debianPackageForAsset("/usr/share/glmark2/models/bunny.obj"), "glmark2-data");
    EXPECT_EQ(debianPackageForAsset("/usr/share/assimp/models/OBJ/spider.obj"), "assimp-testmodels");
    EXPECT_EQ(debianPackageForAsset("/home/me/model.obj"), "");
    fx::DiagnosticList diagnostics;
    EXPECT_FALSE(importMesh("/usr/share/glmark2/models/no-such-model.obj", {}, diagnostics));
    ASSERT_EQ(diagnostics.items().size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].id, fx::DiagId::MeshFileNotInstalled);
    EXPECT_NE(diagnostics.items()[0].message.find("no-such-model.obj"), std::string::npos);
    EXPECT_NE(diagnostics.items()[0].message.find("glmark2-data"), std::string::npos);
}
}  // namespace test_builtin_scenes
