// HlslToSpirv: one HLSL unit -> SPIR-V, behind one small interface. Today glslang's HLSL front end (its
// DX9-compatible mode is what accepts sampler2D/tex2D); glslang deprecates that front end upstream, and
// DXC could take its place behind the same function.
#pragma once

#include <fx/CompiledEffect.h>

#include <cstdint>
#include <string>
#include <vector>

namespace fx {

struct HlslMessage {
    bool error = true;
    std::string file;  // from #line ("" when glslang gave none)
    int line = 0;
    int column = 0;
    std::string text;
};

struct HlslCompileResult {
    bool success = false;
    std::vector<uint32_t> spirv;
    std::vector<HlslMessage> messages;
    std::string log;  // glslang's raw info log, for debugging
};

// The text of the warning compileHlslToSpirv adds for each implicit vector truncation glslang made:
// "implicit truncation of vector type: 'float4' to 'float3'" (fxc's X3206).
constexpr const char* kImplicitTruncationPrefix = "implicit truncation of vector type: ";

// Compiles `source` for `stage` with entry point `entryPoint` (SPIR-V 1.0, Vulkan client rules).
HlslCompileResult compileHlslToSpirv(const std::string& source, ShaderStage stage,
                                     const std::string& entryPoint);

// The options that change the produced SPIR-V, folded into cache keys.
std::string hlslToSpirvOptionsKey();

// Parses glslang info-log lines ("ERROR: file:line:column: message").
std::vector<HlslMessage> parseGlslangLog(const std::string& log);

}  // namespace fx
