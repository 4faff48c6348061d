// GpuTexture: an immutable-storage GL texture (2D or cube) of an fx::TextureFormat, owned RAII. Colour
// formats are render targets and sampled textures; depth formats (D16, D24S8, D24X8, D32F) are depth
// targets that shaders may sample (as depth or, through a comparison SamplerObject, as shadow tests).
// Row 0 of the storage is the image's top row, as everywhere in the runtime (see GlContext.cpp).
#pragma once

#include <runtime/GlApi.h>

#include <fx/CompiledEffect.h>

#include <cstdint>

namespace runtime {

// How a TextureFormat maps to GL: storage format, and the format/type pair for uploads and readbacks.
struct GlTextureFormat {
    GLenum internalFormat;
    GLenum pixelFormat;  // GL_RGBA, GL_RED, GL_RG, GL_DEPTH_COMPONENT, GL_DEPTH_STENCIL
    GLenum pixelType;    // of a natural upload: GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_INT_24_8
    int channels;        // colour channels (1 for depth)
    bool isDepth;
    bool hasStencil;
    bool isFloat;   // float or half storage (unclamped values)
    int depthBits;  // 16, 24 or 32 for depth formats, else 0
};
const GlTextureFormat& glTextureFormat(fx::TextureFormat format);

class GpuTexture {
public:
    // mipLevels <= 0 means a full chain (D3D's Levels = 0).
    static GpuTexture create2D(fx::TextureFormat format, int width, int height, int mipLevels = 1);
    // One level of `width` texels (an RWTexture1D's image).
    static GpuTexture create1D(fx::TextureFormat format, int width);
    static GpuTexture createCube(fx::TextureFormat format, int size, int mipLevels = 1);
    // A volume texture (DDS volume files): `depth` slices; mipLevels <= 0 is the chain of the largest side.
    static GpuTexture create3D(fx::TextureFormat format, int width, int height, int depth, int mipLevels = 1);
    // D3D10's texture arrays: `elements` layers (a cube array's are cubes: 6 layers each); a 1D array's
    // height is 1.
    static GpuTexture create1DArray(fx::TextureFormat format, int width, int elements, int mipLevels = 1);
    static GpuTexture create2DArray(fx::TextureFormat format, int width, int height, int elements,
                                    int mipLevels = 1);
    static GpuTexture createCubeArray(fx::TextureFormat format, int size, int cubes, int mipLevels = 1);
    // D3D10's Texture2DMS (`arrayElements` 0) or Texture2DMSArray (that many layers): `samples` per texel (at
    // most the driver's GL_MAX_COLOR_TEXTURE_SAMPLES or GL_MAX_DEPTH_TEXTURE_SAMPLES, which the caller
    // checks), one level, contents undefined until drawn or cleared.
    static GpuTexture createMultisample(fx::TextureFormat format, int width, int height, int samples,
                                        int arrayElements = 0);

    GpuTexture() = default;
    ~GpuTexture();
    GpuTexture(GpuTexture&& other) noexcept;
    GpuTexture& operator=(GpuTexture&& other) noexcept;
    GpuTexture(const GpuTexture&) = delete;
    GpuTexture& operator=(const GpuTexture&) = delete;

    // Uploads tightly packed RGBA8 pixels (top row first) into one level (and face, for cube maps:
    // 0..5 = +X -X +Y -Y +Z -Z). Colour formats only; the driver converts to the storage format.
    void uploadRGBA8(const uint8_t* pixels, int level = 0, int face = 0);
    // Same with RGBA float pixels.
    void uploadRGBA32F(const float* pixels, int level = 0, int face = 0);
    // Every slice of one level of a volume texture, slice after slice, as RGBA floats.
    void uploadVolumeRGBA32F(const float* pixels, int level = 0);
    // One layer of one level of an array texture as RGBA floats (a cube array's layer is cube * 6 + face).
    void uploadLayerRGBA32F(const float* pixels, int level, int layer);
    void generateMipmaps() const;  // GL storage only: the object itself does not change
    void setLabel(const std::string& label);

    GLuint id() const { return mId; }
    // GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D, GL_TEXTURE_1D_ARRAY, GL_TEXTURE_2D_ARRAY,
    // GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_2D_MULTISAMPLE or GL_TEXTURE_2D_MULTISAMPLE_ARRAY
    GLenum target() const { return mTarget; }
    fx::TextureFormat format() const { return mFormat; }
    const GlTextureFormat& glFormat() const { return glTextureFormat(mFormat); }
    bool isDepth() const { return glFormat().isDepth; }
    bool isCube() const { return mTarget == GL_TEXTURE_CUBE_MAP; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    int mipLevels() const { return mLevels; }
    bool isArray() const {
        return mTarget == GL_TEXTURE_1D_ARRAY || mTarget == GL_TEXTURE_2D_ARRAY ||
               mTarget == GL_TEXTURE_CUBE_MAP_ARRAY || mTarget == GL_TEXTURE_2D_MULTISAMPLE_ARRAY;
    }
    int layers() const { return isArray() ? mDepth : 1; }  // an array's layers (6 per cube)
    // A cube, an array or a volume: what a layered framebuffer attachment binds whole, its faces, elements or
    // slices addressed by gl_Layer.
    bool isLayered() const { return isCube() || isArray() || mTarget == GL_TEXTURE_3D; }
    int samples() const { return mSamples; }  // 1 unless multisampled
    // Unique for the life of the process, unlike GL names, which GL reuses after deletion: what the
    // framebuffer cache keys on.
    uint64_t serial() const { return mSerial; }
    explicit operator bool() const { return mId != 0; }

    static int fullMipChainLength(int width, int height);

private:
    GpuTexture(GLenum target, fx::TextureFormat format, int width, int height, int levels, int depth = 1);
    void upload(const void* pixels, GLenum type, int level, int face);

    GLuint mId = 0;
    GLenum mTarget = GL_TEXTURE_2D;
    fx::TextureFormat mFormat = fx::TextureFormat::RGBA8;
    int mWidth = 0;
    int mHeight = 0;
    int mDepth = 1;  // slices of a 3D texture, layers of an array
    int mLevels = 0;
    int mSamples = 1;
    uint64_t mSerial = 0;
};

}  // namespace runtime
