#include <runtime/SamplerObject.h>

#include <runtime/RenderStateApplier.h>

#include <algorithm>
#include <cstring>
#include <utility>

namespace runtime {

namespace {

constexpr int kTexfNone = 0, kTexfPoint = 1, kTexfAnisotropic = 3;  // D3DTEXF values
// GL_TEXTURE_MAX_ANISOTROPY / GL_MAX_TEXTURE_MAX_ANISOTROPY: core in 4.6, same values as the EXT enums.
constexpr GLenum kTextureMaxAnisotropy = 0x84FE;
constexpr GLenum kMaxTextureMaxAnisotropy = 0x84FF;

bool hasAnisotropy() {
    GLint count = 0;
    gl::GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(gl::GetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name != nullptr && (std::strcmp(name, "GL_EXT_texture_filter_anisotropic") == 0 ||
                                std::strcmp(name, "GL_ARB_texture_filter_anisotropic") == 0)) {
            return true;
        }
    }
    return false;
}

GLenum minFilter(int minFilter, int mipFilter) {
    bool linear = minFilter != kTexfPoint && minFilter != kTexfNone;
    if (mipFilter == kTexfNone) return linear ? GL_LINEAR : GL_NEAREST;
    if (mipFilter == kTexfPoint) return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
}

}  // namespace

GLenum glCompareFunc(int d3dCmp) {
    // 0: the sampler_state sets no ComparisonFunc; a depth target then compares with D3D's LESSEQUAL.
    return d3dCmp >= 1 && d3dCmp <= 8 ? glCompareFromD3d(d3dCmp) : GL_LEQUAL;
}

GLenum glAddressMode(int d3dAddress) {
    switch (d3dAddress) {
        case 1:
            return GL_REPEAT;
        case 2:
            return GL_MIRRORED_REPEAT;
        case 3:
            return GL_CLAMP_TO_EDGE;
        case 4:
            return GL_CLAMP_TO_BORDER;
        case 5:
            return GL_MIRROR_CLAMP_TO_EDGE;
        default:
            return GL_REPEAT;
    }
}

SamplerObject::SamplerObject(const fx::SamplerDesc& desc, bool depthCompare)
    : mCompare(depthCompare || desc.comparisonFunc != 0) {
    gl::GenSamplers(1, &mId);
    gl::SamplerParameteri(mId, GL_TEXTURE_WRAP_S, GLint(glAddressMode(desc.addressU)));
    gl::SamplerParameteri(mId, GL_TEXTURE_WRAP_T, GLint(glAddressMode(desc.addressV)));
    gl::SamplerParameteri(mId, GL_TEXTURE_WRAP_R, GLint(glAddressMode(desc.addressW)));
    gl::SamplerParameteri(mId, GL_TEXTURE_MIN_FILTER, GLint(minFilter(desc.minFilter, desc.mipFilter)));
    gl::SamplerParameteri(
        mId, GL_TEXTURE_MAG_FILTER,
        desc.magFilter == kTexfPoint || desc.magFilter == kTexfNone ? GL_NEAREST : GL_LINEAR);
    gl::SamplerParameterfv(mId, GL_TEXTURE_BORDER_COLOR, desc.borderColor);
    gl::SamplerParameterf(mId, GL_TEXTURE_LOD_BIAS, desc.mipLodBias);
    gl::SamplerParameterf(mId, GL_TEXTURE_MIN_LOD, desc.minLod);
    gl::SamplerParameterf(mId, GL_TEXTURE_MAX_LOD, desc.maxLod);

    bool anisotropic = desc.minFilter == kTexfAnisotropic || desc.magFilter == kTexfAnisotropic;
    if (anisotropic && desc.maxAnisotropy > 1) {
        static const bool supported = hasAnisotropy();
        if (supported) {
            GLfloat maximum = 1.0f;
            gl::GetFloatv(kMaxTextureMaxAnisotropy, &maximum);
            gl::SamplerParameterf(mId, kTextureMaxAnisotropy, std::min(float(desc.maxAnisotropy), maximum));
        }
    }

    if (mCompare) {
        gl::SamplerParameteri(mId, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        gl::SamplerParameteri(mId, GL_TEXTURE_COMPARE_FUNC, GLint(glCompareFunc(desc.comparisonFunc)));
    }
}

SamplerObject::~SamplerObject() {
    if (mId != 0) gl::DeleteSamplers(1, &mId);
}

SamplerObject::SamplerObject(SamplerObject&& other) noexcept {
    *this = std::move(other);
}

SamplerObject& SamplerObject::operator=(SamplerObject&& other) noexcept {
    if (this != &other) {
        if (mId != 0) gl::DeleteSamplers(1, &mId);
        mId = std::exchange(other.mId, 0);
        mCompare = other.mCompare;
    }
    return *this;
}

}  // namespace runtime
