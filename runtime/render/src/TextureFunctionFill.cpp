#include "TextureFunctionFill.h"

#include <algorithm>
#include <memory>

namespace runtime {

namespace {

// The GL state the fill changes, as it found it: effect creation may run between another effect's
// frames (hot reload), whose state the runtime tracks.
class SavedFillState {
public:
    SavedFillState() {
        gl::GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDrawFramebuffer);
        gl::GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadFramebuffer);
        gl::GetIntegerv(GL_VIEWPORT, mViewport);
        gl::GetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
        gl::GetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
        gl::GetBooleanv(GL_COLOR_WRITEMASK, mColorMask);
        for (size_t i = 0; i < std::size(kCapabilities); ++i) mEnabled[i] = gl::IsEnabled(kCapabilities[i]);
    }
    // A name bound when the fill began may have been deleted meanwhile (a program or vertex array
    // deleted while current lives until it is replaced, which the fill does): such a one is not rebound.
    ~SavedFillState() {
        const auto name = [](GLint value) { return static_cast<GLuint>(value); };
        const bool drawFramebuffer = mDrawFramebuffer == 0 || gl::IsFramebuffer(name(mDrawFramebuffer));
        const bool readFramebuffer = mReadFramebuffer == 0 || gl::IsFramebuffer(name(mReadFramebuffer));
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, drawFramebuffer ? name(mDrawFramebuffer) : 0);
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer ? name(mReadFramebuffer) : 0);
        gl::Viewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
        gl::BindVertexArray(gl::IsVertexArray(name(mVertexArray)) ? name(mVertexArray) : 0);
        gl::UseProgram(gl::IsProgram(name(mProgram)) ? name(mProgram) : 0);
        gl::ColorMask(mColorMask[0], mColorMask[1], mColorMask[2], mColorMask[3]);
        for (size_t i = 0; i < std::size(kCapabilities); ++i)
            (mEnabled[i] ? gl::Enable : gl::Disable)(kCapabilities[i]);
    }
    SavedFillState(const SavedFillState&) = delete;
    SavedFillState& operator=(const SavedFillState&) = delete;

    // What would change the texels a fill draws: every one is off while it draws.
    static constexpr GLenum kCapabilities[] = {
        GL_BLEND,     GL_DEPTH_TEST,         GL_STENCIL_TEST,     GL_SCISSOR_TEST,
        GL_CULL_FACE, GL_RASTERIZER_DISCARD, GL_FRAMEBUFFER_SRGB, GL_SAMPLE_ALPHA_TO_COVERAGE};

private:
    GLint mDrawFramebuffer = 0, mReadFramebuffer = 0, mViewport[4] = {}, mVertexArray = 0, mProgram = 0;
    GLboolean mColorMask[4] = {};
    GLboolean mEnabled[std::size(kCapabilities)] = {};
};

GpuTexture createTexture(const fx::TextureDesc& desc) {
    switch (desc.type) {
        case fx::BaseType::TextureCube:
            return GpuTexture::createCube(desc.format, desc.width, desc.mipLevels);
        case fx::BaseType::Texture3D:
            return GpuTexture::create3D(desc.format, desc.width, desc.height, desc.depth, desc.mipLevels);
        default:
            return GpuTexture::create2D(desc.format, desc.width, desc.height, desc.mipLevels);
    }
}

}  // namespace

std::optional<GpuTexture> fillTextureFunction(const fx::TextureDesc& desc,
                                              const std::vector<fx::Value>& values, UniformRing& ring,
                                              fx::DiagnosticSink& diagnostics) {
    const SavedFillState saved;
    std::unique_ptr<GpuProgram> program = GpuProgram::create(*desc.fill, diagnostics);
    if (!program) return std::nullopt;
    GpuTexture texture = createTexture(desc);

    GLuint framebuffer = 0, vertexArray = 0;
    gl::GenFramebuffers(1, &framebuffer);
    gl::GenVertexArrays(1, &vertexArray);  // the vertex stage reads SV_VertexID alone
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::BindVertexArray(vertexArray);
    for (GLenum capability : SavedFillState::kCapabilities) gl::Disable(capability);
    gl::ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    program->bind();

    const bool cube = desc.type == fx::BaseType::TextureCube;
    const bool volume = desc.type == fx::BaseType::Texture3D;
    for (int level = 0; level < texture.mipLevels(); ++level) {
        const int width = std::max(1, desc.width >> level);
        const int height = std::max(1, desc.height >> level);
        const int depth = volume ? std::max(1, desc.depth >> level) : 1;
        gl::Viewport(0, 0, width, height);
        for (int layer = 0; layer < (cube ? 6 : depth); ++layer) {
            if (cube)
                gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                         GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(layer),
                                         texture.id(), level);
            else if (volume)
                gl::FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture.id(), level, layer);
            else
                gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(),
                                         level);
            // fx::TextureDesc::fill: the texel's size, then the slice's centre or the face.
            const float slice = cube ? static_cast<float>(layer) : volume ? (layer + 0.5f) / depth : 0.0f;
            const std::vector<fx::Value> fill{
                fx::Value::vector({1.0f / width, 1.0f / height, volume ? 1.0f / depth : 0.0f, slice})};
            program->upload(values, fill, ring);
            gl::DrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteVertexArrays(1, &vertexArray);
    return texture;
}

}  // namespace runtime
