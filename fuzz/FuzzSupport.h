// Shared by the fuzz targets: effect parsing with an in-memory file system, so that an #include in a
// fuzzed input can never read the disk, and small limits, so that one input stays fast.
#pragma once

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace fuzz {

// The input is the main file "fuzz/input.fx". Includes resolve to a small fixed header (any name under
// "include/") or fail; the input itself may include "input.fx" to exercise recursion.
inline fx::ParseOptions parseOptions(const std::string& input) {
    fx::ParseOptions options;
    options.maxIncludeDepth = 8;
    options.maxSourceBytes = 1u << 20;
    options.readFile = [input](const std::string& path) -> std::optional<std::string> {
        if (path == "fuzz/input.fx") return input;
        if (path.rfind("fuzz/include/", 0) == 0)
            return std::string("float4 Helper(float4 v) { return v * 2; }\n#define HELPER_SCALE 2.0\n");
        return std::nullopt;
    };
    return options;
}

inline std::string text(const uint8_t* data, size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// Parse + compile one input with `options`; traps when the result and the diagnostics disagree (an
// effect without errors that did not compile, or errors with an effect), the finding of both compiler
// targets. glslang is slow on huge units, so inputs over 64 KiB are left to the parser target.
// `inspect`, when given, sees the diagnostics of every compiled input.
inline int compileInput(const uint8_t* data, size_t size, const fx::CompileOptions& options,
                        void (*inspect)(const fx::DiagnosticList&) = nullptr) {
    if (size > (64u << 10)) return 0;
    const std::string input = text(data, size);
    fx::DiagnosticList diagnostics;
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectSource(input, "fuzz/input.fx", parseOptions(input), diagnostics);
    if (!effect) return 0;
    std::unique_ptr<fx::CompiledEffect> compiled = fx::compileEffect(effect, options, diagnostics);
    if ((compiled != nullptr) == diagnostics.hasErrors()) __builtin_trap();
    if (inspect) inspect(diagnostics);
    (void)diagnostics.str();
    return 0;
}

}  // namespace fuzz
