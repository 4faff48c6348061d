// GpuProgram: one compiled pass on the GPU: the linked GL program of its vertex and pixel stages and a
// uniform buffer per stage, filled from effect parameter values and compile arguments (UniformPacker).
#pragma once

#include "GlApi.h"

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace runtime {

// Writes values into a std140 uniform block image as the reflection describes it.
class UniformPacker {
public:
    // Packs `value` (HLSL element order, see fx/Value.h) into `block` at the member's offset, honouring
    // array and matrix strides and the GLSL matrix orientation.
    static void pack(const fx::UniformBinding& member, const fx::Value& value, std::vector<uint8_t>& block);
};

class GpuProgram {
public:
    // Compiles and links the pass's GLSL. Returns nullptr and reports LinkError (with the driver's log)
    // at the pass's location on failure.
    static std::unique_ptr<GpuProgram> create(const fx::CompiledPass& pass, fx::DiagnosticSink& diagnostics);
    ~GpuProgram();
    GpuProgram(const GpuProgram&) = delete;
    GpuProgram& operator=(const GpuProgram&) = delete;

    bool hasShaders() const { return mProgram != 0; }

    // Binds the program and uploads both stages' uniform blocks from `parameters` (one value per effect
    // parameter) and `arguments` (one value per CompiledPass::arguments entry).
    void use(const std::vector<fx::Value>& parameters, const std::vector<fx::Value>& arguments);

private:
    struct StageBlock {
        const fx::StageProgram* stage = nullptr;
        GLuint buffer = 0;
        std::vector<uint8_t> data;
    };
    GpuProgram() = default;

    GLuint mProgram = 0;
    StageBlock mBlocks[2];
};

}  // namespace runtime
