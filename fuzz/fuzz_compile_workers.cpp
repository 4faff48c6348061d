// Fuzz target: parse + fx::compileEffect through the compile worker processes (fx/CompileWorkers.h).
// glslang and SPIRV-Cross may crash or hang in a worker on these inputs; this process must not: every
// such failure has to come back as an error diagnostic, and the pool has to keep compiling.
#include "FuzzSupport.h"

#include <fx/CompileWorkers.h>
#include <fx/EffectCompiler.h>

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
    if (size > (64u << 10)) return 0;
    const std::string input = fuzz::text(data, size);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectSource(input, "fuzz/input.fx", fuzz::parseOptions(input), diagnostics);
    if (!effect) return 0;
    fx::CompileOptions options;
    options.isolation = fx::CompileIsolation::Workers;
    options.workers = &workers();
    std::unique_ptr<fx::CompiledEffect> compiled = fx::compileEffect(effect, options, diagnostics);
    if ((compiled != nullptr) == diagnostics.hasErrors()) __builtin_trap();
    (void)diagnostics.str();
    return 0;
}
