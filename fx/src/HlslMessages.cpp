// HlslMessages: what glslang and SPIRV-Cross say about a generated unit, said at the user's source: the
// .fx line through #line, generated code at the pass's compile expression (see Compiler.h).

#include "Compiler.h"
#include "HlslToSpirv.h"
#include "TypeNames.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>
#include <string_view>
#include <utility>

namespace fx::detail {

namespace {

// A line of the generated unit and the user's file and line it stands for (through its #line).
struct UnitLine {
    std::string file;
    int number = 0;
    std::string text;
};

std::vector<UnitLine> unitLines(const std::string& text) {
    std::vector<UnitLine> lines;
    std::string file;
    int number = 0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string l = text.substr(pos, end - pos);
        pos = end + 1;
        if (l.rfind("#line ", 0) == 0) {
            size_t q = l.find('"');
            number = std::stoi(l.substr(6)) - 1;
            file = q == std::string::npos ? file : l.substr(q + 1, l.rfind('"') - q - 1);
        } else {
            lines.push_back({file, ++number, std::move(l)});
        }
    }
    return lines;
}

// Where `line` ends, comments and trailing blanks left out; npos if it holds no code.
size_t codeEnd(const std::string& line) {
    const size_t comment = line.find("//");
    const size_t last =
        line.find_last_not_of(" \t\r", comment == std::string::npos ? std::string::npos : comment - 1);
    return comment == 0 || last == std::string::npos ? std::string::npos : last + 1;
}

// Whether the value a message stands at follows a cast the code spells (`(float3)v`, `(half)(a + b)`):
// glslang places the conversion of a cast at its operand, as it places an implicit one, but a cast is
// explicit and fxc said nothing of it.
bool followsSpelledCast(const std::vector<UnitLine>& lines, const HlslMessage& m) {
    const auto line = std::find_if(lines.begin(), lines.end(),
                                   [&](const UnitLine& l) { return l.file == m.file && l.number == m.line; });
    if (line == lines.end() || m.column <= 1) return false;
    std::string before = line->text.substr(0, std::min(line->text.size(), static_cast<size_t>(m.column - 1)));
    const auto trim = [&before](const char* characters) {
        while (!before.empty() && std::strchr(characters, before.back())) before.pop_back();
    };
    trim(" \t(");
    if (before.empty() || before.back() != ')') return false;
    before.pop_back();
    trim(" \t");
    const size_t name =
        before.find_last_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_");
    TypeDesc type;
    const std::string typeName = before.substr(name == std::string::npos ? 0 : name + 1);
    before.resize(name == std::string::npos ? 0 : name + 1);
    trim(" \t");
    return !before.empty() && before.back() == '(' && parseScalarTypeName(typeName, type);
}

}  // namespace

SourceLoc Compiler::userLocation(const HlslMessage& m, const LoweredStage& lowered) const {
    if (m.file.empty() || m.file == kGeneratedFile || m.line <= 0) return lowered.compileLoc;
    SourceLoc loc{m.file, m.line, m.column};
    if (loc.column == 0) {
        // glslang 12 gives no column: find the token the message quotes ('name' : ...) on that line of the
        // unit, whose columns are the preprocessed text's (declarations are padded to their column).
        const std::vector<UnitLine> lines = unitLines(lowered.hlsl);
        size_t at = 0;
        while (at < lines.size() && !(lines[at].file == m.file && lines[at].number == m.line)) ++at;
        const std::string line = at < lines.size() ? lines[at].text : std::string();
        // "';' : Expected" names the token after the gap, the next line's first when the ';' is missing
        // at the end of a line: point after that line's last token, where the ';' belongs.
        if (m.text.rfind("';' : Expected", 0) == 0 && at < lines.size()) {
            size_t previous = at;
            while (previous > 0 && codeEnd(lines[previous - 1].text) == std::string::npos) --previous;
            if (previous > 0 && lines[previous - 1].file == m.file) {
                const UnitLine& before = lines[previous - 1];
                // Only a line that ends an expression (a name, a number, ')' or ']') can be the one.
                const char last = before.text[codeEnd(before.text) - 1];
                if (std::isalnum(static_cast<unsigned char>(last)) || last == '_' || last == ')' ||
                    last == ']')
                    return mEffect.sourceMap.map(
                        SourceLoc{before.file, before.number, static_cast<int>(codeEnd(before.text)) + 1});
            }
        }
        size_t q1 = m.text.find('\''), q2 = q1 == std::string::npos ? q1 : m.text.find('\'', q1 + 1);
        size_t column = std::string::npos;
        if (q2 != std::string::npos && q2 > q1 + 1) column = line.find(m.text.substr(q1 + 1, q2 - q1 - 1));
        if (column == std::string::npos) column = line.find_first_not_of(" \t");
        loc.column = column == std::string::npos ? 0 : static_cast<int>(column) + 1;
    }
    return mEffect.sourceMap.map(loc);
}

void Compiler::reportHlslMessages(const std::vector<HlslMessage>& messages, const LoweredStage& lowered) {
    // After glslang's first error its parser recovers with generic follow-ons at column 1 ("'declaration'
    // : Expected", "'expression' : Expected", "'' : Could not perform requested binary operation") that
    // only repeat the first one.
    bool hadError = false;
    auto isFollowOn = [](const std::string& text) {
        return text.rfind("'declaration' : Expected", 0) == 0 ||
               text.rfind("'expression' : Expected", 0) == 0 ||
               text.rfind("'function call arguments' : Expected", 0) == 0 || text.rfind("'' : ", 0) == 0;
    };
    // mul()'s truncation of its vector is said once, as mul()'s.
    std::set<std::pair<std::string, int>> mulMismatches;
    for (const HlslMessage& m : messages)
        if (m.text.find("mul() matrix size mismatch") != std::string::npos)
            mulMismatches.insert({m.file, m.line});
    const std::vector<UnitLine> lines = unitLines(lowered.hlsl);
    for (const HlslMessage& m : messages) {
        if (m.error && hadError && isFollowOn(m.text)) continue;
        if (m.text.rfind(kImplicitTruncationPrefix, 0) == 0 &&
            (mulMismatches.count({m.file, m.line}) || followsSpelledCast(lines, m)))
            continue;
        hadError = hadError || m.error;
        SourceLoc loc = userLocation(m, lowered);
        std::string text = m.text;
        while (!text.empty() && text.back() == ' ') text.pop_back();
        if (m.error && m.file == kGeneratedFile)
            error(DiagId::HlslErrorInGeneratedCode, loc, {text, lowered.entryPoint});
        else if (m.error)
            error(DiagId::HlslError, loc, {text});
        else if (m.file != kGeneratedFile && text.find("mul() matrix size mismatch") != std::string::npos)
            mDiagnostics.report(DiagId::ImplicitTruncation, loc, {});
        else if (m.file != kGeneratedFile && text.rfind(kImplicitTruncationPrefix, 0) == 0)
            mDiagnostics.report(DiagId::ImplicitVectorTruncation, loc,
                                {text.substr(std::string_view(kImplicitTruncationPrefix).size())});
        else if (m.file != kGeneratedFile)
            mDiagnostics.report(DiagId::HlslWarning, loc, {text});
    }
}

// SPIRV-Cross speaks of SPIR-V, which the user never wrote: say which shader of the effect it failed on
// and, where the cause is known, what in the effect led there.
void Compiler::reportCrossError(const std::string& message, const LoweredStage& lowered) {
    const DiagId id = message.find("Cannot find mapping for combined sampler") != std::string::npos
                          ? DiagId::CrossCompileCombinedSampler
                          : DiagId::CrossCompileError;
    error(id, lowered.compileLoc,
          {std::string(shaderStageName(lowered.stage)), lowered.entryPoint, lowered.profile, message});
}

SourceLoc Compiler::functionLocation(const LoweredStage& lowered) const {
    std::vector<const FunctionDecl*> functions = mEffect.findFunctions(lowered.entryPoint);
    return functions.empty() || !functions.front()->loc.valid() ? lowered.compileLoc : functions.front()->loc;
}

}  // namespace fx::detail
