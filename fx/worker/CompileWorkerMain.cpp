// shadowfx-compile-worker: answers compile requests (fx/src/CompileProtocol.h) on fd 0, a stream socket
// the compiler (fx/CompileWorkers.h) created, until the compiler closes it. Not meant to be run by hand.
#include "CompileProtocol.h"

#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define SHADOWFX_WORKER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHADOWFX_WORKER_ASAN 1
#endif
#endif

#ifdef SHADOWFX_WORKER_ASAN
#include <sanitizer/lsan_interface.h>

// In sanitizer builds a SIGSEGV in glslang stays a signal, as in release builds, so that the compiler
// reports the same "signal 11" (ASan would print its report and exit). Every other sanitizer report ends
// the worker with kWorkerSanitizerExitStatus, which the compiler reports as a sanitizer finding, not as a
// crash of the HLSL compiler. UBSan has its own copy of these flags in GCC's runtime.
extern "C" const char* __asan_default_options() {
    return "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0:exitcode=86";
}
extern "C" const char* __ubsan_default_options() {
    return "exitcode=86";
}
static_assert(fx::kWorkerSanitizerExitStatus == 86, "the sanitizer options above name the exit status");

namespace {

// LeakSanitizer after every job (where detect_leaks is on; a no-op otherwise): a leak in glslang,
// SPIRV-Cross or our stage-compile code is then the finding of the compile that caused it. At exit it
// could not be: the worker ends with _exit, and an exit-time report would reach no compile.
bool jobLeftNoLeak() {
    return __lsan_do_recoverable_leak_check() == 0;
}

}  // namespace
#endif

int main() {
    // _exit: no static destructors after the compiler hung up (glslang's process-wide tables are not
    // torn down); leaks were checked after each job in sanitizer builds.
#ifdef SHADOWFX_WORKER_ASAN
    _exit(fx::serveCompileRequests(0, jobLeftNoLeak));
#else
    _exit(fx::serveCompileRequests(0));
#endif
}
