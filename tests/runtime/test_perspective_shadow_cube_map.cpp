// The cube-map variant of perspective shadow maps (runtime/PerspectiveShadowCubeMap.h, Kozlov 2004 §14.2.2),
// without GL: for a dense sweep of light directions, every
// receiver of B (its vertices and points between them) lands inside the clip volume of exactly the face
// that the dominant axis of its cube coordinates selects, and its casters in the same face at the same
// texel, nearer in depth; the sun in view spreads the receivers over several faces where the single-map
// PSM has faded into Focused; faces nobody uses cull every draw; spot lights keep the uniform fit.
#include "LightFitScenes.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/PerspectiveShadowCubeMap.h>
#include <runtime/PerspectiveShadowMap.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace test_perspective_shadow_cube_map {

using namespace runtime;

namespace {

using namespace shadowfx::test;  // terrain, fromAngles, finite (LightFitScenes.h)
constexpr float kAspect = kLightFitAspect;

glm::dvec4 clipOf(const LightView& face, const glm::vec3& p) {
    return glm::dmat4(face.projection) * glm::dmat4(face.view) * glm::dvec4(glm::dvec3(p), 1.0);
}

// Checks one receiver and its caster (the same point moved toward the light): both in the face the
// receiver selects, inside its clip volume, at the same texel, the caster nearer the light.
void expectInsideItsFace(const LightFit& fit, const glm::vec3& receiver, const glm::vec3& caster,
                         const std::string& what) {
    const int face = cubeFaceOf(fit, receiver);
    ASSERT_TRUE(fit.cascades[size_t(face)].serves) << what << " face " << face;
    EXPECT_EQ(cubeFaceOf(fit, caster), face) << what;
    const glm::dvec4 c = clipOf(fit.cascades[size_t(face)], receiver);
    const glm::dvec4 e = clipOf(fit.cascades[size_t(face)], caster);
    ASSERT_GT(c.w, 0.0) << what;
    // Float matrices: the selection and the window both round; the window's margin is 1e-3 of its extent.
    EXPECT_LE(std::abs(c.x), c.w * (1.0 + 1e-3)) << what << " face " << face;
    EXPECT_LE(std::abs(c.y), c.w * (1.0 + 1e-3)) << what << " face " << face;
    EXPECT_GE(c.z, -1e-5 * c.w) << what;
    EXPECT_LE(c.z, c.w * (1.0 + 1e-5)) << what;
    EXPECT_NEAR(e.w, c.w, 1e-4 * c.w) << what;
    EXPECT_NEAR(e.x / e.w, c.x / c.w, 1e-3) << what;  // float matrices: 0.2 texels of a 341-texel tile
    EXPECT_NEAR(e.y / e.w, c.y / c.w, 1e-3) << what;
    EXPECT_GE(e.z, -1e-5 * e.w) << what;
    EXPECT_LE(e.z / e.w, c.z / c.w + 1e-6) << what;
}

// The used faces' tiles lie inside the atlas without overlapping and cover it (five faces: 5 of 3 x 2
// tiles); unused faces have none.
void expectUsedFacesShareTheAtlas(const LightFit& fit, int facesUsed, const std::string& what) {
    double area = 0.0;
    for (size_t a = 0; a < fit.cascades.size(); ++a) {
        const glm::vec4 r = fit.cascades[a].atlasRect;
        if (!fit.cascades[a].serves) {
            EXPECT_EQ(r.z, 0.0f) << what;
            continue;
        }
        EXPECT_GE(r.x, 0.0f) << what;
        EXPECT_GE(r.y, 0.0f) << what;
        EXPECT_LE(r.x + r.z, 1.0f + 1e-6f) << what;
        EXPECT_LE(r.y + r.w, 1.0f + 1e-6f) << what;
        area += double(r.z) * r.w;
        for (size_t b = a + 1; b < fit.cascades.size(); ++b) {
            const glm::vec4 o = fit.cascades[b].atlasRect;
            if (!fit.cascades[b].serves) continue;
            const bool apart = r.x + r.z <= o.x + 1e-6f || o.x + o.z <= r.x + 1e-6f ||
                               r.y + r.w <= o.y + 1e-6f || o.y + o.w <= r.y + 1e-6f;
            EXPECT_TRUE(apart) << what << " faces " << a << ", " << b;
        }
    }
    EXPECT_NEAR(area, facesUsed == 5 ? 5.0 / 6.0 : 1.0, 1e-6) << what;
}

}  // namespace

// The grid of test_light_parameterizations.cpp made dense: every 10 degrees of elevation and azimuth,
// straight up and down included, for a level, a tilted and a straight-down camera.
TEST(PerspectiveShadowCubeMap, EveryReceiverLandsInsideTheFaceItSelects) {
    int fits = 0, severalFaces = 0;
    for (const glm::vec3& view :
         {fromAngles(0.0f, 0.0f), fromAngles(-30.0f, 20.0f), glm::vec3(0.0f, -1.0f, 0.0f)})
        for (float elevation = -90.0f; elevation <= 90.0f; elevation += 10.0f)
            for (float azimuth = 0.0f; azimuth < 360.0f; azimuth += 10.0f) {
                const Scene scene = terrain(view, fromAngles(elevation, azimuth));
                CubeMapDetails details;
                const LightFit fit = fitPerspectiveShadowCubeMap(scene, scene.bounds(), kAspect,
                                                                 scene.lights[0], LightTunables{}, &details);
                const std::string what = std::to_string(elevation) + "/" + std::to_string(azimuth);
                ASSERT_FALSE(details.fellBack) << what;
                ASSERT_EQ(fit.cascades.size(), size_t(kCubeFaces)) << what;
                ASSERT_TRUE(fit.cubeFaces && finite(fit.faceSelect)) << what;
                for (const LightView& face : fit.cascades)
                    ASSERT_TRUE(finite(face.view) && finite(face.projection)) << what;
                ++fits;
                severalFaces += details.facesUsed > 1 ? 1 : 0;
                expectUsedFacesShareTheAtlas(fit, details.facesUsed, what);
                const std::vector<glm::vec3> body =
                    focusBody(scene.camera, kAspect, scene.bounds(), scene.lights[0].direction);
                const size_t n = body.size() / 2;
                // B's vertices, and points between each pair of them (inside B, off its vertices: they
                // cross the faces' borders).
                for (size_t i = 0; i < n; ++i)
                    for (size_t j = i; j < n; ++j)
                        expectInsideItsFace(fit, 0.5f * (body[i] + body[j]),
                                            0.5f * (body[n + i] + body[n + j]), what);
            }
    EXPECT_EQ(fits, 3 * 19 * 36);
    EXPECT_GT(severalFaces, 0);  // the sweep does reach lights close to the receivers
}

// The sun low ahead of a level camera lies among the receivers in post-perspective space: the single-map
// PSM has faded into Focused there (Kozlov 2004 §14.2.2: "the closer the light source is to the unit cube,
// the poorer the quality"); the cube map spreads the receivers over several faces instead, each a
// perspective from L'.
TEST(PerspectiveShadowCubeMap, SunInViewUsesSeveralFacesWherePsmFades) {
    const Scene scene = terrain(fromAngles(0.0f, 0.0f), fromAngles(-10.0f, 180.0f));
    PsmDetails psm;
    fitPerspectiveShadowMap(scene, scene.bounds(), kAspect, scene.lights[0], LightTunables{}, &psm);
    EXPECT_EQ(psm.focusedWeight, 1.0);
    CubeMapDetails details;
    const LightFit fit = fitPerspectiveShadowCubeMap(scene, scene.bounds(), kAspect, scene.lights[0],
                                                     LightTunables{}, &details);
    ASSERT_FALSE(details.fellBack);
    EXPECT_GE(details.facesUsed, 4);
    // L' in the camera's view: its image lies inside the screen, beyond the far plane.
    const glm::dvec4 light = details.lightPostPerspective;
    ASSERT_GT(light.w, 0.0);
    EXPECT_LT(std::abs(light.x / light.w), 1.0);
    EXPECT_LT(std::abs(light.y / light.w), 1.0);
    EXPECT_GT(light.z / light.w, 1.0);
    for (int face = 0; face < kCubeFaces; ++face)
        EXPECT_EQ(fit.cascades[size_t(face)].serves, details.used[size_t(face)]);
}

// A face no receiver uses has serves = false and puts every vertex outside the clip volume (x > w > 0).
TEST(PerspectiveShadowCubeMap, UnusedFacesCullEveryDraw) {
    const Scene scene = terrain(fromAngles(-30.0f, 20.0f), fromAngles(-45.0f, 90.0f));
    CubeMapDetails details;
    const LightFit fit = fitPerspectiveShadowCubeMap(scene, scene.bounds(), kAspect, scene.lights[0],
                                                     LightTunables{}, &details);
    ASSERT_LT(details.facesUsed, kCubeFaces);
    int unused = 0;
    for (const LightView& face : fit.cascades) {
        if (face.serves) continue;
        ++unused;
        for (const glm::vec3& p : {glm::vec3(0.0f), glm::vec3(50.0f, 10.0f, -30.0f), glm::vec3(-1e4f)}) {
            const glm::dvec4 clip = clipOf(face, p);
            EXPECT_GT(clip.w, 0.0);
            EXPECT_GT(clip.x, clip.w);
        }
    }
    EXPECT_EQ(unused, kCubeFaces - details.facesUsed);
}

// Spot lights keep the uniform fit, in face 4, which every point selects.
TEST(PerspectiveShadowCubeMap, SpotLightsKeepTheUniformFitInOneFace) {
    Scene scene = terrain(fromAngles(-10.0f, 0.0f), fromAngles(-45.0f, 30.0f));
    scene.lights[0].type = Light::Type::Spot;
    scene.lights[0].position = {0.0f, 60.0f, -60.0f};
    const LightFit uniform =
        fitLight(LightParameterization::Uniform, scene, scene.bounds(), kAspect, scene.lights[0]);
    CubeMapDetails details;
    const LightFit fit = fitPerspectiveShadowCubeMap(scene, scene.bounds(), kAspect, scene.lights[0],
                                                     LightTunables{}, &details);
    EXPECT_TRUE(details.fellBack);
    EXPECT_EQ(details.facesUsed, 1);
    ASSERT_EQ(fit.cascades.size(), size_t(kCubeFaces));
    EXPECT_EQ(fit.cascades[4].view, uniform.view);
    EXPECT_EQ(fit.cascades[4].projection, uniform.projection);
    for (const glm::vec3& p :
         {glm::vec3(0.0f), glm::vec3(90.0f, 1.0f, 90.0f), glm::vec3(-90.0f, 29.0f, 5.0f)})
        EXPECT_EQ(cubeFaceOf(fit, p), 4);
}

// Kozlov 2004's scene (a row of boxes on both sides of the viewer, casters behind it) with a low light in
// front of the viewer, stress case behind-ordinary: every receiver of B and its casters in their face.
TEST(PerspectiveShadowCubeMap, SeedSceneWithTheLightInFront) {
    Scene scene = *makeBuiltinScene("behind");
    scene.lights[0].direction = glm::normalize(glm::vec3(0.25f, -0.35f, -1.0f));
    CubeMapDetails details;
    const LightFit fit = fitPerspectiveShadowCubeMap(scene, scene.bounds(), kAspect, scene.lights[0],
                                                     LightTunables{}, &details);
    ASSERT_FALSE(details.fellBack);
    const std::vector<glm::vec3> body =
        focusBody(scene.camera, kAspect, scene.bounds(), scene.lights[0].direction);
    const size_t n = body.size() / 2;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i; j < n; ++j)
            expectInsideItsFace(fit, 0.5f * (body[i] + body[j]), 0.5f * (body[n + i] + body[n + j]),
                                "behind");
    EXPECT_GE(details.facesUsed, 3);
}
}  // namespace test_perspective_shadow_cube_map
