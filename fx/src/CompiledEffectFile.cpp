// CompiledEffectFile: the header (magic, version, size, hash), the content through CompiledEffectFields.h,
// and the checks a read effect passes before anything follows its indices.
//
// [SECTION] Header
// [SECTION] Checks
// [SECTION] Reading and writing

#include <fx/CompiledEffectFile.h>
#include <fx/StorageLimits.h>

#include "CompiledEffectFields.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace fx {

namespace {

// [SECTION] Header

constexpr std::string_view kMagic{"SFXO\r\n\x1a\n", 8};
constexpr size_t kHeaderSize = 8 + 4 + 8 + 8;

// FNV-1a, 64 bits (Fowler, Noll & Vo): catches a flipped or lost byte; not a signature.
uint64_t contentHash(std::string_view bytes) {
    uint64_t hash = 0xcbf29ce484222325ull;
    for (char c : bytes) {
        hash ^= static_cast<uint8_t>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

uint64_t readLittleEndian(std::string_view bytes, size_t offset, size_t width) {
    uint64_t value = 0;
    for (size_t i = 0; i < width; ++i)
        value |= static_cast<uint64_t>(static_cast<uint8_t>(bytes[offset + i])) << (8 * i);
    return value;
}

// [SECTION] Checks

// What the runtime indexes with the effect's numbers, checked against what they index: the first check that
// fails, as its diagnostic and arguments, or none if all hold.
struct Corruption {
    DiagId id;
    std::vector<std::string> args = {};
};

class Checks {
public:
    explicit Checks(const CompiledEffect& effect) : mEffect(effect), mParameters(effect.parameters.size()) {}

    // A member of a struct parameter's element, numeric, within the element; a light in range, or each
    // light in the elements of a one-dimensional array.
    bool memberBindingFits(const ParameterInfo& parameter, const MemberBinding& member) const {
        const TypeDesc& type = parameter.type;
        if (type.base != BaseType::Struct || type.arrayDims.size() > 1 || !member.type.isNumeric() ||
            !member.type.arrayDims.empty())
            return false;
        TypeDesc element = type;
        element.arrayDims.clear();
        const size_t elementCount = mEffect.componentCount(element);
        const size_t end = size_t(member.firstComponent) + mEffect.componentCount(member.type);
        if (end > elementCount || member.elementStride != (type.arrayDims.empty() ? 0 : elementCount))
            return false;
        const int light = member.standard.light;
        if (light < -1 || (light >= 0 && static_cast<size_t>(light) >= mEffect.lights.size())) return false;
        return !member.standard.eachLight || !type.arrayDims.empty();
    }

    std::optional<Corruption> run() {
        if (mEffect.initialValues.size() != mParameters)
            return Corruption{DiagId::CompiledEffectInitialValueCount};
        // A struct holds structs listed before it only (componentCount counts no further), and a value is
        // sized by its count.
        for (size_t i = 0; i < mEffect.structs.size(); ++i)
            for (const StructMemberInfo& member : mEffect.structs[i].members)
                if (member.type.base == BaseType::Struct &&
                    std::none_of(mEffect.structs.begin(),
                                 mEffect.structs.begin() + static_cast<std::ptrdiff_t>(i),
                                 [&](const StructInfo& s) { return s.name == member.type.structName; }))
                    return Corruption{DiagId::CompiledEffectStructOrder, {mEffect.structs[i].name}};
        for (const ParameterInfo& parameter : mEffect.parameters) {
            if (mEffect.componentCount(parameter.type) > (size_t(1) << 24))
                return Corruption{DiagId::CompiledEffectParameterTooLarge, {parameter.name}};
            const int light = parameter.standard.light;
            if (light < -1 || (light >= 0 && static_cast<size_t>(light) >= mEffect.lights.size()))
                return Corruption{DiagId::CompiledEffectParameterLightOutOfRange, {parameter.name}};
            // The runtime writes each bound member into its place in every element of the value.
            for (const MemberBinding& member : parameter.memberBindings)
                if (!memberBindingFits(parameter, member))
                    return Corruption{DiagId::CompiledEffectMemberBindingOutOfRange, {parameter.name}};
            // The runtime binds a view's resource in its place, and makes buffers and images of these sizes.
            if (parameter.viewOf && (*parameter.viewOf >= mParameters ||
                                     !(mEffect.parameters[*parameter.viewOf].type.isBuffer() ||
                                       mEffect.parameters[*parameter.viewOf].type.isImage())))
                return Corruption{DiagId::CompiledEffectParameterViewOutOfRange, {parameter.name}};
            // The compiler's limits (StorageLimits.h): the runtime allocates what these say.
            const int* size = parameter.imageSize;
            const int mostSide =
                parameter.type.base == BaseType::RWTexture3D ? kMostVolumeImageSide : kMostImageSide;
            if (parameter.elementCount < 1 || parameter.elementCount > kMostStorageElements || size[0] < 1 ||
                size[0] > mostSide || size[1] < 1 || size[1] > mostSide || size[2] < 1 ||
                size[2] > kMostVolumeImageSide)
                return Corruption{DiagId::CompiledEffectParameterStorageSizeOutOfRange, {parameter.name}};
            // An image format only on an image, and only one an image can have: the runtime sizes texels by
            // it.
            if (parameter.imageFormat &&
                (!parameter.type.isImage() || !isImageFormat(*parameter.imageFormat)))
                return Corruption{DiagId::CompiledEffectParameterImageFormatInvalid, {parameter.name}};
            // A Buffer<T>'s texels and no other parameter's: the runtime makes its buffer texture by them.
            const BufferTexel& texel = parameter.bufferTexel;
            const bool texelValid =
                parameter.type.base == BaseType::Buffer
                    ? (texel.component == BaseType::Float || texel.component == BaseType::Int ||
                       texel.component == BaseType::UInt) &&
                          texel.components >= 1 && texel.components <= 4
                    : texel.components == 0;
            if (!texelValid)
                return Corruption{DiagId::CompiledEffectParameterBufferTexelInvalid, {parameter.name}};
        }
        for (const TextureDesc& texture : mEffect.textures)
            if (texture.parameter >= mParameters)
                return Corruption{DiagId::CompiledEffectTextureWithoutParameter};
        for (const std::vector<SamplerDesc>* list : {&mEffect.samplers, &mEffect.passSamplers})
            for (const SamplerDesc& sampler : *list)
                if (sampler.parameter >= mParameters || (sampler.texture && *sampler.texture >= mParameters))
                    return Corruption{DiagId::CompiledEffectSamplerWithoutParameter};
        if (std::optional<Corruption> error = script(mEffect.globalScript, 0)) return error;
        for (const TextureDesc& texture : mEffect.textures)
            if (texture.fill) {
                if (std::optional<Corruption> error = check(*texture.fill)) return error;
                if (texture.fill->arguments.size() != 1)
                    return Corruption{DiagId::CompiledEffectFillArgumentMissing};
                if (texture.width < 1 || texture.width > 16384 || texture.height < 1 ||
                    texture.height > 16384 || texture.depth < 1 || texture.depth > 2048)
                    return Corruption{DiagId::CompiledEffectFillSizeOutOfRange};
            }
        for (const CompiledTechnique& technique : mEffect.techniques) {
            if (std::optional<Corruption> error = script(technique.script, technique.passes.size()))
                return error;
            for (const CompiledPass& pass : technique.passes) {
                if (std::optional<Corruption> error = check(pass)) return error;
                if (pass.drawAuto < -1 ||
                    (pass.drawAuto >= 0 && static_cast<size_t>(pass.drawAuto) >= technique.passes.size()))
                    return Corruption{DiagId::CompiledEffectDrawAutoOutOfRange, {pass.name}};
            }
        }
        return std::nullopt;
    }

private:
    std::optional<Corruption> script(const std::vector<ScriptCommand>& commands, size_t passes) const {
        // -1 (none) or an index below `count`.
        const auto within = [](int index, size_t count) {
            return index >= -1 && (index < 0 || static_cast<size_t>(index) < count);
        };
        for (const ScriptCommand& command : commands) {
            if (!within(command.pass, passes)) return Corruption{DiagId::CompiledEffectScriptPassOutOfRange};
            bool parameters =
                within(command.parameter, mParameters) && within(command.selectorParameter, mParameters);
            for (const ScriptCommand::DispatchTerm& term : command.dispatch)
                parameters = parameters && within(term.parameter, mParameters);
            if (!parameters) return Corruption{DiagId::CompiledEffectScriptParameterOutOfRange};
            if (!within(command.light, mEffect.lights.size()))
                return Corruption{DiagId::CompiledEffectScriptLightOutOfRange};
            if (command.clearTarget < -1 || command.clearTarget >= kScriptColorTargets ||
                (command.clearTarget >= 0 && (command.kind != ScriptCommand::Kind::Clear ||
                                              command.clear != ScriptCommand::ClearWhat::Color)))
                return Corruption{DiagId::CompiledEffectScriptClearTargetOutOfRange};
            if (!within(command.technique, mEffect.techniques.size()) ||
                !within(command.techniqueIfFalse, mEffect.techniques.size()))
                return Corruption{DiagId::CompiledEffectScriptTechniqueOutOfRange};
        }
        return std::nullopt;
    }

    // The checks of a pass; the diagnostics name it.
    std::optional<Corruption> check(const CompiledPass& pass) const {
        const auto inPass = [&pass](DiagId id) { return Corruption{id, {pass.name}}; };
        for (const CompileArgument& argument : pass.arguments)
            if (std::optional<DiagId> error = argument.value.malformation(mParameters)) return inPass(*error);
        for (const RenderStateSetting& state : pass.states)
            if (std::optional<DiagId> error = state.value.malformation(mParameters)) return inPass(*error);
        if (std::optional<Corruption> error = script(pass.script, 0)) return error;
        // EffectVariable::isUsed searches the list: ascending, once each, parameters all.
        for (size_t i = 0; i < pass.readParameters.size(); ++i)
            if (pass.readParameters[i] >= mParameters ||
                (i > 0 && pass.readParameters[i] <= pass.readParameters[i - 1]))
                return inPass(DiagId::CompiledEffectPassReadsOutOfRange);
        // One image unit per image parameter of the pass, below the effect's parameter count (a bound on
        // the pass's image parameters; a unit is only ever handed to GL): the runtime binds each parameter's
        // image at its unit.
        std::vector<std::pair<size_t, int>> imageUnits;
        for (const StageProgram* stage :
             {&pass.vertex, &pass.fragment, &pass.geometry, &pass.hull, &pass.domain, &pass.compute}) {
            for (const UniformBinding& uniform : stage->uniforms) {
                const size_t limit =
                    uniform.source == UniformBinding::Source::Parameter ? mParameters : pass.arguments.size();
                if (uniform.index >= limit) return inPass(DiagId::CompiledEffectUniformWithoutSource);
            }
            for (const SamplerBinding& sampler : stage->samplers) {
                if (sampler.samplerParameter != kNoSampler && sampler.samplerParameter >= mParameters)
                    return inPass(DiagId::CompiledEffectSamplerBindingWithoutParameter);
                if (sampler.textureParameter && *sampler.textureParameter >= mParameters)
                    return inPass(DiagId::CompiledEffectSamplerBindingWithoutTexture);
                if (sampler.passSampler < -1 ||
                    (sampler.passSampler >= 0 &&
                     static_cast<size_t>(sampler.passSampler) >= mEffect.passSamplers.size()))
                    return inPass(DiagId::CompiledEffectSamplerBindingWithoutPassSampler);
            }
            for (const StorageBufferBinding& buffer : stage->storageBuffers)
                if (buffer.parameter >= mParameters)
                    return inPass(DiagId::CompiledEffectStorageBufferWithoutParameter);
            for (const ImageBinding& image : stage->images) {
                if (image.parameter >= mParameters)
                    return inPass(DiagId::CompiledEffectImageWithoutParameter);
                if (image.unit < 0 || static_cast<size_t>(image.unit) >= mParameters)
                    return inPass(DiagId::CompiledEffectImageUnitInvalid);
                for (const auto& [parameter, unit] : imageUnits)
                    if ((parameter == image.parameter) != (unit == image.unit))
                        return inPass(DiagId::CompiledEffectImageUnitInvalid);
                imageUnits.emplace_back(image.parameter, image.unit);
            }
            // GL enables one clip plane per entry (GL_CLIP_DISTANCE0 + i), of which it guarantees 8.
            if (stage->effects.clipDistances < 0 || stage->effects.clipDistances > 8)
                return inPass(DiagId::CompiledEffectClipDistancesOutOfRange);
        }
        // Stream output sizes the pass's GL buffers (capacity times stride) and names their slots.
        if (pass.streamOut) {
            for (const StreamOutElement& element : pass.streamOut->elements)
                if (element.slot < 0 || element.slot > 3)
                    return inPass(DiagId::CompiledEffectStreamOutSlotInvalid);
            for (uint32_t stride : pass.streamOut->strides)
                if (stride > (1u << 16)) return inPass(DiagId::CompiledEffectStreamOutStrideOutOfRange);
            if (pass.streamOut->capacity < 0 || pass.streamOut->capacity > (1 << 24))
                return inPass(DiagId::CompiledEffectStreamOutCapacityOutOfRange);
        }
        return std::nullopt;
    }

    const CompiledEffect& mEffect;
    size_t mParameters;
};

}  // namespace

// [SECTION] Reading and writing

bool hasCompiledEffectMagic(std::string_view bytes) {
    return bytes.substr(0, kMagic.size()) == kMagic;
}

bool isCompiledEffectFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char head[kMagic.size()] = {};
    in.read(head, sizeof head);
    return in.gcount() == static_cast<std::streamsize>(sizeof head) &&
           hasCompiledEffectMagic({head, sizeof head});
}

std::string compiledEffectFileAround(std::string_view content) {
    detail::BinaryWriter header;
    header(kCompiledEffectFormatVersion, static_cast<uint64_t>(content.size()), contentHash(content));
    return std::string(kMagic) + header.bytes() + std::string(content);
}

std::string serializeCompiledEffect(const CompiledEffect& effect) {
    detail::BinaryWriter content;
    content(effect);
    return compiledEffectFileAround(content.bytes());
}

std::unique_ptr<CompiledEffect> deserializeCompiledEffect(std::string_view bytes, const std::string& path,
                                                          DiagnosticSink& diagnostics) {
    const SourceLoc where{path, 0, 0};
    if (!hasCompiledEffectMagic(bytes)) {
        diagnostics.report(DiagId::NotCompiledEffect, where, {});
        return nullptr;
    }
    if (bytes.size() < kHeaderSize) {
        diagnostics.report(DiagId::CompiledEffectHeaderTruncated, where,
                           {std::to_string(bytes.size()), std::to_string(kHeaderSize)});
        return nullptr;
    }
    const uint64_t version = readLittleEndian(bytes, 8, 4);
    if (version != kCompiledEffectFormatVersion) {
        diagnostics.report(version > kCompiledEffectFormatVersion ? DiagId::CompiledEffectNewerFormat
                                                                  : DiagId::CompiledEffectOlderFormat,
                           where, {std::to_string(version), std::to_string(kCompiledEffectFormatVersion)});
        return nullptr;
    }
    const uint64_t size = readLittleEndian(bytes, 12, 8);
    const std::string_view content = bytes.substr(kHeaderSize);
    if (content.size() < size) {
        diagnostics.report(DiagId::CompiledEffectContentTruncated, where,
                           {std::to_string(content.size()), std::to_string(size)});
        return nullptr;
    }
    if (content.size() > size) {
        diagnostics.report(DiagId::CompiledEffectTrailingBytes, where,
                           {std::to_string(content.size() - size)});
        return nullptr;
    }
    if (contentHash(content) != readLittleEndian(bytes, 20, 8)) {
        diagnostics.report(DiagId::CompiledEffectHashMismatch, where);
        return nullptr;
    }
    auto effect = std::make_unique<CompiledEffect>();
    detail::BinaryReader reader(content);
    reader(*effect);
    if (!reader.failed() && !reader.atEnd()) reader.require(false, DiagId::CompiledEffectContentLeftOver);
    if (reader.failed()) {
        diagnostics.report(reader.error(), where, reader.errorArgs());
        return nullptr;
    }
    if (std::optional<Corruption> error = Checks(*effect).run()) {
        diagnostics.report(error->id, where, error->args);
        return nullptr;
    }
    return effect;
}

namespace {

bool isTextureFile(const TextureDesc& texture) {
    return texture.kind == TextureDesc::Kind::File && !texture.resolvedPath.empty();
}

// A texture file named by a relative path is found from where the file is loaded: first beside the file
// (an application ships the file with its textures laid out as beside the source), then beside the source
// effect the file was compiled from. One found nowhere is drawn with a neutral texture after a warning, as
// the compiler does for a file missing at compile time.
void findTextureFiles(CompiledEffect& effect, const std::string& path, DiagnosticSink& diagnostics) {
    const std::filesystem::path folders[] = {std::filesystem::path(path).parent_path(),
                                             std::filesystem::path(effect.path).parent_path()};
    for (TextureDesc& texture : effect.textures) {
        if (!isTextureFile(texture) || std::filesystem::path(texture.resolvedPath).is_absolute()) continue;
        const std::string relative = texture.resolvedPath;
        texture.resolvedPath.clear();
        for (const std::filesystem::path& folder : folders) {
            std::error_code error;
            const std::filesystem::path candidate = folder / relative;
            if (std::filesystem::exists(candidate, error)) {
                texture.resolvedPath = candidate.string();
                break;
            }
        }
        if (texture.resolvedPath.empty())
            diagnostics.report(DiagId::TextureFileNotFound, texture.loc, {texture.resourceName});
    }
}

}  // namespace

std::unique_ptr<CompiledEffect> readCompiledEffectFile(const std::string& path, DiagnosticSink& diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diagnostics.report(DiagId::FileNotFound, SourceLoc{path, 0, 0}, {path});
        return nullptr;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::unique_ptr<CompiledEffect> effect = deserializeCompiledEffect(bytes, path, diagnostics);
    if (effect) findTextureFiles(*effect, path, diagnostics);
    return effect;
}

bool writeCompiledEffectFile(const CompiledEffect& effect, const std::string& path,
                             DiagnosticSink& diagnostics) {
    // The file records texture files relative to the source effect's folder, not to the folder the
    // compiler ran in (readCompiledEffectFile finds them). A texture named by an absolute path keeps it.
    std::string bytes;
    if (std::any_of(effect.textures.begin(), effect.textures.end(), isTextureFile)) {
        CompiledEffect relative = effect;
        const std::filesystem::path source = std::filesystem::path(effect.path).parent_path();
        for (TextureDesc& texture : relative.textures) {
            std::string name = texture.resourceName;
            std::replace(name.begin(), name.end(), '\\', '/');
            if (!isTextureFile(texture) || std::filesystem::path(name).is_absolute()) continue;
            const std::filesystem::path fromSource =
                std::filesystem::path(texture.resolvedPath).lexically_relative(source);
            if (!fromSource.empty()) texture.resolvedPath = fromSource.generic_string();
        }
        bytes = serializeCompiledEffect(relative);
    } else {
        bytes = serializeCompiledEffect(effect);
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        diagnostics.report(DiagId::CompiledEffectWriteFailed, SourceLoc{path, 0, 0}, {path});
        return false;
    }
    return true;
}

}  // namespace fx
