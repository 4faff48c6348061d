// An application of the contract library and the effect runtime only (the `render` library, which links
// fxcontract, not the compiler): it loads a compiled effect file that the CLI wrote and renders a frame.
// CMake gives the file's path; tests/CMakeLists.txt checks that this binary holds no glslang or
// SPIRV-Cross symbol.
#include <runtime/EffectRenderer.h>
#include <runtime/GlContext.h>
#include <runtime/Mesh.h>
#include <runtime/Scene.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <set>

namespace {

runtime::Scene boxOnGround() {
    runtime::Scene scene;
    scene.name = "box";
    auto add = [&scene](runtime::Mesh mesh, const glm::mat4& world) {
        runtime::SceneObject object;
        object.name = "object" + std::to_string(scene.objects.size() + 1);
        object.mesh = std::make_shared<runtime::Mesh>(std::move(mesh));
        object.world = world;
        object.color = glm::vec3(0.8f);
        object.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(std::move(object));
    };
    add(runtime::makePlane(8.0f, 8.0f), glm::mat4(1.0f));
    add(runtime::makeBox(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f)));
    scene.camera.position = glm::vec3(-3.0f, 3.0f, -5.0f);
    scene.camera.target = glm::vec3(0.0f, 0.5f, 0.0f);
    runtime::Light light;
    light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    scene.lights.push_back(light);
    return scene;
}

TEST(ContractOnly, LoadsACompiledEffectFileAndRendersAFrame) {
    std::string error;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext(runtime::ContextOptions{}, error);
    ASSERT_TRUE(context) << error;
    context->makeCurrent();
    fx::DiagnosticList diagnostics;
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::createFromFile(SHADOWFX_COMPILED_EFFECT, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    runtime::FrameOptions options;
    options.width = 96;
    options.height = 72;
    ASSERT_TRUE(renderer->render(boxOnGround(), options, diagnostics)) << diagnostics.str();
    const runtime::FrameImage frame = renderer->readFrame();
    ASSERT_EQ(frame.rgba.size(), size_t{96} * 72 * 4);
    // The clear colour, the ground and the box's faces, each lit differently: not a blank or constant frame.
    std::set<uint32_t> colours;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4)
        colours.insert(uint32_t(frame.rgba[i]) << 16 | uint32_t(frame.rgba[i + 1]) << 8 | frame.rgba[i + 2]);
    EXPECT_GE(colours.size(), 3u);
}

}  // namespace
