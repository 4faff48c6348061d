// GPU resources on llvmpipe: every texture format allocates, clears and reads back; four simultaneous
// colour targets; the full-screen quad's texcoord orientation; missing vertex inputs read their defaults;
// comparison samplers on depth textures; PNG write/load round trip.
#include "GlTestSupport.h"

#include <runtime/Framebuffer.h>
#include <runtime/GpuTexture.h>
#include <runtime/Image.h>
#include <runtime/RenderStateApplier.h>
#include <runtime/SamplerObject.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace test_gpu_resources {

using namespace runtime;
using testsupport::Program;

namespace {

class GpuResources : public ::testing::Test {
protected:
    GlContext& mContext = testsupport::sharedContext();
    FramebufferCache mFramebuffers;

    void bind(const RenderTargets& targets) {
        FramebufferFault fault;
        ASSERT_TRUE(mFramebuffers.bind(targets, fault));
    }
};

constexpr fx::TextureFormat kAllFormats[] = {
    fx::TextureFormat::RGBA8, fx::TextureFormat::RGBA16F, fx::TextureFormat::RGBA32F,
    fx::TextureFormat::R16F,  fx::TextureFormat::R32F,    fx::TextureFormat::RG16F,
    fx::TextureFormat::RG32F, fx::TextureFormat::RGBA16,  fx::TextureFormat::D16,
    fx::TextureFormat::D24S8, fx::TextureFormat::D24X8,   fx::TextureFormat::D32F,
};

const char* kUvFragmentShader = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(uv, 0.0, 1.0); }
)";

const char* kUvVertexShader = R"(#version 450
layout(location = 0) in vec4 inPosition;
layout(location = 3) in vec2 inTexcoord;
layout(location = 0) out vec2 uv;
void main() { gl_Position = inPosition; uv = inTexcoord; }
)";

TEST_F(GpuResources, EveryFormatAllocatesClearsAndReadsBack) {
    for (fx::TextureFormat format : kAllFormats) {
        SCOPED_TRACE("format " + std::to_string(int(format)));
        GpuTexture texture = GpuTexture::create2D(format, 8, 4);
        ASSERT_TRUE(texture);
        EXPECT_EQ(texture.width(), 8);
        EXPECT_EQ(texture.height(), 4);
        RenderTargets targets;
        if (texture.isDepth()) {
            targets.depth.texture = &texture;
            bind(targets);
            FramebufferCache::clear(
                {{}, 0.25f, texture.glFormat().hasStencil ? std::optional<int>(7) : std::nullopt});
            Image depth = readFloatTexture(texture);
            EXPECT_NEAR(depth.sample(7, 3, 0), 0.25f, 1e-4);
            if (texture.glFormat().hasStencil) {
                EXPECT_EQ(readFramebufferStencil(8, 4).bytes[5], 7);
            }
        } else {
            targets.colors[0].texture = &texture;
            bind(targets);
            FramebufferCache::clear({std::array<float, 4>{0.25f, 0.5f, 0.75f, 1.0f}, {}, {}});
            Image image = readColorTarget(texture);
            EXPECT_EQ(image.channels, texture.glFormat().channels);
            EXPECT_EQ(image.isFloat, texture.glFormat().isFloat);
            const float expected[4] = {0.25f, 0.5f, 0.75f, 1.0f};
            for (int c = 0; c < image.channels; ++c) {
                EXPECT_NEAR(image.sample(7, 3, c), expected[c], 1.0f / 255.0f) << "channel " << c;
            }
        }
        EXPECT_EQ(gl::GetError(), GLenum(GL_NO_ERROR));
    }
}

TEST_F(GpuResources, FloatTargetsKeepUnclampedValues) {
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA32F, 4, 4);
    RenderTargets targets;
    targets.colors[0].texture = &texture;
    bind(targets);
    FramebufferCache::clear({std::array<float, 4>{-3.5f, 1000.0f, 0.0f, 2.0f}, {}, {}});
    EXPECT_EQ(readColorTarget(texture).pixel(1, 1), glm::vec4(-3.5f, 1000.0f, 0.0f, 2.0f));
}

TEST_F(GpuResources, CubeMapsAndMipLevelsAreRenderTargets) {
    GpuTexture cube = GpuTexture::createCube(fx::TextureFormat::R32F, 8, 0);
    EXPECT_TRUE(cube.isCube());
    EXPECT_EQ(cube.mipLevels(), 4);
    for (int face = 0; face < 6; ++face) {
        RenderTargets targets;
        targets.colors[0] = {&cube, 1, face};
        bind(targets);
        EXPECT_EQ(targets.width(), 4);
        FramebufferCache::clear({std::array<float, 4>{float(face), 0, 0, 0}, {}, {}});
    }
    for (int face = 0; face < 6; ++face) {
        Image image = readFloatTexture(cube, 1, face);
        EXPECT_EQ(image.width, 4);
        EXPECT_EQ(image.sample(3, 3, 0), float(face));
    }
}

TEST_F(GpuResources, FourColorTargetsAtOnce) {
    std::vector<GpuTexture> colors;
    for (int i = 0; i < 4; ++i) colors.push_back(GpuTexture::create2D(fx::TextureFormat::RGBA32F, 8, 8));
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D24S8, 8, 8);
    RenderTargets targets;
    for (int i = 0; i < 4; ++i) targets.colors[size_t(i)].texture = &colors[size_t(i)];
    targets.depth.texture = &depth;
    bind(targets);
    bind(targets);
    EXPECT_EQ(mFramebuffers.size(), 1u) << "the same targets reuse one FBO";
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 1.0f, 0});
    Program program(testsupport::kClipSpaceVertexShader, R"(#version 450
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
layout(location = 2) out vec4 out2;
layout(location = 3) out vec4 out3;
void main() { out0 = vec4(1); out1 = vec4(2); out2 = vec4(3); out3 = vec4(4); }
)");
    program.use();
    applyRenderStates(RenderStateBlock::defaults());
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    quad.draw(testsupport::kPositionOnly);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(readColorTarget(colors[size_t(i)]).pixel(5, 5), glm::vec4(float(i + 1))) << "target " << i;
        EXPECT_EQ(readFramebufferColor(i, 8, 8).pixel(2, 6), glm::vec4(float(i + 1))) << "attachment " << i;
    }
    mFramebuffers.evict(colors[2]);
    EXPECT_EQ(mFramebuffers.size(), 0u);
}

// A target of the wrong kind is refused before GL sees it, each with its own id; nothing is cached.
TEST_F(GpuResources, TargetsOfTheWrongFormatAreRefusedWithTheirOwnIds) {
    GpuTexture color = GpuTexture::create2D(fx::TextureFormat::RGBA8, 8, 8);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D24S8, 8, 8);
    RenderTargets depthAsColor;
    depthAsColor.colors[1].texture = &depth;
    FramebufferFault fault;
    EXPECT_FALSE(mFramebuffers.bind(depthAsColor, fault));
    EXPECT_EQ(fault.id, fx::DiagId::ColorTargetHasDepthFormat);
    EXPECT_EQ(fault.arguments, std::vector<std::string>{"1"});

    RenderTargets colorAsDepth;
    colorAsDepth.colors[0].texture = &color;
    colorAsDepth.depth.texture = &color;
    fault = {};
    EXPECT_FALSE(mFramebuffers.bind(colorAsDepth, fault));
    EXPECT_EQ(fault.id, fx::DiagId::DepthTargetHasColorFormat);
    EXPECT_EQ(mFramebuffers.size(), 0u);

    // GL's own refusal carries no id: the caller reports it with its own, naming what it drew.
    const FramebufferFault incomplete{std::nullopt, {"GL_FRAMEBUFFER_UNSUPPORTED"}};
    const auto [id, arguments] = incomplete.diagnostic(fx::DiagId::PassTargetsUnbindable, {"p0"});
    EXPECT_EQ(id, fx::DiagId::PassTargetsUnbindable);
    EXPECT_EQ(arguments, (std::vector<std::string>{"p0", "GL_FRAMEBUFFER_UNSUPPORTED"}));
}

// SAS Draw=Buffer: TEXCOORD0 = (0,0) at the image's top-left, (1,1) at the bottom-right, front-facing
// under the default CullMode, at depth 0.
TEST_F(GpuResources, FullScreenQuadTexcoordsStartTopLeft) {
    constexpr int kSize = 8;
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RG32F, kSize, kSize);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D32F, kSize, kSize);
    RenderTargets targets;
    targets.colors[0].texture = &target;
    targets.depth.texture = &depth;
    bind(targets);
    FramebufferCache::clear({std::array<float, 4>{-1, -1, 0, 0}, 1.0f, {}});
    Program program(kUvVertexShader, kUvFragmentShader);
    program.use();
    applyRenderStates(RenderStateBlock::defaults());
    GpuMesh quad = GpuMesh::makeFullScreenQuad();
    quad.draw({{"POSITION", 0, 4, {fx::VertexStream::Position, 0}},
               {"TEXCOORD0", 3, 2, {fx::VertexStream::Texcoord, 0}}});
    Image image = readFloatTexture(target);
    const float half = 0.5f / kSize;
    EXPECT_NEAR(image.sample(0, 0, 0), half, 1e-5);
    EXPECT_NEAR(image.sample(0, 0, 1), half, 1e-5);
    EXPECT_NEAR(image.sample(kSize - 1, kSize - 1, 0), 1.0f - half, 1e-5);
    EXPECT_NEAR(image.sample(kSize - 1, kSize - 1, 1), 1.0f - half, 1e-5);
    EXPECT_NEAR(image.sample(kSize - 1, 0, 0), 1.0f - half, 1e-5);  // top-right: u = 1, v = 0
    EXPECT_NEAR(image.sample(kSize - 1, 0, 1), half, 1e-5);
    EXPECT_FLOAT_EQ(readFloatTexture(depth).sample(3, 3, 0), 0.0f);
}

TEST_F(GpuResources, MissingVertexInputsReadTheirDefaults) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RGBA32F, 4, 4);
    RenderTargets targets;
    targets.colors[0].texture = &target;
    bind(targets);
    Program program(R"(#version 450
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inColor;
layout(location = 2) in vec4 inNormal;
layout(location = 5) in vec4 inTangent;
layout(location = 6) in vec4 inBinormal;
layout(location = 0) flat out vec4 value;
uniform int uWhich;
void main() {
    gl_Position = inPosition;
    value = uWhich == 0 ? inColor : uWhich == 1 ? inNormal : uWhich == 2 ? inTangent : inBinormal;
}
)",
                    R"(#version 450
layout(location = 0) flat in vec4 value;
layout(location = 0) out vec4 outColor;
void main() { outColor = value; }
)");
    program.use();
    applyRenderStates(RenderStateBlock::defaults());
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);  // positions only
    const std::vector<fx::VertexInput> inputs = {{"POSITION", 0, 4, {fx::VertexStream::Position, 0}},
                                                 {"COLOR0", 1, 4, {fx::VertexStream::Color, 0}},
                                                 {"NORMAL", 2, 4, {fx::VertexStream::Normal, 0}},
                                                 {"TANGENT0", 5, 4, {fx::VertexStream::Tangent, 0}},
                                                 {"BINORMAL0", 6, 4, {fx::VertexStream::Binormal, 0}}};
    const glm::vec4 expected[4] = {{1, 1, 1, 1}, {0, 1, 0, 0}, {1, 0, 0, 1}, {0, 0, -1, 0}};
    for (int which = 0; which < 4; ++which) {
        gl::Uniform1i(gl::GetUniformLocation(program.id(), "uWhich"), which);
        quad.draw(inputs);
        EXPECT_EQ(readColorTarget(target).pixel(1, 1), expected[which]) << "input " << which;
    }
    EXPECT_EQ(gl::GetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GpuResources, ComparisonSamplerOnDepthTexture) {
    GpuTexture shadowMap = GpuTexture::create2D(fx::TextureFormat::D32F, 4, 4);
    RenderTargets depthOnly;
    depthOnly.depth.texture = &shadowMap;
    bind(depthOnly);
    FramebufferCache::clear({{}, 0.5f, {}});

    GpuTexture result = GpuTexture::create2D(fx::TextureFormat::R32F, 4, 4);
    RenderTargets targets;
    targets.colors[0].texture = &result;
    bind(targets);
    Program program(testsupport::kClipSpaceVertexShader, R"(#version 450
layout(binding = 0) uniform sampler2DShadow shadowMap;
uniform vec4 uRef;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(texture(shadowMap, vec3(0.5, 0.5, uRef.x))); }
)");
    fx::SamplerDesc desc;
    desc.addressU = desc.addressV = 3;  // CLAMP
    SamplerObject sampler(desc, /*depthCompare=*/true);
    EXPECT_TRUE(sampler.compares());
    gl::BindTextureUnit(0, shadowMap.id());
    sampler.bind(0);
    applyRenderStates(RenderStateBlock::defaults());
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    auto lit = [&](float reference) {
        program.set("uRef", reference);
        quad.draw(testsupport::kPositionOnly);
        return readFloatTexture(result).sample(2, 2, 0);
    };
    EXPECT_EQ(lit(0.4f), 1.0f);  // LESSEQUAL: 0.4 <= 0.5
    EXPECT_EQ(lit(0.5f), 1.0f);
    EXPECT_EQ(lit(0.6f), 0.0f);
    SamplerObject::unbind(0);
    gl::BindTextureUnit(0, 0);
}

TEST_F(GpuResources, SamplerAddressModesAndUpload) {
    // 2×1 texture: red, green. Sampling u = 1.25 (point): WRAP -> red (u 0.25), CLAMP -> green,
    // BORDER -> the border colour, MIRROR -> green (u 0.75).
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, 2, 1);
    const uint8_t pixels[] = {255, 0, 0, 255, 0, 255, 0, 255};
    texture.uploadRGBA8(pixels);
    GpuTexture result = GpuTexture::create2D(fx::TextureFormat::RGBA32F, 1, 1);
    RenderTargets targets;
    targets.colors[0].texture = &result;
    bind(targets);
    Program program(testsupport::kClipSpaceVertexShader, R"(#version 450
layout(binding = 0) uniform sampler2D tex;
layout(location = 0) out vec4 outColor;
void main() { outColor = texture(tex, vec2(1.25, 0.5)); }
)");
    program.use();
    applyRenderStates(RenderStateBlock::defaults());
    gl::BindTextureUnit(0, texture.id());
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    auto sampleWith = [&](int address) {
        fx::SamplerDesc desc;
        desc.addressU = desc.addressV = address;
        desc.borderColor[2] = 1.0f;
        desc.borderColor[3] = 1.0f;
        SamplerObject sampler(desc);
        sampler.bind(0);
        quad.draw(testsupport::kPositionOnly);
        SamplerObject::unbind(0);
        return readColorTarget(result).pixel(0, 0);
    };
    EXPECT_EQ(sampleWith(1), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(sampleWith(2), glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(sampleWith(3), glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(sampleWith(4), glm::vec4(0, 0, 1, 1));
    gl::BindTextureUnit(0, 0);
}

TEST_F(GpuResources, PngWriteAndLoadRoundTrip) {
    Image image = Image::makeBytes(5, 3, 4);
    for (size_t i = 0; i < image.bytes.size(); ++i) image.bytes[i] = uint8_t(i * 37 % 256);
    std::filesystem::path path = std::filesystem::temp_directory_path() / "shadowfx_test_roundtrip.png";
    std::string error;
    ASSERT_TRUE(image.writePng(path.string(), error)) << error;
    auto loaded = loadImageFile(path.string(), error);
    ASSERT_TRUE(loaded.has_value()) << error;
    EXPECT_EQ(loaded->width, 5);
    EXPECT_EQ(loaded->height, 3);
    EXPECT_EQ(loaded->bytes, image.bytes);
    std::filesystem::remove(path);

    EXPECT_FALSE(loadImageFile("/nonexistent/file.png", error).has_value());
    EXPECT_EQ(error, "can't fopen") << "stb_image's own reason";
}

TEST_F(GpuResources, RenderedImageSurvivesPngWithTopRowFirst) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RGBA8, 4, 4);
    RenderTargets targets;
    targets.colors[0].texture = &target;
    bind(targets);
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 1}, {}, {}});
    Program program(testsupport::kClipSpaceVertexShader, testsupport::kSolidColorFragmentShader);
    program.set("uColor", 1, 0, 0, 1);
    applyRenderStates(RenderStateBlock::defaults());
    // Top half (clip y > 0) red.
    GpuMesh topHalf = testsupport::clipSpaceTriangles(
        {{-1, 1, 0.5f}, {1, 1, 0.5f}, {1, 0, 0.5f}, {-1, 1, 0.5f}, {1, 0, 0.5f}, {-1, 0, 0.5f}});
    topHalf.draw(testsupport::kPositionOnly);
    Image image = readColorTarget(target);
    std::filesystem::path path = std::filesystem::temp_directory_path() / "shadowfx_test_tophalf.png";
    std::string error;
    ASSERT_TRUE(image.writePng(path.string(), error)) << error;
    auto loaded = loadImageFile(path.string(), error);
    ASSERT_TRUE(loaded.has_value()) << error;
    EXPECT_EQ(loaded->pixel(0, 0), glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(loaded->pixel(3, 3), glm::vec4(0, 0, 0, 1));
    std::filesystem::remove(path);
}
}  // namespace

}  // namespace test_gpu_resources
