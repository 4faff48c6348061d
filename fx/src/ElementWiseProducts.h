// ElementWiseProducts: HLSL's `*` multiplies two matrices element by element (`m * n`, `m *= n`), but
// glslang's HLSL front end types it as GLSL does, as a matrix product: the same node (EOpMatrixTimesMatrix)
// that mul(n, m) gives, so `m * n` compiled to a product without a word. The two are told apart by where
// the node stands: glslang places the product of a `*` or `*=` at that operator, and mul()'s at the call.
// This rewrite, run on the linked tree before the integer matrices are split (IntegerMatrixSplitting.h),
// makes each product that stands at a `*` or `*=` of the unit's text element-wise (EOpMul, EOpMulAssign).
// A `*` that glslang read as a product of matrices of different shapes, or of a vector and a matrix, is an
// error at the operator: fxc multiplied them element by element after truncating one (X3206), which this
// rewrite does not do. Private to fx; built without RTTI like every file of glslang's tree.
#pragma once

#include "HlslToSpirv.h"
#include "Lexer.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <string>
#include <tuple>
#include <vector>

namespace fx::detail {

// A place in the unit as glslang's source locations give it: the file of the unit's `#line`, the line that
// `#line` numbers, and the column in the unit's own line. A token's and a node's places compare equal
// where glslang built the node at the token.
using SourcePlace = std::tuple<std::string, int, int>;
SourcePlace placeOf(const Token& token);
SourcePlace placeOf(const glslang::TSourceLoc& loc);

// Whether a product node stands between its operands, as a `*` does; mul(a, b) is built with its operands
// swapped, so one of them stands on the far side of the call's place. This keeps a mul() that happens to
// share a `*`'s place (a function's copies, generated code behind its own #line) a product.
bool standsBetweenItsOperands(const glslang::TIntermBinary& node);

// The error at a `*` that glslang reads as a product of a `left` and a `right` of different shapes, or of a
// vector and a matrix.
std::string elementWiseProductOfShapesMessage(const glslang::TType& left, const glslang::TType& right);

// Rewrites the tree of `intermediate` (see above), whose text `tokens` are (lexHlslUnit). Returns an error
// for each `*` left a product.
std::vector<HlslMessage> makeStarProductsElementWise(glslang::TIntermediate& intermediate,
                                                     const std::vector<Token>& tokens);

}  // namespace fx::detail
