// GlStateSnapshot: the part of a GL context's state that applying an effect pass writes, read before the
// pass and written back after it: what D3DX9's Begin()/End() did unless the application passed
// D3DXFX_DONOTSAVESTATE. GlStateMask names that part per pass, as FX11's ComputeStateBlockMask did: an
// application that saves its state itself reads from the mask what it must save.
//
// Reading GL state back costs a round trip per value on most drivers (llvmpipe answers from the context at
// once): a frame loop that sets every state it draws with anyway asks for no saving.
#pragma once

#include <runtime/GlApi.h>

#include <array>
#include <string>
#include <vector>

namespace runtime {

struct GlStateMask {
    // glUseProgram.
    bool program = false;
    // Every state runtime/RenderStateApplier.h writes: depth test, mask and function; cull face, front
    // face, polygon mode and offset, scissor test enable, multisample, depth clamp, sRGB writes, alpha to
    // coverage, sample mask, point size and program point size; blend enables, functions and equations of
    // draw buffers 0-7, blend colour, colour write masks of draw buffers 0-3; stencil test, functions,
    // operations and write masks.
    bool renderStates = false;
    // The draw and read framebuffer bindings and the viewport.
    bool framebuffer = false;
    // Texture units whose texture bindings (every target) and sampler object the pass sets, and the active
    // unit (glActiveTexture).
    std::vector<int> textureUnits;
    // GL_UNIFORM_BUFFER binding points the pass binds ranges to, and the generic GL_UNIFORM_BUFFER binding.
    std::vector<int> uniformBuffers;
    // GL_SHADER_STORAGE_BUFFER binding points, and the generic GL_SHADER_STORAGE_BUFFER binding.
    std::vector<int> storageBuffers;

    // What both masks touch.
    void add(const GlStateMask& other);
    // One line per group ("program", "render states", "framebuffer and viewport", "texture unit 2", ...),
    // for tools and messages.
    std::vector<std::string> describe() const;
};

class GlStateSnapshot {
public:
    // Reads the state `mask` names from the current context.
    static GlStateSnapshot capture(const GlStateMask& mask);
    // The same into `into`, whose storage is reused: a snapshot taken every frame allocates nothing once
    // it has been taken.
    static void capture(const GlStateMask& mask, GlStateSnapshot& into);
    // Writes it back to the current context.
    void restore() const;

private:
    struct Enable {
        GLenum capability;
        bool on;
    };
    struct BufferRange {
        int binding;
        GLint buffer;
        GLint start, size;  // offsets past 2 GiB do not occur in uniform or storage ranges
    };
    struct TextureUnit {
        int unit;
        std::array<GLint, 9> textures;  // per target in kTextureTargets
        GLint sampler;
    };
    GlStateMask mMask;
    GLint mProgram = 0;
    // Render states.
    std::vector<Enable> mEnables;
    std::array<bool, 8> mBlend{};
    GLboolean mDepthMask = GL_TRUE;
    GLint mDepthFunc = GL_LESS, mFrontFace = GL_CCW, mCullFace = GL_BACK;
    std::array<GLint, 2> mPolygonMode{};
    GLfloat mOffsetFactor = 0, mOffsetUnits = 0, mOffsetClamp = 0;
    GLfloat mPointSize = 1;
    GLint mSampleMask = 0;
    std::array<std::array<GLint, 6>, 8> mBlendFunctions{};  // src rgb, dst rgb, src a, dst a, eq rgb, eq a
    std::array<GLfloat, 4> mBlendColor{};
    std::array<std::array<GLboolean, 4>, 4> mColorMasks{};
    std::array<std::array<GLint, 6>, 2> mStencil{};  // func, ref, value mask, fail, depth fail, pass
    std::array<GLint, 2> mStencilWriteMask{};
    // Framebuffer.
    GLint mDrawFramebuffer = 0, mReadFramebuffer = 0;
    std::array<GLint, 4> mViewport{};
    // Resources.
    GLint mActiveTexture = GL_TEXTURE0;
    std::vector<TextureUnit> mUnits;
    std::vector<int> mUnitOrder;  // the units mUnits saves, in order: the mask's and the active one
    GLint mUniformBuffer = 0, mStorageBuffer = 0;
    std::vector<BufferRange> mUniformRanges, mStorageRanges;
};

}  // namespace runtime
