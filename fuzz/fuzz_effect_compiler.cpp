// Fuzz target 2: parse + fx::compileEffect (lowering, glslang HLSL -> SPIR-V, SPIRV-Cross -> GLSL), all in
// this process, so that crashes inside glslang and SPIRV-Cross show up as crashes here and get triaged
// (fuzz_compile_workers drives the same inputs through the worker processes).
#include "FuzzSupport.h"

#include <fx/EffectCompiler.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > (64u << 10)) return 0;  // glslang is slow on huge units; the parser target covers size
    const std::string input = fuzz::text(data, size);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectSource(input, "fuzz/input.fx", fuzz::parseOptions(input), diagnostics);
    if (!effect) return 0;
    fx::CompileOptions options;
    options.isolation = fx::CompileIsolation::InProcess;
    std::unique_ptr<fx::CompiledEffect> compiled = fx::compileEffect(effect, options, diagnostics);
    if ((compiled != nullptr) == diagnostics.hasErrors()) __builtin_trap();
    (void)diagnostics.str();
    return 0;
}
