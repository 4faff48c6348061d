// GpuMesh: a runtime::Mesh in GL buffers plus a VAO, drawn with whatever vertex inputs the current program
// asks for. Inputs bind by the stream the compiler chose for each (fx::VertexStream), never by attribute
// order:
//   POSITION -> positions, NORMAL -> normals, TEXCOORD0 -> texcoords, TANGENT -> tangents,
//   BINORMAL -> cross(normal, tangent.xyz) * tangent.w, computed at upload.
// An input the mesh lacks reads a constant default (glVertexAttrib4f, attribute array disabled):
//   POSITION (0,0,0,1), NORMAL (0,1,0,0), TEXCOORDn (0,0,0,0), COLORn (1,1,1,1), TANGENT (1,0,0,1),
//   BINORMAL (0,0,-1,0) (= cross(NORMAL, TANGENT) of the defaults), anything else (0,0,0,0).
//
// makeFullScreenQuad(): SAS Draw=Buffer's quad. POSITION is already in clip space: x, y in [-1, 1], z = 0,
// w = 1 (z = 0 is the near plane under GL_ZERO_TO_ONE: the quad passes the default LESSEQUAL depth test
// against any cleared depth, as FX Composer's z = 0 quads do in D3D). TEXCOORD0 is (0,0) at the image's
// top-left and (1,1) at its bottom-right, and its triangles are clockwise on screen, i.e. front-facing
// under D3D's default CullMode = CCW. Texel centres: GL (like D3D10+) samples pixel centres at
// half-integers, so no D3D9 half-texel offset is applied; D3D9 effects that add one (QuadTexelOffsets)
// shift by half a texel.
#pragma once

#include <runtime/GlApi.h>

#include <fx/CompiledEffect.h>
#include <runtime/Mesh.h>

#include <array>
#include <vector>

namespace runtime {

// The constant a missing stream reads (see above).
std::array<float, 4> defaultVertexValue(fx::VertexStream stream);

class GpuMesh {
public:
    GpuMesh() = default;
    explicit GpuMesh(const Mesh& mesh);
    static GpuMesh makeFullScreenQuad();
    ~GpuMesh();
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    // Binds the VAO, enables exactly the locations in `inputs` (feeding a mesh attribute or a default),
    // disables the locations enabled by the previous draw, and draws the triangle list. The program must
    // be current. `instances` > 1 draws that many instances in one call (gl_InstanceID 0..instances-1).
    // `patchVertices` 3 draws the triangles as GL_PATCHES (tessellation), 4 each triangle as a quad patch
    // whose last corner is its third repeated (a quad domain's bilinear patch collapsed onto the triangle);
    // `primitive` draws the vertices as points, the unique edges as lines or the triangles with adjacency
    // instead (a geometry shader's input; the index buffers are built at the first such draw and kept).
    void draw(const std::vector<fx::VertexInput>& inputs, int instances = 1, int patchVertices = 0,
              fx::CompiledPass::DrawPrimitive primitive = fx::CompiledPass::DrawPrimitive::Triangles);

    size_t indexCount() const { return mIndexCount; }
    size_t vertexCount() const { return mVertexCount; }

private:
    enum Stream { kPosition, kNormal, kTexcoord, kTangent, kBinormal, kStreamCount };
    struct StreamBuffer {
        GLuint buffer = 0;
        int components = 0;
    };
    void release();
    void drawElements(int instances, int patchVertices, fx::CompiledPass::DrawPrimitive primitive);
    // The element buffer of lines, triangles with adjacency or quad patches, built from the triangle list on
    // first use.
    enum class Derived { Edges, Adjacency, QuadPatches };
    const std::pair<GLuint, size_t>& derivedIndices(Derived kind);
    void uploadStream(Stream stream, const float* data, int components);

    GLuint mVao = 0;
    GLuint mIndexBuffer = 0;
    std::pair<GLuint, size_t> mEdgeIndices{0, 0};       // GL_LINES: each welded edge once
    std::pair<GLuint, size_t> mAdjacencyIndices{0, 0};  // GL_TRIANGLES_ADJACENCY: 6 per triangle
    std::pair<GLuint, size_t> mQuadPatchIndices{0, 0};  // GL_PATCHES of 4: a, b, c, c per triangle
    std::array<StreamBuffer, kStreamCount> mStreams{};
    size_t mIndexCount = 0;
    size_t mVertexCount = 0;
    uint32_t mEnabledLocations = 0;  // bit i: attribute array i enabled in mVao
    // The inputs mVao's arrays were last set up for, when every one of them came from a stream (defaults are
    // context state, not VAO state): a draw with the same inputs only binds the VAO.
    std::vector<fx::VertexInput> mLayout;
};

}  // namespace runtime
