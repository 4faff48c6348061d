// FrameExecutor: see FrameExecutor.h.
#include "FrameExecutor.h"

#include "ComputeDispatch.h"

#include <runtime/GlDebug.h>
#include <runtime/IntersectionBody.h>
#include "PassBindings.h"
#include "RenderPort.h"
#include <runtime/RenderStateApplier.h>

#include <algorithm>
#include <cstring>

namespace runtime {

FrameExecutor::FrameExecutor(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                             fx::DiagnosticSink& diagnostics, FrameStats& stats, size_t techniqueIndex,
                             const SemanticBinder& binder, const std::vector<PassUse>& uses,
                             const FramePlan& plan)
    : mResources(resources),
      mScene(scene),
      mOptions(options),
      mDiagnostics(diagnostics),
      mStats(stats),
      mTechnique(techniqueIndex),
      mBinder(binder),
      mUses(uses),
      mPlan(plan),
      mVisible(resources.frameScratch.visible),
      mPerObject(resources.frameScratch.perObject),
      mContext(resources.frameScratch.context),
      mBatchOfMesh(resources.frameScratch.batchOfMesh),
      mObjectBatch(resources.frameScratch.objectBatch),
      mInstanceList(resources.frameScratch.instances),
      mArguments(resources.frameScratch.arguments),
      mBatches(resources.frameScratch.batches),
      mStencilUnread(!techniqueTestsStencil(resources.effect().techniques[techniqueIndex])) {
    mTargets.colors[0].texture = &resources.textures->frameColor();
    mTargets.depth.texture = &resources.textures->frameDepth();
    setRenderPort("", -1, -1, {});
}

void FrameExecutor::finish() {
    closePass();
    for (const auto& [pass, query] : mTexelQueries) {
        GLuint64 samples = 0;
        gl::GetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
        mStats.passes[pass].texelsWritten += samples;
        gl::DeleteQueries(1, &query);
    }
    for (const PassStats& pass : mStats.passes) {
        if (pass.leftOut.empty()) {
            ++mStats.passesRun;
        } else {
            ++mStats.passesLeftOut;
        }
    }
    mTimer.finish();
}

void FrameExecutor::beginPass(const fx::CompiledPass& pass) {
    closePass();
    mCurrentPass = static_cast<size_t>(&pass - mResources.effect().techniques[mTechnique].passes.data());
    PassStats record;
    record.pass = pass.name;
    mStats.passes.push_back(record);
    mPassOps = 0;
    mPassLeftOut.fill(0);
    mTimer.beginPass(pass.name);
}

void FrameExecutor::setColorTarget(int index, const std::string& texture, int parameter) {
    if (index < 0 || index >= RenderTargets::kMaxColorTargets) return;
    if (texture.empty()) {
        mTargets.colors[static_cast<size_t>(index)] =
            RenderTargetAttachment::wholeOf(index == 0 ? &mResources.textures->frameColor() : nullptr);
        return;
    }
    mTargets.colors[static_cast<size_t>(index)] = RenderTargetAttachment::wholeOf(target(texture, parameter));
}

void FrameExecutor::setDepthTarget(const std::string& texture, int parameter) {
    mTargets.depth = RenderTargetAttachment::wholeOf(texture.empty() ? &mResources.textures->frameDepth()
                                                                     : target(texture, parameter));
}

void FrameExecutor::setRenderPort(const std::string& lightName, int lightSlot, int cascade,
                                  const fx::SourceLoc& loc) {
    mLightPort = !lightName.empty();
    mPortLight = mLightPort ? mBinder.slotLight(lightSlot) : nullptr;
    RenderPortError error;
    if (!portMatrices(mScene, mBinder, mOptions, lightName, lightSlot, cascade, mPort, &error)) {
        if (!mFailed)
            mDiagnostics.report(error.id, loc.valid() ? loc : fx::SourceLoc{mResources.effect().path, 0, 0},
                                error.args);
        mFailed = true;
    }
}

void FrameExecutor::setClearColor(const fx::Value& color) {
    for (size_t i = 0; i < 4; ++i)
        mClearColor[i] = i < color.data.size() ? color.data[i] : (i == 3 ? 1.0f : 0.0f);
    if (color.data.size() == 1) mClearColor = {color.data[0], color.data[0], color.data[0], color.data[0]};
}

void FrameExecutor::clear(fx::ScriptCommand::ClearWhat what, int colorTarget) {
    const PlannedOp::Kind kind = what == fx::ScriptCommand::ClearWhat::Color ? PlannedOp::Kind::ClearColor
                                 : what == fx::ScriptCommand::ClearWhat::Depth
                                     ? PlannedOp::Kind::ClearDepth
                                     : PlannedOp::Kind::ClearStencil;
    if (leftOut(nextOp(kind, mCurrentPass))) return;
    const bool colour = what == fx::ScriptCommand::ClearWhat::Color;
    const bool depthAlone = !colour && clearsDepthAlone();
    if (!bindTargets(!colour, depthAlone)) return;
    const bool tileOnly = mPort.cascade >= 0;  // D3D clears the viewport: a cascade port its tile
    if (tileOnly) {
        const glm::ivec4 tile = portTile(mBinder, mScene, mPort, mTargets.width(), mTargets.height());
        gl::Enable(GL_SCISSOR_TEST);
        gl::Scissor(tile.x, tile.y, tile.z, tile.w);
    }
    ClearRequest request;
    uint64_t texels = 0;
    switch (what) {
        case fx::ScriptCommand::ClearWhat::Color:
            request.color = mClearColor;
            for (size_t i = 0; i < mTargets.colors.size(); ++i)
                if (mTargets.colors[i].texture && (colorTarget < 0 || i == static_cast<size_t>(colorTarget)))
                    texels += texelCount(*mTargets.colors[i].texture);
            break;
        case fx::ScriptCommand::ClearWhat::Depth:
            request.depth = mClearDepth;
            if (mTargets.depth.texture) {
                texels += texelCount(*mTargets.depth.texture);
                if (mStencilUnread && mTargets.depth.texture->glFormat().hasStencil) request.stencil = 0;
            }
            break;
        case fx::ScriptCommand::ClearWhat::Stencil:
            if (mTargets.depth.texture && mTargets.depth.texture->glFormat().hasStencil) {
                request.stencil = mClearStencil;
                texels += texelCount(*mTargets.depth.texture);
            }
            break;
    }
    {
        PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
        FramebufferCache::clear(request, colorTarget);
    }
    if (tileOnly) gl::Disable(GL_SCISSOR_TEST);  // every pass's states set it anew (RenderStateApplier)
    ++mStats.clears;
    if (PassStats* record = currentPass()) {
        ++record->clears;
        record->depthOnlyClears += depthAlone;
        record->texelsWritten += texels;
    }
}

void FrameExecutor::draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) {
    const size_t passIndex =
        static_cast<size_t>(&pass - mResources.effect().techniques[mTechnique].passes.data());
    GpuProgram* program = mResources.programs->program(mTechnique, passIndex);
    if (!program || !program->hasShaders() || program->isCompute()) {  // a compute pass dispatches
        if (mWarnedPasses.insert(passIndex).second) {
            mDiagnostics.report(fx::DiagId::PassWithoutShaders, pass.loc, {pass.name});
        }
        return;
    }
    const bool buffer = what == fx::ScriptCommand::DrawWhat::Buffer;
    const PlannedOp* op =
        nextOp(buffer ? PlannedOp::Kind::DrawBuffer : PlannedOp::Kind::DrawGeometry, passIndex);
    if (leftOut(op)) return;
    const RenderStateBlock& states = passStates(pass, passIndex, op);
    const bool usesDepth =
        states.get(fx::RenderStateId::ZEnable) != 0.0 || states.get(fx::RenderStateId::StencilEnable) != 0.0;
    RenderTargets framebuffer;
    if (!drawTargets(usesDepth, &pass, framebuffer)) return;
    const bool streams = pass.streamOut || pass.drawAuto >= 0;  // its vertices are not the meshes'
    GpuProgram* vertexOnly =
        mOptions.depthOnlyPasses && !streams ? depthOnly(pass, passIndex, states) : nullptr;
    if (vertexOnly) {
        program = vertexOnly;
        framebuffer = RenderTargets{};  // the depth-stencil target alone: draw buffers GL_NONE
        framebuffer.depth = mTargets.depth;
    }
    PassBinding binding;
    binding.framebuffer = &framebuffer;
    binding.depthBits = depthBiasBits(mTargets.depth.texture);
    binding.states = &states;
    mPort.viewportSize = glm::vec2(mTargets.width(), mTargets.height());
    if (mPort.cascade >= 0) {
        const glm::ivec4 tile = portTile(mBinder, mScene, mPort, mTargets.width(), mTargets.height());
        binding.viewport = tile;
        mPort.viewportSize = glm::vec2(tile.z, tile.w);
    } else if (vertexOnly) {
        // The colour targets' viewport, as D3D9 sets it: a larger depth target alone would set its own.
        binding.viewport = glm::ivec4(0, 0, mTargets.width(), mTargets.height());
    }
    const PassUse& use = mUses[passIndex];
    BatchedPass* batched = buffer || streams ? nullptr : batchedPass(pass, passIndex, use);
    if (batched) {
        GpuProgram* variant = batched->program(vertexOnly != nullptr);
        if (variant) {
            program = variant;
        } else {
            batched = nullptr;
        }
    }
    binding.program = program;
    // The vertex-only variant has no pixel stage to read it.
    if (!vertexOnly && readsHostPicture(mResources, pass)) binding.hostPicture = hostPicture();
    {
        PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
        FramebufferFault fault;
        if (!bindPass(mResources, mTechnique, passIndex, binding, mDiagnostics, fault)) {
            const auto [id, arguments] = fault.diagnostic(fx::DiagId::ScriptTargetsUnbindable, {});
            fail(id, arguments);
            return;
        }
    }
    if (mOptions.leaveOut) {
        // Per-frame and per-port values once per pass; drawWith() then binds only per-object ones.
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        mResources.values.bindSemantics(mBinder, mPort, nullptr, mOptions.time,
                                        SemanticBinder::Scope::PerPort, &use.used);
    }
    evaluateArguments(passIndex, use, false);

    const int drawsBefore = mStats.draws;
    GLuint query = 0;
    if (mOptions.countTexels) {
        gl::GenQueries(1, &query);
        gl::BeginQuery(GL_SAMPLES_PASSED, query);
    }
    StreamOutBuffers* capture =
        pass.streamOut ? mResources.programs->streamOut(mTechnique, passIndex) : nullptr;
    if (capture) {
        if (!pass.streamOut->rasterizes) gl::Enable(GL_RASTERIZER_DISCARD);
        capture->begin();
    }
    if (pass.drawAuto >= 0) {
        drawCapture(pass, passIndex, *program, use);
    } else if (buffer) {
        drawWith(pass, passIndex, *program, use, nullptr, mResources.quad);
    } else {
        mVisible.clear();
        mVisible.reserve(mScene.objects.size());  // once: the list then never outgrows its storage
        // What a pass streams out must not depend on the view: it draws every object.
        const bool culling = mOptions.leaveOut && mResources.sceneCache.valid() &&
                             use.projectsWith(mPortLight, mBinder) && !capture;
        // The executor runs after the scene cache was updated with its scene (EffectRenderer::render).
        const std::vector<uint32_t>& drawable = mResources.sceneCache.drawable();
        if (culling) {
            cull(op, mVisible);
        } else {
            mVisible.assign(drawable.begin(), drawable.end());
        }
        const int culled = culling ? static_cast<int>(drawable.size() - mVisible.size()) : 0;
        // A light pass of shadow casters alone: an object the scene declares a receiver only (a ground under
        // a sun) would cover the map and shadow nothing but itself, where the truth and osgShadow's casters
        // mask leave it out. Not counted as culled: no volume test dropped it.
        if (pass.castersOnly)
            mVisible.erase(std::remove_if(mVisible.begin(), mVisible.end(),
                                          [&](uint32_t index) { return !mScene.objects[index].castsShadow; }),
                           mVisible.end());
        if (batched) {
            drawBatched(pass, passIndex, *program, use, *batched, states);
        } else {
            for (uint32_t index : mVisible) {
                const SceneObject& object = mScene.objects[index];
                drawWith(pass, passIndex, *program, use, &object, mResources.gpuMesh(object.mesh));
            }
        }
        if (culling) {
            mStats.culled += culled;
            if (PassStats* record = currentPass()) record->culled += culled;
        }
    }
    if (capture) {
        capture->end();
        gl::Disable(GL_RASTERIZER_DISCARD);
    }
    if (PassStats* record = currentPass(); record && vertexOnly)
        record->depthOnlyDraws += mStats.draws - drawsBefore;
    if (query) {
        gl::EndQuery(GL_SAMPLES_PASSED);
        if (!mStats.passes.empty())
            mTexelQueries.emplace_back(mStats.passes.size() - 1, query);
        else
            gl::DeleteQueries(1, &query);
    }
    // What the draws wrote to storage buffers and images reaches the next pass's reads only through a
    // barrier in GL, where D3D11 orders a draw's UAV writes before later draws by itself (as after a
    // dispatch, ComputeDispatch.cpp).
    if (passWritesStorage(pass))
        gl::MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                          GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                          GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void FrameExecutor::dispatch(const fx::CompiledPass& pass, const std::array<uint32_t, 3>& groups,
                             const fx::SourceLoc& loc) {
    const size_t passIndex =
        static_cast<size_t>(&pass - mResources.effect().techniques[mTechnique].passes.data());
    {
        // The frame's and the render port's semantics (Time, the camera's matrices), as a draw binds them.
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        mResources.values.bindSemantics(mBinder, mPort, nullptr, mOptions.time,
                                        SemanticBinder::Scope::PerPort, &mUses[passIndex].used);
    }
    if (!bindComputePass(mResources, mTechnique, passIndex, mArguments, mDiagnostics)) {
        mDiagnostics.report(fx::DiagId::DispatchNotCompute, loc, {pass.name});
        mFailed = true;
        return;
    }
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    if (!dispatchBoundCompute(mResources, pass, groups, mDiagnostics)) mFailed = true;
}

void FrameExecutor::drawScene(const fx::ScriptCommand&) {
    if (leftOut(nextOp(PlannedOp::Kind::DrawGeometry, mCurrentPass))) return;
    if (!bindTargets(true)) return;
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    paintHostScene(mPort.view, mPort.projection);
}

void FrameExecutor::paintHostScene(const glm::mat4& view, const glm::mat4& projection) {
    applyRenderStates(RenderStateBlock::defaults());
    for (const SceneObject& object : mScene.objects) {
        if (!object.mesh) continue;
        GpuMesh& mesh = mResources.gpuMesh(object.mesh);
        mResources.hostScene.draw(mScene, object, view, projection, mesh);
        ++mStats.draws;
        mStats.triangles += mesh.indexCount() / 3;
    }
}

const GpuTexture* FrameExecutor::hostPicture() {
    if (mHostPicture) return mHostPicture;
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    const GpuTexture& frame = mResources.textures->frameColor();
    const RenderTargets targets = mResources.textures->hostPictureTargets(frame.width(), frame.height());
    FramebufferFault fault;
    if (!bindPassTargets(mResources, targets, fault)) return nullptr;
    ClearRequest clear;
    clear.color = {kHostBackground.r, kHostBackground.g, kHostBackground.b, kHostBackground.a};
    clear.depth = 1.0f;
    clear.stencil = 0;
    FramebufferCache::clear(clear);
    RenderPortView camera;
    if (portMatrices(mScene, mBinder, mOptions, "", -1, -1, camera))
        paintHostScene(camera.view, camera.projection);
    mHostPicture = targets.colors[0].texture;
    return mHostPicture;
}

void FrameExecutor::setLoopIndex(const std::string& name, int parameter, int index) {
    if (parameter < 0) {
        fail(fx::DiagId::UnknownParameter, {name});
        return;
    }
    mResources.values.storeScalar(static_cast<size_t>(parameter), static_cast<float>(index));
    // A script's value of a `shared` parameter is the pool's, as an application's setter's is.
    mResources.pool.published(mResources, static_cast<size_t>(parameter));
}

void FrameExecutor::fail(fx::DiagId id, const std::vector<std::string>& args) {
    if (!mFailed) mDiagnostics.report(id, fx::SourceLoc{mResources.effect().path, 0, 0}, args);
    mFailed = true;
}

uint64_t FrameExecutor::texelCount(const GpuTexture& texture) {
    return static_cast<uint64_t>(texture.width()) * static_cast<uint64_t>(texture.height());
}

// The plan's record of the command about to run, or null once the frame left the plan (never
// expected: the dry run follows the same script over the same values).
const PlannedOp* FrameExecutor::nextOp(PlannedOp::Kind kind, size_t pass) {
    if (!mPlanFollowed) return nullptr;
    if (mNextOp >= mPlan.ops.size() || mPlan.ops[mNextOp].kind != kind || mPlan.ops[mNextOp].pass != pass) {
        mPlanFollowed = false;
        return nullptr;
    }
    ++mPassOps;
    return &mPlan.ops[mNextOp++];
}

// Counts a command the plan leaves out; true if it is left out.
bool FrameExecutor::leftOut(const PlannedOp* op) {
    if (!op || op->leftOut == LeftOut::No) return false;
    ++mPassLeftOut[static_cast<size_t>(op->leftOut)];
    return true;
}

void FrameExecutor::closePass() {
    PassStats* record = currentPass();
    int leftOut = 0;
    for (int count : mPassLeftOut) leftOut += count;
    if (!record || mPassOps == 0 || leftOut < mPassOps) return;
    static constexpr const char* kReasons[] = {"", "dead", "cached", "scene"};
    for (size_t reason = 1; reason < mPassLeftOut.size(); ++reason)
        if (mPassLeftOut[reason] > 0)
            record->leftOut += (record->leftOut.empty() ? "" : "+") + std::string(kReasons[reason]);
}

// Objects whose draws can change this pass's targets: inside the camera's frustum, or casters whose
// extrusion away from the light meets the camera's receivers (IntersectionBody.h).
void FrameExecutor::cull(const PlannedOp* op, std::vector<uint32_t>& visible) const {
    const InstanceBvh& bvh = mResources.sceneCache.bvh();
    CullCache::Volume volume;
    volume.sceneStamp = mResources.sceneCache.stamp();
    volume.viewProjection = mPort.projection * mPort.view;
    volume.lightPort = mLightPort;
    if (mLightPort) volume.region = op && op->cullToReceivers ? op->region : fullLightRegion();
    if (const std::vector<uint32_t>* kept = mResources.cullCache.find(volume)) {
        visible.insert(visible.end(), kept->begin(), kept->end());
        return;
    }
    mResources.cullCache.reserve(mScene.objects.size());
    std::vector<uint32_t>& list = mResources.cullCache.insert(volume);
    if (!mLightPort) {
        const ConvexVolume frustum = frustumPlanes(volume.viewProjection);
        bvh.query([&](const Aabb& box) { return overlapVolume(frustum, box); }, list);
    } else {
        mResources.cullCache.footprints(bvh, volume.sceneStamp, volume.viewProjection)
            .query(bvh, volume.region, list);
    }
    visible.insert(visible.end(), list.begin(), list.end());
}

const GpuTexture* FrameExecutor::target(const std::string& name, int parameter) {
    const std::optional<size_t> index =
        parameter >= 0 ? std::optional<size_t>(static_cast<size_t>(parameter)) : std::nullopt;
    const GpuTexture* texture = index ? mResources.textures->find(*index) : nullptr;
    if (!texture) {
        // Left unallocated because no operation that runs uses it (FramePlan): not an error.
        const fx::TextureDesc* desc = index ? mResources.effect().findTexture(*index) : nullptr;
        if (!desc || !isRenderTarget(*desc)) fail(fx::DiagId::ScriptUnknownTarget, {name});
        return nullptr;
    }
    return texture;
}

glm::ivec2 FrameExecutor::depthTargetSize() const {
    const RenderTargetAttachment& depth = mTargets.depth;
    if (!depth.texture) return glm::ivec2(0);
    return glm::ivec2(std::max(1, depth.texture->width() >> depth.level),
                      std::max(1, depth.texture->height() >> depth.level));
}

bool FrameExecutor::depthTargetIsSmaller() const {
    if (!mTargets.depth.texture) return false;
    const glm::ivec2 size = depthTargetSize();
    return size.x < mTargets.width() || size.y < mTargets.height();
}

// D3D9 wants a depth-stencil surface at least as large as the colour targets; GL draws and clears only
// where all attachments overlap. A clear or draw that uses neither depth nor stencil is bound without a
// smaller surface, so it covers its colour targets as D3D9's drivers did (a float shadow map drawn with
// ZEnable = false and the frame's depth buffer); a draw that tests them covers the overlap, with a warning.
bool FrameExecutor::drawTargets(bool usesDepth, const fx::CompiledPass* pass, RenderTargets& targets) {
    if (mFailed) return false;
    targets = mTargets;
    // A multisample colour target with a depth target of another sample count cannot be one framebuffer;
    // a pass that tests no depth is drawn without it, as above.
    const bool otherSamples = mTargets.depth.texture && mTargets.colors[0].texture &&
                              mTargets.depth.texture->samples() != mTargets.colors[0].texture->samples();
    if (otherSamples && !usesDepth) targets.depth = {};
    dropDepthOfOtherLayering(targets);
    if (depthTargetIsSmaller()) {
        if (!usesDepth) {
            targets.depth = {};
        } else if (pass && mWarnedDepthSizes.insert(pass).second) {
            const auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
            const glm::ivec2 depthSize = depthTargetSize();
            mDiagnostics.report(
                fx::DiagId::DepthTargetSmaller, pass->loc,
                {pass->name, size(mTargets.width(), mTargets.height()), size(depthSize.x, depthSize.y)});
        }
    }
    return true;
}

bool FrameExecutor::bindTargets(bool usesDepth, bool depthAlone) {
    RenderTargets targets;
    if (!drawTargets(usesDepth, nullptr, targets)) return false;
    if (depthAlone && targets.depth.texture) {
        const RenderTargetAttachment depth = targets.depth;
        targets = RenderTargets{};
        targets.depth = depth;
    }
    FramebufferFault fault;
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    if (!bindPassTargets(mResources, targets, fault)) {
        const auto [id, arguments] = fault.diagnostic(fx::DiagId::ScriptTargetsUnbindable, {});
        fail(id, arguments);
        return false;
    }
    return true;
}

const RenderStateBlock& FrameExecutor::passStates(const fx::CompiledPass& pass, size_t passIndex,
                                                  const PlannedOp* op) {
    const RenderStateBlock* block = op ? &op->states : nullptr;
    if (!block) {
        PassTimer::Scope preshaderTime(mTimer, &FrameCpuTime::preshaderNs);
        block = &mResources.programs->preshaders(mTechnique, passIndex)
                     .states(mResources.values.all(), mResources.values.stamps(), mDiagnostics);
    }
    // The pass annotation `bool CullClosedOnly = true;`: its CullMode applies to closed (watertight)
    // meshes only, open ones are drawn with culling off. Back-face shadow maps (Wang & Molnar) and dual
    // depth layers with back-face culling (Weiskopf & Ertl 2003, §4: "back face culling for solid
    // objects can be mixed with non-culled open surfaces in the same scene") need both in one pass: a
    // culled open plane would vanish.
    mCullClosedOnly = pass.cullClosedOnly && block->get(fx::RenderStateId::CullMode) != 1.0;
    return *block;
}

// A pass that masks every colour write (the hardware shadow map's ColorWriteEnable = 0) still had its
// colour target bound and its pixel shader run for every fragment, only for the results to be thrown
// away; on llvmpipe that shading was most of the light pass's time. D3D9 leaves this to the driver; GL
// lets the runtime say it: a framebuffer with the depth-stencil target alone (draw buffers GL_NONE) and a
// program without a fragment stage. The pixel shader is kept where it can change depth or coverage
// (discard, clip, depth output: GpuProgram::pixelShaderHasSideEffects).
GpuProgram* FrameExecutor::depthOnly(const fx::CompiledPass& pass, size_t passIndex,
                                     const RenderStateBlock& states) {
    static constexpr fx::RenderStateId kColorWrites[] = {
        fx::RenderStateId::ColorWriteEnable, fx::RenderStateId::ColorWriteEnable1,
        fx::RenderStateId::ColorWriteEnable2, fx::RenderStateId::ColorWriteEnable3};
    // A smaller depth target alone would set a smaller viewport than the colour-bound draw's.
    if (!mTargets.depth.texture || depthTargetIsSmaller()) return nullptr;
    for (size_t slot = 0; slot < mTargets.colors.size(); ++slot)
        if (mTargets.colors[slot].texture && states.get(kColorWrites[slot]) != 0.0) return nullptr;
    if (GpuProgram::pixelShaderHasSideEffects(pass.fragment)) return nullptr;
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    // An optimization, not the effect's program: null where it did not link, and the full pass is drawn.
    return mResources.programs->depthOnlyProgram(mTechnique, passIndex, pass);
}

// A depth-only draw binds another framebuffer than its pass's depth clear did, and llvmpipe ends its binned
// scene at every change of framebuffer: the clear ran as a scene of its own over the whole target, then the
// draw's scene went over the same tiles again (on the teapot with a 2048² map, about a fifth of the frame's
// CPU time). A depth or stencil clear binds the draw's framebuffer instead, where every colour target is at
// least the depth target's size: GL clears where all attachments overlap, which is then the depth target
// either way. The draw is found in the plan (the pass's next draw, with the states the dry run evaluated);
// where the script rebinds targets in between, the clear is the same, only not the draw's framebuffer.
bool FrameExecutor::clearsDepthAlone() {
    if (!mOptions.depthOnlyPasses || !mPlanFollowed || !mTargets.depth.texture) return false;
    const glm::ivec2 depthSize = depthTargetSize();
    for (const RenderTargetAttachment& color : mTargets.colors)
        if (color.texture && (std::max(1, color.texture->width() >> color.level) < depthSize.x ||
                              std::max(1, color.texture->height() >> color.level) < depthSize.y))
            return false;
    const fx::CompiledTechnique& technique = mResources.effect().techniques[mTechnique];
    for (size_t i = mNextOp; i < mPlan.ops.size() && mPlan.ops[i].pass == mCurrentPass; ++i) {
        const PlannedOp& op = mPlan.ops[i];
        if (!op.isDraw()) continue;
        // The host's scene (ScriptExternal) is drawn by no pass: its op's pass is only the last one begun, 0
        // in a technique without passes (FX Composer's "preprocess" clears), and there is no depth-only
        // program to share a framebuffer with.
        if (op.hostScene) return false;
        if (op.leftOut != LeftOut::No && mOptions.leaveOut) return false;
        const fx::CompiledPass& pass = technique.passes[mCurrentPass];
        if (pass.streamOut || pass.drawAuto >= 0) return false;
        const GpuProgram* program = mResources.programs->program(mTechnique, mCurrentPass);
        if (!program || !program->hasShaders() || program->isCompute()) return false;
        return depthOnly(pass, mCurrentPass, op.states) != nullptr;
    }
    return false;
}

// Evaluates the pass's compile arguments into mArguments: with leave-out, the per-pass ones once per
// pass (perObject false) and the per-object ones per draw (perObject true); without, all per draw.
void FrameExecutor::evaluateArguments(size_t passIndex, const PassUse& use, bool perObject) {
    if (mOptions.leaveOut && perObject && !use.anyArgumentPerObject) return;  // nothing to run per draw
    PassTimer::Scope preshaderTime(mTimer, &FrameCpuTime::preshaderNs);
    const std::vector<bool>* which =
        mOptions.leaveOut ? (perObject ? &use.argumentPerObject : &use.argumentPerPass) : nullptr;
    evaluatePassArguments(mResources, mTechnique, passIndex, which, mArguments, mDiagnostics);
}

void FrameExecutor::drawWith(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program,
                             const PassUse& use, const SceneObject* object, GpuMesh& mesh) {
    {
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);  // the preshaders' time nested
        if (mOptions.leaveOut) {
            mResources.values.bindSemantics(mBinder, mPort, object, mOptions.time,
                                            SemanticBinder::Scope::PerObject, &use.used);
        } else {
            mResources.values.bindSemantics(mBinder, mPort, object, mOptions.time, SemanticBinder::Scope::All,
                                            nullptr);
        }
        evaluateArguments(passIndex, use, true);
        uploadPassValues(mResources, program, mArguments);
    }
    {
        PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
        const bool drawUnculled = mCullClosedOnly && object && !(object->mesh && object->mesh->closed);
        if (drawUnculled) gl::Disable(GL_CULL_FACE);
        mesh.draw(pass.vertex.inputs, 1, pass.patchVertices, pass.primitive);
        if (drawUnculled) gl::Enable(GL_CULL_FACE);
    }
    countDraw(mesh, 1);
}

// D3D10's DrawAuto: the vertices the pass named by `DrawAuto` captured last (the seed vertex before its
// first capture), drawn once with the per-frame values and no object's.
void FrameExecutor::drawCapture(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program,
                                const PassUse& use) {
    const StreamOutBuffers& source =
        *mResources.programs->streamOut(mTechnique, static_cast<size_t>(pass.drawAuto));
    {
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        mResources.values.bindSemantics(
            mBinder, mPort, nullptr, mOptions.time,
            mOptions.leaveOut ? SemanticBinder::Scope::PerObject : SemanticBinder::Scope::All,
            mOptions.leaveOut ? &use.used : nullptr);
    }
    evaluateArguments(passIndex, use, true);
    {
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        uploadPassValues(mResources, program, mArguments);
    }
    // A geometry shader takes the primitive its input declares; without one the vertices are drawn as
    // they were captured (or as the pass captures them, where it streams out itself).
    GLenum mode = pass.streamOut ? StreamOutBuffers::mode(pass.streamOut->primitive) : source.primitive();
    if (!pass.geometry.glsl.empty()) {
        using Primitive = fx::CompiledPass::DrawPrimitive;
        mode = pass.primitive == Primitive::Points               ? GL_POINTS
               : pass.primitive == Primitive::Lines              ? GL_LINES
               : pass.primitive == Primitive::TrianglesAdjacency ? GL_TRIANGLES_ADJACENCY
                                                                 : GL_TRIANGLES;
    }
    {
        PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
        source.drawLast(mode);
    }
    ++mStats.draws;
    mTimer.countDraw();
    if (PassStats* record = currentPass()) ++record->draws;
}

void FrameExecutor::countDraw(const GpuMesh& mesh, int objects) {
    const uint64_t triangles = mesh.indexCount() / 3 * static_cast<uint64_t>(objects);
    ++mStats.draws;
    mStats.objects += objects;
    mTimer.countDraw();
    mStats.triangles += triangles;
    if (PassStats* record = currentPass()) {
        ++record->draws;
        record->objects += objects;
        record->triangles += triangles;
    }
}

// [SECTION] Batching

BatchedPass* FrameExecutor::batchedPass(const fx::CompiledPass& pass, size_t passIndex, const PassUse& use) {
    // Per-frame values are bound once per pass only with leave-out; without it every draw binds all.
    if (!mOptions.batching || !mOptions.leaveOut) return nullptr;
    mPerObject.assign(use.used.size(), false);
    for (size_t p = 0; p < use.used.size(); ++p)
        mPerObject[p] = use.used[p] && !mResources.values.isPinned(p) && mBinder.isPerObject(p);
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);  // a variant is linked when the flags change
    return mResources.programs->batchedPass(mTechnique, passIndex, pass, mPerObject, use.argumentPerObject,
                                            use.viewDerived);
}

// True if drawing the pass's objects in another order leaves the same image: fragments that meet at a
// pixel are resolved by the depth test (strict or not, with depth writes) or by a min/max blend, and no
// stencil operation counts them. Draws whose states do not say so keep their order: only consecutive
// objects with the same mesh share an instanced draw. (Two different meshes' fragments at exactly the
// same depth would resolve to the one drawn first; coplanar surfaces of different meshes are rare and
// fight in any renderer.)
bool FrameExecutor::orderFree(const RenderStateBlock& states) {
    using Id = fx::RenderStateId;
    constexpr double kMin = 4, kMax = 5;  // D3DBLENDOP
    if (states.get(Id::StencilEnable) != 0.0 || states.get(Id::AlphaToCoverageEnable) != 0.0) return false;
    if (states.get(Id::AlphaBlendEnable) != 0.0) {
        const auto minMax = [](double op) { return op == kMin || op == kMax; };
        return minMax(states.get(Id::BlendOp)) &&
               (states.get(Id::SeparateAlphaBlendEnable) == 0.0 || minMax(states.get(Id::BlendOpAlpha)));
    }
    const double func = states.get(Id::ZFunc);  // D3DCMP: LESS 2, LESSEQUAL 4, GREATER 5, GREATEREQUAL 7
    return states.get(Id::ZEnable) != 0.0 && states.get(Id::ZWriteEnable) != 0.0 &&
           (func == 2 || func == 4 || func == 5 || func == 7);
}

void FrameExecutor::drawBatched(const fx::CompiledPass& pass, size_t passIndex, GpuProgram& program,
                                const PassUse& use, BatchedPass& batched, const RenderStateBlock& states) {
    // The objects' records: packed again only for objects that changed (whole) or whose view part derives
    // from something that did (the port's or a light's matrices, the other inputs of per-object compile
    // arguments: their values, since stamps change whenever passes with other ports bind them).
    mContext.clear();
    mBinder.objectContext(mPort, use.used, mContext);
    for (size_t a = 0; a < pass.arguments.size(); ++a) {
        if (a >= use.argumentPerObject.size() || !use.argumentPerObject[a]) continue;
        for (size_t p : pass.arguments[a].value.inputs()) {
            if (p >= mPerObject.size() || mPerObject[p]) continue;
            const std::vector<float>& data = mResources.values[p].data;
            const size_t at = mContext.size();
            mContext.resize(at + data.size() + 1);
            mContext[at] = static_cast<uint32_t>(p);
            if (!data.empty())
                std::memcpy(mContext.data() + at + 1, data.data(), data.size() * sizeof(float));
        }
    }
    batched.beginRecords(mContext, mScene.objects.size(), mResources.sceneCache.stamp());
    const auto bindObject = [&](const SceneObject& object, const std::vector<bool>& parameters) {
        mResources.values.bindSemantics(mBinder, mPort, &object, mOptions.time,
                                        SemanticBinder::Scope::PerObject, &parameters);
        evaluateArguments(passIndex, use, true);
    };
    {
        // The records timed as one binding scope, the preshaders' share nested (PassTimer::Scope).
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        // A few objects ahead: far enough that their records arrive before they are compared.
        constexpr size_t kPrefetchAhead = 8;
        for (size_t i = 0; i < mVisible.size(); ++i) {
            if (i + kPrefetchAhead < mVisible.size()) batched.prefetchRecord(mVisible[i + kPrefetchAhead]);
            const uint32_t index = mVisible[i];
            const SceneObject& object = mScene.objects[index];
            switch (batched.recordNeed(index, object)) {
                case BatchedPass::RecordNeed::Nothing:
                    break;
                case BatchedPass::RecordNeed::ViewPart:
                    bindObject(object, use.viewRebound);
                    batched.packViewPart(index, mResources.values.all(), mArguments);
                    ++mStats.recordViewPartsPacked;
                    break;
                case BatchedPass::RecordNeed::Whole:
                    bindObject(object, use.used);
                    batched.packRecord(index, object, mResources.values.all(), mArguments);
                    ++mStats.recordsPacked;
                    break;
            }
        }
        // The values as drawing object by object leaves them (the last object's), for whatever reads them
        // next.
        if (!mVisible.empty()) bindObject(mScene.objects[mVisible.back()], use.used);
    }

    // The instance lists: one run per mesh (in order of first appearance, each keeping its objects' order),
    // or per run of consecutive objects with one mesh where the order matters.
    const bool anyOrder = orderFree(states);
    constexpr size_t kNoBatch = ~size_t(0);
    const std::vector<uint32_t>& meshSlots = mResources.sceneCache.meshSlots();
    mBatches.clear();
    if (anyOrder) mBatchOfMesh.assign(mResources.sceneCache.meshCount(), kNoBatch);
    mObjectBatch.reserve(mScene.objects.size());  // once: the list then never outgrows its storage
    mObjectBatch.resize(mVisible.size());
    for (size_t i = 0; i < mVisible.size(); ++i) {
        size_t batch = mBatches.size();
        if (anyOrder) {  // by the mesh's slot: the objects themselves, scattered in memory, are not read
            size_t& ofMesh = mBatchOfMesh[meshSlots[mVisible[i]]];
            if (ofMesh == kNoBatch) {
                ofMesh = mBatches.size();
                mBatches.push_back(Batch{mVisible[i], 0, 0});
            }
            batch = ofMesh;
        } else if (!mBatches.empty() && meshSlots[mBatches.back().first] == meshSlots[mVisible[i]]) {
            batch = mBatches.size() - 1;
        } else {
            mBatches.push_back(Batch{mVisible[i], 0, 0});
        }
        ++mBatches[batch].count;
        mObjectBatch[i] = batch;
    }
    const size_t alignment = batched.listAlignment();
    size_t size = 0;
    for (Batch& batch : mBatches) {
        batch.offset = size;
        size = (size + batch.count + alignment - 1) / alignment * alignment;
        batch.count = 0;  // counted again while filling
    }
    // Grown geometrically: lists that vary with the view stop allocating once the longest has been seen.
    if (size > mInstanceList.capacity()) mInstanceList.reserve(std::max(size, 2 * mInstanceList.capacity()));
    mInstanceList.assign(size, 0);
    for (size_t i = 0; i < mVisible.size(); ++i) {
        Batch& batch = mBatches[mObjectBatch[i]];
        mInstanceList[batch.offset + batch.count++] = mVisible[i];
    }
    {
        PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
        uploadPassValues(mResources, program, mArguments);
    }
    PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
    batched.setInstances(mInstanceList);
    batched.bindRecords();
    for (const Batch& batch : mBatches) {
        const SceneObject& object = mScene.objects[batch.first];
        GpuMesh& mesh = mResources.gpuMesh(object.mesh);
        batched.bindInstances(batch.offset, batch.count);
        const bool drawUnculled = mCullClosedOnly && !object.mesh->closed;
        if (drawUnculled) gl::Disable(GL_CULL_FACE);
        mesh.draw(batched.pass().vertex.inputs, static_cast<int>(batch.count));
        if (drawUnculled) gl::Enable(GL_CULL_FACE);
        countDraw(mesh, static_cast<int>(batch.count));
    }
}

}  // namespace runtime
