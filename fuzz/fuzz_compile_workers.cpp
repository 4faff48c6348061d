// Fuzz target: parse + fx::compileEffect through the compile worker processes (fx/CompileWorkers.h).
// glslang and SPIRV-Cross may crash or hang in a worker on these inputs; this process must not: every
// such failure has to come back as an error diagnostic, and the pool has to keep compiling.
#include "FuzzSupport.h"

#include <fx/CompileWorkers.h>

namespace {

fx::CompileWorkers& workers() {
    // Two workers, a time limit well under libFuzzer's -timeout: a hanging worker is our finding, not
    // a libFuzzer timeout.
    static fx::CompileWorkers pool(fx::CompileWorkerOptions{"", 2, 5000, 2048});
    if (!pool.available()) __builtin_trap();  // no worker executable: the target would test nothing
    return pool;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fx::CompileOptions options;
    options.isolation = fx::CompileIsolation::Workers;
    options.workers = &workers();
    return fuzz::compileInput(data, size, options);
}
