// Effects in the Direct3D 10/11 form rendered through the real pipeline: hardware PCF with a
// SamplerComparisonState through RenderPort=light0 against the ray-cast truth, D3D10's state defaults
// (DepthFunc LESS, back faces culled) against D3D9's on pixels, Texture2D methods through glslang,
// texture arrays, buffers and a multisample target on pixels, a geometry shader expanding a triangle into
// a quad, geometry shaders taking points, edges and triangles with adjacency, hull and domain shaders
// whose tessellation factors, domain locations and patch constants show on pixels, a technique11 twin
// rendering the same frame as its D3D9 technique, vertex inputs by input-layout names, more than eight
// free-named varyings, per-target and dual-source blending, and a multisample target above the driver's
// sample count. Stream output: test_stream_output_effects.cpp.
#include "VisibilityHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/Mesh.h>
#include <runtime/ShadowMetrics.h>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace shadowfx::test::test_d3d10_effects {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

runtime::Scene scene(const char* name) {
    auto s = runtime::makeBuiltinScene(name, nullptr);
    if (!s) throw std::runtime_error(std::string("no scene ") + name);
    return std::move(*s);
}

// The pixels of colour (r, g, b) in the frame that `technique` of the test effect at `path` draws on the
// teapot; 0 where the effect does not load or render.
int pixelsOfColourDrawn(const char* path, const char* technique, int r, int g, int b) {
    auto renderer = loadEffect(sourcePath(path), true);
    EXPECT_TRUE(renderer) << path;
    if (!renderer || !render(*renderer, scene("teapot"), kWidth, kHeight, technique)) return 0;
    return countPixelsOfColour(renderer->readFrame(), kWidth, kHeight, r, g, b);
}

struct Counts {
    size_t red = 0, green = 0;
};

// Pixels that are pure red or pure green (what the state tests' shaders write).
Counts countRedGreen(const runtime::FrameImage& image) {
    Counts c;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        const uint8_t* p = &image.rgba[i];
        if (p[0] == 255 && p[1] == 0 && p[2] == 0) ++c.red;
        if (p[0] == 0 && p[1] == 255 && p[2] == 0) ++c.green;
    }
    return c;
}

Counts renderCounts(runtime::EffectRenderer& renderer, const std::string& technique) {
    EXPECT_TRUE(render(renderer, scene("teapot"), kWidth, kHeight, technique));
    return countRedGreen(renderer.readFrame());
}

// [SECTION] Hardware PCF in the D3D11 form

TEST(D3d10Effects, SampleCmpThroughRenderPortLight0MatchesTheRayCastTruth) {
    constexpr int kTruthWidth = 320, kTruthHeight = 240;
    auto renderer = loadVisibilityEffect("tests/data/d3d10/shadow_cmp.fx");
    ASSERT_TRUE(renderer);
    const SceneTruth t = computeSceneTruth(scene("dual-l"), kTruthWidth, kTruthHeight);
    const std::vector<float> lit(t.truth.visibility.size(), 1.0f);
    const double blank =
        runtime::compareVisibility(t.truth.visibility, lit, t.receivers).misclassifiedPercent;
    constexpr double kBound = 0.2;  // effects/pcf.fx's `hardware` bound on this scene is 0.1 % at 1024²
    ASSERT_LT(kBound * 4, blank) << "an all-lit image must fail the bound by far";
    ASSERT_TRUE(render(*renderer, t.scene, kTruthWidth, kTruthHeight, "HardwarePcf"));
    const std::vector<float> visibility = runtime::visibilityFromFrame(renderer->readFrame());
    const runtime::ShadowErrors errors =
        runtime::compareVisibility(t.truth.visibility, visibility, t.receivers);
    EXPECT_LT(errors.misclassifiedPercent, kBound);
    // Filtered: some receiver pixels at shadow edges are neither 0 nor 1.
    size_t fractional = 0;
    for (float v : visibility) fractional += v > 0.05f && v < 0.95f;
    EXPECT_GT(fractional, 10u);
}

TEST(D3d10Effects, ShadowedFrameIsShadedAndNotConstant) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/shadow_cmp.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("dual-l"), kWidth, kHeight));
    EXPECT_TRUE(notConstant(renderer->readFrame()));
}

// [SECTION] State defaults on pixels

const char* kStateEffect = R"(
float4x4 Wvp : WorldViewProjection;
float4 VS(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), Wvp); }
float4 Red() : SV_Target { return float4(1, 0, 0, 1); }
float4 Green() : SV_Target { return float4(0, 1, 0, 1); }
float4 Faces(bool front : SV_IsFrontFace) : SV_Target { return front ? float4(0, 1, 0, 1) : float4(1, 0, 0, 1); }
DepthStencilState NoDepth { DepthEnable = FALSE; };
RasterizerState NoCulling { CullMode = NONE; };

// The same triangles twice, red then green: the second pass passes the depth test only with LESSEQUAL.
technique11 SameDepth10
{
    pass A { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Red())); }
    pass B { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Green())); }
}
technique SameDepth9
{
    pass A { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Red(); }
    pass B { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Green(); }
}
// Without a depth test, back faces would draw over front ones in red: culled, none do.
technique11 DefaultCull10
{
    pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Faces()));
           SetDepthStencilState(NoDepth, 0); }
}
technique11 NoCull10
{
    pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Faces()));
           SetDepthStencilState(NoDepth, 0); SetRasterizerState(NoCulling); }
}
)";

TEST(D3d10Effects, D3d10PassesDefaultToDepthFuncLessAndD3d9PassesToLessEqual) {
    auto renderer = loadEffect(kStateEffect, false, "states.fx");
    ASSERT_TRUE(renderer);
    const Counts d3d10 = renderCounts(*renderer, "SameDepth10");
    EXPECT_GT(d3d10.red, 1000u);
    EXPECT_EQ(d3d10.green, 0u);
    const Counts d3d9 = renderCounts(*renderer, "SameDepth9");
    EXPECT_GT(d3d9.green, 1000u);
    EXPECT_EQ(d3d9.red, 0u);
}

TEST(D3d10Effects, APassThatSetsNoRasterizerStateCullsBackFaces) {
    auto renderer = loadEffect(kStateEffect, false, "states.fx");
    ASSERT_TRUE(renderer);
    const Counts culled = renderCounts(*renderer, "DefaultCull10");
    EXPECT_GT(culled.green, 1000u);
    EXPECT_EQ(culled.red, 0u);
    const Counts all = renderCounts(*renderer, "NoCull10");
    EXPECT_GT(all.red, 100u);  // the teapot's inside, seen through the spout and under the lid
}

// [SECTION] Texture objects and their methods

TEST(D3d10Effects, TextureMethodsSampleThroughSamplerStates) {
    auto renderer = loadEffect(R"(
cbuffer Frame { float4x4 Wvp : WorldViewProjection; float Scale < string UIName = "Scale"; > = 0.25; };
Texture2D Noise < string Procedural = "noise"; int Seed = 3; float2 Dimensions = {64, 64}; >;
SamplerState Linear { AddressU = WRAP; AddressV = WRAP; };
SamplerState Point { Filter = MIN_MAG_MIP_POINT; AddressU = WRAP; AddressV = WRAP; };
struct VsOut { float4 Position : SV_Position; float2 Uv : SURFACE_UV; };
VsOut VS(float3 p : POSITION, float2 uv : TEXCOORD0)
{
    VsOut o;
    o.Position = mul(float4(p, 1), Wvp);
    o.Uv = p.xy * 4;
    return o;
}
float4 PS(VsOut i) : SV_Target
{
    uint w, h;
    Noise.GetDimensions(w, h);
    float4 c = Noise.Sample(Linear, i.Uv) + Noise.SampleLevel(Point, i.Uv, 0) + Noise.SampleBias(Linear, i.Uv, 0.5)
             + Noise.SampleGrad(Linear, i.Uv, ddx(i.Uv), ddy(i.Uv)) + Noise.Gather(Point, i.Uv)
             + Noise.Load(int3(int2(i.Position.xy) % int2(w, h), 0));
    return float4(c.rgb * Scale, 1);
}
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                               false, "texture_methods.fx");
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    EXPECT_TRUE(notConstant(renderer->readFrame()));
}

// [SECTION] Texture arrays

// A full-screen pass per technique (Draw=Buffer), depth and culling off.
std::string fullScreenTechniques(const std::vector<std::string>& pixelShaders) {
    std::string text = R"(
struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : SV_Position; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex v) { QuadOut o; o.Position = v.Position; o.UV = v.UV; return o; }
DepthStencilState NoDepth { DepthEnable = FALSE; };
RasterizerState NoCulling { CullMode = NONE; };
)";
    for (const std::string& ps : pixelShaders)
        text += "technique11 " + ps +
                " < string Script = \"Pass=p;\"; > { pass p < string Script = \"Draw=Buffer;\"; > {" +
                " SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, " +
                ps + "())); SetDepthStencilState(NoDepth, 0); SetRasterizerState(NoCulling); } }\n";
    return text;
}

constexpr int kStripWidth = 96, kStripHeight = 16;

// The frame's pixel at the middle of third `third` (0..2) of its width.
const uint8_t* third(const runtime::FrameImage& image, int third) {
    return image.pixel(kStripWidth / 6 + third * kStripWidth / 3, kStripHeight / 2);
}

::testing::AssertionResult isColor(const uint8_t* p, int r, int g, int b) {
    if (std::abs(p[0] - r) <= 2 && std::abs(p[1] - g) <= 2 && std::abs(p[2] - b) <= 2)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "pixel (" << int(p[0]) << ", " << int(p[1]) << ", " << int(p[2])
                                         << ") expected (" << r << ", " << g << ", " << b << ")";
}

// `elements` layers of `width` x `height` texels, layer i all `colors[i]`.
runtime::TextureData solidLayers(int width, int height, const std::vector<glm::vec3>& colors, int elements) {
    runtime::TextureData data;
    data.width = width;
    data.height = height;
    data.elements = elements;
    for (const glm::vec3& c : colors)
        for (int t = 0; t < width * height; ++t) data.rgba.insert(data.rgba.end(), {c.r, c.g, c.b, 1.0f});
    return data;
}

TEST(D3d10Effects, TextureArraysSetThroughTheApiShowTheElementTheCodeSelects) {
    auto renderer = loadEffect(R"(
Texture2DArray Layers;
Texture2DArray Unset < int ArraySize = 5; >;
TextureCubeArray Cubes;
Texture1DArray Strips;
SamplerState Point { Filter = MIN_MAG_MIP_POINT; };
SamplerComparisonState Less { ComparisonFunc = LESS; };
// Left to right: elements 0, 1 and 2 of Layers.
float4 Slices(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    return Layers.Sample(Point, float3(uv, floor(uv.x * 3)));
}
// Left: Load of Layers' element 2, full only if GetDimensions counts 3 elements; middle: cube 1's +X
// face; right: element 1 of Strips.
float4 Others(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    uint w, h, elements, levels;
    Layers.GetDimensions(0, w, h, elements, levels);
    if (uv.x < 1.0 / 3) return Layers.Load(int4(1, 1, 2, 0)) * (elements == 3 ? 1 : 0.5);
    if (uv.x < 2.0 / 3) return Cubes.SampleLevel(Point, float4(1, 0, 0, 1), 0);
    return Strips.Sample(Point, float2(0.9, 1));
}
// An array nobody set: white in each of its ArraySize elements.
float4 Default(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    uint w, h, elements;
    Unset.GetDimensions(w, h, elements);
    return float4(Unset.Sample(Point, float3(uv, 4)).rgb * (elements == 5 ? 1 : 0.5), 1);
}
// Compiles and links (a comparison reads a depth array, which passes have no way to render yet).
float4 Compare(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    return Layers.SampleCmpLevelZero(Less, float3(uv, 1), 0.5) + Cubes.SampleCmp(Less, float4(1, 0, 0, 1), 0.5);
}
)" + fullScreenTechniques({"Slices", "Others", "Default", "Compare"}),
                               false, "arrays.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene boxes = scene("boxes");
    ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, "Default"));
    EXPECT_TRUE(isColor(third(renderer->readFrame(), 1), 255, 255, 255));

    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Layers"),
                                     solidLayers(2, 2, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 3), diagnostics))
        << diagnostics.str();
    std::vector<glm::vec3> faces(6, glm::vec3(0.2f));
    faces.push_back({1, 1, 0});  // cube 1, +X
    faces.insert(faces.end(), 5, glm::vec3(1, 0, 1));
    ASSERT_TRUE(
        renderer->setTexture(*renderer->findParameter("Cubes"), solidLayers(1, 1, faces, 2), diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Strips"),
                                     solidLayers(4, 1, {{1, 0, 0}, {0, 1, 1}}, 2), diagnostics))
        << diagnostics.str();
    // A cube array's texels must fill six faces per cube.
    EXPECT_FALSE(
        renderer->setTexture(*renderer->findParameter("Cubes"), solidLayers(1, 1, faces, 3), diagnostics));

    ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, "Slices"));
    const runtime::FrameImage slices = renderer->readFrame();
    EXPECT_TRUE(isColor(third(slices, 0), 255, 0, 0));
    EXPECT_TRUE(isColor(third(slices, 1), 0, 255, 0));
    EXPECT_TRUE(isColor(third(slices, 2), 0, 0, 255));
    ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, "Others"));
    const runtime::FrameImage others = renderer->readFrame();
    EXPECT_TRUE(isColor(third(others, 0), 0, 0, 255));
    EXPECT_TRUE(isColor(third(others, 1), 255, 255, 0));
    EXPECT_TRUE(isColor(third(others, 2), 0, 255, 255));
}

// An array of textures passed on from a function that itself takes a texture (the deferred renderers'
// G-buffer helpers, `get(Texture2D g[3], float2 uv)`): the pass links (the GLSL indexed a single sampler
// before) and the helper reads the array's element 0, red, beside the function's own texture, blue. The
// runtime gives an array of textures one texture, which its element 0 samples.
TEST(D3d10Effects, ATextureArrayPassedThroughFunctionsSamplesItsElement) {
    auto renderer = loadEffect(R"(
Texture2D Picture;
Texture2D<half4> GBuffer[3];
SamplerState Point { Filter = MIN_MAG_MIP_POINT; };
float4 first(Texture2D<half4> g[3], float2 uv) { return g[0].Sample(Point, uv); }
float4 blend(Texture2D t, float2 uv) { return t.Sample(Point, uv) + first(GBuffer, uv); }
float4 Show(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target { return blend(Picture, uv); }
)" + fullScreenTechniques({"Show"}),
                               false, "texture_array_argument.fx");
    ASSERT_TRUE(renderer);
    const std::string& glsl = renderer->effect().techniques[0].passes[0].fragment.glsl;
    EXPECT_NE(glsl.find("uniform sampler2D fx_pair_GBuffer_Point[3];"), std::string::npos) << glsl;
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Picture"), solidLayers(1, 1, {{0, 0, 1}}, 1),
                                     diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("GBuffer"), solidLayers(1, 1, {{1, 0, 0}}, 1),
                                     diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight, "Show"));
    EXPECT_TRUE(isColor(third(renderer->readFrame(), 1), 255, 0, 255));
}

// D3D10's `Length` property, each object's size as GetDimensions gives it without a mip level (glslang
// refused it as an operator on a texture): left, a 5 x 3 Texture2D; middle, a 2 x 2 Texture2DArray of 3
// elements; right, a 4-texel Texture1DArray of 2 elements and a Buffer of 7 elements. Each size is a
// colour channel in 1/255 steps.
TEST(D3d10Effects, LengthIsTheObjectsSizeInTexels) {
    auto renderer = loadEffect(R"(
Texture2D Picture;
Texture2DArray Layers;
Texture1DArray Strips;
Buffer<float4> Items;
float4 Sizes(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    float3 size = uv.x < 1.0 / 3 ? float3(Picture.Length.xy, 0)
                : uv.x < 2.0 / 3 ? float3(Layers.Length)
                                 : float3(Strips.Length, Items.Length);
    return float4(size / 255, 1);
}
)" + fullScreenTechniques({"Sizes"}),
                               false, "length.fx");
    ASSERT_TRUE(renderer);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Picture"), solidLayers(5, 3, {{1, 0, 0}}, 1),
                                     diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Layers"),
                                     solidLayers(2, 2, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 3), diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(renderer->setTexture(*renderer->findParameter("Strips"),
                                     solidLayers(4, 1, {{1, 0, 0}, {0, 1, 1}}, 2), diagnostics))
        << diagnostics.str();
    const float items[7][4] = {};
    ASSERT_TRUE(
        renderer->setBuffer(*renderer->findParameter("Items"), items, 7, sizeof items[0], diagnostics))
        << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight, "Sizes"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(isColor(third(frame, 0), 5, 3, 0));
    EXPECT_TRUE(isColor(third(frame, 1), 2, 2, 3));
    EXPECT_TRUE(isColor(third(frame, 2), 4, 2, 7));
}

// [SECTION] Buffers

TEST(D3d10Effects, BuffersSetThroughTheApiReachThePixelsAndUnsetOnesReadZero) {
    auto renderer = loadEffect(R"(
// D3D packs a Light in 24 bytes; GL's std430 block pads it to 32, so the runtime repacks.
struct Light { float3 Color; float Intensity; float2 Offset; };
StructuredBuffer<Light> Lights;
Buffer<float4> Colors;
ByteAddressBuffer Raw;
StructuredBuffer<float4> UnsetStructured;
Buffer<float> UnsetTyped;
ByteAddressBuffer UnsetRaw;
// Left: Lights[1]'s members; middle: Colors[3], full only if Lights counts 2 elements; right: three
// words of Raw from byte 4.
float4 Read(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    uint count, stride;
    Lights.GetDimensions(count, stride);
    if (uv.x < 1.0 / 3) return float4(Lights[1].Offset, Lights[1].Intensity, 1);
    if (uv.x < 2.0 / 3) return Colors.Load(3) * (count == 2 ? 1 : 0.5);
    return float4(asfloat(Raw.Load3(4)), 1);
}
float4 Zeros(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target
{
    return float4(0.5 + UnsetStructured[0].rgb + UnsetTyped[0] + asfloat(UnsetRaw.Load(0)), 1);
}
)" + fullScreenTechniques({"Read", "Zeros"}),
                               false, "buffers.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene boxes = scene("boxes");
    ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, "Zeros"));
    EXPECT_TRUE(isColor(third(renderer->readFrame(), 1), 128, 128, 128));

    fx::DiagnosticList diagnostics;
    const float lights[2][6] = {{1, 0, 0, 1, 0, 0}, {0, 1, 0, 0.5f, 0.25f, 0.75f}};
    EXPECT_FALSE(renderer->setBuffer(*renderer->findParameter("Lights"), lights, 2, 32, diagnostics));
    ASSERT_TRUE(
        renderer->setBuffer(*renderer->findParameter("Lights"), lights, 2, sizeof lights[0], diagnostics))
        << diagnostics.str();
    const float colors[4][4] = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {0, 0.5f, 1, 1}};
    ASSERT_TRUE(
        renderer->setBuffer(*renderer->findParameter("Colors"), colors, 4, sizeof colors[0], diagnostics))
        << diagnostics.str();
    const float raw[4] = {9, 1, 0.5f, 0};
    ASSERT_TRUE(renderer->setBuffer(*renderer->findParameter("Raw"), raw, 4, 4, diagnostics))
        << diagnostics.str();

    ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, "Read"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(isColor(third(frame, 0), 64, 191, 128));
    EXPECT_TRUE(isColor(third(frame, 1), 0, 128, 255));
    EXPECT_TRUE(isColor(third(frame, 2), 255, 128, 0));
}

// [SECTION] Multisample render targets

// A parallelogram with slanted sides drawn into a 4-sample target, then read per sample by a second pass:
// red the mean of the samples, green where they differ, blue GetDimensions' sample count / 4.
TEST(D3d10Effects, MultisampleTargetIsReadPerSampleByALaterPass) {
    auto renderer = loadEffect(R"(
Texture2DMS<float4, 4> Coverage : RENDERCOLORTARGET;
float4 Black = {0, 0, 0, 1};
struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
float4 Slanted(QuadVertex v) : SV_Position
{
    return float4(v.Position.x * 0.5 + v.Position.y * 0.3, v.Position.y * 0.8, 0.5, 1);
}
float4 QuadVS(QuadVertex v) : SV_Position { return v.Position; }
float4 White() : SV_Target { return 1; }
float4 PerSample(float4 p : SV_Position) : SV_Target
{
    uint w, h, samples;
    Coverage.GetDimensions(w, h, samples);
    const int2 at = int2(p.xy);
    const float4 first = Coverage.Load(at, 0);
    float sum = 0;
    bool differ = false;
    for (int i = 0; i < 4; ++i) {
        const float4 s = Coverage.Load(at, i);
        sum += s.r;
        differ = differ || any(s != first);
    }
    return float4(sum / 4, differ ? 1 : 0, samples / 4.0, 1);
}
DepthStencilState NoDepth { DepthEnable = FALSE; };
RasterizerState Multisampled { CullMode = NONE; MultisampleEnable = TRUE; };
technique11 Msaa < string Script = "Pass=Draw; Pass=Read;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Coverage; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    { SetVertexShader(CompileShader(vs_5_0, Slanted())); SetPixelShader(CompileShader(ps_5_0, White()));
      SetDepthStencilState(NoDepth, 0); SetRasterizerState(Multisampled); }
    pass Read < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    { SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, PerSample()));
      SetDepthStencilState(NoDepth, 0); SetRasterizerState(Multisampled); }
}
)",
                               false, "multisample.fx");
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight * 2));
    const runtime::FrameImage frame = renderer->readFrame();
    size_t inside = 0, outside = 0, edges = 0, partial = 0, fourSamples = 0;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const uint8_t* p = frame.pixel(x, y);
            inside += p[0] == 255 && p[1] == 0;
            outside += p[0] == 0 && p[1] == 0;
            edges += p[1] == 255;
            partial += p[1] == 255 && p[0] > 0 && p[0] < 255;
            fourSamples += p[2] == 255;
        }
    EXPECT_GT(inside, 400u);
    EXPECT_GT(outside, 400u);
    // Both slanted sides cross every covered row; where the samples differ, the mean is a fraction.
    EXPECT_GE(edges, static_cast<size_t>(2 * kStripHeight));
    EXPECT_EQ(partial, edges);
    EXPECT_EQ(fourSamples, static_cast<size_t>(frame.width * frame.height));
}

// [SECTION] Geometry shaders

// The quad tests/data/d3d10/geometry_sprite.fx's geometry shader emits: (2 HalfSize)² / 4 of the frame,
// centred, in the vertex shader's green, its blue the quad's u from 0 at the left to 1 at the right.
TEST(D3d10Effects, GeometryShaderExpandsTheFirstTriangleIntoACentredQuad) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/geometry_sprite.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Sprites"));
    const runtime::FrameImage frame = renderer->readFrame();
    size_t inside = 0, outside = 0;
    int left = kWidth, right = -1, top = kHeight, bottom = -1;
    uint8_t blueAtLeft = 0, blueAtRight = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const uint8_t* p = &frame.rgba[(static_cast<size_t>(y) * kWidth + x) * 4];
            if (p[0] != 0 || p[1] != 255) continue;  // not the sprite's colour
            const bool central =
                x >= kWidth / 4 && x < 3 * kWidth / 4 && y >= kHeight / 4 && y < 3 * kHeight / 4;
            ++(central ? inside : outside);
            if (x < left) left = x, blueAtLeft = p[2];
            if (x > right) right = x, blueAtRight = p[2];
            top = std::min(top, y);
            bottom = std::max(bottom, y);
        }
    // HalfSize 0.5: the central quarter of the frame, every pixel of it and nothing else.
    EXPECT_EQ(inside, static_cast<size_t>(kWidth * kHeight / 4));
    EXPECT_EQ(outside, 0u);
    EXPECT_EQ(left, kWidth / 4);
    EXPECT_EQ(right, 3 * kWidth / 4 - 1);
    EXPECT_EQ(top, kHeight / 4);
    EXPECT_EQ(bottom, 3 * kHeight / 4 - 1);
    // The float2 UV crossed the geometry stage: u rises from the left edge to the right one.
    EXPECT_LT(blueAtLeft, 8);
    EXPECT_GT(blueAtRight, 247);

    // Without the geometry shader the same pass draws the teapot, not the quad.
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "NoSprites"));
    const runtime::FrameImage meshes = renderer->readFrame();
    EXPECT_FALSE(meshes.rgba == frame.rgba);
}

// tests/data/d3d10/geometry_inputs.fx's geometry shaders address pixels of a 64 x 64 frame by their
// SV_PrimitiveID; the scene is one torus whose seam vertices repeat (with positions a few ulps apart).
constexpr int kInputsSize = 64;

runtime::Scene torusAlone() {
    runtime::Scene s;
    runtime::SceneObject object;
    object.name = "torus";
    object.mesh = std::make_shared<runtime::Mesh>(runtime::makeTorus(1.0f, 0.4f, 12, 8));
    s.objects.push_back(object);
    return s;
}

std::vector<bool> whitePixels(const runtime::FrameImage& frame) {
    std::vector<bool> white(kInputsSize * kInputsSize);
    for (size_t i = 0; i < white.size(); ++i)
        white[i] = frame.rgba[i * 4] == 255 && frame.rgba[i * 4 + 1] == 255 && frame.rgba[i * 4 + 2] == 255;
    return white;
}

// `point` input: the mesh's vertices drawn as points, each one expanded into a 2 x 2 sprite in the vertex
// shader's colour: exactly four pixels per vertex, at the blocks 0 .. vertices - 1 and nowhere else.
TEST(D3d10Effects, PointInputGeometryShaderExpandsEveryVertexIntoASprite) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/geometry_inputs.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = torusAlone();
    const size_t vertices = scene.objects[0].mesh->positions.size();
    ASSERT_LE(vertices, 32u * 32u);
    ASSERT_TRUE(render(*renderer, scene, kInputsSize, kInputsSize, "Sprites"));
    const runtime::FrameImage frame = renderer->readFrame();
    size_t green = 0, misplaced = 0;
    for (int y = 0; y < kInputsSize; ++y)
        for (int x = 0; x < kInputsSize; ++x) {
            const uint8_t* p = &frame.rgba[(static_cast<size_t>(y) * kInputsSize + x) * 4];
            if (p[0] != 0 || p[1] != 255 || p[2] != 0) continue;
            ++green;
            misplaced += static_cast<size_t>((y / 2) * 32 + x / 2) >= vertices;
        }
    EXPECT_EQ(green, 4 * vertices);
    EXPECT_EQ(misplaced, 0u);
}

// A value the vertex shader writes under PSIZE, read by the geometry shader as SM4 user data (FX11
// point-sprite particles carry each sprite's size so): tests/data/d3d10/point_size_geometry.fx colours
// each sprite with the size its geometry shader read, and draws nothing where it read 0.
TEST(D3d10Effects, GeometryShaderReadsThePointSizeTheVertexShaderWrote) {
    // Size (0.25, 0.75) as the colour (0.25, 0.75, 1).
    EXPECT_GT(pixelsOfColourDrawn("tests/data/d3d10/point_size_geometry.fx", "Sprites", 64, 191, 255),
              kWidth * kHeight / 20);
}

// An instance ID the vertex shader writes under SV_InstanceID, read by the geometry shader and, written on
// by it, by the pixel shader (FX11 trail effects carry it so): tests/data/d3d10/instance_id_geometry.fx
// draws a quad per vertex only where the geometry shader read the vertex shader's value, coloured by what
// the pixel shader read.
TEST(D3d10Effects, InstanceIdTheVertexShaderWroteReachesTheGeometryAndPixelShaders) {
    // Read 6 as the colour (6 / 8, 1, 0.25).
    EXPECT_GT(pixelsOfColourDrawn("tests/data/d3d10/instance_id_geometry.fx", "Trail", 191, 255, 64),
              kWidth * kHeight / 20);
}

// Locals brace-initialized as C++ does (`float rim{};`, `float3 v{...}`, `Pair p{...}`), which FX11
// games' fxc builds accepted: tests/data/d3d10/brace_initializers.fx colours the object with all three.
TEST(D3d10Effects, BraceInitializedLocalsTakeTheirValues) {
    EXPECT_GT(pixelsOfColourDrawn("tests/data/d3d10/brace_initializers.fx", "Braces", 64, 128, 191),
              kWidth * kHeight / 50);
}

// `triangleadj` input: the silhouette edges as seen from the light, pixel 3 t + i for edge i of triangle
// t, against the same test computed here from the mesh with its own (brute-force) neighbour search.
TEST(D3d10Effects, TriangleAdjacencyGeometryShaderFindsTheSilhouetteEdges) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/geometry_inputs.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = torusAlone();
    const runtime::Mesh& mesh = *scene.objects[0].mesh;
    ASSERT_LE(mesh.indices.size(), static_cast<size_t>(kInputsSize * kInputsSize));
    const glm::vec3 toLight = -glm::vec3(0.6f, -0.7f, 0.4f);
    auto near = [](const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-4f; };
    auto vertex = [&](size_t t, size_t k) { return mesh.positions[mesh.indices[3 * t + k % 3]]; };
    auto normal = [](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        return glm::cross(b - a, c - a);
    };
    const size_t triangles = mesh.triangleCount();
    std::vector<bool> expected(kInputsSize * kInputsSize, false);
    size_t silhouettes = 0;
    for (size_t t = 0; t < triangles; ++t) {
        if (glm::dot(normal(vertex(t, 0), vertex(t, 1), vertex(t, 2)), toLight) <= 0) continue;
        for (size_t i = 0; i < 3; ++i) {
            const glm::vec3 a = vertex(t, i), b = vertex(t, i + 1);
            bool neighbourFacesAway = true;  // no neighbour: the edge bounds the mesh
            for (size_t u = 0; u < triangles; ++u)
                for (size_t k = 0; k < 3 && u != t; ++k)
                    if (near(vertex(u, k), b) && near(vertex(u, k + 1), a))
                        neighbourFacesAway = glm::dot(normal(b, a, vertex(u, k + 2)), toLight) <= 0;
            if (neighbourFacesAway) expected[3 * t + i] = true, ++silhouettes;
        }
    }
    ASSERT_GT(silhouettes, 8u);
    ASSERT_TRUE(render(*renderer, scene, kInputsSize, kInputsSize, "Silhouettes"));
    const std::vector<bool> found = whitePixels(renderer->readFrame());
    EXPECT_EQ(std::count(found.begin(), found.end(), true), static_cast<long>(silhouettes));
    EXPECT_TRUE(found == expected);
}

// `line` input: every edge of the mesh once. A closed torus of 12 x 8 quads has 96 distinct vertices,
// 192 triangles and so 288 edges (Euler: V - E + F = 0); its seams repeat vertices that must not count.
TEST(D3d10Effects, LineInputGeometryShaderGetsEveryEdgeOnce) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/geometry_inputs.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, torusAlone(), kInputsSize, kInputsSize, "Edges"));
    const std::vector<bool> found = whitePixels(renderer->readFrame());
    EXPECT_EQ(std::count(found.begin(), found.end(), true), 288);
    EXPECT_TRUE(std::all_of(found.begin(), found.begin() + 288, [](bool b) { return b; }));
}

// [SECTION] Tessellation

constexpr int kTessSize = 96;

// The white pixels of a wireframe frame, and the runs of white pixels along its middle row.
struct Wire {
    size_t pixels = 0;
    int runs = 0;
};

Wire renderWire(runtime::EffectRenderer& renderer, const std::string& technique, const char* factor) {
    fx::DiagnosticList diagnostics;
    EXPECT_TRUE(renderer.setParameterFromText("TessFactor", factor, diagnostics)) << diagnostics.str();
    EXPECT_TRUE(render(renderer, scene("teapot"), kTessSize, kTessSize, technique));
    const runtime::FrameImage frame = renderer.readFrame();
    auto white = [&](int x, int y) {
        const uint8_t* p = &frame.rgba[(static_cast<size_t>(y) * kTessSize + x) * 4];
        return p[0] == 255 && p[1] == 255 && p[2] == 255;
    };
    Wire w;
    for (int y = 0; y < kTessSize; ++y)
        for (int x = 0; x < kTessSize; ++x) w.pixels += white(x, y);
    for (int x = 0; x < kTessSize; ++x)
        w.runs += white(x, kTessSize / 2) && (x == 0 || !white(x - 1, kTessSize / 2));
    return w;
}

// tests/data/d3d10/tessellation.fx draws one domain triangle in wireframe with the factor TessFactor: at
// 1 it is the triangle alone (a row through its middle crosses its two slanted edges), at 8 the
// tessellator's edges cross that row many times and cover several times the pixels.
TEST(D3d10Effects, TessellationFactorsReachTheTessellator) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/tessellation.fx"), true);
    ASSERT_TRUE(renderer);
    const Wire one = renderWire(*renderer, "WireInteger", "1");
    const Wire eight = renderWire(*renderer, "WireInteger", "8");
    EXPECT_EQ(one.runs, 2);
    EXPECT_GT(one.pixels, static_cast<size_t>(2 * kTessSize));  // the outline, not a blank frame
    EXPECT_GE(eight.runs, 8);
    EXPECT_GT(eight.pixels, 3 * one.pixels);
    // fractional_odd partitioning at 8 makes 9 segments of two lengths, integer partitioning 8 equal ones.
    const Wire odd = renderWire(*renderer, "WireFractionalOdd", "8");
    EXPECT_GE(odd.runs, 8);
    EXPECT_NE(odd.pixels, eight.pixels);
    const Wire oddOne = renderWire(*renderer, "WireFractionalOdd", "1");
    EXPECT_EQ(oddOne.runs, 2);
}

// The filled domain triangle's colour is half its SV_DomainLocation plus half a patch constant: every
// pixel inside it equals what the pixel centre's barycentric coordinates give, so u, v and w reach the
// domain shader at the corners the DS puts them and the patch constant crosses from the hull shader.
TEST(D3d10Effects, DomainLocationAndPatchConstantsReachTheDomainShader) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/tessellation.fx"), true);
    ASSERT_TRUE(renderer);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("TessFactor", "5", diagnostics)) << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene("teapot"), kTessSize, kTessSize, "Corners"));
    const runtime::FrameImage frame = renderer->readFrame();
    // The corners in clip space (y up); frame rows run from the top.
    const glm::vec2 a(-0.9f, -0.9f), b(0.0f, 0.9f), c(0.9f, -0.9f);
    const glm::vec3 tint(0.25f, 0.5f, 0.75f);
    size_t inside = 0, wrong = 0;
    for (int y = 0; y < kTessSize; ++y)
        for (int x = 0; x < kTessSize; ++x) {
            const glm::vec2 p((x + 0.5f) / kTessSize * 2 - 1, 1 - (y + 0.5f) / kTessSize * 2);
            const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
            const float v = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
            const float w = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
            const glm::vec3 uvw(1 - v - w, v, w);
            if (glm::min(uvw.x, glm::min(uvw.y, uvw.z)) < 0.03f) continue;  // outside or on an edge
            ++inside;
            const glm::vec3 expected = (0.5f * uvw + 0.5f * tint) * 255.0f;
            const uint8_t* got = &frame.rgba[(static_cast<size_t>(y) * kTessSize + x) * 4];
            for (int k = 0; k < 3; ++k) wrong += std::abs(got[k] - expected[k]) > 3.0f;
        }
    EXPECT_GT(inside, static_cast<size_t>(kTessSize * kTessSize / 4));
    EXPECT_EQ(wrong, 0u);
}

// Through VS -> HS -> DS -> PS at factor 1 the meshes come out as the plain pass draws them, back faces
// culled by D3D10's default rasterizer state: the control points and their float3 POSITION link by
// semantic, and the tessellator winds its triangles as the mesh does.
// So does a quad domain (Frank Luna's D3D11 tessellation samples), each triangle a quad patch whose third
// corner comes twice.
TEST(D3d10Effects, TessellatedMeshAtFactorOneDrawsTheFrameOfThePlainPass) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/tessellation.fx"), true);
    ASSERT_TRUE(renderer);
    fx::DiagnosticList diagnostics;
    ASSERT_TRUE(renderer->setParameterFromText("TessFactor", "1", diagnostics)) << diagnostics.str();
    ASSERT_TRUE(render(*renderer, scene("teapot"), kTessSize, kTessSize, "Plain"));
    const runtime::FrameImage plain = renderer->readFrame();
    ASSERT_TRUE(notConstant(plain));
    for (const char* technique : {"Mesh", "QuadMesh"}) {
        SCOPED_TRACE(technique);
        ASSERT_TRUE(render(*renderer, scene("teapot"), kTessSize, kTessSize, technique));
        const runtime::FrameImage tessellated = renderer->readFrame();
        size_t differing = 0;
        for (size_t i = 0; i + 3 < plain.rgba.size(); i += 4)
            for (int k = 0; k < 3; ++k)
                if (std::abs(plain.rgba[i + k] - tessellated.rgba[i + k]) > 2) {
                    ++differing;
                    break;
                }
        EXPECT_LE(differing, static_cast<size_t>(kTessSize * kTessSize / 200));
    }
}

// [SECTION] Compile expressions

// Two pixel shaders of one name told apart by a uniform parameter, as the D3D11 book's texture viewer
// has them: CompileShader(ps_5_0, Show()) compiles the overload without one, Show(1) and Show(2) the one
// with; each technique draws its own colour (the first overload alone was taken before, and Show(1)
// refused).
TEST(D3d10Effects, CompileArgumentsChooseTheOverloadOfTheirUniformParameterCount) {
    auto renderer = loadEffect(R"(
float4 Show(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Target { return float4(1, 1, 1, 1); }
float4 Show(float4 p : SV_Position, float2 uv : TEXCOORD0, uniform int channel) : SV_Target
{
    float4 c = float4(0, 0, 0, 1);
    c[channel] = 1;
    return c;
}
)" + fullScreenTechniques({}) + R"(
technique11 Whole < string Script = "Pass=p;"; > { pass p < string Script = "Draw=Buffer;"; > {
    SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, Show())); SetDepthStencilState(NoDepth, 0); SetRasterizerState(NoCulling); } }
technique11 Green < string Script = "Pass=p;"; > { pass p < string Script = "Draw=Buffer;"; > {
    SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, Show(1))); SetDepthStencilState(NoDepth, 0); SetRasterizerState(NoCulling); } }
technique11 Blue < string Script = "Pass=p;"; > { pass p < string Script = "Draw=Buffer;"; > {
    SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, Show(2))); SetDepthStencilState(NoDepth, 0); SetRasterizerState(NoCulling); } }
)",
                               false, "overloads.fx");
    ASSERT_TRUE(renderer);
    const runtime::Scene boxes = scene("boxes");
    const std::pair<const char*, std::array<int, 3>> expected[] = {
        {"Whole", {255, 255, 255}}, {"Green", {0, 255, 0}}, {"Blue", {0, 0, 255}}};
    for (const auto& [technique, color] : expected) {
        SCOPED_TRACE(technique);
        ASSERT_TRUE(render(*renderer, boxes, kStripWidth, kStripHeight, technique));
        EXPECT_TRUE(isColor(third(renderer->readFrame(), 1), color[0], color[1], color[2]));
    }
}

// [SECTION] SAS scripts on the D3D11 form

TEST(D3d10Effects, Technique11TwinRendersTheFrameOfItsD3d9Technique) {
    auto renderer = loadEffect(R"(
float Script : STANDARDSGLOBAL < string ScriptClass = "object"; string ScriptOrder = "standard";
    string ScriptOutput = "color"; string Script = "Technique=Technique?Lit11:Lit9;"; > = 0.8;
float4x4 Wvp : WorldViewProjection;
float4x4 World : World;
float4x4 WorldIT : WorldInverseTranspose;
float3 Lamp : POSITION < string Object = "PointLight0"; string Space = "World"; > = {2, 4, 3};
struct VIn { float4 P : POSITION; float3 N : NORMAL; };
struct VOut { float4 P : POSITION; float3 N : TEXCOORD0; float3 L : TEXCOORD1; };
VOut VS(VIn i)
{
    VOut o;
    o.P = mul(float4(i.P.xyz, 1), Wvp);
    o.N = mul(i.N, (float3x3)WorldIT);
    o.L = Lamp - mul(float4(i.P.xyz, 1), World).xyz;
    return o;
}
float4 PS(VOut i) : COLOR { return float4(saturate(dot(normalize(i.N), normalize(i.L))) * float3(0.9, 0.6, 0.3) + 0.1, 1); }
DepthStencilState LessEqual { DepthFunc = LESS_EQUAL; };
technique Lit9 < string Script = "Pass=p0;"; >
{
    pass p0 < string Script = "Draw=geometry;"; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); ZFunc = LessEqual; CullMode = CCW; }
}
technique11 Lit11 < string Script = "Pass=p0;"; >
{
    pass p0 < string Script = "Draw=geometry;"; >
    { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS()));
      SetDepthStencilState(LessEqual, 0); }
}
)",
                               false, "twins.fx");
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Lit9"));
    const runtime::FrameImage d3d9 = renderer->readFrame();
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Lit11"));
    const runtime::FrameImage d3d11 = renderer->readFrame();
    ASSERT_TRUE(notConstant(d3d9));
    EXPECT_TRUE(d3d9.rgba == d3d11.rgba);
}

// [SECTION] Parameters bound by their conventional names

// FX11 and D3DX applications set parameters by name, so effects written for them carry no semantics. Each
// naming style below must draw the frame its explicit-semantic counterpart draws; a name outside the
// conventions stays the user's (zero here) and draws nothing.
const char* kNamedEffect = R"(
float4x4 Wvp : WorldViewProjection;
float4x4 SemWorld : World;
float4x4 SemWorldIT : WorldInverseTranspose;
float4x4 SemViewProj : ViewProjection;
float3 SemEye : CameraPosition;
cbuffer cbPerObject { float4x4 gWorldViewProj; float4x4 gWorld; float4x4 gWorldInvTranspose; };
matrix World; matrix View; matrix Projection;
float4x4 g_mWorldViewProjection;
float4x4 matViewProj;
float3 gEyePosW;
float4x4 gTransform;

struct Lit { float4 pos : SV_Position; float3 normal : NORMAL; float3 toEye : TEXCOORD0; };
float4 Red() : SV_Target { return float4(1, 0, 0, 1); }
float4 Shade(Lit i) : SV_Target {
    return float4(saturate(dot(normalize(i.normal), normalize(i.toEye))).xxx, 1);
}
float4 BySemantic(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), Wvp); }
float4 Luna(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), gWorldViewProj); }
float4 Tutorial(float3 p : POSITION) : SV_Position {
    return mul(mul(mul(float4(p, 1), World), View), Projection);
}
float4 Dxut(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), g_mWorldViewProjection); }
float4 Unconventional(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), gTransform); }
Lit LitBySemantic(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    float4 w = mul(float4(p, 1), SemWorld);
    o.pos = mul(w, SemViewProj);
    o.normal = mul(n, (float3x3)SemWorldIT);
    o.toEye = SemEye - w.xyz;
    return o;
}
Lit LitByName(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    float4 w = mul(float4(p, 1), gWorld);
    o.pos = mul(w, matViewProj);
    o.normal = mul(n, (float3x3)gWorldInvTranspose);
    o.toEye = gEyePosW - w.xyz;
    return o;
}
technique11 Semantic { pass { SetVertexShader(CompileShader(vs_5_0, BySemantic())); SetPixelShader(CompileShader(ps_5_0, Red())); } }
technique11 LunaStyle { pass { SetVertexShader(CompileShader(vs_5_0, Luna())); SetPixelShader(CompileShader(ps_5_0, Red())); } }
technique10 TutorialStyle { pass { SetVertexShader(CompileShader(vs_4_0, Tutorial())); SetPixelShader(CompileShader(ps_4_0, Red())); } }
technique10 DxutStyle { pass { SetVertexShader(CompileShader(vs_4_0, Dxut())); SetPixelShader(CompileShader(ps_4_0, Red())); } }
technique11 NoConvention { pass { SetVertexShader(CompileShader(vs_5_0, Unconventional())); SetPixelShader(CompileShader(ps_5_0, Red())); } }
technique11 LitSemantic { pass { SetVertexShader(CompileShader(vs_5_0, LitBySemantic())); SetPixelShader(CompileShader(ps_5_0, Shade())); } }
technique11 LitNames { pass { SetVertexShader(CompileShader(vs_5_0, LitByName())); SetPixelShader(CompileShader(ps_5_0, Shade())); } }
)";

// Effects written in the styles of D3D10/11 code in the wild (SDK samples and tutorials, a textbook's
// lit effects, FX10 pools, full-screen passes, later HLSL), none with semantics: every technique of each
// compiles, links and draws a frame that is not one colour.
TEST(D3d10Effects, EffectsInTheStylesOfForeignCodeRenderEveryTechnique) {
    size_t effects = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/data/d3d10/styles"))) {
        if (entry.path().extension() != ".fx") continue;
        ++effects;
        auto renderer = loadEffect(entry.path().string(), true);
        ASSERT_TRUE(renderer) << entry.path();
        ASSERT_FALSE(renderer->effect().techniques.empty()) << entry.path();
        for (const fx::CompiledTechnique& technique : renderer->effect().techniques) {
            ASSERT_TRUE(render(*renderer, scene("teapot"), 96, 72, technique.name))
                << entry.path() << " " << technique.name;
            EXPECT_TRUE(notConstant(renderer->readFrame())) << entry.path() << " " << technique.name;
        }
    }
    EXPECT_GE(effects, 6u);
}

// A struct-typed cbuffer member no application set reads zero, as in D3D10: the object is drawn in the
// grey the code adds to it, not in colours from stray block contents. (A light's or a material's struct
// is bound by its members' names: LightsAndMaterialsInStructsBindByTheirMembersNames.)
TEST(D3d10Effects, StructMembersOfConstantBuffersReadZeroUntilSet) {
    auto renderer = loadEffect(R"(
struct Surface { float4 Diffuse; float4 Specular; };
cbuffer cbPerObject { float4x4 gWorldViewProj; Surface gSurface; float4 gTint = float4(0, 0, 1, 1); };
float4 VS(float3 p : POSITION) : SV_Position { return mul(float4(p, 1), gWorldViewProj); }
float4 PS() : SV_Target { return gSurface.Diffuse + gSurface.Specular + float4(0.5, 0.5, 0, 1) + gTint; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)",
                               false, "material.fx");
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    size_t drawn = 0;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4)
        drawn += frame.rgba[i] == 128 && frame.rgba[i + 1] == 128 && frame.rgba[i + 2] == 255;
    EXPECT_GT(drawn, 1000u);
}

TEST(D3d10Effects, ParametersWithoutSemanticsBindByTheirConventionalNames) {
    auto renderer = loadEffect(kNamedEffect, false, "named.fx");
    ASSERT_TRUE(renderer);
    const Counts semantic = renderCounts(*renderer, "Semantic");
    ASSERT_GT(semantic.red, 1000u);
    for (const char* technique : {"LunaStyle", "TutorialStyle", "DxutStyle"}) {
        const Counts named = renderCounts(*renderer, technique);
        EXPECT_EQ(named.red, semantic.red) << technique;
    }
    EXPECT_EQ(renderCounts(*renderer, "NoConvention").red, 0u);

    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "LitSemantic"));
    const runtime::FrameImage bySemantic = renderer->readFrame();
    ASSERT_TRUE(notConstant(bySemantic));
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "LitNames"));
    EXPECT_TRUE(renderer->readFrame().rgba == bySemantic.rgba);
}

// The twin the by-name techniques below are compared with: the same lighting read through semantics, the
// sun light0 and the fill light1 (LightDirection points away from the light).
const std::string kSemanticLights = R"(
float4x4 g_mWorld;
float4x4 g_mWorldViewProjection;
float4 SemDiffuse : Diffuse;
float4 SemAmbient : Ambient;
float3 Sun : LightDirection < string Object = "light0"; >;
float4 SunColour : LightColor < string Object = "light0"; >;
float3 Fill : LightDirection < string Object = "light1"; >;
float4 FillColour : LightColor < string Object = "light1"; >;
struct Lit { float4 pos : SV_Position; float4 colour : COLOR0; };
Lit BySemantic(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    o.pos = mul(float4(p, 1), g_mWorldViewProjection);
    float3 normal = normalize(mul(n, (float3x3)g_mWorld));
    float3 diffuse = SunColour.rgb * max(0, dot(normal, -Sun)) + FillColour.rgb * max(0, dot(normal, -Fill));
    o.colour = float4(SemDiffuse.rgb * diffuse + SemDiffuse.rgb * SemAmbient.rgb, 1);
    return o;
}
float4 Colour(Lit i) : SV_Target { return i.colour; }
technique10 Semantic { pass { SetVertexShader(CompileShader(vs_4_0, BySemantic())); SetPixelShader(CompileShader(ps_4_0, Colour())); } }
)";

// An effect in the style of the DirectX SDK's samples, whose application set the lights and the material
// by name (BasicHLSL's g_LightDir[3], g_LightDiffuse[3], g_MaterialDiffuseColor, ...), none with an
// initializer. A D3D sample's light direction points towards the light (`dot(N, g_LightDir)`).
const std::string kApplicationSetLights = kSemanticLights + R"(
float4x4 g_mView;
float4 g_MaterialDiffuseColor;
float4 g_MaterialAmbientColor;
float4 g_LightAmbient;
int g_nNumLights;
float3 g_LightDir[3];
float4 g_LightDiffuse[3];
float3 g_vLightDirView;
Lit ByName(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    o.pos = mul(float4(p, 1), g_mWorldViewProjection);
    float3 normal = normalize(mul(n, (float3x3)g_mWorld));
    float3 diffuse = 0;
    for (int i = 0; i < g_nNumLights; i++)
        diffuse += g_LightDiffuse[i].rgb * max(0, dot(normal, g_LightDir[i]));
    o.colour = float4(g_MaterialDiffuseColor.rgb * diffuse + g_MaterialAmbientColor.rgb * g_LightAmbient.rgb, 1);
    return o;
}
Lit ViewSpaceByName(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    o.pos = mul(float4(p, 1), g_mWorldViewProjection);
    float3 normal = normalize(mul(mul(n, (float3x3)g_mWorld), (float3x3)g_mView));
    o.colour = float4(max(0, dot(normal, g_vLightDirView)).xxx, 1);
    return o;
}
Lit ViewSpaceBySemantic(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    o.pos = mul(float4(p, 1), g_mWorldViewProjection);
    float3 normal = normalize(mul(mul(n, (float3x3)g_mWorld), (float3x3)g_mView));
    o.colour = float4(max(0, dot(normal, mul(-Sun, (float3x3)g_mView))).xxx, 1);
    return o;
}
technique10 Named { pass { SetVertexShader(CompileShader(vs_4_0, ByName())); SetPixelShader(CompileShader(ps_4_0, Colour())); } }
technique10 ViewNamed { pass { SetVertexShader(CompileShader(vs_4_0, ViewSpaceByName())); SetPixelShader(CompileShader(ps_4_0, Colour())); } }
technique10 ViewSemantic { pass { SetVertexShader(CompileShader(vs_4_0, ViewSpaceBySemantic())); SetPixelShader(CompileShader(ps_4_0, Colour())); } }
)";

// XNA's and MonoGame's stock effects number their lights (DirLight0Direction, DirLight1DiffuseColor, ...),
// their directions pointing the way the light travels.
const std::string kNumberedLights = kSemanticLights + R"(
float4 DiffuseColor;
float3 AmbientLightColor;
float3 DirLight0Direction;
float3 DirLight0DiffuseColor;
float3 DirLight1Direction;
float3 DirLight1DiffuseColor;
Lit ByName(float3 p : POSITION, float3 n : NORMAL) {
    Lit o;
    o.pos = mul(float4(p, 1), g_mWorldViewProjection);
    float3 normal = normalize(mul(n, (float3x3)g_mWorld));
    float3 diffuse = DirLight0DiffuseColor * max(0, dot(normal, -DirLight0Direction)) +
                     DirLight1DiffuseColor * max(0, dot(normal, -DirLight1Direction));
    o.colour = float4(DiffuseColor.rgb * diffuse + DiffuseColor.rgb * AmbientLightColor, 1);
    return o;
}
technique10 Numbered { pass { SetVertexShader(CompileShader(vs_4_0, ByName())); SetPixelShader(CompileShader(ps_4_0, Colour())); } }
)";

// Frames equal up to one step of 8 bits in any channel (the twins add the same terms in another order).
::testing::AssertionResult nearlyEqual(const runtime::FrameImage& a, const runtime::FrameImage& b) {
    if (a.rgba.size() != b.rgba.size()) return ::testing::AssertionFailure() << "sizes differ";
    for (size_t i = 0; i < a.rgba.size(); ++i)
        if (std::abs(int(a.rgba[i]) - int(b.rgba[i])) > 1)
            return ::testing::AssertionFailure()
                   << "byte " << i << ": " << int(a.rgba[i]) << " vs " << int(b.rgba[i]);
    return ::testing::AssertionSuccess();
}

// The teapot scene's sun, light0, and a bluish fill light from the side, light1.
runtime::Scene teapotWithFill() {
    runtime::Scene twoLights = scene("teapot");
    EXPECT_EQ(twoLights.lights.size(), 1u);
    runtime::Light fill;
    fill.name = "light1";
    fill.direction = glm::normalize(glm::vec3(0.8f, -0.2f, 0.6f));
    fill.color = glm::vec3(0.2f, 0.5f, 0.9f);
    twoLights.lights.push_back(fill);
    return twoLights;
}

TEST(D3d10Effects, NumberedLightsAnApplicationSetByNameAreTheScenes) {
    auto renderer = loadEffect(kNumberedLights, false, "numbered_lights.fx");
    ASSERT_TRUE(renderer);
    runtime::Scene twoLights = teapotWithFill();
    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "Semantic"));
    const runtime::FrameImage bySemantic = renderer->readFrame();
    ASSERT_TRUE(notConstant(bySemantic));
    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "Numbered"));
    EXPECT_TRUE(nearlyEqual(renderer->readFrame(), bySemantic));
    // DirLight1 is the scene's second light, whatever a scene that numbers none of its lights calls it.
    twoLights.lights[0].name = "sun";
    twoLights.lights[1].name = "fill";
    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "Numbered"));
    EXPECT_TRUE(nearlyEqual(renderer->readFrame(), bySemantic));
}

TEST(D3d10Effects, LightsAndMaterialsAnApplicationSetByNameAreTheScenes) {
    auto renderer = loadEffect(kApplicationSetLights, false, "application_lights.fx");
    ASSERT_TRUE(renderer);
    runtime::Scene twoLights = teapotWithFill();

    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "Semantic"));
    const runtime::FrameImage bySemantic = renderer->readFrame();
    ASSERT_TRUE(notConstant(bySemantic));
    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "Named"));
    const runtime::FrameImage byName = renderer->readFrame();
    EXPECT_TRUE(nearlyEqual(byName, bySemantic));
    // Without the application's values the frame is black on the clear colour: a lit frame has shades.
    std::set<uint32_t> colours;
    for (size_t i = 0; i + 3 < byName.rgba.size(); i += 4)
        colours.insert(uint32_t(byName.rgba[i]) << 16 | uint32_t(byName.rgba[i + 1]) << 8 |
                       byName.rgba[i + 2]);
    EXPECT_GT(colours.size(), 50u);

    // The second light is element 1 and g_nNumLights counts it: with the scene's one light, another frame.
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Named"));
    EXPECT_FALSE(nearlyEqual(renderer->readFrame(), byName));

    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "ViewSemantic"));
    const runtime::FrameImage viewBySemantic = renderer->readFrame();
    ASSERT_TRUE(notConstant(viewBySemantic));
    ASSERT_TRUE(render(*renderer, twoLights, kWidth, kHeight, "ViewNamed"));
    EXPECT_TRUE(nearlyEqual(renderer->readFrame(), viewBySemantic));
}

// Luna's lights and material in structs (tests/data/d3d10/struct_lights.fx): each member bound by its name
// in its struct's context, so that his lighting lights the teapot; unbound, every member is zero and every
// pixel of the teapot black.
const fx::MemberBinding* memberBinding(const fx::CompiledEffect& effect, const std::string& parameter,
                                       const std::string& member) {
    const fx::ParameterInfo* info = effect.findParameter(parameter);
    if (!info) return nullptr;
    for (const fx::MemberBinding& binding : info->memberBindings)
        if (binding.member == member) return &binding;
    return nullptr;
}

double summedLuminance(const runtime::FrameImage& frame) {
    double sum = 0.0;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4) sum += luminance(&frame.rgba[i]);
    return sum;
}

TEST(D3d10Effects, LightsAndMaterialsInStructsBindByTheirMembersNames) {
    LoadedEffect loaded = loadEffectWithDiagnostics(sourcePath("tests/data/d3d10/struct_lights.fx"));
    ASSERT_TRUE(loaded.renderer);
    const fx::CompiledEffect& effect = loaded.renderer->effect();
    const fx::MemberBinding* materialDiffuse = memberBinding(effect, "gMaterial", "Diffuse");
    ASSERT_TRUE(materialDiffuse);
    EXPECT_EQ(materialDiffuse->standard.kind, fx::SemanticKind::ObjectColor);
    const fx::MemberBinding* lightDiffuse = memberBinding(effect, "gDirLights", "Diffuse");
    ASSERT_TRUE(lightDiffuse);
    EXPECT_EQ(lightDiffuse->standard.kind, fx::SemanticKind::LightColor);
    EXPECT_TRUE(lightDiffuse->standard.eachLight);
    EXPECT_EQ(countDiagnostics(loaded.diagnostics, fx::DiagId::MemberBoundByName),
              static_cast<int>(effect.findParameter("gDirLights")->memberBindings.size() +
                               effect.findParameter("gPointLight")->memberBindings.size() +
                               effect.findParameter("gMaterial")->memberBindings.size()));

    ASSERT_TRUE(render(*loaded.renderer, scene("teapot"), kWidth, kHeight, "DirectionalOnly"));
    const runtime::FrameImage lit = loaded.renderer->readFrame();
    ASSERT_TRUE(notConstant(lit));
    // Shaded: many colours, and lit pixels as bright as a white light on the teapot's grey makes them
    // (a frame with the members unbound has the clear colour and black).
    std::set<uint32_t> colours;
    size_t bright = 0;
    for (size_t i = 0; i + 3 < lit.rgba.size(); i += 4) {
        colours.insert(uint32_t(lit.rgba[i]) << 16 | uint32_t(lit.rgba[i + 1]) << 8 | lit.rgba[i + 2]);
        bright += luminance(&lit.rgba[i]) > 0.6f;
    }
    EXPECT_GT(colours.size(), 50u);
    EXPECT_GT(bright, lit.rgba.size() / 4 / 50);

    // Element 1 is the scene's second light: the fill light adds to the frame.
    ASSERT_TRUE(render(*loaded.renderer, teapotWithFill(), kWidth, kHeight, "DirectionalOnly"));
    EXPECT_GT(summedLuminance(loaded.renderer->readFrame()), summedLuminance(lit) * 1.02);
    // The point light reaches the teapot from the sun's eye, its range covering the scene, unattenuated.
    ASSERT_TRUE(render(*loaded.renderer, scene("teapot"), kWidth, kHeight, "WithPointLight"));
    EXPECT_GT(summedLuminance(loaded.renderer->readFrame()), summedLuminance(lit) * 1.02);
}

// Skinning palettes only the application fills, on meshes without skin: the DirectX SDK's SkinnedMesh
// (WORLDMATRIXARRAY: bones placed in the world; NumBones - 1 weights read, the last one 1 minus their sum)
// and XNA's SkinnedEffect (`Bones`, then World; the weights read as they are) draw each object as modelled,
// where it stands, as the plain transform does.
const char* kSkinningPalettes = R"(
float4x4 WorldViewProj : WorldViewProjection;
float4x4 ViewProj : ViewProjection;
float4x4 World;
float4x3 mWorldMatrixArray[26] : WORLDMATRIXARRAY;
float4x3 Bones[72];
struct Drawn { float4 pos : POSITION; float4 colour : COLOR0; };
Drawn Plain(float4 p : POSITION) {
    Drawn o = { mul(p, WorldViewProj), float4(1, 0, 0, 1) };
    return o;
}
Drawn SdkSkin(float4 p : POSITION, float4 weights : BLENDWEIGHT, float4 indices : BLENDINDICES,
              uniform int NumBones) {
    int4 index = (int4)indices;
    float3 position = 0;
    float last = 0;
    for (int i = 0; i < NumBones - 1; i++) {
        last += weights[i];
        position += mul(p, mWorldMatrixArray[index[i]]) * weights[i];
    }
    position += mul(p, mWorldMatrixArray[index[NumBones - 1]]) * (1 - last);
    Drawn o = { mul(float4(position, 1), ViewProj), float4(1, 0, 0, 1) };
    return o;
}
Drawn XnaSkin(float4 p : POSITION, int4 indices : BLENDINDICES0, float4 weights : BLENDWEIGHT0) {
    float4x3 skinning = 0;
    for (int i = 0; i < 2; i++) skinning += Bones[indices[i]] * weights[i];
    Drawn o = { mul(mul(float4(mul(p, skinning), 1), World), ViewProj), float4(1, 0, 0, 1) };
    return o;
}
float4 Colour(float4 c : COLOR0) : COLOR { return c; }
technique Plain { pass { VertexShader = compile vs_3_0 Plain(); PixelShader = compile ps_3_0 Colour(); } }
technique Sdk { pass { VertexShader = compile vs_3_0 SdkSkin(3); PixelShader = compile ps_3_0 Colour(); } }
technique Xna { pass { VertexShader = compile vs_3_0 XnaSkin(); PixelShader = compile ps_3_0 Colour(); } }
)";

TEST(D3d10Effects, SkinningPalettesAnApplicationSetDrawTheMeshAsModelled) {
    auto renderer = loadEffect(kSkinningPalettes, false, "skinning_palettes.fx");
    ASSERT_TRUE(renderer);
    const fx::ParameterInfo* bones = renderer->effect().findParameter("Bones");
    ASSERT_TRUE(bones);
    EXPECT_EQ(bones->standard.kind, fx::SemanticKind::BonePalette);
    // The boxes stand apart, each with its own World: every element of the SDK's palette is the object's.
    const runtime::Scene boxes = scene("boxes");
    ASSERT_TRUE(render(*renderer, boxes, kWidth, kHeight, "Plain"));
    const size_t plain = countRedGreen(renderer->readFrame()).red;
    ASSERT_GT(plain, 1000u);
    for (const char* technique : {"Sdk", "Xna"}) {
        ASSERT_TRUE(render(*renderer, boxes, kWidth, kHeight, technique));
        const runtime::FrameImage frame = renderer->readFrame();
        const size_t red = countRedGreen(frame).red;
        // The same coverage, up to edge pixels the differently rounded products move.
        EXPECT_NEAR(double(red), double(plain), plain * 0.01) << technique;
    }
}

// [SECTION] Input layouts, stream output, blending and sample counts

// Loads an effect file keeping the diagnostics of parsing, compiling and creating its renderer.
std::unique_ptr<runtime::EffectRenderer> loadKeeping(const std::string& file,
                                                     fx::DiagnosticList& diagnostics) {
    sharedContext();
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(file, fx::ParseOptions{}, diagnostics);
    if (!effect) return nullptr;
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    if (!compiled || diagnostics.hasErrors()) return nullptr;
    return runtime::EffectRenderer::create(compiled, diagnostics);
}

// "file:line:column: severity: message" of each diagnostic with `id`, as the CLI prints them.
std::vector<std::string> messagesOf(const fx::DiagnosticList& diagnostics, fx::DiagId id) {
    std::vector<std::string> out;
    for (const fx::Diagnostic& d : diagnostics.items())
        if (d.id == id)
            out.push_back(d.loc.file + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
                          ": " + std::string(fx::severityName(d.severity)) + ": " + d.message);
    return out;
}

TEST(D3d10Effects, VertexInputsOfAnyNameAndInstanceRowsRenderTheFrameOfTheD3d9Names) {
    fx::DiagnosticList diagnostics;
    auto renderer = loadKeeping(sourcePath("tests/data/d3d10/input_layout_names.fx"), diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    // The inputs no stream fits are named once each, at their declarations.
    const std::vector<std::string> notes = messagesOf(diagnostics, fx::DiagId::VertexInputConstant);
    ASSERT_EQ(notes.size(), 2u) << diagnostics.str();
    EXPECT_NE(notes[0].find("input_layout_names.fx:19:"), std::string::npos) << notes[0];
    EXPECT_NE(notes[0].find("vertex input 'INST0' matches no mesh stream by its name; it reads the constant "
                            "float4(0, 0, 0, 0)"),
              std::string::npos)
        << notes[0];
    const std::vector<std::string> matrices = messagesOf(diagnostics, fx::DiagId::VertexInputMatrixIdentity);
    ASSERT_EQ(matrices.size(), 1u) << diagnostics.str();
    EXPECT_NE(matrices[0].find("vertex input 'MTRANSFORM0' is a matrix"), std::string::npos) << matrices[0];
    const std::vector<std::string> rows = messagesOf(diagnostics, fx::DiagId::VertexInputInstanceRow);
    ASSERT_EQ(rows.size(), 4u) << diagnostics.str();
    EXPECT_NE(rows[3].find("vertex input 'TEXCOORD4' is row 3 of a per-instance transform"),
              std::string::npos)
        << rows[3];
    EXPECT_NE(rows[3].find("it reads the identity's row float4(0, 0, 0, 1)"), std::string::npos) << rows[3];

    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Named"));
    const runtime::FrameImage named = renderer->readFrame();
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Layout"));
    const runtime::FrameImage layout = renderer->readFrame();
    EXPECT_TRUE(layout.rgba == named.rgba);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Rows"));
    EXPECT_TRUE(renderer->readFrame().rgba == named.rgba);
    // A matrix of the mesh's own streams keeps them: the normal's z varies over the teapot (read as
    // identity rows, every pixel would be the same blue).
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight, "Frame"));
    const runtime::FrameImage frame = renderer->readFrame();
    std::set<std::array<uint8_t, 3>> colours;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4)
        colours.insert({frame.rgba[i], frame.rgba[i + 1], frame.rgba[i + 2]});
    EXPECT_GT(colours.size(), 16u);
    // The frame shows the streams: the normal's |x| in red and u in green vary over the teapot, blue is 0
    // (the background, the corner's colour, excepted).
    const uint8_t* background = layout.pixel(0, 0);
    std::set<int> reds, greens;
    size_t drawn = 0, blue = 0;
    for (size_t i = 0; i + 3 < layout.rgba.size(); i += 4) {
        if (std::equal(background, background + 3, &layout.rgba[i])) continue;
        ++drawn;
        reds.insert(layout.rgba[i]);
        greens.insert(layout.rgba[i + 1]);
        blue += layout.rgba[i + 2] != 0;
    }
    EXPECT_GT(drawn, 1000u);
    EXPECT_GT(reds.size(), 64u);
    EXPECT_GT(greens.size(), 64u);
    EXPECT_EQ(blue, 0u);
}

// The SDK's geometry shaders pass TEXTURE0..TEXTURE8 on: more free-named varyings than the eight locations
// above D3D9's table, through a geometry stage to the pixel shader.
TEST(D3d10Effects, MoreThanEightFreeNamedVaryingsCrossTheGeometryStage) {
    std::string members, sum;
    for (int i = 0; i < 10; ++i) {
        members += "float Value" + std::to_string(i) + " : TEXTURE" + std::to_string(i) + "; ";
        sum += "+ v.Value" + std::to_string(i);
    }
    std::string setValues;
    for (int i = 0; i < 10; ++i) setValues += "o.Value" + std::to_string(i) + " = 0.1; ";
    auto renderer = loadEffect(R"(
float4x4 g_mWorldViewProjection;
struct Vertex { float4 Pos : SV_Position; )" +
                                   members + R"( };
Vertex VS(float3 pos : POS)
{
    Vertex o;
    o.Pos = mul(float4(pos, 1), g_mWorldViewProjection);
    )" + setValues + R"(
    return o;
}
[maxvertexcount(3)]
void GS(triangle Vertex input[3], inout TriangleStream<Vertex> stream)
{
    for (int k = 0; k < 3; ++k) stream.Append(input[k]);
}
float4 PS(Vertex v) : SV_Target { return float4(0 )" +
                                   sum + R"(, 0, 1, 1); }
technique10 T { pass { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS()));
                       SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
                               false, "varyings.fx");
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("teapot"), kWidth, kHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    size_t full = 0, other = 0;
    for (size_t i = 0; i + 3 < frame.rgba.size(); i += 4) {
        if (frame.rgba[i + 2] != 255) continue;  // the teapot: blue 1
        ++(frame.rgba[i] >= 254 ? full : other);
    }
    EXPECT_GT(full, 1000u);  // ten varyings of 0.1 each summed to 1
    EXPECT_EQ(other, 0u);
}

TEST(D3d10Effects, EachRenderTargetBlendsByItsOwnBlendStateFields) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/independent_blend.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight, "PerTarget"));
    const runtime::FrameImage frame = renderer->readFrame();
    EXPECT_TRUE(isColor(third(frame, 0), 191, 191, 191));  // 0.25 + 0.5: ONE + ONE
    EXPECT_TRUE(isColor(third(frame, 1), 128, 128, 128));  // not blended: no BlendEnable[1]
    EXPECT_TRUE(isColor(third(frame, 2), 64, 64, 64));     // ZERO + ONE keeps the clear colour
}

TEST(D3d10Effects, DualSourceBlendingTakesTheSecondOutputAsTheFactor) {
    auto renderer = loadEffect(sourcePath("tests/data/d3d10/independent_blend.fx"), true);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight, "DualSource"));
    const runtime::FrameImage frame = renderer->readFrame();
    for (int t = 0; t < 3; ++t) EXPECT_TRUE(isColor(third(frame, t), 128, 64, 0)) << t;
}

TEST(D3d10Effects, MoreSamplesThanTheDriverHoldsGetItsMostWithAWarning) {
    const std::string source = R"(
Texture2DMS<float4, 32> Coverage : RENDERCOLORTARGET;
float4 Black = {0, 0, 0, 1};
struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
float4 QuadVS(QuadVertex v) : SV_Position { return v.Position; }
float4 White() : SV_Target { return 1; }
float4 Count(float4 p : SV_Position) : SV_Target
{
    uint w, h, samples;
    Coverage.GetDimensions(w, h, samples);
    return float4(Coverage.Load(int2(p.xy), 0).r, 0, samples / 32.0, 1);
}
DepthStencilState NoDepth { DepthEnable = FALSE; };
technique11 Msaa < string Script = "Pass=Draw; Pass=Read;"; >
{
    pass Draw < string Script = "RenderColorTarget0=Coverage; ClearSetColor=Black; Clear=Color; Draw=Buffer;"; >
    { SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, White()));
      SetDepthStencilState(NoDepth, 0); }
    pass Read < string Script = "RenderColorTarget0=; Draw=Buffer;"; >
    { SetVertexShader(CompileShader(vs_5_0, QuadVS())); SetPixelShader(CompileShader(ps_5_0, Count()));
      SetDepthStencilState(NoDepth, 0); }
}
)";
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto effect = fx::parseEffectSource(source, "samples.fx", fx::ParseOptions{}, diagnostics);
    ASSERT_TRUE(effect) << diagnostics.str();
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    const std::vector<std::string> reduced = messagesOf(diagnostics, fx::DiagId::SampleCountReduced);
    ASSERT_EQ(reduced.size(), 1u) << diagnostics.str();
    EXPECT_NE(reduced[0].find("samples.fx:2:25: warning: 'Coverage' has 32 samples per texel; this OpenGL "
                              "holds at most "),
              std::string::npos)
        << reduced[0];
    ASSERT_TRUE(render(*renderer, scene("boxes"), kStripWidth, kStripHeight));
    const runtime::FrameImage frame = renderer->readFrame();
    // Every pixel read the target's white, and the count it has is a fraction of 32 (blue), 1 or more.
    const uint8_t* first = frame.pixel(0, 0);
    EXPECT_EQ(first[0], 255);
    EXPECT_GT(first[2], 0);
    EXPECT_LT(first[2], 255);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) ASSERT_TRUE(isColor(frame.pixel(x, y), 255, 0, first[2]));
}

}  // namespace
}  // namespace shadowfx::test::test_d3d10_effects
