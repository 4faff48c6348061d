#include <runtime/GlApi.h>

#include <cstring>

namespace gl {

#define GL_FUNCTION(type, name) type name = nullptr;
#include <runtime/GlFunctions.h>
#undef GL_FUNCTION

PFNGLPOLYGONOFFSETCLAMPPROC PolygonOffsetClamp = nullptr;

namespace {
bool gLoaded = false;

// Whether the current context advertises `name` (GetProcAddress answers for names it does not support).
bool hasExtension(const char* name) {
    GLint count = 0;
    GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* extension =
            reinterpret_cast<const char*>(GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (extension && std::strcmp(extension, name) == 0) return true;
    }
    return false;
}
}  // namespace

bool load(GetProcAddressFn getProcAddress, std::string& missing) {
    missing.clear();
    // A reinterpret_cast from void* to a function pointer is conditionally supported; POSIX (dlsym)
    // and every GetProcAddress this runtime uses require it to work.
#define GL_FUNCTION(type, name)                                \
    name = reinterpret_cast<type>(getProcAddress("gl" #name)); \
    if (name == nullptr) missing += (missing.empty() ? "gl" : " gl") + std::string(#name);
#include <runtime/GlFunctions.h>
#undef GL_FUNCTION
    gLoaded = missing.empty();
    PolygonOffsetClamp = nullptr;
    if (gLoaded) {
        GLint major = 0, minor = 0;
        GetIntegerv(GL_MAJOR_VERSION, &major);
        GetIntegerv(GL_MINOR_VERSION, &minor);
        if (major * 10 + minor >= 46 || hasExtension("GL_ARB_polygon_offset_clamp"))
            PolygonOffsetClamp =
                reinterpret_cast<PFNGLPOLYGONOFFSETCLAMPPROC>(getProcAddress("glPolygonOffsetClamp"));
        if (!PolygonOffsetClamp && hasExtension("GL_EXT_polygon_offset_clamp"))
            PolygonOffsetClamp =
                reinterpret_cast<PFNGLPOLYGONOFFSETCLAMPPROC>(getProcAddress("glPolygonOffsetClampEXT"));
    }
    return gLoaded;
}

bool isLoaded() {
    return gLoaded;
}

}  // namespace gl
