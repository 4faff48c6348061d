// TunableParameters: what `shadowfx tune` searches in a technique — the effect's scalar tweakables that the
// technique reads, each with its range, step and scale from its UI annotations (docs/effect-format.md,
// "Tuning annotations"), as the GL-free search (report/TuneSearch.h) takes them.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <report/TuneSearch.h>

#include <vector>

namespace shadowfx::cli {

// The parameters of `effect` that `technique` reads (in a shader's uniforms, a compile argument or a state
// value), in declaration order, that are float, int or bool scalars, driven by no semantic, not hidden
// (`UIWidget = "none"`), not excluded (`bool Tune = false;`) and, but for bools, bounded by UIMin and UIMax.
// An annotation that cannot be followed (a log scale over a range reaching 0, an unknown UIScale, UIMin above
// UIMax) is an error reported into `sink` at the parameter.
std::vector<report::TuneParameter> tunableParameters(const fx::CompiledEffect& effect,
                                                     const fx::CompiledTechnique& technique,
                                                     fx::DiagnosticSink& sink);

}  // namespace shadowfx::cli
