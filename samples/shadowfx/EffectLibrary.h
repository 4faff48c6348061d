// EffectLibrary: where the shadowfx tool finds the effect library — the headers of effects/include and the
// shipped effects — so that an effect in any folder can `#include "include/shadowscene.fxh"` as the
// shipped ones do (docs/effect-library/README.md).
#pragma once

#include <filesystem>

namespace shadowfx::cli {

// The library folder (it holds include/*.fxh): share/shadowfx/effects beside the installed tool
// (<prefix>/bin/../share/shadowfx/effects, so a relocated prefix still finds it), else, for the tool in the
// build tree it was built in, the source tree's effects/. Empty if neither exists.
std::filesystem::path effectLibraryDir();

}  // namespace shadowfx::cli
