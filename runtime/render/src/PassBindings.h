// PassBindings: the one way a pass is made ready to draw, for both clients of a pass: the application's
// EffectPass::apply() and commitChanges() (runtime/EffectPass.h; host files' frames use them too), and the
// SAS host's draws and dispatches (FrameExecutor). Each client resolves what differs between them (the
// targets the script's commands name, the states the frame plan evaluated already, a variant of the
// program) and hands it over in a PassBinding; binding the framebuffer, the render states, the program and
// the resources its stages read, and evaluating and uploading its values, happen here alone.
#pragma once

#include "EffectResources.h"

#include <runtime/Framebuffer.h>
#include <runtime/GlStateSnapshot.h>
#include <runtime/RenderStateApplier.h>

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>

#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace runtime {

// What a client decided about a pass before it is bound.
struct PassBinding {
    // The targets the pass draws into, as the client resolved its script's commands; null leaves the bound
    // framebuffer and viewport (the application's, for a pass whose script names no effect target).
    const RenderTargets* framebuffer = nullptr;
    // A part of the framebuffer to draw into (a cascade's tile) instead of all of it.
    std::optional<glm::ivec4> viewport;
    int depthBits = 24;  // of the depth buffer drawn into, for DepthBias (depthBiasBits)
    // The pass's render states, where the client evaluated them (the frame plan's); null: evaluated here.
    const RenderStateBlock* states = nullptr;
    // A variant of the pass's program (vertex stage alone, instanced); null: the pass's own.
    GpuProgram* program = nullptr;
    // The host's picture of the scene, bound to the samplers the compiler marked as reading it
    // (SamplerBinding::hostPicture) where the application gave them no texture: the SAS host's (render()).
    // Null under apply(), whose application binds its own.
    const GpuTexture* hostPicture = nullptr;
};

// Binds pass `pass` of `technique` as `binding` says: the framebuffer (its mipmapped colour targets marked
// for a new chain), every render state, the textures and sampler objects, storage buffers and images its
// stages read, and its program. A pass without shaders binds targets and states and leaves the bound
// program; a compute program (a compute pass's, or the dispatch of a pass that also draws, given in
// `binding.program`) binds no target and no state. False, with the reason in `fault`, where the
// framebuffer cannot be bound (nothing after it is bound then).
bool bindPass(EffectResources& resources, size_t technique, size_t pass, const PassBinding& binding,
              fx::DiagnosticSink& diagnostics, FramebufferFault& fault);
// Binds `targets` as the framebuffer and viewport and marks their mipmapped colour targets for a new chain
// (D3D9's AUTOGENMIPMAP): what bindPass() does first, and what a script's clears bind.
bool bindPassTargets(EffectResources& resources, const RenderTargets& targets, FramebufferFault& fault);

// The pass's compile arguments that `which` selects (one flag per CompiledPass::arguments entry; null:
// all), evaluated over the current values into `arguments`; each runs only if an input changed.
void evaluatePassArguments(EffectResources& resources, size_t technique, size_t pass,
                           const std::vector<bool>* which, std::vector<fx::Value>& arguments,
                           fx::DiagnosticSink& diagnostics);
// Packs the bound `program`'s uniform blocks from the current values and `arguments`, uploading the blocks
// whose bytes changed.
void uploadPassValues(EffectResources& resources, GpuProgram& program,
                      const std::vector<fx::Value>& arguments);
// Both, every argument, for the pass's own program (nothing for a pass without shaders): what apply() and
// commitChanges() do. The SAS host calls the two apart: the per-pass arguments once, then per object the
// per-object ones and the upload of its variant program.
void commitPassValues(EffectResources& resources, size_t technique, size_t pass,
                      std::vector<fx::Value>& arguments, fx::DiagnosticSink& diagnostics);

// DepthBias's depth bits for a depth target of `texture` (RenderStateApplier.h): 2^-bits for UNORM depth;
// for D32F the resolvable difference is 2^-24 for depths in [0.5, 1), so 32-bit float depth counts as 24
// bits; 24 without one.
int depthBiasBits(const GpuTexture* texture);
// Whether a sampler of the pass reads the host's picture: one marked SamplerBinding::hostPicture whose
// texture the application did not give.
bool readsHostPicture(const EffectResources& resources, const fx::CompiledPass& pass);
// What applying `pass` writes to the context besides its targets (GlStateSnapshot.h).
GlStateMask passStateMask(const fx::CompiledPass& pass);

}  // namespace runtime
