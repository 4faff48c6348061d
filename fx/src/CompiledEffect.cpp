// CompiledEffect: lookups, stage names and the texture-format table.
#include <fx/CompiledEffect.h>
#include <fx/RenderStates.h>

#include "CaseFolding.h"

#include <algorithm>
#include <cctype>

namespace fx {

std::string_view shaderStageName(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex:
            return "vertex";
        case ShaderStage::Fragment:
            return "pixel";
        case ShaderStage::Geometry:
            return "geometry";
        case ShaderStage::Hull:
            return "hull";
        case ShaderStage::Domain:
            return "domain";
        case ShaderStage::Compute:
            return "compute";
    }
    return "vertex";
}

const AnnotationValue* findAnnotation(const Annotations& annotations, std::string_view name) {
    for (const AnnotationValue& annotation : annotations)
        if (equalsIgnoreCase(annotation.name, name)) return &annotation;
    return nullptr;
}

const CompiledTechnique* CompiledEffect::findTechnique(const std::string& name) const {
    for (const CompiledTechnique& t : techniques)
        if (t.name == name) return &t;
    for (const CompiledTechnique& t : techniques)
        if (!t.group.empty() && t.group + "." + t.name == name) return &t;
    return nullptr;
}

const ParameterInfo* CompiledEffect::findParameter(const std::string& name) const {
    for (const ParameterInfo& p : parameters)
        if (p.name == name) return &p;
    return nullptr;
}

const TextureDesc* CompiledEffect::findTexture(size_t parameter) const {
    for (const TextureDesc& t : textures)
        if (t.parameter == parameter) return &t;
    return nullptr;
}

const SamplerDesc* CompiledEffect::findSampler(size_t parameter) const {
    for (const SamplerDesc& s : samplers)
        if (s.parameter == parameter) return &s;
    return nullptr;
}

const StructInfo* CompiledEffect::findStruct(const std::string& name) const {
    for (const StructInfo& s : structs)
        if (s.name == name) return &s;
    return nullptr;
}

namespace {

// A struct counts with the structs before it only, so that a file whose structs hold each other in a
// circle (a corrupt one) counts in finite time. Saturates rather than overflows.
size_t countComponents(const std::vector<StructInfo>& structs, const TypeDesc& type, size_t before) {
    constexpr size_t kSaturated = size_t(1) << 40;
    size_t perElement = static_cast<size_t>(std::max(type.rows, 0) * std::max(type.cols, 0));
    if (type.base == BaseType::Struct) {
        perElement = 0;
        for (size_t i = 0; i < before; ++i)
            if (structs[i].name == type.structName) {
                for (const StructMemberInfo& member : structs[i].members)
                    perElement = std::min(kSaturated, perElement + countComponents(structs, member.type, i));
                break;
            }
    }
    size_t count = perElement;
    for (int dim : type.arrayDims) {
        const size_t n = static_cast<size_t>(std::max(dim, 1));
        count = count > kSaturated / n ? kSaturated : count * n;
    }
    return count;
}

}  // namespace

size_t CompiledEffect::componentCount(const TypeDesc& type) const {
    return countComponents(structs, type, structs.size());
}

bool isDepthFormat(TextureFormat format) {
    return format == TextureFormat::D16 || format == TextureFormat::D24S8 || format == TextureFormat::D24X8 ||
           format == TextureFormat::D32F;
}

namespace {
struct FormatName {
    std::string_view name;
    TextureFormat format;
};
// Every spelling we accept, upper case. D3D9 names first (what FX Composer effects use), then DXGI, then
// plain GL-ish names. D3D9 A8R8G8B8/X8R8G8B8 are BGRA in memory; GL uploads handle the swizzle, so both map
// to RGBA8 here.
constexpr FormatName kFormats[] = {
    {"A8R8G8B8", TextureFormat::RGBA8},
    {"X8R8G8B8", TextureFormat::RGBA8},
    {"A8B8G8R8", TextureFormat::RGBA8},
    {"X8B8G8R8", TextureFormat::RGBA8},
    {"R32F", TextureFormat::R32F},
    {"G32R32F", TextureFormat::RG32F},
    {"A16B16G16R16F", TextureFormat::RGBA16F},
    {"A32B32G32R32F", TextureFormat::RGBA32F},
    {"R16F", TextureFormat::R16F},
    {"G16R16F", TextureFormat::RG16F},
    {"D24S8", TextureFormat::D24S8},
    {"D24X8", TextureFormat::D24X8},
    {"D16", TextureFormat::D16},
    {"D16_LOCKABLE", TextureFormat::D16},
    {"D32", TextureFormat::D32F},
    {"D32F", TextureFormat::D32F},
    {"D32F_LOCKABLE", TextureFormat::D32F},
    {"A16B16G16R16", TextureFormat::RGBA16},
    // Formats without an exact counterpart here take the nearest one that holds at least their precision:
    // other 16-bit normalized channels go to half floats, luminance and alpha formats to RGBA8.
    {"G16R16", TextureFormat::RG16F},
    {"A2R10G10B10", TextureFormat::RGBA16F},
    {"A2B10G10R10", TextureFormat::RGBA16F},
    {"R8G8B8", TextureFormat::RGBA8},
    {"R5G6B5", TextureFormat::RGBA8},
    {"X1R5G5B5", TextureFormat::RGBA8},
    {"A1R5G5B5", TextureFormat::RGBA8},
    {"A4R4G4B4", TextureFormat::RGBA8},
    {"L8", TextureFormat::RGBA8},
    {"A8", TextureFormat::RGBA8},
    {"A8L8", TextureFormat::RGBA8},
    {"L16", TextureFormat::R16F},
    {"D24S8_SHADOWMAP", TextureFormat::D24S8},
    {"D24X8_SHADOWMAP", TextureFormat::D24X8},
    {"D16_SHADOWMAP", TextureFormat::D16},
    {"D24FS8", TextureFormat::D24S8},
    {"D15S1", TextureFormat::D16},
    {"D24X4S4", TextureFormat::D24S8},
    {"D32F_SHADOWMAP", TextureFormat::D32F},
    // DXGI
    {"R8G8B8A8_UNORM", TextureFormat::RGBA8},
    {"B8G8R8A8_UNORM", TextureFormat::RGBA8},
    {"R16G16B16A16_FLOAT", TextureFormat::RGBA16F},
    {"R32G32B32A32_FLOAT", TextureFormat::RGBA32F},
    {"R16_FLOAT", TextureFormat::R16F},
    {"R32_FLOAT", TextureFormat::R32F},
    {"R16G16_FLOAT", TextureFormat::RG16F},
    {"R32G32_FLOAT", TextureFormat::RG32F},
    {"D16_UNORM", TextureFormat::D16},
    {"D24_UNORM_S8_UINT", TextureFormat::D24S8},
    {"D32_FLOAT", TextureFormat::D32F},
    {"R8G8B8A8_UNORM_SRGB", TextureFormat::RGBA8},
    {"B8G8R8A8_UNORM_SRGB", TextureFormat::RGBA8},
    {"B8G8R8X8_UNORM", TextureFormat::RGBA8},
    {"R8G8B8A8_TYPELESS", TextureFormat::RGBA8},
    {"R10G10B10A2_UNORM", TextureFormat::RGBA16F},
    {"R11G11B10_FLOAT", TextureFormat::RGBA16F},
    {"R16G16B16A16_UNORM", TextureFormat::RGBA16},
    {"R16G16_UNORM", TextureFormat::RG16F},
    {"R8_UNORM", TextureFormat::RGBA8},
    {"A8_UNORM", TextureFormat::RGBA8},
    {"R8G8_UNORM", TextureFormat::RGBA8},
    {"R16_UNORM", TextureFormat::R16F},
    {"D32_FLOAT_S8X24_UINT", TextureFormat::D32F},
    // plain
    {"RGBA8", TextureFormat::RGBA8},
    {"RGBA16F", TextureFormat::RGBA16F},
    {"RGBA32F", TextureFormat::RGBA32F},
    {"RG16F", TextureFormat::RG16F},
    {"RG32F", TextureFormat::RG32F},
    {"RGBA16", TextureFormat::RGBA16},
    {"DEPTH24_STENCIL8", TextureFormat::D24S8},
    {"DEPTH32F", TextureFormat::D32F},
    {"DEPTH16", TextureFormat::D16},
};
}  // namespace

std::optional<TextureFormat> parseTextureFormat(std::string_view name) {
    std::string upper = upperCase(name);
    // Accept the prefixed spellings too: D3DFMT_A8R8G8B8, DXGI_FORMAT_R32_FLOAT.
    for (std::string_view prefix : {std::string_view("D3DFMT_"), std::string_view("DXGI_FORMAT_")})
        if (upper.rfind(prefix, 0) == 0) upper.erase(0, prefix.size());
    for (const FormatName& f : kFormats)
        if (f.name == upper) return f.format;
    return std::nullopt;
}

std::string_view textureFormatName(TextureFormat format) {
    switch (format) {
        case TextureFormat::RGBA8:
            return "RGBA8";
        case TextureFormat::RGBA16F:
            return "RGBA16F";
        case TextureFormat::RGBA32F:
            return "RGBA32F";
        case TextureFormat::R16F:
            return "R16F";
        case TextureFormat::R32F:
            return "R32F";
        case TextureFormat::RG16F:
            return "RG16F";
        case TextureFormat::RG32F:
            return "RG32F";
        case TextureFormat::RGBA16:
            return "RGBA16";
        case TextureFormat::D16:
            return "D16";
        case TextureFormat::D24S8:
            return "D24S8";
        case TextureFormat::D24X8:
            return "D24X8";
        case TextureFormat::D32F:
            return "D32F";
    }
    return "RGBA8";
}

}  // namespace fx
