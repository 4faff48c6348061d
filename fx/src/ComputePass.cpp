// ComputePass: a pass that sets a compute shader (D3D11's SetComputeShader, D3D9-style `ComputeShader =
// compile cs_5_0 CS();`, or a ComputeShader variable): its compute stage, which the application or the
// pass's script dispatches (docs/d3d10.md, "Compute shaders and read-write resources"). A pass that also
// sets graphics shaders keeps both, as FX11 did: a dispatch runs the compute stage, a draw the others.
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
    if (const Expr* compile = shaderExpr(*compute)) compileStage(*compile, ShaderStage::Compute, pass, slot);
    for (const StateAssignment& s : p.states) {
        const std::optional<RenderStateId> id = findRenderState(s.name);
        const bool graphics = id == RenderStateId::VertexShader || id == RenderStateId::PixelShader ||
                              id == RenderStateId::GeometryShader || id == RenderStateId::HullShader ||
                              id == RenderStateId::DomainShader;
        if (graphics && setsShader(s)) return false;  // the graphics stages too
    }
    return true;
}

}  // namespace fx::detail
