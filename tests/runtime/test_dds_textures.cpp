// DDS texture files, which nearly every FX Composer and DirectX SDK effect names: 2D with a mip chain,
// DXT1/3/5, cube and volume textures, read by runtime/TextureFile.h, and Direct3D 10's arrays of 2D textures
// and of cubes. The files are written by the test
// (DdsWriter.h) with a colour per face, level and slice, and a full-screen pass samples them at known
// coordinates; what lands in the frame is compared with what was written.
#include "DdsWriter.h"
#include "ScratchDirectory.h"
#include "effects/EffectHarness.h"
#include <runtime/BuiltinScenes.h>
#include <runtime/TextureFile.h>

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <filesystem>
#include <fstream>

namespace shadowfx::test::test_dds_textures {
namespace {

class DdsTextures : public ::testing::Test {
protected:
    ScratchDirectory mScratch{"dds"};
    std::filesystem::path mDir = mScratch.path();

    // An 8x1 frame: pixel i returns `lookup` with uv = ((i + 0.5) / 8, 0.5).
    std::unique_ptr<runtime::EffectRenderer> effect(const std::string& declarations,
                                                    const std::string& lookup) {
        const std::filesystem::path path = mDir / "dds.fx";
        std::ofstream(path) << declarations << R"(
struct Quad { float4 Position : POSITION; float2 UV : TEXCOORD0; };
Quad VS(float4 p : POSITION, float2 uv : TEXCOORD0) { Quad o; o.Position = p; o.UV = uv; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return )"
                            << lookup << R"(; }
technique t { pass p < string Script = "RenderColorTarget0=; Draw=Buffer;"; > {
    ZEnable = false; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
        return loadEffect(path.string(), true);
    }

    runtime::FrameImage frame(runtime::EffectRenderer& renderer) {
        static const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
        EXPECT_TRUE(render(renderer, scene, 8, 1));
        return renderer.readFrame();
    }
};

::testing::AssertionResult near(const uint8_t* pixel, DdsColor expected, int tolerance = 3) {
    const int e[4] = {expected.r, expected.g, expected.b, expected.a};
    for (int c = 0; c < 4; ++c)
        if (std::abs(pixel[c] - e[c]) > tolerance)
            return ::testing::AssertionFailure()
                   << "pixel (" << int(pixel[0]) << ", " << int(pixel[1]) << ", " << int(pixel[2]) << ", "
                   << int(pixel[3]) << ") expected (" << e[0] << ", " << e[1] << ", " << e[2] << ", " << e[3]
                   << ")";
    return ::testing::AssertionSuccess();
}

// A colour per level (red), column (green) and slice (blue).
DdsColor ramp(int face, int level, int x, int, int z) {
    return DdsColor{static_cast<uint8_t>(30 + 40 * face + 20 * level), static_cast<uint8_t>(16 * x + 8),
                    static_cast<uint8_t>(60 * z + 20), 255};
}

TEST_F(DdsTextures, UncompressedMipChainKeepsEveryStoredLevel) {
    ASSERT_TRUE(DdsWriter::write((mDir / "ramp.dds").string(), DdsWriter::Layout::Flat,
                                 DdsWriter::Compression::None, 8, 4, 1, 3, ramp));
    auto renderer = effect(R"(texture T < string ResourceName = "ramp.dds"; >;
sampler2D S = sampler_state { texture = <T>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };)",
                           "float4(tex2Dlod(S, float4(uv, 0, 0)).rg, tex2Dlod(S, float4(uv, 0, 1)).r, 1)");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    for (int x = 0; x < 8; ++x) {
        // Level 1 is 4 texels wide: pixel x reads its texel x / 2; its red is level 1's (50), not level 0's.
        EXPECT_TRUE(near(image.pixel(x, 0), DdsColor{30, static_cast<uint8_t>(16 * x + 8), 50, 255})) << x;
    }
}

TEST_F(DdsTextures, Dxt1Dxt3AndDxt5Decode) {
    auto blocks = [](int, int, int x, int, int) {
        return DdsColor{static_cast<uint8_t>(x < 4 ? 248 : 0), static_cast<uint8_t>(x < 4 ? 0 : 252),
                        static_cast<uint8_t>(x < 4 ? 0 : 248), static_cast<uint8_t>(x < 4 ? 255 : 136)};
    };
    for (auto compression :
         {DdsWriter::Compression::Dxt1, DdsWriter::Compression::Dxt3, DdsWriter::Compression::Dxt5}) {
        SCOPED_TRACE(static_cast<int>(compression));
        ASSERT_TRUE(DdsWriter::write((mDir / "blocks.dds").string(), DdsWriter::Layout::Flat, compression, 8,
                                     8, 1, 1, blocks));
        auto renderer = effect(R"(texture T < string ResourceName = "blocks.dds"; >;
sampler2D S = sampler_state { texture = <T>; MinFilter = POINT; MagFilter = POINT; MipFilter = NONE; };)",
                               "tex2D(S, uv)");
        ASSERT_TRUE(renderer);
        const runtime::FrameImage image = frame(*renderer);
        ASSERT_TRUE(notConstant(image));
        const uint8_t alpha = compression == DdsWriter::Compression::Dxt1 ? 255 : 136;
        EXPECT_TRUE(near(image.pixel(1, 0), DdsColor{255, 0, 0, 255}, 8));
        EXPECT_TRUE(near(image.pixel(6, 0), DdsColor{0, 255, 255, alpha}, 8));
    }
}

TEST_F(DdsTextures, CubeMapFacesLandOnTheirDirections) {
    ASSERT_TRUE(DdsWriter::write((mDir / "cube.dds").string(), DdsWriter::Layout::Cube,
                                 DdsWriter::Compression::None, 4, 4, 1, 1, ramp));
    // Pixel i looks along axis i / 2 (of +X -X +Y -Y +Z -Z), for i < 6.
    auto renderer = effect(R"(texture Env < string ResourceName = "cube.dds"; string ResourceType = "Cube"; >;
samplerCUBE S = sampler_state { texture = <Env>; MinFilter = POINT; MagFilter = POINT; MipFilter = NONE; };
float3 axis(float i) {
    float3 d[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1),
                    float3(0, 0, -1) };
    return d[min((int)i, 5)];
})",
                           "texCUBE(S, axis(floor(uv.x * 8)))");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    for (int face = 0; face < 6; ++face) EXPECT_NEAR(image.pixel(face, 0)[0], 30 + 40 * face, 2) << face;
}

TEST_F(DdsTextures, VolumeSlicesLandAtTheirDepth) {
    ASSERT_TRUE(DdsWriter::write((mDir / "volume.dds").string(), DdsWriter::Layout::Volume,
                                 DdsWriter::Compression::None, 4, 4, 4, 1, ramp));
    auto renderer = effect(R"(texture3D V < string ResourceName = "volume.dds"; >;
sampler3D S = sampler_state { texture = <V>; MinFilter = POINT; MagFilter = POINT; MipFilter = NONE; };)",
                           "tex3D(S, float3(0.1, 0.5, uv.x))");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    for (int x = 0; x < 8; ++x) EXPECT_NEAR(image.pixel(x, 0)[2], 60 * (x / 2) + 20, 2) << x;
}

// A file of another kind than the effect samples: a located warning and the neutral texture, not black.
TEST_F(DdsTextures, CubeFileBehindA2DSamplerIsAWarningAndNeutral) {
    ASSERT_TRUE(DdsWriter::write((mDir / "cube.dds").string(), DdsWriter::Layout::Cube,
                                 DdsWriter::Compression::None, 4, 4, 1, 1, ramp));
    sharedContext();
    const std::filesystem::path path = mDir / "dds.fx";
    std::ofstream(path) << R"(texture T < string ResourceName = "cube.dds"; >;
sampler2D S = sampler_state { texture = <T>; };
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return tex2D(S, float2(0.5, 0.5)); }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";
    fx::DiagnosticList diagnostics;
    auto parsed = fx::parseEffectFile(path.string(), {}, diagnostics);
    ASSERT_TRUE(parsed) << diagnostics.str();
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::compileEffect(parsed, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    auto renderer = runtime::EffectRenderer::create(compiled, diagnostics);
    ASSERT_TRUE(renderer) << diagnostics.str();
    EXPECT_FALSE(diagnostics.hasErrors());
    EXPECT_NE(diagnostics.str().find("dds.fx:1:9: warning: texture file 'cube.dds' holds a cube texture"),
              std::string::npos)
        << diagnostics.str();
}

// A cube map's stored levels are used, face by face, not regenerated from level 0.
TEST_F(DdsTextures, CubeMapKeepsItsStoredMipLevels) {
    ASSERT_TRUE(DdsWriter::write((mDir / "cube.dds").string(), DdsWriter::Layout::Cube,
                                 DdsWriter::Compression::None, 4, 4, 1, 3, ramp));
    auto renderer = effect(R"(texture Env < string ResourceName = "cube.dds"; string ResourceType = "Cube"; >;
samplerCUBE S = sampler_state { texture = <Env>; MinFilter = POINT; MagFilter = POINT; MipFilter = POINT; };
float3 axis(float i) {
    float3 d[6] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0), float3(0, 0, 1),
                    float3(0, 0, -1) };
    return d[min((int)i, 5)];
})",
                           "texCUBElod(S, float4(axis(floor(uv.x * 8)), 1))");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    // Level 1's red is 20 above level 0's on every face; a chain regenerated from level 0 would keep it.
    for (int face = 0; face < 6; ++face) EXPECT_NEAR(image.pixel(face, 0)[0], 50 + 40 * face, 2) << face;
}

// [SECTION] The reader alone: formats, channels a format lacks, damaged files (no GL)

std::vector<float> firstTexel(const std::filesystem::path& path) {
    std::optional<runtime::TextureFileFault> fault;
    const std::optional<runtime::TextureFile> file = runtime::loadTextureFile(path.string(), fault);
    EXPECT_TRUE(file) << fx::diagnosticName(fault->id);
    if (!file || file->levels.empty() || file->levels[0].size() < 4) return {};
    return {file->levels[0].begin(), file->levels[0].begin() + 4};
}

std::vector<uint8_t> bytesOf(std::initializer_list<float> values) {
    std::vector<uint8_t> bytes(values.size() * 4);
    std::memcpy(bytes.data(), values.begin(), bytes.size());
    return bytes;
}

TEST(DdsReader, D3d9FormatsReadMissingChannelsAsOneAndDxgiFormatsAsZero) {
    ScratchDirectory scratch{"dds-reader"};
    const std::filesystem::path r32f = scratch.path() / "r32f.dds", dxgi = scratch.path() / "r32.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(r32f.string(), 1, 1, {0x4, 114}, bytesOf({0.25f})));  // D3DFMT_R32F
    EXPECT_EQ(firstTexel(r32f), (std::vector<float>{0.25f, 1, 1, 1}));
    ASSERT_TRUE(DdsWriter::writeSurface(dxgi.string(), 1, 1, {}, bytesOf({0.25f}), 41));  // R32_FLOAT
    EXPECT_EQ(firstTexel(dxgi), (std::vector<float>{0.25f, 0, 0, 1}));

    // D3DFMT_A16B16G16R16F: halves 1.0, -2.0, 0.5, 65504.
    const std::filesystem::path half = scratch.path() / "half.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(half.string(), 1, 1, {0x4, 113},
                                        {0x00, 0x3c, 0x00, 0xc0, 0x00, 0x38, 0xff, 0x7b}));
    EXPECT_EQ(firstTexel(half), (std::vector<float>{1.0f, -2.0f, 0.5f, 65504.0f}));
}

TEST(DdsReader, MaskFormatsLuminanceAndAlpha) {
    ScratchDirectory scratch{"dds-reader"};
    // R5G6B5: red 31 (full), green 0, blue 16 of 31.
    const std::filesystem::path rgb565 = scratch.path() / "565.dds";
    const uint16_t texel = uint16_t(31 << 11 | 16);
    ASSERT_TRUE(DdsWriter::writeSurface(rgb565.string(), 1, 1, {0x40, 0, 16, 0xf800, 0x07e0, 0x001f, 0},
                                        {uint8_t(texel), uint8_t(texel >> 8)}));
    const std::vector<float> c = firstTexel(rgb565);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_FLOAT_EQ(c[0], 1.0f);
    EXPECT_FLOAT_EQ(c[1], 0.0f);
    EXPECT_FLOAT_EQ(c[2], 16.0f / 31.0f);
    EXPECT_FLOAT_EQ(c[3], 1.0f);  // no DDPF_ALPHAPIXELS: opaque
    // A8L8: luminance 51 fills red, green and blue; alpha 204.
    const std::filesystem::path a8l8 = scratch.path() / "a8l8.dds";
    ASSERT_TRUE(
        DdsWriter::writeSurface(a8l8.string(), 1, 1, {0x20000 | 0x1, 0, 16, 0xff, 0, 0, 0xff00}, {51, 204}));
    EXPECT_EQ(firstTexel(a8l8), (std::vector<float>{0.2f, 0.2f, 0.2f, 0.8f}));
    // A8: colour 0, as D3D9 read it.
    const std::filesystem::path a8 = scratch.path() / "a8.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(a8.string(), 1, 1, {0x2, 0, 8, 0, 0, 0, 0xff}, {255}));
    EXPECT_EQ(firstTexel(a8), (std::vector<float>{0, 0, 0, 1}));
}

TEST(DdsReader, Bc4AndBc5BlocksDecodeIntoRedAndGreen) {
    ScratchDirectory scratch{"dds-reader"};
    // Endpoints 255 and 0 (eight values); texel 0's index 1 (= e1 = 0), texel 1's index 2 ((6*255+0)/7).
    const std::vector<uint8_t> bc4 = {255, 0, 0b010001, 0, 0, 0, 0, 0};
    const std::filesystem::path ati1 = scratch.path() / "ati1.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(ati1.string(), 4, 4, {0x4, 0x31495441}, bc4));  // "ATI1"
    std::optional<runtime::TextureFileFault> fault;
    std::optional<runtime::TextureFile> file = runtime::loadTextureFile(ati1.string(), fault);
    ASSERT_TRUE(file) << fx::diagnosticName(fault->id);
    EXPECT_EQ(std::vector<float>(file->levels[0].begin(), file->levels[0].begin() + 8),
              (std::vector<float>{0, 0, 0, 1, 6.0f / 7.0f, 0, 0, 1}));
    // BC5 (DXGI 83): red from the first half, green from the second (endpoints 10 <= 200: six values).
    std::vector<uint8_t> bc5 = bc4;
    bc5.insert(bc5.end(), {10, 200, 0, 0, 0, 0, 0, 0});
    const std::filesystem::path bc5File = scratch.path() / "bc5.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(bc5File.string(), 4, 4, {}, bc5, 83));
    file = runtime::loadTextureFile(bc5File.string(), fault);
    ASSERT_TRUE(file) << fx::diagnosticName(fault->id);
    EXPECT_EQ(std::vector<float>(file->levels[0].begin(), file->levels[0].begin() + 4),
              (std::vector<float>{0, 10.0f / 255.0f, 0, 1}));
}

TEST(DdsReader, DamagedFilesAreErrorsThatSayWhat) {
    ScratchDirectory scratch{"dds-reader"};
    std::optional<runtime::TextureFileFault> fault;
    const std::filesystem::path text = scratch.path() / "text.dds";
    std::ofstream(text) << "not a texture";
    EXPECT_FALSE(runtime::loadTextureFile(text.string(), fault));
    EXPECT_EQ(fault->id, fx::DiagId::TextureFileNotDds);
    EXPECT_TRUE(fault->values.empty());

    const std::filesystem::path shortFile = scratch.path() / "short.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(shortFile.string(), 2, 2, {0x4, 114}, bytesOf({1, 2, 3})));
    EXPECT_FALSE(runtime::loadTextureFile(shortFile.string(), fault));
    EXPECT_EQ(fault->id, fx::DiagId::TextureFileTexelsTruncated);
    EXPECT_EQ(fault->values, (std::vector<std::string>{"12", "16"}));

    const std::filesystem::path unknown = scratch.path() / "unknown.dds";
    ASSERT_TRUE(DdsWriter::writeSurface(unknown.string(), 1, 1, {0x4, 0x31545848}, bytesOf({1})));  // "HXT1"
    EXPECT_FALSE(runtime::loadTextureFile(unknown.string(), fault));
    EXPECT_EQ(fault->id, fx::DiagId::TextureFileFourCCUnsupported);
    EXPECT_EQ(fault->values, (std::vector<std::string>{"HXT1", std::to_string(0x31545848)}));

    EXPECT_FALSE(runtime::loadTextureFile((scratch.path() / "absent.dds").string(), fault));
    EXPECT_EQ(fault->id, fx::DiagId::TextureFileUnopenable);
}

// [SECTION] Direct3D 10 arrays (DX10 header, arraySize > 1)

DdsColor byElement(int face, int, int, int, int element) {
    return DdsColor{static_cast<uint8_t>(30 + 40 * face), 10, static_cast<uint8_t>(100 * element + 50), 255};
}

TEST_F(DdsTextures, Texture2DArrayElementsComeFromADx10ArrayFile) {
    ASSERT_TRUE(DdsWriter::writeDx10Array((mDir / "layers.dds").string(), 2, 2, 3, false, byElement));
    // Pixel x reads element x / 2; element 3 does not exist and clamps to 2, as in D3D.
    auto renderer = effect(R"(Texture2DArray T < string ResourceName = "layers.dds"; >;
SamplerState S { Filter = MIN_MAG_MIP_POINT; };)",
                           "T.Sample(S, float3(uv, floor(uv.x * 4)))");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    for (int x = 0; x < 8; ++x)
        EXPECT_TRUE(near(image.pixel(x, 0),
                         DdsColor{30, 10, static_cast<uint8_t>(50 + 100 * std::min(x / 2, 2)), 255}))
            << x;
}

TEST_F(DdsTextures, TextureCubeArrayCubesAndFacesComeFromADx10ArrayFile) {
    ASSERT_TRUE(DdsWriter::writeDx10Array((mDir / "cubes.dds").string(), 2, 2, 2, true, byElement));
    // Pixel x looks along axis x % 4 (of +X -X +Y -Y) in cube x / 4.
    auto renderer = effect(R"(TextureCubeArray C < string ResourceName = "cubes.dds"; >;
SamplerState S { Filter = MIN_MAG_MIP_POINT; };
float3 axis(float i) {
    float3 d[4] = { float3(1, 0, 0), float3(-1, 0, 0), float3(0, 1, 0), float3(0, -1, 0) };
    return d[min((int)i, 3)];
})",
                           "C.SampleLevel(S, float4(axis(floor(uv.x * 8) % 4), floor(uv.x * 2)), 0)");
    ASSERT_TRUE(renderer);
    const runtime::FrameImage image = frame(*renderer);
    ASSERT_TRUE(notConstant(image));
    for (int x = 0; x < 8; ++x)
        EXPECT_TRUE(near(image.pixel(x, 0), DdsColor{static_cast<uint8_t>(30 + 40 * (x % 4)), 10,
                                                     static_cast<uint8_t>(50 + 100 * (x / 4)), 255}))
            << x;
}

TEST_F(DdsTextures, TruncatedDx10ArrayIsALocatedError) {
    ASSERT_TRUE(DdsWriter::writeDx10Array((mDir / "short.dds").string(), 2, 2, 3, false, byElement, 5));
    sharedContext();
    const std::filesystem::path path = mDir / "dds.fx";
    std::ofstream(path) << R"(Texture2DArray T < string ResourceName = "short.dds"; >;
SamplerState S;
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS() : SV_Target { return T.Sample(S, float3(0.5, 0.5, 2)); }
technique11 t { pass p { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)";
    fx::DiagnosticList diagnostics;
    auto parsed = fx::parseEffectFile(path.string(), {}, diagnostics);
    ASSERT_TRUE(parsed) << diagnostics.str();
    std::shared_ptr<const fx::CompiledEffect> compiled =
        fx::compileEffect(parsed, fx::CompileOptions{}, diagnostics);
    ASSERT_TRUE(compiled) << diagnostics.str();
    EXPECT_FALSE(runtime::EffectRenderer::create(compiled, diagnostics));
    EXPECT_NE(diagnostics.str().find("dds.fx:1:16: error:"), std::string::npos) << diagnostics.str();
    EXPECT_NE(diagnostics.str().find("texture file 'short.dds' ends inside element 2's data"),
              std::string::npos)
        << diagnostics.str();
    EXPECT_EQ(diagnostics.items().back().id, fx::DiagId::TextureFileElementTruncated);

    // A header that claims 16384² texels per element is refused before anything that size is allocated.
    const std::string huge = (mDir / "huge.dds").string();
    ASSERT_TRUE(DdsWriter::writeDx10Array(huge, 2, 2, 3, false, byElement));
    {
        std::fstream file(huge, std::ios::in | std::ios::out | std::ios::binary);
        const char side[4] = {0, 0x40, 0, 0};  // 16384, little-endian
        file.seekp(12);
        file.write(side, 4);
        file.write(side, 4);
    }
    std::optional<runtime::TextureFileFault> fault;
    EXPECT_FALSE(runtime::loadTextureFile(huge, fault));
    EXPECT_EQ(fault->id, fx::DiagId::TextureFileElementTruncated);
    EXPECT_EQ(fault->values, std::vector<std::string>{"0"});
}

}  // namespace
}  // namespace shadowfx::test::test_dds_textures
