// BoolCompoundAssignments: `b |= e`, `b &= e` and `b ^= e` on a bool or bool vector in glslang's syntax
// tree, made what GLSL has. HLSL applies `|`, `&` and `^` to bools (as to the ints 0 and 1); glslang's front
// end converts the operands of the binary operators to int, but keeps a compound assignment on bools, which
// its SPIR-V back end writes as a bitwise operation on bools and SPIRV-Cross as GLSL's `|=` on a bool,
// which no GL driver compiles. Each becomes the logical operation it means: `b = b || e`, `b = b && e`,
// `b = b != e` (element by element on vectors); an `e` with side effects is evaluated into a temporary
// first, since GLSL's `||` and `&&` would skip it where HLSL's `|=` and `&=` evaluate it. Private to fx;
// built without RTTI like every file of glslang's tree.
#pragma once

#include <glslang/MachineIndependent/localintermediate.h>

namespace fx::detail {

// Rewrites the tree of `intermediate` (see above); `unusedSymbolId` is above every symbol id of the tree (for
// the temporaries). A bool written through an expression with side effects
// (`flags[i++] |= e`) is left as it was (GL then refuses the program).
void rewriteBoolCompoundAssignments(glslang::TIntermediate& intermediate, long long unusedSymbolId);

}  // namespace fx::detail
