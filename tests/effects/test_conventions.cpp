// D3D conventions on OpenGL, pinned through whole effects: Draw=Buffer texture coordinates, row-vector
// matrices with mul(v, M), BlendOp=min on float targets, RenderPort and the frame's orientation.
#include "EffectHarness.h"
#include <runtime/BuiltinScenes.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace shadowfx::test::test_conventions {
namespace {

runtime::Scene emptyScene() {
    runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    return scene;
}

TEST(Conventions, DrawBufferTexcoordIsZeroAtTheTopLeft) {
    auto renderer = loadEffect(R"(
struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : POSITION; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex IN) { QuadOut OUT; OUT.Position = IN.Position; OUT.UV = IN.UV; return OUT; }
float4 ShowUV(QuadOut IN) : COLOR { return float4(IN.UV, 0, 1); }
technique t < string Script = "Pass=p;"; >
{
    pass p < string Script = "Draw=Buffer;"; >
    {
        ZEnable = false;
        VertexShader = compile vs_3_0 QuadVS();
        PixelShader = compile ps_3_0 ShowUV();
    }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, emptyScene(), 64, 32));
    const runtime::FrameImage image = renderer->readFrame();
    ASSERT_TRUE(notConstant(image));
    const uint8_t* topLeft = image.pixel(0, 0);
    const uint8_t* topRight = image.pixel(63, 0);
    const uint8_t* bottomLeft = image.pixel(0, 31);
    EXPECT_LT(topLeft[0], 8);
    EXPECT_LT(topLeft[1], 8);
    EXPECT_GT(topRight[0], 247);
    EXPECT_LT(topRight[1], 8);
    EXPECT_LT(bottomLeft[0], 8);
    EXPECT_GT(bottomLeft[1], 247);
}

// A small quad moved by a translation matrix in D3DX's row-vector form (translation in the fourth row):
// mul(v, M) must move it right, as D3D does.
TEST(Conventions, MulRowVectorByTranslationMovesGeometryTheD3DWay) {
    auto renderer = loadEffect(R"(
float4x4 Offset;
struct QuadVertex { float4 Position : POSITION; };
float4 MovedVS(QuadVertex IN) : POSITION { return mul(float4(IN.Position.xy * 0.25, 0.5, 1), Offset); }
float4 White() : COLOR { return 1; }
technique t < string Script = "ClearSetColor=Black; Clear=Color; Pass=p;"; >
{
    pass p < string Script = "Draw=Buffer;"; >
    {
        ZEnable = false;
        CullMode = None;
        VertexShader = compile vs_3_0 MovedVS();
        PixelShader = compile ps_3_0 White();
    }
}
float4 Black = {0, 0, 0, 1};
)",
                               false);
    ASSERT_TRUE(renderer);
    const glm::mat4 translation = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f));
    const float* m = glm::value_ptr(translation);  // memory = the D3DX matrix row by row (fx/Value.h)
    ASSERT_EQ(m[12], 0.5f) << "translation must sit in the fourth row of the D3DX matrix";
    renderer->setParameter(*renderer->findParameter("Offset"),
                           fx::Value::matrix(4, 4, std::vector<float>(m, m + 16)));
    ASSERT_TRUE(render(*renderer, emptyScene(), 64, 64));
    const runtime::FrameImage image = renderer->readFrame();
    ASSERT_TRUE(notConstant(image));
    // The quad spans NDC x in [0.25, 0.75] -> pixels 40..56; y in [-0.25, 0.25] -> rows 24..40.
    EXPECT_GT(image.pixel(48, 32)[0], 200) << "the moved quad is not where mul(v, M) puts it";
    EXPECT_LT(image.pixel(32, 32)[0], 50) << "the quad was not moved";
    EXPECT_LT(image.pixel(16, 32)[0], 50) << "the quad moved the wrong way";
}

// The thesis's shadow-map pass: BlendOp=min with One/One on an R32F target keeps the smallest value
// written, whatever the order.
TEST(Conventions, BlendOpMinOnR32FKeepsTheMinimum) {
    auto renderer = loadEffect(R"(
texture Target : RENDERCOLORTARGET < float2 Dimensions = {16, 16}; string Format = "R32F"; >;
float4 Hundred = {100, 100, 100, 100};
float Value = 0;
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 WriteValue(uniform float v) : COLOR { return float4(v, v, v, v); }
float4 WriteLeftOnly(float4 pos : VPOS, uniform float v) : COLOR { if (pos.x >= 8) discard; return v; }
technique t
< string Script = "RenderColorTarget0=Target; ClearSetColor=Hundred; Clear=Color;"
                  "Pass=five; Pass=seven; Pass=threeLeft; RenderColorTarget0=;"; >
{
    pass five < string Script = "Draw=Buffer;"; >
    { ZEnable = false; AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; BlendOp = Min;
      VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 WriteValue(5.0); }
    pass seven < string Script = "Draw=Buffer;"; >
    { ZEnable = false; AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; BlendOp = Min;
      VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 WriteValue(7.0); }
    pass threeLeft < string Script = "Draw=Buffer;"; >
    { ZEnable = false; AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; BlendOp = Min;
      VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 WriteLeftOnly(3.0); }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, emptyScene(), 32, 32, "", {"Target"}));
    int width = 0, height = 0, channels = 0;
    auto target = renderer->readTarget("Target", &width, &height, &channels);
    ASSERT_TRUE(target);
    ASSERT_EQ(width, 16);
    ASSERT_EQ(height, 16);
    const auto at = [&](int x, int y) { return (*target)[static_cast<size_t>((y * width + x) * channels)]; };
    EXPECT_FLOAT_EQ(at(2, 5), 3.0f);
    EXPECT_FLOAT_EQ(at(7, 15), 3.0f);
    EXPECT_FLOAT_EQ(at(8, 0), 5.0f);
    EXPECT_FLOAT_EQ(at(15, 9), 5.0f);
}

// LoopByCount runs its body the given number of times, LoopGetIndex exposes the iteration, and an
// additive pass accumulates once per iteration.
TEST(Conventions, LoopByCountRepeatsPasses) {
    auto renderer = loadEffect(R"(
texture Target : RENDERCOLORTARGET < float2 Dimensions = {4, 4}; string Format = "R32F"; >;
int Count = 5;
int Index = 0;
float4 Zero = {0, 0, 0, 0};
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 AddIndex() : COLOR { return Index + 1; }
technique t
< string Script = "RenderColorTarget0=Target; ClearSetColor=Zero; Clear=Color;"
                  "LoopByCount=Count; LoopGetIndex=Index; Pass=add; LoopEnd=;"; >
{
    pass add < string Script = "Draw=Buffer;"; >
    { ZEnable = false; AlphaBlendEnable = true; SrcBlend = One; DestBlend = One;
      VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 AddIndex(); }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, emptyScene(), 8, 8, "", {"Target"}));
    int width = 0, height = 0, channels = 0;
    auto target = renderer->readTarget("Target", &width, &height, &channels);
    ASSERT_TRUE(target);
    EXPECT_FLOAT_EQ((*target)[0], 1.0f + 2.0f + 3.0f + 4.0f + 5.0f);
}

// RenderPort=light0: View and Projection semantics are the light's during the pass, the camera's after
// RenderPort= (empty). Each pass writes the difference between the port's matrix and the light's.
TEST(Conventions, RenderPortGivesThePassTheLightsMatrices) {
    auto renderer = loadEffect(R"(
float4x4 ViewProj : ViewProjection;
float4x4 LightViewProj : ViewProjection < string frustum = "light0"; >;
texture LightPort : RENDERCOLORTARGET < float2 Dimensions = {4, 4}; string Format = "A32B32G32R32F"; >;
texture CameraPort : RENDERCOLORTARGET < float2 Dimensions = {4, 4}; string Format = "A32B32G32R32F"; >;
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 Difference() : COLOR
{
    float d = 0;
    for (int r = 0; r < 4; ++r) d += dot(abs(ViewProj[r] - LightViewProj[r]), 1);
    return d;
}
technique t < string Script = "RenderColorTarget0=LightPort; RenderPort=light0; Pass=p;"
                             "RenderColorTarget0=CameraPort; RenderPort=; Pass=p; RenderColorTarget0=;"; >
{
    pass p < string Script = "Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 Difference(); }
}
)",
                               false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, emptyScene(), 8, 8, "", {"LightPort", "CameraPort"}));
    int width = 0, height = 0, channels = 0;
    auto lightPort = renderer->readTarget("LightPort", &width, &height, &channels);
    auto cameraPort = renderer->readTarget("CameraPort", &width, &height, &channels);
    ASSERT_TRUE(lightPort && cameraPort);
    EXPECT_LT((*lightPort)[0], 1e-4f);
    EXPECT_GT((*cameraPort)[0], 0.01f);
}

}  // namespace
}  // namespace shadowfx::test::test_conventions
