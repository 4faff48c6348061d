// GlStateSnapshot: see GlStateSnapshot.h. The lists below follow RenderStateApplier.cpp call for call: a
// state it learns to write must be read and restored here too (test_pass_api's save/restore test compares
// every value before and after).
#include <runtime/GlStateSnapshot.h>

#include <algorithm>

namespace runtime {

namespace {

// The capabilities applyRenderStates() enables or disables (GL_BLEND per draw buffer, separately).
constexpr GLenum kCapabilities[] = {
    GL_DEPTH_TEST,           GL_CULL_FACE,
    GL_POLYGON_OFFSET_FILL,  GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT, GL_SCISSOR_TEST,
    GL_MULTISAMPLE,          GL_DEPTH_CLAMP,
    GL_FRAMEBUFFER_SRGB,     GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_MASK,          GL_STENCIL_TEST,
    GL_PROGRAM_POINT_SIZE,  // GpuProgram::bind, for a program that writes gl_PointSize
};

// Every target a pass binds a texture to (GpuTexture's and Buffer<T>'s).
constexpr std::array<std::pair<GLenum, GLenum>, 9> kTextureTargets = {{
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER},
}};

constexpr GLuint kBlendBuffers = 8;  // applyRenderStates() sets the blend of draw buffers 0-7
constexpr GLuint kMaskBuffers = 4;   // and the colour masks of 0-3

GLint integer(GLenum name) {
    GLint value = 0;
    gl::GetIntegerv(name, &value);
    return value;
}

GLint integerAt(GLenum name, GLuint index) {
    GLint value = 0;
    gl::GetIntegeri_v(name, index, &value);
    return value;
}

void unionInto(std::vector<int>& into, const std::vector<int>& from) {
    for (int value : from)
        if (std::find(into.begin(), into.end(), value) == into.end()) into.push_back(value);
    std::sort(into.begin(), into.end());
}

}  // namespace

void GlStateMask::add(const GlStateMask& other) {
    program = program || other.program;
    renderStates = renderStates || other.renderStates;
    framebuffer = framebuffer || other.framebuffer;
    unionInto(textureUnits, other.textureUnits);
    unionInto(uniformBuffers, other.uniformBuffers);
    unionInto(storageBuffers, other.storageBuffers);
}

std::vector<std::string> GlStateMask::describe() const {
    std::vector<std::string> lines;
    if (program) lines.push_back("program");
    if (renderStates) lines.push_back("render states");
    if (framebuffer) lines.push_back("framebuffer and viewport");
    for (int unit : textureUnits) lines.push_back("texture unit " + std::to_string(unit));
    for (int binding : uniformBuffers) lines.push_back("uniform buffer " + std::to_string(binding));
    for (int binding : storageBuffers) lines.push_back("storage buffer " + std::to_string(binding));
    return lines;
}

GlStateSnapshot GlStateSnapshot::capture(const GlStateMask& mask) {
    GlStateSnapshot s;
    capture(mask, s);
    return s;
}

void GlStateSnapshot::capture(const GlStateMask& mask, GlStateSnapshot& s) {
    s.mMask = mask;
    if (mask.program) s.mProgram = integer(GL_CURRENT_PROGRAM);
    s.mEnables.clear();
    if (mask.renderStates) {
        for (GLenum capability : kCapabilities)
            s.mEnables.push_back({capability, gl::IsEnabled(capability) != 0});
        for (GLuint i = 0; i < kBlendBuffers; ++i) {
            s.mBlend[i] = gl::IsEnabledi(GL_BLEND, i) != 0;
            s.mBlendFunctions[i] = {
                integerAt(GL_BLEND_SRC_RGB, i),      integerAt(GL_BLEND_DST_RGB, i),
                integerAt(GL_BLEND_SRC_ALPHA, i),    integerAt(GL_BLEND_DST_ALPHA, i),
                integerAt(GL_BLEND_EQUATION_RGB, i), integerAt(GL_BLEND_EQUATION_ALPHA, i)};
        }
        gl::GetBooleanv(GL_DEPTH_WRITEMASK, &s.mDepthMask);
        s.mDepthFunc = integer(GL_DEPTH_FUNC);
        s.mFrontFace = integer(GL_FRONT_FACE);
        s.mCullFace = integer(GL_CULL_FACE_MODE);
        gl::GetIntegerv(GL_POLYGON_MODE, s.mPolygonMode.data());
        gl::GetFloatv(GL_POLYGON_OFFSET_FACTOR, &s.mOffsetFactor);
        gl::GetFloatv(GL_POLYGON_OFFSET_UNITS, &s.mOffsetUnits);
        gl::GetFloatv(GL_POINT_SIZE, &s.mPointSize);
        if (gl::PolygonOffsetClamp) gl::GetFloatv(GL_POLYGON_OFFSET_CLAMP, &s.mOffsetClamp);
        s.mSampleMask = integerAt(GL_SAMPLE_MASK_VALUE, 0);
        gl::GetFloatv(GL_BLEND_COLOR, s.mBlendColor.data());
        for (GLuint i = 0; i < kMaskBuffers; ++i)
            gl::GetBooleani_v(GL_COLOR_WRITEMASK, i, s.mColorMasks[i].data());
        s.mStencil[0] = {integer(GL_STENCIL_FUNC),
                         integer(GL_STENCIL_REF),
                         integer(GL_STENCIL_VALUE_MASK),
                         integer(GL_STENCIL_FAIL),
                         integer(GL_STENCIL_PASS_DEPTH_FAIL),
                         integer(GL_STENCIL_PASS_DEPTH_PASS)};
        s.mStencil[1] = {integer(GL_STENCIL_BACK_FUNC),
                         integer(GL_STENCIL_BACK_REF),
                         integer(GL_STENCIL_BACK_VALUE_MASK),
                         integer(GL_STENCIL_BACK_FAIL),
                         integer(GL_STENCIL_BACK_PASS_DEPTH_FAIL),
                         integer(GL_STENCIL_BACK_PASS_DEPTH_PASS)};
        s.mStencilWriteMask = {integer(GL_STENCIL_WRITEMASK), integer(GL_STENCIL_BACK_WRITEMASK)};
    }
    if (mask.framebuffer) {
        s.mDrawFramebuffer = integer(GL_DRAW_FRAMEBUFFER_BINDING);
        s.mReadFramebuffer = integer(GL_READ_FRAMEBUFFER_BINDING);
        gl::GetIntegerv(GL_VIEWPORT, s.mViewport.data());
    }
    // The active unit's bindings too: creating a texture (a render target allocated on first use) binds it
    // there.
    s.mActiveTexture = integer(GL_ACTIVE_TEXTURE);
    std::vector<int>& units = s.mUnitOrder;
    units = mask.textureUnits;
    const int active = static_cast<int>(s.mActiveTexture - GL_TEXTURE0);
    if (std::find(units.begin(), units.end(), active) == units.end()) units.push_back(active);
    std::sort(units.begin(), units.end());
    s.mUnits.clear();
    for (int unit : units) {
        TextureUnit saved{unit, {}, 0};
        gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        for (size_t t = 0; t < kTextureTargets.size(); ++t)
            saved.textures[t] = integer(kTextureTargets[t].second);
        saved.sampler = integer(GL_SAMPLER_BINDING);
        s.mUnits.push_back(saved);
    }
    gl::ActiveTexture(static_cast<GLenum>(s.mActiveTexture));
    const auto ranges = [](const std::vector<int>& bindings, GLenum binding, GLenum start, GLenum size,
                           std::vector<BufferRange>& out) {
        out.clear();
        for (int index : bindings) {
            const GLuint i = static_cast<GLuint>(index);
            out.push_back(BufferRange{index, integerAt(binding, i), integerAt(start, i), integerAt(size, i)});
        }
    };
    s.mUniformBuffer = integer(GL_UNIFORM_BUFFER_BINDING);
    ranges(mask.uniformBuffers, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE,
           s.mUniformRanges);
    s.mStorageBuffer = integer(GL_SHADER_STORAGE_BUFFER_BINDING);
    ranges(mask.storageBuffers, GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
           GL_SHADER_STORAGE_BUFFER_SIZE, s.mStorageRanges);
}

void GlStateSnapshot::restore() const {
    // A program deleted while current stays current, and its name with it, until another is made current:
    // then it is gone, and making its name current again is an error. Such a program goes back to none.
    if (mMask.program)
        gl::UseProgram(gl::IsProgram(static_cast<GLuint>(mProgram)) ? static_cast<GLuint>(mProgram) : 0);
    if (mMask.renderStates) {
        for (const Enable& e : mEnables) {
            if (e.on) {
                gl::Enable(e.capability);
            } else {
                gl::Disable(e.capability);
            }
        }
        for (GLuint i = 0; i < kBlendBuffers; ++i) {
            if (mBlend[i]) {
                gl::Enablei(GL_BLEND, i);
            } else {
                gl::Disablei(GL_BLEND, i);
            }
            const auto& f = mBlendFunctions[i];
            gl::BlendFuncSeparatei(i, static_cast<GLenum>(f[0]), static_cast<GLenum>(f[1]),
                                   static_cast<GLenum>(f[2]), static_cast<GLenum>(f[3]));
            gl::BlendEquationSeparatei(i, static_cast<GLenum>(f[4]), static_cast<GLenum>(f[5]));
        }
        gl::DepthMask(mDepthMask);
        gl::DepthFunc(static_cast<GLenum>(mDepthFunc));
        gl::FrontFace(static_cast<GLenum>(mFrontFace));
        gl::CullFace(static_cast<GLenum>(mCullFace));
        gl::PolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(mPolygonMode[0]));
        if (gl::PolygonOffsetClamp) {
            gl::PolygonOffsetClamp(mOffsetFactor, mOffsetUnits, mOffsetClamp);
        } else {
            gl::PolygonOffset(mOffsetFactor, mOffsetUnits);
        }
        gl::SampleMaski(0, static_cast<GLbitfield>(mSampleMask));
        gl::PointSize(mPointSize);
        gl::BlendColor(mBlendColor[0], mBlendColor[1], mBlendColor[2], mBlendColor[3]);
        for (GLuint i = 0; i < kMaskBuffers; ++i)
            gl::ColorMaski(i, mColorMasks[i][0], mColorMasks[i][1], mColorMasks[i][2], mColorMasks[i][3]);
        const GLenum faces[2] = {GL_FRONT, GL_BACK};
        for (size_t f = 0; f < 2; ++f) {
            const auto& st = mStencil[f];
            gl::StencilFuncSeparate(faces[f], static_cast<GLenum>(st[0]), st[1], static_cast<GLuint>(st[2]));
            gl::StencilOpSeparate(faces[f], static_cast<GLenum>(st[3]), static_cast<GLenum>(st[4]),
                                  static_cast<GLenum>(st[5]));
            gl::StencilMaskSeparate(faces[f], static_cast<GLuint>(mStencilWriteMask[f]));
        }
    }
    if (mMask.framebuffer) {
        gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(mDrawFramebuffer));
        gl::BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(mReadFramebuffer));
        gl::Viewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
    }
    for (const TextureUnit& unit : mUnits) {
        gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit.unit));
        for (size_t t = 0; t < kTextureTargets.size(); ++t)
            gl::BindTexture(kTextureTargets[t].first, static_cast<GLuint>(unit.textures[t]));
        gl::BindSampler(static_cast<GLuint>(unit.unit), static_cast<GLuint>(unit.sampler));
    }
    gl::ActiveTexture(static_cast<GLenum>(mActiveTexture));
    const auto rebind = [](GLenum target, const std::vector<BufferRange>& ranges, GLint generic) {
        for (const BufferRange& r : ranges) {
            const GLuint i = static_cast<GLuint>(r.binding);
            // A range of size 0 is glBindBufferBase's whole buffer (or no buffer).
            if (r.buffer == 0 || r.size == 0) {
                gl::BindBufferBase(target, i, static_cast<GLuint>(r.buffer));
            } else {
                gl::BindBufferRange(target, i, static_cast<GLuint>(r.buffer), static_cast<GLintptr>(r.start),
                                    static_cast<GLsizeiptr>(r.size));
            }
        }
        gl::BindBuffer(target, static_cast<GLuint>(generic));  // the indexed binds set it too
    };
    rebind(GL_UNIFORM_BUFFER, mUniformRanges, mUniformBuffer);
    rebind(GL_SHADER_STORAGE_BUFFER, mStorageRanges, mStorageBuffer);
}

}  // namespace runtime
