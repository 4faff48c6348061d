// D3D9 render states on GL, checked by rendering with llvmpipe and reading back: blend ops, the cull
// convention under upper-left clip control, depth functions and writes, colour write masks, depth bias,
// stencil (one- and two-sided), and the return to defaults.
#include "GlTestSupport.h"

#include <runtime/Framebuffer.h>
#include <runtime/GpuTexture.h>
#include <runtime/Image.h>
#include <runtime/RenderStateApplier.h>

#include <gtest/gtest.h>

namespace test_gl_states {

using namespace runtime;
using fx::RenderStateId;
using testsupport::Program;

namespace {

constexpr int kSize = 16;

class GlStates : public ::testing::Test {
protected:
    // First member: the context must be current before mSolid compiles.
    GlContext& mContext = testsupport::sharedContext();

    // Binds a colour target (and optionally a depth target) of kSize².
    void bindTargets(const GpuTexture* color, const GpuTexture* depth = nullptr) {
        RenderTargets targets;
        targets.colors[0].texture = color;
        targets.depth.texture = depth;
        FramebufferFault fault;
        ASSERT_TRUE(mFramebuffers.bind(targets, fault));
    }

    void drawColor(GpuMesh& mesh, float r, float g, float b, float a) {
        mSolid.set("uColor", r, g, b, a);
        mesh.draw(testsupport::kPositionOnly);
    }

    FramebufferCache mFramebuffers;
    Program mSolid{testsupport::kClipSpaceVertexShader, testsupport::kSolidColorFragmentShader};
};

RenderStateBlock withStates(std::initializer_list<std::pair<RenderStateId, double>> states) {
    RenderStateBlock block = RenderStateBlock::defaults();
    for (auto [id, value] : states) block.set(id, value);
    return block;
}

TEST_F(GlStates, DefaultsComeFromTheD3dTable) {
    RenderStateBlock block = RenderStateBlock::defaults();
    EXPECT_EQ(block.get(RenderStateId::CullMode), 3);  // CCW
    EXPECT_EQ(block.get(RenderStateId::ZFunc), 4);     // LESSEQUAL
    EXPECT_EQ(block.get(RenderStateId::ColorWriteEnable), 15);
    EXPECT_EQ(block.get(RenderStateId::StencilMask), double(0xffffffffu));
    EXPECT_EQ(block.get(RenderStateId::BlendFactor), double(0xffffffffu));
}

TEST_F(GlStates, BlendOpMinKeepsTheMinimumOnAnR32FTarget) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::R32F, kSize, kSize);
    bindTargets(&target);
    FramebufferCache::clear({std::array<float, 4>{100, 0, 0, 0}, {}, {}});
    applyRenderStates(withStates({{RenderStateId::AlphaBlendEnable, 1},
                                  {RenderStateId::BlendOp, 4},
                                  // factors are ignored by MIN: ZERO/ZERO would give 0 if they were not
                                  {RenderStateId::SrcBlend, 1},
                                  {RenderStateId::DestBlend, 1},
                                  {RenderStateId::ZEnable, 0}}));
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    for (float value : {5.0f, 2.0f, 7.0f, 3.5f}) drawColor(quad, value, 0, 0, 1);
    Image image = readFloatTexture(target);
    EXPECT_FLOAT_EQ(image.sample(0, 0, 0), 2.0f);
    EXPECT_FLOAT_EQ(image.sample(kSize - 1, kSize - 1, 0), 2.0f);

    applyRenderStates(withStates(
        {{RenderStateId::AlphaBlendEnable, 1}, {RenderStateId::BlendOp, 5}, {RenderStateId::ZEnable, 0}}));
    for (float value : {-4.0f, 9.0f, 7.0f}) drawColor(quad, value, 0, 0, 1);
    EXPECT_FLOAT_EQ(readFloatTexture(target).sample(3, 3, 0), 9.0f);
}

// DepthClipEnable = false clamps depth instead of clipping: a quad in front of the near plane (z = -0.5)
// is drawn, where by default it is clipped away (pancaking,
// docs/techniques/light-space-parameterizations.md).
TEST_F(GlStates, DepthClipDisabledDrawsWhatLiesBeforeTheNearPlane) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::R32F, kSize, kSize);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D24S8, kSize, kSize);
    bindTargets(&target, &depth);
    GpuMesh quad = testsupport::clipSpaceQuad(-0.5f);
    FramebufferCache::clear({std::array<float, 4>{100, 0, 0, 0}, 1.0f, {}});
    applyRenderStates(RenderStateBlock::defaults());
    drawColor(quad, 1, 0, 0, 1);
    EXPECT_FLOAT_EQ(readFloatTexture(target).sample(3, 3, 0), 100.0f) << "clipped at the near plane";
    applyRenderStates(withStates({{RenderStateId::DepthClipEnable, 0}}));
    EXPECT_TRUE(gl::IsEnabled(GL_DEPTH_CLAMP));
    drawColor(quad, 1, 0, 0, 1);
    EXPECT_FLOAT_EQ(readFloatTexture(target).sample(3, 3, 0), 1.0f) << "clamped to depth 0 and drawn";
    applyRenderStates(RenderStateBlock::defaults());
    EXPECT_FALSE(gl::IsEnabled(GL_DEPTH_CLAMP));
}

TEST_F(GlStates, BlendSubtractAndFactor) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RGBA32F, kSize, kSize);
    bindTargets(&target);
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    FramebufferCache::clear({std::array<float, 4>{1, 1, 1, 1}, {}, {}});
    // RevSubtract: dst*ONE - src*ONE.
    applyRenderStates(withStates({{RenderStateId::AlphaBlendEnable, 1},
                                  {RenderStateId::BlendOp, 3},
                                  {RenderStateId::SrcBlend, 2},
                                  {RenderStateId::DestBlend, 2}}));
    drawColor(quad, 0.25f, 0.5f, 0.0f, 0.0f);
    glm::vec4 pixel = readFloatTexture(target).pixel(1, 1);
    EXPECT_FLOAT_EQ(pixel.r, 0.75f);
    EXPECT_FLOAT_EQ(pixel.g, 0.5f);
    // BlendFactor is a D3DCOLOR (ARGB): src * factor.
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, {}, {}});
    applyRenderStates(withStates({{RenderStateId::AlphaBlendEnable, 1},
                                  {RenderStateId::SrcBlend, 14},
                                  {RenderStateId::DestBlend, 1},
                                  {RenderStateId::BlendFactor, double(0x80FF0000u)}}));
    drawColor(quad, 1, 1, 1, 1);
    pixel = readFloatTexture(target).pixel(1, 1);
    EXPECT_FLOAT_EQ(pixel.r, 1.0f);
    EXPECT_FLOAT_EQ(pixel.g, 0.0f);
    EXPECT_FLOAT_EQ(pixel.b, 0.0f);
    EXPECT_NEAR(pixel.a, 128.0f / 255.0f, 1e-6);
}

// The cull convention, pinned: D3D9's default CullMode = CCW culls triangles whose vertices run
// counter-clockwise on screen (y down) and keeps clockwise ones.
TEST_F(GlStates, CullConventionMatchesD3dScreenWinding) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    bindTargets(&target);
    // Upper-left, upper-right, lower-right: clockwise as seen on screen (and on the image read back).
    GpuMesh clockwise = testsupport::clipSpaceTriangles({{-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}});
    GpuMesh counterClockwise = testsupport::clipSpaceTriangles({{-1, 1, 0.5f}, {1, -1, 0.5f}, {1, 1, 0.5f}});

    auto covered = [&](GpuMesh& mesh, double cullMode) {
        FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, {}, {}});
        applyRenderStates(withStates({{RenderStateId::CullMode, cullMode}}));
        drawColor(mesh, 1, 1, 1, 1);
        // The triangle covers the upper-right half; pixel (kSize-2, 1) is well inside it, in image rows
        // counted from the top.
        Image image = readColorTarget(target);
        EXPECT_EQ(image.pixel(1, kSize - 2).r, 0.0f) << "lower-left half must stay empty";
        return image.pixel(kSize - 2, 1).r > 0.5f;
    };
    EXPECT_TRUE(covered(clockwise, 3)) << "CCW must keep clockwise triangles";
    EXPECT_FALSE(covered(counterClockwise, 3)) << "CCW must cull counter-clockwise triangles";
    EXPECT_FALSE(covered(clockwise, 2)) << "CW must cull clockwise triangles";
    EXPECT_TRUE(covered(counterClockwise, 2)) << "CW must keep counter-clockwise triangles";
    EXPECT_TRUE(covered(clockwise, 1));
    EXPECT_TRUE(covered(counterClockwise, 1));
}

TEST_F(GlStates, DepthFuncAndDepthWrites) {
    GpuTexture color = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D32F, kSize, kSize);
    bindTargets(&color, &depth);
    GpuMesh near = testsupport::clipSpaceQuad(0.25f);
    GpuMesh far = testsupport::clipSpaceQuad(0.75f);

    auto passes = [&](GpuMesh& mesh, double zFunc) {
        FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 0.5f, {}});
        applyRenderStates(withStates({{RenderStateId::ZFunc, zFunc}}));
        drawColor(mesh, 1, 1, 1, 1);
        return readColorTarget(color).pixel(4, 4).r > 0.5f;
    };
    EXPECT_TRUE(passes(near, 2));  // LESS
    EXPECT_FALSE(passes(far, 2));
    EXPECT_FALSE(passes(near, 5));  // GREATER
    EXPECT_TRUE(passes(far, 5));
    EXPECT_FALSE(passes(near, 1));  // NEVER
    EXPECT_TRUE(passes(far, 8));    // ALWAYS

    // ZWriteEnable = FALSE: the test still runs, the buffer keeps its value.
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 0.5f, {}});
    applyRenderStates(withStates({{RenderStateId::ZWriteEnable, 0}}));
    drawColor(near, 1, 1, 1, 1);
    EXPECT_FLOAT_EQ(readFloatTexture(depth).sample(4, 4, 0), 0.5f);
    applyRenderStates(RenderStateBlock::defaults());
    drawColor(near, 1, 1, 1, 1);
    EXPECT_FLOAT_EQ(readFloatTexture(depth).sample(4, 4, 0), 0.25f);

    // ZEnable = FALSE: everything passes, nothing is written.
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 0.0f, {}});
    applyRenderStates(withStates({{RenderStateId::ZEnable, 0}}));
    drawColor(far, 1, 1, 1, 1);
    EXPECT_GT(readColorTarget(color).pixel(4, 4).r, 0.5f);
    EXPECT_FLOAT_EQ(readFloatTexture(depth).sample(4, 4, 0), 0.0f);
}

TEST_F(GlStates, ColorWriteEnableMasksChannelsPerTarget) {
    GpuTexture target = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    bindTargets(&target);
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, {}, {}});
    applyRenderStates(withStates({{RenderStateId::ColorWriteEnable, 1 | 4}}));  // RED | BLUE
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    drawColor(quad, 1, 1, 1, 1);
    glm::vec4 pixel = readColorTarget(target).pixel(2, 2);
    EXPECT_EQ(pixel, glm::vec4(1, 0, 1, 0));

    // D3D's Clear ignores ColorWriteEnable; the mask is back afterwards.
    FramebufferCache::clear({std::array<float, 4>{0, 1, 0, 1}, {}, {}});
    EXPECT_EQ(readColorTarget(target).pixel(2, 2), glm::vec4(0, 1, 0, 1));
    GLboolean mask[4];
    gl::GetBooleani_v(GL_COLOR_WRITEMASK, 0, mask);
    EXPECT_TRUE(mask[0] && !mask[1] && mask[2] && !mask[3]);

    // ColorWriteEnable1 applies to draw buffer 1 only.
    applyRenderStates(withStates({{RenderStateId::ColorWriteEnable1, 8}}));
    gl::GetBooleani_v(GL_COLOR_WRITEMASK, 0, mask);
    EXPECT_TRUE(mask[0] && mask[1] && mask[2] && mask[3]);
    gl::GetBooleani_v(GL_COLOR_WRITEMASK, 1, mask);
    EXPECT_TRUE(!mask[0] && !mask[1] && !mask[2] && mask[3]);
}

// DepthBias is in depth units (D3D9 adds it to z): 0.01 moves a z = 0.5 quad to 0.51 (exactly on D32F;
// UNORM depth within GL's implementation-defined resolvable difference, see below).
TEST_F(GlStates, DepthBiasOffsetsDepthInDepthUnits) {
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    for (auto format : {fx::TextureFormat::D24S8, fx::TextureFormat::D32F, fx::TextureFormat::D16}) {
        GpuTexture depth = GpuTexture::create2D(format, kSize, kSize);
        bindTargets(nullptr, &depth);
        int bits = depth.glFormat().depthBits == 32 ? 24 : depth.glFormat().depthBits;
        FramebufferCache::clear({{}, 1.0f, 0});
        applyRenderStates(withStates({{RenderStateId::DepthBias, 0.01}}), bits);
        drawColor(quad, 1, 1, 1, 1);
        float biased = readFloatTexture(depth).sample(5, 5, 0);
        if (format == fx::TextureFormat::D32F) {
            EXPECT_NEAR(biased, 0.51f, 2e-4) << "D32F";
        } else {
            // GL leaves r implementation-defined ("the smallest value guaranteed to produce a resolvable
            // offset"); llvmpipe uses 2 / 2^bits for UNORM depth, so the bias comes out doubled there.
            EXPECT_GE(biased, 0.51f - 2e-4) << "format " << int(format);
            EXPECT_LE(biased, 0.52f + 2e-4) << "format " << int(format);
        }

        FramebufferCache::clear({{}, 1.0f, 0});
        applyRenderStates(RenderStateBlock::defaults(), bits);
        drawColor(quad, 1, 1, 1, 1);
        EXPECT_NEAR(readFloatTexture(depth).sample(5, 5, 0), 0.5f, 1e-4) << "format " << int(format);
    }
    // SlopeScaleDepthBias: nothing on a quad facing the viewer, an offset on a slanted one.
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D32F, kSize, kSize);
    bindTargets(nullptr, &depth);
    GpuMesh slanted = testsupport::clipSpaceTriangles(
        {{-1, 1, 0.2f}, {1, 1, 0.8f}, {1, -1, 0.8f}, {-1, 1, 0.2f}, {1, -1, 0.8f}, {-1, -1, 0.2f}});
    FramebufferCache::clear({{}, 1.0f, {}});
    applyRenderStates(RenderStateBlock::defaults());
    drawColor(slanted, 1, 1, 1, 1);
    float plain = readFloatTexture(depth).sample(8, 8, 0);
    FramebufferCache::clear({{}, 1.0f, {}});
    applyRenderStates(withStates({{RenderStateId::SlopeScaleDepthBias, 2.0}}));
    drawColor(slanted, 1, 1, 1, 1);
    float sloped = readFloatTexture(depth).sample(8, 8, 0);
    // The depth slope is 0.6 over 16 pixels per pixel: 2 × 0.0375 = 0.075.
    EXPECT_NEAR(sloped - plain, 0.075f, 0.01f);
}

// D3D10's DepthBiasClamp bounds the whole offset (in depth units) through glPolygonOffsetClamp, which
// llvmpipe offers (ARB_polygon_offset_clamp): the 0.01 bias above stops at 0.002.
TEST_F(GlStates, DepthBiasClampBoundsTheOffset) {
    ASSERT_TRUE(gl::PolygonOffsetClamp) << "this GL has no glPolygonOffsetClamp";
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D32F, kSize, kSize);
    bindTargets(nullptr, &depth);
    FramebufferCache::clear({{}, 1.0f, 0});
    applyRenderStates(withStates({{RenderStateId::DepthBias, 0.01}, {RenderStateId::DepthBiasClamp, 0.002}}));
    drawColor(quad, 1, 1, 1, 1);
    EXPECT_NEAR(readFloatTexture(depth).sample(5, 5, 0), 0.502f, 2e-4);
    // 0 is D3D10's "no clamp": the full bias.
    FramebufferCache::clear({{}, 1.0f, 0});
    applyRenderStates(withStates({{RenderStateId::DepthBias, 0.01}, {RenderStateId::DepthBiasClamp, 0.0}}));
    drawColor(quad, 1, 1, 1, 1);
    EXPECT_NEAR(readFloatTexture(depth).sample(5, 5, 0), 0.51f, 2e-4);
}

TEST_F(GlStates, StencilReplaceThenEqualMasksDrawing) {
    GpuTexture color = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D24S8, kSize, kSize);
    bindTargets(&color, &depth);
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 1.0f, 0});
    // Left half: stencil := 5, no colour.
    GpuMesh leftHalf = testsupport::clipSpaceTriangles(
        {{-1, 1, 0.5f}, {0, 1, 0.5f}, {0, -1, 0.5f}, {-1, 1, 0.5f}, {0, -1, 0.5f}, {-1, -1, 0.5f}});
    applyRenderStates(withStates({{RenderStateId::StencilEnable, 1},
                                  {RenderStateId::StencilPass, 3},
                                  {RenderStateId::StencilRef, 5},
                                  {RenderStateId::ColorWriteEnable, 0}}));
    drawColor(leftHalf, 1, 1, 1, 1);
    // Everywhere, where stencil == 5.
    GpuMesh quad = testsupport::clipSpaceQuad(0.5f);
    applyRenderStates(withStates({{RenderStateId::StencilEnable, 1},
                                  {RenderStateId::StencilFunc, 3},
                                  {RenderStateId::StencilRef, 5},
                                  {RenderStateId::ZFunc, 8}}));
    drawColor(quad, 1, 1, 1, 1);
    Image image = readColorTarget(color);
    EXPECT_GT(image.pixel(2, 8).r, 0.5f);
    EXPECT_EQ(image.pixel(kSize - 3, 8).r, 0.0f);
    Image stencil = readFramebufferStencil(kSize, kSize);
    EXPECT_EQ(stencil.bytes[8 * kSize + 2], 5);
    EXPECT_EQ(stencil.bytes[8 * kSize + kSize - 3], 0);

    // StencilWriteMask limits the bits written; Clear ignores it.
    applyRenderStates(withStates({{RenderStateId::StencilEnable, 1},
                                  {RenderStateId::StencilPass, 3},
                                  {RenderStateId::StencilRef, 0xff},
                                  {RenderStateId::StencilWriteMask, 0x0f}}));
    FramebufferCache::clear({{}, {}, 0x80});
    drawColor(quad, 1, 1, 1, 1);
    EXPECT_EQ(readFramebufferStencil(kSize, kSize).bytes[3], 0x8f);
}

// TwoSidedStencilMode: Stencil* for clockwise (front) triangles, CCW_* for counter-clockwise ones.
TEST_F(GlStates, TwoSidedStencilUsesCcwStatesForCounterClockwiseTriangles) {
    GpuTexture color = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    GpuTexture depth = GpuTexture::create2D(fx::TextureFormat::D24S8, kSize, kSize);
    bindTargets(&color, &depth);
    FramebufferCache::clear({std::array<float, 4>{0, 0, 0, 0}, 1.0f, 1});
    // Upper-right half clockwise; lower-left half counter-clockwise (top-left, bottom-left, bottom-right).
    GpuMesh mesh = testsupport::clipSpaceTriangles(
        {{-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}, {-1, 1, 0.5f}, {-1, -1, 0.5f}, {1, -1, 0.5f}});
    applyRenderStates(withStates({{RenderStateId::CullMode, 1},
                                  {RenderStateId::StencilEnable, 1},
                                  {RenderStateId::TwoSidedStencilMode, 1},
                                  {RenderStateId::StencilPass, 7},         // INCR
                                  {RenderStateId::CCW_StencilPass, 8}}));  // DECR
    drawColor(mesh, 1, 1, 1, 1);
    Image stencil = readFramebufferStencil(kSize, kSize);
    EXPECT_EQ(stencil.bytes[1 * kSize + (kSize - 2)], 2) << "clockwise: StencilPass = INCR";
    EXPECT_EQ(stencil.bytes[(kSize - 2) * kSize + 1], 0) << "counter-clockwise: CCW_StencilPass = DECR";
}

TEST_F(GlStates, UnsetStatesReturnToDefaults) {
    applyRenderStates(withStates({{RenderStateId::CullMode, 1},
                                  {RenderStateId::AlphaBlendEnable, 1},
                                  {RenderStateId::StencilEnable, 1},
                                  {RenderStateId::ZEnable, 0},
                                  {RenderStateId::FillMode, 2},
                                  {RenderStateId::DepthBias, 0.5},
                                  {RenderStateId::ScissorTestEnable, 1}}));
    applyRenderStates(RenderStateBlock::defaults());
    EXPECT_TRUE(gl::IsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(gl::IsEnabled(GL_BLEND));
    EXPECT_FALSE(gl::IsEnabled(GL_STENCIL_TEST));
    EXPECT_TRUE(gl::IsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(gl::IsEnabled(GL_POLYGON_OFFSET_FILL));
    EXPECT_FALSE(gl::IsEnabled(GL_SCISSOR_TEST));
    GLint mode[2] = {};
    gl::GetIntegerv(GL_POLYGON_MODE, mode);
    EXPECT_EQ(mode[0], GL_FILL);
    GLint func = 0;
    gl::GetIntegerv(GL_DEPTH_FUNC, &func);
    EXPECT_EQ(func, GL_LEQUAL);
    EXPECT_EQ(gl::GetError(), GLenum(GL_NO_ERROR));
}
}  // namespace

}  // namespace test_gl_states
