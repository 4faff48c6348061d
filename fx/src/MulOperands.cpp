// MulOperands: see MulOperands.h.
#include "MulOperands.h"

#include "TypeNames.h"

#include <set>

namespace fx::detail {

namespace {

// `float1`, `int1x3`, `half4x1`, ...: the scalar types of HLSL with a dimension of one.
bool isOneDimensionTypeName(const std::string& word) {
    TypeDesc type;
    if (!parseScalarTypeName(word, type)) return false;
    return (type.shape == Shape::Vector && type.cols == 1) ||
           (type.shape == Shape::Matrix && (type.rows == 1 || type.cols == 1));
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

bool opens(const Token& token) {
    return token.is("(") || token.is("[") || token.is("{");
}
bool closes(const Token& token) {
    return token.is(")") || token.is("]") || token.is("}");
}

// What the text declares with a type of one dimension, in text order (a typedef precedes its uses).
struct OneDimensionNames {
    std::set<std::string> typedefs;
    std::set<std::string> members;  // of structs: read after a `.`
    std::set<std::string> values;   // variables, parameters and functions (by what they return)
};

OneDimensionNames declaredNames(const std::vector<Token>& tokens) {
    OneDimensionNames names;
    // The `{` of the struct bodies open at each token.
    std::vector<size_t> structBodies;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].is("{") && i >= 2 && tokens[i - 2].is("struct")) structBodies.push_back(i);
        if (tokens[i].is("}") && !structBodies.empty()) {
            // Only a struct's own `}` closes it: count the braces opened inside.
            int depth = 0;
            for (size_t k = structBodies.back() + 1; k < i; ++k)
                depth += tokens[k].is("{") - tokens[k].is("}");
            if (depth == 0) structBodies.pop_back();
        }
        const size_t end = oneDimensionTypeEnd(tokens, i, names.typedefs);
        if (end == i || end >= tokens.size() || tokens[end].kind != Token::Kind::Identifier) continue;
        std::set<std::string>& into = i > 0 && tokens[i - 1].is("typedef") ? names.typedefs
                                      : structBodies.empty()               ? names.values
                                                                           : names.members;
        into.insert(tokens[end].text);
        // `float1 a = f(x, y), b[2], c : TEXCOORD0;`: every declarator of the declaration. A parameter list's
        // next parameter starts with its type, a name followed by a name: there the declaration ends.
        int depth = 0;
        for (size_t k = end + 1; k + 1 < tokens.size(); ++k) {
            if (opens(tokens[k])) ++depth;
            if (closes(tokens[k]) && --depth < 0) break;
            if (depth > 0) continue;
            if (tokens[k].is(";") || tokens[k].is("{")) break;
            if (!tokens[k].is(",")) continue;
            const Token& next = tokens[k + 1];
            const Token& after = tokens[k + 2 < tokens.size() ? k + 2 : k + 1];
            if (next.kind != Token::Kind::Identifier || after.kind == Token::Kind::Identifier) break;
            into.insert(next.text);
        }
    }
    return names;
}

// Whether the argument tokens[begin, end) of a mul() is of one dimension as far as the text tells: a type of
// one dimension (a cast or a constructor), or a name declared with one, at its top level. A name inside a
// call's or a constructor's arguments or an index is another value (`float4(v.xyz, w)` is a float4).
bool argumentOfOneDimension(const std::vector<Token>& tokens, size_t begin, size_t end,
                            const OneDimensionNames& names) {
    int depth = 0;  // inside a call's, constructor's or index's brackets; grouping parentheses do not count
    std::vector<bool> counted;
    for (size_t k = begin; k < end; ++k) {
        const Token& token = tokens[k];
        if (opens(token)) {
            const bool grouping =
                token.is("(") && (k == begin || tokens[k - 1].kind != Token::Kind::Identifier);
            counted.push_back(!grouping);
            depth += !grouping;
            continue;
        }
        if (closes(token)) {
            if (!counted.empty()) {
                depth -= counted.back();
                counted.pop_back();
            }
            continue;
        }
        if (depth > 0) continue;
        if (oneDimensionTypeEnd(tokens, k, names.typedefs) != k) return true;
        if (token.kind != Token::Kind::Identifier) continue;
        const bool member = k > begin && tokens[k - 1].is(".");
        if ((member ? names.members : names.values).count(token.text)) return true;
    }
    return false;
}

}  // namespace

std::vector<HlslMessage> mulCallsGlslangCannotCompile(const std::vector<Token>& tokens) {
    std::vector<HlslMessage> errors;
    const OneDimensionNames names = declaredNames(tokens);

    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
        if (!tokens[i].is("mul") || !tokens[i + 1].is("(") || (i > 0 && tokens[i - 1].is("."))) continue;
        // The arguments: the tokens between the call's parentheses, split at its own commas.
        bool oneDimension = false;
        int depth = 0;
        size_t argument = i + 2, k = i + 1;
        for (; k < tokens.size(); ++k) {
            if (opens(tokens[k])) ++depth;
            const bool last = closes(tokens[k]) && --depth == 0;
            if (last || (depth == 1 && tokens[k].is(","))) {
                oneDimension = oneDimension || argumentOfOneDimension(tokens, argument, k, names);
                argument = k + 1;
            }
            if (last || depth < 0) break;
        }
        if (!oneDimension) continue;
        const Token& at = tokens[i];
        errors.push_back({true, at.loc.file, at.loc.line, at.ppColumn,
                          "'mul' : an operand has a dimension of one (a one-component vector or a matrix of "
                          "one row or column), which glslang's HLSL front end crashes on beside a matrix: "
                          "write it as a scalar or a full vector"});
    }
    return errors;
}

}  // namespace fx::detail
