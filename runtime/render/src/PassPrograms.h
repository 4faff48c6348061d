// PassPrograms: every pass's GL programs, preshaders and stream-output capture, made once when the effect
// is loaded (FX11's EffectLoad) and looked up by technique and pass index for the effect's life. The
// variants a frame asks for (depth-only, instanced) are linked on first use and kept.
#pragma once

#include "BatchedPass.h"
#include "PassPreshaders.h"

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <runtime/GpuProgram.h>
#include <runtime/StreamOutBuffers.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace runtime {

class PassPrograms {
public:
    // Links every pass's program (and a drawing pass's compute program), makes its preshaders and, for a
    // stream-output pass, its capture. nullptr if a program does not link; the diagnostics say why. Every
    // pass of `effect` then has a program and preshaders.
    static std::unique_ptr<PassPrograms> create(const fx::CompiledEffect& effect,
                                                fx::DiagnosticSink& diagnostics);

    // The pass's program: its graphics stages, or its compute stage for a pass that only dispatches.
    GpuProgram* program(size_t technique, size_t pass) const { return mPrograms[technique][pass].get(); }
    // What a dispatch of the pass runs: its compute program, or null for a pass without one.
    GpuProgram* computeProgram(size_t technique, size_t pass) const;
    PassPreshaders& preshaders(size_t technique, size_t pass) { return mPreshaders[technique][pass]; }
    const std::vector<PassPreshaders>& techniquePreshaders(size_t technique) const {
        return mPreshaders[technique];
    }
    // The capture of a stream-output pass (CompiledPass::streamOut), kept between frames: a pass drawing it
    // (DrawAuto) reads last frame's where it runs first. Null for a pass without stream output.
    StreamOutBuffers* streamOut(size_t technique, size_t pass) const;
    // The vertex stage alone, for a draw with no colour write (FrameExecutor::draw): linked on first use,
    // null where it does not link (a driver that refuses it costs speed, not the frame).
    GpuProgram* depthOnlyProgram(size_t technique, size_t pass, const fx::CompiledPass& compiled);
    // The pass drawn instanced (FrameOptions::batching) for these per-object flags: relinked when the
    // flags differ from the last call's, null where the variant cannot be made or linked.
    // `viewParameter` (PassUse::viewDerived, the same for every call of a pass) splits its records.
    BatchedPass* batchedPass(size_t technique, size_t pass, const fx::CompiledPass& compiled,
                             const std::vector<bool>& perObjectParameter,
                             const std::vector<bool>& perObjectArgument,
                             const std::vector<bool>& viewParameter);

private:
    using PassKey = std::pair<size_t, size_t>;  // technique, pass
    struct BatchedSlot {
        std::vector<bool> perObjectParameter;
        std::vector<bool> perObjectArgument;
        std::unique_ptr<BatchedPass> pass;
    };

    std::vector<std::vector<std::unique_ptr<GpuProgram>>> mPrograms;  // [technique][pass]
    std::vector<std::vector<PassPreshaders>> mPreshaders;             // [technique][pass]
    // The compute programs of passes that also draw (mPrograms holds their graphics stages).
    std::map<PassKey, std::unique_ptr<GpuProgram>> mDrawingPassComputePrograms;
    std::map<PassKey, std::unique_ptr<StreamOutBuffers>> mStreamOuts;
    std::map<PassKey, std::unique_ptr<GpuProgram>> mDepthOnlyPrograms;
    std::map<PassKey, BatchedSlot> mBatchedPasses;
};

}  // namespace runtime
