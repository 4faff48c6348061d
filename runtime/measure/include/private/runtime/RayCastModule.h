// RayCastModule: what libshadowfx_raycast.so (runtime/measure/module/) offers GroundTruth.cpp, which opens it
// when the first ShadowRayCaster is made (runtime/RuntimeModules.h). Built by this build tree beside the
// library that opens it, so the two share one compiler and one standard library: the table passes C++ types
// (only those whose members it uses are defined in headers: GBuffer, Light, GroundTruth and its options).
#pragma once

#include <runtime/GroundTruth.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace runtime {

// One object's shadow-casting triangles, in object space, and where the object stands.
struct CasterTriangles {
    glm::mat4 world{1.0f};
    const glm::vec3* positions = nullptr;
    size_t positionCount = 0;
    const uint32_t* indices = nullptr;  // three per triangle
    size_t triangleCount = 0;
};

// A segment from origin + t * direction, t in (0, tMax).
struct ShadowRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float tMax;
};

struct RayCastBvh;  // the module's own: an Embree device and scene

struct RayCastModule {
    // A robust, high-quality BVH over every object's triangles in world space; nullptr with `error` set when
    // Embree fails.
    RayCastBvh* (*build)(const CasterTriangles* objects, size_t objectCount, std::string& error);
    void (*release)(RayCastBvh* bvh);
    // True if the ray hits a triangle. Safe from many threads at once.
    bool (*occluded)(const RayCastBvh* bvh, const ShadowRay& ray);
    // ShadowRayCaster::compute (GroundTruth.h), the scene's bounds given: the rays never leave the module.
    GroundTruth (*compute)(const RayCastBvh* bvh, const GBuffer& gbuffer, const Light& light,
                           const GroundTruthOptions& options, float sceneRadius,
                           const glm::vec3& sceneCenter);
};

// The module's entry point, extern "C": raise the version with any change to RayCastModule, so that a
// module of another version is refused by name rather than called wrongly.
using RayCastModuleEntry = const RayCastModule* (*)();
inline constexpr const char* kRayCastModuleEntry = "shadowfx_raycast_v1";

}  // namespace runtime
