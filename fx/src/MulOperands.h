// MulOperands: glslang's HLSL front end (12.0, and upstream still) crashes on mul() where it must shrink one
// operand to a shape with a dimension of one: a one-component vector (`float1`) or a matrix of one row or
// column (`float1x3`, `float3x1`) beside a matrix of another shape
// (HlslParseContext::addGenMulArgumentConversion reads the null its constructor gives back). The operands'
// types are not known before glslang parses them, so every mul() with an operand of such a type is refused
// (a few of which glslang would compile, `mul(float1x3, float3x3)`): an argument counts where such a type,
// or a variable, member or function declared with one, stands at its top level, not inside a
// constructor's, call's or index's brackets. Names are matched by name, whatever scope declared them.
// Private to fx.
#pragma once

#include "HlslToSpirv.h"
#include "Lexer.h"

#include <string>
#include <vector>

namespace fx::detail {

// An error for each such call of mul() in the `tokens` of an HLSL unit (lexHlslUnit), at the call's file,
// line and column.
std::vector<HlslMessage> mulCallsGlslangCannotCompile(const std::vector<Token>& tokens);

}  // namespace fx::detail
