// ScriptValidation: SAS Script annotations parsed and checked against the effect: passes, targets and
// loops resolved where the compiler can (see Compiler.h).

#include "Compiler.h"
#include "CaseFolding.h"

#include <fx/DispatchTerms.h>
#include <fx/LiteralNumbers.h>

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
    for (size_t index = 0; index < commands.size(); ++index) {
        const ScriptCommand& c = commands[index];
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
                if (!mIndex.count(c.value) && !literal) ignore(DiagId::ScriptClearValueIgnored);
                break;
            }
            case ScriptCommand::Kind::RenderColorTarget:
            case ScriptCommand::Kind::RenderDepthStencilTarget: {
                if (c.value.empty()) break;
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
                // and with none left the first technique runs (runtime/src/ScriptInterpreter.cpp).
                const std::vector<std::string> names =
                    c.selectorCondition.empty() ? std::vector<std::string>{c.value} : c.selectorAlternatives;
                bool any = false;
                for (const std::string& name : names) {
                    any = any || mEffect.findTechnique(name);
                    if (!mEffect.findTechnique(name))
                        mDiagnostics.report(DiagId::ScriptUnknownTechnique, c.loc, {name});
                }
                if (!any && !mEffect.techniques.empty())
                    mDiagnostics.report(DiagId::ScriptTechniqueFallback, c.loc,
                                        {mEffect.techniques.front().name});
                break;
            }
            case ScriptCommand::Kind::LoopByCount: {
                ++loops;
                // A literal count is checked here, once, rather than failing every frame in the runtime
                // (runtime/render/src/ScriptInterpreter.cpp checks parameter values against the same
                // limit, CompiledEffect::maxScriptLoopCount).
                const std::optional<std::vector<float>> numbers = parseLiteralNumbers(c.value);
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
                    if (mIndex.count(term)) continue;
                    const std::optional<std::vector<float>> number = parseLiteralNumbers(term);
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

void Compiler::scripts() {
    for (const Parameter& p : mEffect.parameters) {
        if (upperCase(p.semantic) != "STANDARDSGLOBAL") continue;
        mOut->globalScript = script(p.annotations, mOut->hasGlobalScript);
        validateScript(mOut->globalScript, nullptr);
    }
}

}  // namespace fx::detail
