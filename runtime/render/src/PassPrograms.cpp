// PassPrograms: see PassPrograms.h.
#include "PassPrograms.h"

#include <runtime/GlApi.h>

namespace runtime {

std::unique_ptr<PassPrograms> PassPrograms::create(const fx::CompiledEffect& effect,
                                                   fx::DiagnosticSink& diagnostics) {
    auto programs = std::unique_ptr<PassPrograms>(new PassPrograms());
    PassPrograms& r = *programs;
    bool ok = true;
    for (const fx::CompiledTechnique& technique : effect.techniques) {
        auto& passes = r.mPrograms.emplace_back();
        auto& preshaders = r.mPreshaders.emplace_back();
        for (const fx::CompiledPass& pass : technique.passes) {
            const PassKey key{r.mPrograms.size() - 1, passes.size()};
            std::unique_ptr<GpuProgram> program = GpuProgram::create(pass, diagnostics);
            ok = ok && program != nullptr;
            if (program && !program->isCompute() && !pass.compute.glsl.empty()) {
                std::unique_ptr<GpuProgram> compute = GpuProgram::createCompute(pass, diagnostics);
                ok = ok && compute != nullptr;
                r.mDrawingPassComputePrograms[key] = std::move(compute);
            }
            // D3D10's DepthBiasClamp needs glPolygonOffsetClamp; without it the bias is applied unbounded.
            for (const fx::RenderStateSetting& setting : pass.states)
                if (setting.id == fx::RenderStateId::DepthBiasClamp && !gl::PolygonOffsetClamp &&
                    !(setting.constant && *setting.constant == 0.0))
                    diagnostics.report(fx::DiagId::DepthBiasClampUnavailable, setting.loc);
            if (pass.streamOut) r.mStreamOuts[key] = std::make_unique<StreamOutBuffers>(*pass.streamOut);
            passes.push_back(std::move(program));
            preshaders.emplace_back(pass);
        }
    }
    if (!ok) return nullptr;
    return programs;
}

GpuProgram* PassPrograms::computeProgram(size_t technique, size_t pass) const {
    if (auto found = mDrawingPassComputePrograms.find({technique, pass});
        found != mDrawingPassComputePrograms.end())
        return found->second.get();
    GpuProgram* program = mPrograms[technique][pass].get();
    return program && program->isCompute() ? program : nullptr;
}

StreamOutBuffers* PassPrograms::streamOut(size_t technique, size_t pass) const {
    auto found = mStreamOuts.find({technique, pass});
    return found == mStreamOuts.end() ? nullptr : found->second.get();
}

GpuProgram* PassPrograms::depthOnlyProgram(size_t technique, size_t pass, const fx::CompiledPass& compiled) {
    const PassKey key{technique, pass};
    auto found = mDepthOnlyPrograms.find(key);
    if (found == mDepthOnlyPrograms.end()) {
        fx::DiagnosticList ignored;
        found = mDepthOnlyPrograms
                    .emplace(key, GpuProgram::create(compiled, ignored, GpuProgram::Stages::DepthOnly))
                    .first;
    }
    return found->second.get();
}

BatchedPass* PassPrograms::batchedPass(size_t technique, size_t pass, const fx::CompiledPass& compiled,
                                       const std::vector<bool>& perObjectParameter,
                                       const std::vector<bool>& perObjectArgument,
                                       const std::vector<bool>& viewParameter) {
    BatchedSlot& slot = mBatchedPasses[{technique, pass}];
    if (slot.perObjectParameter != perObjectParameter || slot.perObjectArgument != perObjectArgument) {
        slot.perObjectParameter = perObjectParameter;
        slot.perObjectArgument = perObjectArgument;
        slot.pass = BatchedPass::create(compiled, perObjectParameter, perObjectArgument, viewParameter);
    }
    return slot.pass.get();
}

}  // namespace runtime
