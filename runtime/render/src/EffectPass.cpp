// EffectPass, EffectTechnique: see runtime/EffectPass.h. apply() resolves what the pass's script names
// against the application's frame and binds the pass through PassBindings.h, as the SAS host's draws do:
// one way to make GL ready for a pass, whichever client draws.
#include <runtime/EffectPass.h>

#include "ComputeDispatch.h"
#include "EffectResources.h"
#include "PassBindings.h"

#include <fx/SasScript.h>

#include <algorithm>

namespace runtime {

namespace {

const fx::CompiledPass& compiledPass(const EffectResources& resources, size_t technique, size_t pass) {
    return resources.effect().techniques[technique].passes[pass];
}

// DepthBias's depth bits (RenderStateApplier.h) of the framebuffer bound as GL_DRAW_FRAMEBUFFER.
int boundDepthBits(GLint framebuffer) {
    const GLenum attachment = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    GLint type = GL_NONE, bits = 24, component = GL_UNSIGNED_NORMALIZED;
    gl::GetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE) return 24;
    gl::GetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                            GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    gl::GetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &component);
    return component == GL_FLOAT ? 24 : std::clamp(static_cast<int>(bits), 16, 24);
}

// The application's framebuffer and viewport, which passes that bind the frame's targets return to; the
// effect's render targets are sized for that viewport (ViewPortRatio).
void captureApplicationTarget(EffectResources& resources) {
    EffectResources::ApplicationFrame& frame = resources.application;
    gl::GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame.framebuffer);
    gl::GetIntegerv(GL_VIEWPORT, frame.viewport.data());
    frame.depthBits = boundDepthBits(frame.framebuffer);
    frame.boundDepthBits = frame.depthBits;
    frame.targetKnown = true;
    resources.textures->ensureRenderTargets(std::max(frame.viewport[2], 1), std::max(frame.viewport[3], 1));
}

// The targets a pass's Script annotation names (RenderColorTargetN, RenderDepthStencilTarget).
struct ScriptTargets {
    bool named = false;          // the script names a target at all
    bool effectTargets = false;  // one of them is an effect texture ("" is the application's)
    RenderTargets targets;
    std::string missing;  // a named texture that is no allocated render target
    fx::SourceLoc missingLoc;
};

ScriptTargets scriptTargets(const EffectResources& resources, const fx::CompiledPass& pass) {
    ScriptTargets out;
    for (const fx::ScriptCommand& command : pass.script) {
        const bool color = command.kind == fx::ScriptCommand::Kind::RenderColorTarget;
        if (!color && command.kind != fx::ScriptCommand::Kind::RenderDepthStencilTarget) continue;
        if (color && (command.index < 0 || command.index >= RenderTargets::kMaxColorTargets)) continue;
        out.named = true;
        const GpuTexture* texture = nullptr;
        if (!command.value.empty()) {
            out.effectTargets = true;
            texture = command.parameter >= 0
                          ? resources.textures->find(static_cast<size_t>(command.parameter))
                          : nullptr;
            if (!texture) {
                out.missing = command.value;
                out.missingLoc = command.loc;
                continue;
            }
        }
        if (color) {
            out.targets.colors[static_cast<size_t>(command.index)] = RenderTargetAttachment::wholeOf(texture);
        } else {
            out.targets.depth = RenderTargetAttachment::wholeOf(texture);
        }
    }
    dropDepthOfOtherLayering(out.targets);
    return out;
}

}  // namespace

// [SECTION] EffectPass

const std::string& EffectPass::name() const {
    static const std::string none;
    return isValid() ? compiledPass(*mResources, mTechnique, mPass).name : none;
}

std::vector<PassInput> EffectPass::inputSignature() const {
    std::vector<PassInput> inputs;
    if (!isValid()) return inputs;
    for (const fx::VertexInput& input : compiledPass(*mResources, mTechnique, mPass).vertex.inputs)
        inputs.push_back(PassInput{input.semantic, input.location, input.components});
    std::sort(inputs.begin(), inputs.end(),
              [](const PassInput& a, const PassInput& b) { return a.location < b.location; });
    return inputs;
}

GlStateMask EffectPass::stateMask() const {
    if (!isValid()) return {};
    const fx::CompiledPass& pass = compiledPass(*mResources, mTechnique, mPass);
    GlStateMask mask = passStateMask(pass);
    mask.framebuffer = scriptTargets(*mResources, pass).named;
    return mask;
}

bool EffectPass::apply(fx::DiagnosticSink* diagnostics) const {
    if (!isValid()) return false;
    fx::DiagnosticList unreported;
    fx::DiagnosticSink& sink = diagnostics ? *diagnostics : unreported;
    EffectResources& r = *mResources;
    r.pool.pull(r);
    EffectResources::ApplicationFrame& frame = r.application;
    const fx::CompiledPass& pass = compiledPass(r, mTechnique, mPass);
    if (r.programs->program(mTechnique, mPass) && r.programs->program(mTechnique, mPass)->isCompute()) {
        if (!bindComputePass(r, mTechnique, mPass, frame.arguments, sink)) return false;
        frame.applied = std::make_pair(mTechnique, mPass);
        return true;
    }
    if (!frame.targetKnown) captureApplicationTarget(r);

    const ScriptTargets named = scriptTargets(r, pass);
    if (!named.missing.empty()) {
        sink.report(fx::DiagId::ScriptUnknownTarget, named.missingLoc, {named.missing});
        return false;
    }
    PassBinding binding;
    if (named.effectTargets) {
        binding.framebuffer = &named.targets;
        binding.depthBits = depthBiasBits(named.targets.depth.texture);
    } else if (named.named) {
        gl::BindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(frame.framebuffer));
        gl::Viewport(frame.viewport[0], frame.viewport[1], frame.viewport[2], frame.viewport[3]);
        binding.depthBits = frame.depthBits;
    } else {
        binding.depthBits = frame.boundDepthBits;
    }
    FramebufferFault fault;
    if (!bindPass(r, mTechnique, mPass, binding, sink, fault)) {
        const auto [id, arguments] = fault.diagnostic(fx::DiagId::PassTargetsUnbindable, {pass.name});
        sink.report(id, pass.loc, arguments);
        return false;
    }
    // render(Scene) may no longer reuse what it left in the targets (leave-out's cached passes).
    if (named.effectTargets) r.targetHistory.clear();
    frame.boundDepthBits = binding.depthBits;
    commitPassValues(r, mTechnique, mPass, frame.arguments, sink);
    frame.applied = std::make_pair(mTechnique, mPass);
    return true;
}

bool EffectPass::commitChanges(fx::DiagnosticSink* diagnostics) const {
    if (!isValid()) return false;
    EffectResources& r = *mResources;
    if (r.application.applied != std::make_pair(mTechnique, mPass)) return false;
    r.pool.pull(r);
    fx::DiagnosticList unreported;
    commitPassValues(r, mTechnique, mPass, r.application.arguments, diagnostics ? *diagnostics : unreported);
    return true;
}

std::optional<StreamOutCapture> EffectPass::streamOutput() const {
    if (!isValid()) return std::nullopt;
    StreamOutBuffers* capture = mResources->programs->streamOut(mTechnique, mPass);
    if (!capture) return std::nullopt;
    return capture->last();
}

bool EffectPass::beginStreamOutput() const {
    if (!isValid()) return false;
    StreamOutBuffers* capture = mResources->programs->streamOut(mTechnique, mPass);
    if (!capture) return false;
    if (!mResources->effect().techniques[mTechnique].passes[mPass].streamOut->rasterizes)
        gl::Enable(GL_RASTERIZER_DISCARD);
    capture->begin();
    return true;
}

void EffectPass::endStreamOutput() const {
    if (!isValid()) return;
    StreamOutBuffers* capture = mResources->programs->streamOut(mTechnique, mPass);
    if (!capture) return;
    capture->end();
    gl::Disable(GL_RASTERIZER_DISCARD);
}

size_t EffectPass::annotationCount() const {
    return isValid() ? mResources->annotations.pass(mTechnique, mPass).size() : 0;
}

EffectAnnotation EffectPass::annotation(size_t i) const {
    return isValid() ? AnnotationTable::at(mResources->annotations.pass(mTechnique, mPass), i)
                     : EffectAnnotation{};
}

EffectAnnotation EffectPass::annotation(std::string_view name) const {
    return isValid() ? AnnotationTable::find(mResources->annotations.pass(mTechnique, mPass), name)
                     : EffectAnnotation{};
}

// [SECTION] EffectTechnique

const std::string& EffectTechnique::name() const {
    static const std::string none;
    return isValid() ? mResources->effect().techniques[mTechnique].name : none;
}

const std::string& EffectTechnique::group() const {
    static const std::string none;
    return isValid() ? mResources->effect().techniques[mTechnique].group : none;
}

size_t EffectTechnique::passCount() const {
    return isValid() ? mResources->effect().techniques[mTechnique].passes.size() : 0;
}

EffectPass EffectTechnique::pass(size_t index) const {
    if (index >= passCount()) return {};
    return EffectPass(mResources, mTechnique, index);
}

EffectPass EffectTechnique::pass(std::string_view name) const {
    for (size_t p = 0; p < passCount(); ++p)
        if (fx::scriptNameMatches(name, mResources->effect().techniques[mTechnique].passes[p].name))
            return EffectPass(mResources, mTechnique, p);
    return {};
}

GlStateMask EffectTechnique::stateMask() const {
    GlStateMask mask;
    for (size_t p = 0; p < passCount(); ++p) mask.add(pass(p).stateMask());
    return mask;
}

bool EffectTechnique::begin(bool saveState) const {
    if (!isValid() || mResources->application.begun) return false;
    EffectResources::ApplicationFrame& frame = mResources->application;
    // Read before anything is written: allocating the render targets binds textures.
    if (saveState) {
        std::vector<std::optional<GlStateMask>>& masks = mResources->techniqueStateMasks;
        if (masks.size() <= mTechnique) masks.resize(mResources->effect().techniques.size());
        if (!masks[mTechnique]) masks[mTechnique] = stateMask();
        if (!frame.saved) frame.saved.emplace();
        GlStateSnapshot::capture(*masks[mTechnique], *frame.saved);
    }
    frame.saving = saveState;
    captureApplicationTarget(*mResources);
    frame.begun = mTechnique;
    return true;
}

void EffectTechnique::end() const {
    if (!isValid() || mResources->application.begun != mTechnique) return;
    EffectResources::ApplicationFrame& frame = mResources->application;
    if (frame.saving) frame.saved->restore();
    // As a new frame, the snapshot's and the arguments' storage kept for the next begin().
    std::optional<GlStateSnapshot> saved = std::move(frame.saved);
    std::vector<fx::Value> arguments = std::move(frame.arguments);
    arguments.clear();
    frame = EffectResources::ApplicationFrame{};
    frame.saved = std::move(saved);
    frame.arguments = std::move(arguments);
}

size_t EffectTechnique::annotationCount() const {
    return isValid() ? mResources->annotations.technique(mTechnique).size() : 0;
}

EffectAnnotation EffectTechnique::annotation(size_t i) const {
    return isValid() ? AnnotationTable::at(mResources->annotations.technique(mTechnique), i)
                     : EffectAnnotation{};
}

EffectAnnotation EffectTechnique::annotation(std::string_view name) const {
    return isValid() ? AnnotationTable::find(mResources->annotations.technique(mTechnique), name)
                     : EffectAnnotation{};
}

// [SECTION] Viewports

void setViewports(const std::vector<fx::Viewport>& viewports) {
    GLint most = 1;
    gl::GetIntegerv(GL_MAX_VIEWPORTS, &most);
    for (size_t i = 0; i < viewports.size() && i < static_cast<size_t>(most); ++i)
        gl::ViewportIndexedf(static_cast<GLuint>(i), viewports[i].x, viewports[i].y, viewports[i].width,
                             viewports[i].height);
}

}  // namespace runtime
