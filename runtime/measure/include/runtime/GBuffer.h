// GBuffer: what the scene's camera sees, per pixel, in world space: the surface position, its normal and
// which object it belongs to. The ground truth (runtime/GroundTruth.h) casts its shadow rays from these
// points and the metrics (runtime/ShadowMetrics.h) choose their receiver pixels with them.
//
// Rendered through the runtime itself (a small built-in effect, runtime/measure/src/GBuffer.cpp) with the
// same camera matrices, rasterizer and D3D culling an effect's final pass uses, so its pixels are the pixels
// of the effect's frame.
#pragma once

#include <fx/Diagnostics.h>
#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace runtime {

struct GBuffer {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> position;  // world space; rows top to bottom
    std::vector<glm::vec3> normal;    // world space, normalized (the interpolated shading normal)
    std::vector<uint32_t> objectId;   // 0 = background, else index into Scene::objects + 1

    size_t index(int x, int y) const { return static_cast<size_t>(y) * static_cast<size_t>(width) + x; }
    size_t pixelCount() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
    bool covered(size_t i) const { return objectId[i] != 0; }
};

// Renders the G-buffer of `scene`'s camera at width x height. Needs a current GL context (GlContext.h).
// nullopt (with diagnostics) if the built-in effect fails to compile or render.
std::optional<GBuffer> renderGBuffer(const Scene& scene, int width, int height,
                                     fx::DiagnosticSink& diagnostics);

}  // namespace runtime
