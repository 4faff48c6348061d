// StageCompile: one stage's generated HLSL unit -> GLSL + reflection (glslang, then SPIRV-Cross), the unit
// of work a compile worker process runs (CompileWorkers.h) and that the in-process mode runs directly.
#pragma once

#include "HlslToSpirv.h"
#include "SpirvToGlsl.h"

#include <fx/CompiledEffect.h>

#include <string>
#include <vector>

namespace fx {

struct StageJob {
    std::string hlsl;
    ShaderStage stage = ShaderStage::Vertex;
    std::string entryPoint;
    CrossOptions cross;
};

struct StageOutcome {
    enum class Status {
        Compiled,         // `program` holds GLSL and reflection
        HlslFailed,       // glslang rejected the unit: `messages` say why
        CrossFailed,      // SPIRV-Cross threw: `crossError`
        Crashed,          // the worker died or exited before it answered: `fault`
        TimedOut,         // the worker took longer than the time limit and was killed
        WorkerFailed,     // no worker could be started, or it answered something unreadable: `fault`
        SanitizerReport,  // the worker stopped on a sanitizer finding (kWorkerSanitizerExitStatus):
                          // `fault`
    };
    Status status = Status::Compiled;
    std::vector<HlslMessage> messages;  // glslang's errors and warnings (any status)
    std::string crossError;
    // What the worker pool reports for Crashed, WorkerFailed and SanitizerReport (set in this process,
    // never sent).
    DiagId fault = DiagId::CompileWorkerFailed;
    std::vector<std::string> faultArguments;
    // Filled when Compiled: glsl, uniform block, uniforms, samplers and inputs (stage, entry point,
    // profile, hlsl and hash are the caller's).
    StageProgram program;
};

// Runs both compilers in this process. A crash in either takes the process down: that is what workers
// are for.
StageOutcome compileStageInProcess(const StageJob& job);

}  // namespace fx
