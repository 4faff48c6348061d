// Shared by the GL tests of tests/runtime: a headless context per test suite and inline GLSL programs.
// The GL plumbing (runtime/gl) is a library of its own whose headers are public: the tests include them
// like any other.
#pragma once

#include <runtime/GlContext.h>

#include <runtime/GlApi.h>
#include <runtime/GpuMesh.h>
#include <runtime/Mesh.h>

#include <stdexcept>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace testsupport {

// One context for the whole executable: creating one per test costs ~15 ms on llvmpipe for nothing.
inline runtime::GlContext& sharedContext() {
    static std::unique_ptr<runtime::GlContext> context = [] {
        std::string error;
        auto created = runtime::createContext(runtime::ContextOptions{}, error);
        if (!created) throw std::runtime_error("no GL context: " + error);
        return created;
    }();
    context->makeCurrent();
    return *context;
}

// A linked program, or 0 with the info log as a test failure.
class Program {
public:
    Program(const std::string& vertex, const std::string& fragment) {
        GLuint vs = compile(GL_VERTEX_SHADER, vertex);
        GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
        mId = gl::CreateProgram();
        gl::AttachShader(mId, vs);
        gl::AttachShader(mId, fs);
        gl::LinkProgram(mId);
        gl::DeleteShader(vs);
        gl::DeleteShader(fs);
        GLint linked = 0;
        gl::GetProgramiv(mId, GL_LINK_STATUS, &linked);
        if (!linked) {
            char log[4096] = {};
            gl::GetProgramInfoLog(mId, sizeof log, nullptr, log);
            ADD_FAILURE() << "link failed: " << log;
        }
    }
    ~Program() { gl::DeleteProgram(mId); }
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const { gl::UseProgram(mId); }
    void set(const char* name, float x, float y = 0, float z = 0, float w = 0) const {
        gl::UseProgram(mId);
        gl::Uniform4f(gl::GetUniformLocation(mId, name), x, y, z, w);
    }
    GLuint id() const { return mId; }

private:
    static GLuint compile(GLenum stage, const std::string& source) {
        GLuint shader = gl::CreateShader(stage);
        const char* text = source.c_str();
        gl::ShaderSource(shader, 1, &text, nullptr);
        gl::CompileShader(shader);
        GLint compiled = 0;
        gl::GetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
        if (!compiled) {
            char log[4096] = {};
            gl::GetShaderInfoLog(shader, sizeof log, nullptr, log);
            ADD_FAILURE() << "compile failed: " << log << "\n" << source;
        }
        return shader;
    }
    GLuint mId = 0;
};

// Position-only vertex shader: clip-space POSITION at location 0.
inline const char* kClipSpaceVertexShader = R"(#version 450
layout(location = 0) in vec4 inPosition;
void main() { gl_Position = inPosition; }
)";

// Solid colour from the uniform `uColor` to output 0.
inline const char* kSolidColorFragmentShader = R"(#version 450
uniform vec4 uColor;
layout(location = 0) out vec4 outColor;
void main() { outColor = uColor; }
)";

inline const std::vector<fx::VertexInput> kPositionOnly = {
    {"POSITION", 0, 4, {fx::VertexStream::Position, 0}}};

// A mesh of clip-space triangles (x, y, z per vertex, indices in order).
inline runtime::GpuMesh clipSpaceTriangles(const std::vector<glm::vec3>& vertices) {
    runtime::Mesh mesh;
    mesh.positions = vertices;
    for (uint32_t i = 0; i < vertices.size(); ++i) mesh.indices.push_back(i);
    return runtime::GpuMesh(mesh);
}

// A quad covering the whole target at depth z, clockwise on screen (D3D front face).
inline runtime::GpuMesh clipSpaceQuad(float z) {
    return clipSpaceTriangles({{-1, 1, z}, {1, 1, z}, {1, -1, z}, {-1, 1, z}, {1, -1, z}, {-1, -1, z}});
}

}  // namespace testsupport
