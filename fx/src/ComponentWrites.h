// ComponentWrites: a write to part of a vector or matrix local (`dir.x = ...`, `c.rgb += ...`,
// `m._11 = ...`, `m._m01_m10 = ...`), as the host evaluator's expression of the whole value after it: what
// the inliner (UserFunctionInliner.cpp) binds the local to. Private to fx.
#pragma once

#include <fx/Effect.h>

#include <optional>
#include <string>
#include <vector>

namespace fx::detail {

// Marks the per-component selects writeComponents builds: (mask, new components, old value).
inline constexpr const char* kComponentSelect = "components";

// `old`, a scalar or vector of `type`, with the components `member` names (`x`, `rgb`) written from
// `value` (a scalar for one component, else its components in the member's order): a per-component
// select between the value, spread to the type, and `old`. None for a member naming no component of the
// type.
std::optional<Expr> writeComponents(const TypeDesc& type, const std::string& member, Expr old, Expr value,
                                    const SourceLoc& loc);

// The vector type of a row of the matrix type `matrix`.
TypeDesc matrixRowType(const TypeDesc& matrix);

// The rows of `old`, a matrix of `type`, to rebuild it from: those of the constructor that built it last
// where it is one (so that writing every row in turn copies none of them again), else its rows read by
// index.
std::vector<Expr> matrixRows(const TypeDesc& type, const Expr& old, const SourceLoc& loc);

// `old`, a matrix of `type`, with the elements the member `._11`, `._m01` or `._11_22` names written from
// `value`'s components in the member's order (a scalar for one element), as D3DX's preshaders wrote them:
// each row it names elements of is written as a vector's components, and the matrix rebuilt from its rows.
// None for an element outside the matrix or one named twice.
std::optional<Expr> writeMatrixElements(const TypeDesc& type, const std::string& member, const Expr& old,
                                        const Expr& value, const SourceLoc& loc);

}  // namespace fx::detail
