// EffectResources: see EffectResources.h.
#include "EffectResources.h"

#include <private/runtime/NameLookups.h>

#include <algorithm>
#include <optional>

namespace runtime {

std::unique_ptr<EffectResources> EffectResources::create(std::shared_ptr<const fx::CompiledEffect> compiled,
                                                         fx::DiagnosticSink& diagnostics) {
    auto resources = std::unique_ptr<EffectResources>(new EffectResources());
    EffectResources& r = *resources;
    r.mCompiled = std::move(compiled);
    const std::vector<fx::ParameterInfo>& parameters = r.parameterInfo();
    r.values = ParameterValues(parameters, r.mCompiled->initialValues);
    for (size_t i = 0; i < parameters.size(); ++i) r.mParameterIndex.emplace(parameters[i].name, i);

    r.binder = std::make_unique<SemanticBinder>(parameters, r.mCompiled->lights);
    for (const fx::CompiledTechnique& technique : r.mCompiled->techniques)
        r.passUses.push_back(runtime::passUses(technique, parameters.size(), *r.binder));

    r.programs = PassPrograms::create(*r.mCompiled, diagnostics);
    if (!r.programs) return nullptr;

    r.samplers = EffectSamplers(*r.mCompiled);
    r.uniformRing = std::make_unique<UniformRing>();  // texture functions draw with it
    r.textures = EffectTextures::create(*r.mCompiled, r.values.all(), *r.uniformRing, diagnostics);
    if (!r.textures) return nullptr;
    r.storage = StorageResources::create(*r.mCompiled);
    r.quad = GpuMesh::makeFullScreenQuad();
    r.annotations = AnnotationTable(*r.mCompiled);
    return resources;
}

const SemanticBinder& EffectResources::fitLights(const Scene& scene, int width, int height) {
    // A fit to what the camera sees finds the samples of this scene at this size, as render() does.
    std::optional<VisibleSamples> visible;
    if (binder->wantsVisibleSamples(values.all()))
        visible = visibleSamplePass.run(
            scene, InstanceBvh{}, width, height,
            [this](const SceneObject& object) -> GpuMesh& { return gpuMesh(object.mesh); });
    fx::DiagnosticList ignored;
    binder->prepare(scene, scene.bounds(), static_cast<float>(width) / static_cast<float>(height),
                    values.all(), values.stamps(), ignored, visible ? &*visible : nullptr);
    return *binder;
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

void EffectResources::setApplicationTexture(size_t parameter, GLuint name, GLenum target) {
    textures->setApplicationTexture(parameter, name, target);
    // What render(Scene) kept in its targets may have been drawn from the texture this replaces.
    targetHistory.clear();
}

bool EffectResources::setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                                fx::DiagnosticSink& diagnostics) {
    if (!storage->set(index, bytes, elements, elementBytes, diagnostics)) return false;
    targetHistory.clear();  // as for setTexture
    return true;
}

GpuMesh& EffectResources::gpuMesh(const std::shared_ptr<const Mesh>& mesh) {
    auto it = mMeshes.find(mesh.get());
    if (it == mMeshes.end()) it = mMeshes.emplace(mesh.get(), std::make_pair(mesh, GpuMesh(*mesh))).first;
    return it->second.second;
}

}  // namespace runtime
