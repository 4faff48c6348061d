// PassBindings: the resources a pass's stages read, bound for a draw: its samplers' textures and sampler
// objects on their units, and its storage buffers on their binding points. One implementation for both
// clients of a pass: the SAS host (FrameExecutor) and the application's EffectPass::apply().
#pragma once

#include "EffectResources.h"

#include <runtime/Framebuffer.h>
#include <runtime/GlStateSnapshot.h>

#include <fx/CompiledEffect.h>

namespace runtime {

// Binds every stage's sampled textures (an application's GL texture where it set one, else the effect's
// texture or Buffer<T>, else none) and sampler objects. A mipmapped render target written since its chain
// was built gets its chain first, unless `drawing` renders into it.
void bindPassTextures(EffectResources& resources, const fx::CompiledPass& pass, const RenderTargets& drawing);
// Binds the buffers behind the pass's StructuredBuffer and ByteAddressBuffer blocks, and after them the
// counters of its append, consume and counted buffers (GpuProgram::counterParameters).
void bindPassStorageBuffers(EffectResources& resources, const fx::CompiledPass& pass);
// Binds the textures behind the pass's images (RWTexture1D/2D/3D/2DArray, all layers) and the buffer
// textures behind its RWBuffers on their image units, read-write.
void bindPassImages(EffectResources& resources, const fx::CompiledPass& pass);
// DepthBias's depth bits for a depth target of `texture` (RenderStateApplier.h): 2^-bits for UNORM depth;
// for D32F the resolvable difference is 2^-24 for depths in [0.5, 1), so 32-bit float depth counts as 24
// bits; 24 without one.
int depthBiasBits(const GpuTexture* texture);
// What applying `pass` writes to the context besides its targets (GlStateSnapshot.h).
GlStateMask passStateMask(const fx::CompiledPass& pass);

}  // namespace runtime
