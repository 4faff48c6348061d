// EffectRenderer: GL resources of one compiled effect, and the frame executor that runs its SAS scripts.
//
// [SECTION] Resources   textures (render targets sized per frame, file and runtime textures), samplers,
//                       one GpuProgram per pass, GPU meshes cached per scene mesh
// [SECTION] Parameters  values, pinning, --set parsing
// [SECTION] Frame       FrameExecutor: the ScriptTarget that binds targets, states, semantics and draws
#include <runtime/EffectRenderer.h>

#include "Framebuffer.h"
#include "GlDebug.h"
#include "GpuMesh.h"
#include "GpuProgram.h"
#include "GpuTexture.h"
#include "Image.h"
#include "PassTimer.h"
#include "ProceduralTexture.h"
#include "RenderStateApplier.h"
#include "SamplerObject.h"
#include "ScriptInterpreter.h"
#include "SemanticBinder.h"

#include <fx/Preshader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <set>
#include <unordered_map>

namespace runtime {

struct EffectRenderer::Impl {
    std::shared_ptr<const fx::CompiledEffect> compiled;
    std::vector<fx::Value> values;
    std::vector<bool> pinned;
    std::unordered_map<std::string, size_t> parameterIndex;

    // programs[technique][pass]
    std::vector<std::vector<std::unique_ptr<GpuProgram>>> programs;
    std::map<size_t, GpuTexture> textures;  // by texture parameter index
    // Mipmapped render targets written since their mip chain was last generated: regenerated before a
    // pass samples them (D3D9's AUTOGENMIPMAP).
    std::set<const GpuTexture*> staleMipChains;
    std::map<size_t, SamplerObject> samplers;
    std::map<size_t, SamplerObject> comparisonSamplers;
    std::map<const Mesh*, std::pair<std::shared_ptr<const Mesh>, GpuMesh>> meshes;
    GpuMesh quad;
    FramebufferCache framebuffers;
    GpuTexture frameColor;
    GpuTexture frameDepth;

    const fx::Effect& effect() const { return *compiled->effect; }
    const fx::Value* find(std::string_view name) const {
        auto it = parameterIndex.find(std::string(name));
        return it == parameterIndex.end() ? nullptr : &values[it->second];
    }
    bool createFileTextures(fx::DiagnosticSink& diagnostics);
    // (Re)allocates render targets whose size depends on the frame's.
    void ensureFrameResources(int width, int height);
    GpuMesh& gpuMesh(const std::shared_ptr<const Mesh>& mesh);
};

// [SECTION] Resources

namespace {

// A deterministic noise texture for the `noise` semantic (the thesis's jitter lookups): RGBA uniform in
// [0, 1], from a fixed-seed LCG so every run renders the same image.
GpuTexture makeNoiseTexture() {
    constexpr int kSize = 64;
    std::vector<uint8_t> pixels(kSize * kSize * 4);
    uint32_t state = 0x2545F491u;
    for (uint8_t& p : pixels) {
        state = state * 1664525u + 1013904223u;
        p = static_cast<uint8_t>(state >> 24);
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    texture.uploadRGBA8(pixels.data());
    return texture;
}

// White: the neutral value for textures the effect multiplies with.
GpuTexture makeNeutralTexture(bool cube) {
    const uint8_t white[4] = {255, 255, 255, 255};
    if (cube) {
        GpuTexture texture = GpuTexture::createCube(fx::TextureFormat::RGBA8, 1);
        for (int face = 0; face < 6; ++face) texture.uploadRGBA8(white, 0, face);
        return texture;
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, 1, 1);
    texture.uploadRGBA8(white);
    return texture;
}

bool isRenderTarget(const fx::TextureDesc& desc) {
    return desc.kind == fx::TextureDesc::Kind::RenderColorTarget ||
           desc.kind == fx::TextureDesc::Kind::RenderDepthStencilTarget;
}

}  // namespace

bool EffectRenderer::Impl::createFileTextures(fx::DiagnosticSink& diagnostics) {
    for (const fx::TextureDesc& desc : compiled->textures) {
        if (isRenderTarget(desc)) continue;
        const bool cube = desc.type == fx::BaseType::TextureCube;
        const std::string semantic = effect().parameters[desc.parameter].semantic;
        if (desc.kind == fx::TextureDesc::Kind::Runtime && fx::equalsIgnoreCase(semantic, "noise") && !cube) {
            textures[desc.parameter] = makeNoiseTexture();
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::Procedural) {
            GpuTexture texture = GpuTexture::create2D(desc.format, desc.width, desc.height, desc.mipLevels);
            texture.uploadRGBA32F(whiteNoiseTexels(texture.width(), texture.height(), desc.seed).data());
            texture.generateMipmaps();
            textures[desc.parameter] = std::move(texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() && !cube) {
            std::string error;
            std::optional<Image> image = loadImageFile(desc.resolvedPath, error);
            if (!image) {
                diagnostics.report(fx::DiagId::TextureFileUnreadable, desc.loc, {desc.resourceName, error});
                return false;
            }
            // HDR files keep their range in a float texture; everything else is 8-bit RGBA.
            const int levels = desc.mipLevels == 1 ? 1 : 0;
            GpuTexture texture =
                GpuTexture::create2D(image->isFloat ? fx::TextureFormat::RGBA32F : fx::TextureFormat::RGBA8,
                                     image->width, image->height, levels);
            if (image->isFloat) {
                texture.uploadRGBA32F(image->floats.data());
            } else {
                texture.uploadRGBA8(image->toRGBA8().bytes.data());
            }
            texture.generateMipmaps();
            textures[desc.parameter] = std::move(texture);
            continue;
        }
        textures[desc.parameter] = makeNeutralTexture(cube);
    }
    return true;
}

void EffectRenderer::Impl::ensureFrameResources(int width, int height) {
    if (frameColor.width() != width || frameColor.height() != height) {
        if (frameColor) framebuffers.evict(frameColor);
        if (frameDepth) framebuffers.evict(frameDepth);
        frameColor = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        frameDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    for (const fx::TextureDesc& desc : compiled->textures) {
        if (!isRenderTarget(desc)) continue;
        const int w = desc.width > 0
                          ? desc.width
                          : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[0] * width)));
        const int h = desc.height > 0
                          ? desc.height
                          : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[1] * height)));
        auto it = textures.find(desc.parameter);
        if (it != textures.end() && it->second.width() == w && it->second.height() == h) continue;
        if (it != textures.end()) framebuffers.evict(it->second);
        GpuTexture texture = desc.type == fx::BaseType::TextureCube
                                 ? GpuTexture::createCube(desc.format, w, desc.mipLevels)
                                 : GpuTexture::create2D(desc.format, w, h, desc.mipLevels);
        texture.setLabel(effect().parameters[desc.parameter].name);
        textures[desc.parameter] = std::move(texture);
    }
}

GpuMesh& EffectRenderer::Impl::gpuMesh(const std::shared_ptr<const Mesh>& mesh) {
    auto it = meshes.find(mesh.get());
    if (it == meshes.end()) it = meshes.emplace(mesh.get(), std::make_pair(mesh, GpuMesh(*mesh))).first;
    return it->second.second;
}

EffectRenderer::EffectRenderer(std::unique_ptr<Impl> impl) : mImpl(std::move(impl)) {}
EffectRenderer::~EffectRenderer() = default;

std::unique_ptr<EffectRenderer> EffectRenderer::create(std::shared_ptr<const fx::CompiledEffect> effect,
                                                       fx::DiagnosticSink& diagnostics) {
    auto impl = std::make_unique<Impl>();
    impl->compiled = std::move(effect);
    const fx::Effect& source = impl->effect();
    impl->values = impl->compiled->initialValues;
    impl->values.resize(source.parameters.size());
    impl->pinned.assign(source.parameters.size(), false);
    for (size_t i = 0; i < source.parameters.size(); ++i) {
        impl->parameterIndex.emplace(source.parameters[i].name, i);
        if (impl->values[i].type.base == fx::BaseType::Float && impl->values[i].data.empty())
            impl->values[i] = fx::zeroValue(source.parameters[i].type);
    }

    bool ok = true;
    for (const fx::CompiledTechnique& technique : impl->compiled->techniques) {
        auto& passes = impl->programs.emplace_back();
        for (const fx::CompiledPass& pass : technique.passes) {
            std::unique_ptr<GpuProgram> program = GpuProgram::create(pass, diagnostics);
            ok = ok && program != nullptr;
            passes.push_back(std::move(program));
        }
    }
    if (!ok) return nullptr;

    for (const fx::SamplerDesc& desc : impl->compiled->samplers) {
        impl->samplers.emplace(desc.parameter, SamplerObject(desc, false));
        impl->comparisonSamplers.emplace(desc.parameter, SamplerObject(desc, true));
    }
    if (!impl->createFileTextures(diagnostics)) return nullptr;
    impl->quad = GpuMesh::makeFullScreenQuad();
    return std::unique_ptr<EffectRenderer>(new EffectRenderer(std::move(impl)));
}

const fx::CompiledEffect& EffectRenderer::effect() const {
    return *mImpl->compiled;
}

// [SECTION] Parameters

std::optional<size_t> EffectRenderer::findParameter(std::string_view name) const {
    auto it = mImpl->parameterIndex.find(std::string(name));
    if (it == mImpl->parameterIndex.end()) return std::nullopt;
    return it->second;
}

const fx::Value& EffectRenderer::parameter(size_t index) const {
    return mImpl->values.at(index);
}

void EffectRenderer::setParameter(size_t index, const fx::Value& value) {
    fx::Value stored = value;
    stored.type = mImpl->effect().parameters.at(index).type;
    mImpl->values.at(index) = std::move(stored);
    mImpl->pinned.at(index) = true;
}

bool EffectRenderer::isPinned(size_t index) const {
    return mImpl->pinned.at(index);
}

bool EffectRenderer::setParameterFromText(std::string_view name, std::string_view text,
                                          fx::DiagnosticSink& diagnostics) {
    const std::optional<size_t> index = findParameter(name);
    const fx::SourceLoc where{mImpl->effect().path, 0, 0};
    if (!index) {
        diagnostics.report(fx::DiagId::UnknownParameter, where, {std::string(name)});
        return false;
    }
    const fx::Parameter& parameter = mImpl->effect().parameters[*index];
    if (parameter.type.base == fx::BaseType::String) {
        setParameter(*index, fx::Value::text(std::string(text)));
        return true;
    }
    if (!parameter.type.isNumeric()) {
        diagnostics.report(fx::DiagId::TypeMismatch, parameter.loc,
                           {"parameter '" + parameter.name + "' of type " + parameter.type.hlslName() +
                            " cannot be set from the command line"});
        return false;
    }
    // Numbers separated by commas or spaces, optionally in braces; true/false for bools.
    std::string cleaned;
    for (char c : text) cleaned += (c == '{' || c == '}' || c == ',') ? ' ' : c;
    std::istringstream stream(cleaned);
    std::vector<float> numbers;
    std::string word;
    while (stream >> word) {
        std::string lower = word;
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        if (lower == "true" || lower == "false") {
            numbers.push_back(lower == "true" ? 1.0f : 0.0f);
            continue;
        }
        char* end = nullptr;
        const float number = std::strtof(word.c_str(), &end);
        if (end != word.c_str() + word.size() || !std::isfinite(number)) {
            diagnostics.report(fx::DiagId::TypeMismatch, parameter.loc,
                               {"'" + std::string(text) + "' is not a value of type " +
                                parameter.type.hlslName() + " for parameter '" + parameter.name + "'"});
            return false;
        }
        numbers.push_back(number);
    }
    const size_t expected = static_cast<size_t>(parameter.type.componentCount());
    if (numbers.size() == 1 && expected > 1) numbers.assign(expected, numbers[0]);  // HLSL scalar broadcast
    if (numbers.size() != expected) {
        diagnostics.report(
            fx::DiagId::TypeMismatch, parameter.loc,
            {"parameter '" + parameter.name + "' of type " + parameter.type.hlslName() + " needs " +
             std::to_string(expected) + " values, got " + std::to_string(numbers.size())});
        return false;
    }
    fx::Value value = fx::zeroValue(parameter.type);
    value.data = numbers;
    setParameter(*index, value);
    return true;
}

// [SECTION] Frame

namespace {

class FrameExecutor : public ScriptTarget {
public:
    FrameExecutor(EffectRenderer::Impl& impl, const Scene& scene, const FrameOptions& options,
                  fx::DiagnosticSink& diagnostics, FrameStats& stats, size_t techniqueIndex)
        : mImpl(impl),
          mScene(scene),
          mOptions(options),
          mDiagnostics(diagnostics),
          mStats(stats),
          mTechnique(techniqueIndex),
          mBinder(impl.effect(), scene, diagnostics),
          mSceneBounds(scene.bounds()) {
        mTargets.colors[0].texture = &impl.frameColor;
        mTargets.depth.texture = &impl.frameDepth;
        setRenderPort("");
    }

    bool failed() const { return mFailed; }
    // With FrameOptions::timePasses: waits for the GPU and fills the frame's pass timings.
    void finishTiming() { mTimer.finish(); }

    void beginPass(const fx::CompiledPass& pass) override {
        ++mStats.passesRun;
        mTimer.beginPass(pass.name);
    }

    void setColorTarget(int index, const std::string& texture) override {
        if (index < 0 || index >= RenderTargets::kMaxColorTargets) return;
        if (texture.empty()) {
            mTargets.colors[static_cast<size_t>(index)].texture = index == 0 ? &mImpl.frameColor : nullptr;
            return;
        }
        mTargets.colors[static_cast<size_t>(index)].texture = target(texture);
    }

    void setDepthTarget(const std::string& texture) override {
        mTargets.depth.texture = texture.empty() ? &mImpl.frameDepth : target(texture);
    }

    void setRenderPort(const std::string& lightName) override {
        if (lightName.empty()) {
            const float aspect = static_cast<float>(mOptions.width) / static_cast<float>(mOptions.height);
            mPort.view = mScene.camera.view();
            mPort.projection = mScene.camera.projection(aspect);
            return;
        }
        const Light* light = mScene.findLight(lightName);
        if (!light) {
            fail(fx::DiagId::UnsupportedFeature, {"RenderPort names light '" + lightName +
                                                  "', which scene '" + mScene.name + "' does not have"});
            return;
        }
        mPort.view = light->view(mSceneBounds);
        mPort.projection = light->projection(mSceneBounds, nearestDepthFrom(mScene, *light));
    }

    void setClearColor(const fx::Value& color) override {
        for (size_t i = 0; i < 4; ++i)
            mClearColor[i] = i < color.data.size() ? color.data[i] : (i == 3 ? 1.0f : 0.0f);
        if (color.data.size() == 1)
            mClearColor = {color.data[0], color.data[0], color.data[0], color.data[0]};
    }
    void setClearDepth(float depth) override { mClearDepth = depth; }
    void setClearStencil(int stencil) override { mClearStencil = stencil; }

    void clear(fx::ScriptCommand::ClearWhat what) override {
        if (!bindTargets()) return;
        ClearRequest request;
        switch (what) {
            case fx::ScriptCommand::ClearWhat::Color:
                request.color = mClearColor;
                break;
            case fx::ScriptCommand::ClearWhat::Depth:
                request.depth = mClearDepth;
                break;
            case fx::ScriptCommand::ClearWhat::Stencil:
                if (mTargets.depth.texture && mTargets.depth.texture->glFormat().hasStencil)
                    request.stencil = mClearStencil;
                break;
        }
        {
            PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
            FramebufferCache::clear(request);
        }
        ++mStats.clears;
    }

    void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) override {
        const size_t passIndex =
            static_cast<size_t>(&pass - mImpl.compiled->techniques[mTechnique].passes.data());
        GpuProgram* program = mImpl.programs[mTechnique][passIndex].get();
        if (!program || !program->hasShaders()) {
            if (mWarnedPasses.insert(passIndex).second) {
                mDiagnostics.report(fx::Diagnostic{
                    fx::DiagId::UnsupportedFeature, fx::Severity::Warning, pass.loc,
                    "pass '" + pass.name + "' draws but has no vertex and pixel shader; skipped"});
            }
            return;
        }
        if (!bindTargets()) return;
        applyStates(pass);
        bindSamplers(pass.vertex);
        bindSamplers(pass.fragment);
        mPort.viewportSize = glm::vec2(mTargets.width(), mTargets.height());

        if (what == fx::ScriptCommand::DrawWhat::Buffer) {
            drawWith(pass, *program, nullptr, mImpl.quad);
            return;
        }
        for (const SceneObject& object : mScene.objects) {
            if (!object.mesh) continue;
            drawWith(pass, *program, &object, mImpl.gpuMesh(object.mesh));
        }
    }

    void reportIgnored(const fx::ScriptCommand& command) override {
        mDiagnostics.report(fx::DiagId::ScriptCommandIgnored, command.loc,
                            {std::string(fx::scriptCommandName(command.kind))});
    }

    const fx::Value* parameter(const std::string& name) const override { return mImpl.find(name); }

    void setParameter(const std::string& name, const fx::Value& value) override {
        auto it = mImpl.parameterIndex.find(name);
        if (it == mImpl.parameterIndex.end()) {
            fail(fx::DiagId::UnknownParameter, {name});
            return;
        }
        fx::Value stored = value;
        stored.type = mImpl.effect().parameters[it->second].type;
        stored.data.resize(static_cast<size_t>(std::max(1, stored.type.componentCount())), value.asFloat());
        mImpl.values[it->second] = std::move(stored);
    }

private:
    void fail(fx::DiagId id, const std::vector<std::string>& args) {
        if (!mFailed) mDiagnostics.report(id, fx::SourceLoc{mImpl.effect().path, 0, 0}, args);
        mFailed = true;
    }

    const GpuTexture* target(const std::string& name) {
        auto index = mImpl.parameterIndex.find(name);
        auto texture =
            index == mImpl.parameterIndex.end() ? mImpl.textures.end() : mImpl.textures.find(index->second);
        if (texture == mImpl.textures.end()) {
            fail(fx::DiagId::ScriptUnknownTarget, {name});
            return nullptr;
        }
        return &texture->second;
    }

    bool bindTargets() {
        if (mFailed) return false;
        std::string error;
        PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
        if (!mImpl.framebuffers.bind(mTargets, error)) {
            fail(fx::DiagId::GlError, {"cannot render to the script's targets: " + error});
            return false;
        }
        for (const RenderTargetAttachment& color : mTargets.colors) {
            if (color.texture && color.texture->mipLevels() > 1) mImpl.staleMipChains.insert(color.texture);
        }
        return true;
    }

    bool isColorTarget(const GpuTexture* texture) const {
        return std::any_of(
            mTargets.colors.begin(), mTargets.colors.end(),
            [texture](const RenderTargetAttachment& color) { return color.texture == texture; });
    }

    void applyStates(const fx::CompiledPass& pass) {
        RenderStateBlock block = RenderStateBlock::defaults();
        const auto lookup = [this](std::string_view name) { return mImpl.find(name); };
        {
            PassTimer::Scope preshaderTime(mTimer, &FrameCpuTime::preshaderNs);
            for (const fx::RenderStateSetting& setting : pass.states) {
                const fx::Expr& value = setting.value;
                if (value.kind == fx::Expr::Kind::Number || value.kind == fx::Expr::Kind::Bool) {
                    block.set(setting.id, value.number);
                    continue;
                }
                if (std::optional<fx::Value> evaluated = fx::evaluate(value, lookup, nullptr, &mDiagnostics))
                    block.set(setting.id, evaluated->asFloat());
            }
        }
        // DepthBias units (RenderStateApplier.h): 2^-bits for UNORM depth; for D32F the resolvable
        // difference is 2^-24 for depths in [0.5, 1), so 32-bit float depth counts as 24 bits.
        const GpuTexture* depth = mTargets.depth.texture;
        const int depthBits = depth ? std::clamp(depth->glFormat().depthBits, 16, 24) : 24;
        applyRenderStates(block, depthBits);
        mCullClosedOnly = cullsClosedObjectsOnly(pass) && block.get(fx::RenderStateId::CullMode) != 1.0;
    }

    // The pass annotation `bool CullClosedOnly = true;`: its CullMode applies to closed (watertight) meshes
    // only, open ones are drawn with culling off. Back-face shadow maps (Wang & Molnar) and dual depth
    // layers with back-face culling (seed 001, §4: "back face culling for solid objects can be mixed with
    // non-culled open surfaces in the same scene") need both in one pass: a culled open plane would vanish.
    bool cullsClosedObjectsOnly(const fx::CompiledPass& pass) const {
        const auto& passes = mImpl.compiled->techniques[mTechnique].passes;
        const auto& sourcePasses = mImpl.effect().techniques[mTechnique].passes;
        const size_t passIndex = static_cast<size_t>(&pass - passes.data());
        if (passIndex >= sourcePasses.size()) return false;
        const fx::Annotation* annotation = sourcePasses[passIndex].annotation("CullClosedOnly");
        return annotation && annotation->value.number != 0.0;
    }

    void bindSamplers(const fx::StageProgram& stage) {
        for (const fx::SamplerBinding& binding : stage.samplers) {
            const fx::SamplerDesc* desc = mImpl.compiled->findSampler(binding.samplerParameter);
            const GpuTexture* texture = nullptr;
            if (desc && desc->texture) {
                auto it = mImpl.textures.find(*desc->texture);
                if (it != mImpl.textures.end()) texture = &it->second;
            }
            // Not while the pass renders into it (the chain would be built before the draw that changes it).
            if (texture && !isColorTarget(texture) && mImpl.staleMipChains.erase(texture) > 0) {
                PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
                texture->generateMipmaps();
            }
            gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(binding.unit));
            if (texture) {
                gl::BindTexture(texture->target(), texture->id());
            } else {
                gl::BindTexture(GL_TEXTURE_2D, 0);
            }
            auto& samplers = binding.depthCompare ? mImpl.comparisonSamplers : mImpl.samplers;
            auto sampler = samplers.find(binding.samplerParameter);
            if (sampler != samplers.end()) {
                sampler->second.bind(binding.unit);
            } else {
                SamplerObject::unbind(binding.unit);
            }
        }
    }

    void drawWith(const fx::CompiledPass& pass, GpuProgram& program, const SceneObject* object,
                  GpuMesh& mesh) {
        {
            PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
            mBinder.bind(mPort, object, mOptions.time, mImpl.values, mImpl.pinned);
        }
        std::vector<fx::Value> arguments;
        arguments.reserve(pass.arguments.size());
        const auto lookup = [this](std::string_view name) { return mImpl.find(name); };
        {
            PassTimer::Scope preshaderTime(mTimer, &FrameCpuTime::preshaderNs);
            for (const fx::CompileArgument& argument : pass.arguments) {
                std::optional<fx::Value> value =
                    fx::evaluate(argument.expr, lookup, &argument.type, &mDiagnostics);
                arguments.push_back(value ? std::move(*value) : fx::zeroValue(argument.type));
            }
        }
        {
            PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
            program.use(mImpl.values, arguments);
        }
        {
            PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
            const bool drawUnculled = mCullClosedOnly && object && !(object->mesh && object->mesh->closed);
            if (drawUnculled) gl::Disable(GL_CULL_FACE);
            mesh.draw(pass.vertex.inputs);
            if (drawUnculled) gl::Enable(GL_CULL_FACE);
        }
        ++mStats.draws;
        mTimer.countDraw();
        mStats.triangles += mesh.indexCount() / 3;
    }

    EffectRenderer::Impl& mImpl;
    const Scene& mScene;
    const FrameOptions& mOptions;
    fx::DiagnosticSink& mDiagnostics;
    FrameStats& mStats;
    PassTimer mTimer{mOptions.timePasses, mStats};
    size_t mTechnique;
    SemanticBinder mBinder;
    Bounds mSceneBounds;
    RenderTargets mTargets;
    RenderPortView mPort;
    std::array<float, 4> mClearColor{0.0f, 0.0f, 0.0f, 0.0f};  // D3D's Clear defaults
    float mClearDepth = 1.0f;
    int mClearStencil = 0;
    bool mFailed = false;
    bool mCullClosedOnly = false;  // this pass culls closed objects only (cullsClosedObjectsOnly)
    std::set<size_t> mWarnedPasses;
};

}  // namespace

bool EffectRenderer::render(const Scene& scene, const FrameOptions& options, fx::DiagnosticSink& diagnostics,
                            FrameStats* stats) {
    FrameStats localStats;
    FrameStats& frameStats = stats ? *stats : localStats;
    frameStats = {};

    // Technique selection reads parameters only; a throwaway executor would need GL, so use a minimal view.
    struct ParameterView : ScriptTarget {
        const Impl& impl;
        explicit ParameterView(const Impl& i) : impl(i) {}
        void beginPass(const fx::CompiledPass&) override {}
        void setColorTarget(int, const std::string&) override {}
        void setDepthTarget(const std::string&) override {}
        void setRenderPort(const std::string&) override {}
        void setClearColor(const fx::Value&) override {}
        void setClearDepth(float) override {}
        void setClearStencil(int) override {}
        void clear(fx::ScriptCommand::ClearWhat) override {}
        void draw(const fx::CompiledPass&, fx::ScriptCommand::DrawWhat) override {}
        void reportIgnored(const fx::ScriptCommand&) override {}
        const fx::Value* parameter(const std::string& name) const override { return impl.find(name); }
        void setParameter(const std::string&, const fx::Value&) override {}
    };
    const fx::CompiledTechnique* technique = ScriptInterpreter::selectTechnique(
        *mImpl->compiled, options.technique, ParameterView(*mImpl), diagnostics);
    if (!technique) return false;
    const size_t techniqueIndex = static_cast<size_t>(technique - mImpl->compiled->techniques.data());

    // KHR_debug messages (debug contexts) and GL errors found while the frame runs go to the caller's sink.
    setDebugSink([&diagnostics](std::string message) {
        diagnostics.report(fx::Diagnostic{fx::DiagId::GlDebugMessage, fx::Severity::Note, fx::SourceLoc{},
                                          fx::formatDiagnostic(fx::DiagId::GlDebugMessage, {message})});
    });
    mImpl->ensureFrameResources(options.width, options.height);
    // Camera-relative rendering for scenes far from the origin (Scene.h, renderOrigin).
    const glm::vec3 origin = renderOrigin(scene);
    const std::optional<Scene> rebased =
        origin == glm::vec3(0.0f) ? std::nullopt : std::optional<Scene>(scene.translated(-origin));
    FrameExecutor executor(*mImpl, rebased ? *rebased : scene, options, diagnostics, frameStats,
                           techniqueIndex);
    const bool ran = ScriptInterpreter::run(*technique, executor, diagnostics);
    executor.finishTiming();
    FramebufferCache::bindDefault();
    const bool clean = checkGlErrors("EffectRenderer::render", __FILE__, __LINE__);
    setDebugSink({});
    if (!clean)
        diagnostics.report(fx::DiagId::GlError, fx::SourceLoc{mImpl->effect().path, 0, 0},
                           {"GL error during the frame"});
    return ran && !executor.failed() && clean;
}

FrameImage EffectRenderer::readFrame() const {
    FrameImage frame;
    if (!mImpl->frameColor) return frame;
    const Image image = readColorTarget(mImpl->frameColor).toRGBA8();
    frame.width = image.width;
    frame.height = image.height;
    frame.rgba = image.bytes;
    return frame;
}

std::optional<std::vector<float>> EffectRenderer::readTarget(std::string_view textureName, int* width,
                                                             int* height, int* channels, int level) const {
    const std::optional<size_t> index = findParameter(textureName);
    if (!index) return std::nullopt;
    auto it = mImpl->textures.find(*index);
    if (it == mImpl->textures.end() || level < 0 || level >= it->second.mipLevels()) return std::nullopt;
    const Image image = readFloatTexture(it->second, level);
    if (width) *width = image.width;
    if (height) *height = image.height;
    if (channels) *channels = image.channels;
    return image.floats;
}

bool writePng(const FrameImage& frame, const std::string& path, std::string& error) {
    Image image = Image::makeBytes(frame.width, frame.height, 4);
    image.bytes = frame.rgba;
    return image.writePng(path, error);
}

}  // namespace runtime
