// EffectRenderer: GL resources of one compiled effect, and the frame executor that runs its SAS scripts.
//
// [SECTION] Resources   textures (render targets sized per frame, file and runtime textures), samplers,
//                       one GpuProgram per pass, GPU meshes cached per scene mesh
// [SECTION] Parameters  values, pinning, --set parsing
// [SECTION] Frame       FrameExecutor: the ScriptTarget that binds targets, states, semantics and draws
#include <runtime/EffectRenderer.h>

#include <runtime/CascadedShadowMaps.h>
#include <private/runtime/FramePlan.h>
#include <runtime/Framebuffer.h>
#include <runtime/GlDebug.h>
#include <runtime/GpuMesh.h>
#include <runtime/GpuProgram.h>
#include <runtime/GpuTexture.h>
#include <runtime/Image.h>
#include <runtime/InstanceBvh.h>
#include <runtime/IntersectionBody.h>
#include <runtime/PassTimer.h>
#include <private/runtime/ProceduralTexture.h>
#include <runtime/RenderStateApplier.h>
#include <runtime/SamplerObject.h>
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
    std::unique_ptr<UniformRing> uniformRing;
    // The scene as last rendered: a stamp of its objects, its bounds (a pass over every vertex) and the
    // BVH over its objects' boxes, rebuilt only when the stamp changes (see sceneStamp()).
    struct SceneCache {
        uint64_t stamp = 0;
        bool valid = false;
        Bounds bounds;
        InstanceBvh bvh;
        std::map<const Mesh*, Aabb> meshBoxes;
    } sceneCache;
    // What each render target holds after the frames so far (FramePlan): how light passes are reused.
    std::map<int, TargetHistory> targetHistory;

    const fx::Effect& effect() const { return *compiled->effect; }
    const fx::Value* find(std::string_view name) const {
        auto it = parameterIndex.find(std::string(name));
        return it == parameterIndex.end() ? nullptr : &values[it->second];
    }
    bool createFileTextures(fx::DiagnosticSink& diagnostics);
    // (Re)allocates render targets whose size depends on the frame's.
    // `needed`: the render targets to allocate (null: all); others already allocated are still resized.
    void ensureFrameResources(int width, int height, const std::set<int>* needed = nullptr);
    GpuMesh& gpuMesh(const std::shared_ptr<const Mesh>& mesh);
    void updateSceneCache(const Scene& scene);
    // A render target's allocation (GL name, size, format), for FramePlan's content hashes.
    uint64_t targetIdentity(int resource) const;
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

// A render target's size for a frame of width x height: its Dimensions, or its ViewPortRatio of the frame.
glm::ivec2 renderTargetSize(const fx::TextureDesc& desc, int width, int height) {
    return glm::ivec2(
        desc.width > 0 ? desc.width
                       : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[0] * width))),
        desc.height > 0 ? desc.height
                        : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[1] * height))));
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

void EffectRenderer::Impl::ensureFrameResources(int width, int height, const std::set<int>* needed) {
    if (frameColor.width() != width || frameColor.height() != height) {
        if (frameColor) framebuffers.evict(frameColor);
        if (frameDepth) framebuffers.evict(frameDepth);
        frameColor = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        frameDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    for (const fx::TextureDesc& desc : compiled->textures) {
        if (!isRenderTarget(desc)) continue;
        const glm::ivec2 size = renderTargetSize(desc, width, height);
        const int w = size.x, h = size.y;
        auto it = textures.find(desc.parameter);
        if (it == textures.end() && needed && !needed->count(static_cast<int>(desc.parameter))) continue;
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
    impl->uniformRing = std::make_unique<UniformRing>();
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

// A stamp of everything about the scene's objects a draw depends on (mesh, transform, colour, id, flags)
// and of its explicit bounds. Hashed every frame rather than kept as a revision counter that every
// editor of a Scene would have to bump: 10,000 objects are about 1 MB of hashing, well under a
// millisecond next to a frame of them.
uint64_t sceneStamp(const Scene& scene) {
    uint64_t h = hashCombine(0, scene.objects.size());
    for (const SceneObject& object : scene.objects) {
        h = hashCombine(h, reinterpret_cast<uintptr_t>(object.mesh.get()));
        if (object.mesh)
            h = hashCombine(h, object.mesh->indices.size() ^ (object.mesh->positions.size() << 32));
        h = hashBytes(h, &object.world, sizeof(object.world));
        h = hashBytes(h, &object.color, sizeof(object.color));
        h = hashCombine(h, (uint64_t(object.id) << 2) | (object.castsShadow ? 1u : 0u) |
                               (object.receivesShadow ? 2u : 0u));
    }
    if (scene.explicitBounds) h = hashBytes(h, &*scene.explicitBounds, sizeof(Bounds));
    return h;
}

// Filter footprint the receiver region keeps around every receiver, in shadow-map texels: bilinear PCF
// reads one texel around the lookup, the thesis effect's jitter up to JITTER_AMOUNT / 2 = 2 texels.
constexpr float kReceiverPadTexels = 8.0f;

}  // namespace

void EffectRenderer::Impl::updateSceneCache(const Scene& scene) {
    const uint64_t stamp = sceneStamp(scene);
    if (sceneCache.valid && sceneCache.stamp == stamp) return;
    sceneCache.stamp = stamp;
    sceneCache.valid = true;
    sceneCache.bounds = scene.bounds();
    sceneCache.meshBoxes.clear();
    std::vector<Aabb> boxes(scene.objects.size());
    std::vector<bool> present(scene.objects.size(), false);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (!object.mesh || object.mesh->positions.empty()) continue;
        auto it = sceneCache.meshBoxes.find(object.mesh.get());
        if (it == sceneCache.meshBoxes.end())
            it = sceneCache.meshBoxes
                     .emplace(object.mesh.get(), Aabb{object.mesh->boundsMin(), object.mesh->boundsMax()})
                     .first;
        boxes[i] = transformBox(it->second, object.world);
        present[i] = true;
    }
    sceneCache.bvh = InstanceBvh(std::move(boxes), present);
}

uint64_t EffectRenderer::Impl::targetIdentity(int resource) const {
    const GpuTexture* texture = nullptr;
    if (resource == kFrameColor) texture = &frameColor;
    if (resource == kFrameDepth) texture = &frameDepth;
    if (resource >= 0) {
        auto it = textures.find(static_cast<size_t>(resource));
        if (it != textures.end()) texture = &it->second;
    }
    uint64_t h = hashCombine(0, static_cast<uint64_t>(static_cast<int64_t>(resource)));
    if (!texture) return h;
    h = hashCombine(h, texture->id());
    h = hashCombine(h, (uint64_t(uint32_t(texture->width())) << 32) | uint32_t(texture->height()));
    return hashCombine(h, static_cast<uint64_t>(texture->format()));
}

namespace {

// What one pass reads: the parameters its stages' uniform blocks, compile arguments and render-state
// expressions name. Only these are bound (semantics) and hashed (FramePlan signatures); compile arguments
// that read no per-object semantic are evaluated once per pass instead of once per draw.
struct PassUse {
    std::vector<bool> used;                 // per effect parameter
    std::vector<bool> argumentPerObject;    // per CompiledPass::arguments entry
    std::vector<size_t> perPassParameters;  // used and not bound per object
    // The view/projection matrices it reads: the port's, and those of annotated lights. Culling trusts
    // the port's frustum only for passes that project with it (a camera-port pass that draws a light's
    // view with frustum="light0" matrices is not culled).
    bool readsPortMatrix = false;
    std::vector<const Light*> lightMatrices;
};

void collectParameters(const fx::Expr& expr, const EffectRenderer::Impl& impl, std::vector<bool>& used) {
    if (expr.kind == fx::Expr::Kind::Identifier) {
        auto it = impl.parameterIndex.find(expr.text);
        if (it != impl.parameterIndex.end()) used[it->second] = true;
    }
    for (const fx::Expr& arg : expr.args) collectParameters(arg, impl, used);
}

std::vector<PassUse> passUses(const EffectRenderer::Impl& impl, const fx::CompiledTechnique& technique,
                              const SemanticBinder& binder) {
    const size_t count = impl.values.size();
    std::vector<PassUse> uses;
    for (const fx::CompiledPass& pass : technique.passes) {
        PassUse use;
        use.used.assign(count, false);
        for (const fx::StageProgram* stage : {&pass.vertex, &pass.fragment})
            for (const fx::UniformBinding& member : stage->uniforms)
                if (member.active && member.source == fx::UniformBinding::Source::Parameter &&
                    member.index < count)
                    use.used[member.index] = true;
        for (const fx::RenderStateSetting& setting : pass.states)
            collectParameters(setting.value, impl, use.used);
        for (const fx::CompileArgument& argument : pass.arguments) {
            std::vector<bool> reads(count, false);
            collectParameters(argument.expr, impl, reads);
            bool perObject = false;
            for (size_t p = 0; p < count; ++p) {
                if (!reads[p]) continue;
                use.used[p] = true;
                perObject = perObject || binder.isPerObject(p);
            }
            use.argumentPerObject.push_back(perObject);
        }
        for (size_t p = 0; p < count; ++p) {
            if (!use.used[p]) continue;
            if (!binder.isPerObject(p)) use.perPassParameters.push_back(p);
            const Light* light = nullptr;
            if (!binder.projectionSource(p, light)) continue;
            if (light) {
                use.lightMatrices.push_back(light);
            } else {
                use.readsPortMatrix = true;
            }
        }
        uses.push_back(std::move(use));
    }
    return uses;
}

// The view and projection a RenderPort gives ("" = the camera; `cascade` >= 0: that cascade of the light).
// A light port renders with the matrices the effect's parameterization of that light gives (`binder`).
// False, with why in `error`, if the scene has no such light or the light no such cascade.
bool portMatrices(const Scene& scene, const SemanticBinder& binder, const FrameOptions& options,
                  const std::string& light, int cascade, RenderPortView& port, std::string* error = nullptr) {
    port.lightIndex = port.cascade = -1;
    if (light.empty()) {
        const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
        port.view = scene.camera.view();
        port.projection = scene.camera.projection(aspect);
        return true;
    }
    const Light* found = scene.findLight(light);
    if (!found) {
        if (error) *error = "light '" + light + "', which scene '" + scene.name + "' does not have";
        return false;
    }
    const LightFit fit = binder.lightFit(*found);
    if (cascade >= static_cast<int>(fit.cascades.size())) {
        if (error)
            *error = "cascade " + std::to_string(cascade) + " of light '" + light + "', which has " +
                     (fit.cascades.empty()
                          ? std::string("no cascades (its Parameterization is not \"Cascaded\" or "
                                        "\"PSMCube\")")
                          : std::to_string(fit.cascades.size()) + " (CascadeCount)");
        return false;
    }
    port.view = cascade >= 0 ? fit.cascades[static_cast<size_t>(cascade)].view : fit.view;
    port.projection = cascade >= 0 ? fit.cascades[static_cast<size_t>(cascade)].projection : fit.projection;
    port.shinesIntoPositiveW = fit.shinesIntoPositiveW;
    if (cascade >= 0) {
        port.lightIndex = static_cast<int>(found - scene.lights.data());
        port.cascade = cascade;
    }
    return true;
}

// The tile of a `width` x `height` target that RenderPort=lightN.cascadeK renders into
// (runtime/CascadedShadowMaps.h): x, y, w, h in texels.
glm::ivec4 portTile(const SemanticBinder& binder, const Scene& scene, const RenderPortView& port, int width,
                    int height) {
    const LightFit fit = binder.lightFit(scene.lights[static_cast<size_t>(port.lightIndex)]);
    const LightView& view = fit.cascades[static_cast<size_t>(port.cascade)];
    // A PSMCube face's own tile (the used faces share the atlas), else the cascades' fixed grid.
    if (view.atlasRect.z > 0.0f) return atlasViewport(view.atlasRect, width, height);
    return cascadeViewport(port.cascade, static_cast<int>(fit.cascades.size()), width, height);
}

std::vector<const fx::SamplerBinding*> passSamplers(const fx::CompiledPass& pass) {
    std::vector<const fx::SamplerBinding*> samplers;
    for (const fx::StageProgram* stage : {&pass.vertex, &pass.fragment})
        for (const fx::SamplerBinding& binding : stage->samplers) samplers.push_back(&binding);
    return samplers;
}

// The dry run: follows the technique's script as FrameExecutor will, on a copy of the parameter values,
// and records every clear and draw with its targets, sampled textures and signature (FramePlan). No GL.
class PlanRecorder : public ScriptTarget {
public:
    static constexpr int kNone = -1000;     // an unbound colour slot
    static constexpr int kUnknown = -1001;  // a target the executor will reject

    PlanRecorder(const EffectRenderer::Impl& impl, const Scene& scene, const FrameOptions& options,
                 const SemanticBinder& binder, const std::vector<PassUse>& uses, size_t technique,
                 const std::vector<glm::vec3>& body, FramePlan& plan)
        : mImpl(impl),
          mScene(scene),
          mOptions(options),
          mBinder(binder),
          mUses(uses),
          mTechnique(technique),
          mBody(body),
          mPlan(plan),
          mValues(impl.values) {
        mColors.fill(kNone);
        mColors[0] = kFrameColor;
        setRenderPort("", -1, {});
    }

    void beginPass(const fx::CompiledPass& pass) override {
        mPass = passIndex(pass);
        mSceneSaysSkip = sceneSaysSkip(pass);
        mPadTexels = receiverPadTexels(pass);
    }
    void setColorTarget(int index, const std::string& texture) override {
        if (index < 0 || index >= RenderTargets::kMaxColorTargets) return;
        mColors[static_cast<size_t>(index)] =
            texture.empty() ? (index == 0 ? kFrameColor : kNone) : resource(texture);
    }
    void setDepthTarget(const std::string& texture) override {
        mDepth = texture.empty() ? kFrameDepth : resource(texture);
    }
    void setRenderPort(const std::string& light, int cascade, const fx::SourceLoc&) override {
        mLightPort = !light.empty();
        portMatrices(mScene, mBinder, mOptions, light, cascade, mPort);
    }
    void setClearColor(const fx::Value& color) override { mClearColor = color.data; }
    void setClearDepth(float depth) override { mClearDepth = depth; }
    void setClearStencil(int stencil) override { mClearStencil = stencil; }

    void clear(fx::ScriptCommand::ClearWhat what) override {
        PlannedOp op;
        op.pass = mPass;
        op.lightPort = mLightPort;
        uint64_t value = 0;
        switch (what) {
            case fx::ScriptCommand::ClearWhat::Color:
                op.kind = PlannedOp::Kind::ClearColor;
                op.writes = colorTargets();
                value = hashBytes(0, mClearColor.data(), mClearColor.size() * sizeof(float));
                break;
            case fx::ScriptCommand::ClearWhat::Depth:
                op.kind = PlannedOp::Kind::ClearDepth;
                if (mDepth != kNone) op.writes = {mDepth};
                value = hashBytes(0, &mClearDepth, sizeof(mClearDepth));
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
        mPlan.ops.push_back(std::move(op));
    }

    void draw(const fx::CompiledPass& pass, fx::ScriptCommand::DrawWhat what) override {
        const size_t index = passIndex(pass);
        const GpuProgram* program = mImpl.programs[mTechnique][index].get();
        if (!program || !program->hasShaders()) return;  // FrameExecutor warns and skips it too
        PlannedOp op;
        op.kind = what == fx::ScriptCommand::DrawWhat::Buffer ? PlannedOp::Kind::DrawBuffer
                                                              : PlannedOp::Kind::DrawGeometry;
        op.pass = index;
        op.lightPort = mLightPort;
        // Bound targets are read (blending, depth and stencil tests); they are written unless the pass's
        // states mask the writes (the hardware shadow map's ColorWriteEnable = 0, BlendOp=min without Z).
        const RenderStateBlock states = passStates(pass);
        static constexpr fx::RenderStateId kColorWrites[] = {
            fx::RenderStateId::ColorWriteEnable, fx::RenderStateId::ColorWriteEnable1,
            fx::RenderStateId::ColorWriteEnable2, fx::RenderStateId::ColorWriteEnable3};
        for (size_t slot = 0; slot < mColors.size(); ++slot) {
            if (mColors[slot] == kNone) continue;
            op.reads.push_back(mColors[slot]);
            if (states.get(kColorWrites[slot]) != 0.0) op.writes.push_back(mColors[slot]);
        }
        if (mDepth != kNone) {
            op.reads.push_back(mDepth);
            const bool depthWrites = states.get(fx::RenderStateId::ZEnable) != 0.0 &&
                                     states.get(fx::RenderStateId::ZWriteEnable) != 0.0;
            if (depthWrites || states.get(fx::RenderStateId::StencilEnable) != 0.0)
                op.writes.push_back(mDepth);
        }
        for (const fx::SamplerBinding* binding : passSamplers(pass)) {
            const fx::SamplerDesc* desc = mImpl.compiled->findSampler(binding->samplerParameter);
            if (desc && desc->texture) op.reads.push_back(static_cast<int>(*desc->texture));
        }

        const PassUse& use = mUses[index];
        mPort.viewportSize = targetSize();
        if (mPort.cascade >= 0) {
            const glm::ivec4 tile = portTile(mBinder, mScene, mPort, static_cast<int>(mPort.viewportSize.x),
                                             static_cast<int>(mPort.viewportSize.y));
            mPort.viewportSize = glm::vec2(tile.z, tile.w);
        }
        mBinder.bind(mPort, nullptr, mOptions.time, mValues, mImpl.pinned, SemanticBinder::Scope::PerPort,
                     &use.used);
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
        if (op.kind == PlannedOp::Kind::DrawGeometry) h = hashCombine(h, mImpl.sceneCache.stamp);
        op.signature = h;
        op.sceneSaysSkip = mSceneSaysSkip;
        if (mLightPort && op.kind == PlannedOp::Kind::DrawGeometry) {
            const LightFit portFit =
                mPort.cascade >= 0 ? mBinder.lightFit(mScene.lights[static_cast<size_t>(mPort.lightIndex)])
                                   : LightFit{};
            if (portFit.cubeFaces) {
                // A PSMCube face serves the receivers of B within its pyramid (its window is fitted to
                // them); a face that none uses is left out.
                op.sceneSaysSkip =
                    op.sceneSaysSkip || !portFit.cascades[static_cast<size_t>(mPort.cascade)].serves;
                op.region =
                    receiverRegion(mBody, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
            } else if (mPort.cascade >= 0) {
                // A cascade serves the receivers of its own depth slice only: its casters are culled to that
                // slice, and a slice beyond the farthest receiver has nothing to serve.
                const InstanceBvh& bvh = mImpl.sceneCache.bvh;
                const glm::mat4 slice = cascadeSlice();
                std::vector<glm::vec3> body;
                std::vector<uint32_t> receivers;
                if (!bvh.empty()) {
                    body = intersectionBodyPoints(slice, Bounds{bvh.rootBox().min, bvh.rootBox().max});
                    const ConvexVolume frustum = frustumPlanes(slice);
                    bvh.query([&](const Aabb& box) { return overlapVolume(frustum, box); }, receivers);
                    op.sceneSaysSkip = op.sceneSaysSkip || receivers.empty();
                }
                op.region =
                    receiverRegion(body, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
            } else {
                op.region =
                    receiverRegion(mBody, mPort.projection * mPort.view, mPort.viewportSize, mPadTexels);
            }
            op.region.castersBehindLightPlaneCastNothing = mPort.shinesIntoPositiveW;
        }
        mPlan.ops.push_back(std::move(op));
    }

    void reportIgnored(const fx::ScriptCommand&) override {}
    const fx::Value* parameter(const std::string& name) const override {
        auto it = mImpl.parameterIndex.find(name);
        return it == mImpl.parameterIndex.end() ? nullptr : &mValues[it->second];
    }
    void setParameter(const std::string& name, const fx::Value& value) override {
        auto it = mImpl.parameterIndex.find(name);
        if (it == mImpl.parameterIndex.end()) return;
        fx::Value stored = value;
        stored.type = mImpl.effect().parameters[it->second].type;
        stored.data.resize(static_cast<size_t>(std::max(1, stored.type.componentCount())), value.asFloat());
        mValues[it->second] = std::move(stored);
    }

private:
    size_t passIndex(const fx::CompiledPass& pass) const {
        return static_cast<size_t>(&pass - mImpl.compiled->techniques[mTechnique].passes.data());
    }
    int resource(const std::string& name) const {
        auto it = mImpl.parameterIndex.find(name);
        if (it == mImpl.parameterIndex.end()) return kUnknown;
        const fx::TextureDesc* desc = mImpl.compiled->findTexture(it->second);
        if (!mImpl.textures.count(it->second) && !(desc && isRenderTarget(*desc))) return kUnknown;
        return static_cast<int>(it->second);
    }
    // The effect's declaration of `pass`, for its annotations.
    const fx::Pass* sourcePass(const fx::CompiledPass& pass) const {
        const std::string& technique = mImpl.compiled->techniques[mTechnique].name;
        for (const fx::Technique& source : mImpl.effect().techniques) {
            if (source.name != technique) continue;
            for (const fx::Pass& declared : source.passes)
                if (declared.name == pass.name) return &declared;
        }
        return nullptr;
    }
    // A pass annotated `string LeaveOutWhen = "NoClosedObjects";` (no object's mesh is closed: a second
    // depth layer finds nothing) or "NoLightArea" (no light has an area: no soft-shadow filter needed) is
    // left out where that holds. The effect guarantees that later passes do not need what it writes then.
    bool sceneSaysSkip(const fx::CompiledPass& pass) const {
        const fx::Pass* declared = sourcePass(pass);
        const fx::Annotation* when = declared ? declared->annotation("LeaveOutWhen") : nullptr;
        if (!when || when->value.kind != fx::Expr::Kind::String) return false;
        if (when->value.text == "NoClosedObjects")
            return std::none_of(mScene.objects.begin(), mScene.objects.end(),
                                [](const SceneObject& o) { return o.mesh && o.mesh->closed; });
        if (when->value.text == "NoLightArea")
            return std::all_of(mScene.lights.begin(), mScene.lights.end(),
                               [](const Light& light) { return light.areaRadius <= 0.0f; });
        return false;
    }
    // How far around a receiver's own texel the passes reading this light pass's map look, in texels: what
    // the pass declares (`float FilterReachTexels = 65;` on a map read by a PCSS blocker search, 2 for 2x2
    // bilinear PCF), else kReceiverPadTexels, so that light-pass culling keeps every caster they can see.
    // A declared reach matters most for warped maps (LiSPSM), whose far texels are large in world units.
    float receiverPadTexels(const fx::CompiledPass& pass) const {
        const fx::Pass* declared = sourcePass(pass);
        const fx::Annotation* reach = declared ? declared->annotation("FilterReachTexels") : nullptr;
        if (!reach || reach->value.kind != fx::Expr::Kind::Number) return kReceiverPadTexels;
        return std::max(1.0f, static_cast<float>(reach->value.number));  // a texel for rounding at least
    }
    RenderStateBlock passStates(const fx::CompiledPass& pass) const {
        RenderStateBlock block = RenderStateBlock::defaults();
        const auto lookup = [this](std::string_view name) { return parameter(std::string(name)); };
        fx::DiagnosticList ignored;  // FrameExecutor::applyStates reports them
        for (const fx::RenderStateSetting& setting : pass.states) {
            if (setting.value.kind == fx::Expr::Kind::Number || setting.value.kind == fx::Expr::Kind::Bool) {
                block.set(setting.id, setting.value.number);
                continue;
            }
            if (std::optional<fx::Value> value = fx::evaluate(setting.value, lookup, nullptr, &ignored))
                block.set(setting.id, value->asFloat());
        }
        return block;
    }
    // The current cascade's slice of the camera frustum (between its split depths) as a view-projection:
    // its casters are culled to B within it, and a slice no object's box meets has no receiver to serve.
    glm::mat4 cascadeSlice() const {
        const Light& light = mScene.lights[static_cast<size_t>(mPort.lightIndex)];
        const LightView cascade = mBinder.lightFit(light).cascades[static_cast<size_t>(mPort.cascade)];
        Camera slice = mScene.camera;
        slice.nearPlane = cascade.splitNear;
        slice.farPlane = cascade.splitFar;
        const float aspect = static_cast<float>(mOptions.width) / static_cast<float>(mOptions.height);
        return slice.projection(aspect) * slice.view();
    }
    std::vector<int> colorTargets() const {
        std::vector<int> targets;
        for (int target : mColors)
            if (target != kNone) targets.push_back(target);
        return targets;
    }
    glm::vec2 targetSize() const {
        for (int target : {mColors[0], mDepth}) {
            if (target == kFrameColor || target == kFrameDepth)
                return glm::vec2(mOptions.width, mOptions.height);
            if (target < 0) continue;
            const fx::TextureDesc* desc = mImpl.compiled->findTexture(static_cast<size_t>(target));
            if (desc) return glm::vec2(renderTargetSize(*desc, mOptions.width, mOptions.height));
        }
        return glm::vec2(mOptions.width, mOptions.height);
    }

    const EffectRenderer::Impl& mImpl;
    const Scene& mScene;
    const FrameOptions& mOptions;
    const SemanticBinder& mBinder;
    const std::vector<PassUse>& mUses;
    size_t mTechnique;
    const std::vector<glm::vec3>& mBody;
    FramePlan& mPlan;
    std::vector<fx::Value> mValues;
    std::array<int, RenderTargets::kMaxColorTargets> mColors{};
    int mDepth = kFrameDepth;
    bool mLightPort = false;
    RenderPortView mPort;
    size_t mPass = 0;
    bool mSceneSaysSkip = false;
    float mPadTexels = kReceiverPadTexels;  // receiverPadTexels of the current pass
    std::vector<float> mClearColor;
    float mClearDepth = 1.0f;
    int mClearStencil = 0;
};

class FrameExecutor : public ScriptTarget {
public:
    FrameExecutor(EffectRenderer::Impl& impl, const Scene& scene, const FrameOptions& options,
                  fx::DiagnosticSink& diagnostics, FrameStats& stats, size_t techniqueIndex,
                  const SemanticBinder& binder, const std::vector<PassUse>& uses, const FramePlan& plan)
        : mImpl(impl),
          mScene(scene),
          mOptions(options),
          mDiagnostics(diagnostics),
          mStats(stats),
          mTechnique(techniqueIndex),
          mBinder(binder),
          mUses(uses),
          mPlan(plan) {
        mTargets.colors[0].texture = &impl.frameColor;
        mTargets.depth.texture = &impl.frameDepth;
        setRenderPort("", -1, {});
    }

    bool failed() const { return mFailed; }
    // False if the frame's commands did not follow the plan (then nothing after the divergence was left out).
    bool followedPlan() const { return mPlanFollowed && mNextOp == mPlan.ops.size(); }
    // Closes the last pass's record, reads the fragment counts and, with FrameOptions::timePasses, waits
    // for the GPU and fills the frame's pass timings.
    void finish() {
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

    void beginPass(const fx::CompiledPass& pass) override {
        closePass();
        mCurrentPass = static_cast<size_t>(&pass - mImpl.compiled->techniques[mTechnique].passes.data());
        PassStats record;
        record.pass = pass.name;
        mStats.passes.push_back(record);
        mPassOps = 0;
        mPassLeftOut.fill(0);
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

    void setRenderPort(const std::string& lightName, int cascade, const fx::SourceLoc& loc) override {
        mLightPort = !lightName.empty();
        mPortLight = mLightPort ? mScene.findLight(lightName) : nullptr;
        std::string error;
        if (!portMatrices(mScene, mBinder, mOptions, lightName, cascade, mPort, &error)) {
            if (!mFailed)
                mDiagnostics.report(fx::DiagId::ScriptUnknownRenderPort,
                                    loc.valid() ? loc : fx::SourceLoc{mImpl.effect().path, 0, 0}, {error});
            mFailed = true;
        }
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
        const PlannedOp::Kind kind = what == fx::ScriptCommand::ClearWhat::Color ? PlannedOp::Kind::ClearColor
                                     : what == fx::ScriptCommand::ClearWhat::Depth
                                         ? PlannedOp::Kind::ClearDepth
                                         : PlannedOp::Kind::ClearStencil;
        if (leftOut(nextOp(kind, mCurrentPass))) return;
        if (!bindTargets()) return;
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
                for (const auto& color : mTargets.colors)
                    if (color.texture) texels += texelCount(*color.texture);
                break;
            case fx::ScriptCommand::ClearWhat::Depth:
                request.depth = mClearDepth;
                if (mTargets.depth.texture) texels += texelCount(*mTargets.depth.texture);
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
            FramebufferCache::clear(request);
        }
        if (tileOnly) gl::Disable(GL_SCISSOR_TEST);  // every pass's states set it anew (RenderStateApplier)
        ++mStats.clears;
        if (PassStats* record = currentPass()) {
            ++record->clears;
            record->texelsWritten += texels;
        }
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
        const bool buffer = what == fx::ScriptCommand::DrawWhat::Buffer;
        const PlannedOp* op =
            nextOp(buffer ? PlannedOp::Kind::DrawBuffer : PlannedOp::Kind::DrawGeometry, passIndex);
        if (leftOut(op)) return;
        if (!bindTargets()) return;
        applyStates(pass);
        bindSamplers(pass.vertex);
        bindSamplers(pass.fragment);
        mPort.viewportSize = glm::vec2(mTargets.width(), mTargets.height());
        if (mPort.cascade >= 0) {
            const glm::ivec4 tile = portTile(mBinder, mScene, mPort, mTargets.width(), mTargets.height());
            gl::Viewport(tile.x, tile.y, tile.z, tile.w);
            mPort.viewportSize = glm::vec2(tile.z, tile.w);
        }
        program->bind();
        const PassUse& use = mUses[passIndex];
        if (mOptions.leaveOut) {
            // Per-frame and per-port values once per pass; drawWith() then binds only per-object ones.
            PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
            mBinder.bind(mPort, nullptr, mOptions.time, mImpl.values, mImpl.pinned,
                         SemanticBinder::Scope::PerPort, &use.used);
        }
        evaluateArguments(pass, use, false);

        GLuint query = 0;
        if (mOptions.countTexels) {
            gl::GenQueries(1, &query);
            gl::BeginQuery(GL_SAMPLES_PASSED, query);
        }
        if (buffer) {
            drawWith(pass, *program, use, nullptr, mImpl.quad);
        } else if (mOptions.leaveOut && mImpl.sceneCache.valid && projectsWithPort(use)) {
            mVisible.clear();
            cull(op, mVisible);
            int drawable = 0;
            for (const SceneObject& object : mScene.objects) drawable += object.mesh ? 1 : 0;
            for (uint32_t index : mVisible) {
                const SceneObject& object = mScene.objects[index];
                drawWith(pass, *program, use, &object, mImpl.gpuMesh(object.mesh));
            }
            const int culled = drawable - static_cast<int>(mVisible.size());
            mStats.culled += culled;
            if (PassStats* record = currentPass()) record->culled += culled;
        } else {
            for (const SceneObject& object : mScene.objects) {
                if (!object.mesh) continue;
                drawWith(pass, *program, use, &object, mImpl.gpuMesh(object.mesh));
            }
        }
        if (query) {
            gl::EndQuery(GL_SAMPLES_PASSED);
            if (!mStats.passes.empty())
                mTexelQueries.emplace_back(mStats.passes.size() - 1, query);
            else
                gl::DeleteQueries(1, &query);
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

    PassStats* currentPass() { return mStats.passes.empty() ? nullptr : &mStats.passes.back(); }

    static uint64_t texelCount(const GpuTexture& texture) {
        return static_cast<uint64_t>(texture.width()) * static_cast<uint64_t>(texture.height());
    }

    // The plan's record of the command about to run, or null once the frame left the plan (never
    // expected: the dry run follows the same script over the same values).
    const PlannedOp* nextOp(PlannedOp::Kind kind, size_t pass) {
        if (!mPlanFollowed) return nullptr;
        if (mNextOp >= mPlan.ops.size() || mPlan.ops[mNextOp].kind != kind ||
            mPlan.ops[mNextOp].pass != pass) {
            mPlanFollowed = false;
            return nullptr;
        }
        ++mPassOps;
        return &mPlan.ops[mNextOp++];
    }

    // Counts a command the plan leaves out; true if it is left out.
    bool leftOut(const PlannedOp* op) {
        if (!op || op->leftOut == LeftOut::No) return false;
        ++mPassLeftOut[static_cast<size_t>(op->leftOut)];
        return true;
    }

    void closePass() {
        PassStats* record = currentPass();
        int leftOut = 0;
        for (int count : mPassLeftOut) leftOut += count;
        if (!record || mPassOps == 0 || leftOut < mPassOps) return;
        static constexpr const char* kReasons[] = {"", "dead", "cached", "scene"};
        for (size_t reason = 1; reason < mPassLeftOut.size(); ++reason)
            if (mPassLeftOut[reason] > 0)
                record->leftOut += (record->leftOut.empty() ? "" : "+") + std::string(kReasons[reason]);
    }

    bool projectsWithPort(const PassUse& use) const {
        if (use.readsPortMatrix) return true;
        return mPortLight && std::find(use.lightMatrices.begin(), use.lightMatrices.end(), mPortLight) !=
                                 use.lightMatrices.end();
    }

    // Objects whose draws can change this pass's targets: inside the camera's frustum, or casters whose
    // extrusion away from the light meets the camera's receivers (IntersectionBody.h).
    void cull(const PlannedOp* op, std::vector<uint32_t>& visible) const {
        const InstanceBvh& bvh = mImpl.sceneCache.bvh;
        const glm::mat4 viewProjection = mPort.projection * mPort.view;
        if (!mLightPort) {
            const ConvexVolume frustum = frustumPlanes(viewProjection);
            bvh.query([&](const Aabb& box) { return overlapVolume(frustum, box); }, visible);
            return;
        }
        const ReceiverRegion region = op && op->cullToReceivers ? op->region : fullLightRegion();
        bvh.query([&](const Aabb& box) { return casterReaches(region, viewProjection, box); }, visible);
    }

    const GpuTexture* target(const std::string& name) {
        auto index = mImpl.parameterIndex.find(name);
        auto texture =
            index == mImpl.parameterIndex.end() ? mImpl.textures.end() : mImpl.textures.find(index->second);
        if (texture == mImpl.textures.end()) {
            // Left unallocated because no operation that runs uses it (FramePlan): not an error.
            const fx::TextureDesc* desc =
                index == mImpl.parameterIndex.end() ? nullptr : mImpl.compiled->findTexture(index->second);
            if (!desc || !isRenderTarget(*desc)) fail(fx::DiagId::ScriptUnknownTarget, {name});
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
    // layers with back-face culling (Weiskopf & Ertl 2003, §4: "back face culling for solid objects can be mixed with
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

    // Evaluates the pass's compile arguments into mArguments: with leave-out, the per-pass ones once per
    // pass (perObject false) and the per-object ones per draw (perObject true); without, all per draw.
    void evaluateArguments(const fx::CompiledPass& pass, const PassUse& use, bool perObject) {
        PassTimer::Scope preshaderTime(mTimer, &FrameCpuTime::preshaderNs);
        const auto lookup = [this](std::string_view name) { return mImpl.find(name); };
        mArguments.resize(pass.arguments.size());
        for (size_t i = 0; i < pass.arguments.size(); ++i) {
            if (mOptions.leaveOut && use.argumentPerObject[i] != perObject) continue;
            const fx::CompileArgument& argument = pass.arguments[i];
            std::optional<fx::Value> value =
                fx::evaluate(argument.expr, lookup, &argument.type, &mDiagnostics);
            mArguments[i] = value ? std::move(*value) : fx::zeroValue(argument.type);
        }
    }

    void drawWith(const fx::CompiledPass& pass, GpuProgram& program, const PassUse& use,
                  const SceneObject* object, GpuMesh& mesh) {
        {
            PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
            if (mOptions.leaveOut) {
                mBinder.bind(mPort, object, mOptions.time, mImpl.values, mImpl.pinned,
                             SemanticBinder::Scope::PerObject, &use.used);
            } else {
                mBinder.bind(mPort, object, mOptions.time, mImpl.values, mImpl.pinned);
            }
        }
        evaluateArguments(pass, use, true);
        {
            PassTimer::Scope bindingTime(mTimer, &FrameCpuTime::bindingNs);
            program.upload(mImpl.values, mArguments, *mImpl.uniformRing);
        }
        {
            PassTimer::Scope glTime(mTimer, &FrameCpuTime::glNs);
            const bool drawUnculled = mCullClosedOnly && object && !(object->mesh && object->mesh->closed);
            if (drawUnculled) gl::Disable(GL_CULL_FACE);
            mesh.draw(pass.vertex.inputs);
            if (drawUnculled) gl::Enable(GL_CULL_FACE);
        }
        const uint64_t triangles = mesh.indexCount() / 3;
        ++mStats.draws;
        mTimer.countDraw();
        mStats.triangles += triangles;
        if (PassStats* record = currentPass()) {
            ++record->draws;
            record->triangles += triangles;
        }
    }

    EffectRenderer::Impl& mImpl;
    const Scene& mScene;
    const FrameOptions& mOptions;
    fx::DiagnosticSink& mDiagnostics;
    FrameStats& mStats;
    PassTimer mTimer{mOptions.timePasses, mStats};
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
    std::vector<uint32_t> mVisible;
    std::vector<fx::Value> mArguments;
    RenderTargets mTargets;
    RenderPortView mPort;
    bool mLightPort = false;
    const Light* mPortLight = nullptr;
    std::array<float, 4> mClearColor{0.0f, 0.0f, 0.0f, 0.0f};  // D3D's Clear defaults
    float mClearDepth = 1.0f;
    int mClearStencil = 0;
    bool mFailed = false;
    bool mCullClosedOnly = false;  // this pass culls closed objects only (cullsClosedObjectsOnly)
    std::set<size_t> mWarnedPasses;
};

}  // namespace

std::optional<LightFit> EffectRenderer::lightFit(const Scene& scene, std::string_view lightName,
                                                 const FrameOptions& options) const {
    const Light* light = scene.findLight(lightName);
    if (!light) return std::nullopt;
    fx::DiagnosticList diagnostics;  // render() reports the annotations' mistakes
    const SemanticBinder binder(mImpl->effect(), scene, scene.bounds(),
                                static_cast<float>(options.width) / static_cast<float>(options.height),
                                mImpl->values, diagnostics);
    return binder.lightFit(*light);
}

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
        void setRenderPort(const std::string&, int, const fx::SourceLoc&) override {}
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
    // Camera-relative rendering for scenes far from the origin (Scene.h, renderOrigin). Such a scene is
    // translated anew each frame and its cache rebuilt: a price only scenes far from the origin pay.
    mImpl->updateSceneCache(scene);
    const glm::vec3 origin = renderOrigin(mImpl->sceneCache.bounds);
    const std::optional<Scene> rebased =
        origin == glm::vec3(0.0f) ? std::nullopt : std::optional<Scene>(scene.translated(-origin));
    const Scene& frameScene = rebased ? *rebased : scene;
    // Render targets are allocated once an operation that runs needs them (below); the frame's own now.
    std::set<int> none;
    mImpl->ensureFrameResources(options.width, options.height, &none);
    mImpl->updateSceneCache(frameScene);
    const SemanticBinder binder(mImpl->effect(), frameScene, mImpl->sceneCache.bounds,
                                static_cast<float>(options.width) / static_cast<float>(options.height),
                                mImpl->values, diagnostics);
    const std::vector<PassUse> uses = passUses(*mImpl, *technique, binder);

    // Plan the frame with a dry run of its script, then leave out what it shows nobody needs.
    FramePlan plan;
    {
        std::vector<glm::vec3> body;
        if (options.leaveOut && !mImpl->sceneCache.bvh.empty()) {
            RenderPortView camera;
            portMatrices(frameScene, binder, options, "", -1, camera);
            const Aabb& objects = mImpl->sceneCache.bvh.rootBox();
            body = intersectionBodyPoints(camera.projection * camera.view, Bounds{objects.min, objects.max});
        }
        fx::DiagnosticList dryRunDiagnostics;  // the real run reports them
        PlanRecorder recorder(*mImpl, frameScene, options, binder, uses, techniqueIndex, body, plan);
        ScriptInterpreter::run(*technique, recorder, dryRunDiagnostics);
        std::vector<int> outputs;
        for (const std::string& name : options.outputTargets)
            if (const std::optional<size_t> index = findParameter(name))
                outputs.push_back(static_cast<int>(*index));
        plan.markDead(outputs, options.leaveOut);
        // A render target no remaining operation writes or reads is not allocated.
        std::set<int> needed;
        for (const PlannedOp& op : plan.ops) {
            if (op.leftOut != LeftOut::No && options.leaveOut) continue;
            needed.insert(op.writes.begin(), op.writes.end());
            needed.insert(op.reads.begin(), op.reads.end());
        }
        mImpl->ensureFrameResources(options.width, options.height, options.leaveOut ? &needed : nullptr);
        plan.decide(
            mImpl->targetHistory, [this](int resource) { return mImpl->targetIdentity(resource); },
            options.leaveOut);
    }

    FrameExecutor executor(*mImpl, frameScene, options, diagnostics, frameStats, techniqueIndex, binder, uses,
                           plan);
    const bool ran = ScriptInterpreter::run(*technique, executor, diagnostics);
    executor.finish();
    FramebufferCache::bindDefault();
    const bool clean = checkGlErrors("EffectRenderer::render", __FILE__, __LINE__);
    setDebugSink({});
    if (!clean)
        diagnostics.report(fx::DiagId::GlError, fx::SourceLoc{mImpl->effect().path, 0, 0},
                           {"GL error during the frame"});
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
    if (!mImpl->frameColor) return frame;
    const Image image = readColorTarget(mImpl->frameColor).toRGBA8();
    frame.width = image.width;
    frame.height = image.height;
    frame.rgba = image.bytes;
    return frame;
}

bool EffectRenderer::blitFrameTo(uint32_t framebuffer) const {
    if (!mImpl->frameColor) return false;
    RenderTargets source;
    source.colors[0].texture = &mImpl->frameColor;
    std::string error;
    if (!mImpl->framebuffers.bind(source, error)) return false;
    const int width = mImpl->frameColor.width(), height = mImpl->frameColor.height();
    gl::BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    gl::BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    return gl::GetError() == GL_NO_ERROR;
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
