// Mesh: triangle geometry on the CPU, with the vertex attributes effects bind by semantic.
//
// Conventions (D3D's, so effects written for D3D run unmodified): left-handed world space with +y up;
// a triangle's front face is the one whose vertices appear *clockwise* when seen from the side its normal
// points to (D3D9's default CullMode = CCW culls the others).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace runtime {

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // empty or one per position
    std::vector<glm::vec2> texcoords;  // empty or one per position (TEXCOORD0)
    std::vector<glm::vec4> tangents;   // empty or one per position (TANGENT; w = handedness)
    std::vector<uint32_t> indices;     // triangle list
    bool closed = false;               // watertight: back-face shadow methods may rely on it

    size_t triangleCount() const { return indices.size() / 3; }
    glm::vec3 boundsMin() const;
    glm::vec3 boundsMax() const;
};

// Generators. Sizes are full extents; every shape is centred on the origin.
Mesh makePlane(float sizeX, float sizeZ, int divisions = 1);      // y = 0, facing +y, not closed
Mesh makeBox(glm::vec3 size);                                     // closed
Mesh makeSphere(float radius, int slices = 32, int stacks = 16);  // closed
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments = 48,
               int minorSegments = 24);             // closed, in the xz plane
Mesh makeTeapot(float size, int tessellation = 8);  // Newell's teapot from its Bezier patches; not closed
// In ShapeGenerators.cpp: capped cylinder and cone along +y (centred like the rest), closed.
Mesh makeCylinder(float radius, float height, int slices = 16);
Mesh makeCone(float radius, float height, int slices = 16);
// Terrain: a (divisions+1)^2 grid over sizeX x sizeZ whose y is height(x, z); normals from the heights.
Mesh makeHeightField(float sizeX, float sizeZ, int divisions, float (*height)(float x, float z));
// Appends `other` (its positions moved by `offset`) to `mesh`: how one mesh is made of several shapes.
void appendMesh(Mesh& mesh, const Mesh& other, const glm::vec3& offset = glm::vec3(0.0f));

// Index lists derived from a triangle list for geometry shaders' other input primitives. Vertices within
// 1e-5 of the mesh's extent of each other are welded, so that the seams where normals or UVs split still
// join their triangles.
// edgeIndices: every edge once, as a line list (two indices each, in the first triangle's order).
std::vector<uint32_t> edgeIndices(const std::vector<glm::vec3>& positions,
                                  const std::vector<uint32_t>& indices);
// adjacencyIndices: GL_TRIANGLES_ADJACENCY's six per triangle (v0, n01, v1, n12, v2, n20), nij the vertex
// opposite edge ij in the other triangle on that edge. An edge with no other triangle (the mesh's
// boundary) or with more than one takes the triangle's own opposite vertex: the neighbour is the
// triangle itself wound backwards, so a boundary edge of a triangle facing the light is on the silhouette.
std::vector<uint32_t> adjacencyIndices(const std::vector<glm::vec3>& positions,
                                       const std::vector<uint32_t>& indices);

}  // namespace runtime
