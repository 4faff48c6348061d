// ScriptValidation: SAS Script annotations parsed and checked against the effect: passes, targets and
// loops resolved where the compiler can (see Compiler.h).

#include "Compiler.h"
#include "CaseFolding.h"
#include "SemanticClassification.h"

#include <fx/DispatchTerms.h>
#include <fx/LiteralNumbers.h>

#include <algorithm>
#include <cmath>

namespace fx::detail {

std::vector<ScriptCommand> Compiler::script(const std::vector<Annotation>& annotations, bool& has) {
    has = false;
    for (const Annotation& a : annotations) {
        if (!equalsIgnoreCase(a.name, "Script") || a.value.kind != Expr::Kind::String) continue;
        has = true;
        DiagnosticList local;
        auto commands = parseSasScript(a.value, local);
        for (const Diagnostic& d : local.items()) {
            if (d.severity == Severity::Error) mFailed = true;
            mDiagnostics.report(d);
        }
        return commands;
    }
    return {};
}

void Compiler::validateScript(std::vector<ScriptCommand>& commands, const Technique* technique) {
    int loops = 0;
    // Commands FX Composer warned about and skipped: left out of the compiled script, so that the runtime
    // runs what FX Composer ran.
    std::vector<bool> ignored(commands.size(), false);
    // What a value names: the parameter's index, or -1.
    const auto parameterNamed = [this](const std::string& name) {
        const auto it = mIndex.find(name);
        return it == mIndex.end() ? -1 : static_cast<int>(it->second);
    };
    for (size_t index = 0; index < commands.size(); ++index) {
        ScriptCommand& resolved = commands[index];
        const ScriptCommand& c = resolved;
        auto ignore = [&](DiagId why) {
            mDiagnostics.report(why, c.loc, {std::string(scriptCommandName(c.kind)), c.value});
            ignored[index] = true;
        };
        switch (c.kind) {
            case ScriptCommand::Kind::Pass: {
                // The first pass whose name matches.
                int& pass = commands[index].pass;
                for (size_t k = 0; technique && k < technique->passes.size() && pass < 0; ++k)
                    if (scriptNameMatches(c.value, technique->passes[k].name)) pass = static_cast<int>(k);
                if (pass < 0)
                    error(DiagId::ScriptUnknownPass, c.loc, {c.value, technique ? technique->name : ""});
                break;
            }
            case ScriptCommand::Kind::ClearSetColor:
            case ScriptCommand::Kind::ClearSetDepth:
            case ScriptCommand::Kind::ClearSetStencil: {
                // A parameter's name or a literal ("0.5", "1,0,0,1"), as the runtime reads it.
                const std::optional<std::vector<float>> numbers = parseLiteralNumbers(c.value);
                const bool literal = numbers && !numbers->empty();
                resolved.parameter = parameterNamed(c.value);
                if (resolved.parameter < 0 && literal)
                    resolved.literal =
                        numbers->size() == 1 ? Value::scalar(numbers->front()) : Value::vector(*numbers);
                if (resolved.parameter < 0 && !literal) ignore(DiagId::ScriptClearValueIgnored);
                break;
            }
            case ScriptCommand::Kind::RenderColorTarget:
            case ScriptCommand::Kind::RenderDepthStencilTarget: {
                if (c.value.empty()) break;
                resolved.parameter = parameterNamed(c.value);
                // What textures() made of the declaration: a RENDERCOLORTARGET semantic, or FX Composer's
                // size annotations alone.
                auto it = mIndex.find(c.value);
                const bool wantDepth = c.kind == ScriptCommand::Kind::RenderDepthStencilTarget;
                const TextureDesc::Kind want = wantDepth ? TextureDesc::Kind::RenderDepthStencilTarget
                                                         : TextureDesc::Kind::RenderColorTarget;
                bool isTarget = false;
                for (const TextureDesc& t : mOut->textures)
                    isTarget =
                        isTarget || (it != mIndex.end() && t.parameter == it->second && t.kind == want);
                if (!isTarget)
                    ignore(wantDepth ? DiagId::ScriptDepthTargetNotTarget
                                     : DiagId::ScriptColorTargetNotTarget);
                break;
            }
            case ScriptCommand::Kind::Technique: {
                // D3DX and FX Composer never failed an effect over its technique selector: names the
                // effect lacks (its D3D10 twins, techniques a #define renamed) are skipped with a warning,
                // and with none left the first technique that draws runs
                // (runtime/render/src/ScriptInterpreter.cpp).
                const std::vector<std::string> names =
                    c.selectorCondition.empty() ? std::vector<std::string>{c.value} : c.selectorAlternatives;
                bool any = false;
                for (const std::string& name : names) {
                    any = any || mEffect.findTechnique(name);
                    if (!mEffect.findTechnique(name))
                        mDiagnostics.report(DiagId::ScriptUnknownTechnique, c.loc, {name});
                }
                if (!any && !mEffect.techniques.empty()) {
                    // The runtime's default: the first technique that draws (passes or a script).
                    const auto draws = [](const Technique& t) {
                        return !t.passes.empty() || t.annotation("Script");
                    };
                    const auto first =
                        std::find_if(mEffect.techniques.begin(), mEffect.techniques.end(), draws);
                    mDiagnostics.report(
                        DiagId::ScriptTechniqueFallback, c.loc,
                        {(first == mEffect.techniques.end() ? mEffect.techniques.front() : *first).name});
                }
                break;
            }
            case ScriptCommand::Kind::RenderPort:
                if (!c.value.empty()) resolved.light = lightIndex(c.value);
                break;
            case ScriptCommand::Kind::LoopGetIndex:
                resolved.parameter = parameterNamed(c.value);
                break;
            case ScriptCommand::Kind::LoopByCount: {
                ++loops;
                // A literal count is checked here, once, rather than failing every frame in the runtime
                // (runtime/render/src/ScriptInterpreter.cpp checks parameter values against the same
                // limit, CompiledEffect::maxScriptLoopCount).
                const std::optional<std::vector<float>> numbers = parseLiteralNumbers(c.value);
                resolved.parameter = parameterNamed(c.value);
                if (resolved.parameter < 0 && numbers && !numbers->empty())
                    resolved.literal =
                        numbers->size() == 1 ? Value::scalar(numbers->front()) : Value::vector(*numbers);
                if (numbers && numbers->size() == 1 && !mIndex.count(c.value)) {
                    const double count = numbers->front();
                    if (!(count >= 0) || std::floor(count) != count)
                        error(DiagId::ScriptLoopCountNotWhole, c.loc, {c.value});
                    else if (count > mOptions.maxScriptLoopCount)
                        error(DiagId::ScriptLoopCountTooLarge, c.loc,
                              {c.value, std::to_string(mOptions.maxScriptLoopCount)});
                }
                break;
            }
            case ScriptCommand::Kind::Dispatch: {
                // Up to three group counts, each a parameter's name or a whole number; the runtime reads
                // parameters' values per frame.
                const std::vector<std::string> terms = dispatchTerms(c.value);
                bool valid = true;
                for (const std::string& term : terms) {
                    const std::optional<std::vector<float>> number = parseLiteralNumbers(term);
                    ScriptCommand::DispatchTerm& operand = resolved.dispatch.emplace_back();
                    operand.parameter = parameterNamed(term);
                    if (operand.parameter >= 0) continue;
                    if (number && number->size() == 1) operand.count = number->front();
                    valid = valid && number && number->size() == 1 && number->front() >= 0 &&
                            std::floor(number->front()) == number->front();
                }
                if (!valid || terms.size() > 3) error(DiagId::ScriptDispatchCountsInvalid, c.loc, {c.value});
                break;
            }
            case ScriptCommand::Kind::LoopEnd:
                if (--loops < 0) {
                    error(DiagId::ScriptLoopEndWithoutLoop, c.loc, {});
                    loops = 0;
                }
                break;
            default:
                break;
        }
    }
    if (loops > 0 && !commands.empty()) error(DiagId::ScriptUnbalancedLoop, commands.back().loc, {});
    size_t kept = 0;
    for (size_t index = 0; index < commands.size(); ++index) {
        if (ignored[index]) continue;
        if (kept != index) commands[kept] = std::move(commands[index]);  // never onto itself
        ++kept;
    }
    commands.resize(kept);
}

int Compiler::lightIndex(const std::string& name) {
    std::vector<std::string>& lights = mOut->lights;
    const auto known = std::find(lights.begin(), lights.end(), name);
    if (known != lights.end()) return static_cast<int>(known - lights.begin());
    lights.push_back(name);
    return static_cast<int>(lights.size() - 1);
}

void Compiler::resolveTechniqueSelection() {
    const auto techniqueNamed = [this](const std::string& name) {
        const CompiledTechnique* technique = mOut->findTechnique(name);
        return technique ? static_cast<int>(technique - mOut->techniques.data()) : -1;
    };
    for (ScriptCommand& c : mOut->globalScript) {
        if (c.kind != ScriptCommand::Kind::Technique) continue;
        if (c.selectorCondition.empty()) {
            c.technique = techniqueNamed(c.value);
            continue;
        }
        const auto condition = mIndex.find(c.selectorCondition);
        if (condition != mIndex.end()) {
            c.selectorParameter = static_cast<int>(condition->second);
            c.technique = techniqueNamed(c.selectorTrue);
            c.techniqueIfFalse = techniqueNamed(c.selectorFalse);
            continue;
        }
        // FX Composer's `Technique=Technique?Simple:Simple10:Textured:Textured10;` lists alternatives
        // (D3D9 / D3D10 twins) rather than testing a parameter: the first one the effect has runs.
        for (const std::string& alternative : c.selectorAlternatives)
            if (c.technique < 0) c.technique = techniqueNamed(alternative);
    }
}

void Compiler::scripts() {
    // The parameters' lights first, so that their indices do not depend on which scripts compile; what
    // each parameter's semantic gives it, with them.
    // CompiledEffect::parameters has Effect::parameters' indices.
    std::vector<bool> hasInitializer(mOut->parameters.size());
    for (size_t i = 0; i < hasInitializer.size(); ++i)
        hasInitializer[i] = mEffect.parameters[i].initializer.has_value();
    const LightNumbering numbering = lightNumbering(mOut->parameters, hasInitializer);
    std::string semanticLight;
    for (size_t i = 0; i < mOut->parameters.size(); ++i) {
        ParameterInfo& parameter = mOut->parameters[i];
        if (!parameter.light.empty()) lightIndex(parameter.light);
        parameter.standard = classifySemantic(parameter, hasInitializer[i], numbering, semanticLight);
        if (!semanticLight.empty()) parameter.standard.light = lightIndex(semanticLight);
    }
    structMemberBindings(hasInitializer);
    // A light count read by its name indexes per-light arrays, and the runtime keeps it within the
    // shortest one it fills: without such an array it would count lights into arrays of unknown length,
    // so it is not bound. A LightCount semantic is what its author asked for.
    const bool hasPerLightArray =
        std::any_of(mOut->parameters.begin(), mOut->parameters.end(), [](const ParameterInfo& parameter) {
            return parameter.standard.eachLight ||
                   std::any_of(parameter.memberBindings.begin(), parameter.memberBindings.end(),
                               [](const MemberBinding& member) { return member.standard.eachLight; });
        });
    if (!hasPerLightArray)
        for (ParameterInfo& parameter : mOut->parameters)
            if (parameter.standard.kind == SemanticKind::LightCount && parameter.standard.byName)
                parameter.standard = SemanticBinding{};
    for (const Parameter& p : mEffect.parameters) {
        if (upperCase(p.semantic) != "STANDARDSGLOBAL") continue;
        mOut->globalScript = script(p.annotations, mOut->hasGlobalScript);
        validateScript(mOut->globalScript, nullptr);
        for (const Annotation& a : p.annotations)
            if (equalsIgnoreCase(a.name, "ScriptClass") && a.value.kind == Expr::Kind::String)
                mOut->sceneClass = equalsIgnoreCase(a.value.text, "scene");
    }
}

}  // namespace fx::detail
