// LiveGlObjects: the GL objects alive in the current context, counted by asking the driver about every
// name up to a bound. GL implementations hand out small names first and reuse freed ones, so a leak shows
// as a growing count; counting through the driver (rather than a counter in the runtime) also catches
// objects the runtime's own bookkeeping would miss. Used by the reload and load/unload leak tests.
#pragma once

#include <runtime/GlApi.h>

#include <ostream>

namespace shadowfx::test {

struct LiveGlObjects {
    int textures = 0, buffers = 0, programs = 0, shaders = 0, framebuffers = 0, samplers = 0,
        vertexArrays = 0;
    bool operator==(const LiveGlObjects&) const = default;
};

inline std::ostream& operator<<(std::ostream& out, const LiveGlObjects& o) {
    return out << "{textures " << o.textures << ", buffers " << o.buffers << ", programs " << o.programs
               << ", shaders " << o.shaders << ", framebuffers " << o.framebuffers << ", samplers "
               << o.samplers << ", vertex arrays " << o.vertexArrays << "}";
}

inline LiveGlObjects countLiveGlObjects(GLuint probedNames = 8192) {
    LiveGlObjects live;
    for (GLuint name = 1; name <= probedNames; ++name) {
        live.textures += gl::IsTexture(name) ? 1 : 0;
        live.buffers += gl::IsBuffer(name) ? 1 : 0;
        live.programs += gl::IsProgram(name) ? 1 : 0;
        live.shaders += gl::IsShader(name) ? 1 : 0;
        live.framebuffers += gl::IsFramebuffer(name) ? 1 : 0;
        live.samplers += gl::IsSampler(name) ? 1 : 0;
        live.vertexArrays += gl::IsVertexArray(name) ? 1 : 0;
    }
    return live;
}

}  // namespace shadowfx::test
