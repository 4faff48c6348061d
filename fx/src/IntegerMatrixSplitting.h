// IntegerMatrixSplitting: integer and bool matrices (`uint2x4`, `int2x3`, `bool2x3`) in glslang's syntax
// tree, made into what its SPIR-V back end compiles. HLSL applies every operator to a matrix element by
// element; glslang's back end splits such an operation into one per vector only for float matrices (an
// integer one crashes it), and its front end types a comparison of two matrices (`m == 0`, `m >= n`) as
// one bool of the whole, where HLSL compares element by element into a bool matrix. This rewrite, run on
// the linked tree before SPIR-V is written, makes each element-wise operation whose operand or result is
// an integer or bool matrix, and each comparison of matrices, one operation per row (glslang's matrix
// "columns" are HLSL's rows) and a matrix built from the rows:
//   m + n, m << p, m & 0xff, -m, ~m, !b, m == 0, m >= n     -> int2x3(m[0] + n[0], m[1] + n[1])
//   m += n, m &= 3 (compound assignments)                   -> (m[0] += n[0], m[1] += n[1], m)
//   b ? m : n, with b a bool matrix                         -> per row, a vector select
//   (uint2x3)m, abs(m), min(m, n), max, clamp, countbits,
//   reversebits, firstbithigh, firstbitlow, asuint, asint   -> per row
//   any(b), all(b)                                          -> any(b[0]) || any(b[1])
//   int2x3 from scalars, from one scalar (every element), from a larger matrix -> built from row vectors
// A comparison whose bool matrix meets a use that takes one bool (`if (m == n)`, `bool b = m == n;`)
// reads its first element, as fxc truncated it. What stays an integer matrix afterwards (variables,
// rows, elements, whole assignments, arguments) SPIR-V can hold once IntegerMatrixArrays has made its
// type an array of rows. mul(), transpose() and determinant() of an integer matrix, and ++/-- of one,
// are errors at the operation. Private to fx; built without RTTI like every file of glslang's tree.
#pragma once

#include "HlslToSpirv.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <vector>

namespace fx::detail {

// Rewrites the tree of `intermediate` (see above); `unusedSymbolId` is above every symbol id of the tree
// (for the temporaries). Returns an error for each operation left as it was.
std::vector<HlslMessage> splitIntegerMatrixOperations(glslang::TIntermediate& intermediate,
                                                      long long unusedSymbolId);

}  // namespace fx::detail
