// ConstantMatrixProducts: see ConstantMatrixProducts.h.
#include "ConstantMatrixProducts.h"

#include "ElementWiseProducts.h"
#include "TypeNames.h"

#include <map>
#include <set>
#include <tuple>

namespace fx::detail {

namespace {

using glslang::TIntermBinary;
using glslang::TType;

// The function (and the file its `#line` names) that holds the products outside functions in the copy their
// types are read from.
constexpr const char* kProductsOutsideFunctions = "fx_constant_matrix_products";

// Words that end no operand: a `-` after them is a prefix one, a parenthesis after them opens no call.
bool isStatementKeyword(const Token& token) {
    static const std::set<std::string> keywords = {"return",   "if",      "else", "while",   "for",
                                                   "do",       "switch",  "case", "default", "break",
                                                   "continue", "discard", "in",   "out",     "inout"};
    return token.kind == Token::Kind::Identifier && keywords.count(token.text) != 0;
}

bool isOperandWord(const Token& token) {
    return (token.kind == Token::Kind::Identifier && !isStatementKeyword(token)) ||
           token.kind == Token::Kind::Number;
}

bool isPrefixOperator(const Token& token) {
    return token.is("-") || token.is("+") || token.is("!") || token.is("~");
}

// The operands of each `*` found in the text: its left operand (the multiplicative expression before it,
// `a * b` for the second `*` of `a * b * c`) and its right one (the unary expression after it), as token
// ranges [first, last].
class Operands {
public:
    explicit Operands(const std::vector<Token>& tokens)
        : mTokens(tokens), mMatch(tokens.size(), -1), mStatement(tokens.size(), -1) {
        std::vector<long> open;
        // For each open bracket that is a `{` of a function's body or a block in it, the first token of its
        // current statement; -1 for other brackets (parentheses, an initializer list's braces).
        std::vector<long> statementStart;
        long functionBody = -1;  // the `{` of the function body the tokens stand in
        long declaration = 0;    // the first token of the current declaration outside functions
        for (size_t i = 0; i < tokens.size(); ++i) {
            for (size_t k = open.size(); functionBody >= 0 && k-- > 0;)
                if (statementStart[k] >= 0) {
                    mStatement[i] = statementStart[k];
                    break;
                }
            if (tokens[i].is("(") || tokens[i].is("[") || tokens[i].is("{")) {
                // A function's body follows its parameters' `)` or its semantic (`: SV_Target`); a
                // struct's or cbuffer's does too (`cbuffer c : register(b0) {`), but is no function.
                bool block = tokens[i].is("{") && functionBody < 0 && open.empty() && i > 1 &&
                             (tokens[i - 1].is(")") || tokens[i - 2].is(":")) &&
                             !tokens[declaration].is("struct") && !tokens[declaration].is("cbuffer") &&
                             !tokens[declaration].is("tbuffer");
                if (block) functionBody = static_cast<long>(i);
                block = block || (tokens[i].is("{") && functionBody >= 0 && statementStart.back() >= 0 &&
                                  !tokens[i - 1].is("=") && !tokens[i - 1].is(","));
                open.push_back(static_cast<long>(i));
                statementStart.push_back(block ? static_cast<long>(i) + 1 : -1);
            } else if (tokens[i].is(")") || tokens[i].is("]") || tokens[i].is("}")) {
                if (open.empty()) continue;  // unbalanced: glslang reported it
                mMatch[i] = open.back();
                mMatch[open.back()] = static_cast<long>(i);
                if (open.back() == functionBody) functionBody = -1;
                const bool block = statementStart.back() >= 0;
                open.pop_back();
                statementStart.pop_back();
                if (block && !statementStart.empty() && statementStart.back() >= 0)
                    statementStart.back() = static_cast<long>(i) + 1;
            } else if (tokens[i].is(";") && !statementStart.empty() && statementStart.back() >= 0) {
                statementStart.back() = static_cast<long>(i) + 1;
            }
            if (open.empty() && (tokens[i].is(";") || tokens[i].is("}")))
                declaration = static_cast<long>(i) + 1;
            // The names `struct` and `typedef` declare, which a cast `(T)` may name.
            if (tokens[i].is("struct") && i + 1 < tokens.size()) mDeclaredTypes.insert(tokens[i + 1].text);
            if (tokens[i].is("typedef")) {
                size_t end = i + 1;
                while (end < tokens.size() && !tokens[end].is(";") && !tokens[end].is("[")) ++end;
                if (end > i + 1) mDeclaredTypes.insert(tokens[end - 1].text);
            }
        }
    }

    // Where a statement can be written before the one the token at `i` stands in, in a function's body, so
    // that it sees the same names: the first token of that statement, after an `else` or a `case ...:` that
    // begins it; -1 outside functions.
    long statementBefore(long i) const {
        long start = mStatement[i];
        if (start < 0) return -1;
        while (at(start).is("else")) ++start;
        if (at(start).is("case") || at(start).is("default")) {
            while (start < i && !at(start).is(":")) ++start;
            ++start;
        }
        return start <= i ? start : -1;
    }

    // The first token of the left operand of the `*` at `star`, or -1 where it cannot be told.
    long leftFirst(long star) const {
        long first = unaryFirst(star - 1);
        while (first > 1 && (at(first - 1).is("*") || at(first - 1).is("/") || at(first - 1).is("%")))
            first = unaryFirst(first - 2);
        return first;
    }

    // Whether tokens `first`..`last` are a postfix expression (`M`, `P[0]`, `float2x2(...)`, `(a * b)`),
    // which
    // `[i]` indexes as a whole.
    bool isPostfixExpression(long first, long last) const {
        if (!isOperandWord(at(first)) && !(at(first).is("(") && !isCast(first, mMatch[first]))) return false;
        for (long k = first; k <= last; ++k) {
            if ((at(k).is("(") || at(k).is("[")) && mMatch[k] > k) {
                k = mMatch[k];
            } else if ((at(k).is("matrix") || at(k).is("vector")) && at(k + 1).is("<")) {
                while (k < last && !at(k).is(">")) ++k;
            } else if (at(k).kind == Token::Kind::Punct && !at(k).is(".")) {
                return false;
            }
        }
        return true;
    }

    // The last token of the right operand of the `*` at `star`, or -1 where it cannot be told.
    long rightLast(long star) const {
        long k = star + 1;
        for (;;) {
            while (isPrefixOperator(at(k))) ++k;
            if (!at(k).is("(")) break;
            const long close = mMatch[k];
            if (close < 0) return -1;
            if (!isCast(k, close)) {
                return postfixLast(close);
            }
            k = close + 1;
        }
        if (at(k).kind == Token::Kind::Number) return postfixLast(k);
        if (!isOperandWord(at(k))) return -1;
        long last = k;
        if ((at(k).is("matrix") || at(k).is("vector")) && at(k + 1).is("<")) {
            while (last < static_cast<long>(mTokens.size()) - 1 && !at(last).is(">")) ++last;
        }
        if (at(last + 1).is("(")) last = mMatch[last + 1];
        return last < 0 ? -1 : postfixLast(last);
    }

private:
    const Token& at(long i) const {
        static const Token kEnd;
        return i >= 0 && i < static_cast<long>(mTokens.size()) ? mTokens[i] : kEnd;
    }

    bool isTypeWord(const Token& token) const {
        TypeDesc scalar;
        return token.kind == Token::Kind::Identifier &&
               (mDeclaredTypes.count(token.text) || token.text == "vector" || token.text == "matrix" ||
                parseScalarTypeName(token.text, scalar));
    }

    // Whether the parentheses `open`..`close` hold a type: `(float2x2)`, `(matrix<float, 2, 2>)`.
    bool isCast(long open, long close) const {
        if (close - open < 2 || !isTypeWord(at(open + 1))) return false;
        for (long k = open + 2; k < close; ++k)
            if (!(at(k).is("<") || at(k).is(">") || at(k).is(",") || at(k).kind == Token::Kind::Number ||
                  isTypeWord(at(k))))
                return false;
        return true;
    }

    // The last token of the postfix expression whose primary ends at `last`: indices, members, method calls.
    long postfixLast(long last) const {
        for (;;) {
            if (at(last + 1).is("[") && mMatch[last + 1] > 0) {
                last = mMatch[last + 1];
            } else if (at(last + 1).is(".") && at(last + 2).kind == Token::Kind::Identifier) {
                last += 2;
                if (at(last + 1).is("(") && mMatch[last + 1] > 0) last = mMatch[last + 1];
            } else {
                return last;
            }
        }
    }

    // The first token of the unary expression whose last token is `last` (prefix operators and casts
    // included), or -1.
    long unaryFirst(long last) const {
        long j = last;
        long first = -1;
        while (first < 0) {
            if (j < 0) return -1;
            const Token& token = at(j);
            if (token.is("]")) {
                j = mMatch[j] - 1;
            } else if (token.is(")")) {
                const long open = mMatch[j];
                if (open < 0) return -1;
                if (at(open - 1).is(">")) {  // a template type's constructor: matrix<float, 2, 2>(...)
                    long angle = open - 2;
                    while (angle >= 0 && !at(angle).is("<")) --angle;
                    if (angle < 1) return -1;
                    first = angle - 1;
                } else if (isOperandWord(at(open - 1))) {
                    j = open - 1;  // a call or a constructor, or a method (`.f(...)`)
                    if (!at(j - 1).is(".")) first = j;
                    j -= 2;
                } else {
                    first = open;
                }
            } else if (isOperandWord(token)) {
                if (at(j - 1).is(".")) {
                    j -= 2;
                } else {
                    first = j;
                }
            } else {
                return -1;
            }
        }
        // Casts and prefix operators before it.
        for (;;) {
            const Token& before = at(first - 1);
            if (before.is(")") && mMatch[first - 1] >= 0 && isCast(mMatch[first - 1], first - 1)) {
                first = mMatch[first - 1];
            } else if (isPrefixOperator(before) && !isOperandWord(at(first - 2)) && !at(first - 2).is(")") &&
                       !at(first - 2).is("]")) {
                first -= 1;
            } else {
                return first;
            }
        }
    }

    const std::vector<Token>& mTokens;
    std::vector<long> mMatch;      // the bracket closing or opening the one at each index, -1 elsewhere
    std::vector<long> mStatement;  // the first token of the statement in a function each token stands in
    std::set<std::string> mDeclaredTypes;
};

// A `*` whose value glslang computed while it parsed.
struct FoldedStar {
    long left, star, right;  // the first token of the left operand, the `*`, the right operand's last token
    bool leftPostfix,
        rightPostfix;  // whether an operand is a postfix expression, indexed without parentheses
    // From the copy of the text whose right operands are no constants: the HLSL type of a product of two
    // matrices of one shape and its rows, or the error at a product of other shapes.
    std::string matrixName;
    int rows = 0;
    std::string shapesError;
};

class BinaryPlaces : public glslang::TIntermTraverser {
public:
    std::set<SourcePlace> places;
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        places.insert(placeOf(node->getLoc()));
        return true;
    }
};

// HLSL's name of the matrix type `type`, or "" for a type this rewrite does not spell (bool matrices,
// which `*` converts, and 16-bit ones).
std::string hlslMatrixName(const TType& type) {
    const char* base = type.getBasicType() == glslang::EbtFloat    ? "float"
                       : type.getBasicType() == glslang::EbtDouble ? "double"
                       : type.getBasicType() == glslang::EbtInt    ? "int"
                       : type.getBasicType() == glslang::EbtUint   ? "uint"
                                                                   : nullptr;
    if (!base) return "";
    // glslang's matrix columns are HLSL's rows (HlslToSpirv.h).
    return std::string(base) + std::to_string(type.getMatrixCols()) + "x" +
           std::to_string(type.getMatrixRows());
}

class ProductReader : public glslang::TIntermTraverser {
public:
    ProductReader(std::vector<FoldedStar>& stars, std::map<SourcePlace, size_t> places)
        : mStars(stars), mPlaces(std::move(places)) {}

    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        const auto found = mPlaces.find(placeOf(node->getLoc()));
        if (found == mPlaces.end() || !standsBetweenItsOperands(*node)) return true;  // a mul()
        FoldedStar& star = mStars[found->second];
        const glslang::TOperator op = node->getOp();
        const bool withVector = op == glslang::EOpMatrixTimesVector || op == glslang::EOpVectorTimesMatrix;
        if (op != glslang::EOpMatrixTimesMatrix && !withVector) return true;
        const TType& left = node->getLeft()->getType();
        const TType& right = node->getRight()->getType();
        if (withVector || left.getMatrixCols() != right.getMatrixCols() ||
            left.getMatrixRows() != right.getMatrixRows()) {
            star.shapesError = elementWiseProductOfShapesMessage(left, right);
        } else {
            star.matrixName = hlslMatrixName(node->getType());
            star.rows = node->getType().getMatrixCols();  // glslang's matrix columns are HLSL's rows
        }
        return true;
    }

private:
    std::vector<FoldedStar>& mStars;
    std::map<SourcePlace, size_t> mPlaces;
};

// The text of tokens `first`..`last` on one line.
std::string flatText(const std::string& text, const std::vector<Token>& tokens, long first, long last) {
    std::string out = text.substr(tokens[first].begin, tokens[last].end - tokens[first].begin);
    for (char& c : out)
        if (c == '\n' || c == '\r') c = ' ';
    return out;
}

class ProductWriter {
public:
    ProductWriter(const std::string& text, const std::vector<Token>& tokens,
                  const std::vector<const FoldedStar*>& products)
        : mText(text), mTokens(tokens) {
        for (const FoldedStar* product : products) mStartingAt[product->left].push_back(product);
    }

    // The text of tokens `first`..`last` and what lies between them, each product in it rewritten; `flat`:
    // with its line breaks written as spaces, for the copies of an operand.
    std::string write(long first, long last, bool flat) const {
        std::string out;
        for (long i = first; i <= last;) {
            // Of the products starting here, the outermost that ends in the range (`a * b * c` holds `a *
            // b`).
            const FoldedStar* outer = nullptr;
            const auto starting = mStartingAt.find(i);
            if (starting != mStartingAt.end())
                for (const FoldedStar* product : starting->second)
                    if (product->right <= last && (!outer || outer->right < product->right)) outer = product;
            if (outer) {
                out += writeProduct(*outer, flat);
                i = outer->right + 1;
            } else {
                out += spelling(i);
                ++i;
            }
            if (i <= last) out += between(i - 1, i, flat);
        }
        return out;
    }

private:
    // `a * b` of HLSL rows R: `T(a[0] * b[0], ..., a[R-1] * b[R-1])`, the operands in parentheses unless
    // they are postfix expressions (`-a`, `(float2x2)a`, `a * b`); every row but the last copies
    // the operands on the first line, the last keeps their text and line breaks.
    std::string writeProduct(const FoldedStar& product, bool flat) const {
        const auto row = [](const std::string& operand, bool postfix, int i) {
            // glslang reads `(matrix<float, 2, 2>(...))` as a cast that lacks its `)`: a postfix expression
            // is indexed as it stands.
            return (postfix ? operand : "(" + operand + ")") + "[" + std::to_string(i) + "]";
        };
        const int rows = product.rows;
        const std::string leftFlat = write(product.left, product.star - 1, true);
        const std::string rightFlat = write(product.star + 1, product.right, true);
        std::string out = product.matrixName + "(";
        for (int i = 0; i + 1 < rows; ++i)
            out += row(leftFlat, product.leftPostfix, i) + " * " + row(rightFlat, product.rightPostfix, i) +
                   ", ";
        return out + row(write(product.left, product.star - 1, flat), product.leftPostfix, rows - 1) +
               between(product.star - 1, product.star, flat) + "*" +
               between(product.star, product.star + 1, flat) +
               row(write(product.star + 1, product.right, flat), product.rightPostfix, rows - 1) + ")";
    }

    std::string spelling(long i) const {
        return mText.substr(mTokens[i].begin, mTokens[i].end - mTokens[i].begin);
    }

    std::string between(long a, long b, bool flat) const {
        std::string gap = mText.substr(mTokens[a].end, mTokens[b].begin - mTokens[a].end);
        if (flat)
            for (char& c : gap)
                if (c == '\n' || c == '\r') c = ' ';
        return gap;
    }

    const std::string& mText;
    const std::vector<Token>& mTokens;
    std::map<long, std::vector<const FoldedStar*>> mStartingAt;  // by their left operand's first token
};

}  // namespace

ConstantProductRewrite rewriteConstantMatrixProducts(glslang::TIntermediate& parsed, const std::string& text,
                                                     const std::vector<Token>& tokens,
                                                     const ParseUnit& parse) {
    ConstantProductRewrite rewrite;
    BinaryPlaces nodes;
    parsed.getTreeRoot()->traverse(&nodes);
    const Operands operands(tokens);
    std::vector<FoldedStar> folded;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].kind != Token::Kind::Punct || tokens[i].text != "*") continue;
        if (nodes.places.count(placeOf(tokens[i]))) continue;  // glslang kept the operation
        const long star = static_cast<long>(i);
        const long left = operands.leftFirst(star), right = operands.rightLast(star);
        // A literal number is no matrix: `2 * PI` needs no look.
        if (left < 0 || right < 0 || (left == star - 1 && tokens[left].kind == Token::Kind::Number) ||
            (right == star + 1 && tokens[right].kind == Token::Kind::Number))
            continue;
        folded.push_back({left, star, right, operands.isPostfixExpression(left, star - 1),
                          operands.isPostfixExpression(star + 1, right), "", 0, ""});
    }
    if (folded.empty()) return rewrite;

    // A copy of the text in which each of these products is written once more, as `(0, a) * (0, b);`, where
    // it keeps its node, typed: glslang folds no sequence. The text itself is kept, since a constant
    // expression may need the product's value (an array's size). In a function the copy stands before the
    // statement that holds the product, and sees its names; outside functions (a `static const`'s
    // initializer) in a function added at the end.
    std::map<size_t, std::string> inserts;                  // by the offset in the text they are written at
    std::map<std::pair<size_t, size_t>, size_t> productOf;  // (offset, offset in the insert) -> folded index
    const size_t end = text.size();
    for (size_t k = 0; k < folded.size(); ++k) {
        const FoldedStar& star = folded[k];
        const long statement = operands.statementBefore(star.star);
        const size_t at = statement >= 0 ? tokens[statement].begin : end;
        std::string& insert = inserts[at];
        if (statement < 0 && insert.empty())
            insert = "\n#line 1 \"" + std::string(kProductsOutsideFunctions) + "\"\nvoid " +
                     kProductsOutsideFunctions + "() {\n";
        insert += "(0, " + flatText(text, tokens, star.left, star.star - 1) + ") ";
        productOf[{at, insert.size()}] = k;
        insert += "* (0, " + flatText(text, tokens, star.star + 1, star.right) + ");" +
                  (statement < 0 ? "\n" : " ");
    }
    if (inserts.count(end)) inserts[end] += "}\n";
    std::string copy;
    std::map<size_t, size_t> productAtOffset;  // the offset of each copied product's `*` in the copy
    size_t from = 0;
    for (const auto& [offset, insert] : inserts) {
        copy.append(text, from, offset - from);
        for (auto it = productOf.lower_bound({offset, 0}); it != productOf.end() && it->first.first == offset;
             ++it)
            productAtOffset[copy.size() + it->first.second] = it->second;
        copy += insert;
        from = offset;
    }
    copy.append(text, from, std::string::npos);
    std::map<SourcePlace, size_t> copyPlaces;
    for (const Token& token : lexHlslUnit(copy)) {
        const auto found = productAtOffset.find(token.begin);
        if (found != productAtOffset.end()) copyPlaces[placeOf(token)] = found->second;
    }
    ProductReader reader(folded, std::move(copyPlaces));
    // A copy glslang cannot parse (a product's names declared by the statement that holds it: `float2x2 m =
    // ..., n = m * M;`) leaves the products it did not read as they are.
    if (!parse(copy, [&](glslang::TIntermediate& tree) { tree.getTreeRoot()->traverse(&reader); }))
        return rewrite;

    std::vector<const FoldedStar*> products;
    for (const FoldedStar& star : folded) {
        const Token& at = tokens[star.star];
        if (!star.shapesError.empty())
            rewrite.errors.push_back({true, at.loc.file, at.loc.line, at.ppColumn, star.shapesError});
        else if (!star.matrixName.empty())
            products.push_back(&star);
    }
    if (!rewrite.errors.empty() || products.empty()) return rewrite;
    rewrite.text =
        ProductWriter(text, tokens, products).write(0, static_cast<long>(tokens.size()) - 2, false);
    // What precedes the first token and follows the last (the End token) is kept as it is.
    rewrite.text =
        text.substr(0, tokens.front().begin) + *rewrite.text + text.substr(tokens[tokens.size() - 2].end);
    return rewrite;
}

}  // namespace fx::detail
