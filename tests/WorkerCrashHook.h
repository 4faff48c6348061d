// The compile workers' crash hook for the tests of a crash of the HLSL compiler: while one of these lives,
// a worker (this process's or a child's, which inherits the environment) dies of SIGSEGV on any unit that
// contains kWorkerCrashMarker, as glslang does on text it crashes on. tests/data/worker_crash.fx has the
// marker in its pixel shader.
#pragma once

#include <cstdlib>

namespace shadowfx::test {

inline constexpr const char* kWorkerCrashMarker = "fx_test_crash_here";

class WorkerCrashHook {
public:
    WorkerCrashHook() { setenv("SHADOWFX_COMPILE_WORKER_TEST_CRASH", kWorkerCrashMarker, 1); }
    ~WorkerCrashHook() { unsetenv("SHADOWFX_COMPILE_WORKER_TEST_CRASH"); }
    WorkerCrashHook(const WorkerCrashHook&) = delete;
    WorkerCrashHook& operator=(const WorkerCrashHook&) = delete;
};

}  // namespace shadowfx::test
