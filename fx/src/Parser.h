// Parser: the recursive-descent parser of effect syntax (see EffectParser.cpp's feature list). One class,
// its grammar defined in the files named after its parts:
//   EffectParser.cpp       tokens, errors and recovery, types; parseEffectSource/parseEffectFile
//   ParseDeclarations.cpp  top-level declarations (parameters, structs, typedefs, cbuffers), annotations
//   ParseFunctions.cpp     functions, and the loop-free bodies host expressions may call
//   ParseTechniques.cpp    techniques, passes, state blocks (their meaning: StateAssignments.h)
//   ParseExpressions.cpp   expressions
// Private to fx.
#pragma once

#include <fx/EffectParser.h>
#include <fx/RenderStates.h>

#include "HlslLegalization.h"
#include "Lexer.h"
#include "Preprocessor.h"
#include "StateAssignments.h"
#include "TechniqueSupport.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fx::detail {

constexpr size_t kMaxErrors = 20;
constexpr int kMaxDepth = 256;

struct SyntaxError {};    // thrown after reporting; the top level recovers at the next declaration
struct TooManyErrors {};  // thrown when kMaxErrors is reached

class Parser {
public:
    Parser(std::vector<Token> tokens, const std::string& text, Effect& effect, CountingSink& diagnostics)
        : mTokens(std::move(tokens)), mText(text), mEffect(effect), mDiag(diagnostics) {}

    void parseEffect();

private:
    // fxc's D3D10 and later profiles read `sampler` as `SamplerState`: a `sampler` that the code passes to a
    // texture object's Sample or Gather methods (MonoGame's `sampler NameSampler : register(s0);` beside
    // `Texture2D Name`) is one, and glslang's D3D9 mode would take it for a combined sampler that
    // SPIRV-Cross cannot pair with the texture. A sampler also read with tex2D() and its kin stays D3D9's,
    // of the kind its intrinsics read: D3D9's untyped `sampler` read by texCUBE or tex3D is a cube or volume
    // sampler (D3D9 took the dimension from the instruction; glslang would read it as a 2D sampler), and so
    // is its untyped texture (ResourceDescriptors.cpp).
    void retypeSamplersOfTextureObjects();
    // A struct with both an SV_Position and a POSITION member (Frank Luna's `float4 PosH : SV_POSITION;
    // float3 PosW : POSITION;`): under D3D10 the second is user data, which the vertex shader writes and
    // the pixel shader reads like a TEXCOORD. Its semantic becomes a free name that every stage's wrapper
    // takes as a varying; a POSITION alone stays the position (D3D9's, and fxc's legacy mapping). A
    // vertex shader's input struct and a geometry shader's stream element keep their POSITION.
    void positionBesideSvPosition();

    // [SECTION] Tokens

    const Token& peek(size_t ahead = 0) const;
    const Token& advance();
    bool atEnd() const { return peek().kind == Token::Kind::End; }
    bool check(const char* spelling) const { return peek().is(spelling); }
    bool accept(const char* spelling);
    static std::string describe(const Token& token);

    [[noreturn]] void fail(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args);
    void error(DiagId id, const SourceLoc& loc, const std::vector<std::string>& args);
    // Reports a malformed ConstructGSWithSO(shader, "declaration") in `e` (a variable's initializer or a
    // pass's shader value); anything else passes.
    void checkStreamOutput(const Expr& e);
    [[noreturn]] void unexpected(const std::string& expected);
    // The token, consumed. A ';' missing before a new line is reported after the line's last token
    // (MissingSemicolon) and taken as there: nothing is consumed, nothing thrown.
    const Token& expect(const char* spelling);
    const Token& expectIdentifier(const char* what);
    // '>' closing an annotation or template; splits ">=" and ">>" so the rest is seen next.
    void expectCloseAngle();
    // A block's closing '}', naming the opener when the file ends or another block starts first.
    void expectClose(const char* opener, const Token& openToken);
    [[noreturn]] void unclosed(const char* opener, const Token& openToken);

    struct DepthGuard {
        Parser& parser;
        explicit DepthGuard(Parser& p) : parser(p) {
            if (++parser.mDepth > kMaxDepth) {
                --parser.mDepth;
                parser.fail(DiagId::NestingTooDeep, parser.peek().loc, {std::to_string(kMaxDepth)});
            }
        }
        ~DepthGuard() { --parser.mDepth; }
    };

    // Skips to the end of the declaration that started at `start`: after a ';' at brace depth 0, or after
    // the '}' (and an optional ';') that closes its outermost block.
    void synchronize(size_t start);

    std::string sliceText(size_t firstToken, size_t lastToken) const;
    SourceLoc sliceLoc(size_t firstToken) const;

    // [SECTION] Types

    bool isTypeName(const Token& token) const;
    static bool isTemplatedObject(const std::string& name);

    TypeDesc parseType();
    // The D3D10 resources that GL holds: array and multisample textures, buffer textures and storage blocks.
    static std::optional<BaseType> supportedResource(const std::string& name);
    // `<float4, 4>`: the text between the angle brackets as written, consumed.
    std::string angleText();
    void skipAngles();
    int parseDimension();
    // [N][M]... after a name
    void parseArrayDims(TypeDesc& type);
    // ": SEMANTIC", skipping ": register(...)" and ": packoffset(...)".
    // `samplerRegister`: where a `register(sN)` among them names N.
    std::string parseSemantics(int* samplerRegister = nullptr);
    void skipBalanced(const char* open, const char* close);

    // [SECTION] Top level

    void parseTopLevel();

    void parseTypedef();

    // `cbuffer Name : register(b0) { float4x4 World : WORLD; ... };`: its members are effect parameters
    // like any global (semantics, annotations, initializers), bound by semantic; GL gets them in the
    // stage's one uniform block, as D3D9's globals.
    void parseConstantBuffer();

    void addVerbatim(size_t first, size_t last);

    void parseStruct();

    struct Storage {
        bool isStatic = false, isConst = false, isUniform = false, isShared = false, isExtern = false;
        bool rowMajor = false;
    };

    void parseDeclaration(bool inBuffer = false);

    void parseFunction(size_t first, const TypeDesc& returnType, const Token& name);

    // The statements of tokens [begin, end) if they are side-effect-free code (FunctionDecl::straightBody),
    // else nothing. Tried without reporting: any other body is HLSL's business, not the effect parser's.
    std::vector<FunctionDecl::Statement> parseStraightBody(size_t begin, size_t end,
                                                           const TypeDesc& returnType);
    // fxc refuses annotations on a function's local variables; glslang's HLSL front end drops them.
    void rejectLocalAnnotations(size_t begin, size_t end);

    static bool isAssignment(const Token& t);

    // One statement (a block's statements, a declaration's declarators) appended to `out`; throws
    // SyntaxError on anything else (a `switch`, a `do` loop, a `for` without a condition, ...).
    void parseStraightStatement(std::vector<FunctionDecl::Statement>& out);
    // `x = e`, `x.yz += e`, `w[i].y *= e`, `i++`, `--i` (no ';'); false, consuming nothing, if the tokens
    // are none of them.
    bool parseStraightAssignment(FunctionDecl::Statement& statement);
    // Where `name(.member | [index])*` starting at token `at` ends.
    size_t targetEnd(size_t at) const;
    // That target as an expression (Identifier, Member and Index nodes); `local` its name.
    Expr parseAssignmentTarget(std::string& local);
    static void lowerReturnsInLoops(std::vector<FunctionDecl::Statement>& body, const TypeDesc& returnType);
    // `for (init; condition; step) body` and `while (condition) body`, the keyword read.
    void parseStraightLoop(bool isFor, std::vector<FunctionDecl::Statement>& out);
    static bool containsReturn(const std::vector<FunctionDecl::Statement>& statements);
    static bool endsInReturns(std::vector<FunctionDecl::Statement>& statements);

    // [SECTION] Annotations

    std::vector<Annotation> parseAnnotations();

    // [SECTION] Techniques and passes

    static bool isTechniqueKeyword(const Token& token);

    // `fxgroup Name { technique11 A { ... } ... }` (D3D11): its techniques keep their names and are also
    // found as "Name.A".
    void parseGroup();

    void parseTechnique(const std::string& group);

    Pass parsePass(bool d3d10);

    // Set*Shader(...) and Set*State(...) in a D3D10 pass.
    void parseSetCall(Pass& pass, const Token& name);

    void parsePassState(Pass& pass);

    // `{ Field = value; Field[i] = value; ... }` of a D3D10 state object, validated against its fields.
    std::vector<StateAssignment> parseObjectStateBlock(StateObjectKind kind);
    // `{ { ... }, { ... } }`: a block per element of the state-object array `parameter`.
    std::vector<std::vector<StateAssignment>> parseObjectStateArray(StateObjectKind kind,
                                                                    const Parameter& parameter);

    // `sampler`: the declaration the block belongs to (named in a warning).
    std::vector<StateAssignment> parseSamplerStateBlock(const Parameter& sampler);

    // [SECTION] Expressions

    // `inAnnotation`: a top-level '>' ends the annotation block instead of comparing.
    Expr parseExpr(bool inAnnotation = false);

    Expr parseTernary();

    int binaryPrecedence(const Token& token) const;

    Expr parseBinary(int minPrecedence);

    Expr parseUnary();

    bool isParameterName(const std::string& name) const { return mEffect.findParameter(name) != nullptr; }

    Expr parsePostfix(Expr e);

    std::vector<Expr> parseArguments();

    Expr parsePrimary();

    std::vector<Token> mTokens;
    size_t mPos = 0;
    const std::string& mText;
    Effect& mEffect;
    CountingSink& mDiag;
    std::set<std::string> mTypeNames;
    std::vector<FunctionTokenRange> mFunctionRanges;  // every function with a body, for legalizeFunctions
    TechniqueRefusals mRefusals;
    int mMaxVertexCount = 0;  // the [maxvertexcount(n)] before the declaration being parsed
    std::vector<FunctionAttribute> mAttributes;  // the attributes before the declaration being parsed
    std::set<StateObjectKind> mObjectsSet;       // the state objects the pass being parsed sets
    int mDepth = 0;
    bool mNoGreater = false;
    bool mSpeculative = false;  // parseStraightBody(): errors throw without a report
    int mStraightLoops = 0;     // parseStraightStatement(): the loops around it (`break` needs one)
    StateAssignments mStates{mEffect, [this](DiagId id, const SourceLoc& loc,
                                             const std::vector<std::string>& args) { error(id, loc, args); }};
};

}  // namespace fx::detail
