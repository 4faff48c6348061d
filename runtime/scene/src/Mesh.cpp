// Mesh generators (plane, box, sphere, torus) and mesh bounds. The teapot lives in Teapot.cpp.
//
// Winding: D3D's front faces are clockwise on screen. In a left-handed world that means a triangle (a, b, c)
// is front-facing from the side cross(b - a, c - a) points to, so every generator winds its triangles so
// that this cross product points outward. Rather than hand-deriving the vertex order of every quad (easy to
// get wrong once per shape), MeshBuilder::addTriangle orients each triangle against the analytic vertex
// normals: a generator only says which vertices form a face.
#include <runtime/Mesh.h>

#include "TangentFrame.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

glm::vec4 tangentFrame(const glm::vec3& normal, const glm::vec3& dPdu, const glm::vec3& dPdv) {
    glm::vec3 t = dPdu - normal * glm::dot(normal, dPdu);  // Gram-Schmidt: keep it in the tangent plane
    if (glm::dot(t, t) < 1e-12f) {
        // Degenerate u direction (a pole): any vector perpendicular to the normal keeps shading defined.
        t = std::abs(normal.y) < 0.9f ? glm::cross(glm::vec3(0, 1, 0), normal) : glm::vec3(1, 0, 0);
    }
    t = glm::normalize(t);
    float w = glm::dot(glm::cross(normal, t), dPdv) < 0.0f ? -1.0f : 1.0f;
    return glm::vec4(t, w);
}

namespace {

class MeshBuilder {
public:
    explicit MeshBuilder(std::string name) { mMesh.name = std::move(name); }

    uint32_t addVertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& texcoord,
                       const glm::vec3& dPdu, const glm::vec3& dPdv) {
        mMesh.positions.push_back(position);
        mMesh.normals.push_back(normal);
        mMesh.texcoords.push_back(texcoord);
        mMesh.tangents.push_back(tangentFrame(normal, dPdu, dPdv));
        return static_cast<uint32_t>(mMesh.positions.size() - 1);
    }

    // Emits (a, b, c) or (a, c, b), whichever makes cross(b - a, c - a) agree with the vertex normals.
    void addTriangle(uint32_t a, uint32_t b, uint32_t c) {
        const auto& p = mMesh.positions;
        const auto& n = mMesh.normals;
        glm::vec3 winding = glm::cross(p[b] - p[a], p[c] - p[a]);
        if (glm::dot(winding, n[a] + n[b] + n[c]) < 0.0f) std::swap(b, c);
        mMesh.indices.insert(mMesh.indices.end(), {a, b, c});
    }

    // A quad given by its corners in cyclic order, split along the a-c diagonal.
    void addQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        addTriangle(a, b, c);
        addTriangle(a, c, d);
    }

    Mesh take(bool closed) {
        mMesh.closed = closed;
        return std::move(mMesh);
    }

private:
    Mesh mMesh;
};

}  // namespace

glm::vec3 Mesh::boundsMin() const {
    if (positions.empty()) return glm::vec3(0.0f);
    glm::vec3 result(std::numeric_limits<float>::max());
    for (const auto& p : positions) result = glm::min(result, p);
    return result;
}

glm::vec3 Mesh::boundsMax() const {
    if (positions.empty()) return glm::vec3(0.0f);
    glm::vec3 result(std::numeric_limits<float>::lowest());
    for (const auto& p : positions) result = glm::max(result, p);
    return result;
}

// Row 0 of the grid is the far edge (+z): seen from above with +z at the top of the image, texcoord (0,0)
// is then the top-left corner, as D3D samples it. 2 * divisions^2 triangles.
Mesh makePlane(float sizeX, float sizeZ, int divisions) {
    divisions = std::max(divisions, 1);
    MeshBuilder builder("plane");
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    for (int iz = 0; iz <= divisions; ++iz) {
        for (int ix = 0; ix <= divisions; ++ix) {
            float s = float(ix) / float(divisions);
            float t = float(iz) / float(divisions);
            glm::vec3 p((s - 0.5f) * sizeX, 0.0f, (0.5f - t) * sizeZ);
            builder.addVertex(p, up, glm::vec2(s, t), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1));
        }
    }
    const int row = divisions + 1;
    for (int iz = 0; iz < divisions; ++iz) {
        for (int ix = 0; ix < divisions; ++ix) {
            uint32_t a = iz * row + ix;
            builder.addQuad(a, a + 1, a + 1 + row, a + row);
        }
    }
    return builder.take(false);
}

// 24 vertices (4 per face, so each face has its own normal and texture), 12 triangles. Each face's texture
// is upright as seen from outside: u to the viewer's right, v down.
Mesh makeBox(glm::vec3 size) {
    MeshBuilder builder("box");
    const glm::vec3 half = size * 0.5f;
    struct Face {
        glm::vec3 normal, right, down;
    };
    // right = cross(viewUp, viewDirection) in a left-handed system, the viewer looking along -normal.
    const Face faces[6] = {
        {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}},  {{-1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
        {{0, 0, 1}, {-1, 0, 0}, {0, -1, 0}}, {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {-1, 0, 0}, {0, 0, -1}},
    };
    for (const Face& face : faces) {
        uint32_t first = 0;
        for (int corner = 0; corner < 4; ++corner) {
            // Corners in cyclic order: (0,0) (1,0) (1,1) (0,1) in texture space.
            float s = (corner == 1 || corner == 2) ? 1.0f : 0.0f;
            float t = (corner >= 2) ? 1.0f : 0.0f;
            glm::vec3 p =
                (face.normal + face.right * (2.0f * s - 1.0f) + face.down * (2.0f * t - 1.0f)) * half;
            uint32_t index = builder.addVertex(p, face.normal, glm::vec2(s, t), face.right, face.down);
            if (corner == 0) first = index;
        }
        builder.addQuad(first, first + 1, first + 2, first + 3);
    }
    return builder.take(true);
}

// Latitude-longitude sphere: (stacks + 1) rows of (slices + 1) vertices (the seam column is duplicated so
// texcoords wrap; the pole rows are duplicated per slice so each pole triangle gets its own u). The pole
// stacks have one triangle per slice instead of a degenerate quad: 2 * slices * (stacks - 1) triangles.
Mesh makeSphere(float radius, int slices, int stacks) {
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    MeshBuilder builder("sphere");
    const float pi = glm::pi<float>();
    for (int i = 0; i <= stacks; ++i) {
        float theta = pi * float(i) / float(stacks);  // 0 at the north pole (+y): v = 0 at the top
        for (int j = 0; j <= slices; ++j) {
            float phi = 2.0f * pi * float(j) / float(slices);
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            if (i == 0 || i == stacks) n = glm::vec3(0.0f, std::cos(theta) > 0.0f ? 1.0f : -1.0f, 0.0f);
            // dP/dphi without its sin(theta) factor so that it stays defined at the poles.
            glm::vec3 dPdu(-std::sin(phi), 0.0f, std::cos(phi));
            glm::vec3 dPdv(std::cos(theta) * std::cos(phi), -std::sin(theta),
                           std::cos(theta) * std::sin(phi));
            builder.addVertex(n * radius, n, glm::vec2(float(j) / float(slices), float(i) / float(stacks)),
                              dPdu, dPdv);
        }
    }
    const int row = slices + 1;
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            uint32_t a = i * row + j, b = a + 1, c = a + row + 1, d = a + row;
            if (i == 0) {
                builder.addTriangle(a, c, d);
            } else if (i == stacks - 1) {
                builder.addTriangle(a, b, d);
            } else {
                builder.addQuad(a, b, c, d);
            }
        }
    }
    return builder.take(true);
}

// Torus around the y axis (lying in the xz plane): (majorSegments + 1) x (minorSegments + 1) vertices with
// duplicated seams, 2 * majorSegments * minorSegments triangles. u runs around the y axis, v around the tube.
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
    majorSegments = std::max(majorSegments, 3);
    minorSegments = std::max(minorSegments, 3);
    MeshBuilder builder("torus");
    const float twoPi = 2.0f * glm::pi<float>();
    for (int i = 0; i <= minorSegments; ++i) {
        float phi = twoPi * float(i) / float(minorSegments);
        for (int j = 0; j <= majorSegments; ++j) {
            float theta = twoPi * float(j) / float(majorSegments);
            glm::vec3 radial(std::cos(theta), 0.0f, std::sin(theta));
            glm::vec3 n = radial * std::cos(phi) + glm::vec3(0.0f, std::sin(phi), 0.0f);
            glm::vec3 p = radial * majorRadius + n * minorRadius;
            glm::vec3 dPdu(-std::sin(theta), 0.0f, std::cos(theta));
            glm::vec3 dPdv = -radial * std::sin(phi) + glm::vec3(0.0f, std::cos(phi), 0.0f);
            builder.addVertex(p, n,
                              glm::vec2(float(j) / float(majorSegments), float(i) / float(minorSegments)),
                              dPdu, dPdv);
        }
    }
    const int row = majorSegments + 1;
    for (int i = 0; i < minorSegments; ++i) {
        for (int j = 0; j < majorSegments; ++j) {
            uint32_t a = i * row + j;
            builder.addQuad(a, a + 1, a + 1 + row, a + row);
        }
    }
    return builder.take(true);
}

}  // namespace runtime
