// TextureFunctionFill: draws a texture function's fill pass (fx::TextureDesc::fill) into every texel of
// every level of its texture, and every slice or face, as D3DXFillTextureTX filled them when FX Composer
// created the effect (docs/fxcomposer.md, "Texture functions").
#pragma once

#include <runtime/GpuProgram.h>
#include <runtime/GpuTexture.h>

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>

#include <optional>
#include <vector>

namespace runtime {

// The texture `desc` describes, filled by its function with the parameters' `values`; nullopt after a
// located error (the fill pass would not link). Leaves the GL state it found: it saves and restores what
// it changes.
std::optional<GpuTexture> fillTextureFunction(const fx::TextureDesc& desc,
                                              const std::vector<fx::Value>& values, UniformRing& ring,
                                              fx::DiagnosticSink& diagnostics);

}  // namespace runtime
