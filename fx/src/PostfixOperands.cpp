// PostfixOperands: see PostfixOperands.h.
#include "PostfixOperands.h"

#include "TypeNames.h"

#include <algorithm>
#include <set>
#include <vector>

namespace fx::detail {

namespace {

// Words that end no operand: an operator written after them is a prefix one, a parenthesis after them
// opens no call.
bool isStatementKeyword(const Token& token) {
    static const std::set<std::string> keywords = {"return",  "if",    "else",     "while",
                                                   "for",     "do",    "switch",   "case",
                                                   "default", "break", "continue", "discard"};
    return token.kind == Token::Kind::Identifier && keywords.count(token.text) != 0;
}

// A name, number or string literal: what a postfix operator after it applies to.
bool isOperandWord(const Token& token) {
    return (token.kind == Token::Kind::Identifier && !isStatementKeyword(token)) ||
           token.kind == Token::Kind::Number || token.kind == Token::Kind::String;
}

// HLSL's scalar, vector and matrix type names, `vector` and `matrix`, and the names `struct` and
// `typedef` declare in the text: what a cast `(T)` names.
class TypeNames {
public:
    explicit TypeNames(const std::vector<Token>& tokens) {
        for (size_t i = 0; i + 1 < tokens.size(); ++i) {
            if (tokens[i].is("struct") && tokens[i + 1].kind == Token::Kind::Identifier)
                mDeclared.insert(tokens[i + 1].text);
            if (!tokens[i].is("typedef")) continue;
            size_t end = i + 1;
            while (end < tokens.size() && !tokens[end].is(";") && !tokens[end].is("[")) ++end;
            if (end > i + 1 && tokens[end - 1].kind == Token::Kind::Identifier)
                mDeclared.insert(tokens[end - 1].text);
        }
    }
    bool contains(const Token& token) const {
        TypeDesc scalar;
        return token.kind == Token::Kind::Identifier &&
               (mDeclared.count(token.text) || token.text == "vector" || token.text == "matrix" ||
                parseScalarTypeName(token.text, scalar));
    }

private:
    std::set<std::string> mDeclared;
};

bool isIncrement(const Token& token) {
    return token.kind == Token::Kind::Punct && (token.text == "++" || token.text == "--");
}

struct Brackets {
    std::vector<long> match;      // the index of the bracket closing or opening this one, -1 otherwise
    std::vector<long> enclosing;  // the index of the innermost bracket open at a token, -1 at the top
};

Brackets matchBrackets(const std::vector<Token>& tokens) {
    Brackets brackets{std::vector<long>(tokens.size(), -1), std::vector<long>(tokens.size(), -1)};
    std::vector<long> open;
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        brackets.enclosing[i] = open.empty() ? -1 : open.back();
        if (token.is("(") || token.is("[") || token.is("{")) {
            open.push_back(static_cast<long>(i));
        } else if (token.is(")") || token.is("]") || token.is("}")) {
            const char* opening = token.is(")") ? "(" : token.is("]") ? "[" : "{";
            if (open.empty() || !tokens[open.back()].is(opening)) continue;  // unbalanced: glslang reports it
            brackets.match[i] = open.back();
            brackets.match[open.back()] = static_cast<long>(i);
            open.pop_back();
            brackets.enclosing[i] = open.empty() ? -1 : open.back();
        }
    }
    return brackets;
}

// The first token of the postfix expression that the postfix operator at `op` applies to (a name, literal,
// constructor or parenthesized expression followed by members, indices, calls and postfix operators), or -1
// where the text before `op` is no operand.
long operandStart(const std::vector<Token>& tokens, const Brackets& brackets,
                  const std::vector<bool>& postfix, long op) {
    long j = op - 1;
    while (j >= 0) {
        const Token& token = tokens[j];
        if (isIncrement(token) && postfix[j]) {
            --j;
        } else if (token.is("]")) {
            j = brackets.match[j] - 1;
            if (j < -1) return -1;
        } else if (token.is(")")) {
            const long open = brackets.match[j];
            if (open < 0) return -1;
            if (open > 0 && tokens[open - 1].is(">")) {  // a template type's constructor: vector<bool, 4>(q)
                long angle = open - 2;
                while (angle >= 0 && !tokens[angle].is("<")) --angle;
                if (angle < 1) return -1;
                j = angle - 1;
            } else if (open > 0 && isOperandWord(tokens[open - 1])) {
                j = open - 1;  // a call or a constructor
            } else {
                return open;  // a parenthesized expression
            }
        } else if (isOperandWord(token)) {
            if (j >= 2 && (tokens[j - 1].is(".") || tokens[j - 1].is("::"))) {
                j -= 2;
            } else {
                return j;
            }
        } else {
            return -1;
        }
    }
    return -1;
}

// Whether the value of the postfix expression from `start` to the operator at `op` is discarded: the
// expression is a statement of its own, or a for loop's step.
bool valueDiscarded(const std::vector<Token>& tokens, const Brackets& brackets, long start, long op) {
    if (start == 0 || static_cast<size_t>(op + 1) >= tokens.size()) return false;
    const Token& before = tokens[start - 1];
    const Token& after = tokens[op + 1];
    const long scope = brackets.enclosing[op];
    if (scope > 0 && tokens[scope].is("(")) {
        return tokens[scope - 1].is("for") && before.is(";") && brackets.match[scope] == op + 1;
    }
    if (!after.is(";")) return false;
    if (before.is(";") || before.is("{") || before.is("}") || before.is("else") || before.is("do"))
        return true;
    if (!before.is(")")) return false;
    const long header = brackets.match[start - 1];
    return header > 0 &&
           (tokens[header - 1].is("if") || tokens[header - 1].is("while") || tokens[header - 1].is("for"));
}

struct Edit {
    size_t offset;
    size_t erase;
    std::string insert;
};

std::string applyEdits(const std::string& text, std::vector<Edit> edits) {
    std::stable_sort(edits.begin(), edits.end(),
                     [](const Edit& a, const Edit& b) { return a.offset < b.offset; });
    std::string out;
    size_t at = 0;
    for (const Edit& edit : edits) {
        out.append(text, at, edit.offset - at);
        out += edit.insert;
        at = edit.offset + edit.erase;
    }
    out.append(text, at, std::string::npos);
    return out;
}

}  // namespace

PostfixRewrite rewritePostfixOperators(const std::string& text, const std::vector<Token>& tokens) {
    const Brackets brackets = matchBrackets(tokens);

    // Which `++` glslang reads as postfix: every one after an operand (whatever follows it), except after
    // the `)` of a statement's header (`if (c) ++x`) or of a cast (`(float)++x`) and after an attribute's
    // `]` (`[unroll] ++i`).
    const TypeNames typeNames(tokens);
    const auto isCast = [&](long open, long close) {
        if (close - open < 2 || !typeNames.contains(tokens[open + 1])) return false;
        for (long k = open + 2; k < close; ++k)
            if (!(tokens[k].is("<") || tokens[k].is(">") || tokens[k].is(",") || tokens[k].is("[") ||
                  tokens[k].is("]") || tokens[k].kind == Token::Kind::Number ||
                  typeNames.contains(tokens[k])))
                return false;
        return true;
    };
    std::vector<bool> postfix(tokens.size(), false);
    for (size_t i = 1; i < tokens.size(); ++i) {
        if (!isIncrement(tokens[i])) continue;
        const Token& before = tokens[i - 1];
        const long open = brackets.match[i - 1];
        if (isOperandWord(before)) {
            postfix[i] = true;
        } else if (isIncrement(before)) {
            postfix[i] = postfix[i - 1];
        } else if (before.is(")")) {
            const bool header = open > 0 && (tokens[open - 1].is("if") || tokens[open - 1].is("while") ||
                                             tokens[open - 1].is("for") || tokens[open - 1].is("switch"));
            const bool callOrConstructor =
                open > 0 && (isOperandWord(tokens[open - 1]) || tokens[open - 1].is(">"));
            postfix[i] = open < 0 || callOrConstructor || !(header || isCast(open, static_cast<long>(i) - 1));
        } else if (before.is("]")) {
            const bool attribute =
                open == 0 || (open > 0 && (tokens[open - 1].is(";") || tokens[open - 1].is("{") ||
                                           tokens[open - 1].is("}") || tokens[open - 1].is("]") ||
                                           tokens[open - 1].is(":")));
            postfix[i] = !attribute;
        }
    }

    PostfixRewrite rewrite;
    std::vector<Edit> discarded, used;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (!postfix[i]) continue;
        const long op = static_cast<long>(i);
        const long start = operandStart(tokens, brackets, postfix, op);
        if (start < 0) {  // glslang could read something else as the operand: said here, not given to it
            rewrite.errors.push_back(
                {true, tokens[i].loc.file, tokens[i].loc.line, tokens[i].ppColumn,
                 "'" + tokens[i].text + "' : no operand of this postfix operator that shadowfx can find"});
            continue;
        }
        // `x++;` -> ` ++x  ;`; `x++.y` -> ` (++x).y`, which increments what `x++` does (not `x.y`). The
        // space keeps `a+x++` from becoming `a+++x`.
        if (valueDiscarded(tokens, brackets, start, op)) {
            discarded.push_back({tokens[start].begin, 0, " " + tokens[i].text});
            discarded.push_back({tokens[i].begin, 2, "  "});
        } else {
            used.push_back({tokens[start].begin, 0, " (" + tokens[i].text});
            used.push_back({tokens[i].begin, 2, ")"});
        }
    }
    rewrite.text = applyEdits(text, discarded);
    if (!used.empty()) {
        used.insert(used.end(), discarded.begin(), discarded.end());
        rewrite.checkText = applyEdits(text, used);
    }
    return rewrite;
}

}  // namespace fx::detail
