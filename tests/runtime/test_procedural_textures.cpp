// Textures an effect gets without rendering them itself, and render targets beyond the basics, through the
// whole pipeline (parse, compile, EffectRenderer on llvmpipe): procedural noise (`string Procedural =
// "noise"`), FX Composer's texture functions (`string function = "f"`), file textures (PNG, HDR) by
// ResourceName relative to the effect and the error for a missing one, mipmapped render targets regenerated
// before they are sampled, and multiple render targets.
#include "ScratchDirectory.h"
#include "effects/EffectHarness.h"

#include <fx/CompiledEffectFile.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/Image.h>
#include <private/runtime/ProceduralTexture.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace shadowfx::test::test_procedural_textures {
namespace {

// Draws one full-screen quad into the frame with `pixelShader` (a function `float4 PS(float2 uv :
// TEXCOORD0) : COLOR`); `declarations` go before it. Samples the textures, so they must exist.
std::string fullScreenEffect(const std::string& declarations, const std::string& pixelShader,
                             const std::string& script = "RenderColorTarget0=; Draw=Buffer;") {
    return declarations + R"(
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
)" + pixelShader +
           R"(
technique t { pass p < string Script = ")" +
           script + R"("; > { ZEnable = false; VertexShader = compile vs_3_0 VS();
                                   PixelShader = compile ps_3_0 PS(); } }
)";
}

const runtime::Scene& boxes() {
    static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    return scene;
}

// [SECTION] Procedural noise

// PCG32's reference implementation (pcg-c-basic, pcg32-demo.c) prints these six outputs for
// pcg32_srandom_r(&rng, 42u, 54u): the generator is that algorithm, so every machine makes the same noise.
TEST(ProceduralNoise, GeneratorMatchesThePcg32ReferenceOutput) {
    runtime::Pcg32 generator(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (uint32_t value : expected) EXPECT_EQ(generator.next(), value);
}

const char* kNoiseDeclarations = R"(
texture Noise < string Procedural = "noise"; int Seed = 7; float2 Dimensions = {64, 32};
                string Format = "A32B32G32R32F"; >;
texture Other < string Procedural = "noise"; int Seed = 8; float2 Dimensions = {64, 32};
                string Format = "A32B32G32R32F"; >;
sampler NoiseSampler = sampler_state { texture = <Noise>; MinFilter = POINT; MagFilter = POINT; };
sampler OtherSampler = sampler_state { texture = <Other>; MinFilter = POINT; MagFilter = POINT; };
)";

TEST(ProceduralNoise, TextureIsTheDocumentedWhiteNoiseAndTheSameEveryTime) {
    const std::string source = fullScreenEffect(kNoiseDeclarations,
                                                "float4 PS(float2 uv : TEXCOORD0) : COLOR { return "
                                                "tex2D(NoiseSampler, uv) * tex2D(OtherSampler, uv); }");
    auto first = loadEffect(source, false);
    auto second = loadEffect(source, false);
    ASSERT_TRUE(first && second);
    int width = 0, height = 0, channels = 0;
    auto noise = first->readTarget("Noise", &width, &height, &channels);
    ASSERT_TRUE(noise);
    ASSERT_EQ(width, 64);
    ASSERT_EQ(height, 32);
    ASSERT_EQ(channels, 4);
    EXPECT_EQ(*noise, *second->readTarget("Noise", nullptr, nullptr, nullptr)) << "same seed, same texture";
    EXPECT_EQ(*noise, runtime::whiteNoiseTexels(64, 32, 7)) << "what the README documents, texel for texel";
    EXPECT_NE(*noise, *first->readTarget("Other", nullptr, nullptr, nullptr)) << "another seed, other noise";

    // Uniform on [0, 1) per channel: mean 1/2, variance 1/12 (standard errors at 2048 samples: 0.0064 and
    // 0.0019), and neighbouring channels uncorrelated.
    for (int c = 0; c < 4; ++c) {
        double sum = 0, squares = 0, product = 0;
        const size_t n = noise->size() / 4;
        for (size_t i = 0; i < n; ++i) {
            const float v = (*noise)[i * 4 + size_t(c)];
            ASSERT_GE(v, 0.0f);
            ASSERT_LT(v, 1.0f);
            sum += v;
            squares += double(v) * v;
            product += (v - 0.5) * ((*noise)[i * 4 + size_t((c + 1) % 4)] - 0.5);
        }
        const double mean = sum / double(n);
        EXPECT_NEAR(mean, 0.5, 0.025) << "channel " << c;
        EXPECT_NEAR(squares / double(n) - mean * mean, 1.0 / 12.0, 0.008) << "channel " << c;
        EXPECT_NEAR(product / double(n), 0.0, 0.008) << "channels " << c << " and " << (c + 1) % 4;
    }
    ASSERT_TRUE(render(*first, boxes(), 16, 16));
    EXPECT_TRUE(notConstant(first->readFrame()));
}

// The NOISE semantic (the thesis's noise texture): the runtime's fixed 64x64 noise by the kind the compiler
// gave it, not a neutral texture.
TEST(ProceduralNoise, NoiseSemanticGivesTheRuntimesNoiseTexture) {
    const std::string source = fullScreenEffect(
        "texture Jitter : noise;\nsampler JitterSampler = sampler_state { Texture = <Jitter>; };\n",
        "float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(JitterSampler, uv); }");
    auto effect = loadEffect(source, false);
    ASSERT_TRUE(effect);
    int width = 0, height = 0, channels = 0;
    auto noise = effect->readTarget("Jitter", &width, &height, &channels);
    ASSERT_TRUE(noise);
    EXPECT_EQ(width, 64);
    EXPECT_EQ(height, 64);
    ASSERT_FALSE(noise->empty());
    EXPECT_NE(std::count(noise->begin(), noise->end(), (*noise)[0]), static_cast<long>(noise->size()));
    ASSERT_TRUE(render(*effect, boxes(), 16, 16));
    EXPECT_TRUE(notConstant(effect->readFrame()));
}

TEST(ProceduralNoise, UnknownGeneratorIsAnErrorAtTheAnnotation) {
    sharedContext();
    fx::DiagnosticList diagnostics;
    auto effect =
        fx::parseEffectSource("texture T < string Procedural = \"perlin\"; >;\n", "proc.fx", {}, diagnostics);
    ASSERT_TRUE(effect);
    EXPECT_FALSE(fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) && !diagnostics.hasErrors());
    EXPECT_NE(diagnostics.str().find("proc.fx:1:33: error: invalid annotation 'Procedural'"),
              std::string::npos)
        << diagnostics.str();
}

// [SECTION] Texture functions

// D3DXFillTexture's contract: the function sees each texel's centre and the texel size of the level it
// fills, and may read the effect's parameters.
const char* kRampDeclarations = R"(
float4 Tint = {0.25, 0.5, 0.75, 1};
float4 ramp(float2 P : POSITION, float2 S : PSIZE) : COLOR { return float4(P, S.x * 64 * Tint.x, 1); }
texture Ramp < string function = "ramp"; float2 Dimensions = {64, 32}; string Format = "A32B32G32R32F"; >;
sampler RampSampler = sampler_state { texture = <Ramp>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
)";

void expectRamp(runtime::EffectRenderer& effect, int level, float texelScale) {
    SCOPED_TRACE("level " + std::to_string(level));
    int width = 0, height = 0, channels = 0;
    auto texels = effect.readTarget("Ramp", &width, &height, &channels, level);
    ASSERT_TRUE(texels);
    ASSERT_EQ(width, 64 >> level);
    ASSERT_EQ(height, 32 >> level);
    ASSERT_EQ(channels, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* t = &(*texels)[(size_t(y) * size_t(width) + size_t(x)) * 4];
            ASSERT_NEAR(t[0], (x + 0.5f) / width, 1e-6f) << x << "," << y;
            ASSERT_NEAR(t[1], (y + 0.5f) / height, 1e-6f) << x << "," << y << ": row 0 is the top row";
            ASSERT_NEAR(t[2], texelScale, 1e-6f) << x << "," << y;
            ASSERT_EQ(t[3], 1.0f);
        }
}

TEST(TextureFunction, FillsEveryLevelWithTexelCentresTexelSizesAndParameters) {
    const std::string source = fullScreenEffect(
        kRampDeclarations, "float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(RampSampler, uv); }");
    auto effect = loadEffect(source, false);
    ASSERT_TRUE(effect);
    expectRamp(*effect, 0, 0.25f);
    expectRamp(*effect, 1, 0.5f);  // half the texels, twice their size
    ASSERT_TRUE(render(*effect, boxes(), 16, 16));
    EXPECT_TRUE(notConstant(effect->readFrame()));

    // The fill pass is part of the compiled effect, and a compiled file draws the same texture.
    fx::DiagnosticList diagnostics;
    auto parsed = fx::parseEffectSource(source, "ramp.fx", {}, diagnostics);
    ASSERT_TRUE(parsed);
    auto compiled = fx::compileEffect(parsed, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    const std::string bytes = fx::serializeCompiledEffect(*compiled);
    std::shared_ptr<fx::CompiledEffect> read = fx::deserializeCompiledEffect(bytes, "ramp.sfxo", diagnostics);
    ASSERT_TRUE(read) << diagnostics.str();
    EXPECT_EQ(fx::serializeCompiledEffect(*read), bytes);
    auto fromFile = runtime::EffectRenderer::create(read, diagnostics);
    ASSERT_TRUE(fromFile) << diagnostics.str();
    expectRamp(*fromFile, 0, 0.25f);
}

// A volume's function sees (u, v, w) at the texel's centre; a cube's, the direction through the texel's
// centre on its face, as D3D (and GL) pick faces: +Y's s runs along +x and its t along +z.
TEST(TextureFunction, VolumeAndCubeTexelsSeeTheirPositionAndDirection) {
    const std::string source = fullScreenEffect(R"(
float4 cell(float3 P : POSITION) : COLOR { return float4(P, 1); }
float4 direction(float3 D : POSITION) : COLOR { return float4(D * 0.5 + 0.5, 1); }
texture Cells < string function = "cell"; string TextureType = "VOLUME";
                int width = 4, height = 4, depth = 8; string Format = "A32B32G32R32F"; >;
texture Sky < string function = "direction"; string TextureType = "CUBE"; float2 Dimensions = {16, 16};
              string Format = "A32B32G32R32F"; >;
sampler3D CellSampler = sampler_state { texture = <Cells>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
samplerCUBE SkySampler = sampler_state { texture = <Sky>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
texture Out : RENDERCOLORTARGET < float2 Dimensions = {2, 1}; string Format = "A32B32G32R32F"; >;
)",
                                                R"(float4 PS(float2 uv : TEXCOORD0) : COLOR {
    return uv.x < 0.5 ? tex3Dlod(CellSampler, float4(0.375, 0.625, 0.6875, 0))
                      : texCUBElod(SkySampler, float4(-0.3, 1.0, 0.45, 0));
})",
                                                "RenderColorTarget0=Out; Draw=Buffer;");
    auto effect = loadEffect(source, false);
    ASSERT_TRUE(effect);
    ASSERT_TRUE(render(*effect, boxes(), 16, 16, "", {"Out"}));
    auto out = effect->readTarget("Out", nullptr, nullptr, nullptr);
    ASSERT_TRUE(out);
    ASSERT_EQ(out->size(), 8u);
    // Volume texel (1, 2, 5) of 4x4x8.
    EXPECT_NEAR((*out)[0], 0.375f, 1e-6f);
    EXPECT_NEAR((*out)[1], 0.625f, 1e-6f);
    EXPECT_NEAR((*out)[2], 0.6875f, 1e-6f);
    // (-0.3, 1, 0.45) falls on +Y's texel (5, 11) of 16: s = -0.3125, t = 0.4375, the direction (s, 1, t).
    EXPECT_NEAR((*out)[4], -0.3125f * 0.5f + 0.5f, 1e-6f);
    EXPECT_NEAR((*out)[5], 1.0f, 1e-6f);
    EXPECT_NEAR((*out)[6], 0.4375f * 0.5f + 0.5f, 1e-6f);
}

TEST(TextureFunction, AnUndefinedFunctionOrAnUnknownInputIsAnErrorAtTheEffect) {
    sharedContext();
    for (const auto& [source, expected] : std::vector<std::pair<std::string, std::string>>{
             {"texture T < string function = \"missing\"; >;\n",
              "fn.fx:1:31: error: texture function \"missing\" is not a function of the effect"},
             {"float4 f(float2 uv : TEXCOORD0) : COLOR { return 1; }\n"
              "texture T < string function = \"f\"; >;\n",
              "fn.fx:1:8: error: texture function 'f': parameter 'uv' (float2 : TEXCOORD0) is not an input a "
              "texture function takes"},
             {"float4 f(float2 p : POSITION) : COLOR { return 1; }\n"
              "texture T : RENDERCOLORTARGET < string function = \"f\"; >;\n",
              "fn.fx:2:40: error: 'T' cannot be filled by a function"},
             {"texture Tex; sampler S = sampler_state { texture = <Tex>; };\n"
              "float4 f(float2 p : POSITION) : COLOR { return tex2D(S, p); }\n"
              "texture T < string function = \"f\"; >;\n",
              "fn.fx:3:20: error: texture function 'f' reads 'S'"}}) {
        fx::DiagnosticList diagnostics;
        auto effect = fx::parseEffectSource(source, "fn.fx", {}, diagnostics);
        ASSERT_TRUE(effect) << diagnostics.str();
        EXPECT_FALSE(fx::compileEffect(effect, fx::CompileOptions{}, diagnostics));
        EXPECT_NE(diagnostics.str().find(expected), std::string::npos) << diagnostics.str();
    }
}

// [SECTION] File textures

class FileTextures : public ::testing::Test {
protected:
    // One folder per test: CTest runs the tests of this file as parallel processes.
    shadowfx::test::ScratchDirectory mScratch{"file_textures"};
    std::filesystem::path mDir = mScratch.path();
    void SetUp() override { std::filesystem::create_directories(mDir / "images"); }
    std::string writeEffect(const std::string& declarations) {
        const std::filesystem::path path = mDir / "textured.fx";
        std::ofstream(path) << fullScreenEffect(
            declarations, "float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(S, uv); }");
        return path.string();
    }
};

TEST_F(FileTextures, PngAndHdrLoadRelativeToTheEffect) {
    // A 2x2 PNG, written by the runtime's own PNG writer, read back texel for texel.
    runtime::Image png = runtime::Image::makeBytes(2, 2, 4);
    png.bytes = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 10, 20, 30, 255};
    std::string error;
    ASSERT_TRUE(png.writePng((mDir / "images/checker.png").string(), error)) << error;
    auto renderer = loadEffect(writeEffect(R"(texture T < string ResourceName = "images/checker.png"; >;
sampler S = sampler_state { texture = <T>; MinFilter = POINT; MagFilter = POINT; MipFilter = NONE; };)"),
                               true);
    ASSERT_TRUE(renderer);
    int width = 0, height = 0, channels = 0;
    auto texels = renderer->readTarget("T", &width, &height, &channels);
    ASSERT_TRUE(texels);
    ASSERT_EQ(width * height * channels, 16);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR((*texels)[size_t(i)], png.bytes[size_t(i)] / 255.0f, 1e-6f);

    // A 2x1 Radiance HDR file (flat RGBE, mantissa m and exponent e meaning m * 2^(e - 136)): values above
    // 1 survive in a float texture.
    const unsigned char pixels[] = {128, 64, 32, 130, 128, 128, 128, 129};  // (2, 1, 0.5), (1, 1, 1)
    {
        std::ofstream hdr(mDir / "images/sky.hdr", std::ios::binary);
        hdr << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
        hdr.write(reinterpret_cast<const char*>(pixels), sizeof pixels);
    }
    renderer = loadEffect(writeEffect(R"(texture T < string ResourceName = "images/sky.hdr"; >;
sampler S = sampler_state { texture = <T>; MinFilter = POINT; MagFilter = POINT; MipFilter = NONE; };)"),
                          true);
    ASSERT_TRUE(renderer);
    texels = renderer->readTarget("T", &width, &height, &channels);
    ASSERT_TRUE(texels);
    ASSERT_EQ(width, 2);
    ASSERT_EQ(channels, 4);
    const float expected[] = {2.0f, 1.0f, 0.5f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f};
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ((*texels)[size_t(i)], expected[i]) << i;
    ASSERT_TRUE(render(*renderer, boxes(), 8, 8, "", {"A", "B", "C", "D"}));
}

// FX Composer drew with a default texture when a file was missing: a warning at the resource name, the
// same for a PNG as for a DDS, and the effect still compiles.
TEST_F(FileTextures, MissingFileIsAWarningAtTheResourceNameWhateverItsType) {
    for (const char* name : {"images/nothere.png", "images/nothere.dds"}) {
        SCOPED_TRACE(name);
        const std::string path = writeEffect(std::string(R"(texture T < string ResourceName = ")") + name +
                                             R"("; >;
sampler S = sampler_state { texture = <T>; };)");
        fx::DiagnosticList diagnostics;
        auto effect = fx::parseEffectFile(path, {}, diagnostics);
        ASSERT_TRUE(effect);
        auto compiled = fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
        EXPECT_TRUE(compiled);
        EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.str();
        EXPECT_NE(diagnostics.str().find(std::string("textured.fx:1:35: warning: cannot load texture '") +
                                         name + "'; using a neutral texture"),
                  std::string::npos)
            << diagnostics.str();
    }
}

// [SECTION] Render targets

// A mipmapped target (MipLevels = 0: the full chain) written by one pass and sampled by the next: the
// runtime regenerates the chain in between, so level 1 is the 2x2 box average of level 0.
TEST(RenderTargetMips, LevelOneIsTheAverageOfLevelZeroAfterAPassWritesIt) {
    const std::string source = fullScreenEffect(
        R"(texture Pattern : RENDERCOLORTARGET < float2 Dimensions = {16, 8}; string Format = "A32B32G32R32F";
                                             int MipLevels = 0; >;
sampler PatternSampler = sampler_state { texture = <Pattern>; MinFilter = LINEAR; MagFilter = LINEAR;
                                         MipFilter = LINEAR; };
float4 PatternPS(float2 uv : TEXCOORD0) : COLOR
{ return float4(frac(uv.x * 7.3 + uv.y * 3.1), uv.x * uv.x, frac(sin(uv.x * 91.0 + uv.y * 47.0) * 43758.5), 1); }
)",
        "float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2Dlod(PatternSampler, float4(uv, 0, 1)); }",
        "RenderColorTarget0=; Draw=Buffer;");
    // Two passes: the first renders the pattern into the mipmapped target, the second samples level 1.
    std::string twoPasses = source;
    const std::string marker = "technique t { pass p";
    twoPasses.replace(
        twoPasses.find(marker), marker.size(),
        "technique t { pass w < string Script = \"RenderColorTarget0=Pattern; Draw=Buffer;\"; > "
        "{ ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 "
        "PatternPS(); } pass p");
    auto renderer = loadEffect(twoPasses, false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, boxes(), 32, 32));
    int w0 = 0, h0 = 0, c0 = 0, w1 = 0, h1 = 0, c1 = 0;
    auto level0 = renderer->readTarget("Pattern", &w0, &h0, &c0, 0);
    auto level1 = renderer->readTarget("Pattern", &w1, &h1, &c1, 1);
    ASSERT_TRUE(level0 && level1);
    ASSERT_EQ(w1, 8);
    ASSERT_EQ(h1, 4);
    EXPECT_TRUE(renderer->readTarget("Pattern", nullptr, nullptr, nullptr, 4)) << "16x8: 5 levels";
    float spread = 0;
    for (int y = 0; y < h1; ++y) {
        for (int x = 0; x < w1; ++x) {
            for (int c = 0; c < 3; ++c) {
                auto at = [&](int xx, int yy) { return (*level0)[size_t((yy * w0 + xx) * c0 + c)]; };
                const float average = 0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) +
                                               at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
                EXPECT_NEAR((*level1)[size_t((y * w1 + x) * c1 + c)], average, 1e-5f)
                    << x << "," << y << "," << c;
                spread = std::max(spread, std::abs(at(2 * x, 2 * y) - average));
            }
        }
    }
    EXPECT_GT(spread, 0.05f) << "the pattern must vary inside 2x2 blocks, or any level would pass";
}

// RenderColorTarget0..3 in a SAS script with a pixel shader writing COLOR0..COLOR3.
TEST(MultipleRenderTargets, FourTargetsReceiveTheirOwnOutputs) {
    const std::string source = fullScreenEffect(
        R"(texture A : RENDERCOLORTARGET < float2 Dimensions = {8, 8}; string Format = "A32B32G32R32F"; >;
texture B : RENDERCOLORTARGET < float2 Dimensions = {8, 8}; string Format = "R32F"; >;
texture C : RENDERCOLORTARGET < float2 Dimensions = {8, 8}; string Format = "G32R32F"; >;
texture D : RENDERCOLORTARGET < float2 Dimensions = {8, 8}; string Format = "A32B32G32R32F"; >;
struct Outputs { float4 a : COLOR0; float4 b : COLOR1; float4 c : COLOR2; float4 d : COLOR3; };
)",
        R"(Outputs PS(float2 uv : TEXCOORD0)
{ Outputs o; o.a = float4(0.25, 0.5, 0.75, 1); o.b = 2; o.c = float4(3, 4, 0, 0); o.d = float4(uv, 5, 6); return o; })",
        "RenderColorTarget0=A; RenderColorTarget1=B; RenderColorTarget2=C; RenderColorTarget3=D; "
        "Draw=Buffer;");
    auto renderer = loadEffect(source, false);
    ASSERT_TRUE(renderer);
    ASSERT_TRUE(render(*renderer, boxes(), 8, 8, "", {"A", "B", "C", "D"}));
    int width = 0, height = 0, channels = 0;
    auto a = renderer->readTarget("A", &width, &height, &channels);
    ASSERT_TRUE(a);
    EXPECT_EQ(std::vector<float>(a->begin(), a->begin() + 4), (std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f}));
    auto b = renderer->readTarget("B", &width, &height, &channels);
    ASSERT_TRUE(b);
    EXPECT_EQ(channels, 1);
    EXPECT_EQ((*b)[0], 2.0f);
    auto c = renderer->readTarget("C", &width, &height, &channels);
    ASSERT_TRUE(c);
    EXPECT_EQ(channels, 2);
    EXPECT_EQ((*c)[0], 3.0f);
    EXPECT_EQ((*c)[1], 4.0f);
    auto d = renderer->readTarget("D", &width, &height, &channels);
    ASSERT_TRUE(d);
    // Texel (7, 0): uv at its centre.
    EXPECT_NEAR((*d)[7 * 4 + 0], 7.5f / 8.0f, 1e-5f);
    EXPECT_NEAR((*d)[7 * 4 + 1], 0.5f / 8.0f, 1e-5f);
    EXPECT_EQ((*d)[7 * 4 + 2], 5.0f);
}

// A target larger than the frame, drawn with the frame's (smaller) depth buffer: GL would draw and clear only
// the overlap. Without the depth test the runtime binds the target alone and the whole of it is drawn, as on
// D3D9's drivers; with the depth test only the overlap is, and a warning names the pass.
TEST(RenderTargetSizes, ATargetLargerThanTheDepthBufferIsDrawnWholeWhenDepthIsNotTested) {
    const std::string declarations =
        R"(texture Big : RENDERCOLORTARGET < float2 Dimensions = {64, 48}; string Format = "R32F"; >;
float4 Background = {0.5, 0.5, 0.5, 0.5};
)";
    const std::string script = "RenderColorTarget0=Big; ClearSetColor=Background; Clear=Color; Draw=Buffer;";
    for (const bool depthTest : {false, true}) {
        std::string source =
            fullScreenEffect(declarations, "float4 PS(float2 uv : TEXCOORD0) : COLOR { return 2; }", script);
        if (depthTest) source.replace(source.find("ZEnable = false"), 15, "ZEnable = true");
        auto renderer = loadEffect(source, false);
        ASSERT_TRUE(renderer);
        fx::DiagnosticList diagnostics;
        runtime::FrameOptions options;
        options.width = 16;
        options.height = 16;
        options.outputTargets = {"Big"};
        ASSERT_TRUE(renderer->render(boxes(), options, diagnostics)) << diagnostics.str();
        int width = 0, height = 0, channels = 0;
        auto big = renderer->readTarget("Big", &width, &height, &channels);
        ASSERT_TRUE(big);
        ASSERT_EQ(width * height, 64 * 48);
        int drawn = 0, cleared = 0;
        for (int i = 0; i < width * height; ++i) {
            drawn += (*big)[size_t(i * channels)] == 2.0f;
            cleared += (*big)[size_t(i * channels)] == 0.5f;
        }
        const bool warned = diagnostics.str().find("smaller 16x16 depth-stencil target") != std::string::npos;
        if (depthTest) {
            EXPECT_EQ(drawn, 16 * 16) << "the overlap with the 16x16 depth buffer";
            EXPECT_EQ(cleared, 64 * 48 - 16 * 16) << "the colour clear covers the whole target";
            EXPECT_TRUE(warned) << diagnostics.str();
        } else {
            EXPECT_EQ(drawn, 64 * 48);
            EXPECT_FALSE(warned) << diagnostics.str();
        }
    }
}

}  // namespace
}  // namespace shadowfx::test::test_procedural_textures
