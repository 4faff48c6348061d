// MulOperands: see MulOperands.h.
#include "MulOperands.h"

#include "Lexer.h"

#include <regex>
#include <set>

namespace fx::detail {

namespace {

// `float1`, `int1x3`, `half4x1`, ...: the scalar types of HLSL with a dimension of one.
bool isOneDimensionTypeName(const std::string& word) {
    static const std::regex name(
        "(float|half|double|int|uint|bool|dword|min16float|min10float|min16int|min12int|min16uint)"
        "(1|1x[1-4]|[1-4]x1)");
    return std::regex_match(word, name);
}

// The index past a type of one dimension starting at `i` (`float1`, `vector<float, 1>`,
// `matrix<float, 1, 3>`, or a name `typedef` gave such a type), or `i` where none starts there.
size_t oneDimensionTypeEnd(const std::vector<Token>& tokens, size_t i,
                           const std::set<std::string>& typedefs) {
    const Token& token = tokens[i];
    if (token.kind != Token::Kind::Identifier) return i;
    if (isOneDimensionTypeName(token.text) || typedefs.count(token.text)) return i + 1;
    const bool vector = token.text == "vector", matrix = token.text == "matrix";
    if ((!vector && !matrix) || i + 1 >= tokens.size() || !tokens[i + 1].is("<")) return i;
    size_t close = i + 2;
    bool one = false;
    for (; close < tokens.size() && !tokens[close].is(">"); ++close)
        one = one || (tokens[close].kind == Token::Kind::Number && tokens[close].text == "1" &&
                      tokens[close - 1].is(","));
    return one && close < tokens.size() ? close + 1 : i;
}

}  // namespace

std::vector<HlslMessage> mulCallsGlslangCannotCompile(const std::string& text) {
    std::vector<HlslMessage> errors;
    if (text.find("mul") == std::string::npos) return errors;
    SourceMap sourceMap;
    DiagnosticList lexerMessages;  // the effect's own lexing reported these already
    const std::vector<Token> tokens = lexEffect(text, "", {}, sourceMap, lexerMessages);

    // The names declared with a type of one dimension: variables, parameters, members, functions (by what
    // they return) and typedefs. One pass in text order, so that a typedef precedes its uses.
    std::set<std::string> typedefs, names;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const size_t end = oneDimensionTypeEnd(tokens, i, typedefs);
        if (end == i || end >= tokens.size() || tokens[end].kind != Token::Kind::Identifier) continue;
        (i > 0 && tokens[i - 1].is("typedef") ? typedefs : names).insert(tokens[end].text);
    }

    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
        if (!tokens[i].is("mul") || !tokens[i + 1].is("(") || (i > 0 && tokens[i - 1].is("."))) continue;
        int depth = 0;
        bool oneDimension = false;
        for (size_t k = i + 1; k < tokens.size(); ++k) {
            depth += tokens[k].is("(") ? 1 : tokens[k].is(")") ? -1 : 0;
            if (depth == 0) break;
            oneDimension = oneDimension || oneDimensionTypeEnd(tokens, k, typedefs) != k ||
                           (tokens[k].kind == Token::Kind::Identifier && names.count(tokens[k].text));
        }
        if (!oneDimension) continue;
        const SourceLoc& at = tokens[i].loc;
        errors.push_back({true, at.file, at.line, 0,
                          "'mul' : an operand has a dimension of one (a one-component vector or a matrix of "
                          "one row or column), which glslang's HLSL front end cannot multiply: write it as a "
                          "scalar or a full vector"});
    }
    return errors;
}

}  // namespace fx::detail
