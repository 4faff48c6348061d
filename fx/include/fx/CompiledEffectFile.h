// CompiledEffectFile: a compiled effect as a file (`shadowfx compile EFFECT.fx --out EFFECT.sfxo`) that an
// application ships and loads without the compiler, as FX11 applications ship .fxo files. The format is
// little-endian binary, versioned and checked (docs/compiled-effect.md):
//
//   8 bytes   magic "SFXO\r\n\x1a\n" (a text-mode copy or a truncated first line changes it)
//   uint32    format version (kCompiledEffectFormatVersion)
//   uint64    content size in bytes
//   uint64    FNV-1a 64 hash of the content
//   content   every field of fx::CompiledEffect (fx/src/CompiledEffectFields.h)
//
// A file that is truncated, corrupt, or of another format version is a located error
// (`file.sfxo: error: ...`), never a crash: reading checks every length against the bytes left, every
// enumerator against its range or its name, and every index the runtime follows (parameters, passes,
// preshader operands, uniform block ranges) against what it indexes.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace fx {

// Raised whenever the content changes shape (a field added, removed or reordered) or an enum stored by
// number changes its list (fx/src/CompiledEffectFields.h pins their lengths to this version).
inline constexpr uint32_t kCompiledEffectFormatVersion = 20;

// Whether `bytes` begin with the compiled effect magic: how loaders tell a .sfxo from an .fx source,
// whatever the file's name.
bool hasCompiledEffectMagic(std::string_view bytes);
// Reads the first bytes of `path`; false if it cannot be read or is not a compiled effect.
bool isCompiledEffectFile(const std::string& path);

// The whole file's bytes for `effect`.
std::string serializeCompiledEffect(const CompiledEffect& effect);
// A file around `content` with this format version, its size and its hash: for the fuzzer and tests, which
// choose the content and need the header to let it through.
std::string compiledEffectFileAround(std::string_view content);
// The effect in `bytes`, read from `path` (named by the diagnostics); nullptr with an error otherwise.
std::unique_ptr<CompiledEffect> deserializeCompiledEffect(std::string_view bytes, const std::string& path,
                                                          DiagnosticSink& diagnostics);

std::unique_ptr<CompiledEffect> readCompiledEffectFile(const std::string& path, DiagnosticSink& diagnostics);
bool writeCompiledEffectFile(const CompiledEffect& effect, const std::string& path,
                             DiagnosticSink& diagnostics);

}  // namespace fx
