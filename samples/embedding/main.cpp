// An application that runs a shadowfx effect: its own scene built from meshes in code, its own
// framebuffer object, the effect's parameters set from C++, and hot reload when the file changes.
// Usage: embedding EFFECT.fx [FRAMES]. Exits 1 if the effect does not load or the frame comes out blank.
#include <runtime/EffectRenderer.h>
#include <runtime/GlApi.h>
#include <runtime/GlContext.h>
#include <runtime/ReloadableEffect.h>
#include <runtime/Scene.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <memory>
#include <set>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: embedding EFFECT.fx [FRAMES]\n"), 2;
    const int frames = argc > 2 ? std::stoi(argv[2]) : 3, width = 320, height = 240;
    std::string error;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext({}, error);  // headless: EGL/OSMesa
    if (!context) return std::fprintf(stderr, "%s\n", error.c_str()), 1;

    runtime::Scene scene;  // a ground plane and a box floating above it, lit from above
    scene.objects.push_back({"ground",
                             std::make_shared<runtime::Mesh>(runtime::makePlane(20, 20)),
                             glm::mat4(1),
                             {0.8f, 0.8f, 0.8f}});
    scene.objects.push_back({"box",
                             std::make_shared<runtime::Mesh>(runtime::makeBox({2, 2, 2})),
                             glm::translate(glm::mat4(1), {0, 2, 0}),
                             {0.9f, 0.4f, 0.2f}});
    scene.camera.position = {6, 8, -10};
    scene.lights.push_back({.direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f))});

    runtime::ReloadableEffect effect(argv[1]);
    if (!effect.reload()) return std::fprintf(stderr, "%s", effect.errorText().c_str()), 1;

    GLuint color = 0, framebuffer = 0;  // the application's own render target
    gl::GenRenderbuffers(1, &color);
    gl::BindRenderbuffer(GL_RENDERBUFFER, color);
    gl::RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl::GenFramebuffers(1, &framebuffer);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);

    std::vector<unsigned char> pixels(width * height * 4);
    for (int frame = 0; frame < frames; ++frame) {
        if (effect.reloadIfChanged() == runtime::ReloadableEffect::Result::Failed)
            std::fprintf(stderr, "reload failed, keeping the last good effect:\n%s",
                         effect.errorText().c_str());
        runtime::EffectRenderer& renderer = *effect.renderer();
        fx::DiagnosticList diagnostics;
        if (renderer.findParameter("Bias"))
            renderer.setParameter(*renderer.findParameter("Bias"), fx::Value::scalar(0.002f * (frame + 1)));
        runtime::FrameOptions options;
        options.width = width, options.height = height, options.time = frame / 60.0f;
        if (!renderer.render(scene, options, diagnostics) || !renderer.blitFrameTo(framebuffer))
            return std::fprintf(stderr, "frame %d did not render\n", frame), 1;
        gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    }
    std::set<unsigned> colors;  // a blank or constant frame has one colour
    for (size_t i = 0; i < pixels.size(); i += 4)
        colors.insert(pixels[i] | pixels[i + 1] << 8 | pixels[i + 2] << 16);
    std::printf("%d frames of %dx%d into framebuffer %u: %zu distinct colours\n", frames, width, height,
                framebuffer, colors.size());
    gl::DeleteFramebuffers(1, &framebuffer);
    gl::DeleteRenderbuffers(1, &color);
    return colors.size() > 16 ? 0 : 1;
}
