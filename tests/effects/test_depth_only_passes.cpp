// Depth-only passes: a pass that writes no colour (ColorWriteEnable = 0 on every bound target) draws into
// its depth-stencil target alone with the vertex stage alone (FrameExecutor::depthOnly), and the frame is
// byte for byte the frame drawn the D3D9 way (colour target bound, pixel shader run, writes masked); its
// depth clears bind the same depth target alone. And depth clears, which clear stencil too when no pass
// tests it, but not when one does.
#include "EffectHarness.h"

#include <runtime/BuiltinScenes.h>
#include <runtime/GpuProgram.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace shadowfx::test::test_depth_only_passes {
namespace {

struct Frame {
    runtime::FrameImage image;
    int depthOnlyDraws = 0;
    int depthOnlyClears = 0;
};

Frame renderWith(runtime::EffectRenderer& renderer, const runtime::Scene& scene, const std::string& technique,
                 bool depthOnlyPasses, bool leaveOut = true) {
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = 160;
    options.height = 120;
    options.technique = technique;
    options.depthOnlyPasses = depthOnlyPasses;
    options.leaveOut = leaveOut;
    runtime::FrameStats stats;
    EXPECT_TRUE(renderer.render(scene, options, diagnostics, &stats) && !diagnostics.hasErrors())
        << diagnostics.str();
    Frame frame{renderer.readFrame(), 0, 0};
    for (const runtime::PassStats& pass : stats.passes) {
        frame.depthOnlyDraws += pass.depthOnlyDraws;
        frame.depthOnlyClears += pass.depthOnlyClears;
    }
    return frame;
}

// A frame with shadows in it: light and dark receivers, not one colour.
::testing::AssertionResult hasLightAndShadow(const runtime::FrameImage& image) {
    float darkest = 1.0f, brightest = 0.0f;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float l = luminance(image.pixel(x, y));
            darkest = std::min(darkest, l);
            brightest = std::max(brightest, l);
        }
    if (brightest - darkest < 0.2f)
        return ::testing::AssertionFailure()
               << "a near-constant frame: luminance " << darkest << " to " << brightest;
    return ::testing::AssertionSuccess();
}

struct Case {
    const char* effect;
    const char* technique;
    const char* scene;
};

// GoogleTest prints a parameter's bytes unless told otherwise.
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.effect << " " << c.technique << " on " << c.scene;
}

class DepthOnlyPasses : public ::testing::TestWithParam<Case> {};

TEST_P(DepthOnlyPasses, SameBytesAsTheMaskedColourPass) {
    const Case c = GetParam();
    // One renderer each: a second frame of the same renderer would reuse the first one's shadow map.
    std::unique_ptr<runtime::EffectRenderer> first = loadEffect(sourcePath(c.effect), true);
    std::unique_ptr<runtime::EffectRenderer> second = loadEffect(sourcePath(c.effect), true);
    ASSERT_TRUE(first && second);
    const runtime::Scene scene = *runtime::makeBuiltinScene(c.scene);
    const Frame masked = renderWith(*first, scene, c.technique, false);
    const Frame depthOnly = renderWith(*second, scene, c.technique, true);
    EXPECT_EQ(masked.depthOnlyDraws, 0);
    EXPECT_EQ(masked.depthOnlyClears, 0);
    EXPECT_GT(depthOnly.depthOnlyDraws, 0) << "the light pass writes no colour: it should draw depth only";
    EXPECT_GT(depthOnly.depthOnlyClears, 0) << "its depth clear should bind the depth-only draw's target";
    EXPECT_TRUE(hasLightAndShadow(depthOnly.image));
    ASSERT_EQ(masked.image.rgba.size(), depthOnly.image.rgba.size());
    EXPECT_TRUE(masked.image.rgba == depthOnly.image.rgba) << "the depth-only pass changed the frame";
}

INSTANTIATE_TEST_SUITE_P(ShippedEffects, DepthOnlyPasses,
                         ::testing::Values(Case{"effects/thesis_fxcomposer.fx", "hardware", "boxes"},
                                           Case{"effects/bias.fx", "slope_state", "dual-l"},
                                           Case{"effects/depth_formats.fx", "d24", "double-torus"}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return std::string(info.param.technique);
                         });

// A pixel shader that discards decides which fragments write depth: its pass keeps it (and its targets).
TEST(DepthOnlyPasses, APixelShaderThatDiscardsIsKept) {
    std::unique_ptr<runtime::EffectRenderer> renderer = loadEffect(R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Map : RENDERCOLORTARGET < float2 Dimensions = {64, 64}; string Format = "R32F"; >;
texture MapDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 64}; string Format = "D24S8"; >;
struct Out { float4 Position : POSITION; float X : TEXCOORD0; };
Out VS(float4 p : POSITION) { Out o; o.Position = mul(float4(p.xyz, 1), WorldViewProjection); o.X = p.x; return o; }
float4 Clipped(Out i) : COLOR { clip(frac(i.X) - 0.5); return 1; }
float4 Plain(Out i) : COLOR { return 1; }
technique t < string Script = "Pass=Depth; Pass=Show;"; > {
    pass Depth < string Script = "RenderColorTarget0=Map; RenderDepthStencilTarget=MapDepth; Clear=Depth; Draw=Geometry;"; >
    { ColorWriteEnable = 0; ZEnable = true; ZWriteEnable = true;
      VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Clipped(); }
    pass Show < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Plain(); }
}
)",
                                                                   false, "clipped.fx");
    ASSERT_TRUE(renderer);
    const fx::CompiledPass& depth = renderer->effect().techniques[0].passes[0];
    const fx::CompiledPass& show = renderer->effect().techniques[0].passes[1];
    EXPECT_TRUE(runtime::GpuProgram::pixelShaderHasSideEffects(depth.fragment)) << depth.fragment.glsl;
    EXPECT_FALSE(runtime::GpuProgram::pixelShaderHasSideEffects(show.fragment)) << show.fragment.glsl;
    // Leave-out off: nothing reads MapDepth, so leave-out would drop the pass as dead.
    const Frame frame = renderWith(*renderer, *runtime::makeBuiltinScene("boxes"), "t", true);
    EXPECT_EQ(frame.depthOnlyDraws, 0);
}

// A depth-only pass's clears: the depth and stencil clears bind the depth target alone, where the pass's
// draw does, the colour clear its colour target (cleared to grey and never drawn, the map the scene pass
// shows on the boxes). A colour target smaller than the depth target keeps both bound: GL clears only where
// they overlap, which the depth target alone would not.
TEST(DepthOnlyClears, LeaveTheTargetsAsTheMaskedPassDoes) {
    const auto effect = [](int colourSize) {
        const std::string size = std::to_string(colourSize);
        return R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Map : RENDERCOLORTARGET < float2 Dimensions = {)" +
               size + ", " + size + R"(}; string Format = "A8R8G8B8"; >;
texture MapDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 64}; string Format = "D24S8"; >;
sampler MapSampler = sampler_state { Texture = <Map>; MinFilter = Point; MagFilter = Point; };
float4 Grey = {0.5, 0.5, 0.5, 1};
float4 Black = {0, 0, 0, 1};
struct Out { float4 Position : POSITION; float2 Uv : TEXCOORD0; };
Out VS(float4 p : POSITION) { Out o; o.Position = mul(float4(p.xyz, 1), WorldViewProjection); o.Uv = o.Position.xy / o.Position.w * 0.5 + 0.5; return o; }
float4 White() : COLOR { return 1; }
float4 Show(Out i) : COLOR { return tex2D(MapSampler, i.Uv) + 0.25; }
technique t < string Script = "Pass=Depth; Pass=Scene;"; > {
    pass Depth < string Script = "RenderColorTarget0=Map; RenderDepthStencilTarget=MapDepth; ClearSetColor=Grey; Clear=Color; Clear=Depth; Clear=Stencil; Draw=Geometry;"; >
    { ColorWriteEnable = 0; ZEnable = true; ZWriteEnable = true;
      VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 White(); }
    pass Scene < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; ClearSetColor=Black; Clear=Color; Clear=Depth; Draw=Geometry;"; >
    { ZEnable = true; ZWriteEnable = true;
      VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Show(); }
}
)";
    };
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    for (const int colourSize : {64, 32}) {
        SCOPED_TRACE("colour target " + std::to_string(colourSize) + "², depth 64²");
        const std::string source = effect(colourSize);
        std::unique_ptr<runtime::EffectRenderer> first = loadEffect(source, false, "clears.fx");
        std::unique_ptr<runtime::EffectRenderer> second = loadEffect(source, false, "clears.fx");
        ASSERT_TRUE(first && second);
        const Frame masked = renderWith(*first, scene, "t", false, false);
        const Frame depthOnly = renderWith(*second, scene, "t", true, false);
        EXPECT_EQ(depthOnly.depthOnlyClears, colourSize == 64 ? 2 : 0) << "the depth and stencil clears";
        EXPECT_TRUE(hasLightAndShadow(depthOnly.image));
        ASSERT_EQ(masked.image.rgba.size(), depthOnly.image.rgba.size());
        EXPECT_TRUE(masked.image.rgba == depthOnly.image.rgba) << "the depth-only clears changed the frame";
    }
}

// A colour target smaller than the depth target: D3D9 draws into the colour target's viewport, the corner
// of the depth target it covers, and so must the depth-only draw that leaves the colour target out. The
// scene pass shows the depth target through a comparison: the boxes' depth where the map pass drew them.
TEST(DepthOnlyPasses, DrawIntoTheSmallerColourTargetsViewport) {
    const char* source = R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Map : RENDERCOLORTARGET < float2 Dimensions = {32, 32}; string Format = "A8R8G8B8"; >;
texture MapDepth : RENDERDEPTHSTENCILTARGET < float2 Dimensions = {64, 64}; string Format = "D24S8"; >;
sampler DepthSampler = sampler_state { Texture = <MapDepth>; MinFilter = Point; MagFilter = Point; };
float4 VS(float4 p : POSITION) : POSITION { return mul(float4(p.xyz, 1), WorldViewProjection); }
struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };
struct QuadOut { float4 Position : POSITION; float2 UV : TEXCOORD0; };
QuadOut QuadVS(QuadVertex IN) { QuadOut OUT; OUT.Position = IN.Position; OUT.UV = IN.UV; return OUT; }
float4 White() : COLOR { return 1; }
float4 Show(QuadOut i) : COLOR { return tex2Dproj(DepthSampler, float4(i.UV, 0.999, 1)).x; }
technique t < string Script = "Pass=Depth; Pass=Scene;"; > {
    pass Depth < string Script = "RenderColorTarget0=Map; RenderDepthStencilTarget=MapDepth; Clear=Depth; Draw=Geometry;"; >
    { ColorWriteEnable = 0; ZEnable = true; ZWriteEnable = true;
      VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 White(); }
    pass Scene < string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Clear=Color; Draw=Buffer;"; >
    { ZEnable = false; VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 Show(); }
}
)";
    std::unique_ptr<runtime::EffectRenderer> first = loadEffect(source, false, "corner.fx");
    std::unique_ptr<runtime::EffectRenderer> second = loadEffect(source, false, "corner.fx");
    ASSERT_TRUE(first && second);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    const Frame masked = renderWith(*first, scene, "t", false, false);
    const Frame depthOnly = renderWith(*second, scene, "t", true, false);
    EXPECT_TRUE(hasLightAndShadow(masked.image));
    ASSERT_EQ(masked.image.rgba.size(), depthOnly.image.rgba.size());
    EXPECT_TRUE(masked.image.rgba == depthOnly.image.rgba) << "the depth-only draw filled another viewport";
}

// A depth clear may take the stencil bits with it (one whole-texel clear instead of a masked one) only when
// no pass tests stencil. Here one does: the first pass marks the boxes' pixels in stencil, the second
// clears depth alone and draws white where the mark is. Were the mark cleared with the depth, the frame
// would be the clear colour alone.
TEST(DepthClears, KeepTheStencilThatALaterPassTests) {
    std::unique_ptr<runtime::EffectRenderer> renderer = loadEffect(R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(float4(p.xyz, 1), WorldViewProjection); }
float4 QuadVS(float4 p : POSITION) : POSITION { return p; }
float4 White() : COLOR { return 1; }
technique t < string Script = "Pass=Mark; Pass=Show;"; > {
    pass Mark < string Script = "Clear=Color; Clear=Depth; Clear=Stencil; Draw=Geometry;"; >
    { ColorWriteEnable = 0; StencilEnable = true; StencilFunc = Always; StencilPass = Replace; StencilRef = 1;
      VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 White(); }
    pass Show < string Script = "Clear=Depth; Draw=Buffer;"; >
    { ZEnable = false; StencilEnable = true; StencilFunc = Equal; StencilRef = 1;
      VertexShader = compile vs_3_0 QuadVS(); PixelShader = compile ps_3_0 White(); }
}
)",
                                                                   false, "stencil.fx");
    ASSERT_TRUE(renderer);
    const Frame frame = renderWith(*renderer, *runtime::makeBuiltinScene("boxes"), "t", true);
    int white = 0;
    for (int y = 0; y < frame.image.height; ++y)
        for (int x = 0; x < frame.image.width; ++x) white += luminance(frame.image.pixel(x, y)) > 0.99f;
    const int pixels = frame.image.width * frame.image.height;
    EXPECT_GT(white, pixels / 10) << "the stencil mark did not survive the depth clear";
    EXPECT_LT(white, pixels * 9 / 10) << "the stencil test passed everywhere";
}

}  // namespace
}  // namespace shadowfx::test::test_depth_only_passes
