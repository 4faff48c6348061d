// EffectParser: recursive-descent parser for D3DX9 effect syntax (with the D3D10 forms FX Composer files
// use) over the tokens of the preprocessed text. Every node gets the user's SourceLoc.
//
// Features:
//  - global parameters with storage classes, semantics, annotations and initializers
//  - textures, samplers with sampler_state blocks (validated against the sampler state table)
//  - structs, functions (HLSL kept as text slices, what fxc accepted and glslang refuses rewritten on
//    their tokens: HlslLegalization.h), typedefs and cbuffers (verbatim)
//  - techniques (technique/technique10/technique11, fxgroup), passes, render states (validated, enums
//    resolved); D3D10 state objects expanded into the pass states they set (RenderStateDefs.h)
//  - cbuffer/tbuffer members as effect parameters
//  - techniques GL cannot run (stream output, dynamic linkage, stages shadowfx does not lower) left out
//    with a located warning; an effect all of whose techniques are left out is an error
//  - error recovery per top-level declaration, at most kMaxErrors errors, bounded recursion
#include "Parser.h"

#include "ConstantFolding.h"
#include "MacroNoteSink.h"
#include "SemanticTables.h"
#include "TypeNames.h"
#include "UserFunctionInliner.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

namespace fx::detail {

void Parser::parseEffect() {
    try {
        while (!atEnd()) {
            size_t start = mPos;
            try {
                parseTopLevel();
            } catch (const SyntaxError&) {
                synchronize(start);
            }
        }
    } catch (const TooManyErrors&) {
        return;
    }
    retypeSamplersOfTextureObjects();
    positionBesideSvPosition();
    // What fxc accepted and glslang refuses, rewritten in the functions' text glslang will read.
    legalizeFunctions(
        mTokens, mText, mFunctionRanges, [this](const Token& t) { return isTypeName(t); }, mEffect, mDiag);
    if (const auto& first = mRefusals.first(); mEffect.techniques.empty() && first) {
        try {
            error(first->refusal.allLeftOut, first->loc, {first->name});
        } catch (const TooManyErrors&) {
        }
    }
}

namespace {

// The sampler type a D3D9 texture intrinsic reads (tex2Dlod, texCUBEbias, ...); Sampler for others.
BaseType samplerReadBy(const std::string& intrinsic) {
    static const std::pair<const char*, BaseType> kKinds[] = {{"texCUBE", BaseType::SamplerCube},
                                                              {"tex3D", BaseType::Sampler3D},
                                                              {"tex2D", BaseType::Sampler2D},
                                                              {"tex1D", BaseType::Sampler1D}};
    for (const auto& [prefix, kind] : kKinds)
        if (intrinsic.rfind(prefix, 0) == 0) return kind;
    return BaseType::Sampler;
}

}  // namespace

void Parser::positionBesideSvPosition() {
    // A vertex input's POSITION is the mesh's (or a DrawAuto capture's) position, and a stream's element
    // is captured by its semantics as a stream-output declaration names them: both keep POSITION.
    std::set<std::string> kept = vertexInputStructs(mEffect);
    for (const FunctionDecl& f : mEffect.functions)
        for (const FunctionParam& p : f.params)
            if (!p.stream.empty()) kept.insert(p.type.structName);
    for (StructDecl& s : mEffect.structs) {
        if (kept.count(s.name)) continue;
        const auto svPosition = std::find_if(s.members.begin(), s.members.end(), [](const StructMember& m) {
            return canonicalSemantic(m.semantic) == "SV_POSITION";
        });
        if (svPosition == s.members.end()) continue;
        for (StructMember& m : s.members) {
            if (canonicalSemantic(m.semantic) != "POSITION0") continue;
            mDiag.report(DiagId::PositionBesideSvPosition, m.loc, {m.name, svPosition->name});
            m.semantic = kPositionBesideSvPosition;
        }
    }
}

void Parser::retypeSamplersOfTextureObjects() {
    std::set<std::string> byObject, comparing;
    std::map<std::string, std::set<BaseType>> byIntrinsic;  // a sampler's name -> the kinds read from it
    for (size_t i = 0; i + 3 < mTokens.size(); ++i) {
        const Token& a = mTokens[i];
        if (a.is(".") && mTokens[i + 1].kind == Token::Kind::Identifier && mTokens[i + 2].is("(") &&
            mTokens[i + 3].kind == Token::Kind::Identifier) {
            const std::string& method = mTokens[i + 1].text;
            if (method.rfind("Sample", 0) == 0 || method.rfind("Gather", 0) == 0 ||
                method.rfind("CalculateLevelOfDetail", 0) == 0)
                (method.find("Cmp") != std::string::npos ? comparing : byObject).insert(mTokens[i + 3].text);
        }
        if (a.kind == Token::Kind::Identifier && a.text.rfind("tex", 0) == 0 && mTokens[i + 1].is("(") &&
            mTokens[i + 2].kind == Token::Kind::Identifier)
            byIntrinsic[mTokens[i + 2].text].insert(samplerReadBy(a.text));
    }
    for (Parameter& p : mEffect.parameters) {
        if (p.type.base != BaseType::Sampler) continue;
        if (const auto read = byIntrinsic.find(p.name); read != byIntrinsic.end()) {
            const BaseType kind = read->second.size() == 1 ? *read->second.begin() : BaseType::Sampler;
            if (kind == BaseType::SamplerCube || kind == BaseType::Sampler3D) p.type.base = kind;
            continue;
        }
        if (comparing.count(p.name))
            p.type.base = BaseType::SamplerComparisonState;
        else if (byObject.count(p.name))
            p.type.base = BaseType::SamplerState;
    }
}

const Token& Parser::peek(size_t ahead) const {
    size_t index = std::min(mPos + ahead, mTokens.size() - 1);
    return mTokens[index];
}

const Token& Parser::advance() {
    const Token& token = mTokens[mPos];
    if (mPos + 1 < mTokens.size()) ++mPos;
    return token;
}

bool Parser::accept(const char* spelling) {
    if (!check(spelling)) return false;
    advance();
    return true;
}

std::string Parser::describe(const Token& token) {
    switch (token.kind) {
        case Token::Kind::End:
            return "end of file";
        case Token::Kind::String:
            return "\"" + token.text + "\"";
        default:
            return token.text;
    }
}

void Parser::fail(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
    error(id, loc, args);
    throw SyntaxError{};
}

void Parser::error(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
    if (mSpeculative) throw SyntaxError{};  // trying a reading that may not fit: nothing to report
    mDiag.report(id, loc, args);
    if (mDiag.errors() >= kMaxErrors) throw TooManyErrors{};
}

void Parser::unexpected(const std::string& expected) {
    const Token& token = peek();
    if (token.kind == Token::Kind::End) fail(DiagId::UnexpectedEndOfFile, token.loc, {expected});
    fail(DiagId::UnexpectedToken, token.loc, {expected, describe(token)});
}

const Token& Parser::expect(const char* spelling) {
    if (!check(spelling)) {
        // A ';' missing at the end of a line: the statement that lacks it is the one above, not the next
        // line's first token. Report it after the last token of that statement and go on as if it were
        // there, so that the next statement parses and nothing follows from it.
        const bool missingAtLineEnd = std::string_view(spelling) == ";" && mPos > 0 &&
                                      (atEnd() || peek().loc.file != mTokens[mPos - 1].loc.file ||
                                       peek().loc.line > mTokens[mPos - 1].loc.line);
        if (!missingAtLineEnd) unexpected(std::string("'") + spelling + "'");
        const Token& last = mTokens[mPos - 1];
        SourceLoc after = last.loc;
        if (!last.fromMacro) after.column += static_cast<int>(last.end - last.begin);
        error(DiagId::MissingSemicolon, after, {describe(last)});
        return peek();
    }
    return advance();
}

const Token& Parser::expectIdentifier(const char* what) {
    if (peek().kind != Token::Kind::Identifier) unexpected(what);
    return advance();
}

void Parser::expectCloseAngle() {
    Token& token = mTokens[mPos];
    if (token.is(">")) {
        advance();
        return;
    }
    if (token.is(">=") || token.is(">>") || token.is(">>=")) {
        token.text.erase(0, 1);
        token.begin += 1;
        token.ppColumn += 1;
        token.loc.column += 1;
        return;
    }
    unexpected("'>'");
}

void Parser::expectClose(const char* opener, const Token& openToken) {
    if (check("}")) {
        advance();
        return;
    }
    unclosed(opener, openToken);
}

void Parser::unclosed(const char* opener, const Token& openToken) {
    fail(DiagId::UnclosedBlock, peek().loc, {"}", opener, std::to_string(openToken.loc.line)});
}

void Parser::synchronize(size_t start) {
    size_t errorPos = mPos;
    mPos = start;
    int depth = 0;
    while (!atEnd()) {
        const Token& token = advance();
        if (token.is("{")) ++depth;
        if (token.is("}") && --depth <= 0) {
            if (mPos > errorPos || depth == 0) {
                accept(";");
                break;
            }
            depth = 0;
        }
        if (token.is(";") && depth <= 0 && mPos > errorPos) break;
    }
}

std::string Parser::sliceText(size_t firstToken, size_t lastToken) const {
    const Token& first = mTokens[firstToken];
    const Token& last = mTokens[lastToken];
    return mText.substr(first.begin, last.end - first.begin);
}

SourceLoc Parser::sliceLoc(size_t firstToken) const {
    SourceLoc loc = mTokens[firstToken].loc;
    loc.column = mTokens[firstToken].ppColumn;  // see Effect.h: hlslLoc's column is the preprocessed one
    return loc;
}

bool Parser::isTypeName(const Token& token) const {
    if (token.kind != Token::Kind::Identifier) return false;
    TypeDesc type;
    return token.text == "vector" || token.text == "matrix" || parseScalarTypeName(token.text, type) ||
           parseObjectTypeName(token.text, type) || mTypeNames.count(token.text) ||
           isTemplatedObject(token.text);
}

bool Parser::isTemplatedObject(const std::string& name) {
    static const char* kNames[] = {"Texture2DArray",
                                   "TextureCubeArray",
                                   "Texture2DMS",
                                   "Texture2DMSArray",
                                   "Texture1DArray",
                                   "Buffer",
                                   "RWTexture1D",
                                   "RWTexture2D",
                                   "RWTexture3D",
                                   "RWBuffer",
                                   "StructuredBuffer",
                                   "RWStructuredBuffer",
                                   "ByteAddressBuffer",
                                   "RWByteAddressBuffer",
                                   "AppendStructuredBuffer",
                                   "ConsumeStructuredBuffer"};
    for (const char* n : kNames)
        if (name == n) return true;
    return false;
}

TypeDesc Parser::parseType() {
    const Token& name = peek();
    if (name.kind != Token::Kind::Identifier) unexpected("a type");
    TypeDesc type;
    if (name.text == "vector" || name.text == "matrix") {
        bool isMatrix = name.text == "matrix";
        advance();
        type.base = BaseType::Float;
        type.shape = isMatrix ? Shape::Matrix : Shape::Vector;
        type.rows = isMatrix ? 4 : 1;
        type.cols = 4;
        if (accept("<")) {
            const Token& scalar = expectIdentifier("a scalar type");
            TypeDesc scalarType;
            if (!parseScalarTypeName(scalar.text, scalarType) || scalarType.shape != Shape::Scalar)
                fail(DiagId::UnknownType, scalar.loc, {scalar.text});
            type.base = scalarType.base;
            expect(",");
            int first = parseDimension();
            if (isMatrix) {
                expect(",");
                type.rows = first;
                type.cols = parseDimension();
            } else {
                type.cols = first;
            }
            expectCloseAngle();
        }
        return type;
    }
    if (parseScalarTypeName(name.text, type) || parseObjectTypeName(name.text, type)) {
        advance();
        if (type.isTexture() && check("<")) type.templateArgs = angleText();  // Texture2D<float2>
        return type;
    }
    if (mTypeNames.count(name.text)) {
        advance();
        type.base = BaseType::Struct;
        type.structName = name.text;
        return type;
    }
    if (std::optional<BaseType> base = supportedResource(name.text)) {
        advance();
        type.base = *base;
        if (check("<")) type.templateArgs = angleText();
        return type;
    }
    fail(DiagId::UnknownType, name.loc, {name.text});
}

std::optional<BaseType> Parser::supportedResource(const std::string& name) {
    static const std::pair<const char*, BaseType> kResources[] = {
        {"Texture1DArray", BaseType::Texture1DArray},
        {"Texture2DArray", BaseType::Texture2DArray},
        {"TextureCubeArray", BaseType::TextureCubeArray},
        {"Texture2DMS", BaseType::Texture2DMS},
        {"Texture2DMSArray", BaseType::Texture2DMSArray},
        {"Buffer", BaseType::Buffer},
        {"StructuredBuffer", BaseType::StructuredBuffer},
        {"ByteAddressBuffer", BaseType::ByteAddressBuffer},
        {"RWStructuredBuffer", BaseType::RWStructuredBuffer},
        {"RWByteAddressBuffer", BaseType::RWByteAddressBuffer},
        {"AppendStructuredBuffer", BaseType::AppendStructuredBuffer},
        {"ConsumeStructuredBuffer", BaseType::ConsumeStructuredBuffer},
        {"RWTexture1D", BaseType::RWTexture1D},
        {"RWTexture2D", BaseType::RWTexture2D},
        {"RWTexture3D", BaseType::RWTexture3D},
        {"RWTexture2DArray", BaseType::RWTexture2DArray},
        {"RWBuffer", BaseType::RWBuffer}};
    for (const auto& [spelling, base] : kResources)
        if (name == spelling) return base;
    return std::nullopt;
}

std::string Parser::angleText() {
    const size_t open = mPos;
    skipAngles();
    if (mPos - open < 3) return "";
    return sliceText(open + 1, mPos - 2);
}

void Parser::skipAngles() {
    expect("<");
    int depth = 1;
    while (depth > 0 && !atEnd()) {
        if (check("<")) ++depth;
        if (check(">")) --depth;
        if (check(">>")) depth -= 2;
        advance();
    }
}

int Parser::parseDimension() {
    const Token& token = peek();
    Expr value = parseExpr(true);
    double number = 0;
    if (!foldConstant(mEffect, value, number) || number < 1 || number > 4)
        fail(DiagId::VectorDimensionInvalid, token.loc, {value.str()});
    return static_cast<int>(number);
}

void Parser::parseArrayDims(TypeDesc& type) {
    while (check("[")) {
        advance();  // '['
        if (accept("]")) {
            type.arrayDims.push_back(0);
            continue;
        }
        const Token& first = peek();
        Expr size = parseExpr();
        double number = 0;
        if (!foldConstant(mEffect, size, number)) fail(DiagId::ArraySizeNotConstant, first.loc, {size.str()});
        // Bounded, all dimensions together, so that a declaration cannot make the compiler allocate
        // gigabytes of initial value (`float4x4 a[1 << 24]` was 1 GB; `[65536][65536]` more).
        constexpr double kMaxArrayElements = 1 << 16;
        double elements = number;
        for (int dim : type.arrayDims) elements *= dim > 0 ? dim : 1;
        if (!(number >= 1 && elements <= kMaxArrayElements))
            fail(DiagId::ArraySizeOutOfRange, first.loc,
                 {size.str(), std::to_string(static_cast<int>(kMaxArrayElements))});
        if (number != static_cast<double>(static_cast<int>(number)))  // `[2.5]` was truncated silently
            fail(DiagId::ArraySizeNotWhole, first.loc, {size.str()});
        type.arrayDims.push_back(static_cast<int>(number));
        expect("]");
    }
}

std::string Parser::parseSemantics(int* samplerRegister) {
    std::string semantic;
    while (check(":")) {
        advance();
        const Token& name = expectIdentifier("a semantic");
        // `register(s3)`: the sampler register D3D9 passes address by index (`MinFilter[3] = ...`).
        if (samplerRegister && name.text == "register" && check("(") &&
            peek(1).kind == Token::Kind::Identifier && peek(2).is(")")) {
            const std::string& reg = peek(1).text;
            if (reg.size() > 1 && (reg[0] == 's' || reg[0] == 'S') &&
                reg.find_first_not_of("0123456789", 1) == std::string::npos && reg.size() < 5)
                *samplerRegister = std::stoi(reg.substr(1));
        }
        if ((name.text == "register" || name.text == "packoffset") && check("(")) {
            skipBalanced("(", ")");
            continue;
        }
        semantic = name.text;
    }
    return semantic;
}

void Parser::skipBalanced(const char* open, const char* close) {
    const Token& opener = expect(open);
    int depth = 1;
    while (depth > 0) {
        if (atEnd()) unclosed(open, opener);
        if (check(open)) ++depth;
        if (check(close)) --depth;
        advance();
    }
}

}  // namespace fx::detail

namespace fx {

std::shared_ptr<Effect> parseEffectSource(const std::string& source, const std::string& path,
                                          const ParseOptions& options, DiagnosticSink& diagnostics) {
    auto effect = std::make_shared<Effect>();
    detail::MacroNoteSink noted(diagnostics, effect->sourceMap);
    detail::CountingSink counted(noted);
    detail::PreprocessedSource pp;
    effect->path = path;
    if (!detail::preprocessEffect(source, path, options, counted, pp)) return nullptr;
    effect->includedFiles = pp.includedFiles;
    std::vector<detail::Token> tokens =
        detail::lexEffect(pp.text, path, pp.files, effect->sourceMap, counted);
    if (counted.errors() > 0) return nullptr;
    detail::spellKeywordsAsHlsl(tokens, pp.text);
    detail::Parser parser(std::move(tokens), pp.text, *effect, counted);
    parser.parseEffect();
    if (counted.errors() > 0) return nullptr;
    detail::inlineUserFunctionCalls(*effect, counted);
    if (counted.errors() > 0) return nullptr;
    return effect;
}

std::shared_ptr<Effect> parseEffectFile(const std::string& path, const ParseOptions& options,
                                        DiagnosticSink& diagnostics) {
    std::optional<std::string> text;
    if (options.readFile) {
        text = options.readFile(path);
    } else {
        std::ifstream in(path, std::ios::binary);
        if (in) {
            std::ostringstream buffer;
            buffer << in.rdbuf();
            text = buffer.str();
        }
    }
    if (!text) {
        diagnostics.report(DiagId::FileNotFound, SourceLoc{path, 0, 0}, {path});
        return nullptr;
    }
    return parseEffectSource(*text, path, options, diagnostics);
}

}  // namespace fx
