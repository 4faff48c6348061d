// GroundTruth: the ray caster's shell. Embree, the BVH and the loop that casts the rays live in the ray-cast
// module (RayCastModule.h), opened when the first caster is made, so only programs that cast truth load
// Embree.
#include <runtime/GroundTruth.h>
#include <runtime/RuntimeModules.h>

#include <private/runtime/RayCastModule.h>

#include <algorithm>
#include <stdexcept>

namespace runtime {

namespace {

// Opened with the first caster, and kept: a failed open is tried again by the next one.
const RayCastModule& rayCastModule() {
    static const RayCastModule* module = reinterpret_cast<RayCastModuleEntry>(
        openModuleEntry("raycast", "ground-truth ray casting (Embree)", kRayCastModuleEntry))();
    return *module;
}

}  // namespace

struct ShadowRayCaster::Impl {
    const RayCastModule& module = rayCastModule();
    RayCastBvh* bvh = nullptr;
    float sceneRadius = 1.0f;
    glm::vec3 sceneCenter{0.0f};

    ~Impl() {
        if (bvh) module.release(bvh);
    }
};

ShadowRayCaster::ShadowRayCaster(const Scene& scene) : mImpl(std::make_unique<Impl>()) {
    const Bounds bounds = scene.bounds();
    mImpl->sceneRadius = std::max(bounds.radius(), 1e-3f);
    mImpl->sceneCenter = bounds.center();
    std::vector<CasterTriangles> objects;
    for (const SceneObject& object : scene.objects) {
        if (!object.castsShadow || !object.mesh || object.mesh->triangleCount() == 0) continue;
        const Mesh& mesh = *object.mesh;
        objects.push_back({object.world, mesh.positions.data(), mesh.positions.size(), mesh.indices.data(),
                           mesh.triangleCount()});
    }
    std::string error;
    mImpl->bvh = mImpl->module.build(objects.data(), objects.size(), error);
    if (!mImpl->bvh) throw std::runtime_error(error);
}

ShadowRayCaster::~ShadowRayCaster() = default;

bool ShadowRayCaster::occluded(const glm::vec3& from, const glm::vec3& dir, float tMax) const {
    return mImpl->module.occluded(mImpl->bvh, ShadowRay{from, dir, tMax});
}

GroundTruth ShadowRayCaster::compute(const GBuffer& gbuffer, const Light& light,
                                     const GroundTruthOptions& options) const {
    return mImpl->module.compute(mImpl->bvh, gbuffer, light, options, mImpl->sceneRadius, mImpl->sceneCenter);
}

}  // namespace runtime
