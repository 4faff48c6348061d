// GlContext: backend names, the backend table, and the set-up every new context shares.
#include <runtime/GlContext.h>

#include "ContextBackends.h"
#include <runtime/GlApi.h>
#include <runtime/GlDebug.h>

#include <array>
#include <optional>

namespace runtime {

namespace {

using Factory = std::unique_ptr<GlContext> (*)(const ContextOptions&, std::string&);

struct BackendEntry {
    Backend backend;
    std::string_view name;
    Factory create;  // nullptr: not compiled into this build
};

// The one table of backends, in the order Auto tries them (headless first; GLFW only when asked for).
constexpr std::array<BackendEntry, 3> kBackends = {{
    {Backend::EGL, "egl", createEglContext},
#ifdef SHADOWFX_HAVE_OSMESA
    {Backend::OSMesa, "osmesa", createOsmesaContext},
#else
    {Backend::OSMesa, "osmesa", nullptr},
#endif
    {Backend::GLFW, "glfw", createGlfwContext},
}};

const BackendEntry* findEntry(Backend backend) {
    for (const BackendEntry& entry : kBackends) {
        if (entry.backend == backend) return &entry;
    }
    return nullptr;
}

// Whose GL functions gl:: currently holds (the pointers are process-wide, contexts are not).
std::optional<Backend> gLoadedBackend;

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        if (lower(a[i]) != lower(b[i])) return false;
    }
    return true;
}

std::string glString(GLenum name) {
    const GLubyte* text = gl::GetString != nullptr ? gl::GetString(name) : nullptr;
    return text != nullptr ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

std::string_view backendName(Backend backend) {
    if (backend == Backend::Auto) return "auto";
    const BackendEntry* entry = findEntry(backend);
    return entry != nullptr ? entry->name : "unknown";
}

std::optional<Backend> parseBackend(std::string_view name) {
    if (equalsIgnoreCase(name, "auto")) return Backend::Auto;
    for (const BackendEntry& entry : kBackends) {
        if (equalsIgnoreCase(name, entry.name)) return entry.backend;
    }
    return std::nullopt;
}

std::vector<Backend> compiledBackends() {
    std::vector<Backend> backends;
    for (const BackendEntry& entry : kBackends) {
        if (entry.create != nullptr) backends.push_back(entry.backend);
    }
    return backends;
}

std::string GlContext::renderer() const {
    return glString(GL_RENDERER) + " | " + glString(GL_VERSION);
}

void useGlFunctionsOf(Backend backend, ProcAddressFn getProcAddress) {
    if (gLoadedBackend == backend) return;
    std::string missing;
    gl::load(getProcAddress, missing);  // this backend loaded them all once already
    gLoadedBackend = backend;
}

bool initializeCurrentContext(Backend backend, ProcAddressFn getProcAddress, bool debug, std::string& error) {
    std::string missing;
    bool complete = gl::load(getProcAddress, missing);
    gLoadedBackend = complete ? std::optional<Backend>(backend) : std::nullopt;

    // The version first: a 3.3 context misses 4.x functions, and "got 3.3" says why better than the list.
    GLint major = 0, minor = 0, profile = 0;
    if (gl::GetIntegerv != nullptr) {
        gl::GetIntegerv(GL_MAJOR_VERSION, &major);
        gl::GetIntegerv(GL_MINOR_VERSION, &minor);
        gl::GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    }
    if (major * 10 + minor < 45 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
        error = "got OpenGL '" + glString(GL_VERSION) + "', need 4.5 core";
        return false;
    }
    if (!complete) {
        error = "missing GL functions: " + missing;
        return false;
    }

    // D3D conventions, once per context; every other file relies on them:
    // - clip-space z in [0, 1] and window row 0 = clip y +1, so D3D projection matrices work unchanged
    //   and row 0 of every render target (and of every readback) is the image's top row.
    gl::ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    // - tightly packed rows for uploads and readbacks of any width (R32F targets of odd width).
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // - filtering across cube faces, as D3D10+ hardware does for D3D9 effects too.
    gl::Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    if (debug) installDebugCallback();
    gl::GetError();  // start clean: nothing above is the caller's error
    return true;
}

std::unique_ptr<GlContext> createContext(const ContextOptions& options, std::string& error) {
    std::vector<Backend> order;
    if (options.backend == Backend::Auto) {
        order = {Backend::EGL, Backend::OSMesa};
    } else {
        order = {options.backend};
    }

    std::string reasons;
    for (Backend backend : order) {
        const BackendEntry* entry = findEntry(backend);
        std::string why;
        std::unique_ptr<GlContext> context;
        if (entry == nullptr || entry->create == nullptr) {
            why = "not compiled into this build";
        } else {
            context = entry->create(options, why);
        }
        if (context) {
            error.clear();
            return context;
        }
        if (!reasons.empty()) reasons += "; ";
        reasons += std::string(backendName(backend)) + ": " + why;
    }
    error = "no OpenGL 4.5 core context (" + reasons + ")";
    return nullptr;
}

}  // namespace runtime
