// MatrixSwizzles: swizzles of several matrix elements (`m._11_22`, `m._m00_m11`) in glslang's syntax tree,
// made what its SPIR-V back end compiles. glslang's HLSL front end keeps such a swizzle as a matrix
// swizzle node (a single element, or the elements of one of its vectors, become ordinary indexing there),
// which its SPIR-V back end does not compile: it logs "Missing functionality: matrix swizzle" and writes an
// element index in the swizzle's place, a constant, and it crashes where one is written through a vector
// swizzle or an argument (a known glslang defect). Each swizzle is rewritten into single elements, each
// indexed the way the front end indexes `m._12` (m[first selector][second selector]: glslang's matrices
// are HLSL's rows):
//   - a read: what fxc compiled, a vector constructed from the elements, `m._11_22` reads as
//     `float2(m._11, m._22)`. The matrix operand then stands once per element, which reads the same value
//     only where evaluating it has no side effects; anything else (a call's result) is evaluated once into
//     a temporary first: `(t = f(), float2(t._11, t._22))`.
//   - one element written through the swizzle (`m._11_22.y = e;`, `m._11_22[1]++`, `f(m._11_22.x)` with an
//     `out` parameter): that element, `m[1][1]`.
//   - several assigned (`m._11_22_33.zx = v;`, `m._11_22 *= s;`): `(t = v, m._33 = t.x, m._11 = t.y, read)`.
//   - several passed to an `out` or `inout` parameter (`f(m._11_22)`, `f(m._11_22_33.xz)`): the call takes a
//     temporary (initialized from the elements for `inout`), copied to the elements after it, as HLSL
//     copies an argument out: `(t = float2(m._11, m._22), r = f(t), m._11 = t.x, m._22 = t.y, r)`.
// What stays (a write through a matrix with side effects, a read whose element type glslang has no
// constructor for) gets a warning at it, not an error: the unit also holds code whose value no output
// reads (a function D3DX ran on the host, a static only a compile argument uses), where the constant
// changes nothing and fxc's effect still runs. Private to fx; built without RTTI like every file of
// glslang's tree.
#pragma once

#include "HlslToSpirv.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <vector>

namespace fx::detail {

// Rewrites the tree of `intermediate` (see above); `unusedSymbolId` is above every symbol id of the tree
// (for the temporaries). Returns a warning for each swizzle left as it was.
std::vector<HlslMessage> rewriteMatrixSwizzles(glslang::TIntermediate& intermediate,
                                               long long unusedSymbolId);

}  // namespace fx::detail
