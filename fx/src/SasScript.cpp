// SasScript: parses FX Composer / SAS `Script` strings ("Pass=P0;Draw=Geometry;") into commands. Each
// command's location is mapped through the string literal's pieces back to the user's file.
#include <fx/RenderStates.h>
#include <fx/SasScript.h>

#include <fx/Effect.h>

#include "StringLocation.h"

#include <algorithm>
#include <cctype>

namespace fx {

namespace {

struct CommandName {
    std::string_view name;
    ScriptCommand::Kind kind;
};

const CommandName kCommands[] = {
    {"Technique", ScriptCommand::Kind::Technique},
    {"Pass", ScriptCommand::Kind::Pass},
    {"RenderColorTarget", ScriptCommand::Kind::RenderColorTarget},
    {"RenderDepthStencilTarget", ScriptCommand::Kind::RenderDepthStencilTarget},
    {"ClearSetColor", ScriptCommand::Kind::ClearSetColor},
    {"ClearSetDepth", ScriptCommand::Kind::ClearSetDepth},
    {"ClearSetStencil", ScriptCommand::Kind::ClearSetStencil},
    {"Clear", ScriptCommand::Kind::Clear},
    {"Draw", ScriptCommand::Kind::Draw},
    {"RenderPort", ScriptCommand::Kind::RenderPort},
    {"LoopByCount", ScriptCommand::Kind::LoopByCount},
    {"LoopGetIndex", ScriptCommand::Kind::LoopGetIndex},
    {"LoopEnd", ScriptCommand::Kind::LoopEnd},
    {"ScriptExternal", ScriptCommand::Kind::ScriptExternal},
    {"ScriptOrder", ScriptCommand::Kind::ScriptOrder},
    {"ScriptClass", ScriptCommand::Kind::ScriptClass},
    {"ScriptOutput", ScriptCommand::Kind::ScriptOutput},
    {"ScriptSignature", ScriptCommand::Kind::ScriptSignature},
    {"Dispatch", ScriptCommand::Kind::Dispatch},
};

std::string trim(std::string_view text) {
    size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    size_t last = text.find_last_not_of(" \t\r\n");
    return std::string(text.substr(first, last - first + 1));
}

}  // namespace

std::string_view scriptCommandName(ScriptCommand::Kind kind) {
    for (const CommandName& command : kCommands)
        if (command.kind == kind) return command.name;
    return "?";
}

bool scriptNameMatches(std::string_view written, std::string_view declared) {
    return equalsIgnoreCase(written, declared);
}

std::vector<ScriptCommand> parseSasScript(const Expr& script, DiagnosticSink& diagnostics) {
    std::vector<ScriptCommand> commands;
    const std::string& text = script.text;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find(';', start);
        if (end == std::string::npos) end = text.size();
        std::string_view item(text.data() + start, end - start);
        size_t lead = item.find_first_not_of(" \t\r\n");
        if (lead != std::string_view::npos) {
            SourceLoc loc = detail::stringLocation(script, start + lead);
            size_t equals = item.find('=');
            std::string name = trim(item.substr(0, equals));
            std::string value =
                equals == std::string_view::npos ? std::string() : trim(item.substr(equals + 1));

            ScriptCommand command;
            command.loc = loc;
            command.value = value;
            bool known = false;
            for (const CommandName& candidate : kCommands) {
                if (equalsIgnoreCase(name, candidate.name)) {
                    command.kind = candidate.kind;
                    known = true;
                    break;
                }
            }
            // RenderColorTarget0..3
            if (!known && name.size() == 18 && equalsIgnoreCase(name.substr(0, 17), "RenderColorTarget") &&
                name[17] >= '0' && name[17] <= '3') {
                command.kind = ScriptCommand::Kind::RenderColorTarget;
                command.index = name[17] - '0';
                known = true;
            }
            auto invalid = [&](DiagId id, std::vector<std::string> args = {}) {
                args.insert(args.begin(), name);
                diagnostics.report(id, loc, args);
            };
            if (!known) {
                diagnostics.report(DiagId::UnknownScriptCommand, loc, {name});
            } else if (equals == std::string_view::npos && command.kind != ScriptCommand::Kind::LoopEnd) {
                invalid(DiagId::ScriptValueMissing);
            } else {
                bool ok = true;
                switch (command.kind) {
                    case ScriptCommand::Kind::Clear: {
                        // `Clear=;` names no buffer: FX Composer warned and cleared nothing.
                        if (value.empty()) {
                            diagnostics.report(DiagId::ScriptClearNamesNoBuffer, loc, {name});
                            ok = false;
                            break;
                        }
                        // Every form FX Composer took: Color (also Color0..3), Depth, Stencil, the
                        // combinations DepthStencil and All, and lists joined by '|' or '+'; one
                        // command for each buffer.
                        // 3ds Max's `Clear=SV_TARGETn`: colour target n alone (SV_TARGET0..7, fxc's
                        // targets; a script binds RenderColorTarget0..3 here, beyond them nothing is
                        // cleared, with a warning).
                        std::vector<std::pair<ScriptCommand::ClearWhat, int>> what;
                        size_t from = 0;
                        while (ok && from <= value.size()) {
                            size_t bar = value.find_first_of("|+,", from);
                            if (bar == std::string::npos) bar = value.size();
                            std::string word = trim(std::string_view(value).substr(from, bar - from));
                            from = bar + 1;
                            if (word.size() >= 9 && word.size() <= 10 &&
                                equalsIgnoreCase(word.substr(0, 9), "SV_TARGET") &&
                                (word.size() == 9 || (word[9] >= '0' && word[9] <= '7'))) {
                                const int target = word.size() == 9 ? 0 : word[9] - '0';
                                if (target < kScriptColorTargets)
                                    what.push_back({ScriptCommand::ClearWhat::Color, target});
                                else
                                    diagnostics.report(DiagId::ScriptClearTargetBeyond, loc,
                                                       {name + "=" + word, std::to_string(target),
                                                        std::to_string(kScriptColorTargets),
                                                        std::to_string(kScriptColorTargets - 1)});
                                continue;
                            }
                            // FX Composer's `Clear=Depth0;`: the one depth-stencil buffer.
                            if (word.size() > 1 && word.back() == '0' &&
                                !equalsIgnoreCase(word.substr(0, word.size() - 1), "Color"))
                                word.pop_back();
                            const bool color =
                                equalsIgnoreCase(word, "Color") ||
                                (word.size() == 6 && equalsIgnoreCase(word.substr(0, 5), "Color") &&
                                 word[5] >= '0' && word[5] <= '3');
                            const bool all = equalsIgnoreCase(word, "All");
                            const bool depthStencil = equalsIgnoreCase(word, "DepthStencil") ||
                                                      equalsIgnoreCase(word, "Depth_Stencil");
                            if (color || all) what.push_back({ScriptCommand::ClearWhat::Color, -1});
                            if (equalsIgnoreCase(word, "Depth") || equalsIgnoreCase(word, "ZBuffer") || all ||
                                depthStencil)
                                what.push_back({ScriptCommand::ClearWhat::Depth, -1});
                            if (equalsIgnoreCase(word, "Stencil") || all || depthStencil)
                                what.push_back({ScriptCommand::ClearWhat::Stencil, -1});
                            if (!color && !all && !depthStencil && !equalsIgnoreCase(word, "Depth") &&
                                !equalsIgnoreCase(word, "ZBuffer") && !equalsIgnoreCase(word, "Stencil"))
                                ok = false, invalid(DiagId::ScriptClearInvalid);
                        }
                        if (!ok || what.empty()) {  // nothing left to clear: no command
                            ok = false;
                            break;
                        }
                        command.clear = what.front().first;
                        command.clearTarget = what.front().second;
                        for (size_t k = 1; k < what.size(); ++k) {
                            ScriptCommand more = command;
                            more.clear = what[k].first;
                            more.clearTarget = what[k].second;
                            commands.push_back(command);
                            command = more;
                        }
                        break;
                    }
                    case ScriptCommand::Kind::Draw:
                        if (equalsIgnoreCase(value, "Geometry"))
                            command.draw = ScriptCommand::DrawWhat::Geometry;
                        else if (equalsIgnoreCase(value, "Buffer"))
                            command.draw = ScriptCommand::DrawWhat::Buffer;
                        else
                            ok = false, invalid(DiagId::ScriptDrawInvalid);
                        break;
                    case ScriptCommand::Kind::Pass:
                    case ScriptCommand::Kind::ClearSetColor:
                    case ScriptCommand::Kind::ClearSetDepth:
                    case ScriptCommand::Kind::ClearSetStencil:
                    case ScriptCommand::Kind::LoopByCount:
                    case ScriptCommand::Kind::LoopGetIndex:
                    case ScriptCommand::Kind::Dispatch:
                        if (value.empty()) ok = false, invalid(DiagId::ScriptValueEmpty);
                        break;
                    case ScriptCommand::Kind::Technique: {
                        if (value.empty()) {
                            ok = false, invalid(DiagId::ScriptTechniqueNameExpected);
                            break;
                        }
                        // Condition?A:B, and FX Composer's list of alternatives
                        // `Technique?Simple:Simple10:Textured:Textured10`.
                        size_t question = value.find('?');
                        if (question != std::string::npos) {
                            command.selectorCondition = trim(std::string_view(value).substr(0, question));
                            for (size_t from = question + 1;;) {
                                const size_t colon = value.find(':', from);
                                command.selectorAlternatives.push_back(
                                    trim(std::string_view(value).substr(from, colon - from)));
                                if (colon == std::string::npos) break;
                                from = colon + 1;
                            }
                            const bool emptyName = std::any_of(
                                command.selectorAlternatives.begin(), command.selectorAlternatives.end(),
                                [](const std::string& name) { return name.empty(); });
                            if (command.selectorCondition.empty() || emptyName) {
                                ok = false, invalid(DiagId::ScriptTechniqueConditionInvalid);
                                break;
                            }
                            command.selectorTrue = command.selectorAlternatives.front();
                            if (command.selectorAlternatives.size() > 1)
                                command.selectorFalse = command.selectorAlternatives[1];
                        }
                        break;
                    }
                    case ScriptCommand::Kind::RenderPort: {
                        // lightN.cascadeK addresses one cascade of a light, lightN.faceK one face of a
                        // PSMCube cube map: both are the light's sub-view K
                        // (docs/techniques/light-space-parameterizations.md); whether the light has sub-view
                        // K is known only per frame.
                        const size_t dot = value.find('.');
                        if (dot == std::string::npos) break;
                        const std::string light = trim(std::string_view(value).substr(0, dot));
                        const std::string view = trim(std::string_view(value).substr(dot + 1));
                        size_t prefix = 0;
                        for (std::string_view spelling :
                             {std::string_view("cascade"), std::string_view("face")})
                            if (view.size() > spelling.size() &&
                                equalsIgnoreCase(view.substr(0, spelling.size()), spelling))
                                prefix = spelling.size();
                        const bool digits =
                            prefix > 0 && view.size() <= prefix + 2 &&
                            std::all_of(view.begin() + static_cast<std::ptrdiff_t>(prefix), view.end(),
                                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
                        if (light.empty() || !digits) {
                            ok = false, invalid(DiagId::ScriptRenderPortInvalid, {value});
                            break;
                        }
                        command.value = light;
                        command.cascade = std::stoi(view.substr(prefix));
                        break;
                    }
                    case ScriptCommand::Kind::ScriptExternal:
                        break;  // the host draws the scene here (runtime/src/ScriptInterpreter.cpp)
                    default:
                        break;
                }
                if (ok) commands.push_back(std::move(command));
            }
        }
        start = end + 1;
    }
    return commands;
}

std::vector<ScriptCommand> parseSasScript(const std::string& text, const SourceLoc& loc,
                                          DiagnosticSink& diagnostics) {
    Expr script;
    script.kind = Expr::Kind::String;
    script.text = text;
    script.loc = loc;
    script.stringPieces.push_back({0, loc});
    return parseSasScript(script, diagnostics);
}

}  // namespace fx
