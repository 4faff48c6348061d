// OsmesaContext: Mesa's off-screen context (software; removed upstream in Mesa 25.1, EGL surfaceless
// replaces it). OSMesaMakeCurrent insists on a colour buffer; a tiny one suffices since the runtime renders
// into framebuffer objects only.
//
// libOSMesa is opened when the first OSMesa context is created, not linked: it carries Mesa's LLVM, whose
// loading and relocation cost every program that links the runtime about 50 ms at start (measured by
// bench_startup), including those that never render or render through EGL. Opened RTLD_LOCAL, its GL
// symbols cannot shadow glvnd's either.
#include "ContextBackends.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

namespace runtime {

namespace {

// The OSMesa entry points the backend calls, resolved from the library opened on first use.
struct OsmesaLibrary {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaGetCurrentContext) getCurrentContext = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
    std::string error;  // why the library could not be used; empty when it can
};

// Opened once per process and never closed: contexts and the GL entry points taken from it outlive any
// one caller.
const OsmesaLibrary& osmesaLibrary() {
    static const OsmesaLibrary library = [] {
        OsmesaLibrary l;
        void* handle = dlopen(SHADOWFX_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            const char* reason = dlerror();
            l.error =
                std::string("cannot load " SHADOWFX_OSMESA_LIBRARY ": ") + (reason ? reason : "unknown");
            return l;
        }
        auto resolve = [&](auto& entry, const char* name) {
            entry = reinterpret_cast<std::remove_reference_t<decltype(entry)>>(dlsym(handle, name));
            if (entry == nullptr && l.error.empty())
                l.error = std::string(SHADOWFX_OSMESA_LIBRARY " has no ") + name;
        };
        resolve(l.createContextAttribs, "OSMesaCreateContextAttribs");
        resolve(l.makeCurrent, "OSMesaMakeCurrent");
        resolve(l.getCurrentContext, "OSMesaGetCurrentContext");
        resolve(l.destroyContext, "OSMesaDestroyContext");
        resolve(l.getProcAddress, "OSMesaGetProcAddress");
        return l;
    }();
    return library;
}

void* osmesaProcAddress(const char* name) {
    return reinterpret_cast<void*>(osmesaLibrary().getProcAddress(name));
}

class OsmesaContext final : public GlContext {
public:
    explicit OsmesaContext(OSMesaContext context) : mContext(context), mBuffer(kSize * kSize * 4) {}
    ~OsmesaContext() override {
        const OsmesaLibrary& osmesa = osmesaLibrary();
        if (osmesa.getCurrentContext() == mContext)
            osmesa.makeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        osmesa.destroyContext(mContext);
    }
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    Backend backend() const override { return Backend::OSMesa; }

    bool bind() {
        return osmesaLibrary().makeCurrent(mContext, mBuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize) ==
               GL_TRUE;
    }

    void makeCurrent() override {
        bind();
        useGlFunctionsOf(Backend::OSMesa, osmesaProcAddress);
    }

private:
    static constexpr int kSize = 4;
    OSMesaContext mContext;
    std::vector<unsigned char> mBuffer;  // the unused default colour buffer
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext(const ContextOptions& options, std::string& error) {
    const OsmesaLibrary& osmesa = osmesaLibrary();
    if (!osmesa.error.empty()) {
        error = osmesa.error;
        return nullptr;
    }
    // No depth/stencil on the default buffer: nothing renders into it. OSMesa has no debug-context flag;
    // Mesa still produces KHR_debug output once GL_DEBUG_OUTPUT is enabled.
    const std::array<int, 13> attributes = {
        OSMESA_FORMAT,
        OSMESA_RGBA,
        OSMESA_DEPTH_BITS,
        0,
        OSMESA_STENCIL_BITS,
        0,
        OSMESA_PROFILE,
        OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION,
        4,
        OSMESA_CONTEXT_MINOR_VERSION,
        5,
        0,
    };
    OSMesaContext raw = osmesa.createContextAttribs(attributes.data(), nullptr);
    if (raw == nullptr) {
        error = "OSMesaCreateContextAttribs failed (no OpenGL 4.5 core profile)";
        return nullptr;
    }
    auto context = std::make_unique<OsmesaContext>(raw);
    if (!context->bind()) {
        error = "OSMesaMakeCurrent failed";
        return nullptr;
    }
    if (!initializeCurrentContext(Backend::OSMesa, osmesaProcAddress, options.debug, error)) return nullptr;
    return context;
}

}  // namespace runtime
