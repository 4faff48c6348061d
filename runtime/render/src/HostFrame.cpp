// HostFrame: see HostFrame.h. Feature list:
//   [SECTION] Values   — what a host file's parameter is, for a step's render port and an object
//   [SECTION] Targets  — the render targets the application created, given to their texture parameters
//   [SECTION] Resolution — the file's names as indices and handles, once
//   [SECTION] Steps    — techniques and passes applied through the pass API, the draws between them
//   [SECTION] Frame    — one frame, or the shadow factor for scoring
#include "HostFrame.h"

#include "EffectResources.h"

#include <runtime/Framebuffer.h>
#include <runtime/GlDebug.h>
#include <runtime/Image.h>
#include <private/runtime/NameLookups.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <span>
#include <tuple>

namespace runtime {

using fx::HostLightProjection;
using fx::HostMatrix;
using fx::HostParameter;
using fx::HostStep;
using fx::HostTarget;
using fx::HostValue;

namespace {

// [SECTION] Values

using PortMatrices = HostFrame::PortMatrices;

struct StepContext {
    const Scene& scene;
    PortMatrices camera;
    PortMatrices port;
    // Per light the file names (HostFrame's list): its matrices, fitted before the first step, and the
    // scene's light of that name.
    const std::vector<PortMatrices>& lights;
    const std::vector<const Light*>& sceneLights;
    glm::ivec2 viewport{0};
};

// glm holds D3DX's row-vector matrices in the same memory (docs/api.md), so D3D's World * View is glm's
// view * world.
glm::mat4 factorMatrix(const HostMatrix& factor, int light, const StepContext& step,
                       const SceneObject* object) {
    const PortMatrices& space = factor.space == HostMatrix::Space::Camera ? step.camera
                                : factor.space == HostMatrix::Space::Light
                                    ? step.lights[static_cast<size_t>(light)]
                                    : step.port;
    const glm::mat4 world = object ? object->world : glm::mat4(1.0f);
    glm::mat4 m{1.0f};
    switch (factor.kind) {
        case HostMatrix::Kind::World:
            m = world;
            break;
        case HostMatrix::Kind::View:
            m = space.view;
            break;
        case HostMatrix::Kind::Projection:
            m = space.projection;
            break;
        case HostMatrix::Kind::WorldView:
            m = space.view * world;
            break;
        case HostMatrix::Kind::ViewProjection:
            m = space.projection * space.view;
            break;
        case HostMatrix::Kind::WorldViewProjection:
            m = space.projection * space.view * world;
            break;
    }
    if (factor.inverse) m = glm::inverse(m);
    if (factor.transpose) m = glm::transpose(m);
    return m;
}

// The value's components: a matrix as its 16 elements row after row (HLSL's order), vectors as they are;
// computed into `out` (a constant's are its own numbers).
std::span<const float> components(const HostFrame::Value& resolved, const StepContext& step,
                                  const SceneObject* object, std::array<float, 16>& out) {
    const HostValue& value = resolved.parameter->value;
    const auto light = [&]() -> const Light& {
        return *step.sceneLights[static_cast<size_t>(resolved.light)];
    };
    const auto numbers = [&](std::initializer_list<float> list) {
        std::copy(list.begin(), list.end(), out.begin());
        return std::span<const float>(out.data(), list.size());
    };
    switch (value.kind) {
        case HostValue::Kind::Constant:
            return value.numbers;
        case HostValue::Kind::Matrix: {
            // D3D's A * B * C, applied to a row vector left to right, is glm's C * B * A.
            glm::mat4 product{1.0f};
            for (size_t f = 0; f < value.factors.size(); ++f)
                product = factorMatrix(value.factors[f], resolved.factorLights[f], step, object) * product;
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) out[static_cast<size_t>(r * 4 + c)] = product[r][c];
            return out;
        }
        case HostValue::Kind::LightPosition: {
            const glm::vec4 p = (value.cameraViewSpace ? step.camera.view : glm::mat4(1.0f)) *
                                glm::vec4(light().position, 1.0f);
            return numbers({p.x, p.y, p.z, 1.0f});
        }
        case HostValue::Kind::LightDirection: {
            glm::vec3 d = light().direction;
            if (value.cameraViewSpace) d = glm::normalize(glm::mat3(step.camera.view) * d);
            return numbers({d.x, d.y, d.z, 0.0f});
        }
        case HostValue::Kind::LightColor: {
            const glm::vec3 c = light().color;
            return numbers({c.x, c.y, c.z, 1.0f});
        }
        case HostValue::Kind::LightCosHalfAngle:
            return numbers({std::cos(light().spotAngle * 0.5f)});
        case HostValue::Kind::ObjectColor: {
            const glm::vec3 c = object ? object->color : glm::vec3(1.0f);
            return numbers({c.x, c.y, c.z, 1.0f});
        }
        case HostValue::Kind::ViewportSize:
            return numbers({static_cast<float>(step.viewport.x), static_cast<float>(step.viewport.y)});
    }
    return {};
}

// Sets `numbers` as the value's variable's value: a matrix's upper-left rows x columns (as D3DX's SetMatrix
// fills a float3x3), a vector's first components (a position's w dropped for a float3), a scalar
// broadcast. Built in the value's own `staged`, so that a frame allocates nothing.
bool setComponents(HostFrame::Value& resolved, std::span<const float> numbers) {
    const HostValue& value = resolved.parameter->value;
    fx::Value& v = resolved.staged;
    const fx::TypeDesc& type = v.type;
    std::fill(v.data.begin(), v.data.end(), 0.0f);
    if (value.kind == HostValue::Kind::Matrix) {
        for (int r = 0; r < type.rows; ++r)
            for (int c = 0; c < type.cols; ++c)
                v.data[static_cast<size_t>(r * type.cols + c)] = numbers[r * 4 + c];
    } else if (numbers.size() == 1) {
        std::fill(v.data.begin(), v.data.end(), numbers[0]);
    } else {
        for (size_t i = 0; i < v.data.size() && i < numbers.size(); ++i) v.data[i] = numbers[i];
    }
    return resolved.variable.setValue(v);
}

// The step's group counts, each term a count or a parameter's components (a script's Dispatch=x,y,z);
// nothing where they are more than three or a parameter holds a negative count. `parameters`: each term's
// parameter, invalid for a count.
std::optional<std::array<uint32_t, 3>> dispatchGroups(const HostStep& step,
                                                      const std::vector<EffectVariable>& parameters) {
    std::array<uint32_t, 3> groups{1, 1, 1};
    size_t given = 0;
    for (size_t t = 0; t < step.dispatch.size(); ++t) {
        if (!parameters[t].isValid()) {
            if (given == 3) return std::nullopt;
            groups[given++] = step.dispatch[t].count;
            continue;
        }
        for (float count : parameters[t].components()) {
            if (given == 3 || !(count >= 0.0f)) return std::nullopt;
            groups[given++] = static_cast<uint32_t>(count);
        }
    }
    return groups;
}

}  // namespace

// [SECTION] Targets

namespace {

// The colour texture of a target, and its depth buffer: as many layers (a 2D array's) for a target bound
// whole, so that both attach layered to one framebuffer.
std::pair<GpuTexture, GpuTexture> makeTarget(const HostTarget& target, glm::ivec2 size) {
    constexpr fx::TextureFormat kDepth = fx::TextureFormat::D24S8;
    switch (target.kind) {
        case HostTarget::Kind::Cube:
            return {GpuTexture::createCube(target.format, size.x),
                    GpuTexture::create2DArray(kDepth, size.x, size.x, 6)};
        case HostTarget::Kind::Array:
            return {GpuTexture::create2DArray(target.format, size.x, size.y, target.layers),
                    GpuTexture::create2DArray(kDepth, size.x, size.y, target.layers)};
        case HostTarget::Kind::Volume:
            return {GpuTexture::create3D(target.format, size.x, size.y, target.layers),
                    GpuTexture::create2DArray(kDepth, size.x, size.y, target.layers)};
        case HostTarget::Kind::Plane:
            break;
    }
    return {GpuTexture::create2D(target.format, size.x, size.y),
            GpuTexture::create2D(kDepth, size.x, size.y)};
}

}  // namespace

void HostFrame::ensureTargets(int width, int height) {
    for (size_t i = 0; i < mTargets.size(); ++i) {
        const HostTarget& target = mHost->targets[i];
        Target& t = mTargets[i];
        glm::ivec2 size =
            target.width > 0 ? glm::ivec2(target.width, target.height) : glm::ivec2(width, height);
        if (target.kind == HostTarget::Kind::Cube) size.y = size.x = target.width > 0 ? target.width : height;
        if (t.color.id() == 0 || t.color.width() != size.x || t.color.height() != size.y) {
            std::tie(t.color, t.depth) = makeTarget(target, size);
            t.color.setLabel("host target " + target.name);
        }
        // As the application's SetTexture: the effect samples the target wherever it samples the parameter.
        if (t.texture.isValid()) t.texture.setTexture(t.color.id());
    }
}

// [SECTION] Resolution

HostFrame::HostFrame(std::shared_ptr<const fx::HostFile> host, EffectRenderer& renderer)
    : mHost(std::move(host)), mTargets(mHost->targets.size()), mOverridden(renderer.variableCount(), false) {
    for (size_t i = 0; i < mTargets.size(); ++i)
        if (!mHost->targets[i].texture.empty())
            mTargets[i].texture = renderer.variable(mHost->targets[i].texture);
    for (const HostParameter& parameter : mHost->parameters)
        mParameters.push_back(resolve(parameter, renderer));
    if (mHost->visibility)
        for (const HostParameter& parameter : mHost->visibility->set)
            mVisibilitySet.push_back(resolve(parameter, renderer));
    countNameLookup();  // the effect's definitions searched for SHADOWFX_VISIBILITY, here and never per frame
    const auto& defines = renderer.effect().provenance.defines;
    mScored = mHost->visibility && std::any_of(defines.begin(), defines.end(), [](const auto& define) {
                  return define.first == "SHADOWFX_VISIBILITY";
              });
    for (const HostStep& step : mHost->frame) {
        Step resolved;
        resolved.technique = renderer.technique(step.technique);
        for (size_t p = 0; p < resolved.technique.passCount(); ++p)
            if (step.pass.empty() || resolved.technique.pass(p).name() == step.pass)
                resolved.passes.push_back(p);
        for (size_t t = 0; t < mHost->targets.size() && step.target != "frame"; ++t)
            if (mHost->targets[t].name == step.target) resolved.target = static_cast<int>(t);
        if (mHost->visibility)
            for (const std::string& unshadowed : mHost->visibility->unshadowed)
                resolved.unshadowed = resolved.unshadowed || unshadowed == step.target;
        if (step.port != "camera") resolved.port = lightIndex(step.port);
        for (const HostStep::DispatchTerm& term : step.dispatch)
            resolved.dispatch.push_back(term.parameter.empty() ? EffectVariable{}
                                                               : renderer.variable(term.parameter));
        mSteps.push_back(std::move(resolved));
    }
    mLightProjections.assign(mLightNames.size(), nullptr);
    for (const HostLightProjection& projection : mHost->lights)
        for (size_t light = 0; light < mLightNames.size(); ++light)
            if (mLightNames[light] == projection.light) mLightProjections[light] = &projection;
}

int HostFrame::lightIndex(const std::string& name) {
    const auto known = std::find(mLightNames.begin(), mLightNames.end(), name);
    if (known != mLightNames.end()) return static_cast<int>(known - mLightNames.begin());
    mLightNames.push_back(name);
    return static_cast<int>(mLightNames.size() - 1);
}

HostFrame::Value HostFrame::resolve(const HostParameter& parameter, EffectRenderer& renderer) {
    Value value;
    value.parameter = &parameter;
    value.variable = renderer.variable(parameter.name);
    value.staged = fx::zeroValue(value.variable.type());
    if (!parameter.value.light.empty()) value.light = lightIndex(parameter.value.light);
    for (const HostMatrix& factor : parameter.value.factors)
        value.factorLights.push_back(factor.space == HostMatrix::Space::Light ? lightIndex(factor.light)
                                                                              : -1);
    return value;
}

// Scene::findLight's answer depends on the names of the scene's lights and nothing else.
void HostFrame::resolveSceneLights(const Scene& scene) {
    bool same = mSceneLightsResolved && mSceneLightNames.size() == scene.lights.size();
    for (size_t i = 0; same && i < scene.lights.size(); ++i)
        same = mSceneLightNames[i] == scene.lights[i].name;
    if (same) return;
    mSceneLightNames.clear();
    for (const Light& light : scene.lights) mSceneLightNames.push_back(light.name);
    mSceneLights.assign(mLightNames.size(), -1);
    for (size_t light = 0; light < mLightNames.size(); ++light)
        if (const Light* found = scene.findLight(mLightNames[light]))
            mSceneLights[light] = static_cast<int>(found - scene.lights.data());
    mSceneLightsResolved = true;
}

// [SECTION] Steps

bool HostFrame::drawSteps(EffectResources& r, const Scene& scene, const FrameOptions& options,
                          bool leaveUnshadowed, fx::DiagnosticSink& diagnostics) {
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    resolveSceneLights(scene);
    std::vector<const Light*>& sceneLights = mSceneLightsDrawn;
    sceneLights.assign(mLightNames.size(), nullptr);
    for (size_t light = 0; light < mLightNames.size(); ++light)
        if (mSceneLights[light] >= 0)
            sceneLights[light] = &scene.lights[static_cast<size_t>(mSceneLights[light])];
    std::vector<PortMatrices>& lights = mLightMatrices;
    lights.assign(mLightNames.size(), PortMatrices{});
    std::vector<bool>& fitted = mLightsFitted;
    fitted.assign(mLightNames.size(), false);
    std::array<float, 16> computed{};        // a value's components as components() computes them
    const SemanticBinder* binder = nullptr;  // the effect's light fits, prepared when a light is first needed
    const auto lightMatrices = [&](int light, const fx::SourceLoc& loc) -> bool {
        const auto l = static_cast<size_t>(light);
        if (fitted[l]) return true;
        if (!sceneLights[l]) {
            diagnostics.report(fx::DiagId::HostLightNotInScene, loc, {mLightNames[l]});
            return false;
        }
        if (!binder) binder = &r.fitLights(scene, options.width, options.height);
        const LightFit fit = binder->lightFit(*sceneLights[l]);
        lights[l] = PortMatrices{fit.view, fit.projection};
        if (const HostLightProjection* projection = mLightProjections[l])
            lights[l].projection = glm::perspectiveLH_ZO(glm::radians(projection->fovY), 1.0f,
                                                         projection->nearPlane, projection->farPlane);
        fitted[l] = true;
        return true;
    };
    // Every light a value names, before the first step needs it.
    for (const Value& value : mParameters) {
        bool ok = value.light < 0 || lightMatrices(value.light, value.parameter->loc);
        for (int light : value.factorLights)
            if (light >= 0) ok = lightMatrices(light, value.parameter->loc) && ok;
        if (!ok) return false;
    }

    const PortMatrices camera{scene.camera.view(), scene.camera.projection(aspect)};
    for (size_t s = 0; s < mSteps.size(); ++s) {
        const HostStep& step = mHost->frame[s];
        const Step& resolved = mSteps[s];
        if (resolved.port >= 0 && !lightMatrices(resolved.port, step.loc)) return false;
        StepContext context{scene, camera,
                            resolved.port < 0 ? camera : lights[static_cast<size_t>(resolved.port)], lights,
                            sceneLights};

        // The step's target, as the application binds it before Begin().
        RenderTargets targets;
        Target* target = resolved.target < 0 ? nullptr : &mTargets[static_cast<size_t>(resolved.target)];
        if (!target) {
            targets.colors[0].texture = &r.textures->frameColor();
            targets.depth.texture = &r.textures->frameDepth();
        } else {
            targets.colors[0] = RenderTargetAttachment::wholeOf(&target->color);
            targets.depth = RenderTargetAttachment::wholeOf(&target->depth);
        }
        FramebufferFault fault;
        if (!r.textures->bindFramebuffer(targets, fault)) {
            const auto [id, arguments] = fault.diagnostic(fx::DiagId::HostTargetUnbindable, {step.target});
            diagnostics.report(id, step.loc, arguments);
            return false;
        }
        context.viewport = {targets.width(), targets.height()};
        gl::Viewport(0, 0, targets.width(), targets.height());
        setViewports(step.viewports);
        ClearRequest clear;
        if (step.clearColor) clear.color = *step.clearColor;
        clear.depth = step.clearDepth;
        if (clear.color || clear.depth) FramebufferCache::clear(clear);
        if (step.draw == HostStep::Draw::Nothing || (leaveUnshadowed && resolved.unshadowed)) continue;

        const EffectTechnique& technique = resolved.technique;
        if (!technique.begin()) return false;
        bool ok = true;
        for (size_t p : resolved.passes) {
            EffectPass pass = technique.pass(p);
            // Values of the step before apply() uploads them; values of each object before its draw.
            for (Value& value : mParameters)
                if (value.parameter->value.kind != HostValue::Kind::Constant &&
                    !value.parameter->value.perObject() && !mOverridden[value.variable.index()])
                    setComponents(value, components(value, context, nullptr, computed));
            if (!pass.apply(&diagnostics)) {
                ok = false;
                break;
            }
            const fx::CompiledPass& compiled = r.effect().techniques[pass.techniqueIndex()].passes[p];
            if (!step.dispatch.empty() && !compiled.compute.glsl.empty()) {
                const std::optional<std::array<uint32_t, 3>> groups = dispatchGroups(step, resolved.dispatch);
                if (!groups) {
                    diagnostics.report(fx::DiagId::HostStepDispatchInvalid, step.loc,
                                       {"frame/" + std::to_string(s) + "/dispatch"});
                    ok = false;
                    break;
                }
                if (!pass.dispatch((*groups)[0], (*groups)[1], (*groups)[2], &diagnostics)) {
                    ok = false;
                    break;
                }
            }
            if (compiled.vertex.glsl.empty()) continue;  // a pass that only sets states, or computes
            if (step.draw == HostStep::Draw::Quad) {
                r.quad.draw(compiled.vertex.inputs, 1, compiled.patchVertices, compiled.primitive);
                continue;
            }
            for (const SceneObject& object : scene.objects) {
                for (Value& value : mParameters)
                    if (value.parameter->value.perObject() && !mOverridden[value.variable.index()])
                        setComponents(value, components(value, context, &object, computed));
                pass.commitChanges(&diagnostics);
                r.gpuMesh(object.mesh)
                    .draw(compiled.vertex.inputs, 1, compiled.patchVertices, compiled.primitive);
            }
        }
        technique.end();
        if (!ok) return false;
    }
    return true;
}

// [SECTION] Frame

bool HostFrame::render(EffectResources& r, const Scene& scene, const FrameOptions& options,
                       fx::DiagnosticSink& diagnostics) {
    const std::vector<bool> none;  // no render target allocated here: ensureTargets does
    r.textures->ensureFrame(options.width, options.height, &none);
    ensureTargets(options.width, options.height);
    for (Value& value : mParameters)
        if (value.parameter->value.kind == HostValue::Kind::Constant)
            setComponents(value, value.parameter->value.numbers);

    std::fill(mOverridden.begin(), mOverridden.end(), false);
    bool ok = true;
    if (!mScored) {
        ok = drawSteps(r, scene, options, false, diagnostics);
    } else {
        // The shadow factor of an effect with no hook of its own: the frame with the visibility constants
        // (no ambient, a white material) divided by the same frame with the shadow maps left cleared,
        // which lights everything. What remains is the fraction of the light the shadow test let through.
        for (Value& value : mVisibilitySet) {
            setComponents(value, value.parameter->value.numbers);
            mOverridden[value.variable.index()] = true;
        }
        ok = drawSteps(r, scene, options, false, diagnostics);
        const Image shadowed = readColorTarget(r.textures->frameColor()).toRGBA8();
        ok = ok && drawSteps(r, scene, options, true, diagnostics);
        const Image lit = readColorTarget(r.textures->frameColor()).toRGBA8();
        std::vector<uint8_t> ratio(shadowed.bytes.size());
        for (size_t i = 0; i + 3 < ratio.size(); i += 4) {
            // Where the light does not reach at all (outside a spot's cone, facing away) nothing is lit.
            const float v =
                lit.bytes[i] > 0
                    ? std::min(1.0f, static_cast<float>(shadowed.bytes[i]) / static_cast<float>(lit.bytes[i]))
                    : 0.0f;
            const auto byte = static_cast<uint8_t>(v * 255.0f + 0.5f);
            ratio[i] = ratio[i + 1] = ratio[i + 2] = byte;
            ratio[i + 3] = 255;
        }
        r.textures->uploadFrameColor(ratio.data());
    }
    if (options.timePasses) gl::Finish();
    FramebufferCache::bindDefault();
    return ok;
}

}  // namespace runtime
