// ConstantMatrixProducts: HLSL's `*` of two matrices multiplies them element by element; glslang's HLSL
// front end reads it as their product, which ElementWiseProducts.h rewrites in the syntax tree. Where both
// operands are constants (`float2x2(1, 2, 3, 4) * float2x2(...)`, `static const` or `const` matrices with
// constant initializers), glslang computes the product while it parses, so the tree holds its value and
// no node of the `*`. This step, run on the unit's text before glslang compiles it, writes each such `*`
// of two matrices of one shape as the matrix of its rows' products, `float2x2((a)[0] * (b)[0], (a)[1] *
// (b)[1])`, which glslang folds element by element: the product stays a constant (an array size, another
// `static const`'s initializer) of the value HLSL defines. A `*` of constant operands that glslang reads
// as a product of matrices of different shapes, or of a vector and a matrix, is the error ElementWiseProducts
// gives for any such `*`. Private to fx; built without RTTI like every file of glslang's tree.
#pragma once

#include "HlslToSpirv.h"
#include "Lexer.h"

#include <glslang/MachineIndependent/localintermediate.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fx::detail {

struct ConstantProductRewrite {
    // The unit's text with each product of constant matrices at a `*` rewritten (see above); nullopt where
    // the unit has none. Line breaks are kept; the text after a rewritten product on its line moves right.
    std::optional<std::string> text;
    std::vector<HlslMessage> errors;  // at each `*` of constants of different shapes; `text` is then nullopt
};

// Parses `text` with the unit's settings and hands its syntax tree to `read`, also where glslang reported
// errors; false where it built no tree.
using ParseUnit =
    std::function<bool(const std::string& text, const std::function<void(glslang::TIntermediate&)>& read)>;

// `parsed` is glslang's tree of `text` (HLSL, preprocessed, `#line` directives allowed), whose tokens are
// `tokens` (lexHlslUnit). The `*` operators with no node in it are found; only where there are such `*`s
// with operands that may be matrices is a copy of the text, in which their right operands are no
// constants, parsed (with `parse`) to learn their operands' types.
ConstantProductRewrite rewriteConstantMatrixProducts(glslang::TIntermediate& parsed, const std::string& text,
                                                     const std::vector<Token>& tokens,
                                                     const ParseUnit& parse);

}  // namespace fx::detail
