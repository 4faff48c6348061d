// The tangent frame every mesh generator gives its vertices (Mesh.cpp's shapes, Teapot.cpp's teapot).
#pragma once

#include <glm/glm.hpp>

namespace runtime {

// Tangent with handedness, as effects expect it: xyz = direction of increasing u, w = sign such that
// w * cross(N, T) is the direction of increasing v (D3DX's convention for TANGENT / BINORMAL).
glm::vec4 tangentFrame(const glm::vec3& normal, const glm::vec3& dPdu, const glm::vec3& dPdv);

}  // namespace runtime
