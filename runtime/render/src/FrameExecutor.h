// FrameExecutor: runs one frame's scripts on GL, following the frame's plan (FramePlan, recorded by
// PlanRecorder): resolves each draw's targets, states and program variant, binds the pass through
// PassBindings.h as the application's EffectPass::apply() does, binds semantics, runs the compile
// arguments' preshaders, culls and draws; counts what it did into FrameStats.
#pragma once

#include "EffectResources.h"
#include <private/runtime/FramePlan.h>
#include <runtime/PassTimer.h>
#include "PassUse.h"
#include "ScriptInterpreter.h"
#include "SemanticBinder.h"

#include <runtime/EffectRenderer.h>
#include <runtime/Scene.h>

#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace runtime {

class FrameExecutor : public ScriptTarget {
public:
    FrameExecutor(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                  fx::DiagnosticSink& diagnostics, FrameStats& stats, size_t techniqueIndex,
                  const SemanticBinder& binder, const std::vector<PassUse>& uses, const FramePlan& plan);

    bool failed() const { return mFailed; }
    // False if the frame's commands did not follow the plan (then nothing after the divergence was left out).
    bool followedPlan() const { return mPlanFollowed && mNextOp == mPlan.ops.size(); }
    // Closes the last pass's record, reads the fragment counts and, with FrameOptions::timePasses, waits
    // for the GPU and fills the frame's pass timings.
    void finish();

    void beginPass(const fx::CompiledPass& pass) override;
    void setColorTarget(int index, const std::string& texture, int parameter) override;
    void setDepthTarget(const std::string& texture, int parameter) override;
    void setRenderPort(const std::string& lightName, int lightSlot, int cascade,
                       const fx::SourceLoc& loc) override;
    void setClearColor(const fx::Value& color) override;
    void setClearDepth(float depth) override { mClearDepth = depth; }
    void setClearStencil(int stencil) override { mClearStencil = stencil; }
    void clear(fx::ScriptCommand::ClearWhat what, int colorTarget) override;
    void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) override;
    // Dispatch=x,y,z (ComputeDispatch.h): outside the plan, which has no operation for it.
    void dispatch(const fx::CompiledPass& pass, const std::array<uint32_t, 3>& groups,
                  const fx::SourceLoc& loc) override;
    void drawScene(const fx::ScriptCommand& command) override;
    const fx::Value* parameter(size_t index) const override { return &mResources.values[index]; }
    void setLoopIndex(const std::string& name, int parameter, int index) override;

private:
    void fail(fx::DiagId id, const std::vector<std::string>& args);
    PassStats* currentPass() { return mStats.passes.empty() ? nullptr : &mStats.passes.back(); }
    static uint64_t texelCount(const GpuTexture& texture);
    // The plan's record of the command about to run, or null once the frame left the plan (never
    // expected: the dry run follows the same script over the same values).
    const PlannedOp* nextOp(PlannedOp::Kind kind, size_t pass);
    // Counts a command the plan leaves out; true if it is left out.
    bool leftOut(const PlannedOp* op);
    void closePass();
    // Objects whose draws can change this pass's targets: inside the camera's frustum, or casters whose
    // extrusion away from the light meets the camera's receivers (IntersectionBody.h).
    void cull(const PlannedOp* op, std::vector<uint32_t>& visible) const;
    // The render target a script names (`name`, resolved to `parameter`); null where it is not allocated.
    const GpuTexture* target(const std::string& name, int parameter);
    // The framebuffer for a clear or draw into mTargets: without the depth-stencil target when it is smaller
    // than the colour targets and the operation does not use it (`usesDepth`), with a warning for `pass`
    // when it does. False once the frame failed.
    bool drawTargets(bool usesDepth, const fx::CompiledPass* pass, RenderTargets& targets);
    // Binds drawTargets() for a clear, or for the host scene a script draws (ScriptExternal=color);
    // `depthAlone`: the depth-stencil target without the colour targets.
    bool bindTargets(bool usesDepth, bool depthAlone = false);
    // Whether a depth or stencil clear now may bind the depth-stencil target alone: the pass's draw after
    // it will (depthOnly), and the clear covers the same texels either way.
    bool clearsDepthAlone();
    glm::ivec2 depthTargetSize() const;  // at its mip level; 0x0 without one
    bool depthTargetIsSmaller() const;
    // The pass's render states for this draw: those the plan evaluated (`op`), or, once the frame left the
    // plan, evaluated now.
    const RenderStateBlock& passStates(const fx::CompiledPass& pass, size_t passIndex, const PlannedOp* op);
    // For a draw whose states write no colour to any bound target: the pass's vertex-only program, drawn
    // into the depth-stencil target alone, or null where the draw needs its colour targets or pixel shader
    // after all (see draw()).
    GpuProgram* depthOnly(const fx::CompiledPass& pass, size_t passIndex, const RenderStateBlock& states);
    // Runs the pass's compile arguments into mArguments: with leave-out, the per-pass ones once per pass
    // (perObject false) and the per-object ones per draw (perObject true); without, all per draw. Each
    // runs only if a parameter it reads changed (PassPreshaders).
    void evaluateArguments(size_t passIndex, const PassUse& use, bool perObject);
    void drawWith(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program, const PassUse& use,
                  const SceneObject* object, GpuMesh& mesh);
    void drawCapture(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program, const PassUse& use);
    void countDraw(const GpuMesh& mesh, int objects);
    // The host's picture of the scene that full-screen passes read (SamplerBinding::hostPicture): the
    // scene from the camera with the host's default material over the host background, painted at the
    // frame's size when a pass first reads it in the frame. Null if its targets cannot be bound (never
    // expected).
    const GpuTexture* hostPicture();
    // Every object with the host's default material and D3D's default states into the bound targets.
    void paintHostScene(const glm::mat4& view, const glm::mat4& projection);
    // FrameOptions::batching: the pass's instanced variant for its current per-object parameters, or null
    // where it is drawn object by object.
    BatchedPass* batchedPass(const fx::CompiledPass& pass, size_t passIndex, const PassUse& use);
    static bool orderFree(const RenderStateBlock& states);
    // Draws mVisible as one instanced draw per mesh (BatchedPass.h).
    void drawBatched(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program, const PassUse& use,
                     BatchedPass& batched, const RenderStateBlock& states);

    EffectResources& mResources;
    const Scene& mScene;
    const FrameOptions& mOptions;
    fx::DiagnosticSink& mDiagnostics;
    FrameStats& mStats;
    PassTimer mTimer{mOptions.timePasses, mStats, mResources.frameScratch.timerQueries};
    size_t mTechnique;
    const SemanticBinder& mBinder;
    const std::vector<PassUse>& mUses;
    const FramePlan& mPlan;
    size_t mNextOp = 0;
    bool mPlanFollowed = true;
    size_t mCurrentPass = 0;
    int mPassOps = 0;
    std::array<int, 4> mPassLeftOut{};                     // per LeftOut reason
    std::vector<std::pair<size_t, GLuint>> mTexelQueries;  // (PassStats index, GL_SAMPLES_PASSED query)
    // Working lists kept between frames (EffectResources::FrameScratch).
    std::vector<uint32_t>& mVisible;
    std::vector<bool>& mPerObject;
    std::vector<uint32_t>& mContext;
    std::vector<size_t>& mBatchOfMesh;
    std::vector<size_t>& mObjectBatch;
    std::vector<uint32_t>& mInstanceList;
    std::vector<fx::Value>& mArguments;
    using Batch = EffectResources::FrameScratch::Batch;
    std::vector<Batch>& mBatches;
    RenderTargets mTargets;
    const GpuTexture* mHostPicture = nullptr;  // painted this frame (hostPicture())
    RenderPortView mPort;
    bool mLightPort = false;
    const Light* mPortLight = nullptr;
    std::array<float, 4> mClearColor{0.0f, 0.0f, 0.0f, 0.0f};  // D3D's Clear defaults
    float mClearDepth = 1.0f;
    int mClearStencil = 0;
    const bool mStencilUnread;  // no pass tests stencil: depth clears take it along (techniqueTestsStencil)
    bool mFailed = false;
    bool mCullClosedOnly = false;  // the pass's CullClosedOnly applies (passStates)
    std::set<size_t> mWarnedPasses;
    std::set<const fx::CompiledPass*> mWarnedDepthSizes;  // passes warned of a smaller depth target
};

}  // namespace runtime
