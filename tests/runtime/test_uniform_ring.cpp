// The uniform ring (runtime/GpuProgram.h): every draw writes its stages' uniform blocks at a fresh offset
// of one 8 MiB buffer, and a block whose bytes did not change since the last draw keeps the range it was
// bound to. When the ring starts over, its next writes land on the ranges of the lap before, so such a
// block must be written again: a pass whose pixel-stage values stay put while its vertex-stage values
// change per object (World) keeps its pixel values through more than a whole lap of the ring.
#include "effects/EffectHarness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>

namespace test_uniform_ring {

namespace {

using namespace runtime;
using shadowfx::test::loadEffect;

// Every stage's block holds all the globals: Padding makes each 16 KiB, so that one pass over the scene
// below writes more than the ring holds. The pixel stage reads Colour only, the same for every object.
const char* kPerPassPixelValues = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float4 Padding[1024];
float4 Colour = {0, 1, 0, 1};
float4 Background = {0, 0, 1, 1};
float4 Vs(float4 position : POSITION) : POSITION { return mul(float4(position.xyz, 1), WorldViewProjection); }
float4 Ps() : COLOR { return Colour; }
technique t { pass p < string Script = "ClearSetColor=Background; Clear=Color; Draw=Geometry;"; > {
    ZEnable = false; CullMode = None;
    VertexShader = compile vs_3_0 Vs(); PixelShader = compile ps_3_0 Ps();
} }
)";

// 24 x 30 small boxes, all in view: 720 draws of 16 KiB blocks, about 11 MiB, past the ring's 8 MiB.
Scene manyBoxes() {
    Scene scene;
    scene.name = "many-boxes";
    auto box = std::make_shared<const Mesh>(makeBox(glm::vec3(0.3f)));
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 30; ++j) {
            SceneObject object;
            object.name = "box";
            object.mesh = box;
            object.world =
                glm::translate(glm::mat4(1.0f), glm::vec3(-6.0f + 0.5f * i, 0.0f, -7.5f + 0.5f * j));
            object.id = static_cast<uint32_t>(scene.objects.size() + 1);
            scene.objects.push_back(object);
        }
    scene.camera.position = glm::vec3(0.0f, 20.0f, -12.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    scene.camera.farPlane = 60.0f;
    scene.lights.push_back(Light{});
    return scene;
}

TEST(UniformRing, BlocksKeptFromTheLapBeforeAreWrittenAgain) {
    auto renderer = loadEffect(kPerPassPixelValues, false, "ring.fx");
    ASSERT_TRUE(renderer);
    FrameOptions options;
    options.width = 160;
    options.height = 120;
    options.leaveOut = false;  // one draw per object: batching draws all the boxes at once
    fx::DiagnosticList diagnostics;
    FrameStats stats;
    ASSERT_TRUE(renderer->render(manyBoxes(), options, diagnostics, &stats)) << diagnostics.str();
    ASSERT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
    EXPECT_EQ(stats.draws, 720);
    const FrameImage frame = renderer->readFrame();
    size_t boxes = 0, background = 0, other = 0;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4) {
        const uint8_t* p = &frame.rgba[i];
        if (p[0] == 0 && p[1] == 255 && p[2] == 0)
            ++boxes;
        else if (p[0] == 0 && p[1] == 0 && p[2] == 255)
            ++background;
        else
            ++other;
    }
    EXPECT_GT(boxes, frame.rgba.size() / 4 / 10);
    EXPECT_GT(background, 0u);
    EXPECT_EQ(other, 0u) << "pixels of boxes drawn with another range's bytes as their Colour";
}

}  // namespace
}  // namespace test_uniform_ring
