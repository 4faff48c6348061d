// Shape generators the seeds' scenes need beyond Mesh.cpp's: cylinder and cone (the trees of Scherzer 2005's
// forest), a height field (its terrain), and appendMesh (a tree = trunk + crown, one mesh).
//
// Winding as in Mesh.cpp: each triangle is oriented so that cross(b - a, c - a) agrees with its vertices'
// normals, which is D3D's clockwise front face in a left-handed world (see Mesh.h).
#include <runtime/Mesh.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace runtime {

namespace {

uint32_t addVertex(Mesh& mesh, const glm::vec3& position, const glm::vec3& normal,
                   const glm::vec2& texcoord) {
    mesh.positions.push_back(position);
    mesh.normals.push_back(normal);
    mesh.texcoords.push_back(texcoord);
    return static_cast<uint32_t>(mesh.positions.size() - 1);
}

void addTriangle(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
    const auto& p = mesh.positions;
    const auto& n = mesh.normals;
    if (glm::dot(glm::cross(p[b] - p[a], p[c] - p[a]), n[a] + n[b] + n[c]) < 0.0f) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// A surface of revolution about +y from `bottomRadius` at y = -height/2 to `topRadius` at +height/2, with a
// flat cap wherever the radius is not zero. Side and caps have their own vertices (hard edges), so the mesh
// is watertight in positions but not in vertex indices.
Mesh makeFrustum(std::string name, float bottomRadius, float topRadius, float height, int slices) {
    slices = std::max(slices, 3);
    Mesh mesh;
    mesh.name = std::move(name);
    const float twoPi = 2.0f * glm::pi<float>();
    const float y0 = -0.5f * height, y1 = 0.5f * height;
    // Side normal of a cone: perpendicular to the slant line (radius falls by bottom - top over height).
    const float slope = (bottomRadius - topRadius) / std::max(height, 1e-6f);
    for (int j = 0; j <= slices; ++j) {
        const float phi = twoPi * float(j) / float(slices);
        const glm::vec3 radial(std::cos(phi), 0.0f, std::sin(phi));
        const glm::vec3 n = glm::normalize(radial + glm::vec3(0.0f, slope, 0.0f));
        const float u = float(j) / float(slices);
        addVertex(mesh, radial * bottomRadius + glm::vec3(0, y0, 0), n, {u, 1.0f});
        addVertex(mesh, radial * topRadius + glm::vec3(0, y1, 0), n, {u, 0.0f});
    }
    for (int j = 0; j < slices; ++j) {
        const uint32_t a = 2 * j, b = a + 1, c = a + 3, d = a + 2;
        if (topRadius <= 0.0f) {
            addTriangle(mesh, a, b, d);  // apex on top: one triangle per slice, not a degenerate quad
        } else if (bottomRadius <= 0.0f) {
            addTriangle(mesh, a, b, c);  // apex at the bottom
        } else {
            addTriangle(mesh, a, b, c);
            addTriangle(mesh, a, c, d);
        }
    }
    for (int cap = 0; cap < 2; ++cap) {
        const float radius = cap == 0 ? bottomRadius : topRadius;
        if (radius <= 0.0f) continue;
        const float y = cap == 0 ? y0 : y1;
        const glm::vec3 n(0.0f, cap == 0 ? -1.0f : 1.0f, 0.0f);
        const uint32_t centre = addVertex(mesh, {0.0f, y, 0.0f}, n, {0.5f, 0.5f});
        for (int j = 0; j <= slices; ++j) {
            const float phi = twoPi * float(j) / float(slices);
            addVertex(mesh, {radius * std::cos(phi), y, radius * std::sin(phi)}, n,
                      {0.5f + 0.5f * std::cos(phi), 0.5f + 0.5f * std::sin(phi)});
        }
        for (int j = 0; j < slices; ++j) addTriangle(mesh, centre, centre + 1 + j, centre + 2 + j);
    }
    mesh.closed = true;
    return mesh;
}

}  // namespace

Mesh makeCylinder(float radius, float height, int slices) {
    return makeFrustum("cylinder", radius, radius, height, slices);
}

Mesh makeCone(float radius, float height, int slices) {
    return makeFrustum("cone", radius, 0.0f, height, slices);
}

Mesh makeHeightField(float sizeX, float sizeZ, int divisions, float (*height)(float x, float z)) {
    divisions = std::max(divisions, 1);
    Mesh mesh;
    mesh.name = "heightfield";
    const int row = divisions + 1;
    const float dx = sizeX / float(divisions), dz = sizeZ / float(divisions);
    for (int iz = 0; iz <= divisions; ++iz) {
        for (int ix = 0; ix <= divisions; ++ix) {
            const float s = float(ix) / float(divisions), t = float(iz) / float(divisions);
            const float x = (s - 0.5f) * sizeX, z = (0.5f - t) * sizeZ;  // row 0 at +z, as makePlane
            // Normal from central differences of the height function: (-dh/dx, 1, -dh/dz).
            const float hx = (height(x + dx, z) - height(x - dx, z)) / (2.0f * dx);
            const float hz = (height(x, z + dz) - height(x, z - dz)) / (2.0f * dz);
            addVertex(mesh, {x, height(x, z), z}, glm::normalize(glm::vec3(-hx, 1.0f, -hz)), {s, t});
        }
    }
    for (int iz = 0; iz < divisions; ++iz) {
        for (int ix = 0; ix < divisions; ++ix) {
            const uint32_t a = iz * row + ix;
            addTriangle(mesh, a, a + 1, a + 1 + row);
            addTriangle(mesh, a, a + 1 + row, a + row);
        }
    }
    return mesh;
}

void appendMesh(Mesh& mesh, const Mesh& other, const glm::vec3& offset) {
    const bool wasEmpty = mesh.positions.empty();
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    // An attribute survives only if both meshes have it: a half-filled array would misalign the vertices.
    auto merge = [&](auto& mine, const auto& theirs) {
        if ((wasEmpty || !mine.empty()) && !theirs.empty()) {
            mine.insert(mine.end(), theirs.begin(), theirs.end());
        } else {
            mine.clear();
        }
    };
    merge(mesh.normals, other.normals);
    merge(mesh.texcoords, other.texcoords);
    merge(mesh.tangents, other.tangents);
    for (const auto& p : other.positions) mesh.positions.push_back(p + offset);
    for (uint32_t index : other.indices) mesh.indices.push_back(base + index);
    // A union of closed parts is closed as far as back-face methods care: every ray enters and leaves.
    mesh.closed = (wasEmpty || mesh.closed) && other.closed;
}

}  // namespace runtime
