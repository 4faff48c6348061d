// SpirvToGlsl: SPIR-V -> desktop GLSL 4.50 core with SPIRV-Cross, plus the reflection the runtime binds
// by: the stage's uniform block (renamed per stage, fixed binding), its members, the samplers and the
// vertex inputs.
#pragma once

#include <fx/CompiledEffect.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fx {

struct CrossOptions {
    std::string uniformBlockName;  // the $Global block's new name ("fx_VsGlobals")
    int uniformBlockBinding = 0;   // its binding point
    // Texture unit per effect sampler name; samplers not listed keep unit 0.
    std::map<std::string, int> samplerUnits;
    // Effect samplers whose GLSL sampler is the combined (fx_depth_S, fx_cmp_S) comparison sampler.
    std::vector<std::string> depthSamplers;
};

// Fills `program.glsl`, `uniformBlockName/Binding/Size`, `uniforms` (name, offset, size, strides,
// hlslColumnsContiguous; source/index/type are resolved by the caller), `samplers` (glslName, unit,
// depthCompare) and `inputs` (vertex stage). Returns false with `error` set on failure.
bool spirvToGlsl(const std::vector<uint32_t>& spirv, ShaderStage stage, const CrossOptions& options,
                 StageProgram& program, std::string& error);

std::string spirvToGlslOptionsKey();

}  // namespace fx
