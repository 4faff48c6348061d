// RayCastModule: what libshadowfx_raycast.so (runtime/measure/module/) offers GroundTruth.cpp, which opens it
// when the first ShadowRayCaster is made (runtime/RuntimeModules.h). Built by this build tree beside the
// library that opens it, so the two share one compiler and one standard library: the table passes C++ types.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace runtime {

// One object's shadow-casting triangles, positions already in world space.
struct CasterTriangles {
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
    // A robust, high-quality BVH over every object's triangles; nullptr with `error` set when Embree fails.
    RayCastBvh* (*build)(const CasterTriangles* objects, size_t objectCount, std::string& error);
    void (*release)(RayCastBvh* bvh);
    // True if the ray hits a triangle (one Embree ray). Safe from many threads at once.
    bool (*occluded)(const RayCastBvh* bvh, const ShadowRay& ray);
    // Up to 16 rays as one Embree packet; occluded[k] for rays[k]. Safe from many threads at once.
    void (*occluded16)(const RayCastBvh* bvh, const ShadowRay* rays, int count, bool* occluded);
};

// The module's entry point, extern "C": raise the version with any change to RayCastModule, so that a
// module of another version is refused by name rather than called wrongly.
using RayCastModuleEntry = const RayCastModule* (*)();
inline constexpr const char* kRayCastModuleEntry = "shadowfx_raycast_v1";

}  // namespace runtime
