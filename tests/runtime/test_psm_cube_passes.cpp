// psm_cube.fx in the runtime (docs/techniques/light-space-parameterizations.md): its six face passes render
// through RenderPort=light0.faceK; a face that no receiver uses is left out ("scene") and the frame is the
// one every pass drawn in full gives; with the light low in front of the viewer (Kozlov 2004's problem case)
// several faces run.
#include <runtime/BuiltinScenes.h>
#include <runtime/PerspectiveShadowCubeMap.h>

#include "LeaveOutFrames.h"
#include "effects/EffectHarness.h"

#include <algorithm>
#include <cstring>

namespace test_psm_cube_passes {

namespace {

using namespace runtime;
using shadowfx::test::loadEffect;
using shadowfx::test::notConstant;
using shadowfx::test::sourcePath;

using Frame = shadowfx::test::StatsFrame;

Frame render(EffectRenderer& renderer, const Scene& scene, bool leaveOut) {
    return shadowfx::test::renderWithStats(renderer, scene, "", leaveOut);
}

int facesLeftOut(const FrameStats& stats) {
    int count = 0;
    for (const PassStats& pass : stats.passes)
        if (pass.pass.rfind("Face", 0) == 0 && pass.leftOut == "scene") ++count;
    return count;
}

void expectSameFrameWithAndWithoutLeaveOut(const Scene& scene, int facesUsed) {
    auto withLeaveOut = loadEffect(sourcePath("effects/psm_cube.fx"), true);
    auto without = loadEffect(sourcePath("effects/psm_cube.fx"), true);
    ASSERT_TRUE(withLeaveOut && without);
    const Frame lean = render(*withLeaveOut, scene, true);
    const Frame full = render(*without, scene, false);
    EXPECT_TRUE(notConstant(lean.image));
    ASSERT_EQ(lean.image.rgba.size(), full.image.rgba.size());
    EXPECT_EQ(std::memcmp(lean.image.rgba.data(), full.image.rgba.data(), lean.image.rgba.size()), 0);
    EXPECT_EQ(facesLeftOut(lean.stats), kCubeFaces - facesUsed);
    EXPECT_EQ(facesLeftOut(full.stats), 0);
    EXPECT_LT(lean.stats.objects, full.stats.objects);
}

}  // namespace

// The teapot under its own light: the light is far from the receivers in post-perspective space and one
// face holds them all; the other five passes are left out.
TEST(PsmCube, FacesWithoutReceiversAreLeftOut) {
    const Scene scene = *makeBuiltinScene("teapot");
    CubeMapDetails details;
    fitPerspectiveShadowCubeMap(scene, scene.bounds(), 320.0f / 240.0f, scene.lights[0], LightTunables{},
                                &details);
    ASSERT_FALSE(details.fellBack);
    ASSERT_LT(details.facesUsed, kCubeFaces);
    expectSameFrameWithAndWithoutLeaveOut(scene, details.facesUsed);
}

// Kozlov 2004's scene with a low light in front of the viewer: its image lies among the receivers in
// post-perspective space, and the receivers spread over several faces, which all run.
TEST(PsmCube, LightInFrontOfTheViewerUsesSeveralFaces) {
    Scene scene = *makeBuiltinScene("behind");
    scene.lights[0].direction = glm::normalize(glm::vec3(0.25f, -0.35f, -1.0f));
    CubeMapDetails details;
    fitPerspectiveShadowCubeMap(scene, scene.bounds(), 320.0f / 240.0f, scene.lights[0], LightTunables{},
                                &details);
    ASSERT_GE(details.facesUsed, 3);
    expectSameFrameWithAndWithoutLeaveOut(scene, details.facesUsed);
}

// With the camera and light still, the cube map is reused from the previous frame: the faces left out as
// "scene" between the atlas's clear and its one running face do not read the atlas, so they do not spoil it.
TEST(PsmCube, AStillFrameReusesTheCubeMap) {
    const Scene scene = *makeBuiltinScene("teapot");
    auto effect = loadEffect(sourcePath("effects/psm_cube.fx"), true);
    ASSERT_TRUE(effect);
    const Frame first = render(*effect, scene, true);
    const Frame second = render(*effect, scene, true);
    for (const char* pass : {"ClearAtlas", "Face4"}) {
        const auto found = std::find_if(second.stats.passes.begin(), second.stats.passes.end(),
                                        [&](const PassStats& p) { return p.pass == pass; });
        ASSERT_NE(found, second.stats.passes.end()) << pass;
        EXPECT_EQ(found->leftOut, "cached") << pass;
    }
    ASSERT_EQ(first.image.rgba.size(), second.image.rgba.size());
    EXPECT_EQ(std::memcmp(first.image.rgba.data(), second.image.rgba.data(), first.image.rgba.size()), 0);
}
}  // namespace test_psm_cube_passes
