// StateAssignments: see StateAssignments.h.
#include "StateAssignments.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

namespace fx::detail {

StateObjectKind StateAssignments::objectKind(BaseType base) {
    return base == BaseType::RasterizerState     ? StateObjectKind::Rasterizer
           : base == BaseType::DepthStencilState ? StateObjectKind::DepthStencil
                                                 : StateObjectKind::Blend;
}

// SetRasterizerState(rs), SetDepthStencilState(ds, stencilRef), SetBlendState(bs, factor, sampleMask):
// the object's fields (its block, D3D10 defaults for the rest) become the pass's states.
bool StateAssignments::setStateObject(Pass& pass, const Token& name, StateObjectKind kind,
                                      std::vector<Expr>& args) {
    const size_t expected = kind == StateObjectKind::Rasterizer     ? 1
                            : kind == StateObjectKind::DepthStencil ? 2
                                                                    : 3;
    if (args.size() != expected) {
        error(DiagId::StateObjectArgumentCount, name.loc,
              {name.text, std::to_string(expected), std::to_string(args.size())});
        return false;
    }
    const Expr& object = args[0];
    const std::vector<StateAssignment>* block = nullptr;
    static const std::vector<StateAssignment> kNone;
    if (object.kind == Expr::Kind::Identifier && equalsIgnoreCase(object.text, "NULL")) {
        block = &kNone;  // NULL: the D3D10 defaults
    } else if (object.kind == Expr::Kind::Identifier) {
        const Parameter* p = mEffect.findParameter(object.text);
        if (!p) {
            error(DiagId::UnknownIdentifier, object.loc, {object.text});
            return false;
        }
        if (!p->type.isStateObject() || objectKind(p->type.base) != kind) {
            error(DiagId::StateObjectOfOtherKind, object.loc,
                  {name.text, object.text, std::string(stateObjectTypeName(kind))});
            return false;
        }
        block = &p->objectState;
    } else if (object.kind == Expr::Kind::Index && object.args.size() == 2 &&
               object.args[0].kind == Expr::Kind::Identifier) {
        // An element of a state-object array: `rs[1]`, or `rs[Choice]` indexed by a parameter.
        const Expr& array = object.args[0];
        const Parameter* p = mEffect.findParameter(array.text);
        if (!p) {
            error(DiagId::UnknownIdentifier, array.loc, {array.text});
            return false;
        }
        if (!p->type.isStateObject() || objectKind(p->type.base) != kind || p->objectStateElements.empty()) {
            error(DiagId::StateObjectNotArray, array.loc,
                  {name.text, array.text, std::string(stateObjectTypeName(kind))});
            return false;
        }
        const size_t size = p->objectStateElements.size();
        double index = 0;
        if (!constantValue(object.args[1], index)) {
            if (!expandIndexedStateObject(kind, *p, object.args[1], name.loc, pass.states)) return false;
        } else if (!(index >= 0 && index < static_cast<double>(size)) || index != std::trunc(index)) {
            error(DiagId::StateObjectIndexOutOfBounds, object.args[1].loc,
                  {object.args[1].str(), p->name, std::to_string(size)});
            return false;
        } else {
            block = &p->objectStateElements[static_cast<size_t>(index)];
        }
    } else {
        error(DiagId::StateObjectNameExpected, object.loc,
              {name.text, std::string(stateObjectTypeName(kind))});
        return false;
    }
    if (block) expandStateObject(kind, *block, name.loc, pass.states);
    auto add = [&](RenderStateId id, Expr value) {
        StateAssignment state;
        state.name = std::string(renderStateInfo(id).name);
        state.loc = value.loc.valid() ? value.loc : name.loc;
        state.value = std::move(value);
        resolveStateValue(state.value, renderStateInfo(id).domain, state.name);
        pass.states.push_back(std::move(state));
    };
    if (kind == StateObjectKind::DepthStencil) add(RenderStateId::StencilRef, std::move(args[1]));
    if (kind == StateObjectKind::Blend) {
        // D3D10's blend factor is a float4; the state table's BlendFactor a packed D3DCOLOR.
        Expr& factor = args[1];
        double rgba[4];
        if ((factor.kind == Expr::Kind::InitList ||
             (factor.kind == Expr::Kind::Call && factor.text == "float4")) &&
            factor.args.size() == 4 &&
            std::all_of(factor.args.begin(), factor.args.end(),
                        [&, i = 0](const Expr& c) mutable { return constantValue(c, rgba[i++]); })) {
            auto channel = [](double x) {
                return static_cast<uint32_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255));
            };
            const uint32_t packed =
                channel(rgba[3]) << 24 | channel(rgba[0]) << 16 | channel(rgba[1]) << 8 | channel(rgba[2]);
            factor = numberExpr(static_cast<double>(packed), factor.loc);
        }
        add(RenderStateId::BlendFactor, std::move(factor));
        add(RenderStateId::SampleMask, std::move(args[2]));
    }
    return true;
}

bool StateAssignments::expandIndexedStateObject(StateObjectKind kind, const Parameter& array,
                                                const Expr& index, const SourceLoc& loc,
                                                std::vector<StateAssignment>& out) {
    std::vector<std::vector<StateAssignment>> elements(array.objectStateElements.size());
    for (size_t e = 0; e < elements.size(); ++e)
        expandStateObject(kind, array.objectStateElements[e], loc, elements[e]);
    // Every element expands to the same states but where a blend state masks its targets differently.
    for (size_t e = 1; e < elements.size(); ++e) {
        bool same = elements[e].size() == elements[0].size();
        for (size_t k = 0; same && k < elements[0].size(); ++k)
            same = elements[e][k].name == elements[0][k].name;
        if (!same) {
            error(DiagId::StateObjectDynamicIndexFields, index.loc, {array.name, std::to_string(e)});
            return false;
        }
    }
    for (size_t k = 0; k < elements[0].size(); ++k) {
        StateAssignment state = elements[0][k];
        double first = 0, other = 0;
        bool agree = constantValue(state.value, first);
        for (size_t e = 1; agree && e < elements.size(); ++e)
            agree = constantValue(elements[e][k].value, other) && other == first;
        if (!agree) {
            Expr select = elements.back()[k].value;
            for (size_t e = elements.size() - 1; e-- > 0;) {
                Expr test;
                test.kind = Expr::Kind::Binary;
                test.text = "==";
                test.loc = index.loc;
                test.args = {index, numberExpr(static_cast<double>(e), index.loc)};
                Expr choice;
                choice.kind = Expr::Kind::Ternary;
                choice.loc = index.loc;
                choice.args = {std::move(test), elements[e][k].value, std::move(select)};
                select = std::move(choice);
            }
            state.value = std::move(select);
        }
        out.push_back(std::move(state));
    }
    return true;
}

Expr StateAssignments::numberExpr(double value, const SourceLoc& loc) {
    Expr e;
    e.kind = Expr::Kind::Number;
    e.number = value;
    e.isInteger = value == std::trunc(value);
    e.loc = loc;
    return e;
}

// Every field of a state object of `kind` as pass states: the block's value, or D3D10's default.
void StateAssignments::expandStateObject(StateObjectKind kind, const std::vector<StateAssignment>& block,
                                         const SourceLoc& loc, std::vector<StateAssignment>& out) {
    auto find = [&](std::string_view field, int index) -> const StateAssignment* {
        const StateAssignment* found = nullptr;
        for (const StateAssignment& a : block)
            if (equalsIgnoreCase(a.name, field) && (a.index < 0 ? 0 : a.index) == index) found = &a;
        return found;  // the last assignment wins, as in a pass
    };
    auto push = [&](RenderStateId id, Expr value, const SourceLoc& at) {
        StateAssignment state;
        state.name = std::string(renderStateInfo(id).name);
        state.loc = at;
        state.value = std::move(value);
        out.push_back(std::move(state));
    };
    for (const StateObjectField* field : stateObjectFields(kind)) {
        const StateAssignment* a = find(field->name, 0);
        if (field->name == "FrontCounterClockwise") continue;  // folded into CullMode below
        if (field->name == "CullMode") {
            // D3D9's CullMode names the winding that is culled (CW or CCW), D3D10's the facing (FRONT or
            // BACK) with FrontCounterClockwise saying which winding faces front.
            const StateAssignment* ccw = find("FrontCounterClockwise", 0);
            double cull = field->defaultValue, frontCcw = 0;
            if ((a && !constantValue(a->value, cull)) || (ccw && !constantValue(ccw->value, frontCcw))) {
                error(DiagId::CullWindingNotConstant,
                      (a && !constantValue(a->value, cull) ? a : ccw)->value.loc, {a ? a->name : ccw->name});
                continue;
            }
            double d3d9 = cull == 1 ? 1 : (frontCcw != 0) == (cull == 3) ? 2 : 3;
            push(RenderStateId::CullMode, numberExpr(d3d9, a ? a->loc : loc), a ? a->loc : loc);
            continue;
        }
        push(field->state, a ? a->value : numberExpr(field->defaultValue, loc), a ? a->loc : loc);
        if (kind == StateObjectKind::Blend) expandTargetBlend(*field, loc, find, push);
    }
    if (kind == StateObjectKind::DepthStencil)
        push(RenderStateId::TwoSidedStencilMode, numberExpr(1, loc), loc);
    if (kind == StateObjectKind::Blend) {
        push(RenderStateId::SeparateAlphaBlendEnable, numberExpr(1, loc), loc);
        push(RenderStateId::IndependentBlendEnable, numberExpr(1, loc), loc);
    }
}

// A BlendState field for render targets 1..7 (D3D10's independent blend, GL's glBlendFuncSeparatei and
// friends): `BlendEnable[i]` is each target's own (FALSE unless set, as D3D10 has it); the factors and
// operations are target 0's unless indexed (D3D10.0 has one set for all targets, D3D10.1 and FX11 one
// per target); `RenderTargetWriteMask[i]` sets target i's write mask (the runtime draws into four).
template <typename Find, typename Push>
void StateAssignments::expandTargetBlend(const StateObjectField& field, const SourceLoc& loc, Find& find,
                                         Push& push) {
    const std::string_view target0 = renderStateInfo(field.state).name;
    for (int index = 1; index < 8; ++index) {
        const StateAssignment* own = find(field.name, index);
        const std::optional<RenderStateId> state =
            findRenderState(std::string(target0) + std::to_string(index));
        if (field.name == "RenderTargetWriteMask" && index >= 4) {
            double mask = 0;
            if (own && !(constantValue(own->value, mask) && mask == 15))
                error(DiagId::WriteMaskTargetNeverBound, own->loc, {std::to_string(index)});
            continue;
        }
        if (!state) {  // AlphaToCoverageEnable: one for the whole blend state
            if (own) error(DiagId::StateTakesNoTargetIndex, own->loc, {std::string(field.name)});
            continue;
        }
        const StateAssignment* source = own                           ? own
                                        : field.name == "BlendEnable" ? nullptr
                                                                      : find(field.name, 0);
        if (!own && field.name == "RenderTargetWriteMask") continue;  // the state's default, 15
        const SourceLoc at = source ? source->loc : loc;
        push(*state, source ? source->value : numberExpr(field.defaultValue, at), at);
    }
}

// D3DX's effect compiler took `null` (any case) for `NULL`; spell it one way for what follows.
void StateAssignments::normalizeNull(Expr& e) {
    if (e.kind == Expr::Kind::Identifier && equalsIgnoreCase(e.text, "NULL")) e.text = "NULL";
}

// CompileShader(vs_4_0, VS(args)) -> Compile expression, anywhere in `e`.
void StateAssignments::normalizeCompileShader(Expr& e) {
    for (Expr& arg : e.args) normalizeCompileShader(arg);
    if (e.kind != Expr::Kind::Call || e.text != "CompileShader") return;
    if (e.args.size() != 2 || e.args[0].kind != Expr::Kind::Identifier ||
        e.args[1].kind != Expr::Kind::Call) {
        error(DiagId::CompileShaderCallInvalid, e.loc, {});
        return;
    }
    Expr compiled;
    compiled.kind = Expr::Kind::Compile;
    compiled.loc = e.loc;
    compiled.profile = e.args[0].text;
    compiled.text = e.args[1].text;
    compiled.args = std::move(e.args[1].args);
    e = std::move(compiled);
}

void StateAssignments::validateShaderValue(StateAssignment& state) {
    Expr& v = state.value;
    if (v.kind == Expr::Kind::Compile) return;
    // Stream output (checked by the parser, lowered by the compiler): a geometry shader's value only.
    if (v.kind == Expr::Kind::Call && v.text == "ConstructGSWithSO" && state.name == "GeometryShader") return;
    if (v.kind == Expr::Kind::Identifier) {
        if (v.text == "NULL") return;
        const Parameter* p = mEffect.findParameter(v.text);
        if (p && (p->type.base == BaseType::VertexShader || p->type.base == BaseType::PixelShader ||
                  p->type.base == BaseType::GeometryShader || p->type.base == BaseType::HullShader ||
                  p->type.base == BaseType::DomainShader || p->type.base == BaseType::ComputeShader))
            return;
        if (!p) {
            error(DiagId::UnknownIdentifier, v.loc, {v.text});
            return;
        }
    }
    if (v.kind == Expr::Kind::Number && v.number == 0) return;
    if (v.kind == Expr::Kind::Index && !v.args.empty() && v.args[0].kind == Expr::Kind::Identifier) {
        const Parameter* p = mEffect.findParameter(v.args[0].text);
        if (p && (p->type.base == BaseType::VertexShader || p->type.base == BaseType::PixelShader) &&
            !p->type.arrayDims.empty())
            return;  // an element of a shader array (EffectCompiler resolves the index)
    }
    error(DiagId::ShaderStateValueExpected, v.loc, {state.name});
}

bool isSamplerRegisterState(std::string_view name) {
    return equalsIgnoreCase(name, "Sampler") || findSamplerState(name).has_value();
}

bool StateAssignments::resolveSamplerRegisterState(StateAssignment& state) {
    if (state.index < 0) state.index = 0;  // `Texture = <t>;` in a pass is stage 0's
    Expr& v = state.value;
    if (equalsIgnoreCase(state.name, "Sampler")) {
        state.name = "Sampler";
        const Parameter* sampler = v.kind == Expr::Kind::Identifier || v.kind == Expr::Kind::TextureRef
                                       ? mEffect.findParameter(v.text)
                                       : nullptr;
        if (!sampler) {
            error(
                v.kind == Expr::Kind::Identifier || v.kind == Expr::Kind::TextureRef
                    ? DiagId::UnknownIdentifier
                    : DiagId::SamplerStateValueExpected,
                v.loc,
                {v.kind == Expr::Kind::Identifier || v.kind == Expr::Kind::TextureRef ? v.text : state.name});
            return false;
        }
        if (!sampler->type.isSampler() || !sampler->type.arrayDims.empty()) {
            error(DiagId::SamplerStateNotSampler, v.loc, {state.name, v.text, sampler->type.hlslName()});
            return false;
        }
        v.kind = Expr::Kind::Identifier;
        return true;
    }
    const SamplerStateId id = *findSamplerState(state.name);
    const StateInfo& info = samplerStateInfo(id);
    state.name = std::string(info.name);
    if (info.domain != StateDomain::TextureRef) {
        resolveStateValue(v, info.domain, state.name);
        return true;
    }
    if (v.kind == Expr::Kind::Identifier) v.kind = Expr::Kind::TextureRef;  // (t) and t
    if (v.kind != Expr::Kind::TextureRef) {
        error(DiagId::TextureStateValueExpected, v.loc, {state.name});
        return false;
    }
    const Parameter* texture = mEffect.findParameter(v.text);
    if (!texture) {
        error(DiagId::UnknownIdentifier, v.loc, {v.text});
        return false;
    }
    if (!texture->type.isTexture()) {
        error(DiagId::TextureStateNotTexture, v.loc, {state.name, v.text, texture->type.hlslName()});
        return false;
    }
    return true;
}

bool StateAssignments::isEnumDomain(StateDomain domain) {
    switch (domain) {
        case StateDomain::Bool:
        case StateDomain::Int:
        case StateDomain::Float:
        case StateDomain::Color:
        case StateDomain::Vector:
        case StateDomain::Matrix:
        case StateDomain::Shader:
        case StateDomain::TextureRef:
            return false;
        default:
            return true;
    }
}

// Replaces enum names by their numbers, leaves parameter names, reports anything else.
void StateAssignments::resolveStateValue(Expr& e, StateDomain domain, const std::string& stateName) {
    switch (e.kind) {
        case Expr::Kind::Identifier: {
            if (isEnumDomain(domain) || domain == StateDomain::Bool) {
                if (std::optional<double> value = findEnumValue(domain, e.text)) {
                    SourceLoc loc = e.loc;
                    e = Expr{};
                    e.kind = domain == StateDomain::Bool ? Expr::Kind::Bool : Expr::Kind::Number;
                    e.number = *value;
                    e.isInteger = true;
                    e.loc = loc;
                    return;
                }
            }
            if (mEffect.findParameter(e.text)) return;
            if (isEnumDomain(domain) || domain == StateDomain::Bool) {
                std::string names;
                for (std::string_view n : enumValueNames(domain))
                    names += (names.empty() ? "" : ", ") + std::string(n);
                error(DiagId::UnknownStateValue, e.loc, {e.text, stateName, names});
            } else {
                error(DiagId::UnknownIdentifier, e.loc, {e.text});
            }
            return;
        }
        case Expr::Kind::TextureRef:
            // `MinFilter = <g_MinFilter>;`: D3DX's reference to a parameter, whose value the state takes.
            if (domain != StateDomain::TextureRef)
                if (const Parameter* p = mEffect.findParameter(e.text); p && !p->type.isTexture())
                    e.kind = Expr::Kind::Identifier;
            return;
        case Expr::Kind::Bool:
            // MonoGame's `ColorWriteEnable = true;` writes every channel, not only red (1).
            if (domain == StateDomain::ColorMask) {
                e.kind = Expr::Kind::Number;
                e.number = e.number != 0 ? 15 : 0;
            }
            return;
        case Expr::Kind::String:  // `ZEnable = "yes";` was kept and read as 0
            if (domain != StateDomain::TextureRef) error(DiagId::StateValueIsString, e.loc, {stateName});
            return;
        case Expr::Kind::Unary:
        case Expr::Kind::Binary:
        case Expr::Kind::InitList:
            for (Expr& arg : e.args) resolveStateValue(arg, domain, stateName);
            break;
        case Expr::Kind::Ternary:
            if (e.args.size() == 3) {
                resolveStateValue(e.args[1], domain, stateName);
                resolveStateValue(e.args[2], domain, stateName);
            }
            break;
        default:
            break;
    }
    // RED|GREEN|BLUE -> one number
    if (e.kind == Expr::Kind::Binary && e.text == "|" && e.args.size() == 2 &&
        e.args[0].kind == Expr::Kind::Number && e.args[1].kind == Expr::Kind::Number && e.args[0].isInteger &&
        e.args[1].isInteger && std::abs(e.args[0].number) < 9e15 && std::abs(e.args[1].number) < 9e15) {
        // (bounded: casting 1e30 to long long is undefined behaviour)
        double value = static_cast<double>(static_cast<long long>(e.args[0].number) |
                                           static_cast<long long>(e.args[1].number));
        SourceLoc loc = e.args[0].loc;
        e = Expr{};
        e.kind = Expr::Kind::Number;
        e.number = value;
        e.isInteger = true;
        e.loc = loc;
    }
}

}  // namespace fx::detail
