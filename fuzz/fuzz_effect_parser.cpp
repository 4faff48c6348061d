// Fuzz target 1: preprocessor + lexer + effect parser (fx::parseEffectSource), includes in memory.
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input = fuzz::text(data, size);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectSource(input, "fuzz/input.fx", fuzz::parseOptions(input), diagnostics);
    // The contract: an effect exactly when there were no errors.
    if ((effect != nullptr) == diagnostics.hasErrors()) __builtin_trap();
    (void)diagnostics.str();
    return 0;
}
