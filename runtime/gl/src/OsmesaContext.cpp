// OsmesaContext: Mesa's off-screen context (software; removed upstream in Mesa 25.1, EGL surfaceless
// replaces it). OSMesaMakeCurrent insists on a colour buffer; a tiny one suffices since the runtime renders
// into framebuffer objects only.
#include "ContextBackends.h"

#include <GL/osmesa.h>

#include <array>
#include <vector>

namespace runtime {

namespace {

void* osmesaProcAddress(const char* name) {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

class OsmesaContext final : public GlContext {
public:
    explicit OsmesaContext(OSMesaContext context) : mContext(context), mBuffer(kSize * kSize * 4) {}
    ~OsmesaContext() override {
        if (OSMesaGetCurrentContext() == mContext)
            OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(mContext);
    }
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    Backend backend() const override { return Backend::OSMesa; }

    bool bind() {
        return OSMesaMakeCurrent(mContext, mBuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize) == GL_TRUE;
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
    OSMesaContext raw = OSMesaCreateContextAttribs(attributes.data(), nullptr);
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
