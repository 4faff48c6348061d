#include "ScriptInterpreter.h"

#include "HostScene.h"

#include <algorithm>

#include <private/runtime/NameLookups.h>
#include <fx/RenderStates.h>

namespace runtime {

namespace {

using Command = fx::ScriptCommand;

// A ClearSet*/LoopByCount value: the parameter it names, or its literal, both resolved by the compiler.
const fx::Value* scriptValue(const Command& command, const ScriptTarget& target) {
    if (command.parameter >= 0) return target.parameter(static_cast<size_t>(command.parameter));
    return command.literal ? &*command.literal : nullptr;
}

// The pass a Pass= names, by the index the compiler resolved.
const fx::CompiledPass* passOf(const fx::CompiledTechnique& technique, const Command& command) {
    return command.pass >= 0 && static_cast<size_t>(command.pass) < technique.passes.size()
               ? &technique.passes[static_cast<size_t>(command.pass)]
               : nullptr;
}

}  // namespace

bool ScriptInterpreter::selectionReadsParameters(const fx::CompiledEffect& effect,
                                                 const std::string& requested) {
    if (!requested.empty()) return false;
    for (const Command& command : effect.globalScript)
        if (command.kind == Command::Kind::Technique) return command.selectorParameter >= 0;
    return false;
}

const fx::CompiledTechnique* ScriptInterpreter::selectTechnique(const fx::CompiledEffect& effect,
                                                                const std::string& requested,
                                                                const std::vector<fx::Value>& values,
                                                                fx::DiagnosticSink& diagnostics) {
    if (!requested.empty()) {
        // The application's choice, by name (as D3DX's GetTechniqueByName).
        countNameLookup();
        if (const fx::CompiledTechnique* technique = effect.findTechnique(requested)) return technique;
        fx::SourceLoc loc;
        loc.file = effect.path;
        diagnostics.report(fx::DiagId::UnknownTechnique, loc, {requested});
        return nullptr;
    }
    if (effect.techniques.empty()) {
        diagnostics.report(fx::DiagId::NoTechniques, fx::SourceLoc{effect.path, 1, 1});
        return nullptr;
    }
    for (const Command& command : effect.globalScript) {
        if (command.kind != Command::Kind::Technique) continue;
        const bool takesFalse = command.selectorParameter >= 0 &&
                                static_cast<size_t>(command.selectorParameter) < values.size() &&
                                !values[static_cast<size_t>(command.selectorParameter)].asBool();
        const int chosen = takesFalse ? command.techniqueIfFalse : command.technique;
        // A selector never fails the effect: with no name it has, the first technique runs (the
        // compiler warned about the names).
        if (chosen >= 0) return &effect.techniques[static_cast<size_t>(chosen)];
        break;
    }
    // A technique with neither passes nor a script draws nothing (a shared header's placeholder, included
    // first): the default is the first technique that draws, as the application would have chosen one by
    // name.
    const auto draws = [](const fx::CompiledTechnique& t) { return !t.passes.empty() || t.hasScript; };
    const fx::CompiledTechnique& first = effect.techniques.front();
    if (draws(first)) return &first;
    for (const fx::CompiledTechnique& technique : effect.techniques)
        if (draws(technique)) {
            diagnostics.report(fx::DiagId::EmptyTechniqueSkipped, first.loc, {first.name, technique.name});
            return &technique;
        }
    return &first;
}

bool ScriptInterpreter::clearsFrame(const fx::CompiledTechnique& technique) {
    bool frameBound = true;
    // A pass script runs where its Pass= stands, so walk it in place; a pass named twice is walked twice.
    const auto walk = [&](const std::vector<Command>& commands, const auto& self, int depth) -> bool {
        for (const Command& command : commands) {
            if (command.kind == Command::Kind::RenderColorTarget && command.index == 0)
                frameBound = command.value.empty();
            if (command.kind == Command::Kind::Clear && command.clear == Command::ClearWhat::Color &&
                command.clearTarget <= 0 && frameBound)
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

bool ScriptInterpreter::run(const fx::CompiledTechnique& technique, int maxLoopCount, bool keepFrame,
                            ScriptLoopStack& loops, ScriptTarget& target, fx::DiagnosticSink& diagnostics) {
    loops.clear();
    if (!clearsFrame(technique)) {
        // The host's clear values (HostScene.h), set in every frame: a later Clear without ClearSet*
        // clears to the host background, as in FX Composer, in a kept frame too. The host's clear itself
        // only where the frame is not kept.
        static const fx::Value kBackground =
            fx::Value::vector({kHostBackground.r, kHostBackground.g, kHostBackground.b, kHostBackground.a});
        target.setClearColor(kBackground);
        target.setClearDepth(1.0f);
        target.setClearStencil(0);
        if (!keepFrame)
            for (Command::ClearWhat what :
                 {Command::ClearWhat::Color, Command::ClearWhat::Depth, Command::ClearWhat::Stencil})
                target.clear(what, -1);
    }
    if (technique.hasScript)
        return runCommands(technique.script, technique, nullptr, maxLoopCount, loops, target, diagnostics);
    // No script: every pass in order, as D3DX would run them.
    for (const fx::CompiledPass& pass : technique.passes)
        if (!runPass(pass, technique, maxLoopCount, loops, target, diagnostics)) return false;
    return true;
}

bool ScriptInterpreter::runPass(const fx::CompiledPass& pass, const fx::CompiledTechnique& technique,
                                int maxLoopCount, ScriptLoopStack& loops, ScriptTarget& target,
                                fx::DiagnosticSink& diagnostics) {
    target.beginPass(pass);
    if (pass.hasScript)
        return runCommands(pass.script, technique, &pass, maxLoopCount, loops, target, diagnostics);
    target.draw(pass, Command::DrawWhat::Geometry);
    return true;
}

bool ScriptInterpreter::runCommands(const std::vector<Command>& commands,
                                    const fx::CompiledTechnique& technique, const fx::CompiledPass* pass,
                                    int maxLoopCount, ScriptLoopStack& loops, ScriptTarget& target,
                                    fx::DiagnosticSink& diagnostics) {
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
                if (!runPass(*next, technique, maxLoopCount, loops, target, diagnostics)) return false;
                break;
            }
            case Command::Kind::RenderColorTarget:
                target.setColorTarget(command.index, command.value, command.parameter);
                break;
            case Command::Kind::RenderDepthStencilTarget:
                target.setDepthTarget(command.value, command.parameter);
                break;
            case Command::Kind::RenderPort:
                target.setRenderPort(command.value, command.light, command.cascade, command.loc);
                break;
            case Command::Kind::ClearSetColor:
            case Command::Kind::ClearSetDepth:
            case Command::Kind::ClearSetStencil: {
                const fx::Value* value = scriptValue(command, target);
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
                target.clear(command.clear, command.clearTarget);
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
                std::array<float, 3> counts{1, 1, 1};
                size_t given = 0;
                bool valid = !command.dispatch.empty();
                for (size_t term = 0; valid && term < command.dispatch.size(); ++term) {
                    const fx::ScriptCommand::DispatchTerm& operand = command.dispatch[term];
                    const fx::Value* value = operand.parameter >= 0
                                                 ? target.parameter(static_cast<size_t>(operand.parameter))
                                                 : nullptr;
                    const size_t n = value ? value->data.size() : 1;
                    valid = given + n <= 3;
                    for (size_t k = 0; valid && k < n; ++k) {
                        counts[given] = value ? value->data[k] : operand.count;
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
                const fx::Value* value = scriptValue(command, target);
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
                target.setLoopIndex(command.value, command.parameter, loops.back().index);
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
                        target.setLoopIndex(loop.indexCommand->value, loop.indexCommand->parameter,
                                            loop.index);
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
