// ConstantFolding: the compile-time constants of effect syntax (array sizes, state indices, state-object
// fields the parser must know), folded over the effect's declarations so far. Private to fx.
#pragma once

#include <fx/Effect.h>

namespace fx::detail {

// A compile-time constant: literals, the effect's `static const` / `const` scalars declared before
// (D3D9 sizes arrays with them: `float4x3 m[MAX_MATRICES]`), casts, integer arithmetic and comparisons.
bool foldConstant(const Effect& effect, const Expr& e, double& out, int depth = 0);

}  // namespace fx::detail
