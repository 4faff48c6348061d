#include "ScriptInterpreter.h"

#include "HostScene.h"

#include <algorithm>

#include <fx/DispatchTerms.h>
#include <fx/LiteralNumbers.h>
#include <private/runtime/NameLookups.h>
#include <fx/RenderStates.h>

namespace runtime {

namespace {

using Command = fx::ScriptCommand;

// A ClearSet*/LoopByCount value: the parameter it names, or its literal ("0.5", "1,0,0,1";
// fx/LiteralNumbers.h, as the compiler checked it), both resolved when the effect was created.
const fx::Value* scriptValue(const ScriptOperand& operand, const ScriptTarget& target) {
    if (operand.parameter >= 0) return target.parameter(static_cast<size_t>(operand.parameter));
    return operand.literal ? &*operand.literal : nullptr;
}

bool takesParameter(Command::Kind kind) {
    return kind == Command::Kind::RenderColorTarget || kind == Command::Kind::RenderDepthStencilTarget ||
           kind == Command::Kind::ClearSetColor || kind == Command::Kind::ClearSetDepth ||
           kind == Command::Kind::ClearSetStencil || kind == Command::Kind::LoopByCount ||
           kind == Command::Kind::LoopGetIndex;
}

// The pass a Pass= names, by the index the compiler resolved.
const fx::CompiledPass* passOf(const fx::CompiledTechnique& technique, const Command& command) {
    return command.pass >= 0 && static_cast<size_t>(command.pass) < technique.passes.size()
               ? &technique.passes[static_cast<size_t>(command.pass)]
               : nullptr;
}

}  // namespace

ScriptOperands::ScriptOperands(const fx::CompiledEffect& effect,
                               const std::function<std::optional<size_t>(std::string_view)>& findParameter,
                               const std::function<int(std::string_view)>& lightSlot) {
    const auto resolve = [&](const std::vector<Command>& commands) {
        for (const Command& command : commands) {
            ScriptOperand operand;
            if (takesParameter(command.kind) && !command.value.empty()) {
                if (const std::optional<size_t> index = findParameter(command.value)) {
                    operand.parameter = static_cast<int>(*index);
                } else if (command.kind != Command::Kind::RenderColorTarget &&
                           command.kind != Command::Kind::RenderDepthStencilTarget &&
                           command.kind != Command::Kind::LoopGetIndex) {
                    const std::optional<std::vector<float>> numbers = fx::parseLiteralNumbers(command.value);
                    if (numbers && !numbers->empty())
                        operand.literal = numbers->size() == 1 ? fx::Value::scalar(numbers->front())
                                                               : fx::Value::vector(*numbers);
                }
            }
            if (command.kind == Command::Kind::RenderPort && !command.value.empty())
                operand.lightSlot = lightSlot(command.value);
            // Dispatch=x,y,z: a term names a parameter or is a count (-1 where it is neither; the
            // compiler reported it).
            const std::vector<std::string> terms = command.kind == Command::Kind::Dispatch
                                                       ? fx::dispatchTerms(command.value)
                                                       : std::vector<std::string>{};
            for (const std::string& term : terms) {
                const std::optional<size_t> index = findParameter(term);
                const std::optional<std::vector<float>> number = fx::parseLiteralNumbers(term);
                operand.dispatchParameters.push_back(index ? static_cast<int>(*index) : -1);
                operand.dispatchCounts.push_back(!index && number && number->size() == 1 ? number->front()
                                                                                         : -1);
            }
            mOperands.emplace(&command, std::move(operand));
        }
    };
    resolve(effect.globalScript);
    for (const fx::CompiledTechnique& technique : effect.techniques) {
        resolve(technique.script);
        for (const fx::CompiledPass& pass : technique.passes) resolve(pass.script);
    }
}

const ScriptOperand& ScriptOperands::of(const fx::ScriptCommand& command) const {
    auto found = mOperands.find(&command);
    return found == mOperands.end() ? mNone : found->second;
}

bool ScriptInterpreter::selectionReadsParameters(const fx::CompiledEffect& effect,
                                                 const std::string& requested) {
    if (!requested.empty()) return false;
    for (const Command& command : effect.globalScript)
        if (command.kind == Command::Kind::Technique) return !command.selectorCondition.empty();
    return false;
}

const fx::CompiledTechnique* ScriptInterpreter::selectTechnique(
    const fx::CompiledEffect& effect, const std::string& requested,
    const std::function<const fx::Value*(const std::string&)>& parameterByName,
    fx::DiagnosticSink& diagnostics) {
    countNameLookup();
    std::string name = requested;
    fx::SourceLoc loc;
    if (name.empty()) {
        for (const Command& command : effect.globalScript) {
            if (command.kind != Command::Kind::Technique) continue;
            loc = command.loc;
            if (command.selectorCondition.empty()) {
                name = command.value;
            } else if (const fx::Value* condition = parameterByName(command.selectorCondition)) {
                name = condition->asBool() ? command.selectorTrue : command.selectorFalse;
            } else {
                // FX Composer's `Technique=Technique?Simple:Simple10:Textured:Textured10;` lists
                // alternatives (D3D9 / D3D10 twins) rather than testing a parameter: the first one the
                // effect has runs.
                for (const std::string& alternative : command.selectorAlternatives) {
                    if (effect.findTechnique(alternative)) {
                        name = alternative;
                        break;
                    }
                }
            }
            // A selector never fails the effect: with no name it has, the first technique runs (the
            // compiler warned about the names).
            if (!effect.findTechnique(name)) name.clear();
            break;
        }
    }
    if (name.empty()) {
        if (effect.techniques.empty()) {
            diagnostics.report(fx::DiagId::NoTechniques, fx::SourceLoc{effect.path, 1, 1});
            return nullptr;
        }
        return &effect.techniques.front();
    }
    if (const fx::CompiledTechnique* technique = effect.findTechnique(name)) return technique;
    if (!loc.valid()) loc.file = effect.path;
    diagnostics.report(fx::DiagId::UnknownTechnique, loc, {name});
    return nullptr;
}

bool ScriptInterpreter::clearsFrame(const fx::CompiledTechnique& technique) {
    bool frameBound = true;
    // A pass script runs where its Pass= stands, so walk it in place; a pass named twice is walked twice.
    const auto walk = [&](const std::vector<Command>& commands, const auto& self, int depth) -> bool {
        for (const Command& command : commands) {
            if (command.kind == Command::Kind::RenderColorTarget && command.index == 0)
                frameBound = command.value.empty();
            if (command.kind == Command::Kind::Clear && command.clear == Command::ClearWhat::Color &&
                frameBound)
                return true;
            if (command.kind == Command::Kind::Pass && depth == 0)
                if (const fx::CompiledPass* pass = passOf(technique, command);
                    pass && pass->hasScript && self(pass->script, self, 1))
                    return true;
        }
        return false;
    };
    if (technique.hasScript) return walk(technique.script, walk, 0);
    for (const fx::CompiledPass& pass : technique.passes)
        if (pass.hasScript && walk(pass.script, walk, 1)) return true;
    return false;
}

bool ScriptInterpreter::run(const fx::CompiledTechnique& technique, const ScriptOperands& operands,
                            int maxLoopCount, ScriptLoopStack& loops, ScriptTarget& target,
                            fx::DiagnosticSink& diagnostics) {
    loops.clear();
    if (!clearsFrame(technique)) {
        // The host's clear (HostScene.h). The clear values stay set: a later Clear without ClearSet*
        // clears to the host background, as in FX Composer.
        static const fx::Value kBackground =
            fx::Value::vector({kHostBackground.r, kHostBackground.g, kHostBackground.b, kHostBackground.a});
        target.setClearColor(kBackground);
        target.setClearDepth(1.0f);
        target.setClearStencil(0);
        for (Command::ClearWhat what :
             {Command::ClearWhat::Color, Command::ClearWhat::Depth, Command::ClearWhat::Stencil})
            target.clear(what);
    }
    if (technique.hasScript)
        return runCommands(technique.script, technique, nullptr, operands, maxLoopCount, loops, target,
                           diagnostics);
    // No script: every pass in order, as D3DX would run them.
    for (const fx::CompiledPass& pass : technique.passes)
        if (!runPass(pass, technique, operands, maxLoopCount, loops, target, diagnostics)) return false;
    return true;
}

bool ScriptInterpreter::runPass(const fx::CompiledPass& pass, const fx::CompiledTechnique& technique,
                                const ScriptOperands& operands, int maxLoopCount, ScriptLoopStack& loops,
                                ScriptTarget& target, fx::DiagnosticSink& diagnostics) {
    target.beginPass(pass);
    if (pass.hasScript)
        return runCommands(pass.script, technique, &pass, operands, maxLoopCount, loops, target, diagnostics);
    target.draw(pass, Command::DrawWhat::Geometry);
    return true;
}

bool ScriptInterpreter::runCommands(const std::vector<Command>& commands,
                                    const fx::CompiledTechnique& technique, const fx::CompiledPass* pass,
                                    const ScriptOperands& operands, int maxLoopCount, ScriptLoopStack& loops,
                                    ScriptTarget& target, fx::DiagnosticSink& diagnostics) {
    const size_t outer = loops.size();  // loops of the script this one runs inside, not this one's

    for (size_t i = 0; i < commands.size(); ++i) {
        const Command& command = commands[i];
        switch (command.kind) {
            case Command::Kind::Pass: {
                const fx::CompiledPass* next = passOf(technique, command);
                if (!next) {
                    diagnostics.report(fx::DiagId::ScriptUnknownPass, command.loc,
                                       {command.value, technique.name});
                    return false;
                }
                if (!runPass(*next, technique, operands, maxLoopCount, loops, target, diagnostics))
                    return false;
                break;
            }
            case Command::Kind::RenderColorTarget:
                target.setColorTarget(command.index, command.value, operands.of(command).parameter);
                break;
            case Command::Kind::RenderDepthStencilTarget:
                target.setDepthTarget(command.value, operands.of(command).parameter);
                break;
            case Command::Kind::RenderPort:
                target.setRenderPort(command.value, operands.of(command).lightSlot, command.cascade,
                                     command.loc);
                break;
            case Command::Kind::ClearSetColor:
            case Command::Kind::ClearSetDepth:
            case Command::Kind::ClearSetStencil: {
                const fx::Value* value = scriptValue(operands.of(command), target);
                if (!value) {
                    diagnostics.report(fx::DiagId::ScriptClearValueInvalid, command.loc,
                                       {std::string(fx::scriptCommandName(command.kind)), command.value});
                    return false;
                }
                if (command.kind == Command::Kind::ClearSetColor) target.setClearColor(*value);
                if (command.kind == Command::Kind::ClearSetDepth) target.setClearDepth(value->asFloat());
                if (command.kind == Command::Kind::ClearSetStencil) target.setClearStencil(value->asInt());
                break;
            }
            case Command::Kind::Clear:
                target.clear(command.clear);
                break;
            case Command::Kind::Draw:
                if (!pass) {
                    diagnostics.report(fx::DiagId::ScriptDrawInTechniqueScript, command.loc, {});
                    return false;
                }
                target.draw(*pass, command.draw);
                break;
            case Command::Kind::Dispatch: {
                if (!pass) {
                    diagnostics.report(fx::DiagId::ScriptDispatchInTechniqueScript, command.loc, {});
                    return false;
                }
                // Each term a number or a parameter; a vector parameter gives several counts.
                const ScriptOperand& operand = operands.of(command);
                std::array<float, 3> counts{1, 1, 1};
                size_t given = 0;
                bool valid = !operand.dispatchCounts.empty();
                for (size_t term = 0; valid && term < operand.dispatchCounts.size(); ++term) {
                    const int parameter = operand.dispatchParameters[term];
                    const fx::Value* value =
                        parameter >= 0 ? target.parameter(static_cast<size_t>(parameter)) : nullptr;
                    const size_t n = value ? value->data.size() : 1;
                    valid = given + n <= 3;
                    for (size_t k = 0; valid && k < n; ++k) {
                        counts[given] = value ? value->data[k] : operand.dispatchCounts[term];
                        valid = counts[given++] >= 0;
                    }
                }
                std::array<uint32_t, 3> groups{1, 1, 1};
                if (!valid) {
                    diagnostics.report(fx::DiagId::ScriptDispatchValueInvalid, command.loc, {command.value});
                    return false;
                }
                for (size_t axis = 0; axis < 3; ++axis) groups[axis] = static_cast<uint32_t>(counts[axis]);
                target.dispatch(*pass, groups, command.loc);
                break;
            }
            case Command::Kind::LoopByCount: {
                const fx::Value* value = scriptValue(operands.of(command), target);
                int count = value ? value->asInt() : -1;
                if (count < 0) {
                    diagnostics.report(fx::DiagId::ScriptLoopCountNegative, command.loc, {command.value});
                    return false;
                }
                if (count > maxLoopCount) {
                    diagnostics.report(fx::DiagId::ScriptLoopCountTooLarge, command.loc,
                                       {std::to_string(count), std::to_string(maxLoopCount)});
                    return false;
                }
                if (count == 0) {  // skip to the matching LoopEnd
                    int depth = 1;
                    while (depth > 0 && ++i < commands.size()) {
                        if (commands[i].kind == Command::Kind::LoopByCount) ++depth;
                        if (commands[i].kind == Command::Kind::LoopEnd) --depth;
                    }
                    break;
                }
                loops.push_back(ScriptLoop{i + 1, count - 1, 0, nullptr});
                break;
            }
            case Command::Kind::LoopGetIndex:
                if (loops.size() == outer) {
                    diagnostics.report(fx::DiagId::ScriptLoopIndexOutsideLoop, command.loc, {});
                    return false;
                }
                loops.back().indexCommand = &command;
                target.setLoopIndex(command.value, operands.of(command).parameter, loops.back().index);
                break;
            case Command::Kind::LoopEnd:
                if (loops.size() == outer) {
                    diagnostics.report(fx::DiagId::ScriptLoopEndWithoutLoop, command.loc, {});
                    return false;
                }
                if (loops.back().remaining > 0) {
                    ScriptLoop& loop = loops.back();
                    --loop.remaining;
                    ++loop.index;
                    if (loop.indexCommand)
                        target.setLoopIndex(loop.indexCommand->value,
                                            operands.of(*loop.indexCommand).parameter, loop.index);
                    i = loop.body - 1;
                } else {
                    loops.pop_back();
                }
                break;
            case Command::Kind::ScriptExternal:
                target.drawScene(command);
                break;
            case Command::Kind::Technique:
            case Command::Kind::ScriptOrder:
            case Command::Kind::ScriptClass:
            case Command::Kind::ScriptOutput:
            case Command::Kind::ScriptSignature:
                break;  // header commands: nothing to execute
        }
    }
    if (loops.size() != outer) {
        diagnostics.report(fx::DiagId::ScriptUnbalancedLoop,
                           commands.empty() ? fx::SourceLoc{} : commands.back().loc, {});
        return false;
    }
    return true;
}

}  // namespace runtime
