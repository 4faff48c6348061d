// Fuzz target: parse + fx::compileEffect through the compile worker processes (fx/CompileWorkers.h).
// glslang and SPIRV-Cross may crash or hang in a worker on these inputs; this process must not: every
// such failure has to come back as an error diagnostic, and the pool has to keep compiling. A worker that
// stops on a sanitizer report is not such a failure: it traps, so that libFuzzer keeps the input.
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
    // glslang's crashes (signals) are the isolation's business and come back as diagnostics; a sanitizer
    // report in a worker (a memory error or a leak, printed above) is a finding of this target.
    return fuzz::compileInput(data, size, options, [](const fx::DiagnosticList& diagnostics) {
        for (const fx::Diagnostic& d : diagnostics.items())
            if (d.id == fx::DiagId::CompileWorkerSanitizerReport ||
                d.id == fx::DiagId::CompileWorkerSanitizerReportWhileIdle)
                __builtin_trap();
    });
}
