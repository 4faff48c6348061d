// EffectFile: see fx/EffectFile.h.
#include <fx/CompiledEffectFile.h>
#include <fx/EffectFile.h>

namespace fx {

EffectProvenance effectProvenance(const std::string& path, const ParseOptions& parseOptions) {
    return {path, parseOptions.defines, parseOptions.includeDirs, "shadowfx " SHADOWFX_VERSION};
}

std::shared_ptr<CompiledEffect> loadEffectFile(const std::string& path, const ParseOptions& parseOptions,
                                               const CompileOptions& options, DiagnosticSink& diagnostics) {
    if (!isCompiledEffectFile(path)) {
        std::shared_ptr<Effect> effect = parseEffectFile(path, parseOptions, diagnostics);
        if (!effect) return nullptr;
        std::shared_ptr<CompiledEffect> compiled = compileEffect(effect, options, diagnostics);
        if (compiled) compiled->provenance = effectProvenance(path, parseOptions);
        return compiled;
    }
    std::shared_ptr<CompiledEffect> compiled = readCompiledEffectFile(path, diagnostics);
    if (!compiled || options.technique.empty()) return compiled;
    // As a technique compiled alone: the one technique, at index 0.
    const CompiledTechnique* technique = compiled->findTechnique(options.technique);
    if (!technique) {
        diagnostics.report(DiagId::UnknownTechnique, SourceLoc{path, 0, 0}, {options.technique});
        return nullptr;
    }
    std::vector<CompiledTechnique> kept{*technique};
    compiled->techniques = std::move(kept);
    return compiled;
}

}  // namespace fx
