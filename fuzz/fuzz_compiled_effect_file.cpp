// Fuzz target 7: the compiled effect file reader (fx/CompiledEffectFile.h), which reads files an
// application ships. Any bytes, as a whole file and as the content of a file whose header lets them
// through (so the fuzzer reaches the field reader and the checks, not only the hash), must give an
// effect or one error; an effect read must write back to the bytes it was read from.
#include <fx/CompiledEffectFile.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

void readOne(std::string_view bytes) {
    fx::DiagnosticList diagnostics;
    std::unique_ptr<fx::CompiledEffect> effect =
        fx::deserializeCompiledEffect(bytes, "fuzz.sfxo", diagnostics);
    if (effect.operator bool() == diagnostics.hasErrors()) __builtin_trap();
    if (effect && fx::serializeCompiledEffect(*effect) != bytes) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    readOne(bytes);
    readOne(fx::compiledEffectFileAround(bytes));
    return 0;
}
