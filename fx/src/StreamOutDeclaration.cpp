// StreamOutDeclaration: see StreamOutDeclaration.h.
#include "StreamOutDeclaration.h"

#include "CaseFolding.h"
#include "SemanticTables.h"
#include "StringLocation.h"

#include <algorithm>
#include <map>
#include <optional>

#include <cctype>
#include <string_view>

namespace fx::detail {

namespace {

// D3D10 binds at most four stream-output buffers (D3D10_SO_BUFFER_SLOT_COUNT).
constexpr int kStreamOutSlots = 4;

// A mask names contiguous components in order (x, xy, yz, yzw, ...; rgba alike), as an SO declaration
// entry's StartComponent and ComponentCount describe them. False for anything else.
bool readMask(std::string_view mask, int& start, int& count) {
    static constexpr std::string_view kXyzw = "xyzw", kRgba = "rgba";
    if (mask.empty() || mask.size() > 4) return false;
    for (std::string_view set : {kXyzw, kRgba}) {
        size_t at = set.find(mask);
        if (at != std::string_view::npos) {
            start = static_cast<int>(at);
            count = static_cast<int>(mask.size());
            return true;
        }
    }
    return false;
}

bool isBlank(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// Adds an output with `semantic` of `type`; false where the output is not a plain scalar or vector (a
// nested struct, an array, a matrix), whose signature this check does not follow.
bool addOutput(const Effect& effect, const TypeDesc& type, const std::string& semantic,
               OutputSignature& out) {
    if (type.base == BaseType::Struct) {
        const StructDecl* decl = effect.findStruct(type.structName);
        if (!decl || !type.arrayDims.empty()) return false;
        for (const StructMember& m : decl->members)
            if (!addOutput(effect, m.type, m.semantic, out)) return false;
        return true;
    }
    if (semantic.empty()) return true;
    if (!type.arrayDims.empty() || type.shape == Shape::Matrix) return false;
    out[splitSemantic(upperCase(semantic))] = type.shape == Shape::Vector ? type.cols : 1;
    return true;
}

}  // namespace

std::optional<OutputSignature> streamOutputSignature(const Expr& shader, const Effect& effect,
                                                     std::string& name) {
    const Expr* compiled = &shader;
    if (shader.kind == Expr::Kind::Identifier) {
        const Parameter* variable = effect.findParameter(shader.text);
        if (!variable || !variable->initializer) return std::nullopt;
        compiled = &*variable->initializer;
    }
    if (compiled->kind != Expr::Kind::Compile) return std::nullopt;
    std::vector<const FunctionDecl*> overloads = effect.findFunctions(compiled->text);
    if (overloads.size() != 1 || !overloads[0]->hasBody) return std::nullopt;
    const FunctionDecl& fn = *overloads[0];
    name = fn.name;
    OutputSignature out;
    bool stream = false;
    for (const FunctionParam& p : fn.params) {
        if (p.stream.empty()) continue;
        stream = true;
        if (!addOutput(effect, p.type, p.semantic, out)) return std::nullopt;
    }
    if (stream) return out;
    if (!addOutput(effect, fn.returnType, fn.returnSemantic, out)) return std::nullopt;
    for (const FunctionParam& p : fn.params)
        if (p.direction != FunctionParam::Direction::In && !addOutput(effect, p.type, p.semantic, out))
            return std::nullopt;
    return out;
}

std::vector<StreamOutEntry> parseStreamOutDeclaration(const Expr& declaration,
                                                      const ReportStreamOutError& error) {
    std::vector<StreamOutEntry> elements;
    const std::string& text = declaration.text;
    size_t begin = 0;
    while (begin <= text.size()) {
        size_t end = text.find(';', begin);
        if (end == std::string::npos) end = text.size();
        size_t first = begin, last = end;
        while (first < last && isBlank(text[first])) ++first;
        while (last > first && isBlank(text[last - 1])) --last;
        begin = end + 1;
        if (first == last) continue;  // "a; b;" ends in an empty entry, which D3DX took
        const std::string entry = text.substr(first, last - first);
        StreamOutEntry element;
        element.text = entry;
        element.loc = stringLocation(declaration, first);
        auto fail = [&](DiagId id, const std::string& what = {}) { error(id, element.loc, {entry, what}); };
        std::string_view rest(entry);
        if (size_t colon = rest.find(':'); colon != std::string_view::npos) {
            std::string_view slot = rest.substr(0, colon);
            if (slot.size() != 1 || slot[0] < '0' || slot[0] >= '0' + kStreamOutSlots) {
                fail(DiagId::StreamOutSlotInvalid);
                continue;
            }
            element.slot = slot[0] - '0';
            rest.remove_prefix(colon + 1);
            while (!rest.empty() && isBlank(rest.front())) rest.remove_prefix(1);
        }
        std::string_view name = rest.substr(0, rest.find('.'));
        if (name.empty()) {
            fail(DiagId::StreamOutSemanticMissing);
            continue;
        }
        if (name != "$SKIP") {
            size_t digits = name.size();
            while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
            bool identifier =
                digits > 0 && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
            for (size_t i = 0; identifier && i < digits; ++i)
                identifier = std::isalnum(static_cast<unsigned char>(name[i])) || name[i] == '_';
            if (!identifier || name.size() - digits > 4) {
                fail(DiagId::StreamOutSemanticNameInvalid, std::string(name));
                continue;
            }
            if (digits < name.size()) element.semanticIndex = std::stoi(std::string(name.substr(digits)));
            name = name.substr(0, digits);
        }
        element.semantic = std::string(name);
        if (size_t dot = rest.find('.'); dot != std::string_view::npos) {
            std::string_view mask = rest.substr(dot + 1);
            if (!readMask(mask, element.startComponent, element.componentCount)) {
                fail(DiagId::StreamOutMaskInvalid, std::string(mask));
                continue;
            }
        }
        elements.push_back(std::move(element));
    }
    return elements;
}

void validateConstructGSWithSO(const Expr& call, const Effect& effect, const ReportStreamOutError& error) {
    auto isNull = [](const Expr& e) {
        return (e.kind == Expr::Kind::Identifier && e.text == "NULL") ||
               (e.kind == Expr::Kind::Number && e.number == 0);
    };
    const bool fx10 = call.args.size() == 2 && call.args[1].kind == Expr::Kind::String;
    bool fx11 = call.args.size() == 6 && call.args[5].kind == Expr::Kind::Number;
    for (size_t i = 1; fx11 && i < 5; ++i)
        fx11 = call.args[i].kind == Expr::Kind::String || isNull(call.args[i]);
    const bool shader = !call.args.empty() && (call.args[0].kind == Expr::Kind::Compile ||
                                               call.args[0].kind == Expr::Kind::Identifier);
    if (!shader || !(fx10 || fx11)) {
        error(DiagId::ConstructGSWithSOCallInvalid, call.loc, {});
        return;
    }
    std::string function;
    const std::optional<OutputSignature> outputs = streamOutputSignature(call.args[0], effect, function);
    for (size_t i = 1; i < call.args.size() && i < 5; ++i) {
        if (call.args[i].kind != Expr::Kind::String) continue;
        for (const StreamOutEntry& e : parseStreamOutDeclaration(call.args[i], error)) {
            if (!outputs || e.semantic == "$SKIP") continue;
            const std::string semantic =
                e.semantic + (e.semanticIndex ? std::to_string(e.semanticIndex) : "");
            auto found = outputs->find({upperCase(e.semantic), e.semanticIndex});
            if (found == outputs->end())
                error(DiagId::StreamOutOutputMissing, e.loc, {e.text, function, semantic});
            else if (e.startComponent + e.componentCount > found->second)
                error(DiagId::StreamOutMaskBeyondOutput, e.loc,
                      {e.text, semantic, function,
                       std::to_string(found->second) + (found->second == 1 ? " component" : " components")});
        }
    }
}

std::optional<StreamOutCall> readConstructGSWithSO(const Expr& call) {
    if (call.kind != Expr::Kind::Call || call.text != "ConstructGSWithSO" || call.args.size() < 2)
        return std::nullopt;
    StreamOutCall out;
    out.shader = &call.args[0];
    const auto ignore = [](DiagId, const SourceLoc&, const std::vector<std::string>&) {};
    if (call.args[1].kind == Expr::Kind::String)
        out.entries = parseStreamOutDeclaration(call.args[1], ignore);
    for (size_t i = 2; i < call.args.size() && i < 5; ++i)
        out.otherStreams |= call.args[i].kind == Expr::Kind::String;
    std::stable_sort(out.entries.begin(), out.entries.end(),
                     [](const StreamOutEntry& a, const StreamOutEntry& b) { return a.slot < b.slot; });
    return out;
}

}  // namespace fx::detail
