// StorageImages: the textures behind an effect's RWTexture1D, RWTexture2D, RWTexture3D and
// RWTexture2DArray parameters and the buffers behind its RWBuffer parameters
// (StorageResources::createImages), and the parameters that view them or read-write buffers
// (`string ViewOf = "..."`).
// FX11 applications create the resource and its unordered access view themselves; here the parameter's
// annotations size it (`int Width`, `Height`: 64 without them; `Depth` of a 3D texture and `ArraySize` of
// an array: 1; an RWBuffer's `ElementCount`: 1) and the format its code declares (glslang's, from the
// element type) is the texture's or the buffer texture's.
#include "StorageResources.h"

#include <optional>
#include <string>

namespace runtime {

namespace {

std::optional<fx::TextureFormat> imageTextureFormat(const std::string& qualifier) {
    if (qualifier == "rgba32f") return fx::TextureFormat::RGBA32F;
    if (qualifier == "rgba16f") return fx::TextureFormat::RGBA16F;
    if (qualifier == "rg32f") return fx::TextureFormat::RG32F;
    if (qualifier == "rg16f") return fx::TextureFormat::RG16F;
    if (qualifier == "r32f") return fx::TextureFormat::R32F;
    if (qualifier == "r16f") return fx::TextureFormat::R16F;
    if (qualifier == "rgba8") return fx::TextureFormat::RGBA8;
    return std::nullopt;
}

// Bytes per texel of the formats imageTextureFormat gives.
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

const fx::ImageBinding* imageUse(const fx::CompiledEffect& effect, size_t parameter) {
    for (const fx::CompiledTechnique& technique : effect.techniques)
        for (const fx::CompiledPass& pass : technique.passes)
            for (const fx::StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (const fx::ImageBinding& image : stage->images)
                    if (image.parameter == parameter) return &image;
    return nullptr;
}

int sizeAnnotation(const fx::ParameterInfo& parameter, const char* name, int absent) {
    const fx::AnnotationValue* size = fx::findAnnotation(parameter.annotations, name);
    return size && size->value.data.size() == 1 ? static_cast<int>(size->value.data[0]) : absent;
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

bool StorageResources::createImages(const ParameterLookup& findParameter, fx::DiagnosticSink& diagnostics) {
    for (size_t i = 0; i < mEffect->parameters.size(); ++i) {
        const fx::ParameterInfo& parameter = mEffect->parameters[i];
        if (const fx::AnnotationValue* view = fx::findAnnotation(parameter.annotations, "ViewOf")) {
            const std::optional<size_t> viewed = findParameter(view->value.string);
            const bool readWrite = viewed && (mEffect->parameters[*viewed].type.isImage() ||
                                              mEffect->parameters[*viewed].type.isBuffer());
            if (!readWrite) {
                diagnostics.report(fx::DiagId::ViewOfUnknownResource, parameter.loc,
                                   {parameter.name, view->value.string});
                return false;
            }
            mResourceViews[i] = *viewed;
        }
        if (!parameter.type.isImage()) continue;
        const fx::ImageBinding* use = imageUse(*mEffect, i);
        if (!use) continue;  // no pass reads or writes it
        const std::optional<fx::TextureFormat> format = imageTextureFormat(use->format);
        if (!format) {
            diagnostics.report(fx::DiagId::ImageFormatUnsupported, parameter.loc,
                               {parameter.name, parameter.type.hlslName(), use->format});
            return false;
        }
        const fx::BaseType type = parameter.type.base;
        if (type == fx::BaseType::RWBuffer) {
            const std::optional<size_t> elements = declaredElementCount(parameter, diagnostics);
            if (!elements) return false;
            mBuffers[i] = GpuBuffer::create(nullptr, *elements * texelBytes(*format),
                                            glTextureFormat(*format).internalFormat);
            continue;
        }
        const int width = sizeAnnotation(parameter, "Width", 64);
        const int height = type == fx::BaseType::RWTexture1D ? 1 : sizeAnnotation(parameter, "Height", 64);
        const int depth = type == fx::BaseType::RWTexture3D        ? sizeAnnotation(parameter, "Depth", 1)
                          : type == fx::BaseType::RWTexture2DArray ? sizeAnnotation(parameter, "ArraySize", 1)
                                                                   : 1;
        const int most = type == fx::BaseType::RWTexture3D ? 2048 : 16384;
        if (width < 1 || height < 1 || depth < 1 || width > most || height > most || depth > 2048) {
            std::string size = std::to_string(width);
            if (type != fx::BaseType::RWTexture1D) size += " x " + std::to_string(height);
            if (type == fx::BaseType::RWTexture3D || type == fx::BaseType::RWTexture2DArray)
                size += " x " + std::to_string(depth);
            diagnostics.report(fx::DiagId::ImageSizeOutOfRange, parameter.loc, {parameter.name, size});
            return false;
        }
        GpuTexture texture = imageTexture(type, *format, width, height, depth);
        texture.setLabel(parameter.name);
        mImages[i] = std::move(texture);
    }
    return true;
}

}  // namespace runtime
