// GroundTruth: exact per-pixel light visibility of a scene, by casting shadow rays with Embree from the
// surface points of a G-buffer (runtime/GBuffer.h) towards the light — independent of any shadow map.
//
// Hard shadows (Light::areaRadius == 0): one ray per pixel; directional lights along -direction,
// spot/point lights to the light's position. Area lights (areaRadius > 0): the visible fraction of a disk
// of that radius facing the receiver, from stratified samples (the count is recorded, so the reference's
// own noise is known: its standard error is at most 0.5 / sqrt(samples)).
#pragma once

#include <runtime/GBuffer.h>
#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace runtime {

// What compute() returns for given inputs, versioned: raise it with any change to the rays, the sampling or
// the offsets, and every cached truth of an older version (runtime/TruthCache.h) is cast again.
constexpr uint32_t kGroundTruthVersion = 2;

struct GroundTruthOptions {
    // Samples per pixel for area lights, rounded to a square (stratified sqrt x sqrt grid, jittered).
    int areaSamples = 256;
    // Ray origins start this far off the receiver's plane (on the light's side), as a fraction of the
    // scene's bounding radius, reached along the ray so that no shadow edge moves (EmbreeRayCaster.cpp).
    // The G-buffer's positions are rasterizer-interpolated float32 points on their triangles, so their
    // distance from the triangle's plane is ~1e-7 of the coordinates; 1e-4 of the radius is far above that
    // and far below any feature of the scenes (a 10-unit scene: 1 mm).
    float normalOffset = 1e-4f;
    int threads = 0;  // 0 = std::thread::hardware_concurrency()
};

struct GroundTruth {
    int width = 0;
    int height = 0;
    // Per pixel: 1 lit, 0 shadowed, fractions in between for area lights; -1 for background pixels.
    std::vector<float> visibility;
    int samplesPerPixel = 1;  // 1 for hard shadows
    bool soft = false;        // area light
    uint64_t raysCast = 0;
};

// The shadow-casting triangles of a scene in world space, in an Embree BVH: one triangle geometry per
// object with SceneObject::castsShadow. Build once per scene, query from many threads. Embree lives in the
// module libshadowfx_raycast.so, opened by the first caster (runtime/RuntimeModules.h): constructing one
// throws ModuleLoadError when the module cannot be opened.
class ShadowRayCaster {
public:
    explicit ShadowRayCaster(const Scene& scene);
    ~ShadowRayCaster();
    ShadowRayCaster(const ShadowRayCaster&) = delete;
    ShadowRayCaster& operator=(const ShadowRayCaster&) = delete;

    // True if the segment from + t * dir, t in (0, tMax), hits a shadow caster.
    bool occluded(const glm::vec3& from, const glm::vec3& dir, float tMax) const;

    // Visibility of `light` at every covered pixel of `gbuffer`.
    GroundTruth compute(const GBuffer& gbuffer, const Light& light,
                        const GroundTruthOptions& options = {}) const;

    struct Impl;

private:
    std::unique_ptr<Impl> mImpl;
};

}  // namespace runtime
