// PostfixOperands: glslang's HLSL front end (12.0, and upstream still) checks the operand of a prefix `++`
// or `--` but not that of a postfix one: `x++` on an operand it cannot increment (an undeclared name, a
// type name, a void call, a bool, a struct) yields no node. As a statement of its own glslang then drops it
// without a word (the program compiles, minus the statement); inside an expression (`return x++;`, an
// operand, an argument) the expression around it reads through the null and the process crashes. Private
// to fx.
#pragma once

#include "HlslToSpirv.h"
#include "Lexer.h"

#include <optional>
#include <string>
#include <vector>

namespace fx::detail {

struct PostfixRewrite {
    // The text with each postfix `++`/`--` whose value is discarded (a statement of its own, a for loop's
    // step) written as the prefix operator, which means the same there and which glslang checks.
    std::string text;
    // `text` with the postfix operators whose value is used written as prefix operators too; nullopt where
    // there are none. A prefix operator demands what the postfix one demands (a numeric l-value), so
    // glslang parses this without errors exactly when their operands are sound, and only then is `text`
    // safe to parse.
    std::optional<std::string> checkText;
    // A postfix operator whose operand the rewrite cannot find (unbalanced brackets, say): an error at it,
    // since glslang might read an operand there that it then crashes on. Neither text is parsed then.
    std::vector<HlslMessage> errors;
};

// For HLSL `text`, preprocessed: no comments (their words would count), `#line` directives allowed, and its
// `tokens` (lexHlslUnit). Line breaks are kept, so line numbers hold.
PostfixRewrite rewritePostfixOperators(const std::string& text, const std::vector<Token>& tokens);

}  // namespace fx::detail
