// MulOperands: glslang's HLSL front end (12.0, and upstream still) crashes on mul() of a matrix and an
// operand with a dimension of one, a one-component vector (`float1`) or a matrix of one row or column
// (`float1x3`, `float3x1`): it truncates the other operand to a shape it cannot construct and reads the
// null it gets back (HlslParseContext::addGenMulArgumentConversion). Such a call is refused before glslang
// sees it. The operands' types are not known before glslang parses them, so the check is on the text: a
// call is refused where an argument names a type of one dimension or a variable, member or function
// declared with one. Private to fx.
#pragma once

#include "HlslToSpirv.h"

#include <string>
#include <vector>

namespace fx::detail {

// An error for each such call of mul() in HLSL `text` (preprocessed, `#line` directives allowed), at the
// call's file and line and quoting `mul` (the column is recovered from the quote).
std::vector<HlslMessage> mulCallsGlslangCannotCompile(const std::string& text);

}  // namespace fx::detail
