#include <runtime/GlApi.h>

namespace gl {

#define GL_FUNCTION(type, name) type name = nullptr;
#include <runtime/GlFunctions.h>
#undef GL_FUNCTION

namespace {
bool gLoaded = false;
}

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
    return gLoaded;
}

bool isLoaded() {
    return gLoaded;
}

}  // namespace gl
