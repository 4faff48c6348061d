#include <runtime/GlDebug.h>

#include <cstdio>
#include <utility>

namespace runtime {

namespace {

DebugSink& sink() {
    static DebugSink instance;
    return instance;
}

std::string_view sourceName(GLenum source) {
    switch (source) {
        case GL_DEBUG_SOURCE_API:
            return "api";
        case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
            return "window system";
        case GL_DEBUG_SOURCE_SHADER_COMPILER:
            return "shader compiler";
        case GL_DEBUG_SOURCE_THIRD_PARTY:
            return "third party";
        case GL_DEBUG_SOURCE_APPLICATION:
            return "application";
        default:
            return "other";
    }
}

std::string_view typeName(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR:
            return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
            return "deprecated";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
            return "undefined behavior";
        case GL_DEBUG_TYPE_PORTABILITY:
            return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE:
            return "performance";
        case GL_DEBUG_TYPE_MARKER:
            return "marker";
        default:
            return "other";
    }
}

std::string_view severityName(GLenum severity) {
    switch (severity) {
        case GL_DEBUG_SEVERITY_HIGH:
            return "high";
        case GL_DEBUG_SEVERITY_MEDIUM:
            return "medium";
        case GL_DEBUG_SEVERITY_LOW:
            return "low";
        default:
            return "notification";
    }
}

void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                             const GLchar* message, const void* /*userParam*/) {
    if (!sink()) return;
    std::string text = "GL ";
    text += typeName(type);
    text += " (";
    text += sourceName(source);
    text += ", ";
    text += severityName(severity);
    text += ", id ";
    text += std::to_string(id);
    text += "): ";
    text.append(message, length >= 0 ? size_t(length) : std::char_traits<char>::length(message));
    sink()(std::move(text));
}

}  // namespace

void setDebugSink(DebugSink newSink) {
    sink() = std::move(newSink);
}

void reportDebugMessage(std::string message) {
    if (sink()) sink()(std::move(message));
}

void installDebugCallback() {
    gl::Enable(GL_DEBUG_OUTPUT);
    // Synchronous: the callback runs inside the call that caused the message, so a breakpoint in the sink
    // shows the culprit.
    gl::Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl::DebugMessageCallback(onDebugMessage, nullptr);
    // Notifications (buffer placement hints and the like) would drown the messages that matter.
    gl::DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
    // The shader compiler's messages repeat the info logs, which GpuProgram reports at the pass they are
    // about; here they would arrive without it.
    gl::DebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                            GL_FALSE);
}

std::string glErrorName(GLenum error) {
    switch (error) {
        case GL_NO_ERROR:
            return "GL_NO_ERROR";
        case GL_INVALID_ENUM:
            return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE:
            return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION:
            return "GL_INVALID_OPERATION";
        case GL_STACK_OVERFLOW:
            return "GL_STACK_OVERFLOW";
        case GL_STACK_UNDERFLOW:
            return "GL_STACK_UNDERFLOW";
        case GL_OUT_OF_MEMORY:
            return "GL_OUT_OF_MEMORY";
        case GL_INVALID_FRAMEBUFFER_OPERATION:
            return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_CONTEXT_LOST:
            return "GL_CONTEXT_LOST";
        default: {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "GL error 0x%04X", error);
            return buffer;
        }
    }
}

bool checkGlErrors(const char* call, const char* file, int line) {
    bool clean = true;
    // glGetError returns one flag per call and several may be set; a lost context keeps returning
    // GL_CONTEXT_LOST, hence the bound.
    for (int i = 0; i < 8; ++i) {
        GLenum error = gl::GetError();
        if (error == GL_NO_ERROR) break;
        clean = false;
        reportDebugMessage(std::string(file) + ":" + std::to_string(line) + ": " + call + ": " +
                           glErrorName(error));
    }
    return clean;
}

}  // namespace runtime
