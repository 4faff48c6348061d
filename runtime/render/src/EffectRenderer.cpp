// EffectRenderer: the API over the effect runtime. The work is done by one file per stage:
// - EffectResources   what the renderer owns: programs, preshaders, textures, samplers, parameter values
// - PassUse           what each pass reads (parameters, projection matrices)
// - PlanRecorder      the frame's dry run: its plan (FramePlan) of clears and draws, with their states
// - FramePlan         what of the plan the frame leaves out
// - FrameExecutor     the frame on GL, following the plan
#include <runtime/EffectRenderer.h>

#include <fx/CompiledEffectFile.h>
#include <fx/LiteralNumbers.h>

#include "EffectResources.h"
#include "FrameExecutor.h"
#include "HostFrame.h"
#include "PassUse.h"
#include "PlanRecorder.h"
#include "RenderPort.h"

#include <private/runtime/FramePlan.h>
#include <runtime/Framebuffer.h>
#include <runtime/GlDebug.h>
#include <runtime/Image.h>
#include <runtime/IntersectionBody.h>
#include "ScriptInterpreter.h"
#include "SemanticBinder.h"

#include <fx/RenderStates.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace runtime {

EffectRenderer::EffectRenderer(std::unique_ptr<EffectResources> resources) : mImpl(std::move(resources)) {}
EffectRenderer::~EffectRenderer() = default;

std::unique_ptr<EffectRenderer> EffectRenderer::createFromFile(const std::string& path,
                                                               fx::DiagnosticSink& diagnostics,
                                                               std::shared_ptr<EffectPool> pool) {
    std::shared_ptr<const fx::CompiledEffect> effect = fx::readCompiledEffectFile(path, diagnostics);
    return effect ? create(effect, diagnostics, std::move(pool)) : nullptr;
}

std::unique_ptr<EffectRenderer> EffectRenderer::create(std::shared_ptr<const fx::CompiledEffect> effect,
                                                       fx::DiagnosticSink& diagnostics,
                                                       std::shared_ptr<EffectPool> pool) {
    std::unique_ptr<EffectResources> resources = EffectResources::create(std::move(effect), diagnostics);
    if (!resources || !resources->pool.join(std::move(pool), *resources, diagnostics)) return nullptr;
    const std::vector<std::string>& lights = resources->effect().lights;
    for (const fx::ParameterInfo& parameter : resources->parameterInfo()) {
        if (parameter.standard.byName) {
            const int light = parameter.standard.light;
            const std::string bound = fx::semanticBindingName(
                parameter.standard, light >= 0 ? lights[static_cast<size_t>(light)] : std::string());
            if (parameter.semantic.empty())
                diagnostics.report(fx::DiagId::ParameterBoundByName, parameter.loc, {parameter.name, bound});
            else
                diagnostics.report(fx::DiagId::ParameterBoundBySpelling, parameter.loc,
                                   {parameter.name, parameter.semantic, bound});
        }
        for (const fx::MemberBinding& member : parameter.memberBindings) {
            const int light = member.standard.light;
            const bool material = member.standard.kind == fx::SemanticKind::ObjectColor;
            diagnostics.report(
                fx::DiagId::MemberBoundByName, parameter.loc,
                {member.member, parameter.name,
                 fx::semanticBindingName(member.standard,
                                         light >= 0 ? lights[static_cast<size_t>(light)] : std::string()),
                 material ? "material" : "light"});
        }
        // A semantic nothing reads looks bound in the source while the value silently stays the default.
        if (!parameter.semantic.empty() && !parameter.isStatic && parameter.type.isNumeric() &&
            parameter.standard.kind == fx::SemanticKind::None)
            diagnostics.report(fx::DiagId::UnboundSemantic, parameter.loc,
                               {parameter.name, parameter.semantic});
    }
    return std::unique_ptr<EffectRenderer>(new EffectRenderer(std::move(resources)));
}

std::vector<std::string> EffectRenderer::boundSemantics() {
    return fx::standardSemanticNames();
}

const fx::CompiledEffect& EffectRenderer::effect() const {
    return mImpl->effect();
}

// [SECTION] Parameters

std::optional<size_t> EffectRenderer::findParameter(std::string_view name) const {
    return mImpl->findParameter(name);
}

const fx::Value& EffectRenderer::parameter(size_t index) const {
    return mImpl->values.at(index);
}

void EffectRenderer::setParameter(size_t index, const fx::Value& value) {
    mImpl->values.pin(index, value);
    mImpl->pool.published(*mImpl, index);
}

void EffectRenderer::reset() {
    mImpl->resetPending = true;
}

bool EffectRenderer::isPinned(size_t index) const {
    return mImpl->values.isPinned(index);
}

bool EffectRenderer::setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics) {
    return mImpl->setTexture(index, data, diagnostics);
}

bool EffectRenderer::setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                               fx::DiagnosticSink& diagnostics) {
    return mImpl->setBuffer(index, bytes, elements, elementBytes, diagnostics);
}

bool EffectRenderer::setParameterFromText(std::string_view name, std::string_view text,
                                          fx::DiagnosticSink& diagnostics) {
    const std::optional<size_t> index = findParameter(name);
    const fx::SourceLoc where{mImpl->effect().path, 0, 0};
    if (!index) {
        diagnostics.report(fx::DiagId::UnknownParameter, where, {std::string(name)});
        return false;
    }
    const fx::ParameterInfo& parameter = mImpl->parameterInfo()[*index];
    if (parameter.type.base == fx::BaseType::String) {
        setParameter(*index, fx::Value::text(std::string(text)));
        return true;
    }
    if (!parameter.type.isNumeric()) {
        diagnostics.report(fx::DiagId::ParameterNotSettableFromCommandLine, parameter.loc,
                           {parameter.name, parameter.type.hlslName()});
        return false;
    }
    // The literal grammar the scripts' values share (fx/LiteralNumbers.h).
    const std::optional<std::vector<float>> parsed = fx::parseLiteralNumbers(text);
    if (!parsed) {
        diagnostics.report(fx::DiagId::ParameterValueInvalid, parameter.loc,
                           {std::string(text), parameter.type.hlslName(), parameter.name});
        return false;
    }
    std::vector<float> numbers = *parsed;
    const size_t expected = static_cast<size_t>(parameter.type.componentCount());
    if (numbers.size() == 1 && expected > 1) numbers.assign(expected, numbers[0]);  // HLSL scalar broadcast
    if (numbers.size() != expected) {
        diagnostics.report(fx::DiagId::ParameterValueCount, parameter.loc,
                           {parameter.name, parameter.type.hlslName(), std::to_string(expected),
                            std::to_string(numbers.size())});
        return false;
    }
    fx::Value value = fx::zeroValue(parameter.type);
    value.data = numbers;
    setParameter(*index, value);
    return true;
}

// [SECTION] The application's API

size_t EffectRenderer::techniqueCount() const {
    return mImpl->effect().techniques.size();
}

EffectTechnique EffectRenderer::technique(size_t index) {
    if (index >= techniqueCount()) return {};
    return EffectTechnique(mImpl.get(), index);
}

EffectTechnique EffectRenderer::technique(std::string_view name) {
    const fx::CompiledTechnique* found = mImpl->effect().findTechnique(std::string(name));
    if (!found) return {};
    return EffectTechnique(mImpl.get(), static_cast<size_t>(found - mImpl->effect().techniques.data()));
}

TechniqueValidation EffectRenderer::validateTechnique(std::string_view name) const {
    const fx::CompiledEffect& effect = mImpl->effect();
    if (effect.findTechnique(std::string(name))) return {true, ""};
    for (const fx::RefusedTechnique& refused : effect.refusedTechniques)
        if (refused.name == name || (!refused.group.empty() && refused.group + "." + refused.name == name))
            return {false, refused.reason};
    return {false, "the effect has no technique '" + std::string(name) + "'"};
}

size_t EffectRenderer::variableCount() const {
    return mImpl->values.size();
}

EffectVariable EffectRenderer::variable(size_t index) {
    if (index >= variableCount()) return {};
    return EffectVariable(mImpl.get(), index);
}

EffectVariable EffectRenderer::variable(std::string_view name) {
    const std::optional<size_t> index = findParameter(name);
    if (!index) return {};
    return EffectVariable(mImpl.get(), *index);
}

EffectVariable EffectRenderer::variableBySemantic(std::string_view semantic) {
    if (semantic.empty()) return {};
    const std::vector<fx::ParameterInfo>& parameters = mImpl->parameterInfo();
    for (size_t i = 0; i < parameters.size(); ++i)
        if (fx::equalsIgnoreCase(parameters[i].semantic, semantic)) return EffectVariable(mImpl.get(), i);
    return {};
}

// [SECTION] Host files

bool EffectRenderer::setHostFile(std::shared_ptr<const fx::HostFile> host, fx::DiagnosticSink& diagnostics) {
    if (!host) {
        mHostFrame.reset();
        return true;
    }
    if (!fx::checkHostFile(*host, mImpl->effect(), diagnostics)) return false;
    mHostFrame = std::make_unique<HostFrame>(std::move(host), *this);
    return true;
}

// [SECTION] Frame

std::optional<LightFit> EffectRenderer::lightFit(const Scene& scene, std::string_view lightName,
                                                 const FrameOptions& options) const {
    const Light* light = scene.findLight(lightName);
    if (!light) return std::nullopt;
    return mImpl->fitLights(scene, options.width, options.height).lightFit(*light);
}

bool EffectRenderer::render(const Scene& scene, const FrameOptions& options, fx::DiagnosticSink& diagnostics,
                            FrameStats* stats) {
    FrameStats localStats;
    FrameStats& frameStats = stats ? *stats : localStats;
    frameStats.reset();
    mImpl->pool.pull(*mImpl);
    if (mHostFrame) {
        const bool ran = mHostFrame->render(*mImpl, scene, options, diagnostics);
        const bool clean = checkGlErrors("EffectRenderer::render", __FILE__, __LINE__);
        if (!clean)
            diagnostics.report(fx::DiagId::GlErrorDuringFrame, fx::SourceLoc{mImpl->effect().path, 0, 0});
        return ran && clean;
    }

    // The frame's own values, before a Technique= selector or the script (and its dry run) reads them.
    bool resetFrame = mImpl->resetPending;
    mImpl->binder->setResetPulse(resetFrame);
    mImpl->resetPending = false;
    mImpl->values.bindSemantics(*mImpl->binder, RenderPortView{}, nullptr, options.time,
                                SemanticBinder::Scope::PerFrame, nullptr);

    // The technique, chosen by name once for each FrameOptions::technique (every frame where a Technique=
    // selector reads a parameter).
    EffectResources::TechniqueChoice& choice = mImpl->techniqueChoice;
    if (!choice.valid || choice.requested != options.technique) {
        const fx::CompiledTechnique* chosen = ScriptInterpreter::selectTechnique(
            mImpl->effect(), options.technique, mImpl->values.all(), diagnostics);
        if (!chosen) {
            // No frame ran: the reset is still the next frame's.
            mImpl->resetPending = resetFrame;
            return false;
        }
        choice.technique = static_cast<size_t>(chosen - mImpl->effect().techniques.data());
        choice.requested = options.technique;
        choice.valid = !ScriptInterpreter::selectionReadsParameters(mImpl->effect(), options.technique);
    }
    const size_t techniqueIndex = choice.technique;
    const fx::CompiledTechnique* technique = &mImpl->effect().techniques[techniqueIndex];
    SemanticBinder& binder = *mImpl->binder;
    // A frame of another technique than the frame before starts a picture, as FX Composer started one when
    // the technique changed: it is a reset frame (cleared, FXCOMPOSER_RESETPULSE true for its script and
    // shaders; a Technique= selector read the pulse before the change was known).
    if (!resetFrame && mImpl->lastTechnique && *mImpl->lastTechnique != techniqueIndex) {
        resetFrame = true;
        binder.setResetPulse(true);
        mImpl->values.bindSemantics(binder, RenderPortView{}, nullptr, options.time,
                                    SemanticBinder::Scope::PerFrame, nullptr);
    }
    mImpl->lastTechnique = techniqueIndex;

    // KHR_debug messages (debug contexts) and GL errors found while the frame runs go to the caller's sink.
    setDebugSink([&diagnostics](std::string message) {
        diagnostics.report(fx::Diagnostic{fx::DiagId::GlDebugMessage, fx::Severity::Note, fx::SourceLoc{},
                                          fx::formatDiagnostic(fx::DiagId::GlDebugMessage, {message})});
    });
    // Camera-relative rendering for scenes far from the origin (Scene.h, renderOrigin). Such a scene is
    // translated anew each frame and its cache rebuilt: a price only scenes far from the origin pay.
    mImpl->sceneCache.update(scene);
    const glm::vec3 origin = renderOrigin(mImpl->sceneCache.bounds());
    const std::optional<Scene> rebased =
        origin == glm::vec3(0.0f) ? std::nullopt : std::optional<Scene>(scene.translated(-origin));
    const Scene& frameScene = rebased ? *rebased : scene;
    // Render targets are allocated once an operation that runs needs them (below); the frame's own now.
    std::vector<bool>& neededTargets = mImpl->frameScratch.neededTargets;
    neededTargets.assign(mImpl->values.size(), false);
    const bool newFrameTargets = mImpl->textures->ensureFrame(options.width, options.height, &neededTargets);
    // A scene effect's frame as it left it, unless this frame starts a picture
    // (fx::CompiledEffect::sceneClass).
    const bool keepFrame = mImpl->effect().sceneClass && !resetFrame && !newFrameTargets;
    if (rebased) mImpl->sceneCache.update(frameScene);  // else the scene's cache, stamped above
    // Fits to what the camera sees find this frame's samples first (a pre-pass and a read-back: no frame
    // of latency).
    std::optional<VisibleSamples> visible;
    if (binder.wantsVisibleSamples(mImpl->values.all()))
        visible = mImpl->visibleSamplePass.run(
            frameScene, mImpl->sceneCache.bvh(), options.width, options.height,
            [this](const SceneObject& object) -> GpuMesh& { return mImpl->gpuMesh(object.mesh); });
    binder.prepare(frameScene, mImpl->sceneCache.bounds(),
                   static_cast<float>(options.width) / static_cast<float>(options.height),
                   mImpl->values.all(), mImpl->values.stamps(), diagnostics, visible ? &*visible : nullptr);
    const std::vector<PassUse>& uses = mImpl->passUses[techniqueIndex];

    const std::vector<PassPreshaders>& preshaders = mImpl->programs->techniquePreshaders(techniqueIndex);
    const auto preshaderRuns = [&preshaders] {
        uint64_t runs = 0;
        for (const PassPreshaders& pass : preshaders) runs += pass.runs();
        return runs;
    };
    const uint64_t runsBefore = preshaderRuns();

    // Plan the frame with a dry run of its script, then leave out what it shows nobody needs.
    FramePlan& plan = mImpl->framePlan;
    {
        std::vector<glm::vec3>& body = mImpl->frameScratch.cameraBody;
        body.clear();
        if (options.leaveOut && !mImpl->sceneCache.bvh().empty()) {
            RenderPortView camera;
            portMatrices(frameScene, binder, options, "", -1, -1, camera);
            const Aabb& objects = mImpl->sceneCache.bvh().rootBox();
            intersectionBodyPoints(camera.projection * camera.view, Bounds{objects.min, objects.max}, body);
        }
        fx::DiagnosticList dryRunDiagnostics;  // the real run reports them
        plan.beginRecording();
        PlanRecorder recorder(*mImpl, frameScene, options, binder, uses, techniqueIndex, body, plan,
                              diagnostics);
        ScriptInterpreter::run(*technique, mImpl->effect().maxScriptLoopCount, keepFrame,
                               mImpl->frameScratch.scriptLoops, recorder, dryRunDiagnostics);
        plan.finishRecording();
        // FrameOptions::outputTargets, found by name again only when the names change.
        std::vector<int>& outputs = mImpl->frameScratch.outputTargets;
        if (mImpl->frameScratch.outputTargetNames != options.outputTargets) {
            mImpl->frameScratch.outputTargetNames = options.outputTargets;
            outputs.clear();
            for (const std::string& name : options.outputTargets)
                if (const std::optional<size_t> index = findParameter(name))
                    outputs.push_back(static_cast<int>(*index));
        }
        plan.markDead(outputs, options.leaveOut);
        // A render target no remaining operation writes or reads is not allocated.
        const auto need = [&neededTargets](int resource) {
            if (resource >= 0 && static_cast<size_t>(resource) < neededTargets.size())
                neededTargets[static_cast<size_t>(resource)] = true;
        };
        for (const PlannedOp& op : plan.ops) {
            if (op.leftOut != LeftOut::No && options.leaveOut) continue;
            for (int resource : op.writes) need(resource);
            for (int resource : op.reads) need(resource);
        }
        mImpl->textures->ensureFrame(options.width, options.height,
                                     options.leaveOut ? &neededTargets : nullptr);
        // Without reuse the plan sees no history: nothing matches, as after a moved light.
        static const std::map<int, TargetHistory> noHistory;
        plan.decide(
            options.reuseTargets ? mImpl->targetHistory : noHistory,
            [this](int resource) { return mImpl->textures->identity(resource); }, options.leaveOut);
    }

    FrameExecutor executor(*mImpl, frameScene, options, diagnostics, frameStats, techniqueIndex, binder, uses,
                           plan);
    const bool ran = ScriptInterpreter::run(*technique, mImpl->effect().maxScriptLoopCount, keepFrame,
                                            mImpl->frameScratch.scriptLoops, executor, diagnostics);
    executor.finish();
    frameStats.preshaderRuns = preshaderRuns() - runsBefore;
    FramebufferCache::bindDefault();
    const bool clean = checkGlErrors("EffectRenderer::render", __FILE__, __LINE__);
    setDebugSink({});
    if (!clean) diagnostics.report(fx::DiagId::GlErrorDuringFrame, fx::SourceLoc{mImpl->effect().path, 0, 0});
    const bool ok = ran && !executor.failed() && clean;
    // What the targets hold is known only if the frame ran as planned; otherwise forget it all.
    if (ok && executor.followedPlan()) {
        plan.commit(mImpl->targetHistory);
    } else {
        mImpl->targetHistory.clear();
    }
    return ok;
}

FrameImage EffectRenderer::readFrame() const {
    FrameImage frame;
    if (!mImpl->textures->frameColor()) return frame;
    const Image image = readColorTarget(mImpl->textures->frameColor()).toRGBA8();
    frame.width = image.width;
    frame.height = image.height;
    frame.rgba = image.bytes;
    return frame;
}

bool EffectRenderer::blitFrameTo(uint32_t framebuffer) const {
    const GpuTexture& frameColor = mImpl->textures->frameColor();
    if (!frameColor) return false;
    RenderTargets source;
    source.colors[0].texture = &frameColor;
    FramebufferFault unused;  // the frame's own colour target: always bindable
    if (!mImpl->textures->bindFramebuffer(source, unused)) return false;
    const int width = frameColor.width(), height = frameColor.height();
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    gl::BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    return gl::GetError() == GL_NO_ERROR;
}

std::optional<std::vector<float>> EffectRenderer::readTarget(std::string_view textureName, int* width,
                                                             int* height, int* channels, int level) const {
    std::vector<float> texels;
    if (!readTarget(textureName, texels, width, height, channels, level)) return std::nullopt;
    return texels;
}

bool EffectRenderer::readTarget(std::string_view textureName, std::vector<float>& texels, int* width,
                                int* height, int* channels, int level) const {
    const std::optional<size_t> index = findParameter(textureName);
    if (!index) return false;
    const GpuTexture* texture = mImpl->textures->find(*index);
    if (!texture || level < 0 || level >= texture->mipLevels()) return false;
    const ImageShape image = readFloatTexture(*texture, texels, level);
    if (width) *width = image.width;
    if (height) *height = image.height;
    if (channels) *channels = image.channels;
    return true;
}

bool writePng(const FrameImage& frame, const std::string& path, std::string& error) {
    Image image = Image::makeBytes(frame.width, frame.height, 4);
    image.bytes = frame.rgba;
    return image.writePng(path, error);
}

}  // namespace runtime
