// izb.fx, the irregular z-buffer (Johnson, Mark & Burns 2005), against the ray-cast truth where a shadow
// map's samples fail: thin poles and a wire under a low sun, whose shadows on the ground are a few pixels
// wide and run far across it. The thesis's plain shadow map at the same map size (256²) finds a third of
// the truly shadowed pixels and shadows much of the lit ground under so low a sun (measured: 300 of 853
// found, 30.2 % misclassified); the irregular z-buffer tests every camera pixel against the casters'
// triangles themselves (853 of 853, 0.000 %). A blank or constant frame finds none. The frames are drawn
// with leave-out on, as an application draws them: the passes that write only the lists' buffers must run.
#include "VisibilityHarness.h"

#include <glm/gtc/matrix_transform.hpp>

namespace shadowfx::test::test_exact_shadows {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

// A 40 m ground seen from 3 m up; four poles 5 cm thick and a 2 cm wire between two of them, under a sun
// 12 degrees above the horizon that throws their shadows toward the camera.
runtime::Scene thinCastersUnderALowSun() {
    runtime::Scene scene;
    scene.name = "thin-casters-low-sun";
    runtime::SceneObject ground;
    ground.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(40.0f, 40.0f));
    ground.id = 1;
    scene.objects.push_back(ground);
    const auto pole = std::make_shared<runtime::Mesh>(runtime::makeBox(glm::vec3(0.05f, 3.0f, 0.05f)));
    uint32_t id = 2;
    for (int k = 0; k < 4; ++k) {
        runtime::SceneObject object;
        object.mesh = pole;
        object.world = glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f + 2.0f * static_cast<float>(k), 1.5f,
                                                                 8.0f + 1.5f * static_cast<float>(k)));
        object.id = id++;
        scene.objects.push_back(object);
    }
    runtime::SceneObject wire;
    wire.mesh = std::make_shared<runtime::Mesh>(runtime::makeBox(glm::vec3(2.0f, 0.02f, 0.02f)));
    wire.world = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f, 2.9f, 8.75f)),
                             std::atan2(-1.5f, 2.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    wire.world = glm::scale(wire.world, glm::vec3(1.25f, 1.0f, 1.0f));
    wire.id = id++;
    scene.objects.push_back(wire);
    scene.camera.position = {0.0f, 3.0f, -2.0f};
    scene.camera.target = {0.0f, 0.0f, 8.0f};
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 100.0f;
    runtime::Light sun;
    const float elevation = glm::radians(12.0f);
    sun.direction = glm::normalize(glm::vec3(0.3f, -std::sin(elevation), -std::cos(elevation)));
    scene.lights.push_back(sun);
    return scene;
}

struct Score {
    double misclassifiedPercent = 0.0;
    size_t found = 0;  // truly shadowed receivers the effect shadows too
};

Score score(const std::string& effect, const std::string& technique, const SceneTruth& t) {
    auto renderer = loadVisibilityEffect(effect, {{"SHADOWFX_SHADOW_MAP_SIZE", "256"}});
    if (!renderer) return {};
    EXPECT_TRUE(render(*renderer, t.scene, kWidth, kHeight, technique));
    const std::vector<float> visibility = runtime::visibilityFromFrame(renderer->readFrame());
    const runtime::ShadowErrors errors =
        runtime::compareVisibility(t.truth.visibility, visibility, t.receivers);
    Score s;
    s.misclassifiedPercent = errors.misclassifiedPercent;
    for (size_t i = 0; i < t.receivers.size(); ++i)
        s.found += t.receivers[i] && t.truth.visibility[i] < runtime::kShadowedBelow &&
                   visibility[i] < runtime::kShadowedBelow;
    return s;
}

TEST(ExactShadows, ThinCastersAtAGrazingSunAreExactWhereAShadowMapBreaksThem) {
    const SceneTruth t = computeSceneTruth(thinCastersUnderALowSun(), kWidth, kHeight);
    size_t shadowed = 0;
    for (size_t i = 0; i < t.receivers.size(); ++i)
        shadowed += t.receivers[i] && t.truth.visibility[i] < runtime::kShadowedBelow;
    ASSERT_GT(shadowed, 500u);

    const Score exact = score("effects/izb.fx", "exact", t);
    const Score map = score("effects/thesis_fxcomposer.fx", "main", t);
    RecordProperty("izb_misclassified_percent", std::to_string(exact.misclassifiedPercent));
    RecordProperty("thesis_misclassified_percent", std::to_string(map.misclassifiedPercent));
    RecordProperty("izb_shadowed_found", std::to_string(exact.found) + " of " + std::to_string(shadowed));
    RecordProperty("thesis_shadowed_found", std::to_string(map.found) + " of " + std::to_string(shadowed));
    EXPECT_LT(exact.misclassifiedPercent, 0.1 * map.misclassifiedPercent);
    EXPECT_LT(exact.misclassifiedPercent, 0.05);
    EXPECT_GT(static_cast<double>(exact.found), 0.99 * static_cast<double>(shadowed));
}

// A roof that is an open plane turned upside down (its back toward the sun) and a closed box, above a
// ground under a high sun. izb.fx culls the triangles of closed meshes that face away from the light in
// its Occlude pass (the light-facing ones cast the same shadow) and draws open meshes whole: a roof culled
// as the box is would cast nothing, and its shadow is most of the truly shadowed ground.
runtime::Scene anUpsideDownRoofAndABox() {
    runtime::Scene scene;
    scene.name = "upside-down-roof-and-box";
    runtime::SceneObject ground;
    ground.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(30.0f, 30.0f));
    ground.id = 1;
    scene.objects.push_back(ground);
    runtime::SceneObject roof;
    roof.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(4.0f, 4.0f));
    roof.world = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-2.5f, 2.0f, 8.0f)),
                             glm::radians(180.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    roof.id = 2;
    scene.objects.push_back(roof);
    runtime::SceneObject box;
    box.mesh = std::make_shared<runtime::Mesh>(runtime::makeBox(glm::vec3(1.0f, 2.0f, 1.0f)));
    box.world = glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, 1.0f, 8.0f));
    box.id = 3;
    scene.objects.push_back(box);
    scene.camera.position = {0.0f, 6.0f, -2.0f};
    scene.camera.target = {0.0f, 0.0f, 8.0f};
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 100.0f;
    runtime::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.3f));
    scene.lights.push_back(sun);
    return scene;
}

TEST(ExactShadows, AnOpenCasterShadowsWhicheverSideFacesTheLightWhereClosedOnesAreCulled) {
    const runtime::Scene scene = anUpsideDownRoofAndABox();
    ASSERT_FALSE(scene.objects[1].mesh->closed);
    ASSERT_TRUE(scene.objects[2].mesh->closed);
    const SceneTruth t = computeSceneTruth(scene, kWidth, kHeight);
    size_t shadowed = 0;
    for (size_t i = 0; i < t.receivers.size(); ++i)
        shadowed += t.receivers[i] && t.truth.visibility[i] < runtime::kShadowedBelow;
    ASSERT_GT(shadowed, 2000u);

    const Score exact = score("effects/izb.fx", "exact", t);
    RecordProperty("izb_misclassified_percent", std::to_string(exact.misclassifiedPercent));
    RecordProperty("izb_shadowed_found", std::to_string(exact.found) + " of " + std::to_string(shadowed));
    EXPECT_LT(exact.misclassifiedPercent, 0.05);
    EXPECT_GT(static_cast<double>(exact.found), 0.99 * static_cast<double>(shadowed));
}

}  // namespace
}  // namespace shadowfx::test::test_exact_shadows
