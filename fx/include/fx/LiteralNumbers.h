// LiteralNumbers: the one reading of a value written as text outside the effect's syntax: a parameter set
// from the command line (`--set Bias=0.002`, `--set Color={1, 0.5, 0, 1}`) and the literal values of SAS
// script commands (`ClearSetColor=0,0,0,1`, `LoopByCount=4`).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace fx {

// Numbers separated by commas or spaces, optionally in braces; `true`/`false` (any case) read as 1 and 0.
// Every word must be a whole, finite number (strtof's syntax: "0.5", "1e-3", "-2", "0x10"): nullopt
// otherwise. No words give an empty list, which the caller judges (a script value needs at least one).
std::optional<std::vector<float>> parseLiteralNumbers(std::string_view text);

}  // namespace fx
