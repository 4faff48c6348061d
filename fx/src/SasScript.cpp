// SasScript: parses FX Composer / SAS `Script` strings ("Pass=P0;Draw=Geometry;") into commands. Each
// command's location is mapped through the string literal's pieces back to the user's file.
#include <fx/RenderStates.h>
#include <fx/SasScript.h>

#include <fx/Effect.h>

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
};

std::string trim(std::string_view text) {
    size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    size_t last = text.find_last_not_of(" \t\r\n");
    return std::string(text.substr(first, last - first + 1));
}

// The source location of character `offset` of the concatenated string.
SourceLoc locate(const Expr& script, size_t offset) {
    if (script.stringPieces.empty()) return script.loc;
    const Expr::StringPiece* piece = &script.stringPieces.front();
    for (const Expr::StringPiece& p : script.stringPieces)
        if (p.offset <= offset) piece = &p;
    SourceLoc loc = piece->loc;
    loc.column += static_cast<int>(offset - piece->offset);
    return loc;
}

}  // namespace

std::string_view scriptCommandName(ScriptCommand::Kind kind) {
    for (const CommandName& command : kCommands)
        if (command.kind == kind) return command.name;
    return "?";
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
            SourceLoc loc = locate(script, start + lead);
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
            auto invalid = [&](const std::string& why) {
                diagnostics.report(DiagId::InvalidScriptCommand, loc, {name, why});
            };
            if (!known) {
                diagnostics.report(DiagId::UnknownScriptCommand, loc, {name});
            } else if (equals == std::string_view::npos && command.kind != ScriptCommand::Kind::LoopEnd) {
                invalid("expected '=' and a value");
            } else {
                bool ok = true;
                switch (command.kind) {
                    case ScriptCommand::Kind::Clear:
                        if (equalsIgnoreCase(value, "Color"))
                            command.clear = ScriptCommand::ClearWhat::Color;
                        else if (equalsIgnoreCase(value, "Depth"))
                            command.clear = ScriptCommand::ClearWhat::Depth;
                        else if (equalsIgnoreCase(value, "Stencil"))
                            command.clear = ScriptCommand::ClearWhat::Stencil;
                        else
                            ok = false, invalid("expected Color, Depth or Stencil");
                        break;
                    case ScriptCommand::Kind::Draw:
                        if (equalsIgnoreCase(value, "Geometry"))
                            command.draw = ScriptCommand::DrawWhat::Geometry;
                        else if (equalsIgnoreCase(value, "Buffer"))
                            command.draw = ScriptCommand::DrawWhat::Buffer;
                        else
                            ok = false, invalid("expected Geometry or Buffer");
                        break;
                    case ScriptCommand::Kind::Pass:
                    case ScriptCommand::Kind::ClearSetColor:
                    case ScriptCommand::Kind::ClearSetDepth:
                    case ScriptCommand::Kind::ClearSetStencil:
                    case ScriptCommand::Kind::LoopByCount:
                    case ScriptCommand::Kind::LoopGetIndex:
                        if (value.empty()) ok = false, invalid("expected a value");
                        break;
                    case ScriptCommand::Kind::Technique: {
                        if (value.empty()) {
                            ok = false, invalid("expected a technique name");
                            break;
                        }
                        size_t question = value.find('?');
                        if (question != std::string::npos) {
                            size_t colon = value.find(':', question);
                            command.selectorCondition = trim(std::string_view(value).substr(0, question));
                            if (colon == std::string::npos) {
                                ok = false, invalid("expected Condition?TechniqueA:TechniqueB");
                                break;
                            }
                            command.selectorTrue =
                                trim(std::string_view(value).substr(question + 1, colon - question - 1));
                            command.selectorFalse = trim(std::string_view(value).substr(colon + 1));
                            if (command.selectorCondition.empty() || command.selectorTrue.empty() ||
                                command.selectorFalse.empty())
                                ok = false, invalid("expected Condition?TechniqueA:TechniqueB");
                        }
                        break;
                    }
                    case ScriptCommand::Kind::RenderPort: {
                        // lightN.cascadeK addresses one cascade of a light, lightN.faceK one face of a
                        // PSMCube cube map: both are the light's sub-view K (README, "Light-space
                        // parameterizations"); whether the light has sub-view K is known only per frame.
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
                            ok = false, invalid(
                                            "expected lightN, lightN.cascadeK or lightN.faceK, K a "
                                            "sub-view index, not '" +
                                            value + "'");
                            break;
                        }
                        command.value = light;
                        command.cascade = std::stoi(view.substr(prefix));
                        break;
                    }
                    case ScriptCommand::Kind::ScriptExternal:
                        diagnostics.report(DiagId::ScriptCommandIgnored, loc, {name});
                        break;
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
