// StringEscapes: see StringEscapes.h.
#include "StringEscapes.h"

namespace fx::detail {

namespace {

// Control bytes, which effects' strings do not hold in practice: one in a string is refused here, as the
// character check refuses it outside strings.
constexpr char kBackslash = '\x01';
constexpr char kQuote = '\x02';

}  // namespace

std::optional<char> decodeEscape(char e) {
    switch (e) {
        case 'n':
            return '\n';
        case 't':
            return '\t';
        case 'r':
            return '\r';
        case '0':
            return '\0';
        case 'a':
            return '\a';
        case 'b':
            return '\b';
        case 'f':
            return '\f';
        case 'v':
            return '\v';
        case '\\':
        case '"':
        case '\'':
        case '?':
            return e;
        default:
            return std::nullopt;
    }
}

std::string hideStringEscapes(const std::string& text, const std::string& file, DiagnosticSink& diagnostics) {
    std::string out = text;
    enum class State { Code, LineComment, BlockComment, String } state = State::Code;
    bool lineStart = true, otherDirective = false;
    int line = 1;
    size_t lineBegin = 0;
    for (size_t i = 0; i < out.size(); ++i) {
        const char c = out[i];
        if (c == '\n') {
            // A directive continues over backslash-newline; a string or a line comment ends.
            const bool continued = i > 0 && text[i - 1] == '\\';
            if (!continued) otherDirective = false;
            if (state != State::BlockComment) state = State::Code;
            lineStart = true;
            ++line;
            lineBegin = i + 1;
            continue;
        }
        if (state == State::LineComment) continue;
        if (state == State::BlockComment) {
            if (c == '*' && i + 1 < out.size() && out[i + 1] == '/') state = State::Code, ++i;
            continue;
        }
        if (state == State::String) {
            if (c == kBackslash || c == kQuote) {
                // The placeholders' own bytes in the user's string would come back as '\\' or '"'.
                diagnostics.report(DiagId::InvalidCharacter,
                                   SourceLoc{file, line, static_cast<int>(i - lineBegin) + 1},
                                   {c == kBackslash ? "\\x01" : "\\x02"});
                out[i] = ' ';
            } else if (c == '"') {
                state = State::Code;
            } else if (c == '\\' && i + 1 < out.size() && out[i + 1] != '\n' && out[i + 1] != '\r') {
                const char e = out[i + 1];
                if (!decodeEscape(e))
                    diagnostics.report(DiagId::UnknownEscapeSequence,
                                       SourceLoc{file, line, static_cast<int>(i - lineBegin) + 1},
                                       {std::string(1, e)});
                out[i] = kBackslash;
                if (e == '\\') out[i + 1] = kBackslash;
                if (e == '"') out[i + 1] = kQuote;
                ++i;
            }
            continue;
        }
        if (lineStart && c != ' ' && c != '\t') {
            lineStart = false;
            if (c == '#') {
                const size_t word = text.find_first_not_of(" \t", i + 1);
                otherDirective = word == std::string::npos || text.compare(word, 6, "define") != 0;
            }
        }
        if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
            state = State::LineComment;
        } else if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
            state = State::BlockComment;
            ++i;
        } else if (c == '"' && !otherDirective) {
            state = State::String;
        }
    }
    return out;
}

void restoreStringEscapes(std::string& text) {
    for (char& c : text) {
        if (c == kBackslash) c = '\\';
        if (c == kQuote) c = '"';
    }
}

}  // namespace fx::detail
