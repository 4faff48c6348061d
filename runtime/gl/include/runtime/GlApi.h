// GlApi: the OpenGL 4.5 core functions as `gl::Name` pointers (gl::Clear, gl::DrawElements, ...), loaded
// at run time through the context backend's GetProcAddress. The runtime never links libGL or libOpenGL:
// OSMesa and glvnd's libOpenGL export the same symbols and would shadow each other, so every call goes
// through these pointers. The list of functions is GlFunctions.h.
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace gl {

#define GL_FUNCTION(type, name) extern type name;
#include <runtime/GlFunctions.h>
#undef GL_FUNCTION

// Returns the address of a GL entry point, or nullptr (OSMesaGetProcAddress, eglGetProcAddress and
// glfwGetProcAddress behind one signature).
using GetProcAddressFn = void* (*)(const char* name);

// Fills every pointer of GlFunctions.h. A context must be current: some GetProcAddress implementations
// only answer for the current context. On failure returns false and lists the missing functions in
// `missing` ("glClipControl glTexStorage2D"); the pointers found are still set.
bool load(GetProcAddressFn getProcAddress, std::string& missing);

// True once load() has succeeded at least once in this process.
bool isLoaded();

// Beyond core 4.5, loaded by load() where the context offers it, else nullptr: glPolygonOffsetClamp (GL 4.6,
// ARB_polygon_offset_clamp, or EXT_polygon_offset_clamp's glPolygonOffsetClampEXT), which D3D10's
// DepthBiasClamp needs.
extern PFNGLPOLYGONOFFSETCLAMPPROC PolygonOffsetClamp;

}  // namespace gl
