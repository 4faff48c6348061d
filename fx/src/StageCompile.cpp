// StageCompile: see StageCompile.h.
#include "StageCompile.h"

namespace fx {

StageOutcome compileStageInProcess(const StageJob& job) {
    StageOutcome outcome;
    HlslCompileResult spirv = compileHlslToSpirv(job.hlsl, job.stage, job.entryPoint);
    outcome.messages = std::move(spirv.messages);
    if (!spirv.success) {
        outcome.status = StageOutcome::Status::HlslFailed;
        return outcome;
    }
    if (!spirvToGlsl(spirv.spirv, job.stage, job.cross, outcome.program, outcome.crossError))
        outcome.status = StageOutcome::Status::CrossFailed;
    return outcome;
}

}  // namespace fx
