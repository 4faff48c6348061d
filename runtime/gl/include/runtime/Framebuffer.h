// Framebuffer: binding render targets the D3D way (SetRenderTarget(0..3) + SetDepthStencilSurface) on
// top of GL framebuffer objects, cached by the set of attachments, and D3D's Clear.
//
// The cache keys on GpuTexture::serial(), never on GL names (GL reuses a deleted texture's name, and a
// cached FBO would then point at the old, orphaned storage). FBOs of deleted textures stay in the cache
// until evict()/clear(): cheap, and render targets live as long as their effect.
#pragma once

#include <fx/Diagnostics.h>
#include <runtime/GpuTexture.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

struct RenderTargetAttachment {
    const GpuTexture* texture = nullptr;
    int level = 0;  // mip level
    int face = 0;   // cube face 0..5 (+X -X +Y -Y +Z -Z); ignored for 2D textures
    // Every layer at once (a cube's faces, an array's elements, a volume's slices; glFramebufferTexture),
    // as D3D10 binds a view of the whole resource: a geometry shader's SV_RenderTargetArrayIndex
    // (gl_Layer) picks the layer each primitive is drawn into, layer 0 where it writes none; a clear clears
    // every layer. `face` is then ignored.
    bool whole = false;

    // The whole texture, layered where it has layers: how an effect's or an application's target is bound.
    static RenderTargetAttachment wholeOf(const GpuTexture* texture) {
        return {texture, 0, 0, texture != nullptr && texture->isLayered()};
    }
};

struct RenderTargets {
    static constexpr int kMaxColorTargets = 4;  // D3D9's simultaneous render targets
    std::array<RenderTargetAttachment, kMaxColorTargets> colors{};
    RenderTargetAttachment depth{};

    // Width and height of the first attachment present (at its level); 0×0 when empty.
    int width() const;
    int height() const;
};

// A layered colour target (a cube, an array or a volume bound whole) and a depth target that is not
// layered (the frame's), or the reverse, cannot be one framebuffer (GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS):
// such a pair is drawn without the depth target. A layered depth target of its own (a cube or an array
// with a depth format) stays.
void dropDepthOfOtherLayering(RenderTargets& targets);

// D3D9's Clear(flags, color, z, stencil): what to clear and to which values.
struct ClearRequest {
    std::optional<std::array<float, 4>> color;  // every bound colour target, float values (unclamped
                                                // for float targets)
    std::optional<float> depth;
    std::optional<int> stencil;  // only if the depth target has stencil
};

// Why FramebufferCache::bind refused targets: a target of the wrong format (`id`, with `arguments`), or GL
// calling the combination incomplete (no `id`; `arguments` holds the GL_FRAMEBUFFER_... status), which each
// caller reports with its own id, naming what it drew.
struct FramebufferFault {
    std::optional<fx::DiagId> id;
    std::vector<std::string> arguments;

    // The id and arguments to report: the fault's own, or `incomplete` with `names` (what was drawn)
    // followed by the status.
    std::pair<fx::DiagId, std::vector<std::string>> diagnostic(fx::DiagId incomplete,
                                                               std::vector<std::string> names) const;
};

class FramebufferCache {
public:
    FramebufferCache() = default;
    ~FramebufferCache();
    FramebufferCache(const FramebufferCache&) = delete;
    FramebufferCache& operator=(const FramebufferCache&) = delete;

    // Binds (creating on first use) the FBO for these targets as GL_FRAMEBUFFER (draw and read) with
    // glDrawBuffers(color slot i -> GL_COLOR_ATTACHMENTi; empty slots GL_NONE), the read buffer on the
    // first colour target, and the viewport to the targets' size. Returns false and sets `fault` for a
    // target of the wrong format or when GL calls the combination incomplete. Sizes may differ, as D3D9
    // allows a depth surface larger than the colour targets: GL renders the intersection.
    bool bind(const RenderTargets& targets, FramebufferFault& fault);
    // The window's (or the headless context's) default framebuffer.
    static void bindDefault();

    // D3D9 Clear on the currently bound targets: ignores ColorWriteEnable, ZWriteEnable and
    // StencilWriteMask (all write masks are opened for the clear and restored after), honours the scissor
    // test like D3D9 does when ScissorTestEnable is set. `colorTarget` >= 0: the colour clear is that
    // draw buffer's alone (a script's Clear=SV_TARGETn).
    static void clear(const ClearRequest& request, int colorTarget = -1);

    void evict(const GpuTexture& texture);  // drops every FBO that uses it
    void clearCache();
    size_t size() const { return mFramebuffers.size(); }

private:
    struct Key {
        std::array<uint64_t, 5> serials{};
        std::array<int, 5> levels{};
        std::array<int, 5> faces{};
        std::array<bool, 5> whole{};
        auto operator<=>(const Key&) const = default;
    };
    struct Entry {
        GLuint framebuffer = 0;
        std::array<GLenum, 4> drawBuffers{};
        std::array<uint64_t, 5> serials{};  // for evict()
    };
    static Key keyOf(const RenderTargets& targets);

    std::map<Key, Entry> mFramebuffers;
};

}  // namespace runtime
