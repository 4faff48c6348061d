// Parser: top-level declarations and annotations (see Parser.h).
#include "Parser.h"

#include "ConstantFolding.h"
#include "TypeNames.h"

#include <algorithm>

namespace fx::detail {

namespace {

// The first identifier in `value` that names one of `earlier`: fxc evaluates an annotation alone, so a
// value that reads another annotation of the block has nothing to read.
const Expr* namedAnnotation(const Expr& value, const std::vector<Annotation>& earlier) {
    if (value.kind == Expr::Kind::Identifier)
        for (const Annotation& annotation : earlier)
            if (annotation.name == value.text) return &value;
    for (const Expr& argument : value.args)
        if (const Expr* found = namedAnnotation(argument, earlier)) return found;
    return nullptr;
}

bool isObjectType(const TypeDesc& type) {
    return type.isTexture() || type.isBuffer() || type.isImage() || type.isSampler() ||
           type.isStateObject() || type.isShader();
}

}  // namespace

void Parser::parseTopLevel() {
    const Token& token = peek();
    if (token.is(";")) {
        advance();
        return;
    }
    if (token.kind != Token::Kind::Identifier && !token.is("[")) unexpected("a declaration");
    if (isTechniqueKeyword(token)) {
        parseTechnique("");
        return;
    }
    if (token.text == "fxgroup") {
        parseGroup();
        return;
    }
    if (token.text == "interface" || token.text == "class")
        fail(DiagId::DynamicShaderLinkage, token.loc, {token.text});
    if (token.text == "struct") {
        parseStruct();
        return;
    }
    if (token.text == "pass")  // was "unknown type 'pass'"
        fail(DiagId::PassOutsideTechnique, token.loc, {});
    if (token.text == "typedef") {
        parseTypedef();
        return;
    }
    if (token.text == "cbuffer" || token.text == "tbuffer") {
        parseConstantBuffer();
        return;
    }
    parseDeclaration();
}

void Parser::parseTypedef() {
    size_t first = mPos;
    advance();
    accept("const");
    parseType();
    const Token& name = expectIdentifier("a type name");
    TypeDesc dummy;
    parseArrayDims(dummy);
    size_t last = mPos;
    expect(";");
    mTypeNames.insert(name.text);
    addVerbatim(first, last);
}

void Parser::parseConstantBuffer() {
    const Token& keyword = advance();
    expectIdentifier("a name");
    parseSemantics();
    if (check("<")) parseAnnotations();
    if (!check("{")) unexpected("'{'");
    const Token& open = advance();
    while (!check("}")) {
        if (atEnd() || isTechniqueKeyword(peek()))
            unclosed(keyword.text == "cbuffer" ? "cbuffer" : "tbuffer", open);
        if (accept(";")) continue;
        parseDeclaration(/*inBuffer*/ true);
    }
    advance();
    accept(";");
}

void Parser::addVerbatim(size_t first, size_t last) {
    VerbatimDecl decl;
    decl.hlslText = sliceText(first, last);
    decl.hlslLoc = sliceLoc(first);
    mEffect.verbatim.push_back(std::move(decl));
    mEffect.order.push_back({DeclRef::Kind::Verbatim, mEffect.verbatim.size() - 1});
}

void Parser::parseStruct() {
    size_t first = mPos;
    const Token& keyword = advance();
    const Token& name = expectIdentifier("a struct name");
    if (mTypeNames.count(name.text) && mEffect.findStruct(name.text))
        error(DiagId::Redefinition, name.loc, {name.text});
    StructDecl decl;
    decl.name = name.text;
    decl.loc = name.loc;
    mTypeNames.insert(name.text);  // members may not refer to it, but functions after it do
    if (!check("{")) unexpected("'{'");
    const Token& open = advance();
    while (!check("}")) {
        if (atEnd() || check("struct") || isTechniqueKeyword(peek())) unclosed("struct", keyword);
        StructMember member;
        static const char* kInterpolation[] = {"linear", "centroid", "nointerpolation", "noperspective",
                                               "sample"};
        bool modifier = true;
        while (modifier) {
            modifier = false;
            for (const char* m : kInterpolation)
                if (check(m)) {
                    member.interpolation = advance().text;
                    modifier = true;
                }
            if (check("row_major") || check("column_major") || check("const") || check("precise")) {
                member.type.rowMajor = advance().text == "row_major" || member.type.rowMajor;
                modifier = true;
            }
        }
        bool rowMajor = member.type.rowMajor;
        const Token& typeToken = peek();
        TypeDesc type = parseType();
        type.rowMajor = rowMajor;
        const bool isObject = isObjectType(type);
        for (;;) {
            StructMember m = member;
            m.type = type;
            const Token& memberName = expectIdentifier("a member name");
            if (isObject) error(DiagId::ObjectInStruct, memberName.loc, {memberName.text, typeToken.text});
            m.name = memberName.text;
            m.loc = memberName.loc;
            parseArrayDims(m.type);
            m.semantic = parseSemantics();
            decl.members.push_back(std::move(m));
            if (!accept(",")) break;
        }
        expect(";");
    }
    (void)open;
    size_t last = mPos;
    advance();  // '}'
    if (check(";"))
        last = mPos, advance();
    else
        unexpected("';' after struct");
    decl.hlslText = sliceText(first, last);
    decl.hlslLoc = sliceLoc(first);
    mEffect.structs.push_back(std::move(decl));
    mEffect.order.push_back({DeclRef::Kind::Struct, mEffect.structs.size() - 1});
}

void Parser::parseDeclaration(bool inBuffer) {
    size_t first = mPos;
    mMaxVertexCount = 0;
    mAttributes.clear();
    while (check("[")) {  // [numthreads(...)], [maxvertexcount(...)], [domain("tri")] before a function
        if (peek(1).kind == Token::Kind::Identifier) {
            // Every attribute is kept as written; the pass lowering reads those of hull and domain
            // shaders.
            FunctionAttribute attribute;
            attribute.name = peek(1).text;
            attribute.loc = peek(1).loc;
            size_t open = mPos;
            skipBalanced("[", "]");
            attribute.text = sliceText(open, mPos - 1);
            if (mTokens[open + 2].is("(") && mPos - open > 5) {
                const Token& argument = mTokens[open + 3];
                attribute.argument =
                    argument.kind == Token::Kind::String ? argument.text : sliceText(open + 3, mPos - 3);
            }
            mAttributes.push_back(std::move(attribute));
            mPos = open;
        }
        if (peek(1).is("maxvertexcount") && peek(2).is("(")) {
            const Token& attribute = peek(1);
            mPos += 3;
            Expr count = parseExpr();
            double number = 0;
            if (!foldConstant(mEffect, count, number) || number < 1 || number > 1024 ||
                number != static_cast<double>(static_cast<int>(number)))
                fail(DiagId::MaxVertexCountInvalid, attribute.loc, {count.str()});
            mMaxVertexCount = static_cast<int>(number);
            expect(")");
            expect("]");
            continue;
        }
        skipBalanced("[", "]");
    }
    Storage storage;
    for (;;) {
        const Token& token = peek();
        // A compute shader's `groupshared` array is no parameter either: declared as written in the unit,
        // like a static (glslang makes it GLSL's `shared`).
        if (token.is("static") || token.is("groupshared"))
            storage.isStatic = true;
        else if (token.is("const"))
            storage.isConst = true;
        else if (token.is("uniform"))
            storage.isUniform = true;
        else if (token.is("shared"))
            storage.isShared = true;
        else if (token.is("extern"))
            storage.isExtern = true;
        else if (token.is("row_major"))
            storage.rowMajor = true;
        else if (token.is("column_major"))
            storage.rowMajor = false;
        else if (token.is("inline") || token.is("volatile") || token.is("precise")) {
        } else
            break;
        advance();
    }
    if (!inBuffer && (check("cbuffer") || check("tbuffer"))) {  // FX10's `shared cbuffer Name { ... }`
        parseConstantBuffer();
        return;
    }
    if (peek().kind == Token::Kind::Identifier && !isTypeName(peek()) &&
        peek(1).kind == Token::Kind::Identifier)
        fail(DiagId::UnknownType, peek().loc, {peek().text});
    TypeDesc type = parseType();
    type.rowMajor = storage.rowMajor;
    const Token& name = expectIdentifier("a name");
    if (check("(")) {
        if (inBuffer) unexpected("a member declaration");
        parseFunction(first, type, name);
        return;
    }
    bool firstDeclarator = true;
    bool endsInBlock = false;
    std::vector<size_t> declared;
    const Token* declName = &name;
    for (;;) {
        Parameter parameter;
        parameter.name = declName->text;
        parameter.loc = declName->loc;
        parameter.type = type;
        parameter.isStatic = storage.isStatic;
        parameter.isConst = storage.isConst;
        parameter.isUniform = storage.isUniform;
        parameter.isShared = storage.isShared;
        parameter.isExtern = storage.isExtern;
        parseArrayDims(parameter.type);
        parameter.semantic = parseSemantics(&parameter.samplerRegister);
        if (check("<")) parameter.annotations = parseAnnotations();
        endsInBlock = check("{");
        if (parameter.type.isSampler() && check("{")) {
            parameter.samplerState = parseSamplerStateBlock(parameter);  // D3D10: SamplerState s { ... };
        } else if (parameter.type.isStateObject()) {
            const StateObjectKind kind = StateAssignments::objectKind(parameter.type.base);
            if (parameter.type.arrayDims.size() > 1) fail(DiagId::StateObjectArray, parameter.loc, {});
            if (!parameter.type.arrayDims.empty()) {
                // FX11's `RasterizerState rs[2] { { ... }, { ... } };`, also written with `=`.
                accept("=");
                if (check("{")) parameter.objectStateElements = parseObjectStateArray(kind, parameter);
                parameter.objectStateElements.resize(static_cast<size_t>(parameter.type.arrayDims[0]));
            } else if (check("{")) {
                parameter.objectState = parseObjectStateBlock(kind);
            }
        } else if (accept("=")) {
            if (check("sampler_state")) {
                advance();
                parameter.samplerState = parseSamplerStateBlock(parameter);
            } else {
                parameter.initializer = parseExpr();
                mStates.normalizeCompileShader(*parameter.initializer);
                checkStreamOutput(*parameter.initializer);
            }
        }
        if (mEffect.findParameter(parameter.name))
            error(DiagId::Redefinition, parameter.loc, {parameter.name});
        mEffect.parameters.push_back(std::move(parameter));
        declared.push_back(mEffect.parameters.size() - 1);
        mEffect.order.push_back({DeclRef::Kind::Parameter, mEffect.parameters.size() - 1});
        firstDeclarator = false;
        if (!accept(",")) break;
        declName = &expectIdentifier("a name");
    }
    (void)firstDeclarator;
    size_t last = mPos;
    // fxc takes a D3D10 state block without the ';' after its '}'.
    if (!(endsInBlock && !check(";"))) expect(";");
    if (storage.isStatic && !declared.empty()) {
        // The whole declaration goes with its first declarator; the others share it.
        Parameter& p = mEffect.parameters[declared.front()];
        p.hlslText = sliceText(first, last);
        p.hlslLoc = sliceLoc(first);
    }
}

std::vector<Annotation> Parser::parseAnnotations() {
    std::vector<Annotation> annotations;
    expect("<");
    while (!check(">") && !check(">=") && !check(">>")) {
        if (atEnd()) unexpected("'>' to close the annotations");
        bool rowMajor = false;
        while (check("row_major") || check("column_major")) rowMajor = advance().text == "row_major";
        const Token& typeToken = peek();
        TypeDesc type = parseType();
        type.rowMajor = rowMajor;
        const bool isObject = isObjectType(type);
        for (;;) {
            Annotation annotation;
            annotation.type = type;
            const Token& name = expectIdentifier("an annotation name");
            if (isObject) {
                // Read past its initializer (a value or a state block) so that the rest of the block
                // is still checked.
                error(DiagId::ObjectAnnotation, name.loc, {name.text, typeToken.text});
                for (int depth = 0; !atEnd() && !(depth == 0 && check(";"));) {
                    if (check("{")) ++depth;
                    if (check("}")) --depth;
                    advance();
                }
                break;
            }
            annotation.name = name.text;
            annotation.loc = name.loc;
            for (const Annotation& earlier : annotations)
                if (earlier.name == annotation.name) error(DiagId::Redefinition, name.loc, {name.text});
            parseArrayDims(annotation.type);
            expect("=");
            annotation.value = parseExpr(/*inAnnotation*/ true);
            if (const Expr* named = namedAnnotation(annotation.value, annotations))
                error(DiagId::AnnotationNamesAnnotation, named->loc, {annotation.name, named->text});
            // `string UIName = 3;` and `float UIMin = "low";` were kept and read as 0 or "" later.
            const bool isString = annotation.value.kind == Expr::Kind::String;
            if (annotation.type.base == BaseType::String && !isString)
                error(DiagId::AnnotationStringExpected, annotation.value.loc,
                      {annotation.name, annotation.value.str()});
            else if (annotation.type.isNumeric() && isString)
                error(DiagId::AnnotationNumberExpected, annotation.value.loc, {annotation.name});
            annotations.push_back(std::move(annotation));
            if (!accept(",")) break;
        }
        expect(";");
    }
    expectCloseAngle();
    return annotations;
}

}  // namespace fx::detail
