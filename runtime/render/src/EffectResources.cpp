// EffectResources: see EffectResources.h.
#include "EffectResources.h"

#include <private/runtime/NameLookups.h>

#include <algorithm>
#include <bit>
#include <cstring>

namespace runtime {

namespace {

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

std::unique_ptr<EffectResources> EffectResources::create(std::shared_ptr<const fx::CompiledEffect> compiled,
                                                         fx::DiagnosticSink& diagnostics) {
    auto resources = std::unique_ptr<EffectResources>(new EffectResources());
    EffectResources& r = *resources;
    r.mCompiled = std::move(compiled);
    const std::vector<fx::ParameterInfo>& parameters = r.parameterInfo();
    r.values = ParameterValues(parameters, r.mCompiled->initialValues);
    for (size_t i = 0; i < parameters.size(); ++i) r.mParameterIndex.emplace(parameters[i].name, i);

    r.binder = std::make_unique<SemanticBinder>(parameters);
    r.scriptOperands = std::make_unique<ScriptOperands>(
        *r.mCompiled, [&r](std::string_view name) { return r.findParameter(name); },
        [&r](std::string_view light) { return r.binder->lightSlot(light); });
    for (const fx::CompiledTechnique& technique : r.mCompiled->techniques)
        r.passUses.push_back(runtime::passUses(technique, parameters.size(), *r.binder));

    r.programs = PassPrograms::create(*r.mCompiled, diagnostics);
    if (!r.programs) return nullptr;

    for (const fx::SamplerDesc& desc : r.mCompiled->samplers) {
        r.samplers.emplace(desc.parameter, SamplerObject(desc, false));
        r.comparisonSamplers.emplace(desc.parameter, SamplerObject(desc, true));
    }
    for (const fx::SamplerDesc& desc : r.mCompiled->passSamplers) {
        r.passSamplers.emplace_back(desc, false);
        r.passComparisonSamplers.emplace_back(desc, true);
    }
    r.uniformRing = std::make_unique<UniformRing>();  // texture functions draw with it
    r.textures = EffectTextures::create(*r.mCompiled, r.values.all(), *r.uniformRing, diagnostics);
    if (!r.textures || !r.createDefaultBuffers(diagnostics) || !r.createImages(diagnostics)) return nullptr;
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

bool EffectResources::setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics) {
    if (!textures->set(index, data, diagnostics)) return false;
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

}  // namespace runtime
