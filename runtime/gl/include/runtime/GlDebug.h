// GlDebug: where GL diagnostics go. KHR_debug messages of debug contexts and GL_CHECK failures are
// formatted and handed to one sink the application sets (the library never prints); without a sink they
// are dropped.
#pragma once

#include <runtime/GlApi.h>

#include <functional>
#include <string>
#include <string_view>

namespace runtime {

using DebugSink = std::function<void(std::string message)>;

// Replaces the sink (an empty function drops messages). Not thread-safe: set it before rendering.
void setDebugSink(DebugSink sink);
// Sends a message to the current sink, if any.
void reportDebugMessage(std::string message);

// Enables KHR_debug output on the current context and routes it to the sink (synchronous output, so a
// message arrives while the offending call is still on the stack). Notifications are filtered out.
void installDebugCallback();

// "GL_INVALID_ENUM" for 0x0500; "GL error 0x1234" for unknown values.
std::string glErrorName(GLenum error);

// Drains glGetError; reports "file:line: call: GL_INVALID_OPERATION" for each error. Returns true when
// there was none.
bool checkGlErrors(const char* call, const char* file, int line);

}  // namespace runtime

// GL_CHECK(gl::Foo(...)): in debug builds, checks glGetError after the call and reports the error enum
// by name to the debug sink. In release builds it is the bare call. Statements only (no return value).
#ifndef NDEBUG
#define GL_CHECK(call)                                       \
    do {                                                     \
        call;                                                \
        ::runtime::checkGlErrors(#call, __FILE__, __LINE__); \
    } while (0)
#else
#define GL_CHECK(call) \
    do {               \
        call;          \
    } while (0)
#endif
