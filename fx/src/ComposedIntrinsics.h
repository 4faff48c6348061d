// ComposedIntrinsics: the intrinsics that D3DX's preshaders ran as a sequence of their instructions,
// written with those the host evaluator has (HLSL's definitions), for the inliner
// (UserFunctionInliner.cpp). Private to fx.
#pragma once

#include <fx/Effect.h>

#include <string>
#include <vector>

namespace fx::detail {

// An expression node of `kind` at `loc`, the inliner's and the composed intrinsics' one way to build one.
Expr exprNode(Expr::Kind kind, const SourceLoc& loc, std::string text, std::vector<Expr> args);

// Rewrites a call of ldexp, rcp, mad, sinh, cosh, tanh, reflect, faceforward, any, all or lit into an
// expression of the intrinsics the host evaluates; any other call stays as it is.
void expandComposedIntrinsic(Expr& e);

}  // namespace fx::detail
