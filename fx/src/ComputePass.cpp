// ComputePass: a pass that sets a compute shader (D3D11's SetComputeShader, D3D9-style `ComputeShader =
// compile cs_5_0 CS();`, or a ComputeShader variable) compiled as a compute pass: the compute stage alone,
// which the application or the pass's script dispatches (docs/d3d10.md, "Compute shaders and read-write
// resources").
#include "Compiler.h"

#include <fx/RenderStates.h>

namespace fx::detail {

namespace {

bool setsShader(const StateAssignment& s) {
    return !(s.value.kind == Expr::Kind::Identifier && (s.value.text == "NULL" || s.value.text == "null")) &&
           !(s.value.kind == Expr::Kind::Number && s.value.number == 0);
}

}  // namespace

bool Compiler::computePass(const Pass& p, CompiledPass& pass, PassSlot slot) {
    const StateAssignment* compute = nullptr;
    for (const StateAssignment& s : p.states)
        if (findRenderState(s.name) == RenderStateId::ComputeShader && setsShader(s)) compute = &s;
    if (!compute) return false;
    // FX11 lets one pass set both kinds, the draw taking the graphics stages and Dispatch the compute one;
    // shadowfx keeps a pass one or the other, so that what a pass runs is what its script or the
    // application does with it.
    for (const StateAssignment& s : p.states) {
        const std::optional<RenderStateId> id = findRenderState(s.name);
        const bool graphics = id == RenderStateId::VertexShader || id == RenderStateId::PixelShader ||
                              id == RenderStateId::GeometryShader || id == RenderStateId::HullShader ||
                              id == RenderStateId::DomainShader;
        if (graphics && setsShader(s)) {
            unsupported(DiagId::ComputePassWithOtherStages, compute->loc, {s.name});
            return true;
        }
    }
    if (const Expr* compile = shaderExpr(*compute)) compileStage(*compile, ShaderStage::Compute, pass, slot);
    return true;
}

}  // namespace fx::detail
