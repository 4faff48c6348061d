// EglContext: a headless context without any surface. Displays, in the order tried:
//   1. EGL_PLATFORM_SURFACELESS_MESA (Mesa: llvmpipe or a GPU through its render node),
//   2. EGL_PLATFORM_DEVICE_EXT with the first device (NVIDIA's proprietary driver renders headless so),
//   3. EGL_DEFAULT_DISPLAY.
// Contexts are created without a config (EGL_KHR_no_config_context) when possible, since nothing is ever
// drawn to an EGL surface, and made current with EGL_NO_SURFACE (EGL_KHR_surfaceless_context).
#include "ContextBackends.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string_view>
#include <vector>

namespace runtime {

namespace {

void* eglProcAddress(const char* name) {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

std::string eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS:
            return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_CURRENT_SURFACE:
            return "EGL_BAD_CURRENT_SURFACE";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_NATIVE_PIXMAP:
            return "EGL_BAD_NATIVE_PIXMAP";
        case EGL_BAD_NATIVE_WINDOW:
            return "EGL_BAD_NATIVE_WINDOW";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE:
            return "EGL_BAD_SURFACE";
        case EGL_CONTEXT_LOST:
            return "EGL_CONTEXT_LOST";
        default: {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "EGL error 0x%04X", error);
            return buffer;
        }
    }
}

// Extension strings are space-separated lists; a plain strstr would match prefixes.
bool hasExtension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        size_t end = rest.find(' ');
        if (rest.substr(0, end) == name) return true;
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    return false;
}

// eglTerminate ends every context of a display, and displays are shared per platform: count the users so
// one context's destruction does not pull the display from under another.
std::map<EGLDisplay, int>& displayUsers() {
    static std::map<EGLDisplay, int> users;
    return users;
}

void releaseDisplay(EGLDisplay display) {
    auto found = displayUsers().find(display);
    if (found == displayUsers().end()) return;
    if (--found->second == 0) {
        displayUsers().erase(found);
        eglTerminate(display);
    }
}

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context) : mDisplay(display), mContext(context) {}
    ~EglContext() override {
        if (eglGetCurrentContext() == mContext) {
            eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(mDisplay, mContext);
        releaseDisplay(mDisplay);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    Backend backend() const override { return Backend::EGL; }

    bool bind() {
        // eglBindAPI is per thread: set it again in case another thread-local user changed it.
        eglBindAPI(EGL_OPENGL_API);
        return eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext) == EGL_TRUE;
    }

    void makeCurrent() override {
        bind();
        useGlFunctionsOf(Backend::EGL, eglProcAddress);
    }

private:
    EGLDisplay mDisplay;
    EGLContext mContext;
};

struct DisplayChoice {
    EGLDisplay display = EGL_NO_DISPLAY;
    const char* platform = "";
};

// Initializes the first display that works; `tried` collects why the others did not.
DisplayChoice openDisplay(std::string& tried) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto note = [&](const char* what, const std::string& why) {
        if (!tried.empty()) tried += ", ";
        tried += what;
        tried += ": ";
        tried += why;
    };
    auto initialize = [&](EGLDisplay display, const char* what) -> bool {
        if (display == EGL_NO_DISPLAY) {
            note(what, "no display (" + eglErrorName(eglGetError()) + ")");
            return false;
        }
        EGLint major = 0, minor = 0;
        if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
            note(what, "eglInitialize failed (" + eglErrorName(eglGetError()) + ")");
            return false;
        }
        return true;
    };

    if (getPlatformDisplay != nullptr && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (initialize(display, "surfaceless")) return {display, "surfaceless"};
    } else {
        note("surfaceless", "EGL_MESA_platform_surfaceless not supported");
    }

    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (getPlatformDisplay != nullptr && queryDevices != nullptr &&
        hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (queryDevices(8, devices, &count) == EGL_TRUE && count > 0) {
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
            if (initialize(display, "device")) return {display, "device"};
        } else {
            note("device", "no EGL devices");
        }
    } else {
        note("device", "EGL_EXT_platform_device not supported");
    }

    EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (initialize(display, "default display")) return {display, "default display"};
    return {};
}

}  // namespace

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options, std::string& error) {
    std::string tried;
    DisplayChoice choice = openDisplay(tried);
    if (choice.display == EGL_NO_DISPLAY) {
        error = "no usable EGL display (" + tried + ")";
        return nullptr;
    }
    EGLDisplay display = choice.display;
    ++displayUsers()[display];
    auto fail = [&](const std::string& why) -> std::unique_ptr<GlContext> {
        error = why + " on the " + choice.platform + " platform";
        releaseDisplay(display);
        return nullptr;
    };

    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
        return fail("EGL_KHR_surfaceless_context not supported");
    }
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
        return fail("eglBindAPI(EGL_OPENGL_API) failed (" + eglErrorName(eglGetError()) + ")");
    }

    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context") &&
        !hasExtension(extensions, "EGL_MESA_configless_context")) {
        // Older drivers need some config even though no surface is ever created with it.
        const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (eglChooseConfig(display, configAttributes, &config, 1, &count) != EGL_TRUE || count == 0) {
            return fail("no EGL config with EGL_OPENGL_BIT");
        }
    }

    std::vector<EGLint> contextAttributes = {
        EGL_CONTEXT_MAJOR_VERSION,           4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
    };
    // Only when asked: EGL_CONTEXT_OPENGL_DEBUG is EGL 1.5, and an EGL 1.4 driver rejects the attribute.
    if (options.debug)
        contextAttributes.insert(contextAttributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    contextAttributes.push_back(EGL_NONE);
    EGLContext raw = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes.data());
    if (raw == EGL_NO_CONTEXT) {
        return fail("eglCreateContext(OpenGL 4.5 core) failed (" + eglErrorName(eglGetError()) + ")");
    }
    // The context owns a display reference from here on.
    auto context = std::make_unique<EglContext>(display, raw);
    if (!context->bind()) {
        error = "eglMakeCurrent(EGL_NO_SURFACE) failed (" + eglErrorName(eglGetError()) + ")";
        return nullptr;
    }
    if (!initializeCurrentContext(Backend::EGL, eglProcAddress, options.debug, error)) return nullptr;
    return context;
}

}  // namespace runtime
