// Lexer: preprocessed text -> tokens with the user's locations.
#include "Lexer.h"
#include "StringEscapes.h"

#include <fx/RenderStates.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace fx::detail {

namespace {

constexpr size_t kMaxTokens = 1u << 20;  // see the check in lexEffect

bool isIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
    return isIdentStart(c) || (c >= '0' && c <= '9');
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

const char* const kPunctuation[] = {"<<=", ">>=", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "++", "--",
                                    "+=",  "-=",  "*=", "/=", "%=", "&=", "|=", "^=", "::", "->", "{",  "}",
                                    "(",   ")",   "[",  "]",  ";",  ",",  ".",  ":",  "?",  "=",  "<",  ">",
                                    "+",   "-",   "*",  "/",  "%",  "!",  "~",  "&",  "|",  "^"};

// The lines of each user file, split once.
class OriginalLines {
public:
    explicit OriginalLines(const std::map<std::string, std::string>& files) : mFiles(files) {}
    // The user's line, or nullptr if unknown.
    const std::string_view* line(const std::string& file, int line) {
        auto found = mLines.find(file);
        if (found == mLines.end()) {
            std::vector<std::string_view> lines;
            auto text = mFiles.find(file);
            if (text != mFiles.end()) {
                std::string_view all = text->second;
                size_t start = 0;
                while (start <= all.size()) {
                    size_t end = all.find('\n', start);
                    if (end == std::string_view::npos) end = all.size();
                    std::string_view piece = all.substr(start, end - start);
                    if (!piece.empty() && piece.back() == '\r') piece.remove_suffix(1);
                    lines.push_back(piece);
                    start = end + 1;
                }
            }
            found = mLines.emplace(file, std::move(lines)).first;
        }
        if (line < 1 || static_cast<size_t>(line) > found->second.size()) return nullptr;
        return &found->second[line - 1];
    }

private:
    const std::map<std::string, std::string>& mFiles;
    std::map<std::string, std::vector<std::string_view>> mLines;
};

// Finds `spelling` in `line` at or after `from` as a whole token.
size_t findToken(std::string_view line, std::string_view spelling, size_t from) {
    if (spelling.empty()) return std::string_view::npos;
    for (size_t at = line.find(spelling, from); at != std::string_view::npos;
         at = line.find(spelling, at + 1)) {
        bool startOk = !isIdentChar(spelling.front()) || at == 0 || !isIdentChar(line[at - 1]);
        size_t after = at + spelling.size();
        bool endOk = !isIdentChar(spelling.back()) || after >= line.size() || !isIdentChar(line[after]);
        if (startOk && endOk) return at;
    }
    return std::string_view::npos;
}

// Where each macro of the user's files is defined (`#define NAME`), read from the files on first use.
class MacroDefinitions {
public:
    explicit MacroDefinitions(const std::map<std::string, std::string>& files) : mFiles(files) {}

    // The definition of `name` in effect at `line` of `file`: the last one above that line in the same
    // file, else the last one in another file (a header included above); nullptr if none (a macro
    // defined on the command line).
    const SourceLoc* find(std::string_view name, const std::string& file, int line) {
        if (!mRead) read();
        auto found = mDefinitions.find(std::string(name));
        if (found == mDefinitions.end()) return nullptr;
        const SourceLoc* best = nullptr;
        for (const SourceLoc& definition : found->second)
            if (definition.file == file && definition.line < line) best = &definition;
        if (best) return best;
        for (const SourceLoc& definition : found->second)
            if (definition.file != file) best = &definition;
        return best;
    }

private:
    void read() {
        mRead = true;
        for (const auto& [file, text] : mFiles) {
            int number = 1;
            for (size_t start = 0; start < text.size(); ++number) {
                size_t end = text.find('\n', start);
                if (end == std::string::npos) end = text.size();
                std::string_view line(text.data() + start, end - start);
                start = end + 1;
                size_t at = line.find_first_not_of(" \t");
                if (at == std::string_view::npos || line[at] != '#') continue;
                at = line.find_first_not_of(" \t", at + 1);
                if (at == std::string_view::npos || line.compare(at, 6, "define") != 0) continue;
                at = line.find_first_not_of(" \t", at + 6);
                if (at == std::string_view::npos || !isIdentStart(line[at])) continue;
                size_t nameEnd = at;
                while (nameEnd < line.size() && isIdentChar(line[nameEnd])) ++nameEnd;
                mDefinitions[std::string(line.substr(at, nameEnd - at))].push_back(
                    SourceLoc{file, number, static_cast<int>(at) + 1});
            }
        }
    }

    const std::map<std::string, std::string>& mFiles;
    bool mRead = false;
    std::map<std::string, std::vector<SourceLoc>> mDefinitions;  // in file order
};

// The identifier that starts at `at` in `line`, or "".
std::string_view identifierAt(std::string_view line, size_t at) {
    if (at >= line.size() || !isIdentStart(line[at])) return {};
    size_t end = at;
    while (end < line.size() && isIdentChar(line[end])) ++end;
    return line.substr(at, end - at);
}

}  // namespace

std::vector<Token> lexEffect(const std::string& text, const std::string& mainPath,
                             const std::map<std::string, std::string>& files, SourceMap& sourceMap,
                             DiagnosticSink& diagnostics) {
    std::vector<Token> tokens;
    OriginalLines originals(files);
    MacroDefinitions definitions(files);
    // The last macro used on the current line: a token of an expansion found nowhere in the user's line
    // stands at its name (the arguments of a function-like macro come before the rest of its body).
    std::optional<SourceMap::MacroExpansion> lineExpansion;
    std::string file = mainPath;
    int line = 1;
    size_t lineStart = 0;
    size_t origCursor = 0;  // where the previous token ended in the user's line
    bool atLineStart = true;
    int invalidCount = 0;
    size_t pos = 0;
    const size_t n = text.size();

    auto newLine = [&](size_t next) {
        ++line;
        lineStart = next;
        origCursor = 0;
        atLineStart = true;
        lineExpansion.reset();
    };

    while (pos < n) {
        char c = text[pos];
        if (c == '\n') {
            newLine(++pos);
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++pos;
            continue;
        }
        if (c == '#' && atLineStart) {
            // A directive the preprocessor passed through: #line N "file", #pragma ...
            size_t end = text.find('\n', pos);
            if (end == std::string::npos) end = n;
            std::string directive = text.substr(pos + 1, end - pos - 1);
            size_t at = directive.find_first_not_of(" \t");
            if (at != std::string::npos && directive.compare(at, 4, "line") == 0) {
                const char* p = directive.c_str() + at + 4;
                char* after = nullptr;
                long number = std::strtol(p, &after, 10);
                if (after != p && number >= 0 && number < (1L << 30)) {
                    line = static_cast<int>(number) - 1;  // the next line is line `number`
                    const char* quote = std::strchr(after, '"');
                    if (quote) {
                        const char* close = std::strchr(quote + 1, '"');
                        if (close) file.assign(quote + 1, close);
                    }
                }
            }
            pos = end;
            continue;
        }
        atLineStart = false;

        Token token;
        token.begin = pos;
        token.ppColumn = static_cast<int>(pos - lineStart) + 1;
        if (isIdentStart(c)) {
            while (pos < n && isIdentChar(text[pos])) ++pos;
            token.kind = Token::Kind::Identifier;
            token.text = text.substr(token.begin, pos - token.begin);
        } else if (isDigit(c) || (c == '.' && pos + 1 < n && isDigit(text[pos + 1]))) {
            token.kind = Token::Kind::Number;
            bool isFloat = false;
            if (c == '0' && pos + 1 < n && (text[pos + 1] == 'x' || text[pos + 1] == 'X')) {
                pos += 2;
                while (pos < n && isxdigit(static_cast<unsigned char>(text[pos]))) ++pos;
                token.number =
                    static_cast<double>(std::strtoull(text.c_str() + token.begin + 2, nullptr, 16));
            } else {
                while (pos < n && isDigit(text[pos])) ++pos;
                if (pos < n && text[pos] == '.') {
                    isFloat = true;
                    ++pos;
                    while (pos < n && isDigit(text[pos])) ++pos;
                }
                if (pos < n && (text[pos] == 'e' || text[pos] == 'E')) {
                    size_t save = pos++;
                    if (pos < n && (text[pos] == '+' || text[pos] == '-')) ++pos;
                    if (pos < n && isDigit(text[pos])) {
                        isFloat = true;
                        while (pos < n && isDigit(text[pos])) ++pos;
                    } else {
                        pos = save;
                    }
                }
                std::string digits = text.substr(token.begin, pos - token.begin);
                token.number = std::strtod(digits.c_str(), nullptr);
            }
            while (pos < n && strchr("fFhHlLuU", text[pos])) {
                if (text[pos] == 'f' || text[pos] == 'F' || text[pos] == 'h' || text[pos] == 'H')
                    isFloat = true;
                ++pos;
            }
            token.isInteger = !isFloat;
            token.text = text.substr(token.begin, pos - token.begin);
            if (pos < n && isIdentChar(text[pos])) {  // 12abc: report once, skip the rest
                size_t bad = pos;
                while (pos < n && isIdentChar(text[pos])) ++pos;
                diagnostics.report(DiagId::InvalidCharacter,
                                   SourceLoc{file, line, static_cast<int>(bad - lineStart) + 1},
                                   {text.substr(bad, 1)});
            }
        } else if (c == '"') {
            token.kind = Token::Kind::String;
            ++pos;
            bool closed = false;
            while (pos < n && text[pos] != '\n') {
                char s = text[pos];
                if (s == '"') {
                    closed = true;
                    ++pos;
                    break;
                }
                if (s == '\\' && pos + 1 < n && text[pos + 1] != '\n') {
                    // An unknown escape keeps its backslash, as fxc kept it (`"C:\Users\Desktop"`, a
                    // Windows path); the preprocessor warned about it (StringEscapes.h).
                    const char e = text[pos + 1];
                    const std::optional<char> decoded = decodeEscape(e);
                    token.text += decoded ? std::string(1, *decoded) : std::string{'\\', e};
                    pos += 2;
                    continue;
                }
                token.text += s;
                ++pos;
            }
            if (!closed)
                diagnostics.report(DiagId::UnterminatedString, SourceLoc{file, line, token.ppColumn});
        } else {
            for (const char* p : kPunctuation) {
                size_t len = std::strlen(p);
                if (text.compare(pos, len, p) == 0) {
                    token.kind = Token::Kind::Punct;
                    token.text = p;
                    pos += len;
                    break;
                }
            }
            if (token.kind != Token::Kind::Punct) {
                if (++invalidCount <= 20) {
                    char shown[8];
                    unsigned char u = static_cast<unsigned char>(c);
                    if (u < 0x20 || u >= 0x7f)
                        std::snprintf(shown, sizeof shown, "\\x%02X", u);
                    else
                        std::snprintf(shown, sizeof shown, "%c", c);
                    // Column: best effort, recovered below for printable characters.
                    int column = token.ppColumn;
                    if (const std::string_view* orig = originals.line(file, line)) {
                        size_t at = orig->find(c, origCursor);
                        if (at != std::string_view::npos) column = static_cast<int>(at) + 1;
                    }
                    diagnostics.report(DiagId::InvalidCharacter, SourceLoc{file, line, column}, {shown});
                }
                ++pos;
                continue;
            }
        }
        token.end = pos;

        // Column recovery: the token's spelling in the user's line, left to right.
        token.loc.file = file;
        token.loc.line = line;
        token.loc.column = token.ppColumn;
        if (const std::string_view* orig = originals.line(file, line)) {
            std::string_view spelling(text.data() + token.begin, token.end - token.begin);
            size_t at = findToken(*orig, spelling, origCursor);
            if (at != std::string_view::npos) {
                token.loc.column = static_cast<int>(at) + 1;
                origCursor = at + spelling.size();
            } else {
                // From a macro expansion: point at the macro's name, the next thing the user wrote, or
                // the last macro used on this line.
                token.fromMacro = true;
                size_t next = orig->find_first_not_of(" \t", origCursor);
                const std::string_view name = identifierAt(*orig, next);
                if (const SourceLoc* definition =
                        name.empty() ? nullptr : definitions.find(name, file, line)) {
                    lineExpansion = SourceMap::MacroExpansion{
                        std::string(name), SourceLoc{file, line, static_cast<int>(next) + 1}, *definition};
                    if (!sourceMap.expansionAt(lineExpansion->use)) sourceMap.addExpansion(*lineExpansion);
                }
                token.loc.column =
                    lineExpansion
                        ? lineExpansion->use.column
                        : static_cast<int>(next == std::string_view::npos ? orig->size() : next) + 1;
            }
        }
        sourceMap.add(token.loc.file, token.loc.line, token.ppColumn, token.loc.column, token.fromMacro);
        // `__fx_stringize__ X` is what the preprocessor made of a D3DX `#X` (see markStringizing): the
        // marker and the substituted argument become the string literal "X".
        if (!tokens.empty() && tokens.back().kind == Token::Kind::Identifier &&
            tokens.back().text == "__fx_stringize__" && token.kind != Token::Kind::String) {
            Token& marker = tokens.back();
            marker.kind = Token::Kind::String;
            marker.text = token.text;
            marker.end = token.end;
            marker.loc = token.loc;
            continue;
        }
        tokens.push_back(std::move(token));
        // A token costs ~200 bytes with its location: without a bound, 16 MB of `+1+1...` (within
        // ParseOptions::maxSourceBytes) took over 4 GB. Real effects have a few thousand tokens.
        if (tokens.size() > kMaxTokens) {
            diagnostics.report(DiagId::TooManyTokens, tokens.back().loc, {std::to_string(kMaxTokens)});
            break;
        }
    }

    Token end;
    end.kind = Token::Kind::End;
    end.begin = end.end = n;
    end.ppColumn = static_cast<int>(n - lineStart) + 1;
    if (!tokens.empty()) {
        const Token& last = tokens.back();
        end.loc = last.loc;
        end.loc.column = last.loc.column + static_cast<int>(last.end - last.begin);
    } else {
        end.loc = SourceLoc{file, line, 1};
    }
    tokens.push_back(end);
    return tokens;
}

void spellKeywordsAsHlsl(std::vector<Token>& tokens, std::string& text) {
    // The effect-framework keywords and the type keywords effects wrote capitalized. Not `texture`
    // (already case-blind as a parameter type) nor `true`/`false` (macros in some headers).
    static const char* const kKeywords[] = {"technique",    "technique10",   "technique11",    "pass",
                                            "compile",      "CompileShader", "sampler_state",  "matrix",
                                            "VertexShader", "PixelShader",   "GeometryShader", "fxgroup"};
    for (Token& token : tokens) {
        if (token.kind != Token::Kind::Identifier) continue;
        for (const char* keyword : kKeywords) {
            if (token.text == keyword || !equalsIgnoreCase(token.text, keyword)) continue;
            token.text = keyword;
            if (token.end - token.begin == token.text.size())
                text.replace(token.begin, token.text.size(), keyword);
            break;
        }
    }
}

std::vector<Token> lexHlslUnit(const std::string& text) {
    SourceMap sourceMap;
    DiagnosticList reportedWithTheEffect;
    return lexEffect(text, "", {}, sourceMap, reportedWithTheEffect);
}

}  // namespace fx::detail
