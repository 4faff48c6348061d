// StorageImages: the textures behind an effect's RWTexture2D parameters (EffectResources::createImages),
// and the parameters that view them or read-write buffers (`string ViewOf = "..."`).
// FX11 applications create the texture and its unordered access view themselves; here the parameter's
// `int Width = N; int Height = M;` annotations size it (64 x 64 without them) and the format its code
// declares (glslang's, from the element type) is the texture's.
#include "EffectResources.h"

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

const fx::ImageBinding* imageUse(const fx::CompiledEffect& effect, size_t parameter) {
    for (const fx::CompiledTechnique& technique : effect.techniques)
        for (const fx::CompiledPass& pass : technique.passes)
            for (const fx::StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (const fx::ImageBinding& image : stage->images)
                    if (image.parameter == parameter) return &image;
    return nullptr;
}

int sizeAnnotation(const fx::ParameterInfo& parameter, const char* name) {
    const fx::AnnotationValue* size = fx::findAnnotation(parameter.annotations, name);
    return size && size->value.data.size() == 1 ? static_cast<int>(size->value.data[0]) : 64;
}

}  // namespace

bool EffectResources::createImages(fx::DiagnosticSink& diagnostics) {
    for (size_t i = 0; i < parameterInfo().size(); ++i) {
        const fx::ParameterInfo& parameter = parameterInfo()[i];
        if (const fx::AnnotationValue* view = fx::findAnnotation(parameter.annotations, "ViewOf")) {
            const std::optional<size_t> viewed = findParameter(view->value.string);
            const bool readWrite = viewed && (parameterInfo()[*viewed].type.isImage() ||
                                              parameterInfo()[*viewed].type.isBuffer());
            if (!readWrite) {
                diagnostics.report(fx::DiagId::ViewOfUnknownResource, parameter.loc,
                                   {parameter.name, view->value.string});
                return false;
            }
            resourceViews[i] = *viewed;
        }
        if (!parameter.type.isImage()) continue;
        const fx::ImageBinding* use = imageUse(*mCompiled, i);
        if (!use) continue;  // no pass reads or writes it
        const std::optional<fx::TextureFormat> format = imageTextureFormat(use->format);
        if (!format) {
            diagnostics.report(fx::DiagId::ImageFormatUnsupported, parameter.loc,
                               {parameter.name, parameter.type.hlslName(), use->format});
            return false;
        }
        const int width = sizeAnnotation(parameter, "Width"), height = sizeAnnotation(parameter, "Height");
        if (width < 1 || height < 1 || width > 16384 || height > 16384) {
            diagnostics.report(
                fx::DiagId::InvalidDimensions, parameter.loc,
                {parameter.name + " is " + std::to_string(width) + " x " + std::to_string(height)});
            return false;
        }
        GpuTexture texture = GpuTexture::create2D(*format, width, height);
        texture.setLabel(parameter.name);
        images[i] = std::move(texture);
    }
    return true;
}

}  // namespace runtime
