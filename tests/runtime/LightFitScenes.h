// LightFitScenes: what the GL-free tests of the light-space parameterizations share
// (test_light_parameterizations.cpp, test_trapezoidal_shadow_map.cpp, test_perspective_shadow_map.cpp):
// a forest-like terrain box, directions by elevation and azimuth, and a finiteness test for matrices.
#pragma once

#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <cmath>

namespace shadowfx::test {

inline constexpr float kLightFitAspect = 4.0f / 3.0f;

// A 200 x 30 x 200 m terrain-like box seen from 2 m above its ground near one edge (forest-like), lit by
// one directional light.
inline runtime::Scene terrain(const glm::vec3& viewDirection, const glm::vec3& lightDirection) {
    runtime::Scene scene;
    scene.name = "terrain";
    scene.explicitBounds = runtime::Bounds{{-100.0f, 0.0f, -100.0f}, {100.0f, 30.0f, 100.0f}};
    scene.camera.position = {0.0f, 2.0f, -80.0f};
    scene.camera.target = scene.camera.position + viewDirection;
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 110.0f;
    runtime::Light light;
    light.direction = glm::normalize(lightDirection);
    scene.lights.push_back(light);
    return scene;
}

// The unit vector `elevationDegrees` above the horizon, `azimuthDegrees` from +z toward +x.
inline glm::vec3 fromAngles(float elevationDegrees, float azimuthDegrees) {
    const float e = glm::radians(elevationDegrees), a = glm::radians(azimuthDegrees);
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

inline bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace shadowfx::test
