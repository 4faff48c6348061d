// Batching (FrameOptions::batching): the objects of a pass that share a mesh are drawn as one instanced
// draw per mesh, their per-object values read from a buffer by instance. It must never change the image:
// - frames with batching on and off are identical, byte for byte, for several shipped effects (per-object
//   values in the vertex stage, in the pixel stage, in compile arguments, cascaded light ports) on a grid
//   of boxes sharing one mesh and on built-in scenes, while the draws per pass drop to one per mesh;
// - per-object records kept between frames follow what changed: a moved object, a moved camera (which
//   packs only the records' view parts);
// - a parameter the application pins is no longer per object, and the frame follows it;
// - every technique of every shipped effect renders the same frame either way (what `shadowfx check`
//   scores and compares with goldens, so its results cannot differ; the full check without batching is
//   `shadowfx check effects/*.fx --no-batching`, docs/per-draw-cost.md).
#include "LeaveOutFrames.h"
#include "effects/EffectHarness.h"

#include <fx/InstancedPass.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/GpuProgram.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>
#include <set>

namespace test_batching {

namespace {

using namespace runtime;
using shadowfx::test::differingPixels;
using shadowfx::test::loadEffect;
using shadowfx::test::notConstant;
using shadowfx::test::sourcePath;

// A 12 x 12 grid of boxes sharing one mesh on a plane; the camera sees part of it.
Scene gridScene() {
    Scene scene;
    scene.name = "grid";
    auto ground = std::make_shared<const Mesh>(makePlane(30.0f, 30.0f, 4));
    auto box = std::make_shared<const Mesh>(makeBox(glm::vec3(0.8f, 2.0f, 0.8f)));
    SceneObject plane;
    plane.name = "ground";
    plane.mesh = ground;
    plane.id = 1;
    scene.objects.push_back(plane);
    for (int i = 0; i < 12; ++i) {
        for (int j = 0; j < 12; ++j) {
            SceneObject object;
            object.name = "box";
            object.mesh = box;
            object.world =
                glm::translate(glm::mat4(1.0f), glm::vec3(-13.0f + 2.4f * i, 1.0f, -13.0f + 2.4f * j));
            object.world = glm::rotate(object.world, 0.1f * static_cast<float>(i + j), glm::vec3(0, 1, 0));
            object.color = glm::vec3(0.3f + 0.05f * i, 0.5f, 0.3f + 0.05f * j);
            object.id = static_cast<uint32_t>(scene.objects.size() + 1);
            scene.objects.push_back(object);
        }
    }
    scene.camera.position = glm::vec3(-16.0f, 9.0f, -16.0f);
    scene.camera.target = glm::vec3(-2.0f, 0.0f, -4.0f);
    scene.camera.farPlane = 60.0f;
    Light light;
    light.direction = glm::normalize(glm::vec3(0.6f, -0.7f, 0.45f));
    scene.lights.push_back(light);
    return scene;
}

struct Frame {
    FrameImage image;
    FrameStats stats;
};

Frame renderFrame(EffectRenderer& renderer, const Scene& scene, const std::string& technique, bool batching,
                  int width = 128, int height = 96) {
    FrameOptions options;
    options.width = width;
    options.height = height;
    options.technique = technique;
    options.batching = batching;
    options.reuseTargets = false;  // every pass draws in every frame
    fx::DiagnosticList diagnostics;
    Frame frame;
    EXPECT_TRUE(renderer.render(scene, options, diagnostics, &frame.stats)) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    frame.image = renderer.readFrame();
    return frame;
}

size_t distinctMeshes(const Scene& scene) {
    std::set<const Mesh*> meshes;
    for (const SceneObject& object : scene.objects)
        if (object.mesh) meshes.insert(object.mesh.get());
    return meshes.size();
}

struct Case {
    const char* effect;
    const char* technique;
};

// GoogleTest prints a parameter's bytes unless told otherwise.
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.effect << " " << c.technique;
}

class BatchedFrames : public ::testing::TestWithParam<Case> {};

TEST_P(BatchedFrames, SameImageFewerDraws) {
    const Case c = GetParam();
    auto renderer = loadEffect(sourcePath(c.effect), true);
    ASSERT_TRUE(renderer);
    std::vector<Scene> scenes{gridScene()};
    for (const char* name : {"boxes", "teapot"}) {
        std::optional<Scene> scene = makeBuiltinScene(name);
        ASSERT_TRUE(scene) << name;
        scenes.push_back(std::move(*scene));
    }
    for (const Scene& scene : scenes) {
        SCOPED_TRACE(scene.name);
        const Frame single = renderFrame(*renderer, scene, c.technique, false);
        const Frame batched = renderFrame(*renderer, scene, c.technique, true);
        EXPECT_TRUE(notConstant(batched.image));
        EXPECT_EQ(differingPixels(batched.image, single.image), 0u);
        EXPECT_EQ(batched.stats.objects, single.stats.objects);
        EXPECT_EQ(single.stats.objects, single.stats.draws);
        ASSERT_EQ(batched.stats.passes.size(), single.stats.passes.size());
        for (size_t i = 0; i < batched.stats.passes.size(); ++i) {
            const PassStats& pass = batched.stats.passes[i];
            SCOPED_TRACE(pass.pass);
            EXPECT_EQ(pass.objects, single.stats.passes[i].objects);
            EXPECT_EQ(pass.triangles, single.stats.passes[i].triangles);
            if (scene.name == "grid" && pass.objects > 0) {
                EXPECT_LE(pass.draws, static_cast<int>(distinctMeshes(scene))) << "one draw per mesh";
            }
        }
        if (scene.name == "grid") {
            EXPECT_LT(batched.stats.draws * 10, single.stats.draws);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Effects, BatchedFrames,
    ::testing::Values(Case{"effects/thesis_fxcomposer.fx", "main"}, Case{"effects/id_buffer.fx", "main"},
                      Case{"effects/cascades.fx", "blended"}, Case{"effects/plain_lit.fx", "lit"}),
    [](const ::testing::TestParamInfo<Case>& info) {
        std::string name = std::string(info.param.effect).substr(8) + "_" + info.param.technique;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

// Records are kept between frames; whatever changes an object's values must reach its record.
TEST(Batching, RecordsFollowObjectsAndCamera) {
    auto batchedRenderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    auto singleRenderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(batchedRenderer && singleRenderer);
    Scene scene = gridScene();
    const auto same = [&](const char* what) {
        SCOPED_TRACE(what);
        const Frame batched = renderFrame(*batchedRenderer, scene, "main", true);
        const Frame single = renderFrame(*singleRenderer, scene, "main", false);
        EXPECT_TRUE(notConstant(batched.image));
        EXPECT_EQ(differingPixels(batched.image, single.image), 0u);
        return batched.image;
    };
    const FrameImage first = same("first frame");
    same("unchanged");
    // A box in view moves and turns red.
    SceneObject& box = scene.objects[1 + 2 * 12 + 3];
    box.world = glm::translate(box.world, glm::vec3(0.0f, 1.5f, 0.0f));
    box.color = glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_GT(differingPixels(same("object moved"), first), 0u);
    scene.camera.position += glm::vec3(1.0f, 0.5f, 0.0f);
    same("camera moved");
}

// A record's object part (World and its inverse transpose, the object's colour) derives from the object
// alone: with only the camera moving, a frame packs the view parts of the objects it draws
// (World*View*Projection) and no whole record, once every object in view has been drawn before (one first
// seen is packed whole); a recoloured object is packed whole, the others not at all.
TEST(Batching, MovingCameraPacksOnlyTheViewParts) {
    auto batchedRenderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    auto singleRenderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(batchedRenderer && singleRenderer);
    Scene scene = gridScene();
    const auto render = [&](const char* what) {
        SCOPED_TRACE(what);
        const Frame batched = renderFrame(*batchedRenderer, scene, "main", true);
        const Frame single = renderFrame(*singleRenderer, scene, "main", false);
        EXPECT_TRUE(notConstant(batched.image));
        EXPECT_EQ(differingPixels(batched.image, single.image), 0u);
        return batched.stats;
    };
    const FrameStats first = render("first frame");
    EXPECT_GT(first.recordsPacked, 0u);
    EXPECT_EQ(first.recordViewPartsPacked, 0u);
    const FrameStats unchanged = render("unchanged");
    EXPECT_EQ(unchanged.recordsPacked, 0u);
    EXPECT_EQ(unchanged.recordViewPartsPacked, 0u);
    const glm::vec3 start = scene.camera.position;
    const glm::vec3 step(0.4f, 0.2f, -0.3f);
    for (int round = 0; round < 2; ++round) {
        for (int position = 0; position < 3; ++position) {
            scene.camera.position = start + step * static_cast<float>(position + 1);
            const FrameStats moved = render(round == 0 ? "camera moved" : "camera moved where it was");
            if (round == 0) continue;  // objects come into view
            EXPECT_EQ(moved.recordsPacked, 0u);
            EXPECT_GT(moved.recordViewPartsPacked, 0u);
            EXPECT_LE(moved.recordViewPartsPacked, static_cast<uint64_t>(moved.objects));
        }
    }
    scene.objects[1 + 2 * 12 + 3].color = glm::vec3(1.0f, 0.0f, 0.0f);  // a box in view
    const FrameStats recoloured = render("object recoloured");
    EXPECT_GE(recoloured.recordsPacked, 1u);  // in each pass that draws it: the scene's and the shadow map's
    EXPECT_LE(recoloured.recordsPacked, 2u);
    EXPECT_EQ(recoloured.recordViewPartsPacked, 0u);
}

// The batched variant is GLSL shadowfx writes itself, so the driver must have nothing to say about it:
// Mesa warned that the functions above main() read the instance's object index uninitialized.
TEST(Batching, TheDriverHasNoWarningOnTheBatchedVariant) {
    auto renderer = loadEffect(sourcePath("effects/plain_lit.fx"), true);
    ASSERT_TRUE(renderer);
    const fx::CompiledEffect& effect = renderer->effect();
    std::vector<bool> perObject(effect.parameters.size(), false);
    for (size_t i = 0; i < effect.parameters.size(); ++i)
        perObject[i] = effect.parameters[i].semantic.rfind("World", 0) == 0;
    const fx::CompiledPass& pass = effect.techniques.at(0).passes.at(0);
    std::string whyNot;
    const std::optional<fx::InstancedPass> variant =
        fx::instancedPass(pass, perObject, std::vector<bool>(pass.arguments.size(), false), whyNot);
    ASSERT_TRUE(variant) << whyNot;
    ASSERT_NE(variant->pass.vertex.glsl.find("fx_objects[fx_object]"), std::string::npos)
        << "the vertex stage reads no per-object value:\n"
        << variant->pass.vertex.glsl;
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(GpuProgram::create(variant->pass, diagnostics)) << diagnostics.str();
    EXPECT_EQ(shadowfx::test::countDiagnostics(diagnostics, fx::DiagId::DriverShaderLog) +
                  shadowfx::test::countDiagnostics(diagnostics, fx::DiagId::DriverLinkLog),
              0)
        << diagnostics.str();
}

// A pinned per-object parameter holds the application's value for every object.
TEST(Batching, PinnedParameterIsNotPerObject) {
    auto batchedRenderer = loadEffect(sourcePath("effects/plain_lit.fx"), true);
    auto singleRenderer = loadEffect(sourcePath("effects/plain_lit.fx"), true);
    ASSERT_TRUE(batchedRenderer && singleRenderer);
    const Scene scene = gridScene();
    const Frame before = renderFrame(*batchedRenderer, scene, "lit", true);
    bool pinned = false;
    for (size_t i = 0; i < batchedRenderer->effect().parameters.size(); ++i) {
        const fx::ParameterInfo& p = batchedRenderer->effect().parameters[i];
        std::string semantic = p.semantic;
        for (char& ch : semantic) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        if (semantic != "DIFFUSE" && semantic != "MATERIALDIFFUSE" && semantic != "DIFFUSECOLOR") continue;
        fx::Value green = batchedRenderer->parameter(i);
        green.data = {0.1f, 0.9f, 0.2f, 1.0f};
        green.data.resize(batchedRenderer->parameter(i).data.size(), 1.0f);
        batchedRenderer->setParameter(i, green);
        singleRenderer->setParameter(i, green);
        pinned = true;
    }
    ASSERT_TRUE(pinned) << "plain_lit.fx binds the object colour";
    const Frame batched = renderFrame(*batchedRenderer, scene, "lit", true);
    const Frame single = renderFrame(*singleRenderer, scene, "lit", false);
    EXPECT_TRUE(notConstant(batched.image));
    EXPECT_EQ(differingPixels(batched.image, single.image), 0u);
    EXPECT_GT(differingPixels(batched.image, before.image), 0u);
}

std::vector<std::string> shippedEffects() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("effects")))
        if (entry.path().extension() == ".fx") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class ShippedEffect : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedEffect, EveryTechniqueDrawsTheSameFrameBatchedOrNot) {
    auto renderer = loadEffect(sourcePath("effects/" + GetParam()), true);
    ASSERT_TRUE(renderer);
    const Scene grid = gridScene();
    for (const fx::CompiledTechnique& technique : renderer->effect().techniques) {
        const std::string name =
            technique.group.empty() ? technique.name : technique.group + "." + technique.name;
        SCOPED_TRACE(name);
        const Frame single = renderFrame(*renderer, grid, name, false, 96, 72);
        const Frame batched = renderFrame(*renderer, grid, name, true, 96, 72);
        EXPECT_TRUE(notConstant(batched.image));
        EXPECT_EQ(differingPixels(batched.image, single.image), 0u);
        EXPECT_EQ(batched.stats.objects, single.stats.objects);
    }
}

INSTANTIATE_TEST_SUITE_P(Effects, ShippedEffect, ::testing::ValuesIn(shippedEffects()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.size() - 3);
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

}  // namespace
}  // namespace test_batching
