// ComputeDispatch: see ComputeDispatch.h; also EffectPass::dispatch().
#include "ComputeDispatch.h"

#include "PassBindings.h"

#include <runtime/EffectPass.h>

#include <string>

namespace runtime {

bool bindComputePass(EffectResources& resources, size_t technique, size_t pass,
                     std::vector<fx::Value>& arguments, fx::DiagnosticSink& diagnostics) {
    GpuProgram* program = resources.programs->computeProgram(technique, pass);
    if (!program) return false;
    PassBinding binding;
    binding.program = program;
    FramebufferFault unused;  // a compute program binds no framebuffer, the one thing that can fail
    bindPass(resources, technique, pass, binding, diagnostics, unused);
    evaluatePassArguments(resources, technique, pass, nullptr, arguments, diagnostics);
    uploadPassValues(resources, *program, arguments);
    return true;
}

bool dispatchBoundCompute(EffectResources& resources, const fx::CompiledPass& pass,
                          const std::array<uint32_t, 3>& groups, fx::DiagnosticSink& diagnostics) {
    for (GLuint axis = 0; axis < 3; ++axis) {
        GLint most = 0;
        gl::GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &most);
        if (groups[axis] > static_cast<uint32_t>(most)) {
            diagnostics.report(fx::DiagId::DispatchGroupCount, pass.loc,
                               {pass.name,
                                std::to_string(groups[0]) + " x " + std::to_string(groups[1]) + " x " +
                                    std::to_string(groups[2]),
                                std::to_string(most)});
            return false;
        }
    }
    gl::DispatchCompute(groups[0], groups[1], groups[2]);
    resources.storage->countDispatch();
    // GL orders a compute shader's storage-buffer and image writes before nothing by itself (D3D11 orders
    // UAV writes before the next reads implicitly). What reads them next: any shader's storage blocks
    // (SHADER_STORAGE: the next dispatch or a draw's StructuredBuffer), image loads and stores
    // (SHADER_IMAGE_ACCESS), texture fetches of a written image sampled as a texture (TEXTURE_FETCH), and
    // the application's reads of the buffer or texture (BUFFER_UPDATE for glGetBufferSubData,
    // TEXTURE_UPDATE for glGetTexImage and glReadPixels of an attached image).
    gl::MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                      GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                      GL_TEXTURE_UPDATE_BARRIER_BIT);
    return true;
}

bool EffectPass::dispatch(uint32_t x, uint32_t y, uint32_t z, fx::DiagnosticSink* diagnostics) const {
    if (!isValid()) return false;
    fx::DiagnosticList unreported;
    fx::DiagnosticSink& sink = diagnostics ? *diagnostics : unreported;
    const fx::CompiledPass& pass = mResources->effect().techniques[mTechnique].passes[mPass];
    if (!mResources->programs->computeProgram(mTechnique, mPass)) {
        sink.report(fx::DiagId::DispatchNotCompute, pass.loc, {pass.name});
        return false;
    }
    // As FX11's Dispatch after the pass's Apply: the values are those apply() or commitChanges() uploaded.
    if (mResources->application.applied != std::make_pair(mTechnique, mPass) && !apply(&sink)) return false;
    GpuProgram* applied = mResources->programs->program(mTechnique, mPass);
    if (applied->isCompute()) return dispatchBoundCompute(*mResources, pass, {x, y, z}, sink);
    // A pass that also draws: apply() made its graphics program current for the application's draws,
    // which it is again after the dispatch.
    std::vector<fx::Value> arguments;
    if (!bindComputePass(*mResources, mTechnique, mPass, arguments, sink)) return false;
    const bool dispatched = dispatchBoundCompute(*mResources, pass, {x, y, z}, sink);
    applied->bind();
    applied->upload(mResources->values.all(), mResources->application.arguments, *mResources->uniformRing);
    return dispatched;
}

}  // namespace runtime
