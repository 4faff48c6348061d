// EffectResources: see EffectResources.h.
#include "EffectResources.h"

#include <runtime/Image.h>
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

// White: the neutral value for textures the effect multiplies with.
GpuTexture makeNeutralTexture(fx::BaseType type) {
    const uint8_t white[4] = {255, 255, 255, 255};
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

const char* textureFileKindName(TextureFile::Kind kind) {
    return kind == TextureFile::Kind::Cube ? "cube" : kind == TextureFile::Kind::Volume ? "volume" : "2D";
}

// A DDS file's texture, when its kind is what the effect samples: every level the file has (a cube's
// smaller levels regenerated), float storage so that no file format loses range. nullopt on a mismatch.
std::optional<GpuTexture> makeFileTexture(const TextureFile& file, const fx::TextureDesc& desc) {
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
        const size_t face = static_cast<size_t>(file.width) * static_cast<size_t>(file.height) * 4;
        for (int f = 0; f < 6; ++f)
            texture.uploadRGBA32F(file.levels[0].data() + face * static_cast<size_t>(f), 0, f);
        texture.generateMipmaps();
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

    bool ok = true;
    for (const fx::CompiledTechnique& technique : r.mCompiled->techniques) {
        auto& passes = r.programs.emplace_back();
        auto& preshaders = r.preshaders.emplace_back();
        for (const fx::CompiledPass& pass : technique.passes) {
            std::unique_ptr<GpuProgram> program = GpuProgram::create(pass, diagnostics);
            ok = ok && program != nullptr;
            // D3D10's DepthBiasClamp needs glPolygonOffsetClamp; without it the bias is applied unbounded.
            for (const fx::RenderStateSetting& setting : pass.states)
                if (setting.id == fx::RenderStateId::DepthBiasClamp && !gl::PolygonOffsetClamp &&
                    !(setting.constant && *setting.constant == 0.0))
                    diagnostics.report(fx::Diagnostic{
                        fx::DiagId::UnsupportedFeature, fx::Severity::Warning, setting.loc,
                        "DepthBiasClamp is not applied: this OpenGL has no glPolygonOffsetClamp (GL 4.6 or "
                        "ARB_polygon_offset_clamp); the depth bias is unbounded"});
            passes.push_back(std::move(program));
            preshaders.emplace_back(pass);
        }
    }
    if (!ok) return nullptr;

    for (const fx::SamplerDesc& desc : r.mCompiled->samplers) {
        r.samplers.emplace(desc.parameter, SamplerObject(desc, false));
        r.comparisonSamplers.emplace(desc.parameter, SamplerObject(desc, true));
    }
    if (!r.createFileTextures(diagnostics)) return nullptr;
    r.quad = GpuMesh::makeFullScreenQuad();
    r.uniformRing = std::make_unique<UniformRing>();
    return resources;
}

std::optional<size_t> EffectResources::findParameter(std::string_view name) const {
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
        if (isRenderTarget(desc)) continue;
        const bool cube = desc.type == fx::BaseType::TextureCube;
        const std::string& semantic = parameterInfo()[desc.parameter].semantic;
        if (desc.kind == fx::TextureDesc::Kind::Runtime && fx::equalsIgnoreCase(semantic, "noise") && !cube) {
            textures[desc.parameter] = makeNoiseTexture();
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
                    "texture file '" + desc.resourceName + "' holds a " + textureFileKindName(file->kind) +
                        " texture, but the effect samples it as a " +
                        (cube                                   ? "cube"
                         : desc.type == fx::BaseType::Texture3D ? "volume"
                                                                : "2D") +
                        " texture; using a neutral texture"});
                textures[desc.parameter] = makeNeutralTexture(desc.type);
                continue;
            }
            texture->setLabel(parameterInfo()[desc.parameter].name);
            textures[desc.parameter] = std::move(*texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() && !cube &&
            desc.type != fx::BaseType::Texture3D) {
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
        textures[desc.parameter] = makeNeutralTexture(desc.type);
    }
    return true;
}

void EffectResources::ensureFrameResources(int width, int height, const std::set<int>* needed) {
    if (frameColor.width() != width || frameColor.height() != height) {
        if (frameColor) framebuffers.evict(frameColor);
        if (frameDepth) framebuffers.evict(frameDepth);
        frameColor = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        frameDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    for (const fx::TextureDesc& desc : mCompiled->textures) {
        if (!isRenderTarget(desc)) continue;
        const glm::ivec2 size = renderTargetSize(desc, width, height);
        const int w = size.x, h = size.y;
        auto it = textures.find(desc.parameter);
        if (it == textures.end() && needed && !needed->count(static_cast<int>(desc.parameter))) continue;
        if (it != textures.end() && it->second.width() == w && it->second.height() == h) continue;
        if (it != textures.end()) framebuffers.evict(it->second);
        GpuTexture texture = desc.type == fx::BaseType::TextureCube
                                 ? GpuTexture::createCube(desc.format, w, desc.mipLevels)
                                 : GpuTexture::create2D(desc.format, w, h, desc.mipLevels);
        texture.setLabel(parameterInfo()[desc.parameter].name);
        textures[desc.parameter] = std::move(texture);
    }
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
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (!object.mesh || object.mesh->positions.empty()) continue;
        auto it = sceneCache.meshBoxes.find(object.mesh.get());
        if (it == sceneCache.meshBoxes.end())
            it = sceneCache.meshBoxes
                     .emplace(object.mesh.get(), Aabb{object.mesh->boundsMin(), object.mesh->boundsMax()})
                     .first;
        boxes[i] = transformBox(it->second, object.world);
        present[i] = true;
    }
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
