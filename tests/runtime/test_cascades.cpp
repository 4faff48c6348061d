// Cascaded shadow maps in the runtime (docs/techniques/light-space-parameterizations.md):
// - RenderPort=light0.cascadeK renders into tile K of the bound atlas only, with light0's annotated
//   matrices bound to cascade K's (the CascadeViewProjection semantic's element K), and a Clear under it
//   clears that tile only;
// - a cascade whose depth slice holds no object is left out (scene), the frame identical to one without
//   leave-out;
// - on a field of thousands of posts, every caster drawn into every cascade (leave-out off) gives the frame
//   leave-out gives;
// - a RenderPort naming a cascade the light does not have, or a malformed one, is a file:line:column error.
#include <runtime/CascadedShadowMaps.h>

#include "LeaveOutFrames.h"
#include "effects/EffectHarness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace test_cascades {

namespace {

using namespace runtime;
using shadowfx::test::loadEffect;
using shadowfx::test::notConstant;
using shadowfx::test::sourcePath;

// A ground plane and a box in front of the camera, and a box far away to the side, outside the view: it
// stretches the split range (the far end is the farthest corner of the scene's bounds), so the far
// cascades' slices hold no object.
Scene sceneWithEmptyFarSlices() {
    Scene scene;
    scene.name = "far-slices";
    auto ground = std::make_shared<const Mesh>(makePlane(20.0f, 20.0f, 2));
    auto box = std::make_shared<const Mesh>(makeBox(glm::vec3(2.0f)));
    const auto add = [&](const std::shared_ptr<const Mesh>& mesh, glm::vec3 at) {
        SceneObject object;
        object.name = "object" + std::to_string(scene.objects.size());
        object.mesh = mesh;
        object.world = glm::translate(glm::mat4(1.0f), at);
        object.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(object);
    };
    add(ground, glm::vec3(0.0f));
    add(box, glm::vec3(0.0f, 1.0f, 0.0f));
    add(box, glm::vec3(150.0f, 1.0f, 100.0f));
    scene.camera.position = glm::vec3(0.0f, 4.0f, -10.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    scene.camera.farPlane = 300.0f;
    Light light;
    light.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    scene.lights.push_back(light);
    return scene;
}

// Each pass writes K + 1 where its port's light0 ViewProjection equals CascadeViewProjection[K], else -1.
const char* kTileEffect = R"(
float4x4 LightView : View < string frustum = "light0"; string Parameterization = "Cascaded"; >;
float4x4 PortViewProjection : ViewProjection < string frustum = "light0"; >;
float4x4 Cascades[4] : CascadeViewProjection < string frustum = "light0"; >;
float Zero = 0;
float Nine = 9;
texture Atlas : RENDERCOLORTARGET < float2 Dimensions = {64, 64}; string Format = "R32F"; >;
texture AtlasDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 64}; string Format = "D24S8"; >;
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 Mark(uniform int k) : COLOR
{
    float d = 0;
    for (int r = 0; r < 4; ++r) d += dot(abs(PortViewProjection[r] - Cascades[k][r]), 1);
    return d < 1e-4 ? k + 1 : -1;
}
technique t < string Script = "RenderColorTarget0=Atlas; RenderDepthStencilTarget=AtlasDepth;"
                              "RenderPort=light0; ClearSetColor=Zero; Clear=Color;"
                              "RenderPort=light0.cascade0; Pass=p0; RenderPort=light0.cascade2; Pass=p2;"
                              "RenderPort=light0.cascade3; ClearSetColor=Nine; Clear=Color;"
                              "RenderColorTarget0=; RenderDepthStencilTarget=; RenderPort=;"; >
{
    pass p0 < string Script = "Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 Mark(0); }
    pass p2 < string Script = "Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 Mark(2); }
}
)";

TEST(Cascades, RenderPortWritesOnlyItsTileWithItsMatrices) {
    auto renderer = loadEffect(kTileEffect, false, "tiles.fx");
    ASSERT_TRUE(renderer);
    const Scene scene = sceneWithEmptyFarSlices();
    FrameOptions options;
    options.width = 64;
    options.height = 64;
    options.outputTargets = {"Atlas"};
    // The cascades really differ, so matching element K identifies cascade K.
    const std::optional<LightFit> fit = renderer->lightFit(scene, "light0", options);
    ASSERT_TRUE(fit && fit->cascades.size() == 4u);
    EXPECT_NE(fit->cascades[0].projection, fit->cascades[2].projection);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->render(scene, options, diagnostics)) << diagnostics.str();
    ASSERT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    int width = 0, height = 0, channels = 0;
    const auto atlas = renderer->readTarget("Atlas", &width, &height, &channels);
    ASSERT_TRUE(atlas && width == 64 && height == 64);
    // Tiles of a 2 x 2 grid, row 0 first: 0 drawn (1), 1 untouched (0), 2 drawn (3), 3 cleared (9).
    const float expected[4] = {1.0f, 0.0f, 3.0f, 9.0f};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int tile = (y / 32) * 2 + x / 32;
            ASSERT_EQ((*atlas)[size_t((y * width + x) * channels)], expected[tile]) << x << ", " << y;
        }
}

// CascadeAtlasRects and CascadeSplitDepths bind each cascade's tile and the view depth where it ends: a
// pass writes them into a 4 x 2 target (row 0: rect k at x = k; row 1: the split components), compared
// with the provider's fit and atlas layout. Three cascades: the fourth element repeats the third.
TEST(Cascades, SemanticsBindTilesAndSplits) {
    auto renderer = loadEffect(R"(
float4x4 LightView : View < string frustum = "light0"; string Parameterization = "Cascaded"; >;
int Count : CascadeCount = 3;
float4 Rects[4] : CascadeAtlasRects < string frustum = "light0"; >;
float4 Splits : CascadeSplitDepths < string frustum = "light0"; >;
float2 Size : ViewportPixelSize;
texture Out : RENDERCOLORTARGET < float2 Dimensions = {4, 2}; string Format = "A32B32G32R32F"; >;
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 Write(float4 pixel : VPOS) : COLOR
{
    int k = int(pixel.x);
    return pixel.y < 1 ? Rects[k] : float4(Splits[k], 0, 0, 1);
}
technique t < string Script = "RenderColorTarget0=Out; Pass=p; RenderColorTarget0=;"; >
{
    pass p < string Script = "Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 Write(); }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    const Scene scene = sceneWithEmptyFarSlices();
    FrameOptions options;
    options.width = 4;
    options.height = 2;
    options.outputTargets = {"Out"};
    const std::optional<LightFit> fit = renderer->lightFit(scene, "light0", options);
    ASSERT_TRUE(fit && fit->cascades.size() == 3u);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->render(scene, options, diagnostics)) << diagnostics.str();
    ASSERT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    int width = 0, height = 0, channels = 0;
    const auto out = renderer->readTarget("Out", &width, &height, &channels);
    ASSERT_TRUE(out && width == 4 && height == 2 && channels == 4);
    for (int k = 0; k < 4; ++k) {
        const int cascade = std::min(k, 2);
        const glm::vec4 rect = cascadeAtlasRect(cascade, 3);
        for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ((*out)[size_t(k * 4 + c)], rect[c]) << k << " " << c;
        EXPECT_FLOAT_EQ((*out)[size_t((4 + k) * 4)], fit->cascades[size_t(cascade)].splitFar) << k;
    }
    EXPECT_FLOAT_EQ((*out)[4], 0.5f);  // the second tile of a 2 x 2 grid starts at u = 0.5
}

using Frame = shadowfx::test::StatsFrame;
using shadowfx::test::findPass;

Frame renderCascades(EffectRenderer& renderer, const Scene& scene, bool leaveOut) {
    return shadowfx::test::renderWithStats(renderer, scene, "", leaveOut);
}

// cascades.fx on a scene whose far slices hold nothing: their passes are left out ("scene"), each running
// cascade culls casters to its own slice, and the frame is the one every pass drawn in full gives.
TEST(Cascades, CascadesWithoutReceiversAreLeftOut) {
    auto withLeaveOut = loadEffect(sourcePath("effects/cascades.fx"), true);
    auto without = loadEffect(sourcePath("effects/cascades.fx"), true);
    ASSERT_TRUE(withLeaveOut && without);
    const Scene scene = sceneWithEmptyFarSlices();
    const Frame lean = renderCascades(*withLeaveOut, scene, true);
    const Frame full = renderCascades(*without, scene, false);
    EXPECT_TRUE(notConstant(lean.image));
    ASSERT_EQ(lean.image.rgba.size(), full.image.rgba.size());
    EXPECT_EQ(std::memcmp(lean.image.rgba.data(), full.image.rgba.data(), lean.image.rgba.size()), 0);

    const PassStats* farLean = findPass(lean.stats, "Cascade3");
    const PassStats* farFull = findPass(full.stats, "Cascade3");
    const PassStats* nearLean = findPass(lean.stats, "Cascade0");
    ASSERT_TRUE(farLean && farFull && nearLean);
    EXPECT_EQ(farLean->leftOut, "scene");
    EXPECT_EQ(farLean->draws, 0);
    EXPECT_EQ(farFull->draws, 3);
    EXPECT_TRUE(nearLean->leftOut.empty());
    EXPECT_GT(nearLean->draws, 0);
    EXPECT_GT(nearLean->culled, 0) << "the far box casts on nothing in cascade 0's slice";
    EXPECT_GE(lean.stats.passesLeftOut, 1);
    EXPECT_LT(lean.stats.objects, full.stats.objects);
}

// A forest of posts: 90 x 90 posts, 2 m apart, on a ground plane, one colour for all, the camera among them
// at one edge looking along the field, the sun low across the view. Drawn farthest post first and the
// ground last, so that the nearest posts and the ground come after thousands of draws in every pass.
Scene postField() {
    Scene scene;
    scene.name = "post-field";
    const glm::vec3 eye(0.0f, 1.8f, -80.0f);
    std::vector<glm::vec3> posts;
    for (int i = 0; i < 90; ++i)
        for (int j = 0; j < 90; ++j) {
            const glm::vec3 at(-89.0f + 2.0f * static_cast<float>(i) + (j % 2 ? 0.7f : 0.0f), 1.5f,
                               -89.0f + 2.0f * static_cast<float>(j));
            if (glm::length(glm::vec2(at.x - eye.x, at.z - eye.z)) >= 3.0f) posts.push_back(at);
        }
    const auto distance = [&eye](const glm::vec3& p) {
        return glm::length(glm::vec2(p.x - eye.x, p.z - eye.z));
    };
    std::stable_sort(posts.begin(), posts.end(), [&distance](const glm::vec3& a, const glm::vec3& b) {
        return distance(a) > distance(b);
    });
    auto post = std::make_shared<const Mesh>(makeBox(glm::vec3(0.4f, 3.0f, 0.4f)));
    const auto add = [&scene](const std::shared_ptr<const Mesh>& mesh, const glm::vec3& at) {
        SceneObject object;
        object.name = "object" + std::to_string(scene.objects.size());
        object.mesh = mesh;
        object.world = glm::translate(glm::mat4(1.0f), at);
        object.color = glm::vec3(0.6f, 0.5f, 0.4f);
        object.id = static_cast<uint32_t>(scene.objects.size() + 1);
        scene.objects.push_back(object);
    };
    for (const glm::vec3& at : posts) add(post, at);
    add(std::make_shared<const Mesh>(makePlane(180.0f, 180.0f, 1)), glm::vec3(0.0f));
    scene.camera.position = eye;
    scene.camera.target = glm::vec3(0.0f, 1.5f, -50.0f);
    scene.camera.farPlane = 70.0f;
    Light light;
    light.direction = glm::normalize(glm::vec3(0.55f, -0.6f, 0.45f));
    scene.lights.push_back(light);
    return scene;
}

// cascades.fx at full cost: every post drawn into every cascade and into the scene pass, one draw each.
// The scene pass's pixel-stage values (the cascades' matrices, splits and tiles) are the same for every
// post, so they keep the uniform ring's range bound at the pass's first draw while each draw's
// vertex-stage values move on through the ring (test_uniform_ring.cpp); with more than a ring's worth of
// draws, the later posts and the ground were shaded with other draws' bytes as their cascades (on the
// built-in forest, 30 % of the pixels came out shadowed). Leave-out culls each pass to a few hundred
// posts and batches them, and gives the frame every pass drawn in full must give.
TEST(Cascades, EveryCasterInEveryCascadeGivesTheLeaveOutFrame) {
    auto withLeaveOut = loadEffect(sourcePath("effects/cascades.fx"), true);
    auto without = loadEffect(sourcePath("effects/cascades.fx"), true);
    ASSERT_TRUE(withLeaveOut && without);
    const Scene scene = postField();
    const Frame lean = renderCascades(*withLeaveOut, scene, true);
    const Frame full = renderCascades(*without, scene, false);
    EXPECT_TRUE(notConstant(lean.image));
    const PassStats* sceneFull = findPass(full.stats, "RenderScene");
    ASSERT_TRUE(sceneFull);
    EXPECT_EQ(sceneFull->draws, static_cast<int>(scene.objects.size()));
    EXPECT_EQ(shadowfx::test::differingPixels(lean.image, full.image), 0u);
}

// The diagnostic of a bad RenderPort, rendered, and whether the frame failed.
std::string renderError(const std::string& source, const std::string& name, bool& rendered) {
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect = fx::parseEffectSource(source, name, fx::ParseOptions{}, diagnostics);
    std::shared_ptr<fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    rendered = false;
    if (!compiled || diagnostics.hasErrors()) return diagnostics.str();
    shadowfx::test::sharedContext();
    auto renderer = EffectRenderer::create(compiled, diagnostics);
    if (!renderer) return diagnostics.str();
    FrameOptions options;
    options.width = 32;
    options.height = 32;
    rendered = renderer->render(sceneWithEmptyFarSlices(), options, diagnostics) && !diagnostics.hasErrors();
    return diagnostics.str();
}

std::string portEffect(const std::string& parameterization, const std::string& port) {
    return "float4x4 LightView : View < string frustum = \"light0\"; string Parameterization = \"" +
           parameterization +
           "\"; >;\n"
           "float4 QuadVS(float4 p : POSITION) : POSITION { return p; }\n"
           "float4 White() : COLOR { return 1; }\n"
           "technique t { pass p < string Script = \"RenderPort=" +
           port +
           "; Draw=Buffer;\"; >\n"
           "    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 "
           "White(); "
           "} }\n";
}

TEST(Cascades, BadCascadeIndexIsAnErrorAtItsCommand) {
    // Line 4, column 41: where "RenderPort" stands in `technique t { pass p < string Script = "RenderPort=`.
    bool rendered = true;
    std::string text = renderError(portEffect("Cascaded", "light0.cascade4"), "index.fx", rendered);
    EXPECT_FALSE(rendered);
    EXPECT_NE(text.find("index.fx:4:41: error: RenderPort names cascade 4 of light 'light0', which has 4"),
              std::string::npos)
        << text;

    text = renderError(portEffect("Focused", "light0.cascade0"), "focused.fx", rendered);
    EXPECT_FALSE(rendered);
    EXPECT_NE(text.find("focused.fx:4:41: error: RenderPort names cascade 0 of light 'light0', which has no "
                        "cascades"),
              std::string::npos)
        << text;

    text = renderError(portEffect("Cascaded", "light0.tile1"), "syntax.fx", rendered);
    EXPECT_FALSE(rendered);
    EXPECT_NE(text.find("syntax.fx:4:41: error: invalid script command 'RenderPort': expected lightN, "
                        "lightN.cascadeK or lightN.faceK"),
              std::string::npos)
        << text;

    // The same effect with a cascade the light has renders.
    text = renderError(portEffect("Cascaded", "light0.cascade3"), "good.fx", rendered);
    EXPECT_TRUE(rendered) << text;
}

}  // namespace
}  // namespace test_cascades
