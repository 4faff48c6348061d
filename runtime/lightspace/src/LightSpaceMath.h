// LightSpaceMath: the small pieces of light-space geometry the parameterization providers share
// (LightParameterization.cpp, TrapezoidalShadowMap.cpp, CascadedShadowMaps.cpp).
#pragma once

#include <runtime/Scene.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

// A unit vector perpendicular to `direction`, the same for every direction close to it: a light view's
// "up" where the view direction gives none (the light parallel to the view), or where it must not turn
// with the camera (the cascades' shared light view: every texel would move).
inline glm::vec3 fixedPerpendicular(const glm::vec3& direction) {
    const glm::vec3 axis =
        std::abs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(axis - glm::dot(axis, direction) * direction);
}

// The light view of the focused fits: looking along `lightDir` at the bounds' centre from outside them, its
// y axis along V_P = `viewDir` made perpendicular to the light (Scherzer 2005 eq. 3), so that warps along y run
// from the viewer's side of B to its far side. sinGamma = |V_P| before normalizing: sin of the angle
// between light and view, 0 when they are parallel (then y is fixedPerpendicular's).
struct AlignedLightView {
    glm::mat4 view{1.0f};
    float sinGamma = 0.0f;
};
inline AlignedLightView lightViewAcrossView(const glm::vec3& lightDir, const glm::vec3& viewDir,
                                            const Bounds& bounds) {
    const glm::vec3 across = viewDir - glm::dot(viewDir, lightDir) * lightDir;
    AlignedLightView aligned;
    aligned.sinGamma = glm::length(across);
    const glm::vec3 up = aligned.sinGamma > 1e-4f ? across / aligned.sinGamma : fixedPerpendicular(lightDir);
    const glm::vec3 centre = bounds.center();
    const float radius = std::max(bounds.radius(), 1e-3f);
    aligned.view = glm::lookAtLH(centre - lightDir * (2.0f * radius), centre, up);
    return aligned;
}

// How far from `point` along `direction` the ray leaves the box (0 if it starts outside).
inline float exitDistance(const glm::vec3& point, const glm::vec3& direction, const Bounds& box) {
    float exit = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-12f) continue;
        const float wall = direction[axis] > 0.0f ? box.max[axis] : box.min[axis];
        exit = std::min(exit, (wall - point[axis]) / direction[axis]);
    }
    return exit == std::numeric_limits<float>::max() ? 0.0f : std::max(exit, 0.0f);
}

// The map from the box [lo, hi] (NDC after a provider's own transform) to D3D's clip cube: x, y to
// [-1, 1], depth to [0, 1].
inline glm::mat4 unitCubeFit(const glm::vec3& lo, const glm::vec3& hi) {
    glm::mat4 unitCube(1.0f);  // glm: unitCube[column][row]
    unitCube[0][0] = 2.0f / (hi.x - lo.x);
    unitCube[1][1] = 2.0f / (hi.y - lo.y);
    unitCube[2][2] = 1.0f / (hi.z - lo.z);
    unitCube[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    unitCube[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    unitCube[3][2] = -lo.z / (hi.z - lo.z);
    return unitCube;
}

inline bool isFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace runtime
