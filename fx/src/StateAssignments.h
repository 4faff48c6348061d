// StateAssignments: what a pass's and a state object's assignments mean, resolved once the parser has read
// them: enum names to numbers, CompileShader(...) to a Compile expression, shader values checked, D3D10
// state objects expanded into the D3D9 pass states they set (RenderStateDefs.h). Private to fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>
#include <fx/RenderStates.h>

#include "ConstantFolding.h"
#include "Lexer.h"

#include <functional>
#include <string>
#include <vector>

namespace fx::detail {

// A sampler_state name (MinFilter, AddressU, Texture, ...) or `Sampler`, any case: in a pass, a state of a
// D3D9 sampler register rather than a render state.
bool isSamplerRegisterState(std::string_view name);

class StateAssignments {
public:
    // Reports an error where the parser reports its own (its count and limit, its speculative mode).
    using ReportError = std::function<void(DiagId, const SourceLoc&, const std::vector<std::string>&)>;
    StateAssignments(const Effect& effect, ReportError error) : mEffect(effect), mError(std::move(error)) {}

    // SetRasterizerState(rs), SetDepthStencilState(ds, stencilRef), SetBlendState(bs, factor, sampleMask):
    // the object's fields (its block, D3D10 defaults for the rest) become the pass's states.
    // True when the object was set (the pass then takes nothing of it from D3D10's defaults).
    bool setStateObject(Pass& pass, const Token& name, StateObjectKind kind, std::vector<Expr>& args);
    // Every field of a state object of `kind` as pass states: the block's value, or D3D10's default.
    void expandStateObject(StateObjectKind kind, const std::vector<StateAssignment>& block,
                           const SourceLoc& loc, std::vector<StateAssignment>& out);
    // D3DX's effect compiler took `null` (any case) for `NULL`; spell it one way for what follows.
    static void normalizeNull(Expr& e);
    // CompileShader(vs_4_0, VS(args)) -> Compile expression, anywhere in `e`.
    void normalizeCompileShader(Expr& e);
    void validateShaderValue(StateAssignment& state);
    // Replaces enum names by their numbers, leaves parameter names, reports anything else.
    void resolveStateValue(Expr& e, StateDomain domain, const std::string& stateName);
    // A D3D9 pass's state of sampler register N (`MinFilter[N] = LINEAR;`, `Texture[N] = <t>;`,
    // `Sampler[N] = (s);`): the name spelled as the table does, the index 0 when left out, the value
    // resolved (enum names to numbers, the texture or sampler checked). False after an error.
    bool resolveSamplerRegisterState(StateAssignment& state);
    // The kind of state object a RasterizerState, DepthStencilState or BlendState variable holds.
    static StateObjectKind objectKind(BaseType base);

private:
    static Expr numberExpr(double value, const SourceLoc& loc);
    // `rs[i]` with `i` a parameter: each state selects its element's value by `i` when the pass is applied
    // (i == 0 ? v0 : i == 1 ? v1 : ... : vN-1; an index outside the array takes the last element); a state
    // every element gives the same constant stays that constant. False after an error.
    bool expandIndexedStateObject(StateObjectKind kind, const Parameter& array, const Expr& index,
                                  const SourceLoc& loc, std::vector<StateAssignment>& out);
    // A BlendState field for render targets 1..7 (D3D10's independent blend, GL's glBlendFuncSeparatei and
    // friends): `BlendEnable[i]` is each target's own (FALSE unless set, as D3D10 has it); the factors and
    // operations are target 0's unless indexed (D3D10.0 has one set for all targets, D3D10.1 and FX11 one
    // per target); `RenderTargetWriteMask[i]` sets target i's write mask (the runtime draws into four).
    template <typename Find, typename Push>
    void expandTargetBlend(const StateObjectField& field, const SourceLoc& loc, Find& find, Push& push);
    static bool isEnumDomain(StateDomain domain);
    void error(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        mError(id, loc, args);
    }
    bool constantValue(const Expr& e, double& out) const { return foldConstant(mEffect, e, out); }

    const Effect& mEffect;  // the declarations parsed so far
    ReportError mError;
};

}  // namespace fx::detail
