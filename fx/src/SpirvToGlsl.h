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
    // GL_SHADER_STORAGE_BUFFER binding point per effect storage-block parameter name, and of the block of
    // its hidden counter (Compiler::storageBindings): every stage of every pass declares a parameter's
    // block at the same point, whatever GLSL names SPIRV-Cross gives blocks that share one type.
    std::map<std::string, int> storageBindings;
    std::map<std::string, int> counterBindings;
    // Effect samplers whose GLSL sampler is the combined (fx_depth_S, fx_cmp_S) comparison sampler.
    std::vector<std::string> depthSamplers;
};

// Fills `program.glsl`, `uniformBlockName/Binding/Size`, `uniforms` (name, offset, size, strides,
// hlslColumnsContiguous; source/index/type are resolved by the caller), `samplers` (glslName, unit,
// depthCompare, read) and `inputs` (vertex stage). Returns false with `error` set on failure.
bool spirvToGlsl(const std::vector<uint32_t>& spirv, ShaderStage stage, const CrossOptions& options,
                 StageProgram& program, std::string& error);

std::string spirvToGlslOptionsKey();

// Dual-source blending (D3D10's SRC1_* factors) reads the pixel shader's SV_Target1 as the second source of
// target 0, which GL takes from the output at location 0, index 1. glslang's HLSL has no attribute for the
// index, so a fragment stage's location-1 output is redeclared in its GLSL.
void declareDualSourceOutput(std::string& fragmentGlsl);

// Declares the uniform `name` (a sampler or image SPIRV-Cross declared, on a line of its own) at `binding`
// in `glsl`: a binding glslang gave it is replaced, other layout qualifiers (an image's format) kept. For
// the units the effect compiler assigns once every stage of a pass is known (D3D10 pairs, images), so that
// the runtime finds no uniform by name. False where `glsl` declares no uniform `name` (SPIRV-Cross renames a
// name GLSL reserves, `output`, or one with "__"): the stage is left as it is.
bool declareBinding(std::string& glsl, std::string_view name, int binding);

}  // namespace fx
