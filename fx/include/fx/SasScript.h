// SasScript: the FX Composer / NVIDIA SAS script language of `string Script = "...";` annotations on the
// STANDARDSGLOBAL parameter, on techniques and on passes. A script is a list of `Command=Value;` pairs;
// command names and enum values are case-insensitive ("Draw=geometry" and "Draw=Geometry").
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Value.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

struct Expr;  // fx/Effect.h: the annotation a script is parsed from

// The colour targets a script binds: RenderColorTarget0..3, D3D9's simultaneous render targets.
inline constexpr int kScriptColorTargets = 4;

struct ScriptCommand {
    enum class Kind {
        Technique,                 // STANDARDSGLOBAL: Technique=Name or Technique=Param?A:B
        Pass,                      // Pass=Name
        RenderColorTarget,         // RenderColorTarget0..3=Texture (empty = the frame's colour target)
        RenderDepthStencilTarget,  // RenderDepthStencilTarget=Texture (empty = the frame's depth target)
        ClearSetColor,             // ClearSetColor=float4Param
        ClearSetDepth,             // ClearSetDepth=floatParam
        ClearSetStencil,           // ClearSetStencil=intParam
        Clear,                     // Clear=Color|Depth|Stencil|SV_TARGETn
        Draw,                      // Draw=Geometry|Buffer
        RenderPort,                // RenderPort=light0 (empty = the camera), RenderPort=light0.cascade2
        LoopByCount,               // LoopByCount=intParam (or a literal count)
        LoopGetIndex,              // LoopGetIndex=intParam
        LoopEnd,                   // LoopEnd=
        ScriptExternal,            // ScriptExternal=...: accepted, reported as ignored
        ScriptOrder,               // SAS header commands, kept for completeness
        ScriptClass,
        ScriptOutput,
        ScriptSignature,
        // Dispatch=x,y,z: a compute pass's thread groups, each a number or a parameter (one parameter may
        // hold all: Dispatch=Groups with `uint3 Groups`); missing counts are 1.
        Dispatch,
    };
    enum class ClearWhat { Color, Depth, Stencil };
    enum class DrawWhat { Geometry, Buffer };

    Kind kind;
    int index = 0;  // RenderColorTarget0..3
    // Pass=: the index, in its technique's passes, of the pass the name matches (scriptNameMatches), which
    // the compiler resolves; the runtime never looks a pass up by name. -1 in a script that names none.
    int pass = -1;
    std::string value;  // the text after '=', trimmed ("" if empty); RenderPort: the light's name only
    int cascade =
        -1;         // RenderPort=light0.cascadeK: K (a sub-view of the light, runtime/CascadedShadowMaps.h)
    SourceLoc loc;  // where the command's name stands in the user's file

    // Technique=Cond?A:B: a bool parameter Cond picks A or B. When Cond is not a parameter (FX Composer's
    // `Technique=Technique?Simple:Simple10:Textured:Textured10`), the names after '?' are alternatives
    // and the first one the effect has runs.
    std::string selectorCondition;
    std::string selectorTrue;                       // the first alternative
    std::string selectorFalse;                      // the second alternative ("" if there is one)
    std::vector<std::string> selectorAlternatives;  // every name after '?', in order
    ClearWhat clear = ClearWhat::Color;             // Clear
    // Clear=SV_TARGETn (3ds Max's scripts name the target): colour target n alone, below
    // kScriptColorTargets; -1: every bound one.
    int clearTarget = -1;
    DrawWhat draw = DrawWhat::Geometry;  // Draw

    // The operands, resolved by the compiler against the compiled effect (fx/CompiledEffect.h), so that
    // the runtime looks up no name and parses no literal, at load or per frame. -1 where there is none.
    // RenderColorTarget, RenderDepthStencilTarget, ClearSet*, LoopByCount, LoopGetIndex: the
    // CompiledEffect::parameters index of the parameter `value` names.
    int parameter = -1;
    // ClearSet*, LoopByCount naming no parameter: the literal ("0.5" a scalar, "1,0,0,1" a vector).
    std::optional<Value> literal;
    // RenderPort=lightN: the CompiledEffect::lights index of the light (-1: the camera).
    int light = -1;
    // Dispatch=x,y,z: each term in order, a parameter (its index) or a count (-1 where it is neither;
    // the compiler reported it).
    struct DispatchTerm {
        int parameter = -1;
        float count = -1.0f;
    };
    std::vector<DispatchTerm> dispatch;
    // Technique= (STANDARDSGLOBAL): CompiledEffect::techniques indices. `technique` runs when the
    // selector's condition is true or the command has none (the name, or the first alternative the
    // effect has), `techniqueIfFalse` when the condition parameter `selectorParameter` is false. -1: a
    // name the effect lacks (its first technique runs).
    int technique = -1;
    int techniqueIfFalse = -1;
    int selectorParameter = -1;
};

// Parses the value of a Script annotation. `script` is the annotation's string expression, whose string
// pieces give each command's source location. Unknown commands and bad values are reported; the commands
// that parsed are returned.
std::vector<ScriptCommand> parseSasScript(const Expr& script, DiagnosticSink& diagnostics);

// Same, from plain text starting at `loc` (tests, the CLI).
std::vector<ScriptCommand> parseSasScript(const std::string& text, const SourceLoc& loc,
                                          DiagnosticSink& diagnostics);

std::string_view scriptCommandName(ScriptCommand::Kind kind);

// Whether the name a script writes (`Pass=p0`) names the declaration `declared` (`pass P0`): case-blind, as
// FX Composer and D3DX matched them. The compiler asks it once per Pass= and records the index
// (ScriptCommand::pass); the application's pass handle by name (EffectTechnique::pass) asks it too.
bool scriptNameMatches(std::string_view written, std::string_view declared);

}  // namespace fx
