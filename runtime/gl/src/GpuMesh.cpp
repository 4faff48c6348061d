#include <runtime/GpuMesh.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <utility>

namespace runtime {

std::array<float, 4> defaultVertexValue(fx::VertexStream stream) {
    switch (stream) {
        case fx::VertexStream::Position:
            return {0, 0, 0, 1};
        case fx::VertexStream::Normal:
            return {0, 1, 0, 0};
        case fx::VertexStream::Color:
            return {1, 1, 1, 1};
        case fx::VertexStream::Tangent:
            return {1, 0, 0, 1};
        case fx::VertexStream::Binormal:
            return {0, 0, -1, 0};  // cross((0,1,0), (1,0,0)) * 1
        // A mesh without skin: every vertex on bone 0 (BLENDINDICES 0) with all its weight, drawn as
        // modelled under a palette of identities or of World (whether a skinning shader reads weights
        // 0..n-1 or n-1 of them and the rest as 1 minus their sum).
        case fx::VertexStream::BlendWeight:
            return {1, 0, 0, 0};
        default:
            return {0, 0, 0, 0};
    }
}

GpuMesh::GpuMesh(const Mesh& mesh) {
    gl::GenVertexArrays(1, &mVao);
    gl::BindVertexArray(mVao);
    mVertexCount = mesh.positions.size();
    uploadStream(kPosition, &mesh.positions.data()->x, 3);
    if (mesh.normals.size() == mVertexCount) uploadStream(kNormal, &mesh.normals.data()->x, 3);
    if (mesh.texcoords.size() == mVertexCount) uploadStream(kTexcoord, &mesh.texcoords.data()->x, 2);
    if (mesh.tangents.size() == mVertexCount) {
        uploadStream(kTangent, &mesh.tangents.data()->x, 4);
        if (mesh.normals.size() == mVertexCount) {
            // MikkTSpace's bitangent: the sign in tangent.w restores mirrored UVs.
            std::vector<glm::vec3> binormals(mVertexCount);
            for (size_t i = 0; i < mVertexCount; ++i) {
                binormals[i] = glm::cross(mesh.normals[i], glm::vec3(mesh.tangents[i])) * mesh.tangents[i].w;
            }
            uploadStream(kBinormal, &binormals.data()->x, 3);
        }
    }
    mIndexCount = mesh.indices.size();
    gl::GenBuffers(1, &mIndexBuffer);
    // The element buffer binding is VAO state: bound once here.
    gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mIndexBuffer);
    gl::BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mIndexCount * sizeof(uint32_t)), mesh.indices.data(),
                   GL_STATIC_DRAW);
    gl::BindVertexArray(0);
    gl::BindBuffer(GL_ARRAY_BUFFER, 0);
}

GpuMesh GpuMesh::makeFullScreenQuad() {
    Mesh quad;
    quad.name = "fullscreen quad";
    // Upper-left clip control maps clip y = +1 to the top row.
    quad.positions = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
    quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.normals = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};  // towards the viewer (left-handed)
    // top-left, top-right, bottom-right: clockwise on screen (y down), D3D's front face.
    quad.indices = {0, 1, 2, 0, 2, 3};
    return GpuMesh(quad);
}

void GpuMesh::uploadStream(Stream stream, const float* data, int components) {
    StreamBuffer& target = mStreams[stream];
    target.components = components;
    gl::GenBuffers(1, &target.buffer);
    gl::BindBuffer(GL_ARRAY_BUFFER, target.buffer);
    gl::BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mVertexCount * size_t(components) * sizeof(float)), data,
                   GL_STATIC_DRAW);
}

void GpuMesh::draw(const std::vector<fx::VertexInput>& inputs, int instances, int patchVertices,
                   fx::CompiledPass::DrawPrimitive primitive) {
    if (mVao == 0) return;
    gl::BindVertexArray(mVao);
    const auto sameInput = [](const fx::VertexInput& a, const fx::VertexInput& b) {
        return a.location == b.location && a.components == b.components &&
               a.stream.stream == b.stream.stream && a.stream.index == b.stream.index;
    };
    if (!mLayout.empty() &&
        std::equal(inputs.begin(), inputs.end(), mLayout.begin(), mLayout.end(), sameInput)) {
        drawElements(instances, patchVertices, primitive);
        gl::BindVertexArray(0);
        return;
    }
    bool allStreams = true;
    uint32_t enabled = 0;
    for (const fx::VertexInput& input : inputs) {
        if (input.location < 0 || input.location >= 32) continue;
        const StreamBuffer* stream = nullptr;
        switch (input.stream.stream) {
            case fx::VertexStream::Position:
                stream = &mStreams[kPosition];
                break;
            case fx::VertexStream::Normal:
                stream = &mStreams[kNormal];
                break;
            // The mesh carries one UV set; TEXCOORD1+ read the default rather than repeating set 0.
            case fx::VertexStream::Texcoord:
                stream = input.stream.index == 0 ? &mStreams[kTexcoord] : nullptr;
                break;
            case fx::VertexStream::Tangent:
                stream = &mStreams[kTangent];
                break;
            case fx::VertexStream::Binormal:
                stream = &mStreams[kBinormal];
                break;
            default:
                break;
        }
        GLuint location = GLuint(input.location);
        if (stream != nullptr && stream->buffer != 0) {
            gl::BindBuffer(GL_ARRAY_BUFFER, stream->buffer);
            gl::VertexAttribPointer(location, stream->components, GL_FLOAT, GL_FALSE, 0, nullptr);
            gl::EnableVertexAttribArray(location);
            enabled |= 1u << location;
        } else {
            allStreams = false;
            std::array<float, 4> value = defaultVertexValue(input.stream.stream);
            gl::DisableVertexAttribArray(location);
            gl::VertexAttrib4f(location, value[0], value[1], value[2], value[3]);
        }
    }
    // A location the previous program used but this one does not must not stay enabled on a stale stream.
    for (uint32_t stale = mEnabledLocations & ~enabled; stale != 0; stale &= stale - 1) {
        gl::DisableVertexAttribArray(GLuint(__builtin_ctz(stale)));
    }
    mEnabledLocations = enabled;
    mLayout.clear();
    if (allStreams) mLayout = inputs;
    gl::BindBuffer(GL_ARRAY_BUFFER, 0);
    drawElements(instances, patchVertices, primitive);
    gl::BindVertexArray(0);
}

void GpuMesh::drawElements(int instances, int patchVertices, fx::CompiledPass::DrawPrimitive primitive) {
    using Primitive = fx::CompiledPass::DrawPrimitive;
    if (primitive == Primitive::Points) {  // every vertex once, whatever the triangles
        gl::DrawArraysInstanced(GL_POINTS, 0, GLsizei(mVertexCount), instances);
        return;
    }
    GLenum mode = GL_TRIANGLES;
    size_t count = mIndexCount;
    bool derived = false;
    if (patchVertices == 4) {
        const auto& [buffer, indexCount] = derivedIndices(Derived::QuadPatches);
        gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
        count = indexCount;
        derived = true;
    }
    if (patchVertices > 0) {
        gl::PatchParameteri(GL_PATCH_VERTICES, patchVertices);
        mode = GL_PATCHES;
    } else if (primitive == Primitive::Lines || primitive == Primitive::TrianglesAdjacency) {
        const auto& [buffer, indexCount] =
            derivedIndices(primitive == Primitive::Lines ? Derived::Edges : Derived::Adjacency);
        gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
        mode = primitive == Primitive::Lines ? GL_LINES : GL_TRIANGLES_ADJACENCY;
        count = indexCount;
        derived = true;
    }
    if (instances == 1) {
        gl::DrawElements(mode, GLsizei(count), GL_UNSIGNED_INT, nullptr);
    } else {
        gl::DrawElementsInstanced(mode, GLsizei(count), GL_UNSIGNED_INT, nullptr, instances);
    }
    if (derived) gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mIndexBuffer);  // VAO state: the triangles again
}

const std::pair<GLuint, size_t>& GpuMesh::derivedIndices(Derived kind) {
    std::pair<GLuint, size_t>& derived = kind == Derived::Edges       ? mEdgeIndices
                                         : kind == Derived::Adjacency ? mAdjacencyIndices
                                                                      : mQuadPatchIndices;
    if (derived.first != 0) return derived;
    // Built from what the buffers hold (the Mesh is not kept): read back once, then kept with the mesh.
    std::vector<glm::vec3> positions(mVertexCount);
    std::vector<uint32_t> indices(mIndexCount);
    gl::BindBuffer(GL_ARRAY_BUFFER, mStreams[kPosition].buffer);
    gl::GetBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(positions.size() * sizeof(glm::vec3)),
                         positions.data());
    gl::BindBuffer(GL_ARRAY_BUFFER, 0);
    gl::GetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                         indices.data());
    std::vector<uint32_t> list;
    if (kind == Derived::Edges) {
        list = edgeIndices(positions, indices);
    } else if (kind == Derived::Adjacency) {
        list = adjacencyIndices(positions, indices);
    } else {
        for (size_t t = 0; t + 2 < indices.size(); t += 3)
            list.insert(list.end(), {indices[t], indices[t + 1], indices[t + 2], indices[t + 2]});
    }
    gl::GenBuffers(1, &derived.first);
    gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, derived.first);
    gl::BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(list.size() * sizeof(uint32_t)), list.data(),
                   GL_STATIC_DRAW);
    derived.second = list.size();
    return derived;
}

void GpuMesh::release() {
    for (StreamBuffer& stream : mStreams) {
        if (stream.buffer != 0) gl::DeleteBuffers(1, &stream.buffer);
        stream = {};
    }
    if (mIndexBuffer != 0) gl::DeleteBuffers(1, &mIndexBuffer);
    for (std::pair<GLuint, size_t>* derived : {&mEdgeIndices, &mAdjacencyIndices, &mQuadPatchIndices}) {
        if (derived->first != 0) gl::DeleteBuffers(1, &derived->first);
        *derived = {0, 0};
    }
    if (mVao != 0) gl::DeleteVertexArrays(1, &mVao);
    mIndexBuffer = 0;
    mVao = 0;
}

GpuMesh::~GpuMesh() {
    release();
}

GpuMesh::GpuMesh(GpuMesh&& other) noexcept {
    *this = std::move(other);
}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
    if (this != &other) {
        release();
        mVao = std::exchange(other.mVao, 0);
        mIndexBuffer = std::exchange(other.mIndexBuffer, 0);
        mEdgeIndices = std::exchange(other.mEdgeIndices, {0, 0});
        mAdjacencyIndices = std::exchange(other.mAdjacencyIndices, {0, 0});
        mQuadPatchIndices = std::exchange(other.mQuadPatchIndices, {0, 0});
        mStreams = std::exchange(other.mStreams, {});
        mIndexCount = other.mIndexCount;
        mVertexCount = other.mVertexCount;
        mEnabledLocations = std::exchange(other.mEnabledLocations, 0);
        mLayout = std::exchange(other.mLayout, {});
    }
    return *this;
}

}  // namespace runtime
