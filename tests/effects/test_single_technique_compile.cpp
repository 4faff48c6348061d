// A technique compiled alone (`render --technique`, the visibility variants `check` scores) must render
// exactly what the same technique renders when the whole effect is compiled: the compiled effect carries
// every pass's resolved data, so nothing may depend on where a technique or pass stands in the source.
//
// The scene has what the pass annotations act on: closed objects (a box, a sphere) and open ones (the
// ground and a "roof" plane above the box, facing down), under a directional light from above. The roof
// is what CullClosedOnly keeps in a back-face-culled layer pass: without it, dual_depth.fx's peel_cull
// loses the roof's shadow.
#include "VisibilityHarness.h"
#include "runtime/LeaveOutFrames.h"

#include <fx/CompileCache.h>
#include <runtime/Mesh.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>

namespace shadowfx::test::test_single_technique_compile {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 72;

runtime::Scene roofScene() {
    runtime::Scene scene;
    scene.name = "roof";
    auto add = [&scene](runtime::Mesh mesh, const glm::mat4& world, glm::vec3 color) {
        runtime::SceneObject object;
        object.name = "object" + std::to_string(scene.objects.size() + 1);
        object.mesh = std::make_shared<runtime::Mesh>(std::move(mesh));
        object.world = world;
        object.color = color;
        object.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(std::move(object));
    };
    add(runtime::makePlane(12.0f, 12.0f), glm::mat4(1.0f), glm::vec3(0.8f));
    add(runtime::makeBox(glm::vec3(1.0f)), glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.5f, 0.0f)),
        glm::vec3(0.8f, 0.3f, 0.3f));
    add(runtime::makeSphere(0.6f), glm::translate(glm::mat4(1.0f), glm::vec3(-2.5f, 0.6f, 1.0f)),
        glm::vec3(0.3f, 0.8f, 0.3f));
    // The roof: open, above the box, facing down (a ceiling seen from below): the light sees its back,
    // which a back-face-culled layer pass drops unless the pass culls closed objects only.
    add(runtime::makePlane(3.0f, 3.0f),
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(1.5f, 2.5f, 0.0f)), glm::pi<float>(),
                    glm::vec3(1.0f, 0.0f, 0.0f)),
        glm::vec3(0.3f, 0.3f, 0.8f));
    scene.camera.position = glm::vec3(-1.0f, 2.0f, -8.0f);
    scene.camera.target = glm::vec3(1.0f, 0.5f, 0.0f);
    runtime::Light light;
    light.direction = glm::normalize(glm::vec3(0.15f, -1.0f, 0.1f));
    scene.lights.push_back(light);
    return scene;
}

using Defines = std::vector<std::pair<std::string, std::string>>;

// Parses `path` and compiles it whole (`technique` "") or one technique alone, sharing `cache` so that
// every stage is compiled by glslang once.
std::unique_ptr<runtime::EffectRenderer> compileAndLoad(const std::string& path, const std::string& technique,
                                                        const Defines& defines, fx::CompileCache& cache) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parseOptions;
    parseOptions.defines = defines;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, parseOptions, diagnostics);
    fx::CompileOptions options;
    options.technique = technique;
    options.cache = &cache;
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, options, diagnostics) : nullptr;
    if (!compiled || diagnostics.hasErrors()) {
        ADD_FAILURE() << path << " (technique '" << technique << "') does not compile:\n"
                      << diagnostics.str();
        return nullptr;
    }
    std::unique_ptr<runtime::EffectRenderer> renderer =
        runtime::EffectRenderer::create(compiled, diagnostics);
    if (!renderer) ADD_FAILURE() << diagnostics.str();
    return renderer;
}

std::vector<std::string> shippedEffects() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("effects")))
        if (entry.path().extension() == ".fx") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class SingleTechniqueCompile : public ::testing::TestWithParam<std::string> {};

TEST_P(SingleTechniqueCompile, EveryTechniqueRendersTheFrameTheWholeEffectRenders) {
    const std::string path = sourcePath("effects/" + GetParam() + ".fx");
    // A small map keeps each effect at a few seconds on llvmpipe; the byte comparison does not need more.
    const Defines defines = {{"SHADOWFX_SHADOW_MAP_SIZE", "256"}};
    fx::CompileCache cache;
    std::unique_ptr<runtime::EffectRenderer> whole = compileAndLoad(path, "", defines, cache);
    ASSERT_TRUE(whole);
    const runtime::Scene scene = roofScene();
    ASSERT_FALSE(whole->effect().techniques.empty());
    for (const fx::CompiledTechnique& technique : whole->effect().techniques) {
        SCOPED_TRACE("technique " + technique.name);
        ASSERT_TRUE(render(*whole, scene, kWidth, kHeight, technique.name));
        const runtime::FrameImage expected = whole->readFrame();
        EXPECT_TRUE(notConstant(expected));
        std::unique_ptr<runtime::EffectRenderer> alone = compileAndLoad(path, technique.name, defines, cache);
        ASSERT_TRUE(alone);
        ASSERT_TRUE(render(*alone, scene, kWidth, kHeight, technique.name));
        EXPECT_EQ(differingPixels(alone->readFrame(), expected), 0u)
            << "compiled alone, technique '" << technique.name << "' renders another frame";
    }
}

INSTANTIATE_TEST_SUITE_P(ShippedEffects, SingleTechniqueCompile, ::testing::ValuesIn(shippedEffects()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// The roof case: dual_depth.fx's peel_cull, compiled alone with SHADOWFX_VISIBILITY, shadows what the
// ray-cast truth shadows, the ground under the open roof included.
TEST(SingleTechniqueCompileRoof, PeelCullCompiledAloneKeepsTheOpenRoofsShadow) {
    constexpr int kRoofWidth = 320, kRoofHeight = 240;
    const SceneTruth t = computeSceneTruth(roofScene(), kRoofWidth, kRoofHeight);
    size_t shadowedReceivers = 0;
    for (size_t i = 0; i < t.receivers.size(); ++i)
        shadowedReceivers += t.receivers[i] && t.truth.visibility[i] < runtime::kShadowedBelow;
    ASSERT_GT(shadowedReceivers, 1000u) << "the scene no longer puts the roof's shadow in view";

    fx::CompileCache cache;
    for (const std::string& technique : {std::string("peel_cull"), std::string("")}) {
        SCOPED_TRACE(technique.empty() ? "whole effect" : "technique compiled alone");
        std::unique_ptr<runtime::EffectRenderer> renderer = compileAndLoad(
            sourcePath("effects/dual_depth.fx"), technique, {{"SHADOWFX_VISIBILITY", "1"}}, cache);
        ASSERT_TRUE(renderer);
        ASSERT_TRUE(render(*renderer, t.scene, kRoofWidth, kRoofHeight, "peel_cull"));
        const runtime::ShadowErrors errors = runtime::compareVisibility(
            t.truth.visibility, runtime::visibilityFromFrame(renderer->readFrame()), t.receivers);
        // Most of the truth's shadow is the roof's; losing it turns it into false light.
        EXPECT_LT(static_cast<double>(errors.falseLightPixels), 0.1 * static_cast<double>(shadowedReceivers))
            << errors.falseLightPixels << " of " << shadowedReceivers << " shadowed receiver pixels lit";
        EXPECT_LT(errors.misclassifiedPercent, 5.0);
    }
}

}  // namespace
}  // namespace shadowfx::test::test_single_technique_compile
