// Parser: techniques, passes and state blocks (see Parser.h); what the states mean: StateAssignments.h.
#include "Parser.h"

#include "ConstantFolding.h"
#include "StreamOutDeclaration.h"

#include <cmath>

namespace fx::detail {

bool Parser::isTechniqueKeyword(const Token& token) {
    return token.is("technique") || token.is("technique10") || token.is("technique11");
}

void Parser::parseGroup() {
    const Token& keyword = advance();
    const Token& name = expectIdentifier("a group name");
    if (check("<")) parseAnnotations();
    if (!check("{")) unexpected("'{'");
    advance();
    while (!check("}")) {
        if (atEnd() || check("fxgroup")) unclosed("fxgroup", keyword);
        if (!isTechniqueKeyword(peek())) unexpected("'technique11' or '}'");
        parseTechnique(name.text);
    }
    advance();
    accept(";");
}

void Parser::parseTechnique(const std::string& group) {
    const Token& keyword = advance();
    Technique technique;
    technique.loc = keyword.loc;
    technique.group = group;
    technique.d3d10 = keyword.is("technique10") || keyword.is("technique11");
    if (peek().kind == Token::Kind::Identifier) {
        technique.name = peek().text;
        technique.loc = advance().loc;
    }
    if (check("<")) technique.annotations = parseAnnotations();
    if (!check("{")) unexpected("'{'");
    advance();
    mRefusals.beginTechnique();
    while (!check("}")) {
        if (atEnd() || isTechniqueKeyword(peek())) unclosed("technique", keyword);
        if (!check("pass")) unexpected("'pass' or '}'");
        technique.passes.push_back(parsePass(technique.d3d10));
    }
    advance();
    accept(";");
    for (const Technique& other : mEffect.techniques)
        if (!technique.name.empty() && other.name == technique.name && other.group == technique.group)
            error(DiagId::Redefinition, technique.loc, {technique.name});
    if (mRefusals.leaveOut(technique, mDiag, mEffect.refusedTechniques)) return;
    mEffect.techniques.push_back(std::move(technique));
}

Pass Parser::parsePass(bool d3d10) {
    const Token& keyword = advance();
    Pass pass;
    pass.loc = keyword.loc;
    if (peek().kind == Token::Kind::Identifier) {
        pass.name = peek().text;
        pass.loc = advance().loc;
    }
    if (check("<")) pass.annotations = parseAnnotations();
    if (!check("{")) unexpected("'{'");
    advance();
    mObjectsSet.clear();
    while (!check("}")) {
        if (atEnd() || check("pass") || isTechniqueKeyword(peek())) unclosed("pass", keyword);
        parsePassState(pass);
    }
    advance();
    if (d3d10) {
        // A D3D10 pass that sets no rasterizer, depth-stencil or blend state runs with D3D10's
        // defaults for it, not D3D9's (DepthFunc LESS, stencil masks 0xff, ...): expanded first, so
        // that anything the pass sets wins.
        std::vector<StateAssignment> defaults;
        for (StateObjectKind kind :
             {StateObjectKind::Rasterizer, StateObjectKind::DepthStencil, StateObjectKind::Blend})
            if (!mObjectsSet.count(kind)) mStates.expandStateObject(kind, {}, pass.loc, defaults);
        pass.states.insert(pass.states.begin(), defaults.begin(), defaults.end());
    }
    return pass;
}

void Parser::checkStreamOutput(const Expr& e) {
    if (e.kind != Expr::Kind::Call || e.text != "ConstructGSWithSO") return;
    validateConstructGSWithSO(e, mEffect,
                              [this](DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
                                  error(id, loc, args);
                              });
}

void Parser::parseSetCall(Pass& pass, const Token& name) {
    advance();  // '('
    std::vector<Expr> args;
    if (!check(")")) {
        args.push_back(parseExpr());
        while (accept(",")) args.push_back(parseExpr());
    }
    expect(")");
    expect(";");
    std::string what = name.text.substr(3);
    for (StateObjectKind kind :
         {StateObjectKind::Rasterizer, StateObjectKind::DepthStencil, StateObjectKind::Blend}) {
        if (what != stateObjectTypeName(kind)) continue;
        if (mStates.setStateObject(pass, name, kind, args)) mObjectsSet.insert(kind);
        return;
    }
    const bool isShader = what == "VertexShader" || what == "PixelShader" || what == "GeometryShader" ||
                          what == "HullShader" || what == "DomainShader" || what == "ComputeShader";
    if (!isShader) {
        error(DiagId::UnknownState, name.loc, {name.text});
        return;
    }
    if (args.size() != 1) {
        error(DiagId::ShaderStateArgumentCount, name.loc, {name.text});
        return;
    }
    Expr value = std::move(args[0]);
    if (value.kind == Expr::Kind::Call && value.text == "ConstructGSWithSO") {
        mStates.normalizeCompileShader(value);
        checkStreamOutput(value);
    }
    if (std::optional<ShaderValueRefusal> refusal = unsupportedShaderValue(value, mEffect)) {
        mRefusals.refuse(value.loc, *refusal);
        return;
    }
    mStates.normalizeCompileShader(value);
    mStates.normalizeNull(value);
    StateAssignment state;
    state.name = what;
    state.loc = name.loc;
    state.value = std::move(value);
    mStates.validateShaderValue(state);
    pass.states.push_back(std::move(state));
}

void Parser::parsePassState(Pass& pass) {
    const Token& name = expectIdentifier("a state name");
    StateAssignment state;
    state.name = name.text;
    state.loc = name.loc;
    // D3D10: SetVertexShader(CompileShader(vs_4_0, VS())); SetRasterizerState(rs); ...
    if (name.text.size() > 3 && name.text.compare(0, 3, "Set") == 0 && check("(")) {
        parseSetCall(pass, name);
        return;
    }
    // FX11's OMSetRenderTargets(rtv0, ..., dsv) binds views an application creates and sets
    // (RenderTargetView and DepthStencilView variables, which nothing in an effect reads): the call sets
    // nothing here, and its arguments must be such views or NULL, at most eight targets and a depth view.
    if (name.text == "OMSetRenderTargets" && check("(")) {
        advance();
        for (int count = 0; !check(")"); ++count) {
            if (count > 0) expect(",");
            const Expr view = parseExpr();
            const Parameter* p =
                view.kind == Expr::Kind::Identifier ? mEffect.findParameter(view.text) : nullptr;
            const bool isView = p && (p->type.base == BaseType::RenderTargetView ||
                                      p->type.base == BaseType::DepthStencilView);
            const bool isNull = view.kind == Expr::Kind::Identifier && equalsIgnoreCase(view.text, "NULL");
            if ((!isView && !isNull) || count == 9)
                error(DiagId::UnexpectedToken, view.loc,
                      {"a RenderTargetView or DepthStencilView variable or NULL (at most nine)", view.str()});
        }
        advance();
        expect(";");
        return;
    }
    if (accept("[")) {
        const Token& indexToken = peek();
        Expr index = parseExpr();
        double number = 0;
        // D3D9's largest indexed state is Sampler[0..15]; the bound also keeps the cast defined.
        if (!foldConstant(mEffect, index, number) || !(number >= 0 && number <= 15) ||
            number != static_cast<double>(static_cast<int>(number)))
            fail(DiagId::StateIndexInvalid, indexToken.loc, {index.str()});
        state.index = static_cast<int>(number);
        expect("]");
    }
    expect("=");
    if (check("asm")) fail(DiagId::AsmShader, peek().loc, {});
    state.value = parseExpr();
    mStates.normalizeCompileShader(state.value);
    mStates.normalizeNull(state.value);
    expect(";");
    std::optional<RenderStateId> id = findRenderState(state.name);
    if (!id && isSamplerRegisterState(state.name)) {
        if (mStates.resolveSamplerRegisterState(state)) pass.states.push_back(std::move(state));
        return;
    }
    if (!id) {
        if (equalsIgnoreCase(state.name, "GeometryShader") && state.value.kind == Expr::Kind::Identifier &&
            state.value.text == "NULL")
            return;
        error(DiagId::UnknownState, state.loc, {state.name});
        return;
    }
    const StateInfo& info = renderStateInfo(*id);
    if (info.domain == StateDomain::Shader)
        mStates.validateShaderValue(state);
    else
        mStates.resolveStateValue(state.value, info.domain, state.name);
    pass.states.push_back(std::move(state));
}

std::vector<StateAssignment> Parser::parseObjectStateBlock(StateObjectKind kind) {
    const Token& open = advance();  // '{'
    std::vector<StateAssignment> states;
    while (!check("}")) {
        if (atEnd() || isTechniqueKeyword(peek()))
            unclosed(std::string(stateObjectTypeName(kind)).c_str(), open);
        const Token& name = expectIdentifier("a state name");
        StateAssignment state;
        state.name = name.text;
        state.loc = name.loc;
        if (accept("[")) {
            const Token& indexToken = peek();
            Expr index = parseExpr();
            double number = 0;
            if (!foldConstant(mEffect, index, number) || !(number >= 0 && number <= 7) ||
                number != std::trunc(number))
                fail(DiagId::RenderTargetIndexInvalid, indexToken.loc, {index.str()});
            state.index = static_cast<int>(number);
            expect("]");
        }
        expect("=");
        state.value = parseExpr();
        expect(";");
        const StateObjectField* field = findStateObjectField(kind, state.name);
        if (!field) {
            error(DiagId::UnknownState, state.loc, {state.name});
            continue;
        }
        if (state.index > 0 && field->object != StateObjectKind::Blend)
            error(DiagId::StateTakesNoIndex, state.loc, {state.name});
        state.name = std::string(field->name);
        mStates.resolveStateValue(state.value, field->domain, state.name);
        states.push_back(std::move(state));
    }
    advance();
    return states;
}

std::vector<std::vector<StateAssignment>> Parser::parseObjectStateArray(StateObjectKind kind,
                                                                        const Parameter& parameter) {
    const Token& open = advance();  // '{'
    std::vector<std::vector<StateAssignment>> elements;
    while (!check("}")) {
        if (atEnd() || isTechniqueKeyword(peek()))
            unclosed(std::string(stateObjectTypeName(kind)).c_str(), open);
        if (!check("{")) unexpected("'{'");
        const SourceLoc at = peek().loc;
        elements.push_back(parseObjectStateBlock(kind));
        if (elements.size() == static_cast<size_t>(parameter.type.arrayDims[0]) + 1)
            error(DiagId::StateObjectArrayTooManyBlocks, at,
                  {parameter.name, std::to_string(parameter.type.arrayDims[0])});
        if (!accept(",")) break;
    }
    expect("}");
    return elements;
}

std::vector<StateAssignment> Parser::parseSamplerStateBlock(const Parameter& sampler) {
    if (!check("{")) unexpected("'{'");
    // `sampler S = sampler_state { ... }` is D3DX's form; `sampler S : register(s0) { ... }` MonoGame's.
    const bool monoGameForm = mPos == 0 || !mTokens[mPos - 1].is("sampler_state");
    const Token& open = advance();
    std::vector<StateAssignment> states;
    while (!check("}")) {
        if (atEnd() || check("technique") || check("sampler_state")) unclosed("sampler_state", open);
        const Token& name = expectIdentifier("a sampler state name");
        StateAssignment state;
        state.name = name.text;
        state.loc = name.loc;
        if (accept("[")) {
            Expr index = parseExpr();
            double number = 0;
            if (foldConstant(mEffect, index, number) && number >= 0 &&
                number <= 15)  // keeps the cast defined
                state.index = static_cast<int>(number);
            expect("]");
        }
        expect("=");
        state.value = parseExpr();
        expect(";");
        std::optional<SamplerStateId> id = findSamplerState(state.name);
        if (!id) {
            error(DiagId::UnknownState, state.loc, {state.name});
            continue;
        }
        const StateInfo& info = samplerStateInfo(*id);
        if (info.domain == StateDomain::TextureRef) {
            Expr& v = state.value;
            if (v.kind == Expr::Kind::Identifier) v.kind = Expr::Kind::TextureRef;  // (t) and t
            if (v.kind != Expr::Kind::TextureRef) {
                error(DiagId::TextureStateValueExpected, v.loc, {state.name});
                continue;
            }
            if (!mEffect.findParameter(v.text) && !monoGameForm) {
                error(DiagId::UnknownIdentifier, v.loc, {v.text});
                continue;
            }
            if (!mEffect.findParameter(v.text)) {
                // MonoGame's macros for Direct3D 9 and OpenGL declare a sampler whose Texture names a
                // texture nothing declares: its effect compiler named the sampler's texture parameter
                // after the identifier, and said nothing. So does this one, with a warning at the
                // sampler (a misspelt texture name reads the same); fxc, reading D3DX's form, refused
                // the name.
                if (!mSpeculative)
                    mDiag.report(DiagId::SamplerTextureUndeclared, sampler.loc, {sampler.name, v.text});
                Parameter texture;
                texture.name = v.text;
                texture.type.base = BaseType::Texture;
                texture.loc = v.loc;
                mEffect.parameters.push_back(std::move(texture));
                mEffect.order.push_back({DeclRef::Kind::Parameter, mEffect.parameters.size() - 1});
            }
        } else {
            mStates.resolveStateValue(state.value, info.domain, state.name);
        }
        states.push_back(std::move(state));
    }
    advance();
    return states;
}

}  // namespace fx::detail
