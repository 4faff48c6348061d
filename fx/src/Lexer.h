// Lexer: tokens of preprocessed effect text. Honours `#line N "file"` so that every token carries the
// user's file and line, and recovers the user's column by finding the token's text in the original source
// line (glslang's preprocessor collapses whitespace inside lines). Private to fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <map>
#include <string>
#include <vector>

namespace fx::detail {

struct Token {
    enum class Kind { Identifier, Number, String, Punct, End };
    Kind kind = Kind::End;
    std::string text;        // identifier, punctuation, number spelling; String: the decoded contents
    double number = 0.0;     // Number
    bool isInteger = false;  // Number
    size_t begin = 0;        // offsets of the token's spelling in the preprocessed text
    size_t end = 0;
    SourceLoc loc;           // the user's file, line and column
    int ppColumn = 1;        // the column in the preprocessed text
    bool fromMacro = false;  // written by a macro's expansion, not found in the user's line; `loc` is the use

    bool is(const char* spelling) const {
        return kind != Kind::String && kind != Kind::End && text == spelling;
    }
};

// Lexes `text`; the last token is End. `files` holds the user's sources by the names #line uses.
std::vector<Token> lexEffect(const std::string& text, const std::string& mainPath,
                             const std::map<std::string, std::string>& files, SourceMap& sourceMap,
                             DiagnosticSink& diagnostics);

// Lexes a generated HLSL unit (preprocessed text with `#line` directives, as compileHlslToSpirv receives
// it), for the checks made before glslang parses it. Tokens carry the file and line of `#line`, and the
// column in the unit's line (`ppColumn`); what the lexer would report was reported as the effect's.
std::vector<Token> lexHlslUnit(const std::string& text);
// fxc read the effect keywords in any case (`Technique`, `PASS`, `Compile`, `Matrix`, `VERTEXSHADER`;
// strict mode only warned, X3086 "alternate cases ... are deprecated"): spells them as HLSL does, in the
// tokens and in `text` alike (same length, so token offsets stay valid), so that both the effect parser and
// glslang, which reads the functions' text, see one spelling.
void spellKeywordsAsHlsl(std::vector<Token>& tokens, std::string& text);

}  // namespace fx::detail
