// HlslLegalization: fxc's HLSL made glslang's, before glslang reads it. fxc (and D3DX's effect compiler,
// in its backward-compatibility mode) accepted constructs that glslang's HLSL front end refuses; each is
// rewritten here, on the lexer's tokens of each function, into HLSL that means the same:
//   - `unsigned int` and `unsigned` alone                      -> `uint`
//   - a vector cast to an array, `(float[4])v`, `(int[4])v`    -> a call of a helper returning the array
//   - `float4 v[2] = { 8 scalars };` (a local)                 -> `{ float4(...), float4(...) }`
//   - the l-value constructor `float4(a, b) = e;`              -> `fx_assign_float4(a, b, e);` (out params)
//   - a shader function writing a uniform parameter G          -> every function works on a static copy
//                                                                 initialized from G (each shader its own)
//   - `T.Sample(S, uv, offset)`, the offset not constant        -> `T.Sample(S, fx_offset_uv_T(uv, offset))`
//     (SampleLevel, SampleBias, SampleGrad, SampleCmp, SampleCmpLevelZero alike; `T.Load(location,
//     offset)` -> `T.Load(fx_offset_texel_int3_int2(location, offset))`)
//   - `T.Length`, a texture's or buffer's size                 -> `fx_length_T()` (GetDimensions)
//   - HLSL keywords used as names (`line`, `point`, `linear`)  -> `fx_line`, ...
//   - a `for` variable read after its loop                     -> declared before the loop
//   - a vector passed to a scalar parameter of the effect's    -> `F(v.x)`, with fxc's warning X3206
//     own function, `F(v)`                                        (reported to `diagnostics`)
// The helpers the rewrites call are added to the effect as verbatim declarations. fxc gave no warning
// for any of these but the truncation (docs/legalization.md); the rewrites change no column before the first
// one on a line, so glslang's later messages keep pointing at the user's text. Private to fx.
#pragma once

#include "Lexer.h"

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <functional>
#include <string>
#include <vector>

namespace fx::detail {

// Where a function's definition lies in the lexer's tokens: FunctionDecl::hlslText is the text of
// tokens first..last.
struct FunctionTokenRange {
    size_t function = 0;  // into Effect::functions
    size_t first = 0;
    size_t last = 0;
};

// Rewrites every function of `ranges` (see above) in effect.functions[].hlslText, which must still be the
// text of its tokens in `text`, and adds the declarations the rewritten functions need to the effect.
// `isTypeName` says whether a token names a type (scalar, vector, matrix, object, struct or typedef).
void legalizeFunctions(const std::vector<Token>& tokens, const std::string& text,
                       const std::vector<FunctionTokenRange>& ranges,
                       const std::function<bool(const Token&)>& isTypeName, Effect& effect,
                       DiagnosticSink& diagnostics);

}  // namespace fx::detail
