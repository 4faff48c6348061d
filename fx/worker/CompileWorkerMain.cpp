// shadowfx-compile-worker: answers compile requests (fx/src/CompileProtocol.h) on fd 0, a stream socket
// the compiler (fx/CompileWorkers.h) created, until the compiler closes it. Not meant to be run by hand.
#include "CompileProtocol.h"

#include <unistd.h>

// In sanitizer builds a SIGSEGV in glslang stays a signal, as in release builds, so that the compiler
// reports the same "signal 11" (ASan would print its report and exit with status 1). Unused otherwise.
extern "C" const char* __asan_default_options() {
    return "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0";
}

int main() {
    // _exit: no static destructors or leak report after the compiler hung up; a crashed compile has
    // already been reported by the compiler from this process's wait status.
    _exit(fx::serveCompileRequests(0));
}
