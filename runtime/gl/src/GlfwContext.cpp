// GlfwContext: a window with an OpenGL 4.5 core context, for the interactive viewer. The runtime still
// renders into framebuffer objects and the viewer blits the result to the window's default framebuffer.
#include "ContextBackends.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

namespace runtime {

namespace {

void* glfwProcAddress(const char* name) {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

// glfwInit/glfwTerminate are process-wide: terminate only when the last window is gone.
int gGlfwUsers = 0;

std::string lastGlfwError() {
    const char* description = nullptr;
    int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "unknown error";
    return description != nullptr ? std::string(description) : "GLFW error " + std::to_string(code);
}

void releaseGlfw() {
    if (--gGlfwUsers == 0) glfwTerminate();
}

class GlfwContext final : public GlContext {
public:
    explicit GlfwContext(GLFWwindow* window) : mWindow(window) {}
    ~GlfwContext() override {
        glfwDestroyWindow(mWindow);
        releaseGlfw();
    }
    GlfwContext(const GlfwContext&) = delete;
    GlfwContext& operator=(const GlfwContext&) = delete;

    Backend backend() const override { return Backend::GLFW; }
    void makeCurrent() override {
        glfwMakeContextCurrent(mWindow);
        useGlFunctionsOf(Backend::GLFW, glfwProcAddress);
    }
    void swapBuffers() override { glfwSwapBuffers(mWindow); }
    bool shouldClose() const override { return glfwWindowShouldClose(mWindow) != 0; }
    void* nativeWindow() const override { return mWindow; }

private:
    GLFWwindow* mWindow;
};

}  // namespace

std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options, std::string& error) {
    if (gGlfwUsers == 0 && glfwInit() != GLFW_TRUE) {
        error = "glfwInit failed (" + lastGlfwError() + ")";
        return nullptr;
    }
    ++gGlfwUsers;
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    // The default framebuffer only receives blits of finished frames: no depth or stencil needed.
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    GLFWwindow* window =
        glfwCreateWindow(options.width, options.height, options.windowTitle.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        error = "glfwCreateWindow(OpenGL 4.5 core) failed (" + lastGlfwError() + ")";
        releaseGlfw();
        return nullptr;
    }
    auto context = std::make_unique<GlfwContext>(window);
    glfwMakeContextCurrent(window);
    if (!initializeCurrentContext(Backend::GLFW, glfwProcAddress, options.debug, error)) return nullptr;
    return context;
}

}  // namespace runtime
