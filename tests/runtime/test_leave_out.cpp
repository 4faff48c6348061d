// Leave-out (FrameOptions::leaveOut): what it leaves out must never change the image.
// - InstanceBvh queries return exactly what a brute-force test of every box returns;
// - a light's cull from kept footprints (CasterFootprints) returns what a fresh cull returns, frame after
//   frame of an orbiting camera, under directional and spot lights and after the light moved;
// - the intersection body B's light-space region contains every point of frustum ∩ bounds;
// - frames with and without leave-out are identical, byte for byte, for the thesis effect's techniques
//   (plain, PCF, jittered, hardware) and directional and spot lights, with a camera that sees part of a
//   grid of boxes, while culling really removes objects from camera and light passes;
// - a pass whose target nobody reads is left out (and the target not allocated); a light pass is reused when
// only the camera moved
//   and rerun when the light moved, every frame identical to a frame without leave-out;
// - the per-pass counts add up.
#include <private/runtime/FramePlan.h>
#include <runtime/CasterFootprints.h>
#include <runtime/InstanceBvh.h>
#include <runtime/IntersectionBody.h>
#include "LeaveOutFrames.h"
#include "effects/EffectHarness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <random>

namespace test_leave_out {

namespace {

using namespace runtime;
using shadowfx::test::loadEffect;
using shadowfx::test::notConstant;
using shadowfx::test::sourcePath;

std::vector<Aabb> randomBoxes(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> position(-50.0f, 50.0f), size(0.1f, 4.0f);
    std::vector<Aabb> boxes;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 lo(position(rng), position(rng) * 0.2f, position(rng));
        boxes.push_back({lo, lo + glm::vec3(size(rng), size(rng), size(rng))});
    }
    return boxes;
}

glm::mat4 cameraViewProjection(glm::vec3 eye, glm::vec3 target, float fovDegrees, float farPlane) {
    return glm::perspectiveLH_ZO(glm::radians(fovDegrees), 4.0f / 3.0f, 0.1f, farPlane) *
           glm::lookAtLH(eye, target, glm::vec3(0, 1, 0));
}

TEST(InstanceBvh, QueriesMatchBruteForce) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<Aabb> boxes = randomBoxes(rng, 1 + trial * 97);
        std::vector<bool> present(boxes.size(), true);
        present[0] = trial % 2 == 0;  // an object without a mesh is never reported
        const InstanceBvh bvh(boxes, present);
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        const glm::vec3 eye(unit(rng) * 60, unit(rng) * 10 + 15, unit(rng) * 60);
        const glm::mat4 viewProjection =
            cameraViewProjection(eye, glm::vec3(unit(rng) * 20, 0, unit(rng) * 20), 50.0f, 60.0f);
        const ConvexVolume frustum = frustumPlanes(viewProjection);
        const auto frustumTest = [&](const Aabb& box) { return overlapVolume(frustum, box); };

        const glm::mat4 light = glm::orthoLH_ZO(-60.0f, 60.0f, -60.0f, 60.0f, 0.0f, 200.0f) *
                                glm::lookAtLH(glm::vec3(40, 80, -30), glm::vec3(0), glm::vec3(0, 1, 0));
        const ReceiverRegion region = receiverRegion(
            intersectionBodyPoints(viewProjection, Bounds{glm::vec3(-50, -10, -50), glm::vec3(55, 15, 55)}),
            light, glm::vec2(1024), 4.0f);
        const auto casterTest = [&](const Aabb& box) { return casterReaches(region, light, box); };

        for (int which = 0; which < 2; ++which) {
            std::vector<uint32_t> found, expected;
            if (which == 0) {
                bvh.query(frustumTest, found);
            } else {
                bvh.query(casterTest, found);
            }
            for (uint32_t i = 0; i < boxes.size(); ++i) {
                const Overlap overlap = which == 0 ? frustumTest(boxes[i]) : casterTest(boxes[i]);
                if (present[i] && overlap != Overlap::Outside) expected.push_back(i);
            }
            EXPECT_EQ(found, expected) << "trial " << trial << (which == 0 ? " frustum" : " casters");
        }
    }
}

// An orbiting camera under a light that stands: the region moves every frame, the footprints are kept,
// and each frame's list is the one a fresh cull (casterReaches on every box it reaches) gives.
TEST(CasterFootprints, KeptCullEqualsFreshCullOverAMovingCamera) {
    std::mt19937 rng(31);
    std::vector<Aabb> boxes = randomBoxes(rng, 3000);
    std::vector<bool> present(boxes.size(), true);
    present[5] = false;
    const InstanceBvh bvh(boxes, present);
    const Bounds bounds{glm::vec3(-50, -10, -50), glm::vec3(55, 15, 55)};
    const glm::mat4 directional = glm::orthoLH_ZO(-80.0f, 80.0f, -80.0f, 80.0f, 0.0f, 250.0f) *
                                  glm::lookAtLH(glm::vec3(40, 80, -30), glm::vec3(0), glm::vec3(0, 1, 0));
    // A spot light inside the field: boxes behind it and across its plane.
    const glm::mat4 spot = glm::perspectiveLH_ZO(glm::radians(90.0f), 1.0f, 0.5f, 200.0f) *
                           glm::lookAtLH(glm::vec3(0, 12, 0), glm::vec3(20, 0, 5), glm::vec3(0, 1, 0));
    const glm::mat4 lights[] = {directional, spot, directional};
    CasterFootprints kept;
    uint64_t treeStamp = 1;
    int nonEmpty = 0, changed = 0;
    std::vector<uint32_t> previous;
    for (size_t l = 0; l < std::size(lights); ++l) {
        const glm::mat4& light = lights[l];
        EXPECT_FALSE(kept.holds(treeStamp, light));  // one light's footprints at a time
        kept.reset(bvh, treeStamp, light);
        for (int frame = 0; frame < 40; ++frame) {
            const float angle = glm::radians(4.0f * static_cast<float>(frame + 10 * static_cast<int>(l)));
            const glm::vec3 eye(45.0f * std::cos(angle), 12.0f, 45.0f * std::sin(angle));
            const glm::mat4 camera = cameraViewProjection(eye, glm::vec3(0, 0, 0), 50.0f, 70.0f);
            ReceiverRegion region =
                receiverRegion(intersectionBodyPoints(camera, bounds), light, glm::vec2(2048), 2.0f);
            region.castersBehindLightPlaneCastNothing = l == 1 && frame % 2 == 0;
            ASSERT_TRUE(kept.holds(treeStamp, light));
            std::vector<uint32_t> found, fresh;
            kept.query(bvh, region, found);
            bvh.query([&](const Aabb& box) { return casterReaches(region, light, box); }, fresh);
            ASSERT_EQ(found, fresh) << "light " << l << ", frame " << frame;
            nonEmpty += found.empty() ? 0 : 1;
            changed += found != previous ? 1 : 0;
            previous = found;
        }
    }
    // The region really moved the lists, and they held objects to keep.
    EXPECT_GT(nonEmpty, 100);
    EXPECT_GT(changed, 60);
    // Another tree state forgets what was kept.
    EXPECT_FALSE(kept.holds(treeStamp + 1, directional));
}

// Every point of frustum ∩ bounds projects into the receiver region; a box around such a point, or
// between it and the light, is never rejected.
TEST(IntersectionBody, RegionContainsEveryPointOfFrustumAndBounds) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const Bounds bounds{glm::vec3(-20, 0, -20), glm::vec3(20, 6, 20)};
    const glm::mat4 viewProjection = cameraViewProjection(glm::vec3(-25, 3, -25), glm::vec3(0, 0, 5), 60, 30);
    const glm::vec3 toLight = glm::normalize(glm::vec3(0.5f, 1.0f, -0.3f));
    const glm::mat4 light = glm::orthoLH_ZO(-40.0f, 40.0f, -40.0f, 40.0f, 0.0f, 120.0f) *
                            glm::lookAtLH(toLight * 60.0f, glm::vec3(0), glm::vec3(0, 1, 0));
    const std::vector<glm::vec3> body = intersectionBodyPoints(viewProjection, bounds);
    ASSERT_GE(body.size(), 4u);
    const ReceiverRegion region = receiverRegion(body, light, glm::vec2(2048), 0.0f);
    ASSERT_FALSE(region.full);
    // The region is a real restriction: it covers less than the whole map.
    EXPECT_LT((region.max.x - region.min.x) * (region.max.y - region.min.y), 4.0f * 0.8f);
    int inside = 0;
    for (int i = 0; i < 200000 && inside < 2000; ++i) {
        const glm::vec3 p =
            bounds.min + (bounds.max - bounds.min) * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        if (clip.w <= 0 || std::abs(clip.x) > clip.w || std::abs(clip.y) > clip.w || clip.z < 0 ||
            clip.z > clip.w)
            continue;
        ++inside;
        const glm::vec4 l = light * glm::vec4(p, 1.0f);
        ASSERT_GE(l.x, region.min.x - 1e-5f);
        ASSERT_LE(l.x, region.max.x + 1e-5f);
        ASSERT_GE(l.y, region.min.y - 1e-5f);
        ASSERT_LE(l.y, region.max.y + 1e-5f);
        ASSERT_LE(l.z, region.maxDepth);
        // A small caster between the receiver and the light reaches it.
        const glm::vec3 caster = p + toLight * 3.0f;
        EXPECT_NE(casterReaches(region, light, Aabb{caster - 0.01f, caster + 0.01f}), Overlap::Outside);
    }
    EXPECT_GT(inside, 500);
    // A caster far below everything the camera sees (beyond B, away from the light) casts on nothing seen.
    const glm::vec3 below = glm::vec3(0, 0, 5) - toLight * 50.0f;
    EXPECT_EQ(casterReaches(region, light, Aabb{below - 0.5f, below + 0.5f}), Overlap::Outside);
}

// A 24 x 24 grid of boxes on a plane; the camera at one corner sees part of it.
Scene gridScene(Light::Type lightType) {
    Scene scene;
    scene.name = "grid";
    auto ground = std::make_shared<const Mesh>(makePlane(60.0f, 60.0f, 4));
    auto box = std::make_shared<const Mesh>(makeBox(glm::vec3(0.8f, 2.0f, 0.8f)));
    SceneObject plane;
    plane.name = "ground";
    plane.mesh = ground;
    plane.id = 1;
    scene.objects.push_back(plane);
    for (int i = 0; i < 24; ++i) {
        for (int j = 0; j < 24; ++j) {
            SceneObject object;
            object.name = "box";
            object.mesh = box;
            object.world =
                glm::translate(glm::mat4(1.0f), glm::vec3(-27.5f + 2.4f * i, 1.0f, -27.5f + 2.4f * j));
            object.color = glm::vec3(0.3f + 0.02f * i, 0.5f, 0.3f + 0.02f * j);
            object.id = static_cast<uint32_t>(scene.objects.size() + 1);
            scene.objects.push_back(object);
        }
    }
    scene.camera.position = glm::vec3(-26.0f, 6.0f, -26.0f);
    scene.camera.target = glm::vec3(-12.0f, 0.0f, -16.0f);
    scene.camera.farPlane = 30.0f;
    Light light;
    light.type = lightType;
    if (lightType == Light::Type::Directional) {
        light.direction = glm::normalize(glm::vec3(0.6f, -0.5f, 0.45f));
    } else {
        light.position = glm::vec3(-40.0f, 25.0f, -35.0f);
        light.direction = glm::normalize(glm::vec3(0.0f) - light.position);
        light.spotAngle = glm::radians(80.0f);
    }
    scene.lights.push_back(light);
    return scene;
}

using Frame = shadowfx::test::StatsFrame;
using shadowfx::test::differingPixels;
using shadowfx::test::findPass;

Frame renderFrame(EffectRenderer& renderer, const Scene& scene, const std::string& technique, bool leaveOut) {
    return shadowfx::test::renderWithStats(renderer, scene, technique, leaveOut);
}

struct Case {
    const char* technique;
    const char* settings;  // PCF / JITTER
    Light::Type light;
};

const char* lightTypeName(Light::Type type) {
    switch (type) {
        case Light::Type::Directional:
            return "directional";
        case Light::Type::Spot:
            return "spot";
        case Light::Type::Point:
            return "point";
    }
    return "unknown";
}

// The technique, the settings on (PCF, JITTER) and the light: a test's name, the same in every build
// (GoogleTest's default would print the parameter's bytes, pointers included, into the name CTest registers).
std::string caseName(const Case& c) {
    std::string name = c.technique;
    if (std::strchr(c.settings, 'P')) name += "_PCF";
    if (std::strchr(c.settings, 'J')) name += "_JITTER";
    return name + "_" + lightTypeName(c.light);
}

void PrintTo(const Case& c, std::ostream* out) {
    *out << caseName(c);
}

class LeaveOutImage : public ::testing::TestWithParam<Case> {};

TEST_P(LeaveOutImage, IsIdenticalAndCulls) {
    const Case c = GetParam();
    auto withLeaveOut = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    auto without = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(withLeaveOut && without);
    fx::DiagnosticList diagnostics;
    for (EffectRenderer* renderer : {withLeaveOut.get(), without.get()}) {
        ASSERT_TRUE(renderer->setParameterFromText("PCF", std::strchr(c.settings, 'P') ? "true" : "false",
                                                   diagnostics));
        ASSERT_TRUE(renderer->setParameterFromText("JITTER", std::strchr(c.settings, 'J') ? "true" : "false",
                                                   diagnostics));
    }
    const Scene scene = gridScene(c.light);
    const Frame culled = renderFrame(*withLeaveOut, scene, c.technique, true);
    const Frame full = renderFrame(*without, scene, c.technique, false);
    EXPECT_TRUE(notConstant(culled.image));
    EXPECT_EQ(differingPixels(culled.image, full.image), 0u);

    const std::string lightPass =
        std::string(c.technique) == "main" ? "RenderShadowMap" : "RenderShadowDepth";
    const PassStats* camera = findPass(culled.stats, "RenderScene");
    const PassStats* light = findPass(culled.stats, lightPass);
    ASSERT_TRUE(camera && light);
    const int objects = static_cast<int>(scene.objects.size());
    EXPECT_EQ(camera->objects + camera->culled, objects);
    EXPECT_EQ(light->objects + light->culled, objects);
    EXPECT_GT(camera->culled, objects / 3) << "the camera sees part of the grid";
    EXPECT_GT(light->culled, 0) << "casters that shadow nothing in view are left out";
    EXPECT_LT(camera->objects, light->objects) << "casters outside the view still shadow what is in view";
    // Without leave-out every pass draws every object.
    EXPECT_EQ(full.stats.culled, 0);
    EXPECT_EQ(findPass(full.stats, lightPass)->objects, objects);
    EXPECT_LT(culled.stats.triangles, full.stats.triangles);
}

INSTANTIATE_TEST_SUITE_P(ThesisEffect, LeaveOutImage,
                         ::testing::Values(Case{"main", "", Light::Type::Directional},
                                           Case{"main", "P", Light::Type::Directional},
                                           Case{"main", "PJ", Light::Type::Directional},
                                           Case{"hardware", "", Light::Type::Directional},
                                           Case{"main", "P", Light::Type::Spot},
                                           Case{"hardware", "", Light::Type::Spot}),
                         [](const ::testing::TestParamInfo<Case>& info) { return caseName(info.param); });

// The light-space parameterizations (lightspace.fxh) declare the reach of their 2x2 bilinear test
// (FilterReachTexels = 2) and LiSPSM's fit says that casters behind its warp centre shadow nothing
// (LightFit::shinesIntoPositiveW): the image stays identical to the frame without leave-out, for
// directional lights and for spot lights, whose window Focused and LiSPSM crop to the receivers.
struct LightSpaceCase {
    const char* file;
    Light::Type light;
};

void PrintTo(const LightSpaceCase& c, std::ostream* out) {
    *out << c.file << " " << lightTypeName(c.light);
}

class LightSpaceLeaveOut : public ::testing::TestWithParam<LightSpaceCase> {};

TEST_P(LightSpaceLeaveOut, IsIdenticalAndCulls) {
    const auto [file, lightType] = GetParam();
    auto withLeaveOut = loadEffect(sourcePath(std::string("effects/") + file), true);
    auto without = loadEffect(sourcePath(std::string("effects/") + file), true);
    ASSERT_TRUE(withLeaveOut && without);
    const Scene scene = gridScene(lightType);
    const Frame culled = renderFrame(*withLeaveOut, scene, "bilinear", true);
    const Frame full = renderFrame(*without, scene, "bilinear", false);
    EXPECT_TRUE(notConstant(culled.image));
    EXPECT_EQ(differingPixels(culled.image, full.image), 0u);
    const PassStats* light = findPass(culled.stats, "RenderShadowMap");
    ASSERT_TRUE(light);
    EXPECT_GT(light->culled, static_cast<int>(scene.objects.size()) / 4);
}

INSTANTIATE_TEST_SUITE_P(Effects, LightSpaceLeaveOut,
                         ::testing::Values(LightSpaceCase{"focused.fx", Light::Type::Directional},
                                           LightSpaceCase{"lispsm.fx", Light::Type::Directional},
                                           LightSpaceCase{"focused.fx", Light::Type::Spot},
                                           LightSpaceCase{"lispsm.fx", Light::Type::Spot}),
                         [](const ::testing::TestParamInfo<LightSpaceCase>& info) {
                             std::string name = info.param.file;
                             return name.substr(0, name.size() - 3) + "_" + lightTypeName(info.param.light);
                         });

// A map read by a wide filter declares its reach (`float FilterReachTexels` on the light pass: PCSS's
// blocker search and penumbra, up to 65 texels), and light-pass culling keeps every caster within it: the
// image stays identical, with more casters drawn than under the thesis effect's 8-texel default.
TEST(LeaveOut, WideFiltersKeepTheCastersTheyReach) {
    auto pcss = loadEffect(sourcePath("effects/pcss.fx"), true);
    auto pcssFull = loadEffect(sourcePath("effects/pcss.fx"), true);
    auto thesis = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(pcss && pcssFull && thesis);
    Scene scene = gridScene(Light::Type::Directional);
    scene.lights[0].areaRadius = 0.5f;  // a real penumbra for LightAreaRadius
    const Frame culled = renderFrame(*pcss, scene, "pcss", true);
    const Frame full = renderFrame(*pcssFull, scene, "pcss", false);
    EXPECT_TRUE(notConstant(culled.image));
    EXPECT_EQ(differingPixels(culled.image, full.image), 0u);
    const Frame narrow = renderFrame(*thesis, scene, "main", true);
    const PassStats* wide = findPass(culled.stats, "RenderShadowMap");
    const PassStats* standard = findPass(narrow.stats, "RenderShadowMap");
    ASSERT_TRUE(wide && standard);
    EXPECT_GT(wide->objects, standard->objects);
    EXPECT_GT(wide->culled, 0) << "casters beyond the reach are still left out";
}

// The shadow map is reused while only the camera moves, rerun when the light, an object or a parameter
// the light pass reads changes, and every frame equals the frame without leave-out.
class ShadowMapCache : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadowMapCache, ReusedOnlyWhileUnchanged) {
    const std::string technique = GetParam();
    const std::string mapPass = technique == "main" ? "RenderShadowMap" : "RenderShadowDepth";
    auto withLeaveOut = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    auto without = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(withLeaveOut && without);
    Scene scene = gridScene(Light::Type::Directional);
    const auto step = [&](const char* what) {
        const Frame culled = renderFrame(*withLeaveOut, scene, technique, true);
        const Frame full = renderFrame(*without, scene, technique, false);
        EXPECT_EQ(differingPixels(culled.image, full.image), 0u) << what;
        return culled;
    };
    const auto mapState = [&](const Frame& frame) { return findPass(frame.stats, mapPass)->leftOut; };
    Frame first = step("first frame");
    EXPECT_EQ(mapState(first), "");

    Frame same = step("same frame again");
    EXPECT_EQ(mapState(same), "cached");
    EXPECT_EQ(findPass(same.stats, mapPass)->draws, 0);
    EXPECT_EQ(findPass(same.stats, "RenderScene")->leftOut, "");
    const int lightPasses = technique == "main" ? 2 : 1;  // main clears the map in a pass of its own
    EXPECT_EQ(same.stats.passesLeftOut, lightPasses);
    EXPECT_EQ(same.stats.passesRun, 1);

    // The camera turns to receivers outside the first frame's region: the map is redrawn once, for the
    // whole light frustum, and then serves every viewpoint.
    scene.camera.target = glm::vec3(10.0f, 0.0f, 20.0f);
    Frame turned = step("camera turned");
    EXPECT_EQ(mapState(turned), "");
    scene.camera.position = glm::vec3(20.0f, 8.0f, -20.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    Frame moved = step("camera moved");
    EXPECT_EQ(mapState(moved), "cached");

    scene.lights[0].direction = glm::normalize(glm::vec3(-0.5f, -0.6f, 0.4f));
    EXPECT_EQ(mapState(step("light moved")), "");

    scene.objects[5].world = glm::translate(scene.objects[5].world, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(mapState(step("object moved")), "");
    EXPECT_EQ(mapState(step("nothing moved")), "cached");

    // Bias is read by the scene pass only: the map stays.
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(withLeaveOut->setParameterFromText("Bias", "0.01", diagnostics));
    ASSERT_TRUE(without->setParameterFromText("Bias", "0.01", diagnostics));
    EXPECT_EQ(mapState(step("a parameter only the scene pass reads changed")), "cached");
}

INSTANTIATE_TEST_SUITE_P(ThesisEffect, ShadowMapCache, ::testing::Values("main", "hardware"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string(info.param);
                         });

// The thesis effect's map pass binds a depth target with ZEnable = false (BlendOp=min keeps the nearest
// depth): its draws neither test nor write depth, so the clear of that target is dead and the target is
// never allocated; the hardware technique, which tests depth, keeps both.
TEST(DeadWork, DepthTargetWithoutDepthTestIsNotCleared) {
    auto renderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(renderer);
    const Scene scene = gridScene(Light::Type::Directional);
    const Frame main = renderFrame(*renderer, scene, "main", true);
    ASSERT_TRUE(findPass(main.stats, "ClearShadowMap"));
    EXPECT_EQ(findPass(main.stats, "ClearShadowMap")->clears, 1);
    EXPECT_FALSE(renderer->readTarget("ShadDepthTarget", nullptr, nullptr, nullptr));
    EXPECT_EQ(differingPixels(main.image, renderFrame(*renderer, scene, "main", false).image), 0u);
    EXPECT_TRUE(notConstant(main.image));

    renderFrame(*renderer, scene, "hardware", true);
    EXPECT_TRUE(renderer->readTarget("ShadDepthTarget", nullptr, nullptr, nullptr));
}

// FrameOptions::reuseTargets off (what `bench` times as a technique's full cost): the same static frame
// again redraws the map, so every pass of the technique runs, culling still applies, and the image is the
// one reuse gives.
TEST(ShadowMapCache, WithoutReuseEveryPassRunsEveryFrame) {
    auto renderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(renderer);
    const Scene scene = gridScene(Light::Type::Directional);
    const size_t passes = renderer->effect().techniques[0].passes.size();
    ASSERT_EQ(renderer->effect().techniques[0].name, "main");
    const auto render = [&](bool reuse) {
        FrameOptions options;
        options.width = 320;
        options.height = 240;
        options.technique = "main";
        options.reuseTargets = reuse;
        fx::DiagnosticList diagnostics;
        Frame frame;
        EXPECT_TRUE(renderer->render(scene, options, diagnostics, &frame.stats)) << diagnostics.str();
        frame.image = renderer->readFrame();
        return frame;
    };
    const Frame first = render(true);
    const Frame steady = render(true);
    EXPECT_EQ(findPass(steady.stats, "RenderShadowMap")->leftOut, "cached");
    for (int i = 0; i < 2; ++i) {
        const Frame full = render(false);
        EXPECT_EQ(full.stats.passesRun, static_cast<int>(passes));
        EXPECT_EQ(full.stats.passesLeftOut, 0);
        EXPECT_GT(full.stats.objects, steady.stats.objects);
        EXPECT_GT(full.stats.culled, 0) << "culling is not reuse: it stays";
        EXPECT_EQ(differingPixels(full.image, steady.image), 0u);
        EXPECT_TRUE(notConstant(full.image));
    }
    // A full-cost frame leaves the map it drew behind: the next frame with reuse keeps it.
    EXPECT_EQ(findPass(render(true).stats, "RenderShadowMap")->leftOut, "cached");
    EXPECT_EQ(differingPixels(first.image, steady.image), 0u);
}

// A pass that renders into a target nobody samples, and a clear of a second, unread target.
constexpr const char* kDeadPassEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float3 Color : Diffuse;
texture Unread : RENDERCOLORTARGET < float2 Dimensions = {64, 64}; string Format = "A8R8G8B8"; >;
struct VsOut { float4 position : POSITION; };
VsOut Vs(float4 position : POSITION) { VsOut o; o.position = mul(float4(position.xyz, 1), WorldViewProjection); return o; }
float4 Ps() : COLOR { return float4(Color, 1); }
technique t < string Script = "Pass=Scratch; Pass=Scene;"; > {
    pass Scratch < string Script = "RenderColorTarget0=Unread; RenderDepthStencilTarget=; Clear=Color; Draw=Geometry;"; > {
        VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps();
    }
    pass Scene < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Clear=Color; Clear=Depth; Draw=Geometry;"; > {
        ZEnable = true; ZWriteEnable = true;
        VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps();
    }
}
)";

TEST(LeaveOut, PassWhoseTargetNobodyReadsIsSkipped) {
    auto withLeaveOut = loadEffect(kDeadPassEffect, false, "dead_pass.fx");
    auto without = loadEffect(kDeadPassEffect, false, "dead_pass.fx");
    ASSERT_TRUE(withLeaveOut && without);
    const Scene scene = gridScene(Light::Type::Directional);
    const Frame culled = renderFrame(*withLeaveOut, scene, "", true);
    const Frame full = renderFrame(*without, scene, "", false);
    EXPECT_TRUE(notConstant(culled.image));
    EXPECT_EQ(differingPixels(culled.image, full.image), 0u);
    EXPECT_EQ(findPass(culled.stats, "Scratch")->leftOut, "dead");
    EXPECT_EQ(findPass(culled.stats, "Scratch")->draws, 0);
    EXPECT_EQ(findPass(culled.stats, "Scene")->leftOut, "");
    EXPECT_EQ(findPass(full.stats, "Scratch")->leftOut, "");
    EXPECT_EQ(findPass(full.stats, "Scratch")->objects, static_cast<int>(scene.objects.size()));
    EXPECT_EQ(culled.stats.passesLeftOut, 1);
    EXPECT_EQ(culled.stats.passesRun, 1);
    // Nothing that runs uses the target: it is not even allocated.
    EXPECT_FALSE(withLeaveOut->readTarget("Unread", nullptr, nullptr, nullptr).has_value());
    EXPECT_TRUE(without->readTarget("Unread", nullptr, nullptr, nullptr).has_value());
}

// Totals are the sums of the per-pass records; triangles are the drawn meshes'; texels written count
// clears and fragments.
TEST(LeaveOut, StatsAddUp) {
    auto renderer = loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(renderer);
    const Scene scene = gridScene(Light::Type::Directional);
    for (const bool leaveOut : {true, false}) {
        const Frame frame = renderFrame(*renderer, scene, "hardware", leaveOut);
        int draws = 0, objects = 0, culled = 0, clears = 0;
        uint64_t triangles = 0;
        for (const PassStats& pass : frame.stats.passes) {
            draws += pass.draws;
            objects += pass.objects;
            culled += pass.culled;
            clears += pass.clears;
            triangles += pass.triangles;
            EXPECT_GT(pass.texelsWritten, 0u) << pass.pass;
        }
        EXPECT_EQ(draws, frame.stats.draws);
        EXPECT_EQ(objects, frame.stats.objects);
        EXPECT_EQ(culled, frame.stats.culled);
        EXPECT_EQ(clears, frame.stats.clears);
        EXPECT_EQ(triangles, frame.stats.triangles);
        // Every object but the ground is the same box: the triangles are the drawn boxes' and grounds'.
        const uint64_t boxTriangles = scene.objects[1].mesh->triangleCount();
        const uint64_t groundTriangles = scene.objects[0].mesh->triangleCount();
        EXPECT_EQ((triangles - 2 * groundTriangles) % boxTriangles, 0u) << "both passes draw the ground";
        EXPECT_EQ(frame.stats.passesRun + frame.stats.passesLeftOut,
                  static_cast<int>(frame.stats.passes.size()));
        const PassStats* scenePass = findPass(frame.stats, "RenderScene");
        ASSERT_TRUE(scenePass);
        EXPECT_GE(scenePass->texelsWritten, 2u * 320 * 240) << "colour and depth cleared";
    }
}

}  // namespace

// Scene-driven choices: a pass annotated LeaveOutWhen = "NoClosedObjects" runs only where some mesh is
// closed, and the SceneHasClosedObjects / LightAreaRadius semantics tell the shaders the same.
constexpr const char* kSceneDrivenEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
bool HasClosed : SceneHasClosedObjects;
float AreaRadius : LightAreaRadius;
struct VsOut { float4 position : POSITION; };
VsOut Vs(float4 position : POSITION) { VsOut o; o.position = mul(float4(position.xyz, 1), WorldViewProjection); return o; }
float4 Ps() : COLOR { return float4(HasClosed ? 0 : 1, HasClosed ? 1 : 0, AreaRadius * 10, 1); }
float4 Blue() : COLOR { return float4(0, 0, 1, 1); }
technique t < string Script = "Pass=Scene; Pass=SecondLayer;"; > {
    pass Scene < string Script = "Clear=Color; Clear=Depth; Draw=Geometry;"; > {
        ZEnable = true; ZWriteEnable = true;
        VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps();
    }
    pass SecondLayer < string Script = "Draw=Geometry;"; string LeaveOutWhen = "NoClosedObjects"; > {
        ZEnable = true; ZFunc = LessEqual;
        VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Blue();
    }
}
)";

TEST(LeaveOut, SceneDrivenChoices) {
    auto renderer = loadEffect(kSceneDrivenEffect, false, "scene_driven.fx");
    ASSERT_TRUE(renderer);
    Scene closed = gridScene(Light::Type::Directional);
    closed.lights[0].areaRadius = 0.05f;
    Scene open = closed;
    open.objects.resize(1);  // the ground plane only: not closed
    const FrameImage* image = nullptr;

    const Frame withBoxes = renderFrame(*renderer, closed, "", true);
    EXPECT_EQ(findPass(withBoxes.stats, "SecondLayer")->leftOut, "");
    image = &withBoxes.image;
    const uint8_t* centre = image->pixel(image->width / 2, image->height * 3 / 4);
    EXPECT_EQ(centre[2], 255) << "the second pass drew over the first";

    const Frame planeOnly = renderFrame(*renderer, open, "", true);
    EXPECT_EQ(findPass(planeOnly.stats, "SecondLayer")->leftOut, "scene");
    image = &planeOnly.image;
    centre = image->pixel(image->width / 2, image->height * 3 / 4);
    EXPECT_EQ(centre[0], 255) << "SceneHasClosedObjects is false: red";
    EXPECT_EQ(centre[1], 0);
    EXPECT_NEAR(centre[2], 0.5 * 255, 1.5) << "LightAreaRadius 0.05 x 10";

    // Without leave-out the pass runs whatever the scene.
    const Frame full = renderFrame(*renderer, open, "", false);
    EXPECT_EQ(findPass(full.stats, "SecondLayer")->leftOut, "");
}

// A camera-port pass that projects with the light's matrices (no RenderPort) draws the light's view: the
// camera's frustum says nothing about it, so it is not culled, and the image stays the same.
constexpr const char* kLightViewFromCameraPort = R"(
float4x4 World : World;
float4x4 LightView : View < string frustum = "light0"; >;
float4x4 LightProjection : Projection < string frustum = "light0"; >;
float3 Color : Diffuse;
struct VsOut { float4 position : POSITION; };
VsOut Vs(float4 position : POSITION) {
    VsOut o; o.position = mul(mul(mul(float4(position.xyz, 1), World), LightView), LightProjection); return o;
}
float4 Ps() : COLOR { return float4(Color, 1); }
technique t { pass p < string Script = "Clear=Color; Clear=Depth; Draw=Geometry;"; > {
    ZEnable = true; ZWriteEnable = true;
    VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps();
} }
)";

TEST(LeaveOut, PassProjectingWithOtherMatricesIsNotCulled) {
    auto withLeaveOut = loadEffect(kLightViewFromCameraPort, false, "light_view.fx");
    auto without = loadEffect(kLightViewFromCameraPort, false, "light_view.fx");
    ASSERT_TRUE(withLeaveOut && without);
    const Scene scene = gridScene(Light::Type::Directional);
    const Frame culled = renderFrame(*withLeaveOut, scene, "", true);
    const Frame full = renderFrame(*without, scene, "", false);
    EXPECT_TRUE(notConstant(culled.image));
    EXPECT_EQ(differingPixels(culled.image, full.image), 0u);
    EXPECT_EQ(culled.stats.culled, 0);
}
}  // namespace test_leave_out
