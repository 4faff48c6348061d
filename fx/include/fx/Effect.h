// Effect: the syntax tree of one D3DX9-style effect file (.fx), as the parser builds it.
//
// The tree keeps what the effect *declares* (parameters, textures, samplers, structs, functions,
// techniques, passes, annotations, states) with a SourceLoc on every node. HLSL code (struct and function
// bodies, static globals) is kept as text sliced from the preprocessed source: the pass lowering emits it
// verbatim, preceded by a #line directive, so glslang's diagnostics name the user's file and line.
//
// Nothing here knows about glslang, SPIR-V or OpenGL.
#pragma once

#include <fx/RefusedTechnique.h>
#include <fx/SourceLoc.h>
#include <fx/Types.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace fx {

// [SECTION] Expressions
// One expression type serves initializers, annotation values, state values, compile arguments and
// sampler_state bodies. The runtime's preshader evaluates them on the host.

struct Expr {
    enum class Kind {
        Number,      // 1, 1.5, 2e3; `number`, `isInteger`
        Bool,        // true / false; `number` is 0 or 1
        String,      // "a" "b" (adjacent literals concatenated); `text`, `stringPieces`
        Identifier,  // a parameter, a state enum value (CCW, Min) or NULL; `text`
        Unary,       // `text` is the operator ("-", "!", "~", "+"); args[0]
        Binary,      // `text` is the operator ("+", "*", "==", "&&", ...); args[0], args[1]
        Ternary,     // args[0] ? args[1] : args[2]
        Call,        // function or constructor: `text` is the callee ("mul", "float4"); `args`
        Member,      // args[0] . `text`  (swizzles .xyz, matrix members ._13 / ._m02, struct fields)
        Index,       // args[0] [ args[1] ]
        InitList,    // { args... }
        TextureRef,  // <Name> in `Texture = <Name>`; `text` is the name
        Compile,     // compile `profile` `text`( args... ): a shader bound to a pass
        Cast,        // (float3) args[0]; `castType`
    };

    // One piece of a (possibly concatenated) string literal: where its characters start in `text`, and
    // where the literal's first character (after the quote) stands in the source. A literal that a macro
    // wrote stands at the macro's use as a whole: its characters are in the macro's definition.
    struct StringPiece {
        size_t offset = 0;
        SourceLoc loc;
        bool fromMacro = false;
    };

    Kind kind = Kind::Number;
    SourceLoc loc;
    double number = 0.0;
    bool isInteger = false;
    std::string text;
    std::string profile;  // Compile: "vs_3_0", "ps_2_0", "vs_5_0", ...
    TypeDesc castType;    // Cast
    std::vector<Expr> args;
    std::vector<StringPiece> stringPieces;  // String

    // Source-like spelling, for messages and tests: "mul(WorldMatrix, LightView)".
    std::string str() const;
};

// [SECTION] Declarations

struct Annotation {
    TypeDesc type;
    std::string name;
    Expr value;
    SourceLoc loc;
};

// `Name = value;` or `Name[index] = value;` inside a pass or a sampler_state block.
struct StateAssignment {
    std::string name;  // as written ("CullMode", "cullmode", "ColorWriteEnable1")
    int index = -1;    // the [index], if any
    Expr value;
    SourceLoc loc;
};

// A global variable of the effect: a parameter (float, matrix, bool, ...), a texture, a sampler, a string
// such as the `float Script : STANDARDSGLOBAL` header, or a shader variable.
struct Parameter {
    std::string name;
    TypeDesc type;
    std::string semantic;                       // "WorldViewProjection", "RENDERCOLORTARGET", "" if none
    std::vector<Annotation> annotations;        // < ... >
    std::optional<Expr> initializer;            // = expr / = { ... } / = compile ...
    std::vector<StateAssignment> samplerState;  // sampler_state { ... }; empty for non-samplers
    // A D3D10 state object's block (`RasterizerState rs { CullMode = NONE; };`), its fields validated
    // against RenderStateDefs.h's FX_OBJECT_FIELD table; empty for other parameters.
    std::vector<StateAssignment> objectState;
    // A state-object array's blocks, one per element (`RasterizerState rs[2] { { ... }, { ... } };`,
    // elements not given empty: D3D10's defaults); empty for other parameters.
    std::vector<std::vector<StateAssignment>> objectStateElements;
    bool isStatic = false;  // `static`: a shader-private global, not a parameter
    bool isConst = false;
    bool isUniform = false;  // written `uniform`
    bool isShared = false;
    bool isExtern = false;
    // `: register(sN)`: the D3D9 sampler register N a pass's `MinFilter[N] = ...` reaches; -1 when the
    // compiler assigns it (the used samplers in declaration order, as fxc did).
    int samplerRegister = -1;
    SourceLoc loc;  // the name's location
    // For static globals only: the whole declaration as HLSL text from the preprocessed source.
    std::string hlslText;
    // Where hlslText starts: the user's file and line, but the column in the *preprocessed* text (glslang
    // collapses whitespace), so that `#line` plus column padding keeps glslang's columns aligned with
    // hlslText; map them back with Effect::sourceMap. The same holds for every hlslLoc below.
    SourceLoc hlslLoc;

    const Annotation* annotation(const std::string& annotationName) const;  // case-insensitive lookup
};

struct StructMember {
    TypeDesc type;
    std::string name;
    std::string semantic;       // "POSITION", "TEXCOORD0", ... ("" if none)
    std::string interpolation;  // "linear", "centroid", "nointerpolation", "noperspective", "sample", or ""
    SourceLoc loc;
};

struct StructDecl {
    std::string name;
    std::vector<StructMember> members;
    std::string hlslText;  // "struct Name { ... };" from the preprocessed source
    SourceLoc hlslLoc;     // where hlslText starts
    SourceLoc loc;         // the name's location
};

struct FunctionParam {
    enum class Direction { In, Out, InOut };
    TypeDesc type;
    std::string name;
    std::string semantic;
    std::string interpolation;
    Direction direction = Direction::In;
    bool isUniform = false;  // `uniform`: given by the compile expression's arguments
    // A geometry shader's input primitive (`triangle VSOut input[3]`: "triangle"; "" elsewhere) and output
    // stream (`inout TriangleStream<GSOut> s`: "TriangleStream", with `type` the element struct).
    std::string primitive;
    std::string stream;
    // A hull or domain shader's control points (`InputPatch<VSOut, 3> ip`: "InputPatch" and 3, with `type`
    // the element struct; "OutputPatch" likewise); "" and 0 elsewhere.
    std::string patch;
    int patchSize = 0;
    std::optional<Expr> defaultValue;
    SourceLoc loc;
};

// `[domain("tri")]` before a function: name "domain", argument "tri" (a string's text without its quotes,
// or the expression's spelling), text the whole attribute as written.
struct FunctionAttribute {
    std::string name;
    std::string argument;
    std::string text;
    SourceLoc loc;
};

struct FunctionDecl {
    std::string name;
    TypeDesc returnType;
    std::string returnSemantic;  // float4 PS(...) : COLOR  ->  "COLOR"
    std::vector<FunctionParam> params;
    int maxVertexCount = 0;  // a geometry shader's [maxvertexcount(n)]; 0 if the function has none
    std::vector<FunctionAttribute> attributes;  // every [attribute] before the function, in order
    const FunctionAttribute* attribute(const std::string& attributeName) const;  // case-insensitive lookup
    bool hasBody = true;                                                         // false for a prototype
    std::string hlslText;  // the whole definition (attributes, signature and body)
    SourceLoc hlslLoc;     // where hlslText starts
    SourceLoc loc;         // the name's location

    // A body of side-effect-free code: local declarations (scalars, vectors, matrices, arrays, structs),
    // assignments to locals and to their parts, calls of such functions (`out` and `inout` parameters
    // included), if/else, `for` and `while` loops with `break`, `continue` and `return`, and returns where
    // every path ends (an early return's rest reads as its branch's `else`; a `return` in a loop sets a
    // flag, keeps its value and leaves the loop). Such a function, called in a pass's compile arguments,
    // states or a static's initializer, is inlined there and evaluated on the host as D3DX's preshaders
    // did (fx/src/UserFunctionInliner.cpp; a loop is unrolled, so its condition must be known there).
    // Empty for any other body.
    struct Statement {
        // Loop: `value` is the condition, `then` the body, `otherwise` the step (`for`'s third part); a
        // `for`'s first part stands before it as statements of their own. Evaluate: `value` is an
        // expression whose calls write their `out` arguments (`split(c, hi, lo);`).
        enum class Kind { Declare, Assign, If, Loop, Return, Break, Continue, Evaluate };
        Kind kind = Kind::Return;
        TypeDesc type;     // Declare
        std::string name;  // Declare, Assign: the local
        // Assign: what is written: the local (an Identifier), or a part of it (`v.yz`, `w[i]`,
        // `s.colour.r`: Member and Index nodes over it).
        Expr target;
        std::string op;  // Assign: "=", "+=", "-=", "*=", "/="
        // Declare's initializer, Assign's right-hand side, Return's value, If's condition, Evaluate's
        // expression.
        Expr value;
        bool hasValue = false;                   // false for a declaration without a value and a `return;`
        std::vector<Statement> then, otherwise;  // If, Loop
    };
    std::vector<Statement> straightBody;
};

// Top-level HLSL the effect compiler passes through verbatim: typedefs, cbuffers, and anything else that
// is not a parameter, struct or function.
struct VerbatimDecl {
    std::string hlslText;
    SourceLoc hlslLoc;
};

struct Pass {
    std::string name;  // "" for an unnamed pass (then referred to by index)
    std::vector<Annotation> annotations;
    std::vector<StateAssignment> states;  // render states and VertexShader / PixelShader
    SourceLoc loc;
    // A D3D9 pass with a pixel shader alone: the compiler gives it a pass-through vertex stage and, where
    // it has no Script of its own, the script `Draw=Buffer;` (a full-screen quad; docs/fixed-function.md).
    bool drawsScreenQuad = false;

    const Annotation* annotation(const std::string& annotationName) const;
};

struct Technique {
    std::string name;
    std::string group;   // the D3D11 `fxgroup` holding it; "" if none
    bool d3d10 = false;  // technique10 / technique11: its passes start from D3D10's state defaults
    std::vector<Annotation> annotations;
    std::vector<Pass> passes;
    SourceLoc loc;

    const Annotation* annotation(const std::string& annotationName) const;
};

// Maps a position in the preprocessed text back to the user's column. glslang's preprocessor keeps
// lines (and emits #line for includes) but collapses whitespace inside a line, so the columns it reports
// are not the user's; the lexer records, per token, where it really stood.
class SourceMap {
public:
    // Records that the token at (file, line, preprocessedColumn) starts at `column` in the user's file;
    // `fromMacro`: the token is a macro's expansion, which stands as a whole at the macro's name there.
    void add(const std::string& file, int line, int preprocessedColumn, int column, bool fromMacro = false);
    // The user's location for a location in preprocessed text; the column is mapped to the nearest
    // recorded token at or before it on that line (unchanged if the line has no record).
    SourceLoc map(const SourceLoc& preprocessed) const;

    // A macro used in the user's file: tokens of its expansion stand at `use` (its name), and diagnostics
    // there carry a note at `definition` (the name in its #define).
    struct MacroExpansion {
        std::string name;
        SourceLoc use;
        SourceLoc definition;
    };
    void addExpansion(MacroExpansion expansion);
    // The expansion whose use is exactly at `loc`, if any.
    const MacroExpansion* expansionAt(const SourceLoc& loc) const;

private:
    struct TokenColumn {
        int preprocessed;
        int user;
        bool fromMacro;
    };
    // (file, line) -> its tokens, sorted by preprocessed column
    std::map<std::pair<std::string, int>, std::vector<TokenColumn>> mColumns;
    std::map<std::tuple<std::string, int, int>, MacroExpansion>
        mExpansions;  // by (file, line, column) of the use
};

// Where a top-level declaration stands among the others: HLSL needs them emitted in source order.
struct DeclRef {
    enum class Kind { Parameter, Struct, Function, Verbatim };
    Kind kind;
    size_t index;  // into Effect::parameters / structs / functions / verbatim
};

struct Effect {
    std::string path;  // the main file
    std::vector<Parameter> parameters;
    std::vector<StructDecl> structs;
    std::vector<FunctionDecl> functions;
    std::vector<VerbatimDecl> verbatim;
    std::vector<Technique> techniques;
    std::vector<RefusedTechnique> refusedTechniques;  // left out by the parser, each with its warning
    std::vector<DeclRef> order;  // parameters, structs, functions and verbatim declarations in source order
    std::vector<std::string> includedFiles;  // every file the preprocessor opened, main file first
    SourceMap sourceMap;

    const Parameter* findParameter(const std::string& name) const;  // case-sensitive, as HLSL
    const StructDecl* findStruct(const std::string& name) const;
    // By name; a technique in an fxgroup also by "group.name".
    const Technique* findTechnique(const std::string& name) const;
    // All overloads of a function, in source order.
    std::vector<const FunctionDecl*> findFunctions(const std::string& name) const;
};

}  // namespace fx
