// Fuzz target 2: parse + fx::compileEffect (lowering, glslang HLSL -> SPIR-V, SPIRV-Cross -> GLSL), all in
// this process, so that crashes inside glslang and SPIRV-Cross show up as crashes here and get triaged
// (fuzz_compile_workers drives the same inputs through the worker processes).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fx::CompileOptions options;
    options.isolation = fx::CompileIsolation::InProcess;
    return fuzz::compileInput(data, size, options);
}
