// PassLowering: one pass's compile expression -> one HLSL unit that glslang's HLSL front end accepts.
//
// The effect's declarations are emitted verbatim (each behind `#line`, so glslang names the user's file,
// line and column); effect-only syntax (textures, sampler_state, techniques, strings) is dropped;
// parameters become plain globals of the `$Global` block. The user's entry point is never rewritten:
// a generated wrapper `fx_main` takes D3D9-semantic inputs at fixed locations, rebuilds the user's
// structs, calls the user's function with the compile expression's uniform arguments, and writes the
// results to SV_Position / fixed varying locations / SV_Target n, so that stages link by semantic as on
// D3D9. A geometry shader's wrapper rebuilds its input array the same way and hands the user's function
// its output stream; the stream's element struct is redeclared in that unit with the varying locations
// of its members' semantics. A hull shader's wrapper rebuilds its input patch likewise and writes its
// control points and patch constants as float4 varyings (patch constants through a generated patch-constant
// function around the user's); a domain shader's wrapper reads them back into the user's structs.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/Effect.h>
#include <fx/VertexStreams.h>

#include "HlslSpelling.h"
#include "SemanticTables.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fx {

// The generated entry point's name in every unit.
inline constexpr const char* kWrapperEntryPoint = "fx_main";
// The #line file name of generated code: errors there are reported at the pass's compile expression.
inline constexpr const char* kGeneratedFile = "<fx-generated>";

struct LoweredStage {
    ShaderStage stage = ShaderStage::Vertex;
    std::string entryPoint;  // the user's function
    std::string profile;
    std::string hlsl;
    SourceLoc compileLoc;                    // the compile expression: where generated-code errors go
    std::vector<std::string> depthSamplers;  // effect samplers sampled with depth comparison
    // A geometry shader's outputs by varying location, as its output struct declares them, or a vertex
    // shader's (float4 each): the pixel shader after it declares its inputs with these types (GL links a
    // location's types exactly), and reads 0 for an input that is not among them.
    std::map<int, TypeDesc> varyingOutputs;
    int patchVertices = 0;  // a hull shader's control points per input patch (its InputPatch<T, n>)
    // A geometry shader's input primitive, as the pass's draws must give it.
    CompiledPass::DrawPrimitive primitive = CompiledPass::DrawPrimitive::Triangles;
    // A geometry shader's output stream type: "PointStream", "LineStream" or "TriangleStream".
    std::string streamType;
    // StageStreamOut::captureOnly: the varying location its POSITION output got (-1: none).
    int positionVarying = -1;
};

// What stream output asks of a stage's lowering (docs/d3d10.md, "Stream output").
struct StageStreamOut {
    // A stage whose output is captured and not rasterized (a NULL pixel shader): a geometry shader's
    // POSITION output stays a varying that transform feedback can capture, not only gl_Position, and its
    // integer outputs need no 'nointerpolation'; a vertex shader's outputs keep their declared types
    // instead of float4.
    bool captureOnly = false;
    // A vertex shader of a pass that draws a capture (DrawAuto): the capture's elements' canonical
    // semantics, in order; an input of one of them reads attribute k (its index here), any other a constant.
    std::optional<std::vector<std::string>> capturedInputs;
};

// An argument of a compile expression bound to a `uniform` entry-point parameter, as lowering finds it:
// the effect compiler turns `expr` into the CompileArgument's preshader program.
struct LoweredArgument {
    Expr expr;
    TypeDesc type;
    std::string memberName;  // "fx_arg0", ...
};

// Lowers the shader of one stage of a pass. `compile` is the state's Compile expression. Compile
// arguments that must be evaluated per draw are appended to `arguments` (named fx_argN, N = their index
// there). A pixel shader takes `previousOutputs`, the varyingOutputs of the stage before it (geometry or
// vertex shader) where known; a domain shader takes the pass's `hull` shader (whose partitioning and output
// topology GL's tessellation evaluation stage declares); `streamOut`, what the pass's stream output needs.
// Returns nullopt after reporting an error.
std::optional<LoweredStage> lowerStage(const Effect& effect, const Expr& compile, ShaderStage stage,
                                       std::vector<LoweredArgument>& arguments, DiagnosticSink& diagnostics,
                                       const std::map<int, TypeDesc>* previousOutputs = nullptr,
                                       const FunctionDecl* hull = nullptr,
                                       const StageStreamOut* streamOut = nullptr);

// The effect's declarations a unit needs, in the effect's order, each behind `#line` (see above): the
// functions in `reached`, every static, plain global and sampler, and the D3D10 objects that `wrapper` or
// the reached code names. `streamStruct` (a geometry shader's output element) is declared as
// `streamStructText` instead of as written.
struct EffectDeclarations {
    std::string hlsl;
    // The statics whose initializers call the effect's functions (glslang's "Recursion detected"): the
    // unit's entry point assigns them before anything else runs.
    std::string staticAssignments;
    std::vector<std::string> depthSamplers;  // the depth-compare samplers the unit declares
};
// `boundEntry`, where given, is emitted instead of the effect's function of the same definition
// (`boundEntry->hlslLoc`), after every declaration: an entry point with its sampler and texture compile
// arguments bound.
EffectDeclarations emitEffectDeclarations(const Effect& effect, const std::set<std::string>& reached,
                                          const std::string& wrapper, const std::string& streamStruct = "",
                                          const std::string& streamStructText = "",
                                          const FunctionDecl* boundEntry = nullptr);
// The effect's functions that `entry` calls, directly or not, and those static initializers call.
std::set<std::string> reachableFunctions(const Effect& effect, const std::string& entry);

// Samplers of the effect whose texture is a depth target (RENDERDEPTHSTENCILTARGET or a depth Format):
// they sample with comparison, as NVIDIA's D3D9 hardware shadow maps did.
bool isDepthCompareSampler(const Effect& effect, const Parameter& sampler);
// The texture parameter a sampler's sampler_state names (Texture = <t>), if any.
const Parameter* samplerTexture(const Effect& effect, const Parameter& sampler);

}  // namespace fx
