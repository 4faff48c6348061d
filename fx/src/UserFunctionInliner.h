// UserFunctionInliner: D3DX evaluated the parts of a pass that depend only on uniform parameters and
// literals on the host (its "preshader"), the effect's own functions included:
// `VertexShader = compile vs_2_0 VS(gain(Brightness, 1.5));`, `AlphaRef = threshold(Level);`,
// `static float4x4 BiasXf = make_bias_mat(Bias);`. This stage rewrites such calls of side-effect-free
// functions (FunctionDecl::straightBody: locals of any type, arrays and structs included, writes to their
// parts, if/else, loops whose condition folds to a constant at every iteration, unrolled, returns anywhere,
// calls whose `out` and `inout` arguments are written back) into plain expressions, and names of statics
// into their initializers, before the compiler and the host evaluator (Preshader.cpp) see them. Private to
// fx.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

namespace fx::detail {

// Inlines user-function calls in every pass state (compile arguments included), every shader-variable
// initializer and every numeric parameter's initializer; in pass states and shader variables, a static
// computed from other parameters reads as its initializer, so that the runtime recomputes it when one of
// them changes. A loop the host cannot unroll (no count known when the effect is compiled, or more than
// fxc's 1024 iterations) is an error at the host expression's call (HostLoopUnbounded,
// HostLoopIterationLimit); calls of other functions it cannot rewrite stay as they are, and the evaluator
// reports them where they stand.
void inlineUserFunctionCalls(Effect& effect, DiagnosticSink& diagnostics);

}  // namespace fx::detail
