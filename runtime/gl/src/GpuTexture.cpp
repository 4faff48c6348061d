#include <runtime/GpuTexture.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace runtime {

namespace {

std::atomic<uint64_t> gNextSerial{1};

}  // namespace

const GlTextureFormat& glTextureFormat(fx::TextureFormat format) {
    using F = fx::TextureFormat;
    // Indexed by fx::TextureFormat; the static_assert below catches a format added there but not here.
    static const GlTextureFormat kFormats[] = {
        /* RGBA8   */ {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, false, false, false, 0},
        /* RGBA16F */ {GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, false, false, true, 0},
        /* RGBA32F */ {GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, false, false, true, 0},
        /* R16F    */ {GL_R16F, GL_RED, GL_FLOAT, 1, false, false, true, 0},
        /* R32F    */ {GL_R32F, GL_RED, GL_FLOAT, 1, false, false, true, 0},
        /* RG16F   */ {GL_RG16F, GL_RG, GL_FLOAT, 2, false, false, true, 0},
        /* RG32F   */ {GL_RG32F, GL_RG, GL_FLOAT, 2, false, false, true, 0},
        /* RGBA16  */ {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, 4, false, false, false, 0},
        /* D16     */ {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_FLOAT, 1, true, false, false, 16},
        /* D24S8   */ {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 1, true, true, false, 24},
        /* D24X8   */ {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, 1, true, false, false, 24},
        /* D32F    */ {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 1, true, false, true, 32},
    };
    static_assert(sizeof(kFormats) / sizeof(kFormats[0]) == size_t(F::D32F) + 1);
    return kFormats[size_t(format)];
}

int GpuTexture::fullMipChainLength(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

GpuTexture GpuTexture::create2D(fx::TextureFormat format, int width, int height, int mipLevels) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    int levels = mipLevels <= 0 ? fullMipChainLength(width, height)
                                : std::min(mipLevels, fullMipChainLength(width, height));
    return GpuTexture(GL_TEXTURE_2D, format, width, height, levels);
}

GpuTexture GpuTexture::create1D(fx::TextureFormat format, int width) {
    return GpuTexture(GL_TEXTURE_1D, format, std::max(width, 1), 1, 1);
}

GpuTexture GpuTexture::createCube(fx::TextureFormat format, int size, int mipLevels) {
    size = std::max(size, 1);
    int levels =
        mipLevels <= 0 ? fullMipChainLength(size, size) : std::min(mipLevels, fullMipChainLength(size, size));
    return GpuTexture(GL_TEXTURE_CUBE_MAP, format, size, size, levels);
}

GpuTexture GpuTexture::create3D(fx::TextureFormat format, int width, int height, int depth, int mipLevels) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    depth = std::max(depth, 1);
    const int chain = fullMipChainLength(std::max(width, depth), std::max(height, depth));
    const int levels = mipLevels <= 0 ? chain : std::min(mipLevels, chain);
    return GpuTexture(GL_TEXTURE_3D, format, width, height, levels, depth);
}

GpuTexture GpuTexture::create1DArray(fx::TextureFormat format, int width, int elements, int mipLevels) {
    width = std::max(width, 1);
    const int chain = fullMipChainLength(width, 1);
    return GpuTexture(GL_TEXTURE_1D_ARRAY, format, width, 1,
                      mipLevels <= 0 ? chain : std::min(mipLevels, chain), std::max(elements, 1));
}

GpuTexture GpuTexture::create2DArray(fx::TextureFormat format, int width, int height, int elements,
                                     int mipLevels) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    const int chain = fullMipChainLength(width, height);
    return GpuTexture(GL_TEXTURE_2D_ARRAY, format, width, height,
                      mipLevels <= 0 ? chain : std::min(mipLevels, chain), std::max(elements, 1));
}

GpuTexture GpuTexture::createCubeArray(fx::TextureFormat format, int size, int cubes, int mipLevels) {
    size = std::max(size, 1);
    const int chain = fullMipChainLength(size, size);
    return GpuTexture(GL_TEXTURE_CUBE_MAP_ARRAY, format, size, size,
                      mipLevels <= 0 ? chain : std::min(mipLevels, chain), 6 * std::max(cubes, 1));
}

GpuTexture GpuTexture::createMultisample(fx::TextureFormat format, int width, int height, int samples,
                                         int arrayElements) {
    const bool array = arrayElements > 0;
    GpuTexture texture;
    texture.mTarget = array ? GL_TEXTURE_2D_MULTISAMPLE_ARRAY : GL_TEXTURE_2D_MULTISAMPLE;
    texture.mFormat = format;
    texture.mWidth = std::max(width, 1);
    texture.mHeight = std::max(height, 1);
    texture.mDepth = std::max(arrayElements, 1);
    texture.mLevels = 1;
    texture.mSamples = std::max(samples, 1);
    texture.mSerial = gNextSerial++;
    gl::GenTextures(1, &texture.mId);
    gl::BindTexture(texture.mTarget, texture.mId);
    // Fixed sample locations: every texel's sample i sits at the same place, as D3D's standard patterns.
    const GLenum internalFormat = texture.glFormat().internalFormat;
    if (array)
        gl::TexStorage3DMultisample(texture.mTarget, texture.mSamples, internalFormat, texture.mWidth,
                                    texture.mHeight, texture.mDepth, GL_TRUE);
    else
        gl::TexStorage2DMultisample(texture.mTarget, texture.mSamples, internalFormat, texture.mWidth,
                                    texture.mHeight, GL_TRUE);
    gl::BindTexture(texture.mTarget, 0);
    return texture;
}

GpuTexture::GpuTexture(GLenum target, fx::TextureFormat format, int width, int height, int levels, int depth)
    : mTarget(target),
      mFormat(format),
      mWidth(width),
      mHeight(height),
      mDepth(depth),
      mLevels(levels),
      mSerial(gNextSerial++) {
    gl::GenTextures(1, &mId);
    gl::BindTexture(mTarget, mId);
    // Immutable storage: complete by construction, whatever the filter (a mutable texture with one
    // level and the default mipmapped min filter samples as black).
    if (mTarget == GL_TEXTURE_3D || mTarget == GL_TEXTURE_2D_ARRAY || mTarget == GL_TEXTURE_CUBE_MAP_ARRAY)
        gl::TexStorage3D(mTarget, mLevels, glFormat().internalFormat, mWidth, mHeight, mDepth);
    else if (mTarget == GL_TEXTURE_1D)
        gl::TexStorage1D(mTarget, mLevels, glFormat().internalFormat, mWidth);
    else if (mTarget == GL_TEXTURE_1D_ARRAY)
        gl::TexStorage2D(mTarget, mLevels, glFormat().internalFormat, mWidth, mDepth);
    else
        gl::TexStorage2D(mTarget, mLevels, glFormat().internalFormat, mWidth, mHeight);
    gl::TexParameteri(mTarget, GL_TEXTURE_MAX_LEVEL, mLevels - 1);
    // Sampler objects override these; they matter only for code that samples without one.
    gl::TexParameteri(mTarget, GL_TEXTURE_MIN_FILTER, mLevels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    gl::TexParameteri(mTarget, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::BindTexture(mTarget, 0);
}

GpuTexture::~GpuTexture() {
    if (mId != 0) gl::DeleteTextures(1, &mId);
}

GpuTexture::GpuTexture(GpuTexture&& other) noexcept {
    *this = std::move(other);
}

GpuTexture& GpuTexture::operator=(GpuTexture&& other) noexcept {
    if (this != &other) {
        if (mId != 0) gl::DeleteTextures(1, &mId);
        mId = std::exchange(other.mId, 0);
        mTarget = other.mTarget;
        mFormat = other.mFormat;
        mWidth = other.mWidth;
        mHeight = other.mHeight;
        mDepth = other.mDepth;
        mLevels = other.mLevels;
        mSamples = other.mSamples;
        mSerial = std::exchange(other.mSerial, 0);
    }
    return *this;
}

void GpuTexture::upload(const void* pixels, GLenum type, int level, int face) {
    int width = std::max(mWidth >> level, 1);
    int height = std::max(mHeight >> level, 1);
    GLenum imageTarget = isCube() ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) : mTarget;
    gl::BindTexture(mTarget, mId);
    gl::TexSubImage2D(imageTarget, level, 0, 0, width, height, GL_RGBA, type, pixels);
    gl::BindTexture(mTarget, 0);
}

void GpuTexture::uploadRGBA8(const uint8_t* pixels, int level, int face) {
    upload(pixels, GL_UNSIGNED_BYTE, level, face);
}

void GpuTexture::uploadRGBA32F(const float* pixels, int level, int face) {
    upload(pixels, GL_FLOAT, level, face);
}

void GpuTexture::uploadVolumeRGBA32F(const float* pixels, int level) {
    gl::BindTexture(mTarget, mId);
    gl::TexSubImage3D(mTarget, level, 0, 0, 0, std::max(mWidth >> level, 1), std::max(mHeight >> level, 1),
                      std::max(mDepth >> level, 1), GL_RGBA, GL_FLOAT, pixels);
    gl::BindTexture(mTarget, 0);
}

void GpuTexture::uploadLayerRGBA32F(const float* pixels, int level, int layer) {
    const int width = std::max(mWidth >> level, 1);
    gl::BindTexture(mTarget, mId);
    if (mTarget == GL_TEXTURE_1D_ARRAY)
        gl::TexSubImage2D(mTarget, level, 0, layer, width, 1, GL_RGBA, GL_FLOAT, pixels);
    else
        gl::TexSubImage3D(mTarget, level, 0, 0, layer, width, std::max(mHeight >> level, 1), 1, GL_RGBA,
                          GL_FLOAT, pixels);
    gl::BindTexture(mTarget, 0);
}

void GpuTexture::generateMipmaps() const {
    if (mLevels <= 1 || isDepth()) return;
    // Direct state access: no texture unit's binding changes (the frame executor regenerates chains
    // while it binds samplers).
    gl::GenerateTextureMipmap(mId);
}

void GpuTexture::setLabel(const std::string& label) {
    gl::ObjectLabel(GL_TEXTURE, mId, GLsizei(label.size()), label.c_str());
}

}  // namespace runtime
