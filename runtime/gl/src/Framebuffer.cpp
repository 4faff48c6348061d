#include <runtime/Framebuffer.h>

#include <algorithm>

namespace runtime {

namespace {

int levelSize(int size, int level) {
    return std::max(size >> level, 1);
}

void attach(GLenum attachment, const RenderTargetAttachment& target) {
    const GpuTexture& texture = *target.texture;
    if (target.whole) {
        gl::FramebufferTexture(GL_FRAMEBUFFER, attachment, texture.id(), target.level);
    } else if (texture.isCube()) {
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, attachment,
                                 GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + target.face), texture.id(),
                                 target.level);
    } else {
        // GL_TEXTURE_2D, or GL_TEXTURE_2D_MULTISAMPLE for D3D10's Texture2DMS targets.
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, attachment, texture.target(), texture.id(), target.level);
    }
}

std::string statusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "status " + std::to_string(status);
    }
}

}  // namespace

void dropDepthOfOtherLayering(RenderTargets& targets) {
    if (!targets.depth.texture) return;
    for (const RenderTargetAttachment& color : targets.colors)
        if (color.texture && color.whole != targets.depth.whole) {
            targets.depth = {};
            return;
        }
}

int RenderTargets::width() const {
    for (const auto& color : colors) {
        if (color.texture != nullptr) return levelSize(color.texture->width(), color.level);
    }
    return depth.texture != nullptr ? levelSize(depth.texture->width(), depth.level) : 0;
}

int RenderTargets::height() const {
    for (const auto& color : colors) {
        if (color.texture != nullptr) return levelSize(color.texture->height(), color.level);
    }
    return depth.texture != nullptr ? levelSize(depth.texture->height(), depth.level) : 0;
}

std::pair<fx::DiagId, std::vector<std::string>> FramebufferFault::diagnostic(
    fx::DiagId incomplete, std::vector<std::string> names) const {
    if (id) return {*id, arguments};
    names.insert(names.end(), arguments.begin(), arguments.end());
    return {incomplete, std::move(names)};
}

FramebufferCache::~FramebufferCache() {
    clearCache();
}

FramebufferCache::Key FramebufferCache::keyOf(const RenderTargets& targets) {
    Key key;
    for (int i = 0; i < 5; ++i) {
        const RenderTargetAttachment& attachment = i < 4 ? targets.colors[size_t(i)] : targets.depth;
        if (attachment.texture == nullptr) continue;
        key.serials[size_t(i)] = attachment.texture->serial();
        key.levels[size_t(i)] = attachment.level;
        key.faces[size_t(i)] = attachment.texture->isCube() ? attachment.face : 0;
        key.whole[size_t(i)] = attachment.whole;
    }
    return key;
}

bool FramebufferCache::bind(const RenderTargets& targets, FramebufferFault& fault) {
    Key key = keyOf(targets);
    auto found = mFramebuffers.find(key);
    if (found == mFramebuffers.end()) {
        Entry entry;
        entry.serials = key.serials;
        gl::GenFramebuffers(1, &entry.framebuffer);
        gl::BindFramebuffer(GL_FRAMEBUFFER, entry.framebuffer);
        for (int i = 0; i < RenderTargets::kMaxColorTargets; ++i) {
            const RenderTargetAttachment& color = targets.colors[size_t(i)];
            entry.drawBuffers[size_t(i)] = GL_NONE;
            if (color.texture == nullptr) continue;
            if (color.texture->isDepth()) {
                fault = {fx::DiagId::ColorTargetHasDepthFormat, {std::to_string(i)}};
                gl::DeleteFramebuffers(1, &entry.framebuffer);
                return false;
            }
            attach(GLenum(GL_COLOR_ATTACHMENT0 + i), color);
            entry.drawBuffers[size_t(i)] = GLenum(GL_COLOR_ATTACHMENT0 + i);
        }
        if (targets.depth.texture != nullptr) {
            if (!targets.depth.texture->isDepth()) {
                fault = {fx::DiagId::DepthTargetHasColorFormat, {}};
                gl::DeleteFramebuffers(1, &entry.framebuffer);
                return false;
            }
            attach(targets.depth.texture->glFormat().hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT
                                                                : GL_DEPTH_ATTACHMENT,
                   targets.depth);
        }
        // Slot i always writes GL_COLOR_ATTACHMENTi: a shader's COLORi output stays at location i even when
        // a lower slot is empty, as with D3D's SetRenderTarget(i). The list ends at the last bound slot:
        // GL counts the listed buffers against GL_MAX_DUAL_SOURCE_DRAW_BUFFERS (1) for dual-source blending.
        GLsizei drawBufferCount = 1;
        for (GLsizei i = 0; i < 4; ++i)
            if (entry.drawBuffers[size_t(i)] != GL_NONE) drawBufferCount = i + 1;
        gl::DrawBuffers(drawBufferCount, entry.drawBuffers.data());
        GLenum firstColor = GL_NONE;
        for (GLenum buffer : entry.drawBuffers) {
            if (buffer != GL_NONE) {
                firstColor = buffer;
                break;
            }
        }
        gl::ReadBuffer(firstColor);
        GLenum status = gl::CheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            fault = {std::nullopt, {statusName(status)}};
            gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
            gl::DeleteFramebuffers(1, &entry.framebuffer);
            return false;
        }
        found = mFramebuffers.emplace(key, entry).first;
    } else {
        gl::BindFramebuffer(GL_FRAMEBUFFER, found->second.framebuffer);
    }
    gl::Viewport(0, 0, targets.width(), targets.height());
    return true;
}

void FramebufferCache::bindDefault() {
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FramebufferCache::clear(const ClearRequest& request, int colorTarget) {
    // Clearing a GL_NONE draw buffer or a missing depth/stencil attachment is a no-op in GL, so the bound
    // framebuffer's layout need not be known here.
    if (request.color) {
        GLboolean saved[4][4];
        for (int i = 0; i < 4; ++i) {
            gl::GetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), saved[i]);
            gl::ColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            if (colorTarget < 0 || colorTarget == i) gl::ClearBufferfv(GL_COLOR, i, request.color->data());
        }
        for (int i = 0; i < 4; ++i)
            gl::ColorMaski(GLuint(i), saved[i][0], saved[i][1], saved[i][2], saved[i][3]);
    }
    if (request.depth || request.stencil) {
        GLboolean savedDepthMask = GL_TRUE;
        GLint savedFrontMask = 0, savedBackMask = 0;
        gl::GetBooleanv(GL_DEPTH_WRITEMASK, &savedDepthMask);
        gl::GetIntegerv(GL_STENCIL_WRITEMASK, &savedFrontMask);
        gl::GetIntegerv(GL_STENCIL_BACK_WRITEMASK, &savedBackMask);
        gl::DepthMask(GL_TRUE);
        gl::StencilMask(0xffffffffu);
        if (request.depth && request.stencil) {
            gl::ClearBufferfi(GL_DEPTH_STENCIL, 0, *request.depth, *request.stencil);
        } else if (request.depth) {
            gl::ClearBufferfv(GL_DEPTH, 0, &*request.depth);
        } else {
            gl::ClearBufferiv(GL_STENCIL, 0, &*request.stencil);
        }
        gl::DepthMask(savedDepthMask);
        gl::StencilMaskSeparate(GL_FRONT, GLuint(savedFrontMask));
        gl::StencilMaskSeparate(GL_BACK, GLuint(savedBackMask));
    }
}

void FramebufferCache::evict(const GpuTexture& texture) {
    for (auto it = mFramebuffers.begin(); it != mFramebuffers.end();) {
        const auto& serials = it->second.serials;
        if (std::find(serials.begin(), serials.end(), texture.serial()) != serials.end()) {
            gl::DeleteFramebuffers(1, &it->second.framebuffer);
            it = mFramebuffers.erase(it);
        } else {
            ++it;
        }
    }
}

void FramebufferCache::clearCache() {
    // Requires the owning context to be current, like every GL object's destruction here.
    for (auto& [key, entry] : mFramebuffers) gl::DeleteFramebuffers(1, &entry.framebuffer);
    mFramebuffers.clear();
}

}  // namespace runtime
