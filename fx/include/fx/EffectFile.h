// EffectFile: an effect file, source or compiled, told apart by its content (the compiled effect magic,
// fx/CompiledEffectFile.h), not its name: what the CLI, the measurement code and hot reload load. A
// compiled file is read as it is (its -D and -I were fixed when it was compiled); a source file is parsed
// and compiled with the options given, and its compiled effect records them (CompiledEffect::provenance).
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <memory>
#include <string>

namespace fx {

// `options.technique`, if set, keeps that technique only, from source and from a compiled file alike.
std::shared_ptr<CompiledEffect> loadEffectFile(const std::string& path, const ParseOptions& parseOptions,
                                               const CompileOptions& options, DiagnosticSink& diagnostics);

// What a compile of `path` with `parseOptions` records as its provenance.
EffectProvenance effectProvenance(const std::string& path, const ParseOptions& parseOptions);

}  // namespace fx
