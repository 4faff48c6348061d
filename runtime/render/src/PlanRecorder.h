// PlanRecorder: the dry run of a frame. Follows the technique's script as FrameExecutor will, on a copy of
// the parameter values, and records every clear and draw with its targets, sampled textures, signature,
// render states and receiver region (FramePlan). No GL.
#pragma once

#include "EffectResources.h"
#include <private/runtime/FramePlan.h>
#include "PassUse.h"
#include "ScriptInterpreter.h"
#include "SemanticBinder.h"

#include <runtime/EffectRenderer.h>
#include <runtime/Scene.h>

#include <array>
#include <string>
#include <vector>

namespace runtime {

class PlanRecorder : public ScriptTarget {
public:
    static constexpr int kNone = -1000;     // an unbound colour slot
    static constexpr int kUnknown = -1001;  // a target the executor will reject

    // `body`: the camera's intersection body (receivers' region for light passes); `diagnostics` gets the
    // render states' evaluation errors (the states are evaluated here, once per pass, for the executor).
    PlanRecorder(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                 const SemanticBinder& binder, const std::vector<PassUse>& uses, size_t technique,
                 const std::vector<glm::vec3>& body, FramePlan& plan, fx::DiagnosticSink& diagnostics);

    void beginPass(const fx::CompiledPass& pass) override;
    void setColorTarget(int index, const std::string& texture, int parameter) override;
    void setDepthTarget(const std::string& texture, int parameter) override;
    void setRenderPort(const std::string& light, int lightSlot, int cascade, const fx::SourceLoc&) override;
    void setClearColor(const fx::Value& color) override {
        mClearColor.assign(color.data.begin(), color.data.end());
    }
    void setClearDepth(float depth) override { mClearDepth = depth; }
    void setClearStencil(int stencil) override { mClearStencil = stencil; }
    void clear(fx::ScriptCommand::ClearWhat what, int colorTarget) override;
    void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) override;
    // A dispatch draws nothing: no operation of the plan (what it writes reaches draws through
    // StorageResources::dispatches).
    void dispatch(const fx::CompiledPass&, const std::array<uint32_t, 3>&, const fx::SourceLoc&) override {}
    // The host's scene draw writes the bound targets like a pass of its own; its signature changes with
    // the scene and the camera, so it is never taken for cached.
    void drawScene(const fx::ScriptCommand& command) override;
    const fx::Value* parameter(size_t index) const override { return &mValues[index]; }
    void setLoopIndex(const std::string& name, int parameter, int index) override;

private:
    size_t passIndex(const fx::CompiledPass& pass) const;
    int resource(int parameter) const;
    bool sceneSaysSkip(const fx::CompiledPass& pass) const;
    static float receiverPadTexels(const fx::CompiledPass& pass);
    glm::mat4 cascadeSlice() const;
    uint64_t hostPictureSignature() const;
    // The bound colour targets, into `targets` (its storage kept).
    void colorTargets(std::vector<int>& targets) const;
    glm::vec2 targetSize() const;

    EffectResources& mResources;
    const Scene& mScene;
    const FrameOptions& mOptions;
    const SemanticBinder& mBinder;
    const std::vector<PassUse>& mUses;
    size_t mTechnique;
    const std::vector<glm::vec3>& mBody;
    FramePlan& mPlan;
    fx::DiagnosticSink& mDiagnostics;
    ParameterValues& mValues;  // the dry run's copy of the parameter values (kept between frames)
    std::array<int, RenderTargets::kMaxColorTargets> mColors{};
    int mDepth = kFrameDepth;
    bool mLightPort = false;
    RenderPortView mPort;
    size_t mPass = 0;
    bool mSceneSaysSkip = false;
    float mPadTexels = 0.0f;          // receiverPadTexels of the current pass
    const bool mStencilTested;        // a pass tests stencil: a depth clear keeps it (techniqueTestsStencil)
    std::vector<float>& mClearColor;  // kept between frames
    float mClearDepth = 1.0f;
    int mClearStencil = 0;
};

}  // namespace runtime
