// PlanRecorder: see PlanRecorder.h.
#include "PlanRecorder.h"

#include <runtime/IntersectionBody.h>
#include "PassBindings.h"
#include "RenderPort.h"

#include <algorithm>

namespace runtime {

namespace {

// Filter footprint the receiver region keeps around every receiver, in shadow-map texels: bilinear PCF
// reads one texel around the lookup, the thesis effect's jitter up to JITTER_AMOUNT / 2 = 2 texels.
constexpr float kReceiverPadTexels = 8.0f;

}  // namespace

PlanRecorder::PlanRecorder(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                           const SemanticBinder& binder, const std::vector<PassUse>& uses, size_t technique,
                           const std::vector<glm::vec3>& body, FramePlan& plan,
                           fx::DiagnosticSink& diagnostics)
    : mResources(resources),
      mScene(scene),
      mOptions(options),
      mBinder(binder),
      mUses(uses),
      mTechnique(technique),
      mBody(body),
      mPlan(plan),
      mDiagnostics(diagnostics),
      mValues(resources.frameScratch.planValues),
      mPadTexels(kReceiverPadTexels),
      mStencilTested(techniqueTestsStencil(resources.effect().techniques[technique])),
      mClearColor(resources.frameScratch.planClearColor) {
    mValues.copyFrom(resources.values);
    mClearColor.clear();
    mColors.fill(kNone);
    mColors[0] = kFrameColor;
    setRenderPort("", -1, -1, {});
}

void PlanRecorder::beginPass(const fx::CompiledPass& pass) {
    mPass = passIndex(pass);
    mSceneSaysSkip = sceneSaysSkip(pass);
    mPadTexels = receiverPadTexels(pass);
}

void PlanRecorder::setColorTarget(int index, const std::string& texture, int parameter) {
    if (index < 0 || index >= RenderTargets::kMaxColorTargets) return;
    mColors[static_cast<size_t>(index)] =
        texture.empty() ? (index == 0 ? kFrameColor : kNone) : resource(parameter);
}

void PlanRecorder::setDepthTarget(const std::string& texture, int parameter) {
    mDepth = texture.empty() ? kFrameDepth : resource(parameter);
}

void PlanRecorder::setRenderPort(const std::string& light, int lightSlot, int cascade, const fx::SourceLoc&) {
    mLightPort = !light.empty();
    portMatrices(mScene, mBinder, mOptions, light, lightSlot, cascade, mPort);
}

void PlanRecorder::clear(fx::ScriptCommand::ClearWhat what, int colorTarget) {
    PlannedOp& op = mPlan.add();
    op.pass = mPass;
    op.lightPort = mLightPort;
    uint64_t value = 0;
    switch (what) {
        case fx::ScriptCommand::ClearWhat::Color:
            op.kind = PlannedOp::Kind::ClearColor;
            colorTargets(op.writes);
            // Clear=SV_TARGETn: that target alone (the compiled file's reader keeps n below the targets).
            if (colorTarget >= 0 && colorTarget < RenderTargets::kMaxColorTargets) {
                const int target = mColors[static_cast<size_t>(colorTarget)];
                op.writes.clear();
                if (target != kNone) op.writes.push_back(target);
            }
            value = hashCombine(hashBytes(0, mClearColor.data(), mClearColor.size() * sizeof(float)),
                                static_cast<uint64_t>(colorTarget + 1));
            break;
        case fx::ScriptCommand::ClearWhat::Depth:
            op.kind = PlannedOp::Kind::ClearDepth;
            if (mDepth != kNone) op.writes = {mDepth};
            value = hashBytes(0, &mClearDepth, sizeof(mClearDepth));
            if (mStencilTested) {  // the stencil bits survive the clear for a later pass's test
                op.wholeTarget = false;
                op.reads = op.writes;
            }
            break;
        case fx::ScriptCommand::ClearWhat::Stencil:
            op.kind = PlannedOp::Kind::ClearStencil;
            if (mDepth != kNone) op.writes = {mDepth};
            value = static_cast<uint64_t>(mClearStencil);
            break;
    }
    op.signature = hashCombine(hashCombine(static_cast<uint64_t>(op.kind) + 1, mPass), value);
    if (mPort.cascade >= 0) {
        // A cascade port clears its tile only (D3D clears the viewport): the rest of the target stays.
        op.wholeTarget = false;
        op.reads = op.writes;
        op.signature = hashCombine(op.signature, static_cast<uint64_t>(mPort.cascade) + 1);
    }
    op.sceneSaysSkip = mSceneSaysSkip;
}

void PlanRecorder::drawScene(const fx::ScriptCommand&) {
    PlannedOp& op = mPlan.add();
    op.kind = PlannedOp::Kind::DrawGeometry;
    op.pass = mPass;
    op.hostScene = true;
    colorTargets(op.writes);
    op.reads = op.writes;
    if (mDepth != kNone) {
        op.writes.push_back(mDepth);
        op.reads.push_back(mDepth);
    }
    uint64_t h = hashCombine(0x486f737453636e65ull, mResources.sceneCache.stamp());  // "HostScne"
    h = hashBytes(h, &mPort.view, sizeof(mPort.view));
    op.signature = hashBytes(h, &mPort.projection, sizeof(mPort.projection));
}

// What the host's picture of the scene (FrameExecutor::hostPicture) shows: the objects, the camera, the
// first light of HostScenePainter's lighting, and its size (the frame's).
uint64_t PlanRecorder::hostPictureSignature() const {
    uint64_t h = hashCombine(0x486f737450696374ull, mResources.sceneCache.stamp());  // "HostPict"
    h = hashCombine(h, (static_cast<uint64_t>(static_cast<uint32_t>(mOptions.width)) << 32) |
                           static_cast<uint32_t>(mOptions.height));
    RenderPortView camera;
    if (portMatrices(mScene, mBinder, mOptions, "", -1, -1, camera)) {
        h = hashBytes(h, &camera.view, sizeof(camera.view));
        h = hashBytes(h, &camera.projection, sizeof(camera.projection));
    }
    if (!mScene.lights.empty()) {
        const Light& light = mScene.lights.front();
        h = hashBytes(h, &light.position, sizeof(light.position));
        h = hashBytes(h, &light.direction, sizeof(light.direction));
        h = hashBytes(h, &light.color, sizeof(light.color));
        h = hashCombine(h, static_cast<uint64_t>(light.type));
    }
    return h;
}

void PlanRecorder::draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) {
    const size_t index = passIndex(pass);
    const GpuProgram* program = mResources.programs->program(mTechnique, index);
    // FrameExecutor warns and skips it too.
    if (!program || !program->hasShaders() || program->isCompute()) return;
    PlannedOp& op = mPlan.add();
    op.kind = what == fx::ScriptCommand::DrawWhat::Buffer ? PlannedOp::Kind::DrawBuffer
                                                          : PlannedOp::Kind::DrawGeometry;
    op.pass = index;
    op.lightPort = mLightPort;
    // The pass's render states, evaluated here once for the executor (PlannedOp::states). Bound targets are
    // read (blending, depth and stencil tests); they are written unless the states mask the writes (the
    // hardware shadow map's ColorWriteEnable = 0, BlendOp=min without Z).
    op.states = mResources.programs->preshaders(mTechnique, index)
                    .states(mValues.all(), mValues.stamps(), mDiagnostics);
    const RenderStateBlock& states = op.states;
    static constexpr fx::RenderStateId kColorWrites[] = {
        fx::RenderStateId::ColorWriteEnable, fx::RenderStateId::ColorWriteEnable1,
        fx::RenderStateId::ColorWriteEnable2, fx::RenderStateId::ColorWriteEnable3};
    for (size_t slot = 0; slot < mColors.size(); ++slot) {
        if (mColors[slot] == kNone) continue;
        op.reads.push_back(mColors[slot]);
        if (states.get(kColorWrites[slot]) != 0.0) op.writes.push_back(mColors[slot]);
    }
    if (mDepth != kNone) {
        // Without the depth and stencil tests a draw neither reads nor writes its depth target: the thesis
        // effect's BlendOp=min map pass binds one with ZEnable = false, and clearing it every frame for
        // nobody cost a 2048² D24S8 clear.
        const bool depthTest = states.get(fx::RenderStateId::ZEnable) != 0.0;
        const bool stencilTest = states.get(fx::RenderStateId::StencilEnable) != 0.0;
        if (depthTest || stencilTest) op.reads.push_back(mDepth);
        const bool depthWrites = depthTest && states.get(fx::RenderStateId::ZWriteEnable) != 0.0;
        if (depthWrites || stencilTest) op.writes.push_back(mDepth);
    }
    // Stream output: what the pass captures, and whether it rasterizes at all (GL_RASTERIZER_DISCARD
    // writes no target); a DrawAuto pass reads the capture it draws.
    if (pass.streamOut) {
        if (!pass.streamOut->rasterizes) op.writes.clear();
        op.writes.push_back(passOutputResource(index));
    } else if (passWritesStorage(pass)) {
        // A pass drawing into no target but a buffer (an irregular z-buffer's list building) is not dead.
        op.writes.push_back(passOutputResource(index));
    }
    if (pass.drawAuto >= 0) op.reads.push_back(passOutputResource(static_cast<size_t>(pass.drawAuto)));
    for (const fx::StageProgram* stage :
         {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute})
        for (const fx::SamplerBinding& binding : stage->samplers) {
            const fx::SamplerDesc* desc = mResources.effect().findSampler(binding.samplerParameter);
            if (binding.textureParameter)
                op.reads.push_back(static_cast<int>(*binding.textureParameter));
            else if (desc && desc->texture)
                op.reads.push_back(static_cast<int>(*desc->texture));
        }

    const PassUse& use = mUses[index];
    mPort.viewportSize = targetSize();
    if (mPort.cascade >= 0) {
        const glm::ivec4 tile = portTile(mBinder, mScene, mPort, static_cast<int>(mPort.viewportSize.x),
                                         static_cast<int>(mPort.viewportSize.y));
        mPort.viewportSize = glm::vec2(tile.z, tile.w);
    }
    mValues.bindSemantics(mBinder, mPort, nullptr, mOptions.time, SemanticBinder::Scope::PerPort, &use.used);
    uint64_t h = hashCombine(hashCombine(static_cast<uint64_t>(op.kind) + 1, mTechnique), index);
    // Field by field: the struct's padding bytes are not part of its value.
    h = hashBytes(h, &mPort.view, sizeof(mPort.view));
    h = hashBytes(h, &mPort.projection, sizeof(mPort.projection));
    h = hashBytes(h, &mPort.viewportSize, sizeof(mPort.viewportSize));
    h = hashCombine(h, mPort.shinesIntoPositiveW ? 1 : 0);
    h = hashCombine(hashCombine(h, static_cast<uint64_t>(mPort.lightIndex + 1)),
                    static_cast<uint64_t>(mPort.cascade + 1));
    for (size_t p : use.perPassParameters)
        h = hashBytes(hashCombine(h, p), mValues[p].data.data(), mValues[p].data.size() * sizeof(float));
    if (op.kind == PlannedOp::Kind::DrawGeometry) h = hashCombine(h, mResources.sceneCache.stamp());
    if (readsHostPicture(mResources, pass)) h = hashCombine(h, hostPictureSignature());
    for (const fx::StageProgram* stage :
         {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment})
        if (!stage->storageBuffers.empty() || !stage->images.empty())
            h = hashCombine(h, mResources.storage->dispatches());
    op.signature = h;
    op.sceneSaysSkip = mSceneSaysSkip;
    if (mLightPort && op.kind == PlannedOp::Kind::DrawGeometry) {
        const LightFit portFit = mPort.cascade >= 0
                                     ? mBinder.lightFit(mScene.lights[static_cast<size_t>(mPort.lightIndex)])
                                     : LightFit{};
        if (portFit.cubeFaces) {
            // A PSMCube face serves the receivers of B within its pyramid (its window is fitted to
            // them); a face that none uses is left out.
            op.sceneSaysSkip =
                op.sceneSaysSkip || !portFit.cascades[static_cast<size_t>(mPort.cascade)].serves;
            op.region = receiverRegion(mBody, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
        } else if (mPort.cascade >= 0) {
            // A cascade serves the receivers of its own depth slice only: its casters are culled to that
            // slice, and a slice beyond the farthest receiver has nothing to serve.
            const InstanceBvh& bvh = mResources.sceneCache.bvh();
            const glm::mat4 slice = cascadeSlice();
            std::vector<glm::vec3>& body = mResources.frameScratch.sliceBody;
            std::vector<uint32_t>& receivers = mResources.frameScratch.sliceObjects;
            body.clear();
            receivers.clear();
            if (!bvh.empty()) {
                intersectionBodyPoints(slice, Bounds{bvh.rootBox().min, bvh.rootBox().max}, body);
                const ConvexVolume frustum = frustumPlanes(slice);
                bvh.query([&](const Aabb& box) { return overlapVolume(frustum, box); }, receivers);
                op.sceneSaysSkip = op.sceneSaysSkip || receivers.empty();
            }
            op.region = receiverRegion(body, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
        } else {
            op.region = receiverRegion(mBody, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
        }
        op.region.castersBehindLightPlaneCastNothing = mPort.shinesIntoPositiveW;
    }
}

void PlanRecorder::setLoopIndex(const std::string&, int parameter, int index) {
    if (parameter >= 0) mValues.storeScalar(static_cast<size_t>(parameter), static_cast<float>(index));
}

size_t PlanRecorder::passIndex(const fx::CompiledPass& pass) const {
    return static_cast<size_t>(&pass - mResources.effect().techniques[mTechnique].passes.data());
}

int PlanRecorder::resource(int parameter) const {
    if (parameter < 0) return kUnknown;
    const size_t index = static_cast<size_t>(parameter);
    const fx::TextureDesc* desc = mResources.effect().findTexture(index);
    if (!mResources.textures->find(index) && !(desc && isRenderTarget(*desc))) return kUnknown;
    return parameter;
}

// A pass annotated `string LeaveOutWhen = "NoClosedObjects";` (no object's mesh is closed: a second
// depth layer finds nothing) or "NoLightArea" (no light has an area: no soft-shadow filter needed) is
// left out where that holds. The effect guarantees that later passes do not need what it writes then.
bool PlanRecorder::sceneSaysSkip(const fx::CompiledPass& pass) const {
    switch (pass.leaveOutWhen) {
        case fx::LeaveOutCondition::Never:
            return false;
        case fx::LeaveOutCondition::NoClosedObjects:
            return std::none_of(mScene.objects.begin(), mScene.objects.end(),
                                [](const SceneObject& o) { return o.mesh && o.mesh->closed; });
        case fx::LeaveOutCondition::NoLightArea:
            return std::all_of(mScene.lights.begin(), mScene.lights.end(),
                               [](const Light& light) { return light.areaRadius <= 0.0f; });
    }
    return false;
}

// How far around a receiver's own texel the passes reading this light pass's map look, in texels: what
// the pass declares (`float FilterReachTexels = 65;` on a map read by a PCSS blocker search, 2 for 2x2
// bilinear PCF), else kReceiverPadTexels, so that light-pass culling keeps every caster they can see.
// A declared reach matters most for warped maps (LiSPSM), whose far texels are large in world units.
float PlanRecorder::receiverPadTexels(const fx::CompiledPass& pass) {
    return pass.filterReachTexels > 0.0f ? pass.filterReachTexels : kReceiverPadTexels;
}

// The current cascade's slice of the camera frustum (between its split depths) as a view-projection:
// its casters are culled to B within it, and a slice no object's box meets has no receiver to serve.
glm::mat4 PlanRecorder::cascadeSlice() const {
    const Light& light = mScene.lights[static_cast<size_t>(mPort.lightIndex)];
    const LightView cascade = mBinder.lightFit(light).cascades[static_cast<size_t>(mPort.cascade)];
    Camera slice = mScene.camera;
    slice.nearPlane = cascade.splitNear;
    slice.farPlane = cascade.splitFar;
    const float aspect = static_cast<float>(mOptions.width) / static_cast<float>(mOptions.height);
    return slice.projection(aspect) * slice.view();
}

void PlanRecorder::colorTargets(std::vector<int>& targets) const {
    targets.clear();
    for (int target : mColors)
        if (target != kNone) targets.push_back(target);
}

glm::vec2 PlanRecorder::targetSize() const {
    for (int target : {mColors[0], mDepth}) {
        if (target == kFrameColor || target == kFrameDepth) return glm::vec2(mOptions.width, mOptions.height);
        if (target < 0) continue;
        const fx::TextureDesc* desc = mResources.effect().findTexture(static_cast<size_t>(target));
        if (desc) return glm::vec2(renderTargetSize(*desc, mOptions.width, mOptions.height));
    }
    return glm::vec2(mOptions.width, mOptions.height);
}

}  // namespace runtime
