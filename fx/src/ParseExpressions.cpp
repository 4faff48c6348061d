// Parser: expressions (see Parser.h).
#include "Parser.h"

#include "TypeNames.h"

namespace fx::detail {

Expr Parser::parseExpr(bool inAnnotation) {
    bool saved = mNoGreater;
    mNoGreater = inAnnotation;
    Expr e = parseTernary();
    mNoGreater = saved;
    return e;
}

Expr Parser::parseTernary() {
    DepthGuard guard(*this);
    Expr condition = parseBinary(0);
    if (!check("?")) return condition;
    const Token& question = advance();
    Expr e;
    e.kind = Expr::Kind::Ternary;
    e.loc = condition.loc;
    (void)question;
    e.args.push_back(std::move(condition));
    e.args.push_back(parseTernary());
    expect(":");
    e.args.push_back(parseTernary());
    return e;
}

int Parser::binaryPrecedence(const Token& token) const {
    if (token.kind != Token::Kind::Punct) return -1;
    const std::string& op = token.text;
    if (op == "||") return 1;
    if (op == "&&") return 2;
    if (op == "|") return 3;
    if (op == "^") return 4;
    if (op == "&") return 5;
    if (op == "==" || op == "!=") return 6;
    if (op == "<" || op == "<=" || op == ">=") return 7;
    if (op == ">") return mNoGreater ? -1 : 7;
    if (op == "<<" || op == ">>") return 8;
    if (op == "+" || op == "-") return 9;
    if (op == "*" || op == "/" || op == "%") return 10;
    return -1;
}

Expr Parser::parseBinary(int minPrecedence) {
    Expr left = parseUnary();
    // `1+1+1+...` loops here instead of recursing, but builds a left-deep tree as deep as the chain is
    // long, and everything that walks an Expr (its destructor included) recurses: bound the chain with
    // the nesting depth, so that a long line cannot overflow the stack later.
    int chain = 0;
    for (;;) {
        int precedence = binaryPrecedence(peek());
        if (precedence < 0 || precedence < minPrecedence) break;
        if (++chain + mDepth > kMaxDepth)
            fail(DiagId::ExpressionTooComplex, peek().loc, {std::to_string(kMaxDepth)});
        const Token& op = advance();
        DepthGuard guard(*this);
        Expr right = parseBinary(precedence + 1);
        Expr e;
        e.kind = Expr::Kind::Binary;
        e.text = op.text;
        e.loc = left.loc;
        e.args.push_back(std::move(left));
        e.args.push_back(std::move(right));
        left = std::move(e);
    }
    return left;
}

Expr Parser::parseUnary() {
    DepthGuard guard(*this);
    const Token& token = peek();
    if (token.is("-") || token.is("+") || token.is("!") || token.is("~") || token.is("++") ||
        token.is("--")) {
        advance();
        Expr operand = parseUnary();
        if (token.text == "-" && operand.kind == Expr::Kind::Number) {  // fold literals: -1.0
            operand.number = -operand.number;
            operand.loc = token.loc;
            return operand;
        }
        Expr e;
        e.kind = Expr::Kind::Unary;
        e.text = token.text;
        e.loc = token.loc;
        e.args.push_back(std::move(operand));
        return e;
    }
    // Cast: (float3) x, (MyStruct) x
    if (token.is("(") && isTypeName(peek(1)) && !isParameterName(peek(1).text)) {
        size_t save = mPos;
        advance();
        TypeDesc type = parseType();
        if (check(")")) {
            advance();
            Expr e;
            e.kind = Expr::Kind::Cast;
            e.castType = type;
            e.loc = token.loc;
            e.args.push_back(parseUnary());
            return e;
        }
        mPos = save;
    }
    return parsePostfix(parsePrimary());
}

Expr Parser::parsePostfix(Expr e) {
    for (;;) {
        if (check(".")) {
            advance();
            const Token& member = expectIdentifier("a member name");
            Expr m;
            m.kind = Expr::Kind::Member;
            m.text = member.text;
            m.loc = e.loc;
            m.args.push_back(std::move(e));
            e = std::move(m);
        } else if (check("[")) {
            advance();
            bool saved = mNoGreater;
            mNoGreater = false;
            Expr index = parseTernary();
            mNoGreater = saved;
            expect("]");
            Expr m;
            m.kind = Expr::Kind::Index;
            m.loc = e.loc;
            m.args.push_back(std::move(e));
            m.args.push_back(std::move(index));
            e = std::move(m);
        } else if (check("++") || check("--")) {
            advance();
        } else {
            return e;
        }
    }
}

std::vector<Expr> Parser::parseArguments() {
    expect("(");
    std::vector<Expr> args;
    bool saved = mNoGreater;
    mNoGreater = false;
    while (!check(")")) {
        if (!args.empty()) expect(",");
        args.push_back(parseTernary());
    }
    advance();
    mNoGreater = saved;
    return args;
}

Expr Parser::parsePrimary() {
    const Token& token = peek();
    Expr e;
    e.loc = token.loc;
    switch (token.kind) {
        case Token::Kind::Number:
            advance();
            e.kind = Expr::Kind::Number;
            e.number = token.number;
            e.isInteger = token.isInteger;
            return e;
        case Token::Kind::String:
            e.kind = Expr::Kind::String;
            while (peek().kind == Token::Kind::String) {
                const Token& piece = advance();
                SourceLoc pieceLoc = piece.loc;
                if (!piece.fromMacro) pieceLoc.column += 1;  // after the quote
                e.stringPieces.push_back({e.text.size(), pieceLoc, piece.fromMacro});
                e.text += piece.text;
            }
            return e;
        case Token::Kind::End:
            unexpected("an expression");
        default:
            break;
    }
    if (token.is("(")) {
        advance();
        bool saved = mNoGreater;
        mNoGreater = false;
        Expr inner = parseTernary();
        mNoGreater = saved;
        expect(")");
        return inner;
    }
    if (token.is("{")) {
        const Token& open = advance();
        e.kind = Expr::Kind::InitList;
        bool saved = mNoGreater;
        mNoGreater = false;
        while (!check("}")) {
            if (atEnd()) unclosed("{", open);
            e.args.push_back(parseTernary());
            if (!accept(",")) break;
        }
        mNoGreater = saved;
        if (!check("}")) {
            if (atEnd()) unclosed("{", open);
            unexpected("',' or '}'");
        }
        advance();
        return e;
    }
    if (token.is("<")) {  // <TextureName>, and a fixed-function state's <array[i]>
        advance();
        const Token& name = expectIdentifier("a texture name");
        e.kind = Expr::Kind::TextureRef;
        e.text = name.text;
        if (accept("[")) {
            Expr array = e;
            array.kind = Expr::Kind::Identifier;
            e.kind = Expr::Kind::Index;
            e.text.clear();
            e.args = {std::move(array), parseExpr()};
            expect("]");
        }
        expectCloseAngle();
        return e;
    }
    if (token.kind != Token::Kind::Identifier) unexpected("an expression");
    if (token.text == "compile") {
        advance();
        const Token& profile = expectIdentifier("a shader profile");
        const Token& function = expectIdentifier("a function name");
        e.kind = Expr::Kind::Compile;
        e.profile = profile.text;
        e.text = function.text;
        if (check("(")) e.args = parseArguments();
        return e;
    }
    if (token.text == "sampler_state")
        fail(DiagId::UnexpectedToken, token.loc, {"an expression", token.text});
    advance();
    if (equalsIgnoreCase(token.text, "true") || equalsIgnoreCase(token.text, "false")) {
        e.kind = Expr::Kind::Bool;
        e.number = equalsIgnoreCase(token.text, "true") ? 1 : 0;
        e.isInteger = true;
        return e;
    }
    if (check("(")) {  // call or constructor
        e.kind = Expr::Kind::Call;
        // A bare `vector` or `matrix` is HLSL's float4 or float4x4 (`vector(1, 1, 1, 1)` as a blend factor).
        e.text = token.text == "vector" ? "float4" : token.text == "matrix" ? "float4x4" : token.text;
        e.args = parseArguments();
        return e;
    }
    if ((token.text == "vector" || token.text == "matrix") && check("<")) {
        // vector<float,3>(...) constructor
        mPos -= 1;
        TypeDesc type = parseType();
        e.kind = Expr::Kind::Call;
        e.text = type.hlslName();
        e.args = parseArguments();
        return e;
    }
    e.kind = Expr::Kind::Identifier;
    e.text = token.text;
    return e;
}

}  // namespace fx::detail
