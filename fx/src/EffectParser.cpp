// EffectParser: recursive-descent parser for D3DX9 effect syntax (with the D3D10 forms FX Composer files
// use) over the tokens of the preprocessed text. Every node gets the user's SourceLoc.
//
// Features:
//  - global parameters with storage classes, semantics, annotations and initializers
//  - textures, samplers with sampler_state blocks (validated against the sampler state table)
//  - structs, functions (HLSL kept as text slices), typedefs and cbuffers (verbatim)
//  - techniques (technique/technique10/technique11, fxgroup), passes, render states (validated, enums
//    resolved); D3D10 state objects expanded into the pass states they set (RenderStateDefs.h)
//  - cbuffer/tbuffer members as effect parameters
//  - techniques GL cannot run (stream output, dynamic linkage, stages shadowfx does not lower) left out
//    with a located warning; an effect all of whose techniques are left out is an error
//  - error recovery per top-level declaration, at most kMaxErrors errors, bounded recursion
#include <fx/EffectParser.h>
#include <fx/RenderStates.h>

#include "Lexer.h"
#include "Preprocessor.h"
#include "UserFunctionInliner.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

namespace fx {

namespace {

using detail::Token;

constexpr size_t kMaxErrors = 20;
constexpr int kMaxDepth = 256;

struct SyntaxError {};    // thrown after reporting; the top level recovers at the next declaration
struct TooManyErrors {};  // thrown when kMaxErrors is reached

// "float", "float3", "float4x4", "int2", "bool", "half3x3", "dword" ...
bool parseScalarTypeName(const std::string& name, TypeDesc& type) {
    static const std::pair<const char*, BaseType> kScalars[] = {
        {"bool", BaseType::Bool},      {"int", BaseType::Int},         {"uint", BaseType::UInt},
        {"dword", BaseType::UInt},     {"half", BaseType::Half},       {"float", BaseType::Float},
        {"double", BaseType::Double},  {"min16float", BaseType::Half}, {"min16int", BaseType::Int},
        {"min16uint", BaseType::UInt},
    };
    for (const auto& [spelling, base] : kScalars) {
        size_t len = std::strlen(spelling);
        if (name.compare(0, len, spelling) != 0) continue;
        std::string rest = name.substr(len);
        type = TypeDesc{};
        type.base = base;
        if (rest.empty()) return true;
        if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') {
            type.shape = Shape::Vector;
            type.cols = rest[0] - '0';
            return true;
        }
        if (rest.size() == 3 && rest[0] >= '1' && rest[0] <= '4' && rest[1] == 'x' && rest[2] >= '1' &&
            rest[2] <= '4') {
            type.shape = Shape::Matrix;
            type.rows = rest[0] - '0';
            type.cols = rest[2] - '0';
            return true;
        }
    }
    return false;
}

bool parseObjectTypeName(const std::string& name, TypeDesc& type) {
    static const std::pair<const char*, BaseType> kObjects[] = {
        {"texture", BaseType::Texture},
        {"texture1D", BaseType::Texture1D},
        {"texture2D", BaseType::Texture2D},
        {"texture3D", BaseType::Texture3D},
        {"textureCUBE", BaseType::TextureCube},
        {"sampler", BaseType::Sampler},
        {"sampler1D", BaseType::Sampler1D},
        {"sampler2D", BaseType::Sampler2D},
        {"sampler3D", BaseType::Sampler3D},
        {"samplerCUBE", BaseType::SamplerCube},
        {"SamplerState", BaseType::SamplerState},
        {"SamplerComparisonState", BaseType::SamplerComparisonState},
        {"VertexShader", BaseType::VertexShader},
        {"PixelShader", BaseType::PixelShader},
        {"GeometryShader", BaseType::GeometryShader},
        {"HullShader", BaseType::HullShader},
        {"DomainShader", BaseType::DomainShader},
        {"ComputeShader", BaseType::ComputeShader},
        {"RasterizerState", BaseType::RasterizerState},
        {"DepthStencilState", BaseType::DepthStencilState},
        {"BlendState", BaseType::BlendState},
        {"RenderTargetView", BaseType::RenderTargetView},
        {"DepthStencilView", BaseType::DepthStencilView},
        {"string", BaseType::String},
        {"void", BaseType::Void},
    };
    for (const auto& [spelling, base] : kObjects) {
        if (equalsIgnoreCase(name, spelling)) {
            type = TypeDesc{};
            type.base = base;
            return true;
        }
    }
    return false;
}

class Parser {
public:
    Parser(std::vector<Token> tokens, const std::string& text, Effect& effect,
           detail::CountingSink& diagnostics)
        : mTokens(std::move(tokens)), mText(text), mEffect(effect), mDiag(diagnostics) {}

    void parseEffect() {
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
        if (mEffect.techniques.empty() && mFirstRefused) {
            try {
                error(DiagId::AllTechniquesRefused, mFirstRefused->loc,
                      {mFirstRefused->name, mFirstRefused->reason});
            } catch (const TooManyErrors&) {
            }
        }
    }

private:
    // fxc's D3D10 and later profiles read `sampler` as `SamplerState`: a `sampler` that the code passes to a
    // texture object's Sample or Gather methods (MonoGame's `sampler NameSampler : register(s0);` beside
    // `Texture2D Name`) is one, and glslang's D3D9 mode would take it for a combined sampler that
    // SPIRV-Cross cannot pair with the texture. A sampler also read with tex2D() and its kin stays D3D9's.
    void retypeSamplersOfTextureObjects() {
        std::set<std::string> byObject, comparing, byIntrinsic;
        for (size_t i = 0; i + 3 < mTokens.size(); ++i) {
            const Token& a = mTokens[i];
            if (a.is(".") && mTokens[i + 1].kind == Token::Kind::Identifier && mTokens[i + 2].is("(") &&
                mTokens[i + 3].kind == Token::Kind::Identifier) {
                const std::string& method = mTokens[i + 1].text;
                if (method.rfind("Sample", 0) == 0 || method.rfind("Gather", 0) == 0 ||
                    method.rfind("CalculateLevelOfDetail", 0) == 0)
                    (method.find("Cmp") != std::string::npos ? comparing : byObject)
                        .insert(mTokens[i + 3].text);
            }
            if (a.kind == Token::Kind::Identifier && a.text.rfind("tex", 0) == 0 && mTokens[i + 1].is("(") &&
                mTokens[i + 2].kind == Token::Kind::Identifier)
                byIntrinsic.insert(mTokens[i + 2].text);
        }
        for (Parameter& p : mEffect.parameters) {
            if (p.type.base != BaseType::Sampler || byIntrinsic.count(p.name)) continue;
            if (comparing.count(p.name))
                p.type.base = BaseType::SamplerComparisonState;
            else if (byObject.count(p.name))
                p.type.base = BaseType::SamplerState;
        }
    }

    // [SECTION] Tokens

    const Token& peek(size_t ahead = 0) const {
        size_t index = std::min(mPos + ahead, mTokens.size() - 1);
        return mTokens[index];
    }
    const Token& advance() {
        const Token& token = mTokens[mPos];
        if (mPos + 1 < mTokens.size()) ++mPos;
        return token;
    }
    bool atEnd() const { return peek().kind == Token::Kind::End; }
    bool check(const char* spelling) const { return peek().is(spelling); }
    bool accept(const char* spelling) {
        if (!check(spelling)) return false;
        advance();
        return true;
    }
    static std::string describe(const Token& token) {
        switch (token.kind) {
            case Token::Kind::End:
                return "end of file";
            case Token::Kind::String:
                return "\"" + token.text + "\"";
            default:
                return token.text;
        }
    }

    [[noreturn]] void fail(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        error(id, loc, args);
        throw SyntaxError{};
    }
    void error(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args) {
        if (mSpeculative) throw SyntaxError{};  // trying a reading that may not fit: nothing to report
        mDiag.report(id, loc, args);
        if (mDiag.errors() >= kMaxErrors) throw TooManyErrors{};
    }
    [[noreturn]] void unexpected(const std::string& expected) {
        const Token& token = peek();
        if (token.kind == Token::Kind::End) fail(DiagId::UnexpectedEndOfFile, token.loc, {expected});
        fail(DiagId::UnexpectedToken, token.loc, {expected, describe(token)});
    }
    const Token& expect(const char* spelling) {
        if (!check(spelling)) unexpected(std::string("'") + spelling + "'");
        return advance();
    }
    const Token& expectIdentifier(const char* what) {
        if (peek().kind != Token::Kind::Identifier) unexpected(what);
        return advance();
    }
    // '>' closing an annotation or template; splits ">=" and ">>" so the rest is seen next.
    void expectCloseAngle() {
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
    // A block's closing '}', naming the opener when the file ends or another block starts first.
    void expectClose(const char* opener, const Token& openToken) {
        if (check("}")) {
            advance();
            return;
        }
        unclosed(opener, openToken);
    }
    [[noreturn]] void unclosed(const char* opener, const Token& openToken) {
        fail(DiagId::UnclosedBlock, peek().loc, {"}", opener, std::to_string(openToken.loc.line)});
    }

    struct DepthGuard {
        Parser& parser;
        explicit DepthGuard(Parser& p) : parser(p) {
            if (++parser.mDepth > kMaxDepth) {
                --parser.mDepth;
                parser.fail(DiagId::UnsupportedFeature, parser.peek().loc,
                            {"nesting deeper than " + std::to_string(kMaxDepth) + " levels"});
            }
        }
        ~DepthGuard() { --parser.mDepth; }
    };

    // Skips to the end of the declaration that started at `start`: after a ';' at brace depth 0, or after
    // the '}' (and an optional ';') that closes its outermost block.
    void synchronize(size_t start) {
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

    std::string sliceText(size_t firstToken, size_t lastToken) const {
        const Token& first = mTokens[firstToken];
        const Token& last = mTokens[lastToken];
        return mText.substr(first.begin, last.end - first.begin);
    }
    SourceLoc sliceLoc(size_t firstToken) const {
        SourceLoc loc = mTokens[firstToken].loc;
        loc.column = mTokens[firstToken].ppColumn;  // see Effect.h: hlslLoc's column is the preprocessed one
        return loc;
    }

    // [SECTION] Types

    bool isTypeName(const Token& token) const {
        if (token.kind != Token::Kind::Identifier) return false;
        TypeDesc type;
        return token.text == "vector" || token.text == "matrix" || parseScalarTypeName(token.text, type) ||
               parseObjectTypeName(token.text, type) || mTypeNames.count(token.text) ||
               isTemplatedObject(token.text);
    }
    static bool isTemplatedObject(const std::string& name) {
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

    TypeDesc parseType() {
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
            if (type.isTexture() && check("<")) skipAngles();  // Texture2D<float4>
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
        if (isTemplatedObject(name.text)) {
            const bool readWrite = name.text.rfind("RW", 0) == 0 || name.text.rfind("Append", 0) == 0 ||
                                   name.text.rfind("Consume", 0) == 0;
            fail(DiagId::UnsupportedFeature, name.loc,
                 {"type '" + name.text + "' is not supported in effects: " +
                  (readWrite ? "read-write resources are bound by the application (FX11 sets unordered "
                               "access views outside passes); a pass binds none"
                             : "shadowfx creates no multisample array resources")});
        }
        fail(DiagId::UnknownType, name.loc, {name.text});
    }
    // The D3D10 resources that GL holds: array and multisample textures, buffer textures and storage blocks.
    static std::optional<BaseType> supportedResource(const std::string& name) {
        static const std::pair<const char*, BaseType> kResources[] = {
            {"Texture1DArray", BaseType::Texture1DArray},
            {"Texture2DArray", BaseType::Texture2DArray},
            {"TextureCubeArray", BaseType::TextureCubeArray},
            {"Texture2DMS", BaseType::Texture2DMS},
            {"Buffer", BaseType::Buffer},
            {"StructuredBuffer", BaseType::StructuredBuffer},
            {"ByteAddressBuffer", BaseType::ByteAddressBuffer}};
        for (const auto& [spelling, base] : kResources)
            if (name == spelling) return base;
        return std::nullopt;
    }
    // `<float4, 4>`: the text between the angle brackets as written, consumed.
    std::string angleText() {
        const size_t open = mPos;
        skipAngles();
        if (mPos - open < 3) return "";
        return sliceText(open + 1, mPos - 2);
    }
    void skipAngles() {
        expect("<");
        int depth = 1;
        while (depth > 0 && !atEnd()) {
            if (check("<")) ++depth;
            if (check(">")) --depth;
            if (check(">>")) depth -= 2;
            advance();
        }
    }
    int parseDimension() {
        const Token& token = peek();
        Expr value = parseExpr(true);
        double number = 0;
        if (!constantValue(value, number) || number < 1 || number > 4)
            fail(DiagId::UnexpectedToken, token.loc, {"a dimension 1..4", value.str()});
        return static_cast<int>(number);
    }
    // A compile-time constant: literals, the effect's `static const` / `const` scalars declared before
    // (D3D9 sizes arrays with them: `float4x3 m[MAX_MATRICES]`), casts and integer arithmetic.
    bool constantValue(const Expr& e, double& out, int depth = 0) const {
        if (depth > 32) return false;
        auto integer = [](double x) {
            return std::isfinite(x) && std::abs(x) < 2147483648.0 ? static_cast<int64_t>(x) : int64_t{0};
        };
        switch (e.kind) {
            case Expr::Kind::Number:
            case Expr::Kind::Bool:
                out = e.number;
                return true;
            case Expr::Kind::Identifier: {
                const Parameter* p = mEffect.findParameter(e.text);
                if (!p || !(p->isConst || p->isStatic) || !p->initializer || !p->type.isNumeric() ||
                    !p->type.arrayDims.empty())
                    return false;
                if (!constantValue(*p->initializer, out, depth + 1)) return false;
                if (p->type.base == BaseType::Int || p->type.base == BaseType::UInt) out = std::trunc(out);
                return true;
            }
            case Expr::Kind::Member: {
                // One component of a constant vector: `SIZE.x` of `static const int2 SIZE = int2(4, 2);`.
                static const std::string kComponents[] = {"xyzw", "rgba"};
                int component = -1;
                for (const std::string& set : kComponents)
                    if (e.text.size() == 1 && set.find(e.text[0]) != std::string::npos)
                        component = static_cast<int>(set.find(e.text[0]));
                if (component < 0 || e.args.size() != 1) return false;
                const Expr* vector = &e.args[0];
                if (vector->kind == Expr::Kind::Identifier) {
                    const Parameter* p = mEffect.findParameter(vector->text);
                    if (!p || !(p->isConst || p->isStatic) || !p->initializer || !p->type.arrayDims.empty())
                        return false;
                    vector = &*p->initializer;
                }
                TypeDesc constructed;
                const bool constructor =
                    vector->kind == Expr::Kind::Call && parseScalarTypeName(vector->text, constructed);
                if ((!constructor && vector->kind != Expr::Kind::InitList) ||
                    static_cast<int>(vector->args.size()) <= component)
                    return false;
                return constantValue(vector->args[static_cast<size_t>(component)], out, depth + 1);
            }
            case Expr::Kind::Call:
                // min, max and abs of constants: fxc folded them in array sizes.
                if ((e.text == "min" || e.text == "max") && e.args.size() == 2) {
                    double a, b;
                    if (!constantValue(e.args[0], a, depth + 1) || !constantValue(e.args[1], b, depth + 1))
                        return false;
                    out = e.text == "min" ? std::min(a, b) : std::max(a, b);
                    return true;
                }
                if (e.text == "abs" && e.args.size() == 1) {
                    if (!constantValue(e.args[0], out, depth + 1)) return false;
                    out = std::abs(out);
                    return true;
                }
                [[fallthrough]];
            case Expr::Kind::Cast:
                // (int)x, int(x), float(x)
                if (e.args.size() != 1 || !constantValue(e.args[0], out, depth + 1)) return false;
                if (e.kind == Expr::Kind::Call && e.text != "int" && e.text != "uint" && e.text != "float")
                    return false;
                if ((e.kind == Expr::Kind::Cast &&
                     (e.castType.base == BaseType::Int || e.castType.base == BaseType::UInt)) ||
                    e.text == "int" || e.text == "uint")
                    out = std::trunc(out);
                return true;
            case Expr::Kind::Unary: {
                double a;
                if (e.args.size() != 1 || !constantValue(e.args[0], a, depth + 1)) return false;
                out = e.text == "-" ? -a : e.text == "+" ? a : e.text == "!" ? !a : 0;
                return e.text != "~";
            }
            case Expr::Kind::Ternary: {
                double c;
                if (e.args.size() != 3 || !constantValue(e.args[0], c, depth + 1)) return false;
                return constantValue(e.args[c != 0 ? 1 : 2], out, depth + 1);
            }
            case Expr::Kind::Binary: {
                double a, b;
                if (e.args.size() != 2 || !constantValue(e.args[0], a, depth + 1) ||
                    !constantValue(e.args[1], b, depth + 1))
                    return false;
                const int64_t ia = integer(a), ib = integer(b);
                if (e.text == "+")
                    out = a + b;
                else if (e.text == "-")
                    out = a - b;
                else if (e.text == "*")
                    out = a * b;
                else if (e.text == "/" && b != 0)  // whole operands divide as HLSL's ints do
                    out = a == std::trunc(a) && b == std::trunc(b) ? std::trunc(a / b) : a / b;
                else if (e.text == "%" && ib != 0)
                    out = static_cast<double>(ia % ib);
                else if (e.text == "<<" && ib >= 0 && ib < 32)
                    out = static_cast<double>(ia * (int64_t{1} << ib));
                else if (e.text == ">>" && ib >= 0 && ib < 32)
                    out = static_cast<double>(ia >> ib);
                else
                    return false;
                return true;
            }
            default:
                return false;
        }
    }
    // [N][M]... after a name
    void parseArrayDims(TypeDesc& type) {
        while (check("[")) {
            advance();  // '['
            if (accept("]")) {
                type.arrayDims.push_back(0);
                continue;
            }
            const Token& first = peek();
            Expr size = parseExpr();
            double number = 0;
            if (!constantValue(size, number))
                fail(DiagId::UnexpectedToken, first.loc, {"a constant array size", size.str()});
            // Bounded, all dimensions together, so that a declaration cannot make the compiler allocate
            // gigabytes of initial value (`float4x4 a[1 << 24]` was 1 GB; `[65536][65536]` more).
            constexpr double kMaxArrayElements = 1 << 16;
            double elements = number;
            for (int dim : type.arrayDims) elements *= dim > 0 ? dim : 1;
            if (!(number >= 1 && elements <= kMaxArrayElements))
                fail(DiagId::UnsupportedFeature, first.loc,
                     {"array size " + size.str() + " is outside 1.." +
                      std::to_string(static_cast<int>(kMaxArrayElements)) + " (all dimensions together)"});
            if (number != static_cast<double>(static_cast<int>(number)))  // `[2.5]` was truncated silently
                fail(DiagId::UnexpectedToken, first.loc, {"a whole array size", size.str()});
            type.arrayDims.push_back(static_cast<int>(number));
            expect("]");
        }
    }
    // ": SEMANTIC", skipping ": register(...)" and ": packoffset(...)".
    std::string parseSemantics() {
        std::string semantic;
        while (check(":")) {
            advance();
            const Token& name = expectIdentifier("a semantic");
            if ((name.text == "register" || name.text == "packoffset") && check("(")) {
                skipBalanced("(", ")");
                continue;
            }
            semantic = name.text;
        }
        return semantic;
    }
    void skipBalanced(const char* open, const char* close) {
        const Token& opener = expect(open);
        int depth = 1;
        while (depth > 0) {
            if (atEnd()) unclosed(open, opener);
            if (check(open)) ++depth;
            if (check(close)) --depth;
            advance();
        }
    }

    // [SECTION] Top level

    void parseTopLevel() {
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
            fail(DiagId::UnsupportedFeature, token.loc,
                 {"dynamic shader linkage ('" + token.text +
                  "') is not supported: GLSL has no interfaces or classes to bind at run time"});
        if (token.text == "struct") {
            parseStruct();
            return;
        }
        if (token.text == "pass")  // was "unknown type 'pass'"
            fail(DiagId::UnexpectedToken, token.loc,
                 {"a declaration ('pass' belongs inside a technique)", "pass"});
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

    void parseTypedef() {
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

    // `cbuffer Name : register(b0) { float4x4 World : WORLD; ... };`: its members are effect parameters
    // like any global (semantics, annotations, initializers), bound by semantic; GL gets them in the
    // stage's one uniform block, as D3D9's globals.
    void parseConstantBuffer() {
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

    void addVerbatim(size_t first, size_t last) {
        VerbatimDecl decl;
        decl.hlslText = sliceText(first, last);
        decl.hlslLoc = sliceLoc(first);
        mEffect.verbatim.push_back(std::move(decl));
        mEffect.order.push_back({DeclRef::Kind::Verbatim, mEffect.verbatim.size() - 1});
    }

    void parseStruct() {
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
            TypeDesc type = parseType();
            type.rowMajor = rowMajor;
            for (;;) {
                StructMember m = member;
                m.type = type;
                const Token& memberName = expectIdentifier("a member name");
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

    struct Storage {
        bool isStatic = false, isConst = false, isUniform = false, isShared = false, isExtern = false;
        bool rowMajor = false;
    };

    void parseDeclaration(bool inBuffer = false) {
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
                if (!constantValue(count, number) || number < 1 || number > 1024 ||
                    number != static_cast<double>(static_cast<int>(number)))
                    fail(DiagId::UnexpectedToken, attribute.loc, {"a vertex count 1..1024", count.str()});
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
            if (token.is("static"))
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
            else if (token.is("inline") || token.is("volatile") || token.is("precise") ||
                     token.is("groupshared")) {
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
            parameter.semantic = parseSemantics();
            if (check("<")) parameter.annotations = parseAnnotations();
            endsInBlock = check("{");
            if (parameter.type.isSampler() && check("{")) {
                parameter.samplerState = parseSamplerStateBlock();  // D3D10: SamplerState s { ... };
            } else if (parameter.type.isStateObject()) {
                if (!parameter.type.arrayDims.empty())
                    fail(DiagId::UnsupportedFeature, parameter.loc,
                         {"arrays of state objects are not supported"});
                if (check("{"))
                    parameter.objectState = parseObjectStateBlock(objectKind(parameter.type.base));
            } else if (accept("=")) {
                if (check("sampler_state")) {
                    advance();
                    parameter.samplerState = parseSamplerStateBlock();
                } else {
                    parameter.initializer = parseExpr();
                    normalizeCompileShader(*parameter.initializer);
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

    void parseFunction(size_t first, const TypeDesc& returnType, const Token& name) {
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
                else if (t.is("linear") || t.is("centroid") || t.is("nointerpolation") ||
                         t.is("noperspective") || t.is("sample"))
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
                if (!constantValue(size, number) || number < 1 || number > 32 ||
                    number != static_cast<double>(static_cast<int>(number)))
                    fail(DiagId::UnexpectedToken, size.loc, {"a control point count 1..32", size.str()});
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
            decl.straightBody = parseStraightBody(bodyBegin, last);
        }
        decl.hlslText = sliceText(first, last);
        decl.hlslLoc = sliceLoc(first);
        mEffect.functions.push_back(std::move(decl));
        mEffect.order.push_back({DeclRef::Kind::Function, mEffect.functions.size() - 1});
    }

    // The statements of tokens [begin, end) if they are code without loops (FunctionDecl::straightBody),
    // else nothing. Tried without reporting: any other body is HLSL's business, not the effect parser's.
    std::vector<FunctionDecl::Statement> parseStraightBody(size_t begin, size_t end) {
        using Statement = FunctionDecl::Statement;
        const size_t resume = mPos;
        std::vector<Statement> body;
        mSpeculative = true;
        try {
            mPos = begin;
            while (mPos < end) parseStraightStatement(body);
            if (mPos != end || body.empty() || body.back().kind != Statement::Kind::Return) body.clear();
            for (size_t i = 0; i + 1 < body.size(); ++i)
                if (body[i].kind == Statement::Kind::Return) body.clear();
        } catch (const SyntaxError&) {
            body.clear();
        }
        mSpeculative = false;
        mPos = resume;
        return body;
    }

    static bool isAssignment(const Token& t) {
        return t.is("=") || t.is("+=") || t.is("-=") || t.is("*=") || t.is("/=");
    }

    // One statement (a block's statements, a declaration's declarators) appended to `out`; throws
    // SyntaxError on anything else (loops, calls for their effect, returns inside branches).
    void parseStraightStatement(std::vector<FunctionDecl::Statement>& out) {
        using Statement = FunctionDecl::Statement;
        if (accept(";")) return;
        if (accept("{")) {
            while (!accept("}")) {
                if (atEnd()) throw SyntaxError{};
                parseStraightStatement(out);
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
            for (const std::vector<Statement>* branch : {&statement.then, &statement.otherwise})
                for (const Statement& s : *branch)
                    if (s.kind == Statement::Kind::Return) throw SyntaxError{};
            out.push_back(std::move(statement));
            return;
        }
        if (accept("return")) {
            statement.kind = Statement::Kind::Return;
            statement.value = parseExpr();
            statement.hasValue = true;
        } else if (peek().kind == Token::Kind::Identifier &&
                   (isAssignment(peek(1)) ||
                    (peek(1).is(".") && peek(2).kind == Token::Kind::Identifier && isAssignment(peek(3))))) {
            statement.kind = Statement::Kind::Assign;
            statement.name = advance().text;
            if (accept(".")) statement.member = advance().text;
            statement.op = advance().text;
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
                if (check("[")) throw SyntaxError{};  // local arrays: not straight-line values
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

    // [SECTION] Annotations

    std::vector<Annotation> parseAnnotations() {
        std::vector<Annotation> annotations;
        expect("<");
        while (!check(">") && !check(">=") && !check(">>")) {
            if (atEnd()) unexpected("'>' to close the annotations");
            TypeDesc type = parseType();
            for (;;) {
                Annotation annotation;
                annotation.type = type;
                const Token& name = expectIdentifier("an annotation name");
                annotation.name = name.text;
                annotation.loc = name.loc;
                parseArrayDims(annotation.type);
                expect("=");
                annotation.value = parseExpr(/*inAnnotation*/ true);
                // `string UIName = 3;` and `float UIMin = "low";` were kept and read as 0 or "" later.
                const bool isString = annotation.value.kind == Expr::Kind::String;
                if (annotation.type.base == BaseType::String && !isString)
                    error(DiagId::InvalidAnnotation, annotation.value.loc,
                          {annotation.name, "expected a string, found '" + annotation.value.str() + "'"});
                else if (annotation.type.isNumeric() && isString)
                    error(DiagId::InvalidAnnotation, annotation.value.loc,
                          {annotation.name, "expected a number, found a string"});
                annotations.push_back(std::move(annotation));
                if (!accept(",")) break;
            }
            expect(";");
        }
        expectCloseAngle();
        return annotations;
    }

    // [SECTION] Techniques and passes

    static bool isTechniqueKeyword(const Token& token) {
        return token.is("technique") || token.is("technique10") || token.is("technique11");
    }

    // `fxgroup Name { technique11 A { ... } ... }` (D3D11): its techniques keep their names and are also
    // found as "Name.A".
    void parseGroup() {
        const Token& keyword = advance();
        const Token& name = expectIdentifier("a group name");
        if (check("<")) parseAnnotations();
        if (!check("{")) unexpected("'{'");
        advance();
        while (!check("}")) {
            if (atEnd() || check("fxgroup")) unclosed("fxgroup", keyword);
            if (!isTechniqueKeyword(peek())) unexpected("'technique11' or '}'");
            parseTechnique(name.text);
        }
        advance();
        accept(";");
    }

    void parseTechnique(const std::string& group) {
        const Token& keyword = advance();
        Technique technique;
        technique.loc = keyword.loc;
        technique.group = group;
        technique.d3d10 = keyword.is("technique10") || keyword.is("technique11");
        if (peek().kind == Token::Kind::Identifier) {
            technique.name = peek().text;
            technique.loc = advance().loc;
        }
        if (check("<")) technique.annotations = parseAnnotations();
        if (!check("{")) unexpected("'{'");
        advance();
        mRefusal.reset();
        while (!check("}")) {
            if (atEnd() || isTechniqueKeyword(peek())) unclosed("technique", keyword);
            if (!check("pass")) unexpected("'pass' or '}'");
            technique.passes.push_back(parsePass(technique.d3d10));
        }
        advance();
        accept(";");
        for (const Technique& other : mEffect.techniques)
            if (!technique.name.empty() && other.name == technique.name && other.group == technique.group)
                error(DiagId::Redefinition, technique.loc, {technique.name});
        if (mRefusal) {
            // Never silently: the technique is named, with what GL cannot run and where it stands.
            const std::string name = technique.name.empty() ? "(unnamed)" : technique.name;
            mDiag.report(DiagId::TechniqueRefused, mRefusal->loc, {name, mRefusal->reason});
            if (!mFirstRefused) mFirstRefused = Refused{name, mRefusal->reason, mRefusal->loc};
            mRefusal.reset();
            return;
        }
        mEffect.techniques.push_back(std::move(technique));
    }

    // Something in the technique being parsed that GL cannot run: the technique is left out (the first
    // reason is reported), the rest of the effect still runs.
    void refuseTechnique(const SourceLoc& loc, const std::string& reason) {
        if (!mRefusal) mRefusal = Refused{"", reason, loc};
    }

    Pass parsePass(bool d3d10) {
        const Token& keyword = advance();
        Pass pass;
        pass.loc = keyword.loc;
        if (peek().kind == Token::Kind::Identifier) {
            pass.name = peek().text;
            pass.loc = advance().loc;
        }
        if (check("<")) pass.annotations = parseAnnotations();
        if (!check("{")) unexpected("'{'");
        advance();
        mObjectsSet.clear();
        while (!check("}")) {
            if (atEnd() || check("pass") || isTechniqueKeyword(peek())) unclosed("pass", keyword);
            parsePassState(pass);
        }
        advance();
        if (d3d10) {
            // A D3D10 pass that sets no rasterizer, depth-stencil or blend state runs with D3D10's
            // defaults for it, not D3D9's (DepthFunc LESS, stencil masks 0xff, ...): expanded first, so
            // that anything the pass sets wins.
            std::vector<StateAssignment> defaults;
            for (StateObjectKind kind :
                 {StateObjectKind::Rasterizer, StateObjectKind::DepthStencil, StateObjectKind::Blend})
                if (!mObjectsSet.count(kind)) expandStateObject(kind, {}, pass.loc, defaults);
            pass.states.insert(pass.states.begin(), defaults.begin(), defaults.end());
        }
        return pass;
    }

    static StateObjectKind objectKind(BaseType base) {
        return base == BaseType::RasterizerState     ? StateObjectKind::Rasterizer
               : base == BaseType::DepthStencilState ? StateObjectKind::DepthStencil
                                                     : StateObjectKind::Blend;
    }

    // Set*Shader(...) and Set*State(...) in a D3D10 pass.
    void parseSetCall(Pass& pass, const Token& name) {
        advance();  // '('
        std::vector<Expr> args;
        if (!check(")")) {
            args.push_back(parseExpr());
            while (accept(",")) args.push_back(parseExpr());
        }
        expect(")");
        expect(";");
        std::string what = name.text.substr(3);
        for (StateObjectKind kind :
             {StateObjectKind::Rasterizer, StateObjectKind::DepthStencil, StateObjectKind::Blend}) {
            if (what != stateObjectTypeName(kind)) continue;
            setStateObject(pass, name, kind, args);
            return;
        }
        const bool isShader = what == "VertexShader" || what == "PixelShader" || what == "GeometryShader" ||
                              what == "HullShader" || what == "DomainShader" || what == "ComputeShader";
        if (!isShader) {
            error(DiagId::UnknownState, name.loc, {name.text});
            return;
        }
        if (args.size() != 1) {
            error(DiagId::InvalidStateValue, name.loc, {name.text, "expected one shader"});
            return;
        }
        Expr value = std::move(args[0]);
        if (value.kind == Expr::Kind::Call && value.text == "BindInterfaces") {
            refuseTechnique(
                value.loc,
                "dynamic shader linkage (BindInterfaces) is not supported: GLSL has no interfaces "
                "to bind at run time");
            return;
        }
        // Stream output, inline or through a shader variable (`GeometryShader gsSO = ConstructGSWithSO(
        // CompileShader(gs_4_0, GS()), "POSITION.xyz; ...");`): only the techniques that use it are left
        // out, at the pass that sets it.
        const Parameter* variable =
            value.kind == Expr::Kind::Identifier ? mEffect.findParameter(value.text) : nullptr;
        if ((value.kind == Expr::Kind::Call && value.text == "ConstructGSWithSO") ||
            (variable && variable->initializer && variable->initializer->kind == Expr::Kind::Call &&
             variable->initializer->text == "ConstructGSWithSO")) {
            refuseTechnique(value.loc, std::string("stream output (ConstructGSWithSO") +
                                           (variable ? ", held by '" + variable->name + "'" : "") +
                                           ") is not supported: shadowfx has no transform feedback");
            return;
        }
        normalizeCompileShader(value);
        normalizeNull(value);
        const bool none = (value.kind == Expr::Kind::Identifier && value.text == "NULL") ||
                          (value.kind == Expr::Kind::Number && value.number == 0);
        if (what == "VertexShader" || what == "PixelShader" || what == "GeometryShader" ||
            what == "HullShader" || what == "DomainShader") {
            StateAssignment state;
            state.name = what;
            state.loc = name.loc;
            state.value = std::move(value);
            validateShaderValue(state);
            pass.states.push_back(std::move(state));
            return;
        }
        if (none) return;
        if (value.kind == Expr::Kind::Identifier && !mEffect.findParameter(value.text)) {
            error(DiagId::UnknownIdentifier, value.loc, {value.text});
            return;
        }
        refuseTechnique(name.loc, "compute shaders are dispatched by an application, not drawn by a pass");
    }

    // SetRasterizerState(rs), SetDepthStencilState(ds, stencilRef), SetBlendState(bs, factor, sampleMask):
    // the object's fields (its block, D3D10 defaults for the rest) become the pass's states.
    void setStateObject(Pass& pass, const Token& name, StateObjectKind kind, std::vector<Expr>& args) {
        const size_t expected = kind == StateObjectKind::Rasterizer     ? 1
                                : kind == StateObjectKind::DepthStencil ? 2
                                                                        : 3;
        if (args.size() != expected) {
            error(DiagId::InvalidStateValue, name.loc,
                  {name.text, "expected " + std::to_string(expected) + " argument(s), found " +
                                  std::to_string(args.size())});
            return;
        }
        const Expr& object = args[0];
        const std::vector<StateAssignment>* block = nullptr;
        static const std::vector<StateAssignment> kNone;
        if (object.kind == Expr::Kind::Identifier && equalsIgnoreCase(object.text, "NULL")) {
            block = &kNone;  // NULL: the D3D10 defaults
        } else if (object.kind == Expr::Kind::Identifier) {
            const Parameter* p = mEffect.findParameter(object.text);
            if (!p) {
                error(DiagId::UnknownIdentifier, object.loc, {object.text});
                return;
            }
            if (!p->type.isStateObject() || objectKind(p->type.base) != kind) {
                error(
                    DiagId::InvalidStateValue, object.loc,
                    {name.text, "'" + object.text + "' is not a " + std::string(stateObjectTypeName(kind))});
                return;
            }
            block = &p->objectState;
        } else {
            error(DiagId::InvalidStateValue, object.loc,
                  {name.text, "expected the name of a " + std::string(stateObjectTypeName(kind))});
            return;
        }
        mObjectsSet.insert(kind);
        expandStateObject(kind, *block, name.loc, pass.states);
        auto add = [&](RenderStateId id, Expr value) {
            StateAssignment state;
            state.name = std::string(renderStateInfo(id).name);
            state.loc = value.loc.valid() ? value.loc : name.loc;
            state.value = std::move(value);
            resolveStateValue(state.value, renderStateInfo(id).domain, state.name);
            pass.states.push_back(std::move(state));
        };
        if (kind == StateObjectKind::DepthStencil) add(RenderStateId::StencilRef, std::move(args[1]));
        if (kind == StateObjectKind::Blend) {
            // D3D10's blend factor is a float4; the state table's BlendFactor a packed D3DCOLOR.
            Expr& factor = args[1];
            double rgba[4];
            if ((factor.kind == Expr::Kind::InitList ||
                 (factor.kind == Expr::Kind::Call && factor.text == "float4")) &&
                factor.args.size() == 4 &&
                std::all_of(factor.args.begin(), factor.args.end(),
                            [&, i = 0](const Expr& c) mutable { return constantValue(c, rgba[i++]); })) {
                auto channel = [](double x) {
                    return static_cast<uint32_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255));
                };
                const uint32_t packed = channel(rgba[3]) << 24 | channel(rgba[0]) << 16 |
                                        channel(rgba[1]) << 8 | channel(rgba[2]);
                factor = numberExpr(static_cast<double>(packed), factor.loc);
            }
            add(RenderStateId::BlendFactor, std::move(factor));
            add(RenderStateId::SampleMask, std::move(args[2]));
        }
    }

    static Expr numberExpr(double value, const SourceLoc& loc) {
        Expr e;
        e.kind = Expr::Kind::Number;
        e.number = value;
        e.isInteger = value == std::trunc(value);
        e.loc = loc;
        return e;
    }

    // Every field of a state object of `kind` as pass states: the block's value, or D3D10's default.
    void expandStateObject(StateObjectKind kind, const std::vector<StateAssignment>& block,
                           const SourceLoc& loc, std::vector<StateAssignment>& out) {
        auto find = [&](std::string_view field, int index) -> const StateAssignment* {
            const StateAssignment* found = nullptr;
            for (const StateAssignment& a : block)
                if (equalsIgnoreCase(a.name, field) && (a.index < 0 ? 0 : a.index) == index) found = &a;
            return found;  // the last assignment wins, as in a pass
        };
        auto push = [&](RenderStateId id, Expr value, const SourceLoc& at) {
            StateAssignment state;
            state.name = std::string(renderStateInfo(id).name);
            state.loc = at;
            state.value = std::move(value);
            out.push_back(std::move(state));
        };
        for (const StateObjectField* field : stateObjectFields(kind)) {
            const StateAssignment* a = find(field->name, 0);
            if (field->name == "FrontCounterClockwise") continue;  // folded into CullMode below
            if (field->name == "CullMode") {
                // D3D9's CullMode names the winding that is culled (CW or CCW), D3D10's the facing (FRONT or
                // BACK) with FrontCounterClockwise saying which winding faces front.
                const StateAssignment* ccw = find("FrontCounterClockwise", 0);
                double cull = field->defaultValue, frontCcw = 0;
                if ((a && !constantValue(a->value, cull)) || (ccw && !constantValue(ccw->value, frontCcw))) {
                    error(
                        DiagId::InvalidStateValue, (a && !constantValue(a->value, cull) ? a : ccw)->value.loc,
                        {a ? a->name : ccw->name, "must be a constant (it decides which winding is culled)"});
                    continue;
                }
                double d3d9 = cull == 1 ? 1 : (frontCcw != 0) == (cull == 3) ? 2 : 3;
                push(RenderStateId::CullMode, numberExpr(d3d9, a ? a->loc : loc), a ? a->loc : loc);
                continue;
            }
            push(field->state, a ? a->value : numberExpr(field->defaultValue, loc), a ? a->loc : loc);
            if (kind == StateObjectKind::Blend) expandTargetBlend(*field, loc, find, push);
        }
        if (kind == StateObjectKind::DepthStencil)
            push(RenderStateId::TwoSidedStencilMode, numberExpr(1, loc), loc);
        if (kind == StateObjectKind::Blend) {
            push(RenderStateId::SeparateAlphaBlendEnable, numberExpr(1, loc), loc);
            push(RenderStateId::IndependentBlendEnable, numberExpr(1, loc), loc);
        }
    }

    // A BlendState field for render targets 1..7 (D3D10's independent blend, GL's glBlendFuncSeparatei and
    // friends): `BlendEnable[i]` is each target's own (FALSE unless set, as D3D10 has it); the factors and
    // operations are target 0's unless indexed (D3D10.0 has one set for all targets, D3D10.1 and FX11 one
    // per target); `RenderTargetWriteMask[i]` sets target i's write mask (the runtime draws into four).
    template <typename Find, typename Push>
    void expandTargetBlend(const StateObjectField& field, const SourceLoc& loc, Find& find, Push& push) {
        const std::string_view target0 = renderStateInfo(field.state).name;
        for (int index = 1; index < 8; ++index) {
            const StateAssignment* own = find(field.name, index);
            const std::optional<RenderStateId> state =
                findRenderState(std::string(target0) + std::to_string(index));
            if (field.name == "RenderTargetWriteMask" && index >= 4) {
                double mask = 0;
                if (own && !(constantValue(own->value, mask) && mask == 15))
                    error(DiagId::UnsupportedFeature, own->loc,
                          {"RenderTargetWriteMask[" + std::to_string(index) +
                           "] masks a render target the runtime never binds (it draws into four)"});
                continue;
            }
            if (!state) {  // AlphaToCoverageEnable: one for the whole blend state
                if (own)
                    error(DiagId::UnsupportedFeature, own->loc,
                          {std::string(field.name) + " takes no render-target index"});
                continue;
            }
            const StateAssignment* source = own                           ? own
                                            : field.name == "BlendEnable" ? nullptr
                                                                          : find(field.name, 0);
            if (!own && field.name == "RenderTargetWriteMask") continue;  // the state's default, 15
            const SourceLoc at = source ? source->loc : loc;
            push(*state, source ? source->value : numberExpr(field.defaultValue, at), at);
        }
    }

    void parsePassState(Pass& pass) {
        const Token& name = expectIdentifier("a state name");
        StateAssignment state;
        state.name = name.text;
        state.loc = name.loc;
        // D3D10: SetVertexShader(CompileShader(vs_4_0, VS())); SetRasterizerState(rs); ...
        if (name.text.size() > 3 && name.text.compare(0, 3, "Set") == 0 && check("(")) {
            parseSetCall(pass, name);
            return;
        }
        if (accept("[")) {
            const Token& indexToken = peek();
            Expr index = parseExpr();
            double number = 0;
            // D3D9's largest indexed state is Sampler[0..15]; the bound also keeps the cast defined.
            if (!constantValue(index, number) || !(number >= 0 && number <= 15) ||
                number != static_cast<double>(static_cast<int>(number)))
                fail(DiagId::UnexpectedToken, indexToken.loc, {"a constant index 0..15", index.str()});
            state.index = static_cast<int>(number);
            expect("]");
        }
        expect("=");
        if (check("asm")) fail(DiagId::UnsupportedFeature, peek().loc, {"asm shaders are not supported"});
        state.value = parseExpr();
        normalizeCompileShader(state.value);
        normalizeNull(state.value);
        expect(";");
        std::optional<RenderStateId> id = findRenderState(state.name);
        if (!id) {
            if (equalsIgnoreCase(state.name, "GeometryShader") &&
                state.value.kind == Expr::Kind::Identifier && state.value.text == "NULL")
                return;
            error(DiagId::UnknownState, state.loc, {state.name});
            return;
        }
        const StateInfo& info = renderStateInfo(*id);
        if (info.domain == StateDomain::Shader)
            validateShaderValue(state);
        else
            resolveStateValue(state.value, info.domain, state.name);
        pass.states.push_back(std::move(state));
    }

    // D3DX's effect compiler took `null` (any case) for `NULL`; spell it one way for what follows.
    static void normalizeNull(Expr& e) {
        if (e.kind == Expr::Kind::Identifier && equalsIgnoreCase(e.text, "NULL")) e.text = "NULL";
    }

    // CompileShader(vs_4_0, VS(args)) -> Compile expression, anywhere in `e`.
    void normalizeCompileShader(Expr& e) {
        for (Expr& arg : e.args) normalizeCompileShader(arg);
        if (e.kind != Expr::Kind::Call || e.text != "CompileShader") return;
        if (e.args.size() != 2 || e.args[0].kind != Expr::Kind::Identifier ||
            e.args[1].kind != Expr::Kind::Call) {
            error(DiagId::InvalidCompileExpression, e.loc,
                  {"expected CompileShader(profile, Function(...))"});
            return;
        }
        Expr compiled;
        compiled.kind = Expr::Kind::Compile;
        compiled.loc = e.loc;
        compiled.profile = e.args[0].text;
        compiled.text = e.args[1].text;
        compiled.args = std::move(e.args[1].args);
        e = std::move(compiled);
    }

    void validateShaderValue(StateAssignment& state) {
        Expr& v = state.value;
        if (v.kind == Expr::Kind::Compile) return;
        if (v.kind == Expr::Kind::Identifier) {
            if (v.text == "NULL") return;
            const Parameter* p = mEffect.findParameter(v.text);
            if (p && (p->type.base == BaseType::VertexShader || p->type.base == BaseType::PixelShader ||
                      p->type.base == BaseType::GeometryShader || p->type.base == BaseType::HullShader ||
                      p->type.base == BaseType::DomainShader))
                return;
            if (!p) {
                error(DiagId::UnknownIdentifier, v.loc, {v.text});
                return;
            }
        }
        if (v.kind == Expr::Kind::Number && v.number == 0) return;
        if (v.kind == Expr::Kind::Index && !v.args.empty() && v.args[0].kind == Expr::Kind::Identifier) {
            const Parameter* p = mEffect.findParameter(v.args[0].text);
            if (p && (p->type.base == BaseType::VertexShader || p->type.base == BaseType::PixelShader) &&
                !p->type.arrayDims.empty())
                return;  // an element of a shader array (EffectCompiler resolves the index)
        }
        error(DiagId::InvalidStateValue, v.loc,
              {state.name, "expected 'compile profile Function(...)', a shader variable or NULL"});
    }

    static bool isEnumDomain(StateDomain domain) {
        switch (domain) {
            case StateDomain::Bool:
            case StateDomain::Int:
            case StateDomain::Float:
            case StateDomain::Color:
            case StateDomain::Shader:
            case StateDomain::TextureRef:
                return false;
            default:
                return true;
        }
    }

    // Replaces enum names by their numbers, leaves parameter names, reports anything else.
    void resolveStateValue(Expr& e, StateDomain domain, const std::string& stateName) {
        switch (e.kind) {
            case Expr::Kind::Identifier: {
                if (isEnumDomain(domain) || domain == StateDomain::Bool) {
                    if (std::optional<double> value = findEnumValue(domain, e.text)) {
                        SourceLoc loc = e.loc;
                        e = Expr{};
                        e.kind = domain == StateDomain::Bool ? Expr::Kind::Bool : Expr::Kind::Number;
                        e.number = *value;
                        e.isInteger = true;
                        e.loc = loc;
                        return;
                    }
                }
                if (mEffect.findParameter(e.text)) return;
                if (isEnumDomain(domain) || domain == StateDomain::Bool) {
                    std::string names;
                    for (std::string_view n : enumValueNames(domain))
                        names += (names.empty() ? "" : ", ") + std::string(n);
                    error(DiagId::UnknownStateValue, e.loc, {e.text, stateName, names});
                } else {
                    error(DiagId::UnknownIdentifier, e.loc, {e.text});
                }
                return;
            }
            case Expr::Kind::Bool:
                // MonoGame's `ColorWriteEnable = true;` writes every channel, not only red (1).
                if (domain == StateDomain::ColorMask) {
                    e.kind = Expr::Kind::Number;
                    e.number = e.number != 0 ? 15 : 0;
                }
                return;
            case Expr::Kind::String:  // `ZEnable = "yes";` was kept and read as 0
                if (domain != StateDomain::TextureRef)
                    error(DiagId::InvalidStateValue, e.loc, {stateName, "expected a value, found a string"});
                return;
            case Expr::Kind::Unary:
            case Expr::Kind::Binary:
            case Expr::Kind::InitList:
                for (Expr& arg : e.args) resolveStateValue(arg, domain, stateName);
                break;
            case Expr::Kind::Ternary:
                if (e.args.size() == 3) {
                    resolveStateValue(e.args[1], domain, stateName);
                    resolveStateValue(e.args[2], domain, stateName);
                }
                break;
            default:
                break;
        }
        // RED|GREEN|BLUE -> one number
        if (e.kind == Expr::Kind::Binary && e.text == "|" && e.args.size() == 2 &&
            e.args[0].kind == Expr::Kind::Number && e.args[1].kind == Expr::Kind::Number &&
            e.args[0].isInteger && e.args[1].isInteger && std::abs(e.args[0].number) < 9e15 &&
            std::abs(e.args[1].number) < 9e15) {
            // (bounded: casting 1e30 to long long is undefined behaviour)
            double value = static_cast<double>(static_cast<long long>(e.args[0].number) |
                                               static_cast<long long>(e.args[1].number));
            SourceLoc loc = e.args[0].loc;
            e = Expr{};
            e.kind = Expr::Kind::Number;
            e.number = value;
            e.isInteger = true;
            e.loc = loc;
        }
    }

    // `{ Field = value; Field[i] = value; ... }` of a D3D10 state object, validated against its fields.
    std::vector<StateAssignment> parseObjectStateBlock(StateObjectKind kind) {
        const Token& open = advance();  // '{'
        std::vector<StateAssignment> states;
        while (!check("}")) {
            if (atEnd() || isTechniqueKeyword(peek()))
                unclosed(std::string(stateObjectTypeName(kind)).c_str(), open);
            const Token& name = expectIdentifier("a state name");
            StateAssignment state;
            state.name = name.text;
            state.loc = name.loc;
            if (accept("[")) {
                const Token& indexToken = peek();
                Expr index = parseExpr();
                double number = 0;
                if (!constantValue(index, number) || !(number >= 0 && number <= 7) ||
                    number != std::trunc(number))
                    fail(DiagId::UnexpectedToken, indexToken.loc,
                         {"a render-target index 0..7", index.str()});
                state.index = static_cast<int>(number);
                expect("]");
            }
            expect("=");
            state.value = parseExpr();
            expect(";");
            const StateObjectField* field = findStateObjectField(kind, state.name);
            if (!field) {
                error(DiagId::UnknownState, state.loc, {state.name});
                continue;
            }
            if (state.index > 0 && field->object != StateObjectKind::Blend)
                error(DiagId::UnexpectedToken, state.loc, {"a state without an index", state.name});
            state.name = std::string(field->name);
            resolveStateValue(state.value, field->domain, state.name);
            states.push_back(std::move(state));
        }
        advance();
        return states;
    }

    std::vector<StateAssignment> parseSamplerStateBlock() {
        if (!check("{")) unexpected("'{'");
        const Token& open = advance();
        std::vector<StateAssignment> states;
        while (!check("}")) {
            if (atEnd() || check("technique") || check("sampler_state")) unclosed("sampler_state", open);
            const Token& name = expectIdentifier("a sampler state name");
            StateAssignment state;
            state.name = name.text;
            state.loc = name.loc;
            if (accept("[")) {
                Expr index = parseExpr();
                double number = 0;
                if (constantValue(index, number) && number >= 0 && number <= 15)  // keeps the cast defined
                    state.index = static_cast<int>(number);
                expect("]");
            }
            expect("=");
            state.value = parseExpr();
            expect(";");
            std::optional<SamplerStateId> id = findSamplerState(state.name);
            if (!id) {
                error(DiagId::UnknownState, state.loc, {state.name});
                continue;
            }
            const StateInfo& info = samplerStateInfo(*id);
            if (info.domain == StateDomain::TextureRef) {
                Expr& v = state.value;
                if (v.kind == Expr::Kind::Identifier) v.kind = Expr::Kind::TextureRef;  // (t) and t
                if (v.kind != Expr::Kind::TextureRef) {
                    error(DiagId::InvalidStateValue, v.loc, {state.name, "expected <texture>"});
                    continue;
                }
                const Parameter* texture = mEffect.findParameter(v.text);
                if (!texture) {
                    error(DiagId::UnknownIdentifier, v.loc, {v.text});
                    continue;
                }
            } else {
                resolveStateValue(state.value, info.domain, state.name);
            }
            states.push_back(std::move(state));
        }
        advance();
        return states;
    }

    // [SECTION] Expressions

    // `inAnnotation`: a top-level '>' ends the annotation block instead of comparing.
    Expr parseExpr(bool inAnnotation = false) {
        bool saved = mNoGreater;
        mNoGreater = inAnnotation;
        Expr e = parseTernary();
        mNoGreater = saved;
        return e;
    }

    Expr parseTernary() {
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

    int binaryPrecedence(const Token& token) const {
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

    Expr parseBinary(int minPrecedence) {
        Expr left = parseUnary();
        // `1+1+1+...` loops here instead of recursing, but builds a left-deep tree as deep as the chain is
        // long, and everything that walks an Expr (its destructor included) recurses: bound the chain with
        // the nesting depth, so that a long line cannot overflow the stack later.
        int chain = 0;
        for (;;) {
            int precedence = binaryPrecedence(peek());
            if (precedence < 0 || precedence < minPrecedence) break;
            if (++chain + mDepth > kMaxDepth)
                fail(DiagId::UnsupportedFeature, peek().loc,
                     {"expression too complex (more than " + std::to_string(kMaxDepth) +
                      " nested or chained operators)"});
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

    Expr parseUnary() {
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

    bool isParameterName(const std::string& name) const { return mEffect.findParameter(name) != nullptr; }

    Expr parsePostfix(Expr e) {
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

    std::vector<Expr> parseArguments() {
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

    Expr parsePrimary() {
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
                    pieceLoc.column += 1;  // after the quote
                    e.stringPieces.push_back({e.text.size(), pieceLoc});
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
        if (token.is("<")) {  // <TextureName>
            advance();
            const Token& name = expectIdentifier("a texture name");
            expectCloseAngle();
            e.kind = Expr::Kind::TextureRef;
            e.text = name.text;
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
            e.text = token.text;
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

    std::vector<Token> mTokens;
    size_t mPos = 0;
    const std::string& mText;
    Effect& mEffect;
    detail::CountingSink& mDiag;
    std::set<std::string> mTypeNames;
    struct Refused {
        std::string name;
        std::string reason;
        SourceLoc loc;
    };
    std::optional<Refused> mRefusal;       // of the technique being parsed
    std::optional<Refused> mFirstRefused;  // the first technique left out
    int mMaxVertexCount = 0;               // the [maxvertexcount(n)] before the declaration being parsed
    std::vector<FunctionAttribute> mAttributes;  // the attributes before the declaration being parsed
    std::set<StateObjectKind> mObjectsSet;       // the state objects the pass being parsed sets
    int mDepth = 0;
    bool mNoGreater = false;
    bool mSpeculative = false;  // parseStraightBody(): errors throw without a report
};

}  // namespace

std::shared_ptr<Effect> parseEffectSource(const std::string& source, const std::string& path,
                                          const ParseOptions& options, DiagnosticSink& diagnostics) {
    detail::CountingSink counted(diagnostics);
    detail::PreprocessedSource pp;
    auto effect = std::make_shared<Effect>();
    effect->path = path;
    if (!detail::preprocessEffect(source, path, options, counted, pp)) return nullptr;
    effect->includedFiles = pp.includedFiles;
    std::vector<Token> tokens = detail::lexEffect(pp.text, path, pp.files, effect->sourceMap, counted);
    if (counted.errors() > 0) return nullptr;
    detail::spellKeywordsAsHlsl(tokens, pp.text);
    Parser parser(std::move(tokens), pp.text, *effect, counted);
    parser.parseEffect();
    if (counted.errors() > 0) return nullptr;
    detail::inlineUserFunctionCalls(*effect);
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
