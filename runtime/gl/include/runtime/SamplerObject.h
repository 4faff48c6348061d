// SamplerObject: a GL sampler object built from an effect's sampler_state (fx::SamplerDesc, D3D9 values).
//
// D3D9 -> GL:
//   AddressU/V/W  WRAP -> REPEAT, MIRROR -> MIRRORED_REPEAT, CLAMP -> CLAMP_TO_EDGE,
//                 BORDER -> CLAMP_TO_BORDER, MIRRORONCE -> MIRROR_CLAMP_TO_EDGE (core since 4.4)
//   Min/Mag       POINT -> NEAREST, LINEAR/ANISOTROPIC/PYRAMIDALQUAD/GAUSSIANQUAD -> LINEAR
//   MipFilter     NONE -> no mipmapping (level 0 only, as D3D9), POINT -> *_MIPMAP_NEAREST,
//                 LINEAR -> *_MIPMAP_LINEAR
//   ANISOTROPIC   MaxAnisotropy through GL_TEXTURE_MAX_ANISOTROPY (ARB/EXT_texture_filter_anisotropic,
//                 same enum), clamped to the implementation's maximum; ignored without the extension
//   BorderColor, MipMapLodBias as is.
// A comparison sampler (sampler2DShadow, or ComparisonFunc set) compares with GL_COMPARE_REF_TO_TEXTURE
// and the effect's function, LESSEQUAL by default: texture(shadowMap, vec3(uv, z)) is 1 where z <= depth.
#pragma once

#include <runtime/GlApi.h>

#include <fx/CompiledEffect.h>

namespace runtime {

// D3D9 D3DCMPFUNC value (1 NEVER .. 8 ALWAYS) -> GL comparison; GL_LEQUAL for anything else.
GLenum glCompareFunc(int d3dCmp);
// D3D9 D3DTEXTUREADDRESS (1..5) -> GL wrap mode; GL_REPEAT for anything else.
GLenum glAddressMode(int d3dAddress);

class SamplerObject {
public:
    SamplerObject() = default;
    // `depthCompare`: the shader samples a depth texture through a shadow sampler.
    explicit SamplerObject(const fx::SamplerDesc& desc, bool depthCompare = false);
    ~SamplerObject();
    SamplerObject(SamplerObject&& other) noexcept;
    SamplerObject& operator=(SamplerObject&& other) noexcept;
    SamplerObject(const SamplerObject&) = delete;
    SamplerObject& operator=(const SamplerObject&) = delete;

    void bind(int unit) const { gl::BindSampler(GLuint(unit), mId); }
    static void unbind(int unit) { gl::BindSampler(GLuint(unit), 0); }

    GLuint id() const { return mId; }
    bool compares() const { return mCompare; }

private:
    GLuint mId = 0;
    bool mCompare = false;
};

}  // namespace runtime
