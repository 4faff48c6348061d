// StorageImages: the textures behind an effect's RWTexture1D, RWTexture2D, RWTexture3D and
// RWTexture2DArray parameters and the buffers behind its RWBuffer parameters
// (StorageResources::createImages), and the parameters that view them or read-write buffers
// (`string ViewOf = "..."`, resolved by the compiler: ParameterInfo::viewOf).
// FX11 applications create the resource and its unordered access view themselves; here the size the
// compiler resolved from the parameter's annotations (ParameterInfo::imageSize, an RWBuffer's
// elementCount) sizes it and the format its code declares (ParameterInfo::imageFormat) is the texture's
// or the buffer texture's.
#include "StorageResources.h"

#include <optional>
#include <string>

namespace runtime {

namespace {

// Bytes per texel of the formats the compiler gives images (ParameterInfo::imageFormat).
size_t texelBytes(fx::TextureFormat format) {
    switch (format) {
        case fx::TextureFormat::RGBA32F:
            return 16;
        case fx::TextureFormat::RGBA16F:
        case fx::TextureFormat::RG32F:
            return 8;
        case fx::TextureFormat::R16F:
            return 2;
        default:  // RG16F, R32F, RGBA8
            return 4;
    }
}

GpuTexture imageTexture(fx::BaseType type, fx::TextureFormat format, int width, int height, int depth) {
    switch (type) {
        case fx::BaseType::RWTexture1D:
            return GpuTexture::create1D(format, width);
        case fx::BaseType::RWTexture3D:
            return GpuTexture::create3D(format, width, height, depth);
        case fx::BaseType::RWTexture2DArray:
            return GpuTexture::create2DArray(format, width, height, depth);
        default:
            return GpuTexture::create2D(format, width, height);
    }
}

}  // namespace

void StorageResources::createImages() {
    for (size_t i = 0; i < mEffect->parameters.size(); ++i) {
        const fx::ParameterInfo& parameter = mEffect->parameters[i];
        if (parameter.viewOf) mResourceViews[i] = *parameter.viewOf;
        const std::optional<fx::TextureFormat> format = parameter.imageFormat;
        if (!parameter.type.isImage() || !format) continue;  // no pass reads or writes it
        const fx::BaseType type = parameter.type.base;
        if (type == fx::BaseType::RWBuffer) {
            mBuffers[i] = GpuBuffer::create(nullptr, parameter.elementCount * texelBytes(*format),
                                            glTextureFormat(*format).internalFormat);
            continue;
        }
        const int* size = parameter.imageSize;
        GpuTexture texture = imageTexture(type, *format, size[0], size[1], size[2]);
        texture.setLabel(parameter.name);
        mImages[i] = std::move(texture);
    }
}

}  // namespace runtime
