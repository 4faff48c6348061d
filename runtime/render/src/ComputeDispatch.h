// ComputeDispatch: a compute pass (fx::CompiledPass::compute) bound and dispatched, for both clients of a
// pass: the application's EffectPass::apply()/dispatch() and the SAS host's `Dispatch=x,y,z`
// (FrameExecutor). A compute pass has no targets and no render states: binding it is its resources, its
// program and its values.
#pragma once

#include "EffectResources.h"

#include <fx/Diagnostics.h>

#include <array>
#include <cstdint>
#include <vector>

namespace runtime {

// Binds the compute pass `pass` of `technique`: its textures, storage buffers and images, its program,
// its compile arguments evaluated into `arguments` and its uniform block. False for a pass without a
// compute shader.
bool bindComputePass(EffectResources& resources, size_t technique, size_t pass,
                     std::vector<fx::Value>& arguments, fx::DiagnosticSink& diagnostics);
// Runs the bound compute program over `groups` thread groups, then orders its writes before what reads
// them next. False, with a diagnostic, for more groups than the context dispatches.
bool dispatchBoundCompute(EffectResources& resources, const fx::CompiledPass& pass,
                          const std::array<uint32_t, 3>& groups, fx::DiagnosticSink& diagnostics);

}  // namespace runtime
