// StreamOutDeclaration: see StreamOutDeclaration.h.
#include "StreamOutDeclaration.h"

#include "StringLocation.h"

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

}  // namespace

std::vector<StreamOutElement> parseStreamOutDeclaration(const Expr& declaration,
                                                        const ReportStreamOutError& error) {
    std::vector<StreamOutElement> elements;
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
        StreamOutElement element;
        element.loc = stringLocation(declaration, first);
        auto fail = [&](const std::string& why) {
            error(DiagId::InvalidStreamOutDeclaration, element.loc, {entry, why});
        };
        std::string_view rest(entry);
        if (size_t colon = rest.find(':'); colon != std::string_view::npos) {
            std::string_view slot = rest.substr(0, colon);
            if (slot.size() != 1 || slot[0] < '0' || slot[0] >= '0' + kStreamOutSlots) {
                fail("the output slot is not one of 0..3");
                continue;
            }
            element.slot = slot[0] - '0';
            rest.remove_prefix(colon + 1);
            while (!rest.empty() && isBlank(rest.front())) rest.remove_prefix(1);
        }
        std::string_view name = rest.substr(0, rest.find('.'));
        if (name.empty()) {
            fail("it names no semantic");
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
                fail("'" + std::string(name) + "' is not a semantic name with an optional index");
                continue;
            }
            if (digits < name.size()) element.semanticIndex = std::stoi(std::string(name.substr(digits)));
            name = name.substr(0, digits);
        }
        element.semantic = std::string(name);
        if (size_t dot = rest.find('.'); dot != std::string_view::npos) {
            std::string_view mask = rest.substr(dot + 1);
            if (!readMask(mask, element.startComponent, element.componentCount)) {
                fail("'" + std::string(mask) + "' is not a component mask (contiguous components of xyzw)");
                continue;
            }
        }
        elements.push_back(std::move(element));
    }
    return elements;
}

void validateConstructGSWithSO(const Expr& call, const ReportStreamOutError& error) {
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
        error(
            DiagId::InvalidCompileExpression, call.loc,
            {"expected ConstructGSWithSO(shader, \"declaration\") or ConstructGSWithSO(shader, \"stream0\", "
             "\"stream1\", \"stream2\", \"stream3\", rasterizedStream)"});
        return;
    }
    for (size_t i = 1; i < call.args.size() && i < 5; ++i)
        if (call.args[i].kind == Expr::Kind::String) parseStreamOutDeclaration(call.args[i], error);
}

}  // namespace fx::detail
