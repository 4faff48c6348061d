// Stream output (ConstructGSWithSO) on pixels: a particle system in the style of the SDK's ParticlesGS that
// advances through transform feedback and draws its capture (DrawAuto), its capture read back through the
// pass API, and a NULL pixel shader in a stream-output pass rasterizing nothing (GL_RASTERIZER_DISCARD).
#include "effects/EffectHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/GlApi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadowfx::test::test_stream_output_effects {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

runtime::Scene scene(const char* name) {
    return std::move(*runtime::makeBuiltinScene(name, nullptr));
}

// Where tests/data/d3d10/stream_output_particles.fx draws the particle of age `age` (clip space, no camera).
std::pair<int, int> particlePixel(int age, int width, int height) {
    const float x = -0.8f + 0.15f * static_cast<float>(age), y = 0.8f - 0.15f * static_cast<float>(age);
    return {static_cast<int>((x + 1) / 2 * static_cast<float>(width)),
            static_cast<int>((1 - y) / 2 * static_cast<float>(height))};
}

// A particle system advancing through stream output: the SO pass draws what it captured the frame before
// (the launcher seed on the first) and captures anew; the draw pass draws the capture (DrawAuto). Frame 1
// shows the newborn particle alone, frame 10 ten of them along their path, coloured by age; every other
// pixel keeps the clear colour (a blank or constant frame fails).
TEST(StreamOutputEffects, AStreamOutputParticleSystemAdvancesFromFrameToFrame) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/stream_output_particles.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene teapot = scene("teapot");  // not drawn: the particles are the vertices
    const auto isBlack = [](const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; };
    ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    const runtime::FrameImage first = renderer->readFrame();
    const auto [x0, y0] = particlePixel(0, kWidth, kHeight);
    EXPECT_EQ(first.pixel(x0, y0)[0], 255);
    EXPECT_EQ(first.pixel(x0, y0)[1], 0);
    int lit = 0;
    for (size_t i = 0; i + 3 < first.rgba.size(); i += 4) lit += !isBlack(&first.rgba[i]);
    EXPECT_GT(lit, 40);  // one quad of about 11x8 pixels
    EXPECT_LT(lit, 150);
    for (int frame = 2; frame <= 10; ++frame) ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    const runtime::FrameImage tenth = renderer->readFrame();
    EXPECT_TRUE(notConstant(tenth));
    for (int age = 0; age < 10; ++age) {
        const auto [x, y] = particlePixel(age, kWidth, kHeight);
        const uint8_t* p = tenth.pixel(x, y);
        EXPECT_EQ(p[0], 255) << "age " << age;
        EXPECT_NEAR(p[1], age * 255 / 10, 2) << "age " << age;
        if (age > 0) {
            EXPECT_TRUE(isBlack(first.pixel(x, y))) << "age " << age << " in frame 1";
        }
    }
    const auto [x10, y10] = particlePixel(10, kWidth, kHeight);
    EXPECT_TRUE(isBlack(tenth.pixel(x10, y10)));  // nobody is that old yet
    EXPECT_TRUE(isBlack(tenth.pixel(kWidth - 2, 1)));
}

// The capture read back through the pass API after three frames: the launcher (TYPE 0) counted three
// frames, and the three particles it emitted are one frame apart on their path.
TEST(StreamOutputEffects, AStreamOutputPassCapturesTheVerticesItsGeometryShaderAppends) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/stream_output_particles.fx"), true);
    ASSERT_TRUE(renderer);
    runtime::EffectTechnique technique = renderer->technique("Particles");
    const std::optional<runtime::StreamOutCapture> seed = technique.pass("advance").streamOutput();
    ASSERT_TRUE(seed);
    EXPECT_TRUE(seed->seed);
    EXPECT_EQ(seed->vertices, 1u);
    EXPECT_FALSE(technique.pass("draw").streamOutput());
    const runtime::Scene teapot = scene("teapot");
    for (int frame = 1; frame <= 3; ++frame) ASSERT_TRUE(render(*renderer, teapot, kWidth, kHeight));
    const std::optional<runtime::StreamOutCapture> capture = technique.pass("advance").streamOutput();
    ASSERT_TRUE(capture);
    EXPECT_FALSE(capture->seed);
    ASSERT_EQ(capture->vertices, 4u);
    ASSERT_EQ(capture->strides[0], 32u);  // float3, float3, float, uint
    EXPECT_EQ(capture->buffers[1], 0u);
    struct Vertex {
        float pos[3], vel[3], timer;
        uint32_t type;
    };
    std::vector<Vertex> vertices(4);
    gl::GetNamedBufferSubData(capture->buffers[0], 0, sizeof(Vertex) * 4, vertices.data());
    std::vector<float> ages;
    int launchers = 0;
    for (const Vertex& v : vertices) {
        if (v.type == 0) {
            ++launchers;
            EXPECT_EQ(v.timer, 3.0f);
            continue;
        }
        EXPECT_EQ(v.type, 1u);
        ages.push_back(v.timer);
        EXPECT_NEAR(v.pos[0], -0.8f + 0.15f * v.timer, 1e-5f);
        EXPECT_NEAR(v.pos[1], 0.8f - 0.15f * v.timer, 1e-5f);
        EXPECT_NEAR(v.vel[0], 0.15f, 1e-6f);
    }
    EXPECT_EQ(launchers, 1);
    std::sort(ages.begin(), ages.end());
    EXPECT_EQ(ages, (std::vector<float>{0, 1, 2}));
}

// Passes with NULL pixel shaders, with and without stream output, before a pass that draws the same meshes
// white behind them.
const char* const kNullPixelShaders = R"(
float4x4 Wvp : WorldViewProjection;
struct MeshVertex { float3 Position : POSITION; };
struct Near { float4 Position : SV_Position; };
float4 AtDepth(MeshVertex v, float depth) { float4 p = mul(float4(v.Position, 1), Wvp); p.z = depth * p.w; return p; }
Near NearVS(MeshVertex v) { Near o; o.Position = AtDepth(v, 0.1); return o; }
float4 FarVS(MeshVertex v) : SV_Position { return AtDepth(v, 0.5); }
float4 White() : SV_Target { return 1; }
float4 Dark() : SV_Target { return float4(0, 0, 0, 1); }
VertexShader NearShader = CompileShader(vs_4_0, NearVS());
GeometryShader NearCapture = ConstructGSWithSO(NearShader, "SV_Position.xyzw");
DepthStencilState WriteAlways { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = ALWAYS; };
DepthStencilState TestLess { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = LESS; };
RasterizerState NoCull { CullMode = NONE; };
float4 Black = {0, 0, 0, 1};
technique10 Captured < string Script = "Pass=Near; Pass=Far;"; >
{
    pass Near < string Script = "ClearSetColor=Black; ClearSetDepth=1.0; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    { SetVertexShader(NearShader); SetGeometryShader(NearCapture); SetPixelShader(NULL);
      SetDepthStencilState(WriteAlways, 0); SetRasterizerState(NoCull); }
    pass Far < string Script = "Draw=Geometry;"; >
    { SetVertexShader(CompileShader(vs_4_0, FarVS())); SetGeometryShader(NULL);
      SetPixelShader(CompileShader(ps_4_0, White())); SetDepthStencilState(TestLess, 0); SetRasterizerState(NoCull); }
}
technique10 Rasterized < string Script = "Pass=Near; Pass=Far;"; >
{
    pass Near < string Script = "ClearSetColor=Black; ClearSetDepth=1.0; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    { SetVertexShader(NearShader); SetGeometryShader(NULL); SetPixelShader(CompileShader(ps_4_0, Dark()));
      SetDepthStencilState(WriteAlways, 0); SetRasterizerState(NoCull); }
    pass Far < string Script = "Draw=Geometry;"; >
    { SetVertexShader(CompileShader(vs_4_0, FarVS())); SetGeometryShader(NULL);
      SetPixelShader(CompileShader(ps_4_0, White())); SetDepthStencilState(TestLess, 0); SetRasterizerState(NoCull); }
}
technique10 DepthOnly < string Script = "Pass=Near; Pass=Far;"; >
{
    pass Near < string Script = "ClearSetColor=Black; ClearSetDepth=1.0; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    { SetVertexShader(NearShader); SetGeometryShader(NULL); SetPixelShader(NULL);
      SetDepthStencilState(WriteAlways, 0); SetRasterizerState(NoCull); }
    pass Far < string Script = "Draw=Geometry;"; >
    { SetVertexShader(CompileShader(vs_4_0, FarVS())); SetGeometryShader(NULL);
      SetPixelShader(CompileShader(ps_4_0, White())); SetDepthStencilState(TestLess, 0); SetRasterizerState(NoCull); }
}
)";

// A stream-output pass with a NULL pixel shader rasterizes nothing: its meshes at depth 0.1, written with
// depth test ALWAYS, would hide the same meshes a later pass draws white at depth 0.5 with LESS. The same
// pass drawn black without stream output hides them: the control that the meshes would have been drawn.
TEST(StreamOutputEffects, ANullPixelShaderInAStreamOutputPassRasterizesNothing) {
    auto renderer = loadEffect(kNullPixelShaders, false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kWidth, kHeight, "Captured"));
    const runtime::FrameImage captured = renderer->readFrame();
    const int white = countPixelsOfColour(captured, kWidth, kHeight, 255, 255, 255);
    EXPECT_GT(white, kWidth * kHeight / 10);  // the boxes
    EXPECT_EQ(white + countPixelsOfColour(captured, kWidth, kHeight, 0, 0, 0), kWidth * kHeight);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kWidth, kHeight, "Rasterized"));
    EXPECT_EQ(countPixelsOfColour(renderer->readFrame(), kWidth, kHeight, 0, 0, 0), kWidth * kHeight);
}

// Without stream output a NULL pixel shader is a depth-only pass, as D3D10 draws a shadow map's: the meshes'
// depth hides the white pass behind them, and no colour is written (D3D9's fixed-function white would show).
TEST(StreamOutputEffects, ANullPixelShaderWithoutStreamOutputWritesDepthAndNoColour) {
    auto renderer = loadEffect(kNullPixelShaders, false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kWidth, kHeight, "DepthOnly"));
    EXPECT_EQ(countPixelsOfColour(renderer->readFrame(), kWidth, kHeight, 0, 0, 0), kWidth * kHeight);
}

}  // namespace
}  // namespace shadowfx::test::test_stream_output_effects
