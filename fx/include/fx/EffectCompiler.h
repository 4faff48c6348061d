// EffectCompiler: Effect syntax tree -> CompiledEffect. For every pass: lower to one HLSL unit per stage
// (PassLowering), HLSL -> SPIR-V (glslang), SPIR-V -> GLSL 4.50 + reflection (SPIRV-Cross). Also
// resolves textures, samplers, initial values and scripts. Compiled stages are cached by the hash of
// their generated source, so an unchanged pass is never recompiled.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <memory>
#include <string>

namespace fx {

class CompileCache;    // fx/CompileCache.h
class CompileWorkers;  // fx/CompileWorkers.h

// Where glslang and SPIRV-Cross run. Workers: in worker processes (fx/CompileWorkers.h), so that a crash
// in either becomes a located error; in this process (with a warning) if no worker executable is found.
// InProcess: here, sequentially; a crash in either library ends the program (what the fuzzers want).
enum class CompileIsolation { Workers, InProcess };

struct CompileOptions {
    std::string technique;            // compile only this technique ("" = all)
    CompileCache* cache = nullptr;    // optional; shared across compiles (hot reload)
    int maxRenderTargetSize = 16384;  // largest render-target side (Dimensions, width/height) accepted
    int maxScriptLoopCount =
        1024;  // largest LoopByCount: literal counts here, parameter values in the runtime
    CompileIsolation isolation = CompileIsolation::Workers;
    CompileWorkers* workers = nullptr;  // the pool to use; nullptr = CompileWorkers::shared()
};

// Returns nullptr if any error was reported.
std::unique_ptr<CompiledEffect> compileEffect(std::shared_ptr<const Effect> effect,
                                              const CompileOptions& options, DiagnosticSink& diagnostics);

}  // namespace fx
