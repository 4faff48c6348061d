// GlslangTreeEdits: the edits the rewrites of glslang's syntax tree share (HlslToSpirv's matrix swizzles,
// IntegerMatrixSplitting): putting a node in another's place, and telling whether evaluating an expression
// twice reads the same value. Private to fx; glslang's tree types, so every file that includes it is built
// without RTTI (fx/CMakeLists.txt).
#pragma once

#include <glslang/Include/intermediate.h>

namespace fx::detail {

// Puts `to` where `parent` holds `from` (its first such operand); false where the parent is a node glslang
// gives no way to change (a loop's step expression) or holds no `from`.
bool replaceChild(TIntermNode* parent, glslang::TIntermTyped* from, glslang::TIntermTyped* to);

// Whether replaceChild(parent, from, ...) would succeed: asked before an edit that changes `from` itself.
inline bool canReplaceChild(TIntermNode* parent, glslang::TIntermTyped* from) {
    return replaceChild(parent, from, from);  // `from` in its own place: nothing changes
}

// Symbols and constants combined by indexing, member selection, swizzles, arithmetic and constructors:
// evaluating it again reads the same value and changes nothing.
bool isSideEffectFree(const TIntermNode* node);

}  // namespace fx::detail
