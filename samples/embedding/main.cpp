// An application that draws a shadowfx effect itself, as D3DX9 and FX11 applications drew theirs: its own
// vertex buffers, vertex arrays, framebuffer and draw calls; the effect's matrices set by semantic; one
// technique applied pass by pass around its draws (runtime/EffectPass.h, docs/api.md); hot reload when the
// file changes.
// Usage: embedding EFFECT.fx [FRAMES]. Exits 1 if the effect does not load or the frame comes out blank.
#include <runtime/EffectRenderer.h>
#include <runtime/GlApi.h>
#include <runtime/GlContext.h>
#include <runtime/ReloadableEffect.h>
#include <runtime/Scene.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cctype>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

// An object of the application's: a mesh in its own buffers, a vertex array per pass (the passes read
// different inputs), its world transform and colour.
struct Object {
    GLuint positions = 0, normals = 0, indices = 0;
    GLsizei indexCount = 0;
    glm::mat4 world{1.0f};
    glm::vec3 color{1.0f};
    std::map<std::pair<size_t, size_t>, GLuint> vaos;  // by (technique, pass) of the current effect

    Object(const runtime::Mesh& mesh, const glm::mat4& transform, const glm::vec3& colour)
        : world(transform), color(colour) {
        const auto upload = [](GLenum target, const void* data, size_t bytes) {
            GLuint buffer = 0;
            gl::GenBuffers(1, &buffer);
            gl::BindBuffer(target, buffer);
            gl::BufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
            return buffer;
        };
        positions = upload(GL_ARRAY_BUFFER, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        normals = upload(GL_ARRAY_BUFFER, mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
        indices =
            upload(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
        indexCount = static_cast<GLsizei>(mesh.indices.size());
    }

    void forgetVertexArrays() {
        for (auto& [pass, vao] : vaos) gl::DeleteVertexArrays(1, &vao);
        vaos.clear();
    }
    void release() {
        forgetVertexArrays();
        const GLuint buffers[] = {positions, normals, indices};
        gl::DeleteBuffers(3, buffers);
    }

    // The pass's vertex array, laid out by its input signature on first use.
    void bindFor(const runtime::EffectPass& pass) {
        GLuint& vao = vaos[{pass.techniqueIndex(), pass.index()}];
        if (!vao) {
            gl::GenVertexArrays(1, &vao);
            gl::BindVertexArray(vao);
            for (const runtime::PassInput& input : pass.inputSignature()) {
                const bool position = input.semantic.rfind("POSITION", 0) == 0;
                // Other inputs read GL's current generic attribute, (0, 0, 0, 1) unless set.
                if (!position && input.semantic.rfind("NORMAL", 0) != 0) continue;
                gl::BindBuffer(GL_ARRAY_BUFFER, position ? positions : normals);
                gl::EnableVertexAttribArray(static_cast<GLuint>(input.location));
                gl::VertexAttribPointer(static_cast<GLuint>(input.location), 3, GL_FLOAT, GL_FALSE, 0,
                                        nullptr);
            }
            gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
        }
        gl::BindVertexArray(vao);
    }
};

// What an SAS effect's pass script asks of the application around the pass's draws: clears, with the
// colour and depth the parameters it names hold (FX Composer's ClearSetColor, ClearSetDepth, Clear).
void clearAsScripted(runtime::EffectRenderer& effect, const runtime::EffectPass& pass) {
    std::istringstream script(pass.annotation("Script").asString());
    std::string command;
    while (std::getline(script, command, ';')) {
        const size_t start = command.find_first_not_of(" \t\n"), equals = command.find('=');
        if (equals == std::string::npos || start >= equals) continue;
        const std::string name = command.substr(start, equals - start), value = command.substr(equals + 1);
        if (name == "ClearSetColor") {
            const fx::Value color = effect.variable(value).value();
            if (color.data.size() == 4)
                gl::ClearColor(color.data[0], color.data[1], color.data[2], color.data[3]);
        } else if (name == "ClearSetDepth") {
            gl::ClearDepth(effect.variable(value).value().asFloat());
        } else if (name == "Clear") {
            gl::Clear(value == "Color" ? GL_COLOR_BUFFER_BIT : GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        }
    }
}

// The values an SAS effect takes by semantic, for one object. A View or Projection annotated
// `string frustum = "light0"` is the light's (SAS's convention), any other the camera's.
void setMatrices(runtime::EffectRenderer& effect, const glm::mat4& view, const glm::mat4& projection,
                 const glm::mat4& lightView, const glm::mat4& lightProjection, const Object& object) {
    for (size_t i = 0; i < effect.variableCount(); ++i) {
        runtime::EffectVariable variable = effect.variable(i);
        const bool light = !variable.annotation("frustum").asString().empty();
        const glm::mat4& v = light ? lightView : view;
        const glm::mat4& p = light ? lightProjection : projection;
        std::string semantic = variable.semantic();
        for (char& c : semantic) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (semantic == "world") variable.setMatrix(object.world);
        if (semantic == "worldinversetranspose")
            variable.setMatrix(glm::transpose(glm::inverse(object.world)));
        if (semantic == "worldviewprojection") variable.setMatrix(p * v * object.world);
        if (semantic == "view") variable.setMatrix(v);
        if (semantic == "viewinverse") variable.setMatrix(glm::inverse(v));
        if (semantic == "projection") variable.setMatrix(p);
        if (semantic == "diffuse") variable.setVector(object.color);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: embedding EFFECT.fx [FRAMES]\n"), 2;
    const int frames = argc > 2 ? std::stoi(argv[2]) : 3, width = 320, height = 240;
    std::string error;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext({}, error);  // headless: EGL/OSMesa
    if (!context) return std::fprintf(stderr, "%s\n", error.c_str()), 1;

    std::vector<Object> objects;  // a ground plane and a box floating above it
    objects.emplace_back(runtime::makePlane(20, 20), glm::mat4(1), glm::vec3(0.8f));
    objects.emplace_back(runtime::makeBox({2, 2, 2}), glm::translate(glm::mat4(1), {0, 2, 0}),
                         glm::vec3(0.9f, 0.4f, 0.2f));
    runtime::Camera camera;
    camera.position = {6, 8, -10};
    runtime::Light sun;  // lit from above; its matrices fitted to the scene's bounds
    sun.direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
    const runtime::Bounds bounds{{-10, 0, -10}, {10, 3, 10}};
    const glm::mat4 view = camera.view(), projection = camera.projection(float(width) / height);
    const glm::mat4 lightView = sun.view(bounds), lightProjection = sun.projection(bounds);

    runtime::ReloadableEffect effect(argv[1]);
    if (!effect.reload()) return std::fprintf(stderr, "%s", effect.errorText().c_str()), 1;

    GLuint renderbuffers[2] = {}, framebuffer = 0;  // the application's own colour and depth-stencil target
    gl::GenRenderbuffers(2, renderbuffers);
    gl::BindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl::BindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    gl::GenFramebuffers(1, &framebuffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                renderbuffers[1]);
    gl::Viewport(0, 0, width, height);

    std::vector<unsigned char> pixels(width * height * 4);
    const runtime::EffectRenderer* vertexArraysOf =
        nullptr;  // the effect the vertex arrays were laid out for
    for (int frame = 0; frame < frames; ++frame) {
        if (effect.reloadIfChanged() == runtime::ReloadableEffect::Result::Failed)
            std::fprintf(stderr, "reload failed, keeping the last good effect:\n%s",
                         effect.errorText().c_str());
        runtime::EffectRenderer& renderer = *effect.renderer();
        if (vertexArraysOf != &renderer)
            for (Object& object : objects) object.forgetVertexArrays();
        vertexArraysOf = &renderer;
        renderer.variable("Bias").setFloat(0.002f * (frame + 1));  // does nothing where there is no Bias
        renderer.variableBySemantic("LightColor").setVector(glm::vec3(1.0f));
        renderer.variableBySemantic("Time").setFloat(frame / 60.0f);

        fx::DiagnosticList diagnostics;
        runtime::EffectTechnique technique = renderer.technique(0);
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        if (!technique.begin()) return std::fprintf(stderr, "the effect has no technique\n"), 1;
        for (size_t p = 0; p < technique.passCount(); ++p) {
            const runtime::EffectPass pass = technique.pass(p);
            if (!pass.apply(&diagnostics)) return std::fprintf(stderr, "%s", diagnostics.str().c_str()), 1;
            clearAsScripted(renderer, pass);
            if (pass.inputSignature().empty()) continue;  // a pass that only clears
            for (Object& object : objects) {
                setMatrices(renderer, view, projection, lightView, lightProjection, object);
                pass.commitChanges(&diagnostics);
                object.bindFor(pass);
                gl::DrawElements(GL_TRIANGLES, object.indexCount, GL_UNSIGNED_INT, nullptr);
            }
        }
        technique.end();
        gl::BindVertexArray(0);
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    }
    std::set<unsigned> colors;  // a blank or constant frame has one colour
    for (size_t i = 0; i < pixels.size(); i += 4)
        colors.insert(pixels[i] | pixels[i + 1] << 8 | pixels[i + 2] << 16);
    std::printf("%d frames of %dx%d into framebuffer %u: %zu distinct colours\n", frames, width, height,
                framebuffer, colors.size());
    for (Object& object : objects) object.release();
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteRenderbuffers(2, renderbuffers);
    return colors.size() > 16 ? 0 : 1;
}
