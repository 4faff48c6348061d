// UserFunctionInliner: D3DX evaluated the parts of a pass that depend only on uniform parameters and
// literals on the host (its "preshader"), the effect's own functions included:
// `VertexShader = compile vs_2_0 VS(gain(Brightness, 1.5));`, `AlphaRef = threshold(Level);`. This stage
// rewrites such calls of straight-line user functions (FunctionDecl::straightBody) into plain expressions
// before the compiler and the host evaluator (Preshader.cpp) see them. Private to fx.
#pragma once

#include <fx/Effect.h>

namespace fx::detail {

// Inlines user-function calls in every pass state (compile arguments included) and every shader-variable
// initializer. Calls of functions that are not straight-line code stay as they are: the evaluator then
// reports them where they stand.
void inlineUserFunctionCalls(Effect& effect);

}  // namespace fx::detail
