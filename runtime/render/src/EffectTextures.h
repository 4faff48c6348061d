// EffectTextures: the textures an effect samples and renders into, by parameter index, with the frame's
// own colour and depth targets and the framebuffers that attach them. File, procedural and function
// textures are made at load; render targets are allocated for the frame's size when a frame first needs
// them and reallocated when that size changes; the application replaces a read texture through set().
// Invariants its mutators keep:
// - a render target is allocated at renderTargetSize() of the last frame size given (the frame's colour
//   and depth targets at that size itself);
// - a texture replaced (reallocated or set) leaves the framebuffer cache first: no cached framebuffer
//   attaches storage that is gone, and the next bind builds one on the new texture;
// - a mipmapped texture written through bindTargets() has its chain regenerated before it is next sampled
//   (refreshMipChain; D3D9's AUTOGENMIPMAP), and a replaced one is no longer counted as written.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <runtime/EffectRenderer.h>
#include <runtime/Framebuffer.h>
#include <runtime/GlApi.h>
#include <runtime/GpuTexture.h>
#include <runtime/GpuProgram.h>

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace runtime {

class EffectTextures {
public:
    // The textures the effect reads (files, procedural and function textures, the noise texture, a
    // neutral white one for a texture without contents); no render target yet. nullptr if a file cannot
    // be read or a texture function fails; the diagnostics say why. `values`: the parameter values a
    // texture function reads; `ring`: what it draws with.
    static std::unique_ptr<EffectTextures> create(const fx::CompiledEffect& effect,
                                                  const std::vector<fx::Value>& values, UniformRing& ring,
                                                  fx::DiagnosticSink& diagnostics);

    // A parameter's texture, or null where it has none (a render target the frames so far did not need).
    const GpuTexture* find(size_t parameter) const;
    // The neutral white texture a sampler of `samplerType` reads where nothing gives it a texture (a bare
    // `sampler2D Texture : register(s0);` whose texture only its application set), as an effect's texture
    // without contents is white: 2D, cube or volume.
    const GpuTexture& neutralFor(fx::BaseType samplerType);
    const GpuTexture& frameColor() const { return mFrameColor; }
    const GpuTexture& frameDepth() const { return mFrameDepth; }

    // (Re)allocates the frame's colour and depth targets at width x height and the render targets sized by
    // it. `needed`: the render targets to allocate (null: all); others already allocated are still resized.
    // True when the frame's targets were made anew (the first frame, a new size): they hold no picture.
    bool ensureFrame(int width, int height, const std::vector<bool>* needed = nullptr);
    // The render targets alone, for a frame of width x height (the application's viewport, EffectPass.h).
    void ensureRenderTargets(int width, int height, const std::vector<bool>* needed = nullptr);
    // EffectRenderer::setTexture: a read texture's texels replaced. False, with a diagnostic, for a
    // parameter that is no read texture or data of the wrong size.
    bool set(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics);
    // A GL texture of the application's given to a texture parameter (EffectVariable::setTexture), bound
    // wherever the parameter is sampled instead of the effect's own; the application keeps it alive.
    // Name 0 takes it back.
    struct ApplicationTexture {
        GLuint name = 0;
        GLenum target = GL_TEXTURE_2D;
    };
    void setApplicationTexture(size_t parameter, GLuint name, GLenum target);
    // The application's texture for a parameter, or null where it gave none.
    const ApplicationTexture* applicationTexture(size_t parameter) const;
    // Whether the application gave the parameter a texture: its own GL texture or texels (set()).
    bool givenByApplication(size_t parameter) const;
    // The host's picture of the scene that full-screen passes' samplers read (SamplerBinding::hostPicture):
    // a colour and a depth target of width x height, made or resized here. The caller paints them.
    RenderTargets hostPictureTargets(int width, int height);
    // Host files write their shadow ratio into the frame's colour target.
    void uploadFrameColor(const uint8_t* rgba8);

    // Binds a framebuffer of `targets` (FramebufferCache::bind); the mipmapped colour targets among them
    // are marked written, so that refreshMipChain regenerates their chain before they are sampled.
    bool bindTargets(const RenderTargets& targets, FramebufferFault& fault);
    // The same without marking: the frame's colour target read back, a host file's own targets.
    bool bindFramebuffer(const RenderTargets& targets, FramebufferFault& fault);
    // Regenerates the texture's mip chain if it was written since its last regeneration.
    void refreshMipChain(const GpuTexture& texture);
    size_t framebufferCount() const { return mFramebuffers.size(); }

    // A render target's allocation (GL name, size, format), for FramePlan's content hashes; `resource` is
    // a parameter index or kFrameColor/kFrameDepth.
    uint64_t identity(int resource) const;

private:
    explicit EffectTextures(const fx::CompiledEffect& effect) : mEffect(&effect) {}
    bool createFileTextures(const std::vector<fx::Value>& values, UniformRing& ring,
                            fx::DiagnosticSink& diagnostics);
    // Puts `texture` in the parameter's place, evicting the framebuffers of the one it replaces.
    void replace(size_t parameter, GpuTexture texture);

    const fx::CompiledEffect* mEffect;
    std::map<size_t, GpuTexture> mTextures;  // by texture parameter index
    FramebufferCache mFramebuffers;
    GpuTexture mFrameColor;
    GpuTexture mFrameDepth;
    std::set<const GpuTexture*> mStaleMipChains;  // mipmapped targets written since their chain was made
    std::map<size_t, ApplicationTexture> mApplicationTextures;  // by texture parameter index
    std::map<fx::BaseType, GpuTexture> mNeutralTextures;        // neutralFor's, made on first use
    std::set<size_t> mSetByApplication;  // read textures whose texels the application gave (set())
    GpuTexture mHostPicture;             // hostPictureTargets', made on first use
    GpuTexture mHostPictureDepth;
};

// A render target's size for a frame of width x height: its Dimensions, or its ViewPortRatio of the frame.
glm::ivec2 renderTargetSize(const fx::TextureDesc& desc, int width, int height);
bool isRenderTarget(const fx::TextureDesc& desc);

}  // namespace runtime
