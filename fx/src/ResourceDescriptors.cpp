// ResourceDescriptors: the effect's textures (files, render targets, procedural), samplers and the GL
// units they are bound to (see Compiler.h).

#include "Compiler.h"
#include "CaseFolding.h"

#include "CaseBlindPath.h"
#include "SpirvToGlsl.h"

#include <fx/InstancedPass.h>
#include <fx/StorageLimits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

namespace fx::detail {

namespace {

const char* multisampleKeyword(BaseType type) {
    return type == BaseType::Texture2DMSArray ? "Texture2DMSArray" : "Texture2DMS";
}

// The textures shadowfx makes for images, by the format qualifier glslang gives their element type.
std::optional<TextureFormat> imageTextureFormat(const std::string& qualifier) {
    if (qualifier == "rgba32f") return TextureFormat::RGBA32F;
    if (qualifier == "rgba16f") return TextureFormat::RGBA16F;
    if (qualifier == "rg32f") return TextureFormat::RG32F;
    if (qualifier == "rg16f") return TextureFormat::RG16F;
    if (qualifier == "r32f") return TextureFormat::R32F;
    if (qualifier == "r16f") return TextureFormat::R16F;
    if (qualifier == "rgba8") return TextureFormat::RGBA8;
    return std::nullopt;
}

// An image's size annotation (`int Width = 256;`): `absent` without one or for one that is not one number.
// Kept as the annotation's float until its range is checked: an `int` annotation is folded, not clamped,
// so `Width = 1e10` arrives as a float no `int` can hold.
double sizeAnnotation(const ParameterInfo& parameter, const char* name, double absent) {
    const AnnotationValue* size = findAnnotation(parameter.annotations, name);
    return size && size->value.data.size() == 1 ? double(size->value.data[0]) : absent;
}

// A Buffer<T>'s texels from T as written between its angle brackets ("float4", "uint"; blanks ignored,
// none: float4); nullopt for a T GL buffer textures cannot hold (doubles, halves, structs, 16-bit types).
std::optional<BufferTexel> bufferTexel(const std::string& templateArgs) {
    std::string t;
    for (char c : templateArgs)
        if (c != ' ' && c != '\t') t += c;
    if (t.empty()) return BufferTexel{BaseType::Float, 4};
    for (const auto& [name, component] : {std::pair<std::string_view, BaseType>{"float", BaseType::Float},
                                          std::pair<std::string_view, BaseType>{"int", BaseType::Int},
                                          std::pair<std::string_view, BaseType>{"uint", BaseType::UInt}}) {
        if (t.rfind(name, 0) != 0) continue;
        const std::string_view rest = std::string_view(t).substr(name.size());
        if (rest.empty()) return BufferTexel{component, 1};
        if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4')
            return BufferTexel{component, rest[0] - '0'};
    }
    return std::nullopt;
}

// A side as the error message shows it: a whole number as written, anything else as %g.
std::string sideText(double side) {
    if (side == std::floor(side) && std::fabs(side) < 1e15)
        return std::to_string(static_cast<long long>(side));
    char text[32];
    std::snprintf(text, sizeof text, "%g", side);
    return text;
}

}  // namespace

void Compiler::textures() {
    std::filesystem::path base = std::filesystem::path(mEffect.path).parent_path();
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        if (!p.type.isTexture()) continue;
        TextureDesc t;
        t.parameter = i;
        t.loc = p.loc;
        t.type = p.type.base == BaseType::TextureCube ? BaseType::TextureCube
                 : p.type.base == BaseType::Texture3D ? BaseType::Texture3D
                 : p.type.base >= BaseType::Texture1DArray && p.type.base <= BaseType::Texture2DMSArray
                     ? p.type.base
                     : BaseType::Texture2D;
        resourceShape(p, t);
        // An untyped `texture` says what it holds in FX Composer's ResourceType annotation (TextureType
        // beside a texture function).
        const Annotation* resourceType = p.annotation("ResourceType");
        if (!resourceType) resourceType = p.annotation("TextureType");
        if (resourceType && p.type.base == BaseType::Texture &&
            resourceType->value.kind == Expr::Kind::String) {
            const std::string& holds = resourceType->value.text;
            if (equalsIgnoreCase(holds, "Cube")) t.type = BaseType::TextureCube;
            if (equalsIgnoreCase(holds, "3D") || equalsIgnoreCase(holds, "Volume"))
                t.type = BaseType::Texture3D;
        }
        std::string semantic = upperCase(p.semantic);
        t.kind = semantic == "RENDERCOLORTARGET"          ? TextureDesc::Kind::RenderColorTarget
                 : semantic == "RENDERDEPTHSTENCILTARGET" ? TextureDesc::Kind::RenderDepthStencilTarget
                                                          : TextureDesc::Kind::Runtime;
        bool depth = t.kind == TextureDesc::Kind::RenderDepthStencilTarget;
        t.format = depth ? TextureFormat::D24S8 : TextureFormat::RGBA8;
        TypeDesc int2;
        int2.base = BaseType::Float;
        int2.shape = Shape::Vector;
        int2.cols = 2;
        TypeDesc scalar;
        // Written so that NaN, infinities and fractions below 1 fail too (`w <= 0` let NaN and 0.5 through,
        // and the cast of NaN or 1e30 to an integer was undefined behaviour).
        const int maxSize = mOptions.maxRenderTargetSize;
        auto checkSize = [&](float w, float h, const SourceLoc& loc) {
            auto inRange = [&](float side) { return side >= 1 && side <= static_cast<float>(maxSize); };
            if (!inRange(w) || !inRange(h)) {
                auto shown = [](float side) {
                    if (side != side) return std::string("NaN");
                    char text[32];
                    std::snprintf(text, sizeof text, "%g", static_cast<double>(side));
                    return std::string(text);
                };
                error(DiagId::RenderTargetSizeOutOfRange, loc, {shown(w), shown(h), std::to_string(maxSize)});
                return false;
            }
            return true;
        };
        // FX Composer also treated a texture as a render target when only its size annotations said so
        // (`RenderTargetDimensions`, `ViewPortRatio`), with no RENDERCOLORTARGET semantic; its Format
        // tells colour from depth.
        if (t.kind == TextureDesc::Kind::Runtime && p.semantic.empty() &&
            (p.annotation("RenderTargetDimensions") || p.annotation("ViewPortRatio"))) {
            const Annotation* format = p.annotation("Format");
            const std::optional<TextureFormat> f = format && format->value.kind == Expr::Kind::String
                                                       ? parseTextureFormat(format->value.text)
                                                       : std::nullopt;
            depth = f && isDepthFormat(*f);
            t.kind =
                depth ? TextureDesc::Kind::RenderDepthStencilTarget : TextureDesc::Kind::RenderColorTarget;
            t.format = depth ? TextureFormat::D24S8 : TextureFormat::RGBA8;
        }
        // A volume's Dimensions has a third component, its depth (TextureFunction.cpp reads it).
        for (const char* dimensions : {"Dimensions", "RenderTargetDimensions"})
            if (const Annotation* a = p.annotation(dimensions)) {
                const bool volume = t.type == BaseType::Texture3D && a->value.kind == Expr::Kind::InitList &&
                                    a->value.args.size() == 3;
                if (auto v = eval(a->value, volume ? nullptr : &int2);
                    v && v->data.size() >= 2 && checkSize(v->data[0], v->data[1], a->loc)) {
                    t.width = static_cast<int>(v->data[0]);
                    t.height = static_cast<int>(v->data[1]);
                    if (volume && v->data.size() == 3) {
                        if (v->data[2] >= 1 && v->data[2] <= 2048)
                            t.depth = static_cast<int>(v->data[2]);
                        else
                            error(DiagId::VolumeDepthOutOfRange, a->loc, {});
                    }
                }
            }
        const Annotation* w = p.annotation("width");
        const Annotation* h = p.annotation("height");
        if (w || h) {
            auto wv = w ? eval(w->value, &scalar) : std::optional<Value>(Value::scalar(1));
            auto hv = h ? eval(h->value, &scalar) : wv;
            if (wv && hv && checkSize(wv->asFloat(), hv->asFloat(), (w ? w : h)->loc)) {
                t.width = static_cast<int>(wv->asFloat());
                t.height = static_cast<int>(hv->asFloat());
            }
        }
        if (const Annotation* a = p.annotation("ViewPortRatio")) {
            if (auto v = eval(a->value, nullptr)) {
                t.viewportRatio[0] = v->data.empty() ? 1.0f : v->data[0];
                t.viewportRatio[1] = v->data.size() > 1 ? v->data[1] : t.viewportRatio[0];
                if (t.viewportRatio[0] <= 0 || t.viewportRatio[1] <= 0 || t.viewportRatio[0] > 16 ||
                    t.viewportRatio[1] > 16)
                    error(DiagId::ViewportRatioOutOfRange, a->loc, {});
            }
        }
        if (const Annotation* a = p.annotation("Format")) {
            if (a->value.kind != Expr::Kind::String) {
                error(DiagId::InvalidTextureFormat, a->value.loc, {a->value.str()});
            } else if (auto f = parseTextureFormat(a->value.text)) {
                t.format = *f;
            } else {
                error(DiagId::InvalidTextureFormat, a->value.loc, {a->value.text});
            }
        }
        if (const Annotation* a = p.annotation("MipLevels")) {
            if (auto v = eval(a->value, &scalar)) t.mipLevels = std::max(0, v->asInt());
        }
        if (const Annotation* a = p.annotation("Procedural")) procedural(p, *a, t);
        if (const Annotation* a = p.annotation("function")) textureFunction(p, *a, t);
        std::string resource;
        SourceLoc resourceLoc = p.loc;
        if (const Annotation* a = p.annotation("ResourceName"); a && a->value.kind == Expr::Kind::String) {
            resource = a->value.text;
            resourceLoc = a->value.loc;
        } else if (p.initializer && p.initializer->kind == Expr::Kind::String) {
            resource = p.initializer->text;
            resourceLoc = p.initializer->loc;
        }
        if (!resource.empty() && t.kind == TextureDesc::Kind::Runtime) {
            t.kind = TextureDesc::Kind::File;
            t.resourceName = resource;
            std::string name = resource;  // "textures\\rock.dds" names a folder on Windows
            for (char& c : name)
                if (c == '\\') c = '/';
            std::filesystem::path path = base / name;
            std::error_code ec;
            if (std::filesystem::exists(path, ec)) {
                t.resolvedPath = path.string();
            } else if (std::optional<std::string> found = detail::findPathIgnoringCase(path.string())) {
                t.resolvedPath = *found;
                mDiagnostics.report(DiagId::TextureCaseMismatch, resourceLoc, {resource, *found});
            } else {
                // FX Composer drew with a default texture when a file was missing, and so do we, whatever
                // the file's type: a located warning, and a neutral (white) texture at run time.
                mDiagnostics.report(DiagId::TextureFileNotFound, resourceLoc, {resource});
            }
        }
        if (t.kind == TextureDesc::Kind::Runtime && !resource.empty()) t.resourceName = resource;
        // The thesis's noise texture, by its semantic: classified here so that the runtime reads the kind
        // and compares no semantic text.
        if (t.kind == TextureDesc::Kind::Runtime && t.type == BaseType::Texture2D && semantic == "NOISE")
            t.kind = TextureDesc::Kind::Noise;
        if ((t.type == BaseType::Texture2DMS || t.type == BaseType::Texture2DMSArray) && t.samples == 0) {
            if (t.kind == TextureDesc::Kind::RenderColorTarget ||
                t.kind == TextureDesc::Kind::RenderDepthStencilTarget)
                error(DiagId::MultisampleTargetWithoutSampleCount, p.loc,
                      {p.name, multisampleKeyword(t.type)});
            t.samples = 1;
        }
        mOut->textures.push_back(std::move(t));
    }
}

// A D3D10 array's element count (`int ArraySize = N;`, default 1) and a Texture2DMS<T, N>'s or
// Texture2DMSArray<T, N>'s sample count.
void Compiler::resourceShape(const Parameter& p, TextureDesc& t) {
    const bool array = t.type == BaseType::Texture1DArray || t.type == BaseType::Texture2DArray ||
                       t.type == BaseType::TextureCubeArray || t.type == BaseType::Texture2DMSArray;
    if (const Annotation* a = p.annotation("ArraySize")) {
        TypeDesc scalar;
        std::optional<Value> v = array ? eval(a->value, &scalar) : std::nullopt;
        const float n = v ? v->asFloat() : 0.0f;
        if (!array)
            error(DiagId::ArraySizeWithoutArray, a->loc, {});
        else if (!(n >= 1 && n <= 2048 && n == std::floor(n)))
            error(DiagId::ArraySizeInvalid, a->value.loc, {});
        else
            t.arraySize = static_cast<int>(n);
    }
    if (t.type != BaseType::Texture2DMS && t.type != BaseType::Texture2DMSArray) return;
    // `Texture2DMS<float4, 4>`: the count follows the element type; D3D10 allows 1..32, GL's limit is the
    // driver's (GL_MAX_COLOR_TEXTURE_SAMPLES, at least 1), checked when the runtime creates it.
    const std::string& args = p.type.templateArgs;
    const size_t comma = args.rfind(',');
    std::string count = comma == std::string::npos ? "" : args.substr(comma + 1);
    count.erase(0, count.find_first_not_of(" \t"));
    count.erase(count.find_last_not_of(" \t") + 1);
    if (comma == std::string::npos) {
        t.samples = 0;  // `Texture2DMS<float4>`: any count (SM 5); a render target needs one (below)
        return;
    }
    const bool digits =
        !count.empty() && count.size() <= 2 && count.find_first_not_of("0123456789") == std::string::npos;
    const int n = digits ? std::atoi(count.c_str()) : 0;
    if (n < 1 || n > 32)
        error(DiagId::MultisampleSampleCountInvalid, p.loc, {p.name, multisampleKeyword(t.type)});
    else
        t.samples = static_cast<int>(n);
}

// `string Procedural = "noise"; int Seed = 7;` with Dimensions (default 64x64) and Format (default
// A8R8G8B8): a texture the runtime generates once when it creates the effect.
void Compiler::procedural(const Parameter& p, const Annotation& annotation, TextureDesc& t) {
    if (t.kind != TextureDesc::Kind::Runtime || t.type != BaseType::Texture2D) {
        error(DiagId::ProceduralTextureKind, annotation.loc, {});
        return;
    }
    if (annotation.value.kind != Expr::Kind::String || !equalsIgnoreCase(annotation.value.text, "noise")) {
        error(DiagId::ProceduralGeneratorUnknown, annotation.value.loc, {annotation.value.str()});
        return;
    }
    if (isDepthFormat(t.format)) {
        error(DiagId::ProceduralDepthFormat, annotation.loc, {});
        return;
    }
    t.kind = TextureDesc::Kind::Procedural;
    if (t.width == 0) t.width = t.height = 64;
    if (const Annotation* seed = p.annotation("Seed")) {
        TypeDesc scalar;
        if (auto v = eval(seed->value, &scalar)) {
            const float value = v->asFloat();
            if (!(value >= 0 && value <= 4294967295.0f && value == std::floor(value)))
                error(DiagId::ProceduralSeedInvalid, seed->value.loc, {});
            else
                t.seed = static_cast<uint32_t>(value);
        }
    }
}

// One sampler state (a sampler_state block's, or a D3D9 pass's `MinFilter[N] = ...`) written into `s`.
void Compiler::applySamplerState(const StateAssignment& a, BaseType samplerType, SamplerDesc& s,
                                 bool& hasComparison) {
    auto id = findSamplerState(a.name);
    if (!id) {
        error(DiagId::UnknownState, a.loc, {a.name});
        return;
    }
    const StateInfo& info = samplerStateInfo(*id);
    if (*id == SamplerStateId::Texture) {
        auto it = mIndex.find(a.value.text);
        if (it == mIndex.end())
            error(DiagId::UnknownIdentifier, a.value.loc, {a.value.text});
        else if (const TypeDesc& type = mEffect.parameters[it->second].type; !type.isTexture())
            // Declared, but of the wrong type: say so in the author's terms.
            error(DiagId::TextureStateNotTexture, a.value.loc, {a.name, a.value.text, type.hlslName()});
        else
            s.texture = it->second;
        // An untyped `texture` sampled through a samplerCUBE or sampler3D holds that kind.
        if (s.texture && mEffect.parameters[*s.texture].type.base == BaseType::Texture &&
            (samplerType == BaseType::SamplerCube || samplerType == BaseType::Sampler3D)) {
            for (TextureDesc& t : mOut->textures)
                if (t.parameter == *s.texture)
                    t.type =
                        samplerType == BaseType::SamplerCube ? BaseType::TextureCube : BaseType::Texture3D;
        }
        return;
    }
    // Empty where the value is in error (reported).
    const std::vector<float> value = [&]() -> std::vector<float> {
        if (a.value.kind == Expr::Kind::Identifier && !mIndex.count(a.value.text)) {
            auto e = findEnumValue(info.domain, a.value.text);
            if (!e) {
                error(DiagId::UnknownStateValue, a.value.loc, {a.value.text, a.name, ""});
                return {};
            }
            return {static_cast<float>(*e)};
        }
        if (auto v = eval(a.value, nullptr)) return v->data;
        return {};
    }();
    if (value.empty()) return;
    int n = static_cast<int>(value[0]);
    switch (*id) {
        case SamplerStateId::AddressU:
            s.addressU = n;
            break;
        case SamplerStateId::AddressV:
            s.addressV = n;
            break;
        case SamplerStateId::AddressW:
            s.addressW = n;
            break;
        case SamplerStateId::MinFilter:
            s.minFilter = n;
            break;
        case SamplerStateId::MagFilter:
            s.magFilter = n;
            break;
        case SamplerStateId::MipFilter:
            s.mipFilter = n;
            break;
        case SamplerStateId::MaxAnisotropy:
            s.maxAnisotropy = n;
            break;
        case SamplerStateId::MipMapLodBias:
            s.mipLodBias = value[0];
            break;
        case SamplerStateId::MinLOD:
            s.minLod = std::max(value[0], -1000.0f);
            break;
        case SamplerStateId::MaxLOD:
            s.maxLod = std::min(value[0], 1000.0f);
            break;
        case SamplerStateId::ComparisonFunc:
            s.comparisonFunc = n;
            break;
        case SamplerStateId::BorderColor:
            if (value.size() >= 4) {
                for (int k = 0; k < 4; ++k) s.borderColor[k] = value[static_cast<size_t>(k)];
            } else {  // packed D3DCOLOR 0xAARRGGBB
                auto c = static_cast<uint32_t>(static_cast<int64_t>(value[0]));
                s.borderColor[0] = static_cast<float>((c >> 16) & 255) / 255.0f;
                s.borderColor[1] = static_cast<float>((c >> 8) & 255) / 255.0f;
                s.borderColor[2] = static_cast<float>(c & 255) / 255.0f;
                s.borderColor[3] = static_cast<float>((c >> 24) & 255) / 255.0f;
            }
            break;
        case SamplerStateId::Filter: {
            // D3D10_FILTER bits: mip linear 0x1, mag linear 0x4, min linear 0x10, anisotropic 0x40,
            // comparison 0x80.
            auto tex = [&](int bit) { return (n & 0x40) ? 3 : ((n & bit) ? 2 : 1); };
            s.minFilter = tex(0x10);
            s.magFilter = tex(0x04);
            s.mipFilter = (n & 0x01) ? 2 : 1;
            hasComparison = (n & 0x80) != 0;
            break;
        }
        default:
            break;
    }
}

void Compiler::samplers() {
    int unit = 0;
    for (size_t i = 0; i < mEffect.parameters.size(); ++i) {
        const Parameter& p = mEffect.parameters[i];
        if (!p.type.isSampler()) continue;
        SamplerDesc s;
        s.parameter = i;
        s.loc = p.loc;
        const bool d3d10 =
            p.type.base == BaseType::SamplerState || p.type.base == BaseType::SamplerComparisonState;
        if (d3d10) {
            // D3D10's sampler defaults (D3D11_SAMPLER_DESC's, which FX11 uses) differ from D3D9's: trilinear
            // and clamped, white border; a comparison sampler compares with NEVER until told otherwise.
            s.minFilter = s.magFilter = s.mipFilter = 2;
            s.addressU = s.addressV = s.addressW = 3;
            for (float& c : s.borderColor) c = 1.0f;
            s.comparisonFunc = p.type.base == BaseType::SamplerComparisonState ? 1 : 0;
        } else {
            mSamplerUnits[p.name] = unit++;  // D3D10 samplers get units per (texture, sampler) pair
        }
        bool hasComparison = false;
        for (const StateAssignment& a : p.samplerState) applySamplerState(a, p.type.base, s, hasComparison);
        if (hasComparison && s.comparisonFunc == 0) s.comparisonFunc = 4;  // LESSEQUAL
        // A D3D10 SamplerState compares only through SampleCmp on a SamplerComparisonState.
        if (p.type.base == BaseType::SamplerState) s.comparisonFunc = 0;
        mOut->samplers.push_back(s);
    }
}

// Storage-block parameters (StructuredBuffer, ByteAddressBuffer, their read-write, append and consume
// forms) get GL_SHADER_STORAGE_BUFFER binding points in the effect's order of parameters, and those that can
// have a hidden counter (RWStructuredBuffer, AppendStructuredBuffer, ConsumeStructuredBuffer) one for it
// after them: every stage declares a parameter's block at its point, so the runtime binds by parameter.
// The instanced passes' object records and instance lists keep their own points.
void Compiler::storageBindings() {
    int next = 0;
    const auto take = [&next] {
        while (next == kObjectBufferBinding || next == kInstanceBufferBinding) ++next;
        return next++;
    };
    for (const Parameter& p : mEffect.parameters)
        if (p.type.base >= BaseType::StructuredBuffer && p.type.base <= BaseType::ConsumeStructuredBuffer)
            mStorageBindings[p.name] = take();
    for (const Parameter& p : mEffect.parameters)
        if (p.type.base == BaseType::RWStructuredBuffer || p.type.base == BaseType::AppendStructuredBuffer ||
            p.type.base == BaseType::ConsumeStructuredBuffer)
            mCounterBindings[p.name] = take();
}

// What the runtime makes at load for each buffer and read-write texture, as the resources and views an FX11
// application creates (docs/d3d10.md, "Compute shaders and read-write resources"), from the parameters'
// annotations (ParameterInfo::viewOf, elementCount, imageSize) and a Buffer<T>'s T (bufferTexel). Each
// invalid one is an error at its parameter.
void Compiler::storageResources() {
    for (ParameterInfo& parameter : mOut->parameters) {
        if (const AnnotationValue* view = findAnnotation(parameter.annotations, "ViewOf")) {
            const std::string& name = view->value.string;
            const auto viewed = mIndex.find(name);
            const TypeDesc* viewedType =
                viewed == mIndex.end() ? nullptr : &mOut->parameters[viewed->second].type;
            if (!viewedType || !(viewedType->isImage() || viewedType->isBuffer()))
                error(DiagId::ViewOfUnknownResource, parameter.loc, {parameter.name, name});
            else
                parameter.viewOf = viewed->second;
        }
        const BaseType type = parameter.type.base;
        if (type == BaseType::Buffer) {
            if (const std::optional<BufferTexel> texel = bufferTexel(parameter.type.templateArgs))
                parameter.bufferTexel = *texel;
            else
                error(DiagId::BufferElementUnsupported, parameter.loc, {parameter.type.templateArgs});
            continue;
        }
        if ((parameter.type.isBuffer() && type != BaseType::Buffer) || type == BaseType::RWBuffer) {
            if (const AnnotationValue* count = findAnnotation(parameter.annotations, "ElementCount")) {
                const std::vector<float>& data = count->value.data;
                const double value = data.empty() ? 0.0 : data[0];
                if (data.size() == 1 && value >= 1 && value <= double(kMostStorageElements) &&
                    value == static_cast<double>(static_cast<uint32_t>(value)))
                    parameter.elementCount = static_cast<uint32_t>(value);
                else
                    error(DiagId::ElementCountInvalid, parameter.loc,
                          {parameter.name, data.empty() ? "not a number" : std::to_string(value)});
            }
            continue;
        }
        if (!parameter.type.isImage()) continue;
        const double width = sizeAnnotation(parameter, "Width", 64);
        const double height = type == BaseType::RWTexture1D ? 1 : sizeAnnotation(parameter, "Height", 64);
        const double depth = type == BaseType::RWTexture3D        ? sizeAnnotation(parameter, "Depth", 1)
                             : type == BaseType::RWTexture2DArray ? sizeAnnotation(parameter, "ArraySize", 1)
                                                                  : 1;
        const double most = type == BaseType::RWTexture3D ? kMostVolumeImageSide : kMostImageSide;
        // Written so that NaN fails it too.
        const auto inRange = [](double side, double largest) {
            return side >= 1 && side <= largest && side == std::floor(side);
        };
        if (!inRange(width, most) || !inRange(height, most) || !inRange(depth, kMostVolumeImageSide)) {
            std::string size = sideText(width);
            if (type != BaseType::RWTexture1D) size += " x " + sideText(height);
            if (type == BaseType::RWTexture3D || type == BaseType::RWTexture2DArray)
                size += " x " + sideText(depth);
            error(DiagId::ImageSizeOutOfRange, parameter.loc, {parameter.name, size});
            continue;
        }
        parameter.imageSize[0] = static_cast<int>(width);
        parameter.imageSize[1] = static_cast<int>(height);
        parameter.imageSize[2] = static_cast<int>(depth);
    }
}

void Compiler::imageFormats() {
    std::set<size_t> seen;
    for (const CompiledTechnique& technique : mOut->techniques)
        for (const CompiledPass& pass : technique.passes)
            for (const StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (const ImageBinding& image : stage->images) {
                    if (image.parameter >= mOut->parameters.size() || !seen.insert(image.parameter).second)
                        continue;
                    ParameterInfo& parameter = mOut->parameters[image.parameter];
                    parameter.imageFormat = imageTextureFormat(image.format);
                    if (!parameter.imageFormat)
                        error(DiagId::ImageFormatUnsupported, parameter.loc,
                              {parameter.name, parameter.type.hlslName(), image.format});
                }
}

// A resource the GLSL declares under another name than the effect's: its unit cannot be written into the
// GLSL, and a unit glslang chose would bind another resource there. Reported once, at the parameter.
void Compiler::unboundResource(const std::string& name) {
    if (!mUnboundResources.insert(name).second) return;
    const auto at = mIndex.find(name);
    error(DiagId::ResourceRenamedInGlsl, at != mIndex.end() ? mOut->parameters[at->second].loc : SourceLoc{},
          {name});
}

// D3D10 (texture, sampler) pairs and Buffer<T>s: units after the D3D9 samplers', one per pair a pass
// samples (the same in every stage, so that they link to one GL sampler unit).
void Compiler::assignPairUnits() {
    const int first = static_cast<int>(mSamplerUnits.size());
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes) {
            std::map<std::string, int> units;
            for (StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (SamplerBinding& s : stage->samplers)
                    if (!s.pairTexture.empty()) {
                        s.unit = units.try_emplace(s.glslName, first + static_cast<int>(units.size()))
                                     .first->second;
                        if (!declareBinding(stage->glsl, s.glslName, s.unit)) unboundResource(s.glslName);
                    }
        }
}

// Images (RWTexture1D/2D/3D/2DArray, RWBuffer): the pass's image parameters in ascending order take units
// 0, 1, ..., a parameter the same in every stage. A texture function's fill pass numbers its own.
void Compiler::assignImageUnits() {
    const auto assign = [this](CompiledPass& pass) {
        const std::array<StageProgram*, 6> stages = {&pass.vertex,   &pass.hull,     &pass.domain,
                                                     &pass.geometry, &pass.fragment, &pass.compute};
        std::vector<size_t> parameters;
        for (const StageProgram* stage : stages)
            for (const ImageBinding& image : stage->images) parameters.push_back(image.parameter);
        std::sort(parameters.begin(), parameters.end());
        parameters.erase(std::unique(parameters.begin(), parameters.end()), parameters.end());
        for (StageProgram* stage : stages)
            for (ImageBinding& image : stage->images) {
                image.unit =
                    static_cast<int>(std::lower_bound(parameters.begin(), parameters.end(), image.parameter) -
                                     parameters.begin());
                if (!declareBinding(stage->glsl, image.glslName, image.unit)) unboundResource(image.glslName);
            }
    };
    for (CompiledTechnique& technique : mOut->techniques)
        for (CompiledPass& pass : technique.passes) assign(pass);
    for (TextureDesc& texture : mOut->textures)
        if (texture.fill) assign(*texture.fill);
}

}  // namespace fx::detail
