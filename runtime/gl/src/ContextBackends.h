// ContextBackends: what GlContext.cpp needs from each backend file (OsmesaContext.cpp, EglContext.cpp,
// GlfwContext.cpp) and what they share: one factory per backend, and the set-up every new context gets.
// No GL headers here on purpose: osmesa.h includes GL/gl.h, which does not mix with GL/glcorearb.h.
#pragma once

#include <runtime/GlContext.h>

#include <memory>
#include <string>

namespace runtime {

using ProcAddressFn = void* (*)(const char* name);

// Each creates its context and makes it current, then calls initializeCurrentContext. On failure:
// nullptr and a one-line reason in `error` (without the backend name; the caller prefixes it).
std::unique_ptr<GlContext> createOsmesaContext(const ContextOptions& options, std::string& error);
std::unique_ptr<GlContext> createEglContext(const ContextOptions& options, std::string& error);
std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options, std::string& error);

// For a context that was just made current the first time: loads the GL functions, checks for a 4.5
// core profile, and sets the conventions the whole runtime relies on (D3D clip space:
// glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); pack/unpack alignment 1; seamless cube maps) and, for
// debug contexts, KHR_debug output to the debug sink.
bool initializeCurrentContext(Backend backend, ProcAddressFn getProcAddress, bool debug, std::string& error);

// For makeCurrent: the gl:: pointers are per process, so switching to a context of another backend
// (another libGL implementation) reloads them. A no-op when this backend's functions are loaded.
void useGlFunctionsOf(Backend backend, ProcAddressFn getProcAddress);

}  // namespace runtime
