// GlContext: an OpenGL 4.5 core context from one of three backends behind one interface, chosen at run
// time: OSMesa (headless, software), EGL surfaceless (headless; Mesa's replacement for OSMesa and the
// path on NVIDIA GPUs) and a GLFW window (the viewer). Headless contexts have no default framebuffer
// worth using: the runtime renders every frame into its own framebuffer objects.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

enum class Backend { Auto, OSMesa, EGL, GLFW };

std::string_view backendName(Backend backend);  // "auto", "osmesa", "egl", "glfw"
std::optional<Backend> parseBackend(std::string_view name);
// Backends this build was compiled with, in the order Auto tries them (headless first).
std::vector<Backend> compiledBackends();

struct ContextOptions {
    Backend backend = Backend::Auto;  // Auto: EGL, then OSMesa (GLFW only when asked for)
    int width = 640;                  // window size (GLFW); headless contexts ignore it
    int height = 480;
    std::string windowTitle = "shadowfx";
    bool debug = false;  // a debug context with KHR_debug output
};

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual Backend backend() const = 0;
    virtual void makeCurrent() = 0;
    // Window contexts only.
    virtual void swapBuffers() {}
    virtual bool shouldClose() const { return false; }
    virtual void* nativeWindow() const { return nullptr; }  // GLFWwindow*

    // "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6"
    std::string renderer() const;
};

// Creates a context, makes it current and loads the GL functions. On failure returns nullptr and sets
// `error` to a message naming every backend tried and why it failed (e.g. no 4.5 core context).
std::unique_ptr<GlContext> createContext(const ContextOptions& options, std::string& error);

}  // namespace runtime
