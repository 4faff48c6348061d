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
        Crashed,          // the worker died (`signal`, 0 if it exited) before it answered
        TimedOut,         // the worker took longer than the time limit and was killed
        WorkerFailed,     // no worker could be started, or it answered something unreadable: `crossError`
        SanitizerReport,  // the worker stopped on a sanitizer finding (kWorkerSanitizerExitStatus)
    };
    Status status = Status::Compiled;
    std::vector<HlslMessage> messages;  // glslang's errors and warnings (any status)
    std::string crossError;
    int signal = 0;
    // Filled when Compiled: glsl, uniform block, uniforms, samplers and inputs (stage, entry point,
    // profile, hlsl and hash are the caller's).
    StageProgram program;
};

// Runs both compilers in this process. A crash in either takes the process down: that is what workers
// are for.
StageOutcome compileStageInProcess(const StageJob& job);

}  // namespace fx
