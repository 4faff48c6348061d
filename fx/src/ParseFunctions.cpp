// Parser: functions, and the loop-free bodies host expressions may call (see Parser.h).
#include "Parser.h"
#include "TypeNames.h"

#include <algorithm>
#include <functional>

namespace fx::detail {

void Parser::parseFunction(size_t first, const TypeDesc& returnType, const Token& name) {
    FunctionDecl decl;
    decl.name = name.text;
    decl.loc = name.loc;
    decl.returnType = returnType;
    decl.maxVertexCount = mMaxVertexCount;
    decl.attributes = mAttributes;
    expect("(");
    if (check("void") && peek(1).is(")")) advance();
    while (!check(")")) {
        if (!decl.params.empty()) expect(",");
        FunctionParam param;
        bool modifier = true;
        while (modifier) {
            modifier = true;
            const Token& t = peek();
            if (t.is("in"))
                param.direction = FunctionParam::Direction::In;
            else if (t.is("out"))
                param.direction = FunctionParam::Direction::Out;
            else if (t.is("inout"))
                param.direction = FunctionParam::Direction::InOut;
            else if (t.is("uniform"))
                param.isUniform = true;
            else if (t.is("linear") || t.is("centroid") || t.is("nointerpolation") || t.is("noperspective") ||
                     t.is("sample"))
                param.interpolation = t.text;
            else if (t.is("point") || t.is("line") || t.is("triangle") || t.is("lineadj") ||
                     t.is("triangleadj"))
                param.primitive = t.text;
            else if (t.is("const") || t.is("precise") || t.is("row_major") || t.is("column_major")) {
            } else
                modifier = false;
            if (modifier) advance();
        }
        if (peek().is("InputPatch") || peek().is("OutputPatch")) {
            // A hull or domain shader's control points: the parameter's type is their element.
            param.patch = advance().text;
            expect("<");
            param.type = parseType();
            expect(",");
            Expr size = parseExpr(true);  // '>' closes the template
            double number = 0;
            if (!foldConstant(mEffect, size, number) || number < 1 || number > 32 ||
                number != static_cast<double>(static_cast<int>(number)))
                fail(DiagId::PatchSizeInvalid, size.loc, {size.str()});
            param.patchSize = static_cast<int>(number);
            expectCloseAngle();
        } else if (peek().is("PointStream") || peek().is("LineStream") || peek().is("TriangleStream")) {
            // A geometry shader's output stream: the parameter's type is its element.
            param.stream = advance().text;
            expect("<");
            param.type = parseType();
            expectCloseAngle();
        } else {
            param.type = parseType();
        }
        const Token& paramName = expectIdentifier("a parameter name");
        param.name = paramName.text;
        param.loc = paramName.loc;
        parseArrayDims(param.type);
        param.semantic = parseSemantics();
        if (accept("=")) param.defaultValue = parseExpr();
        decl.params.push_back(std::move(param));
    }
    advance();  // ')'
    decl.returnSemantic = parseSemantics();
    size_t last;
    if (check(";")) {
        decl.hasBody = false;
        last = mPos;
        advance();
    } else {
        if (!check("{")) unexpected("'{' or ';'");
        const Token& open = advance();
        const size_t bodyBegin = mPos;
        int depth = 1;
        while (depth > 0) {
            if (atEnd()) unclosed("{", open);
            if (check("{")) ++depth;
            if (check("}")) --depth;
            advance();
        }
        last = mPos - 1;
        rejectLocalAnnotations(bodyBegin, last);
        decl.straightBody = parseStraightBody(bodyBegin, last, decl.returnType);
        mFunctionRanges.push_back({mEffect.functions.size(), first, last});
    }
    decl.hlslText = sliceText(first, last);
    decl.hlslLoc = sliceLoc(first);
    mEffect.functions.push_back(std::move(decl));
    mEffect.order.push_back({DeclRef::Kind::Function, mEffect.functions.size() - 1});
}

void Parser::rejectLocalAnnotations(size_t begin, size_t end) {
    const auto isTypeName = [this](const Token& token) {
        TypeDesc type;
        return token.kind == Token::Kind::Identifier &&
               (token.text == "vector" || token.text == "matrix" || mTypeNames.count(token.text) ||
                parseScalarTypeName(token.text, type) || parseObjectTypeName(token.text, type));
    };
    // A declaration starts a statement: `T name <` there opens annotations, anywhere else it compares.
    bool statementStart = true;
    for (size_t i = begin; i < end; ++i) {
        const Token& token = mTokens[i];
        if (statementStart && i + 2 < end && isTypeName(token) &&
            mTokens[i + 1].kind == Token::Kind::Identifier && mTokens[i + 2].is("<"))
            error(DiagId::LocalAnnotation, mTokens[i + 2].loc, {mTokens[i + 1].text});
        const bool modifier = token.is("const") || token.is("static") || token.is("uniform") ||
                              token.is("row_major") || token.is("column_major") || token.is("precise");
        statementStart = token.is(";") || token.is("{") || token.is("}") || (statementStart && modifier);
    }
}

std::vector<FunctionDecl::Statement> Parser::parseStraightBody(size_t begin, size_t end,
                                                               const TypeDesc& returnType) {
    using Statement = FunctionDecl::Statement;
    const size_t resume = mPos;
    std::vector<Statement> body;
    mSpeculative = true;
    mStraightLoops = 0;
    try {
        mPos = begin;
        while (mPos < end) parseStraightStatement(body);
        // A void function returns where its body ends.
        if (returnType.base == BaseType::Void && returnType.arrayDims.empty() &&
            (body.empty() || body.back().kind != Statement::Kind::Return))
            body.emplace_back();
        lowerReturnsInLoops(body, returnType);
        if (mPos != end || !endsInReturns(body)) body.clear();
    } catch (const SyntaxError&) {
        body.clear();
    }
    mSpeculative = false;
    mPos = resume;
    return body;
}

bool Parser::isAssignment(const Token& t) {
    return t.is("=") || t.is("+=") || t.is("-=") || t.is("*=") || t.is("/=");
}

void Parser::parseStraightStatement(std::vector<FunctionDecl::Statement>& out) {
    using Statement = FunctionDecl::Statement;
    if (accept(";")) return;
    if (accept("{")) {
        while (!accept("}")) {
            if (atEnd()) throw SyntaxError{};
            parseStraightStatement(out);
        }
        return;
    }
    // Loop attributes ([unroll], [loop], [unroll(8)], [fastopt]) change how fxc compiled a loop, not
    // what it computes.
    if (check("[") && peek(1).kind == Token::Kind::Identifier && (peek(2).is("]") || peek(2).is("("))) {
        advance();
        advance();
        if (check("(")) skipBalanced("(", ")");
        expect("]");
    }
    if (accept("for") || (check("while") && !peek(1).is(";"))) {
        const bool isFor = mTokens[mPos - 1].is("for");
        if (!isFor) advance();
        parseStraightLoop(isFor, out);
        return;
    }
    // sincos(x, s, c), the one intrinsic that writes its arguments: s = sin(x) and c = cos(x), where x
    // reads neither (D3DX's preshaders had sincos as an instruction).
    if (check("sincos") && peek(1).is("(")) {
        const Token& at = advance();
        advance();
        const Expr angle = parseExpr();
        Statement sine, cosine;
        sine.kind = cosine.kind = Statement::Kind::Assign;
        sine.op = cosine.op = "=";
        sine.hasValue = cosine.hasValue = true;
        expect(",");
        sine.name = expectIdentifier("a name").text;
        expect(",");
        cosine.name = expectIdentifier("a name").text;
        expect(")");
        expect(";");
        std::function<bool(const Expr&)> reads = [&](const Expr& e) {
            if (e.kind == Expr::Kind::Identifier && (e.text == sine.name || e.text == cosine.name))
                return true;
            return std::any_of(e.args.begin(), e.args.end(), reads);
        };
        if (reads(angle)) throw SyntaxError{};
        for (Statement* written : {&sine, &cosine}) {
            written->target.kind = Expr::Kind::Identifier;
            written->target.text = written->name;
            written->target.loc = at.loc;
            written->value.kind = Expr::Kind::Call;
            written->value.text = written == &sine ? "sin" : "cos";
            written->value.loc = at.loc;
            written->value.args = {angle};
            out.push_back(std::move(*written));
        }
        return;
    }
    Statement statement;
    if (accept("if")) {
        statement.kind = Statement::Kind::If;
        expect("(");
        statement.value = parseExpr();
        expect(")");
        parseStraightStatement(statement.then);
        if (accept("else")) parseStraightStatement(statement.otherwise);
        out.push_back(std::move(statement));
        return;
    }
    if (accept("return")) {
        statement.kind = Statement::Kind::Return;
        if (!check(";")) {
            statement.value = parseExpr();
            statement.hasValue = true;
        }
    } else if (check("break") || check("continue")) {
        if (mStraightLoops == 0) throw SyntaxError{};  // a `switch`'s break: not straight code
        statement.kind = advance().is("break") ? Statement::Kind::Break : Statement::Kind::Continue;
    } else if (parseStraightAssignment(statement)) {
    } else if (peek().kind == Token::Kind::Identifier && peek(1).is("(")) {
        // A call for what it writes to its `out` arguments.
        statement.kind = Statement::Kind::Evaluate;
        statement.value = parseExpr();
        statement.hasValue = true;
    } else {
        accept("const");
        accept("static");
        const TypeDesc type = parseType();
        for (;;) {
            Statement declaration;
            declaration.kind = Statement::Kind::Declare;
            declaration.type = type;
            declaration.name = expectIdentifier("a name").text;
            parseArrayDims(declaration.type);
            if (accept("=")) {
                declaration.value = parseExpr();
                declaration.hasValue = true;
            }
            out.push_back(std::move(declaration));
            if (!accept(",")) break;
        }
        expect(";");
        return;
    }
    expect(";");
    out.push_back(std::move(statement));
}

bool Parser::parseStraightAssignment(FunctionDecl::Statement& statement) {
    using Statement = FunctionDecl::Statement;
    auto one = [&](const Token& at) {
        Expr e;
        e.kind = Expr::Kind::Number;
        e.number = 1;
        e.isInteger = true;
        e.loc = at.loc;
        return e;
    };
    // ++x, --x
    if ((check("++") || check("--")) && peek(1).kind == Token::Kind::Identifier) {
        const Token& op = advance();
        statement.kind = Statement::Kind::Assign;
        statement.target = parseAssignmentTarget(statement.name);
        statement.op = op.is("++") ? "+=" : "-=";
        statement.value = one(op);
        statement.hasValue = true;
        return true;
    }
    if (peek().kind != Token::Kind::Identifier) return false;
    const Token& after = mTokens[std::min(targetEnd(mPos), mTokens.size() - 1)];
    if (!isAssignment(after) && !after.is("++") && !after.is("--")) return false;
    statement.kind = Statement::Kind::Assign;
    statement.target = parseAssignmentTarget(statement.name);
    const Token& op = advance();
    statement.hasValue = true;
    if (op.is("++") || op.is("--")) {  // x++, x--
        statement.op = op.is("++") ? "+=" : "-=";
        statement.value = one(op);
        return true;
    }
    statement.op = op.text;
    statement.value = parseExpr();
    return true;
}

size_t Parser::targetEnd(size_t at) const {
    size_t i = at + 1;
    while (i < mTokens.size()) {
        if (mTokens[i].is(".") && i + 1 < mTokens.size() && mTokens[i + 1].kind == Token::Kind::Identifier) {
            i += 2;
        } else if (mTokens[i].is("[")) {
            int depth = 0;
            for (; i < mTokens.size(); ++i) {
                if (mTokens[i].is("[")) ++depth;
                if (mTokens[i].is("]") && --depth == 0) break;
            }
            ++i;
        } else {
            break;
        }
    }
    return i;
}

Expr Parser::parseAssignmentTarget(std::string& local) {
    const Token& name = expectIdentifier("a name");
    local = name.text;
    Expr target;
    target.kind = Expr::Kind::Identifier;
    target.text = name.text;
    target.loc = name.loc;
    for (;;) {
        Expr part;
        part.loc = peek().loc;
        if (accept(".")) {
            part.kind = Expr::Kind::Member;
            part.text = expectIdentifier("a member").text;
            part.args.push_back(std::move(target));
        } else if (accept("[")) {
            part.kind = Expr::Kind::Index;
            part.args.push_back(std::move(target));
            part.args.push_back(parseExpr());
            expect("]");
        } else {
            return target;
        }
        target = std::move(part);
    }
}

void Parser::parseStraightLoop(bool isFor, std::vector<FunctionDecl::Statement>& out) {
    using Statement = FunctionDecl::Statement;
    Statement loop;
    loop.kind = Statement::Kind::Loop;
    expect("(");
    if (isFor) {
        if (!accept(";")) parseStraightStatement(out);  // the first part, up to its ';'
        if (check(";")) throw SyntaxError{};            // no condition: no bound to unroll by
        loop.value = parseExpr();
        expect(";");
        while (!check(")")) {
            Statement step;
            if (!parseStraightAssignment(step)) throw SyntaxError{};
            loop.otherwise.push_back(std::move(step));
            if (!accept(",")) break;
        }
    } else {
        loop.value = parseExpr();
    }
    expect(")");
    ++mStraightLoops;
    parseStraightStatement(loop.then);
    --mStraightLoops;
    out.push_back(std::move(loop));
}

bool Parser::containsReturn(const std::vector<FunctionDecl::Statement>& statements) {
    for (const FunctionDecl::Statement& s : statements)
        if (s.kind == FunctionDecl::Statement::Kind::Return || containsReturn(s.then) ||
            containsReturn(s.otherwise))
            return true;
    return false;
}

// A `return` inside a loop, as fxc's unrolled code had it: the value is kept in `$result`, `$returned`
// set and the loop left; after each loop that held one, `$returned` leaves the enclosing loop too, or,
// outside every loop, returns the value kept (the rest of the body then reads as that branch's `else`,
// endsInReturns). The names are no HLSL identifiers, so they hide none of the function's.
void Parser::lowerReturnsInLoops(std::vector<FunctionDecl::Statement>& body, const TypeDesc& returnType) {
    using Statement = FunctionDecl::Statement;
    const bool returnsValue = returnType.base != BaseType::Void || !returnType.arrayDims.empty();
    const auto name = [](const char* text) {
        Expr e;
        e.kind = Expr::Kind::Identifier;
        e.text = text;
        return e;
    };
    const auto assign = [&](const char* local, Expr value) {
        Statement s;
        s.kind = Statement::Kind::Assign;
        s.name = local;
        s.target = name(local);
        s.op = "=";
        s.value = std::move(value);
        s.hasValue = true;
        return s;
    };
    std::function<bool(std::vector<Statement>&, bool)> lower = [&](std::vector<Statement>& list,
                                                                   bool inLoop) {
        bool returns = false;
        for (size_t i = 0; i < list.size(); ++i) {
            Statement& s = list[i];
            if (s.kind == Statement::Kind::Return && inLoop) {
                std::vector<Statement> leaving;
                if (s.hasValue) leaving.push_back(assign("$result", std::move(s.value)));
                Expr yes;
                yes.kind = Expr::Kind::Bool;
                yes.number = 1;
                leaving.push_back(assign("$returned", std::move(yes)));
                leaving.emplace_back().kind = Statement::Kind::Break;
                list.erase(list.begin() + static_cast<long>(i));
                list.insert(list.begin() + static_cast<long>(i), leaving.begin(), leaving.end());
                i += leaving.size() - 1;
                returns = true;
            } else if (s.kind == Statement::Kind::If) {
                const bool inThen = lower(s.then, inLoop);
                const bool inOtherwise = lower(s.otherwise, inLoop);
                returns = returns || inThen || inOtherwise;
            } else if (s.kind == Statement::Kind::Loop && lower(s.then, true)) {
                Statement after;
                after.kind = Statement::Kind::If;
                after.value = name("$returned");
                Statement& leave = after.then.emplace_back();
                leave.kind = inLoop ? Statement::Kind::Break : Statement::Kind::Return;
                if (!inLoop && returnsValue) {
                    leave.value = name("$result");
                    leave.hasValue = true;
                }
                list.insert(list.begin() + static_cast<long>(i) + 1, std::move(after));
                ++i;
                returns = true;
            }
        }
        return returns;
    };
    std::vector<Statement> lowered = body;
    if (!lower(lowered, false)) return;
    Statement returned;
    returned.kind = Statement::Kind::Declare;
    returned.name = "$returned";
    returned.type.base = BaseType::Bool;
    returned.value.kind = Expr::Kind::Bool;
    returned.hasValue = true;
    std::vector<Statement> declarations{std::move(returned)};
    if (returnsValue) {
        Statement result;
        result.kind = Statement::Kind::Declare;
        result.name = "$result";
        result.type = returnType;
        declarations.push_back(std::move(result));
    }
    body = std::move(declarations);
    body.insert(body.end(), std::make_move_iterator(lowered.begin()), std::make_move_iterator(lowered.end()));
}

// An early return (`if (x < 0) return 0; ... return sqrt(x);`) reads as if the rest of the body were the
// branch's `else`: after this, every path through `statements` ends in a return exactly where it ends,
// which is what the inliner turns into `condition ? then : otherwise`. False where some path does not end
// in one (a return in the middle of a list, or a path that runs off the end).
bool Parser::endsInReturns(std::vector<FunctionDecl::Statement>& statements) {
    using Statement = FunctionDecl::Statement;
    for (size_t i = 0; i < statements.size(); ++i) {
        Statement& s = statements[i];
        if (s.kind == Statement::Kind::Return) return i + 1 == statements.size();
        if (s.kind != Statement::Kind::If || !(containsReturn(s.then) || containsReturn(s.otherwise)))
            continue;
        // The rest of the list runs after whichever branch does not return: move it there.
        std::vector<Statement> rest(std::make_move_iterator(statements.begin() + static_cast<long>(i) + 1),
                                    std::make_move_iterator(statements.end()));
        statements.resize(i + 1);
        for (std::vector<Statement>* branch : {&s.then, &s.otherwise})
            if (branch->empty() || branch->back().kind != Statement::Kind::Return) {
                std::vector<Statement> copy = rest;
                branch->insert(branch->end(), std::make_move_iterator(copy.begin()),
                               std::make_move_iterator(copy.end()));
            }
        return endsInReturns(s.then) && endsInReturns(s.otherwise);
    }
    return false;
}

}  // namespace fx::detail
