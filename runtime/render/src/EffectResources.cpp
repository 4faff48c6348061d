// EffectResources: see EffectResources.h.
#include "EffectResources.h"
#include "TextureFunctionFill.h"

#include <runtime/Image.h>
#include <private/runtime/NameLookups.h>
#include <private/runtime/ProceduralTexture.h>
#include <runtime/TextureFile.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace runtime {

namespace {

// A deterministic noise texture for the `noise` semantic (the thesis's jitter lookups): RGBA uniform in
// [0, 1], from a fixed-seed LCG so every run renders the same image.
GpuTexture makeNoiseTexture() {
    constexpr int kSize = 64;
    std::vector<uint8_t> pixels(kSize * kSize * 4);
    uint32_t state = 0x2545F491u;
    for (uint8_t& p : pixels) {
        state = state * 1664525u + 1013904223u;
        p = static_cast<uint8_t>(state >> 24);
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    texture.uploadRGBA8(pixels.data());
    return texture;
}

bool isArrayType(fx::BaseType type) {
    return type == fx::BaseType::Texture1DArray || type == fx::BaseType::Texture2DArray ||
           type == fx::BaseType::TextureCubeArray;
}

// An array texture of a D3D10 array type: `elements` elements (cubes for a TextureCubeArray).
GpuTexture makeArrayTexture(fx::BaseType type, fx::TextureFormat format, int width, int height, int elements,
                            int mipLevels) {
    if (type == fx::BaseType::Texture1DArray)
        return GpuTexture::create1DArray(format, width, elements, mipLevels);
    if (type == fx::BaseType::TextureCubeArray)
        return GpuTexture::createCubeArray(format, width, elements, mipLevels);
    return GpuTexture::create2DArray(format, width, height, elements, mipLevels);
}

// A multisample texture's sample count: the effect's, or the most this GL's textures of its kind hold (an
// effect written for 8 samples runs with 4 where the driver offers 4; loading warns).
int supportedSamples(const fx::TextureDesc& desc) {
    GLint most = 0;
    gl::GetIntegerv(isDepthFormat(desc.format) ? GL_MAX_DEPTH_TEXTURE_SAMPLES : GL_MAX_COLOR_TEXTURE_SAMPLES,
                    &most);
    return std::max(1, std::min(desc.samples, int(most)));
}

// White: the neutral value for textures the effect multiplies with. A texture array gets its ArraySize
// elements of it, so that GetDimensions reports what the effect declared.
GpuTexture makeNeutralTexture(fx::BaseType type, int elements = 1, int samples = 1) {
    const uint8_t white[4] = {255, 255, 255, 255};
    if (type == fx::BaseType::Texture2DMS || type == fx::BaseType::Texture2DMSArray) {
        GpuTexture texture =
            GpuTexture::createMultisample(fx::TextureFormat::RGBA8, 1, 1, samples,
                                          type == fx::BaseType::Texture2DMSArray ? std::max(elements, 1) : 0);
        gl::ClearTexImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
        return texture;
    }
    if (isArrayType(type)) {
        const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        GpuTexture texture = makeArrayTexture(type, fx::TextureFormat::RGBA8, 1, 1, elements, 1);
        for (int layer = 0; layer < texture.layers(); ++layer) texture.uploadLayerRGBA32F(one, 0, layer);
        return texture;
    }
    if (type == fx::BaseType::Texture3D) {
        const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        GpuTexture texture = GpuTexture::create3D(fx::TextureFormat::RGBA8, 1, 1, 1);
        texture.uploadVolumeRGBA32F(one);
        return texture;
    }
    if (type == fx::BaseType::TextureCube) {
        GpuTexture texture = GpuTexture::createCube(fx::TextureFormat::RGBA8, 1);
        for (int face = 0; face < 6; ++face) texture.uploadRGBA8(white, 0, face);
        return texture;
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, 1, 1);
    texture.uploadRGBA8(white);
    return texture;
}

// A render target of the effect's type, `w` x `h` (a cube's faces `w` square). The layered ones (cubes,
// arrays, volumes) are bound whole (RenderTargetAttachment::wholeOf).
GpuTexture makeRenderTarget(const fx::TextureDesc& desc, int w, int h) {
    switch (desc.type) {
        case fx::BaseType::TextureCube:
            return GpuTexture::createCube(desc.format, w, desc.mipLevels);
        case fx::BaseType::Texture3D:
            return GpuTexture::create3D(desc.format, w, h, desc.depth, desc.mipLevels);
        case fx::BaseType::Texture1DArray:
        case fx::BaseType::Texture2DArray:
        case fx::BaseType::TextureCubeArray:
            return makeArrayTexture(desc.type, desc.format, w, h, desc.arraySize, desc.mipLevels);
        case fx::BaseType::Texture2DMS:
            return GpuTexture::createMultisample(desc.format, w, h, supportedSamples(desc));
        case fx::BaseType::Texture2DMSArray:
            return GpuTexture::createMultisample(desc.format, w, h, supportedSamples(desc),
                                                 std::max(desc.arraySize, 1));
        default:
            return GpuTexture::create2D(desc.format, w, h, desc.mipLevels);
    }
}

std::string textureFileKindName(const TextureFile& file) {
    const std::string kind = file.kind == TextureFile::Kind::Cube     ? "cube"
                             : file.kind == TextureFile::Kind::Volume ? "volume"
                                                                      : "2D";
    return file.elements > 1 ? kind + " array (" + std::to_string(file.elements) + " elements)" : kind;
}

std::string textureTypeName(fx::BaseType type) {
    switch (type) {
        case fx::BaseType::TextureCube:
            return "cube";
        case fx::BaseType::Texture3D:
            return "volume";
        case fx::BaseType::Texture1DArray:
            return "1D array";
        case fx::BaseType::Texture2DArray:
            return "2D array";
        case fx::BaseType::TextureCubeArray:
            return "cube array";
        default:
            return "2D";
    }
}

// A texture array from a file's levels (each level every layer in turn).
GpuTexture makeFileArray(const TextureFile& file, const fx::TextureDesc& desc) {
    const size_t faces = file.kind == TextureFile::Kind::Cube ? 6 : 1;
    const size_t layers = faces * static_cast<size_t>(file.elements);
    int levels = 0;
    for (const std::vector<float>& level : file.levels) {
        const size_t w = static_cast<size_t>(std::max(file.width >> levels, 1));
        const size_t h = static_cast<size_t>(std::max(file.height >> levels, 1));
        if (level.size() != w * h * layers * 4) break;
        ++levels;
    }
    const bool regenerate = levels == 1 && desc.mipLevels != 1;
    GpuTexture texture = makeArrayTexture(desc.type, fx::TextureFormat::RGBA16F, file.width, file.height,
                                          file.elements, regenerate ? 0 : levels);
    for (int level = 0; level < levels; ++level) {
        const size_t layerFloats = static_cast<size_t>(std::max(file.width >> level, 1)) *
                                   static_cast<size_t>(std::max(file.height >> level, 1)) * 4;
        for (size_t layer = 0; layer < layers; ++layer)
            texture.uploadLayerRGBA32F(file.levels[static_cast<size_t>(level)].data() + layer * layerFloats,
                                       level, static_cast<int>(layer));
    }
    if (regenerate) texture.generateMipmaps();
    return texture;
}

// A DDS file's texture, when its kind is what the effect samples: every level the file has, float storage
// so that no file format loses range. nullopt on a mismatch.
std::optional<GpuTexture> makeFileTexture(const TextureFile& file, const fx::TextureDesc& desc) {
    // A Texture2DArray takes any 2D file (one element or more), a Texture1DArray one a texel high, a
    // TextureCubeArray any cube file; a plain texture takes no array.
    if (isArrayType(desc.type)) {
        const bool fits = desc.type == fx::BaseType::TextureCubeArray
                              ? file.kind == TextureFile::Kind::Cube
                              : file.kind == TextureFile::Kind::Flat &&
                                    (desc.type == fx::BaseType::Texture2DArray || file.height == 1);
        if (!fits || file.levels.empty()) return std::nullopt;
        return makeFileArray(file, desc);
    }
    if (file.elements > 1) return std::nullopt;
    const bool wantCube = desc.type == fx::BaseType::TextureCube;
    const bool wantVolume = desc.type == fx::BaseType::Texture3D;
    if (wantCube != (file.kind == TextureFile::Kind::Cube) ||
        wantVolume != (file.kind == TextureFile::Kind::Volume))
        return std::nullopt;
    // Only levels of the size the chain expects (a truncated file keeps what it has).
    int levels = 0;
    for (const std::vector<float>& level : file.levels) {
        const size_t w = static_cast<size_t>(std::max(file.width >> levels, 1));
        const size_t h = static_cast<size_t>(std::max(file.height >> levels, 1));
        const size_t d = static_cast<size_t>(std::max(file.depth >> levels, 1));
        const size_t faces = file.kind == TextureFile::Kind::Cube ? 6 : 1;
        if (level.size() != w * h * d * faces * 4) break;
        ++levels;
    }
    const bool regenerate = levels == 1 && desc.mipLevels != 1;
    const int storageLevels = regenerate ? 0 : levels;
    const fx::TextureFormat format = fx::TextureFormat::RGBA16F;
    if (file.kind == TextureFile::Kind::Cube) {
        GpuTexture texture = GpuTexture::createCube(format, file.width, storageLevels);
        for (int level = 0; level < levels; ++level) {
            const size_t face = static_cast<size_t>(std::max(file.width >> level, 1)) *
                                static_cast<size_t>(std::max(file.height >> level, 1)) * 4;
            for (int f = 0; f < 6; ++f)
                texture.uploadRGBA32F(
                    file.levels[static_cast<size_t>(level)].data() + face * static_cast<size_t>(f), level, f);
        }
        if (regenerate) texture.generateMipmaps();
        return texture;
    }
    if (file.kind == TextureFile::Kind::Volume) {
        GpuTexture texture = GpuTexture::create3D(format, file.width, file.height, file.depth, storageLevels);
        for (int level = 0; level < levels; ++level)
            texture.uploadVolumeRGBA32F(file.levels[static_cast<size_t>(level)].data(), level);
        if (regenerate) texture.generateMipmaps();
        return texture;
    }
    GpuTexture texture = GpuTexture::create2D(format, file.width, file.height, storageLevels);
    for (int level = 0; level < levels; ++level)
        texture.uploadRGBA32F(file.levels[static_cast<size_t>(level)].data(), level);
    if (regenerate) texture.generateMipmaps();
    return texture;
}

// A Buffer<T>'s texel: T's GL buffer-texture format and size. nullopt for a T GL cannot hold as texels
// (doubles, structs, 16-bit types).
struct TexelFormat {
    GLenum format;
    size_t bytes;
};
std::optional<TexelFormat> bufferTexelFormat(const std::string& templateArgs) {
    std::string t;
    for (char c : templateArgs)
        if (c != ' ' && c != '\t') t += c;
    if (t.empty()) t = "float4";  // Buffer without <T> reads float4s
    static const struct {
        const char* name;
        GLenum formats[4];
    } kTypes[] = {{"float", {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F}},
                  {"int", {GL_R32I, GL_RG32I, GL_RGB32I, GL_RGBA32I}},
                  {"uint", {GL_R32UI, GL_RG32UI, GL_RGB32UI, GL_RGBA32UI}}};
    for (const auto& type : kTypes) {
        const std::string name = type.name;
        if (t.rfind(name, 0) != 0) continue;
        const std::string rest = t.substr(name.size());
        const int n = rest.empty()                                           ? 1
                      : rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4' ? rest[0] - '0'
                                                                             : 0;
        if (n == 0) continue;
        return TexelFormat{type.formats[n - 1], static_cast<size_t>(n) * 4};
    }
    return std::nullopt;
}

// The storage layout a pass's code gives a StructuredBuffer or ByteAddressBuffer (the first found; every
// unit declares the same type the same way); null if no pass reads it.
const fx::StorageBufferBinding* storageLayout(const fx::CompiledEffect& effect, size_t parameter) {
    for (const fx::CompiledTechnique& technique : effect.techniques)
        for (const fx::CompiledPass& pass : technique.passes)
            for (const fx::StageProgram* stage :
                 {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
                for (const fx::StorageBufferBinding& b : stage->storageBuffers)
                    if (b.parameter == parameter) return &b;
    return nullptr;
}

// Four independent lanes of (lane ^ word) * odd, rotated: each step is a bijection of the lane for a
// given word and of the word for a given lane, so any one changed word changes the stamp, and the lanes
// do not wait for each other. Chained hashCombine calls cost 10,000 objects about half a millisecond a
// frame, most of a batched frame's own CPU time.
class StampHasher {
public:
    void add(uint64_t word) {
        uint64_t& lane = mLanes[mNext++ & 3];
        lane = std::rotl((lane ^ word) * 0x9E3779B97F4A7C15ull, 29);
    }
    void addBytes(const void* data, size_t size) {
        const auto* bytes = static_cast<const uint8_t*>(data);
        size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            uint64_t word;
            std::memcpy(&word, bytes + i, 8);
            add(word);
        }
        uint64_t tail = size;
        for (; i < size; ++i) tail = (tail << 8) | bytes[i];
        add(tail);
    }
    uint64_t finish() const {
        uint64_t h = hashCombine(0, mNext);
        for (uint64_t lane : mLanes) h = hashCombine(h, lane);
        return h;
    }

private:
    uint64_t mLanes[4] = {0x243F6A8885A308D3ull, 0x13198A2E03707344ull, 0xA4093822299F31D0ull,
                          0x082EFA98EC4E6C89ull};
    uint64_t mNext = 0;
};

// A stamp of everything about the scene's objects a draw depends on (mesh, transform, colour, id, flags)
// and of its explicit bounds. Hashed every frame rather than kept as a revision counter that every
// editor of a Scene would have to bump: 10,000 objects are about 1 MB of hashing, a tenth of a
// millisecond.
uint64_t sceneStamp(const Scene& scene) {
    StampHasher h;
    h.add(scene.objects.size());
    for (const SceneObject& object : scene.objects) {
        h.add(reinterpret_cast<uintptr_t>(object.mesh.get()));
        if (object.mesh) h.add(object.mesh->indices.size() ^ (object.mesh->positions.size() << 32));
        h.addBytes(&object.world, sizeof(object.world));
        h.addBytes(&object.color, sizeof(object.color));
        h.add((uint64_t(object.id) << 2) | (object.castsShadow ? 1u : 0u) |
              (object.receivesShadow ? 2u : 0u));
    }
    if (scene.explicitBounds) h.addBytes(&*scene.explicitBounds, sizeof(Bounds));
    return h.finish();
}

}  // namespace

glm::ivec2 renderTargetSize(const fx::TextureDesc& desc, int width, int height) {
    return glm::ivec2(
        desc.width > 0 ? desc.width
                       : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[0] * width))),
        desc.height > 0 ? desc.height
                        : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[1] * height))));
}

bool isRenderTarget(const fx::TextureDesc& desc) {
    return desc.kind == fx::TextureDesc::Kind::RenderColorTarget ||
           desc.kind == fx::TextureDesc::Kind::RenderDepthStencilTarget;
}

void storeParameter(const std::vector<fx::ParameterInfo>& parameters, size_t index, fx::Value value,
                    std::vector<fx::Value>& values, ParameterStamps& stamps) {
    value.type = parameters.at(index).type;
    const size_t components = static_cast<size_t>(std::max(1, value.type.componentCount()));
    if (value.type.isNumeric() && value.data.size() < components)
        value.data.resize(components, value.asFloat());
    values.at(index) = std::move(value);
    stamps.touch(index);
}

void storeScalarParameter(const std::vector<fx::ParameterInfo>& parameters, size_t index, float scalar,
                          std::vector<fx::Value>& values, ParameterStamps& stamps) {
    fx::Value& value = values.at(index);
    value.type = parameters.at(index).type;
    const size_t components =
        value.type.isNumeric() ? static_cast<size_t>(std::max(1, value.type.componentCount())) : 1;
    value.data.assign(components, scalar);
    value.string.clear();
    stamps.touch(index);
}

std::unique_ptr<EffectResources> EffectResources::create(std::shared_ptr<const fx::CompiledEffect> compiled,
                                                         fx::DiagnosticSink& diagnostics) {
    auto resources = std::unique_ptr<EffectResources>(new EffectResources());
    EffectResources& r = *resources;
    r.mCompiled = std::move(compiled);
    const std::vector<fx::ParameterInfo>& parameters = r.parameterInfo();
    r.values = r.mCompiled->initialValues;
    r.values.resize(parameters.size());
    r.pinned.assign(parameters.size(), false);
    r.stamps.stamps.assign(parameters.size(), 0);
    for (size_t i = 0; i < parameters.size(); ++i) {
        r.mParameterIndex.emplace(parameters[i].name, i);
        if (r.values[i].type.base == fx::BaseType::Float && r.values[i].data.empty())
            r.values[i] = fx::zeroValue(parameters[i].type);
    }

    r.binder = std::make_unique<SemanticBinder>(parameters, r.mCompiled->lights);
    for (const fx::CompiledTechnique& technique : r.mCompiled->techniques)
        r.passUses.push_back(runtime::passUses(technique, parameters.size(), *r.binder));

    bool ok = true;
    for (const fx::CompiledTechnique& technique : r.mCompiled->techniques) {
        auto& passes = r.programs.emplace_back();
        auto& preshaders = r.preshaders.emplace_back();
        for (const fx::CompiledPass& pass : technique.passes) {
            std::unique_ptr<GpuProgram> program = GpuProgram::create(pass, diagnostics);
            ok = ok && program != nullptr;
            if (program && !program->isCompute() && !pass.compute.glsl.empty()) {
                std::unique_ptr<GpuProgram> compute = GpuProgram::createCompute(pass, diagnostics);
                ok = ok && compute != nullptr;
                r.drawingPassComputePrograms[{r.programs.size() - 1, passes.size()}] = std::move(compute);
            }
            // D3D10's DepthBiasClamp needs glPolygonOffsetClamp; without it the bias is applied unbounded.
            for (const fx::RenderStateSetting& setting : pass.states)
                if (setting.id == fx::RenderStateId::DepthBiasClamp && !gl::PolygonOffsetClamp &&
                    !(setting.constant && *setting.constant == 0.0))
                    diagnostics.report(fx::DiagId::DepthBiasClampUnavailable, setting.loc);
            if (pass.streamOut)
                r.streamOuts[{r.programs.size() - 1, passes.size()}] =
                    std::make_unique<StreamOutBuffers>(*pass.streamOut);
            passes.push_back(std::move(program));
            preshaders.emplace_back(pass);
        }
    }
    if (!ok) return nullptr;

    for (const fx::SamplerDesc& desc : r.mCompiled->samplers) {
        r.samplers.emplace(desc.parameter, SamplerObject(desc, false));
        r.comparisonSamplers.emplace(desc.parameter, SamplerObject(desc, true));
    }
    for (const fx::SamplerDesc& desc : r.mCompiled->passSamplers) {
        r.passSamplers.emplace_back(desc, false);
        r.passComparisonSamplers.emplace_back(desc, true);
    }
    r.uniformRing = std::make_unique<UniformRing>();  // texture functions draw with it
    if (!r.createFileTextures(diagnostics) || !r.createDefaultBuffers(diagnostics) ||
        !r.createImages(diagnostics))
        return nullptr;
    r.quad = GpuMesh::makeFullScreenQuad();
    r.annotations = AnnotationTable(*r.mCompiled);
    return resources;
}

std::optional<size_t> EffectResources::findParameter(std::string_view name) const {
    countNameLookup();
    auto it = mParameterIndex.find(std::string(name));
    if (it == mParameterIndex.end()) return std::nullopt;
    return it->second;
}

const fx::Value* EffectResources::find(std::string_view name) const {
    const std::optional<size_t> index = findParameter(name);
    return index ? &values[*index] : nullptr;
}

bool EffectResources::createFileTextures(fx::DiagnosticSink& diagnostics) {
    for (const fx::TextureDesc& desc : mCompiled->textures) {
        if ((desc.type == fx::BaseType::Texture2DMS || desc.type == fx::BaseType::Texture2DMSArray) &&
            supportedSamples(desc) < desc.samples)
            diagnostics.report(fx::DiagId::SampleCountReduced, desc.loc,
                               {parameterInfo()[desc.parameter].name, std::to_string(desc.samples),
                                std::to_string(supportedSamples(desc))});
        if (isRenderTarget(desc)) continue;
        const bool cube = desc.type == fx::BaseType::TextureCube;
        const std::string& semantic = parameterInfo()[desc.parameter].semantic;
        if (desc.kind == fx::TextureDesc::Kind::Runtime && fx::equalsIgnoreCase(semantic, "noise") &&
            desc.type == fx::BaseType::Texture2D) {
            textures[desc.parameter] = makeNoiseTexture();
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::Function) {
            std::optional<GpuTexture> texture = fillTextureFunction(desc, values, *uniformRing, diagnostics);
            if (!texture) return false;
            textures[desc.parameter] = std::move(*texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::Procedural) {
            GpuTexture texture = GpuTexture::create2D(desc.format, desc.width, desc.height, desc.mipLevels);
            texture.uploadRGBA32F(whiteNoiseTexels(texture.width(), texture.height(), desc.seed).data());
            texture.generateMipmaps();
            textures[desc.parameter] = std::move(texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() &&
            isTextureFile(desc.resolvedPath)) {
            std::string error;
            std::optional<TextureFile> file = loadTextureFile(desc.resolvedPath, error);
            if (!file) {
                diagnostics.report(fx::DiagId::TextureFileUnreadable, desc.loc, {desc.resourceName, error});
                return false;
            }
            std::optional<GpuTexture> texture = makeFileTexture(*file, desc);
            if (!texture) {
                // A cube file behind a 2D sampler (or the like) samples as black in GL: say so, and draw
                // with the neutral texture as for a missing file.
                diagnostics.report(fx::Diagnostic{
                    fx::DiagId::TextureFileNotFound, fx::Severity::Warning, desc.loc,
                    "texture file '" + desc.resourceName + "' holds a " + textureFileKindName(*file) +
                        " texture, but the effect samples it as a " + textureTypeName(desc.type) +
                        " texture; using a neutral texture"});
                textures[desc.parameter] =
                    makeNeutralTexture(desc.type, desc.arraySize, supportedSamples(desc));
                continue;
            }
            texture->setLabel(parameterInfo()[desc.parameter].name);
            textures[desc.parameter] = std::move(*texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() && !cube &&
            desc.type == fx::BaseType::Texture2D) {
            std::string error;
            std::optional<Image> image = loadImageFile(desc.resolvedPath, error);
            if (!image) {
                diagnostics.report(fx::DiagId::TextureFileUnreadable, desc.loc, {desc.resourceName, error});
                return false;
            }
            // HDR files keep their range in a float texture; everything else is 8-bit RGBA.
            const int levels = desc.mipLevels == 1 ? 1 : 0;
            GpuTexture texture =
                GpuTexture::create2D(image->isFloat ? fx::TextureFormat::RGBA32F : fx::TextureFormat::RGBA8,
                                     image->width, image->height, levels);
            if (image->isFloat) {
                texture.uploadRGBA32F(image->floats.data());
            } else {
                texture.uploadRGBA8(image->toRGBA8().bytes.data());
            }
            texture.generateMipmaps();
            textures[desc.parameter] = std::move(texture);
            continue;
        }
        textures[desc.parameter] = makeNeutralTexture(desc.type, desc.arraySize, supportedSamples(desc));
    }
    return true;
}

void EffectResources::ensureFrameResources(int width, int height, const std::vector<bool>* needed) {
    if (frameColor.width() != width || frameColor.height() != height) {
        if (frameColor) framebuffers.evict(frameColor);
        if (frameDepth) framebuffers.evict(frameDepth);
        frameColor = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        frameDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    ensureRenderTargets(width, height, needed);
}

void EffectResources::ensureRenderTargets(int width, int height, const std::vector<bool>* needed) {
    for (const fx::TextureDesc& desc : mCompiled->textures) {
        if (!isRenderTarget(desc)) continue;
        const glm::ivec2 size = renderTargetSize(desc, width, height);
        const int w = size.x, h = size.y;
        auto it = textures.find(desc.parameter);
        if (it == textures.end() && needed && !(desc.parameter < needed->size() && (*needed)[desc.parameter]))
            continue;
        if (it != textures.end() && it->second.width() == w && it->second.height() == h) continue;
        if (it != textures.end()) framebuffers.evict(it->second);
        GpuTexture texture = makeRenderTarget(desc, w, h);
        texture.setLabel(parameterInfo()[desc.parameter].name);
        textures[desc.parameter] = std::move(texture);
    }
}

bool EffectResources::setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics) {
    const fx::TextureDesc* desc = index < parameterInfo().size() ? mCompiled->findTexture(index) : nullptr;
    const fx::SourceLoc where =
        index < parameterInfo().size() ? parameterInfo()[index].loc : fx::SourceLoc{mCompiled->path, 0, 0};
    auto refuse = [&](fx::DiagId id, const std::vector<std::string>& args) {
        diagnostics.report(id, where, args);
        return false;
    };
    if (!desc || isRenderTarget(*desc) || desc->type == fx::BaseType::Texture3D ||
        desc->type == fx::BaseType::Texture2DMS || desc->type == fx::BaseType::Texture2DMSArray)
        return refuse(fx::DiagId::SetTextureNotReadTexture, {std::to_string(index)});
    const bool cube = desc->type == fx::BaseType::TextureCube || desc->type == fx::BaseType::TextureCubeArray;
    const int elements = isArrayType(desc->type) ? data.elements : 1;
    const size_t layers = static_cast<size_t>(std::max(elements, 0)) * (cube ? 6 : 1);
    const bool sizeOk =
        data.width >= 1 && data.height >= 1 && data.width <= 16384 && data.height <= 16384 && elements >= 1 &&
        elements <= 2048 && (!cube || data.width == data.height) &&
        (desc->type != fx::BaseType::Texture1DArray || data.height == 1) &&
        data.rgba.size() == static_cast<size_t>(data.width) * static_cast<size_t>(data.height) * layers * 4;
    if (!sizeOk)
        return refuse(cube ? fx::DiagId::SetCubeTextureDataSize : fx::DiagId::SetTextureDataSize,
                      {parameterInfo()[index].name, parameterInfo()[index].type.hlslName()});
    const int levels = desc->mipLevels == 1 ? 1 : 0;
    const fx::TextureFormat format = fx::TextureFormat::RGBA32F;
    const size_t layerFloats = static_cast<size_t>(data.width) * static_cast<size_t>(data.height) * 4;
    GpuTexture texture;
    if (isArrayType(desc->type)) {
        texture = makeArrayTexture(desc->type, format, data.width, data.height, elements, levels);
        for (size_t layer = 0; layer < layers; ++layer)
            texture.uploadLayerRGBA32F(data.rgba.data() + layer * layerFloats, 0, static_cast<int>(layer));
    } else if (cube) {
        texture = GpuTexture::createCube(format, data.width, levels);
        for (int face = 0; face < 6; ++face)
            texture.uploadRGBA32F(data.rgba.data() + static_cast<size_t>(face) * layerFloats, 0, face);
    } else {
        texture = GpuTexture::create2D(format, data.width, data.height, levels);
        texture.uploadRGBA32F(data.rgba.data());
    }
    texture.generateMipmaps();
    texture.setLabel(parameterInfo()[index].name);
    textures[index] = std::move(texture);
    // What render targets hold after earlier frames was drawn from the old texels: nothing is reused.
    targetHistory.clear();
    return true;
}

// `int ElementCount = N;` on a storage buffer (docs/d3d10.md, "Compute shaders and read-write resources"):
// the elements it holds from load on, as the buffer an FX11 application creates for it; 1 without one.
std::optional<size_t> declaredElementCount(const fx::ParameterInfo& parameter,
                                           fx::DiagnosticSink& diagnostics) {
    const fx::AnnotationValue* count = fx::findAnnotation(parameter.annotations, "ElementCount");
    if (!count) return 1;
    const double value = count->value.data.empty() ? 0.0 : count->value.data[0];
    if (count->value.data.size() != 1 || !(value >= 1 && value <= double(size_t(1) << 28)) ||
        value != static_cast<double>(static_cast<size_t>(value))) {
        diagnostics.report(
            fx::DiagId::ElementCountInvalid, parameter.loc,
            {parameter.name, count->value.data.empty() ? "not a number" : std::to_string(value)});
        return std::nullopt;
    }
    return static_cast<size_t>(value);
}

// Zeros until the application sets them: what D3D10 reads from a resource slot with nothing bound.
bool EffectResources::createDefaultBuffers(fx::DiagnosticSink& diagnostics) {
    for (size_t i = 0; i < parameterInfo().size(); ++i) {
        const fx::TypeDesc& type = parameterInfo()[i].type;
        if (!type.isBuffer()) continue;
        if (type.base == fx::BaseType::Buffer) {
            const std::optional<TexelFormat> texel = bufferTexelFormat(type.templateArgs);
            if (!texel) {
                diagnostics.report(fx::DiagId::BufferElementUnsupported, parameterInfo()[i].loc,
                                   {type.templateArgs});
                return false;
            }
            buffers[i] = GpuBuffer::create(nullptr, texel->bytes, texel->format);
            continue;
        }
        const fx::StorageBufferBinding* layout = storageLayout(*mCompiled, i);
        const std::optional<size_t> elements = declaredElementCount(parameterInfo()[i], diagnostics);
        if (!elements) return false;
        buffers[i] =
            GpuBuffer::create(nullptr, *elements * (layout ? std::max<size_t>(layout->glStride, 4) : 16));
        if (type.base == fx::BaseType::RWStructuredBuffer ||
            type.base == fx::BaseType::AppendStructuredBuffer ||
            type.base == fx::BaseType::ConsumeStructuredBuffer) {
            const uint32_t zero = 0;
            counters[i] = GpuBuffer::create(&zero, sizeof zero);
        }
    }
    return true;
}

bool EffectResources::setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                                fx::DiagnosticSink& diagnostics) {
    index = viewedResource(index);  // a view's contents are its resource's
    const bool isBuffer = index < parameterInfo().size() && parameterInfo()[index].type.isBuffer();
    auto refuse = [&](fx::DiagId id, const std::vector<std::string>& args) {
        const fx::SourceLoc where = index < parameterInfo().size() ? parameterInfo()[index].loc
                                                                   : fx::SourceLoc{mCompiled->path, 0, 0};
        diagnostics.report(id, where, args);
        return false;
    };
    if (!isBuffer) return refuse(fx::DiagId::SetBufferNotBuffer, {std::to_string(index)});
    const fx::TypeDesc& type = parameterInfo()[index].type;
    const std::vector<std::string> what = {parameterInfo()[index].name, type.hlslName()};
    const auto withSize = [&](size_t elementSize) {
        std::vector<std::string> args = what;
        args.push_back(std::to_string(elementSize));
        return args;
    };
    if ((bytes == nullptr && elements > 0) || elements > (size_t(1) << 28) || elementBytes > 65536)
        return refuse(fx::DiagId::SetBufferByteCount, what);
    const size_t total = elements * elementBytes;
    if (type.base == fx::BaseType::Buffer) {
        const std::optional<TexelFormat> texel = bufferTexelFormat(type.templateArgs);
        if (!texel || elementBytes != texel->bytes)
            return refuse(fx::DiagId::SetBufferElementSize, withSize(texel ? texel->bytes : 0));
        buffers[index] = GpuBuffer::create(bytes, total, texel->format);
    } else if (type.base == fx::BaseType::ByteAddressBuffer) {
        if (total % 4 != 0) return refuse(fx::DiagId::SetBufferWholeWords, what);
        buffers[index] = GpuBuffer::create(bytes, total);
    } else if (const fx::StorageBufferBinding* layout = storageLayout(*mCompiled, index)) {
        if (elementBytes != layout->d3dStride)
            return refuse(fx::DiagId::SetBufferPackedElementSize, withSize(layout->d3dStride));
        // From D3D's packing to the GL block's (std430 aligns vectors and pads elements). A buffer with a
        // counter keeps room for its ElementCount (validated at load), where the shaders append.
        auto counter = counters.find(index);
        const size_t room =
            counter == counters.end()
                ? elements
                : std::max(elements, declaredElementCount(parameterInfo()[index], diagnostics).value_or(0));
        std::vector<uint8_t> packed(room * layout->glStride, 0);
        const auto* in = static_cast<const uint8_t*>(bytes);
        for (size_t e = 0; e < elements; ++e)
            for (const fx::StorageBufferBinding::Run& run : layout->runs)
                std::memcpy(packed.data() + e * layout->glStride + run.glOffset,
                            in + e * layout->d3dStride + run.d3dOffset, run.bytes);
        buffers[index] = GpuBuffer::create(packed.data(), packed.size());
        // D3D11's initial count of the view an application binds the elements it filled through: a consume
        // buffer holds them to consume, an append buffer appends after them.
        if (counter != counters.end()) {
            const auto count = static_cast<uint32_t>(elements);
            counter->second = GpuBuffer::create(&count, sizeof count);
        }
    } else {
        buffers[index] = GpuBuffer::create(bytes, total);  // no pass reads it
    }
    targetHistory.clear();  // as for setTexture
    return true;
}

GpuMesh& EffectResources::gpuMesh(const std::shared_ptr<const Mesh>& mesh) {
    auto it = mMeshes.find(mesh.get());
    if (it == mMeshes.end()) it = mMeshes.emplace(mesh.get(), std::make_pair(mesh, GpuMesh(*mesh))).first;
    return it->second.second;
}

void EffectResources::updateSceneCache(const Scene& scene) {
    const uint64_t stamp = sceneStamp(scene);
    if (sceneCache.valid && sceneCache.stamp == stamp) return;
    sceneCache.stamp = stamp;
    sceneCache.valid = true;
    sceneCache.bounds = scene.bounds();
    sceneCache.meshBoxes.clear();
    std::vector<Aabb> boxes(scene.objects.size());
    std::vector<bool> present(scene.objects.size(), false);
    std::map<const Mesh*, uint32_t> slots;
    sceneCache.meshSlots.assign(scene.objects.size(), 0);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.mesh)
            sceneCache.meshSlots[i] =
                slots.emplace(object.mesh.get(), static_cast<uint32_t>(slots.size())).first->second;
        if (!object.mesh || object.mesh->positions.empty()) continue;
        auto it = sceneCache.meshBoxes.find(object.mesh.get());
        if (it == sceneCache.meshBoxes.end())
            it = sceneCache.meshBoxes
                     .emplace(object.mesh.get(), Aabb{object.mesh->boundsMin(), object.mesh->boundsMax()})
                     .first;
        boxes[i] = transformBox(it->second, object.world);
        present[i] = true;
    }
    sceneCache.meshCount = slots.size();
    sceneCache.bvh = InstanceBvh(std::move(boxes), present);
}

uint64_t EffectResources::targetIdentity(int resource) const {
    const GpuTexture* texture = nullptr;
    if (resource == kFrameColor) texture = &frameColor;
    if (resource == kFrameDepth) texture = &frameDepth;
    if (resource >= 0) {
        auto it = textures.find(static_cast<size_t>(resource));
        if (it != textures.end()) texture = &it->second;
    }
    uint64_t h = hashCombine(0, static_cast<uint64_t>(static_cast<int64_t>(resource)));
    if (!texture) return h;
    h = hashCombine(h, texture->id());
    h = hashCombine(h, (uint64_t(uint32_t(texture->width())) << 32) | uint32_t(texture->height()));
    return hashCombine(h, static_cast<uint64_t>(texture->format()));
}

}  // namespace runtime
