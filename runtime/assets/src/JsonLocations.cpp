// JsonLocations: see JsonLocations.h.
#include "JsonLocations.h"

#include <cctype>

#include <algorithm>
#include <string_view>

namespace runtime {

JsonLocations::JsonLocations(std::string path, const std::string& text)
    : mPath(std::move(path)), mText(text) {
    skipSpace();
    if (mAt < mText.size()) scanValue("", 0);
}

fx::SourceLoc JsonLocations::at(const std::string& pointer) const {
    auto it = mStarts.find(pointer);
    return it != mStarts.end() ? it->second : fx::SourceLoc{mPath, 1, 1};
}

fx::SourceLoc JsonLocations::locationOf(const std::string& path, const std::string& text, size_t offset) {
    fx::SourceLoc loc{path, 1, 1};
    offset = std::min(offset, text.size());
    for (size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++loc.line;
            loc.column = 1;
        } else {
            ++loc.column;
        }
    }
    return loc;
}

fx::SourceLoc JsonLocations::syntaxErrorLocation(const std::string& path, const std::string& text,
                                                 size_t byte) {
    const size_t last = byte > 0 ? byte - 1 : 0;
    size_t start = last;
    if (last < text.size() && text[last] == '"') {
        for (size_t i = last; i-- > 0;)
            if (text[i] == '"' && (i == 0 || text[i - 1] != '\\')) {
                start = i;
                break;
            }
    } else if (last < text.size()) {
        auto inLiteral = [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
        };
        while (start > 0 && inLiteral(text[last]) && inLiteral(text[start - 1])) --start;
    }
    return locationOf(path, text, start);
}

void JsonLocations::reportSyntaxError(const std::string& path, const std::string& text, size_t byte,
                                      const std::string& what, fx::DiagnosticSink& diagnostics) {
    std::string message = what;
    if (auto dash = message.find(" - "); dash != std::string::npos) message = message.substr(dash + 3);
    diagnostics.report(fx::DiagId::SceneSyntaxError, syntaxErrorLocation(path, text, byte), {message});
}

void JsonLocations::skipSpace() {
    while (mAt < mText.size() &&
           (mText[mAt] == ' ' || mText[mAt] == '\t' || mText[mAt] == '\r' || mText[mAt] == '\n')) {
        if (mText[mAt] == '\n') {
            ++mLine;
            mLineStart = mAt + 1;
        }
        ++mAt;
    }
}

std::string JsonLocations::scanString() {
    std::string out;
    ++mAt;  // the opening quote
    while (mAt < mText.size() && mText[mAt] != '"') {
        char c = mText[mAt++];
        if (c == '\\' && mAt < mText.size()) {
            // Keys are plain names in practice; the common escapes decode, \u stays as written.
            const char e = mText[mAt++];
            c = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'u' ? 'u' : e;
            if (e == 'u') out += '\\';
        }
        // A JSON pointer escapes '~' as ~0 and '/' as ~1 (RFC 6901).
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    ++mAt;  // the closing quote
    return out;
}

void JsonLocations::skipNested() {
    int open = 0;
    do {
        const char c = mText[mAt];
        if (c == '"') {
            scanString();
            continue;
        }
        if (c == '{' || c == '[') ++open;
        if (c == '}' || c == ']') --open;
        if (c == '\n') {
            ++mLine;
            mLineStart = mAt + 1;
        }
        ++mAt;
    } while (open > 0 && mAt < mText.size());
}

void JsonLocations::scanValue(const std::string& pointer, int depth) {
    mStarts[pointer] = fx::SourceLoc{mPath, mLine, static_cast<int>(mAt - mLineStart) + 1};
    if (mAt >= mText.size()) return;
    const char c = mText[mAt];
    if ((c == '{' || c == '[') && depth >= kMaxDepth) {
        skipNested();
    } else if (c == '{' || c == '[') {
        const char close = c == '{' ? '}' : ']';
        ++mAt;
        skipSpace();
        for (size_t index = 0; mAt < mText.size() && mText[mAt] != close; ++index) {
            std::string child = pointer + "/";
            if (c == '{') {
                child += scanString();
                skipSpace();
                ++mAt;  // ':'
                skipSpace();
            } else {
                child += std::to_string(index);
            }
            scanValue(child, depth + 1);
            skipSpace();
            if (mAt < mText.size() && mText[mAt] == ',') {
                ++mAt;
                skipSpace();
            }
        }
        ++mAt;
    } else if (c == '"') {
        scanString();
    } else {
        // A number, true, false or null: up to the next delimiter.
        while (mAt < mText.size() &&
               std::string_view(",]} \t\r\n").find(mText[mAt]) == std::string_view::npos)
            ++mAt;
    }
}

}  // namespace runtime
