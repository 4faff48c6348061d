// EffectParser: effect text -> Effect syntax tree. Runs glslang's preprocessor (with an includer that
// resolves "a/b.fxh" and <a\\b.fxh> relative to the including file, then the include directories), lexes
// the preprocessed text, and parses D3DX9 effect syntax.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Effect.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fx {

struct ParseOptions {
    std::vector<std::string> includeDirs;                      // searched after the including file's folder
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME=VALUE
    int maxIncludeDepth = 32;                                  // deeper (or recursive) includes are an error
    size_t maxSourceBytes = 16u << 20;                         // all files together
    // Reads a file; returns nullopt if it cannot be opened. Default: the file system. Tests and hot reload
    // may supply their own.
    std::function<std::optional<std::string>(const std::string& path)> readFile;
};

// Parses an effect file. Returns nullptr if any error was reported (the diagnostics say why).
std::shared_ptr<Effect> parseEffectFile(const std::string& path, const ParseOptions& options,
                                        DiagnosticSink& diagnostics);

// Parses effect text as if it were the file `path` (includes resolve relative to it).
std::shared_ptr<Effect> parseEffectSource(const std::string& source, const std::string& path,
                                          const ParseOptions& options, DiagnosticSink& diagnostics);

}  // namespace fx
