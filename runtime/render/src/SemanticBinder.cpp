#include "SemanticBinder.h"

#include <fx/RenderStates.h>
#include <runtime/CascadedShadowMaps.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <span>
#include <cstring>
#include <cmath>
#include <optional>

namespace runtime {

namespace {

// Copies a rows x cols block of `source` (HLSL row order) into `value`, converting to its shape: a
// float3x3 parameter receives the upper-left 3x3 of a 4x4 matrix, a float3 the first three components.
void store(fx::Value& value, const float* source, int rows, int cols) {
    const fx::TypeDesc& type = value.type;
    // A matrix of the source's shape (the 4x4s bound for every drawn object) is the source as it is.
    if (type.shape == fx::Shape::Matrix && type.rows == rows && type.cols == cols) {
        value.data.assign(source, source + rows * cols);
        return;
    }
    if (type.shape == fx::Shape::Matrix) {
        value.data.assign(static_cast<size_t>(type.rows * type.cols), 0.0f);
        for (int r = 0; r < type.rows; ++r)
            for (int c = 0; c < type.cols; ++c)
                if (r < rows && c < cols)
                    value.data[static_cast<size_t>(r * type.cols + c)] = source[r * cols + c];
        return;
    }
    const int count = type.shape == fx::Shape::Vector ? type.cols : 1;
    value.data.assign(static_cast<size_t>(count), 0.0f);
    for (int i = 0; i < count && i < rows * cols; ++i) value.data[static_cast<size_t>(i)] = source[i];
    if (count == 4 && rows * cols == 3) value.data[3] = 1.0f;
}

void storeMatrix(fx::Value& value, const glm::mat4& m) {
    // A glm matrix's memory equals the D3DX (row-vector) matrix row by row: see fx/Value.h.
    store(value, glm::value_ptr(m), 4, 4);
}

void storeVector(fx::Value& value, const glm::vec4& v) {
    store(value, glm::value_ptr(v), 1, 4);
}

// Fills every element of an array parameter (or the one element of a plain one) from `elements`, each
// `rows` x `cols` floats in HLSL row order and converted to the parameter's element shape like store();
// elements past the source's end repeat its last one.
void storeElements(fx::Value& value, std::span<const float> elements, int rows, int cols) {
    fx::Value element;
    element.type = value.type;
    element.type.arrayDims.clear();
    const size_t perSource = static_cast<size_t>(rows * cols);
    const size_t sources = elements.size() / std::max<size_t>(perSource, 1);
    const int count = std::max(1, value.type.componentCount()) / std::max(1, element.type.componentCount());
    value.data.clear();
    for (int e = 0; e < count && sources > 0; ++e) {
        store(element, elements.data() + std::min(static_cast<size_t>(e), sources - 1) * perSource, rows,
              cols);
        value.data.insert(value.data.end(), element.data.begin(), element.data.end());
    }
}

}  // namespace

bool SemanticBinder::wantsVisibleSamples(const std::vector<fx::Value>& values) const {
    for (const FitInput& input : mFitInputs)
        if (input.tunable == Kind::LightFitVisibleSamples && input.parameter < values.size() &&
            !values[input.parameter].data.empty() && values[input.parameter].data[0] != 0.0f)
            return true;
    return false;
}

SemanticBinder::SemanticBinder(const std::vector<fx::ParameterInfo>& parameters,
                               const std::vector<std::string>& lights)
    : mParameters(parameters) {
    for (const std::string& light : lights) lightSlot(light);
    for (size_t i = 0; i < parameters.size(); ++i) {
        const fx::ParameterInfo& parameter = parameters[i];
        const fx::SemanticBinding& standard = parameter.standard;
        FitInput input;
        input.parameter = i;
        if (!fx::isBoundSemantic(standard.kind) && standard.kind != Kind::StandardsGlobal)
            input.tunable = standard.kind;
        if (parameter.hasParameterization && !parameter.light.empty()) {
            input.parameterizationSlot = lightSlot(parameter.light);
            input.method = parseLightParameterization(parameter.parameterization);
        }
        if (input.tunable != Kind::None || input.parameterizationSlot >= 0) mFitInputs.push_back(input);
        addBinding(i, standard, nullptr);
        for (const fx::MemberBinding& member : parameter.memberBindings)
            addBinding(i, member.standard, &member);
    }
    for (size_t b = 0; b < mBindings.size(); ++b) {
        if (mBindings[b].kind == Kind::ResetPulse) {
            mFrameBindings.push_back(b);
        } else {
            (dependsOnObject(mBindings[b].kind) ? mObjectBindings : mPortBindings).push_back(b);
        }
    }
}

void SemanticBinder::addBinding(size_t parameter, const fx::SemanticBinding& standard,
                                const fx::MemberBinding* member) {
    // The compiler binds numbers the runtime may change only; a light property without a light (a
    // plain Position or Direction) is the object's, which nothing supplies.
    if (!fx::isBoundSemantic(standard.kind)) return;
    const bool isLightProperty = standard.kind == Kind::LightPosition ||
                                 standard.kind == Kind::LightDirection || standard.kind == Kind::LightColor ||
                                 standard.kind == Kind::LightAreaRadius || standard.kind == Kind::LightRange;
    if (isLightProperty && standard.light < 0 && !standard.eachLight) return;
    Binding binding{parameter, standard.kind};
    binding.inverse = standard.inverse;
    binding.transpose = standard.transpose;
    binding.eachLight = standard.eachLight;
    binding.viewSpace = standard.viewSpace;
    binding.towardsLight = standard.towardsLight;
    if (standard.eachLight)  // a one-dimensional array (fx::SemanticBinding::eachLight)
        mLightCountLimit = std::min(mLightCountLimit, mParameters[parameter].type.arrayDims.front());
    // CompiledEffect::lights took the first slots in order: the compiler's index is the slot.
    binding.lightSlot = standard.light;
    binding.member = member;
    mBindings.push_back(binding);
}

int SemanticBinder::lightSlot(std::string_view lightName) {
    for (size_t slot = 0; slot < mSlotNames.size(); ++slot)
        if (mSlotNames[slot] == lightName) return static_cast<int>(slot);
    mSlotNames.emplace_back(lightName);
    mSlotIndices.push_back(-1);
    mSlotLights.push_back(nullptr);
    mResolved = false;
    return static_cast<int>(mSlotNames.size() - 1);
}

const Light* SemanticBinder::slotLight(int slot) const {
    return slot >= 0 && static_cast<size_t>(slot) < mSlotLights.size()
               ? mSlotLights[static_cast<size_t>(slot)]
               : nullptr;
}

// Scene::findLight's answer depends on the names of all the scene's lights and nothing else: while they
// stay the same, so do the slots' lights.
void SemanticBinder::resolveLights(const Scene& scene) {
    bool same = mResolved && mResolvedLightNames.size() == scene.lights.size();
    for (size_t i = 0; same && i < scene.lights.size(); ++i)
        same = mResolvedLightNames[i] == scene.lights[i].name;
    if (!same) {
        mResolvedLightNames.clear();
        for (const Light& light : scene.lights) mResolvedLightNames.push_back(light.name);
        for (size_t slot = 0; slot < mSlotNames.size(); ++slot) {
            const Light* light = scene.findLight(mSlotNames[slot]);
            mSlotIndices[slot] = light ? static_cast<int>(light - scene.lights.data()) : -1;
        }
        mResolved = true;
    }
    for (size_t slot = 0; slot < mSlotNames.size(); ++slot)
        mSlotLights[slot] =
            mSlotIndices[slot] >= 0 ? &scene.lights[static_cast<size_t>(mSlotIndices[slot])] : nullptr;
}

void SemanticBinder::prepare(const Scene& scene, const Bounds& sceneBounds, float aspect,
                             const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                             fx::DiagnosticSink& diagnostics, const VisibleSamples* visible) {
    mScene = &scene;
    mSceneBounds = sceneBounds;
    mAspect = aspect;
    resolveLights(scene);
    mHasClosedObjects =
        std::any_of(scene.objects.begin(), scene.objects.end(),
                    [](const SceneObject& object) { return object.mesh && object.mesh->closed; });
    // The parameterization of each light (the `Parameterization` annotation of any parameter naming it) and
    // its tunables, before any light is fitted.
    mTunables = {};
    mFittedLights.clear();
    for (FitInput& input : mFitInputs) {
        const size_t i = input.parameter;
        const fx::ParameterInfo& parameter = mParameters[i];
        if (i < values.size() && !values[i].data.empty()) {
            const float value = values[i].data[0];
            switch (input.tunable) {
                case Kind::LispsmNScale:
                    mTunables.lispsmNScale = value;
                    break;
                case Kind::LispsmDepthExtent:
                    mTunables.lispsmDepthExtent = value;
                    break;
                case Kind::LispsmMiddleVector:
                    mTunables.lispsmMiddleVector = value != 0.0f;
                    break;
                case Kind::LightPancaking:
                    mTunables.pancaking = value != 0.0f;
                    break;
                case Kind::TsmFocus:
                    mTunables.tsmFocus = value;
                    break;
                case Kind::PsmSlideBack:
                    mTunables.psmSlideBack = value;
                    break;
                case Kind::PsmMaxWarpRatio:
                    mTunables.psmMaxWarpRatio = value;
                    break;
                case Kind::CascadeCount:
                    mTunables.cascadeCount = static_cast<int>(std::lround(value));
                    break;
                case Kind::CascadeSplitLambda:
                    mTunables.cascadeSplitLambda = value;
                    break;
                case Kind::CascadeBlend:
                    mTunables.cascadeBlend = value;
                    break;
                case Kind::LightFitVisibleSamples:
                    mTunables.fitToVisibleSamples = value != 0.0f;
                    break;
                default:
                    break;
            }
        }
        if (input.tunable == Kind::LispsmNOpt && i < values.size()) {
            const uint64_t stamp = i < stamps.stamps.size() ? stamps.stamps[i] : FitInput::kNeverRead;
            if (stamp == FitInput::kNeverRead || stamp != input.readAt) {
                input.lispsmN = parseLispsmN(values[i].string);
                input.readAt = stamp;
            }
            if (input.lispsmN) {
                mTunables.lispsmN = *input.lispsmN;
            } else {
                diagnostics.report(fx::DiagId::LispsmChoiceInvalid, parameter.loc,
                                   {values[i].string, parameter.name});
            }
        }
        if (input.parameterizationSlot < 0) continue;
        if (!input.method) {
            diagnostics.report(fx::DiagId::ParameterizationUnknown, parameter.parameterizationLoc, {});
            continue;
        }
        const Light* light = slotLight(input.parameterizationSlot);
        if (!light) continue;  // reported below with the parameter's binding
        auto known = std::find_if(mFittedLights.begin(), mFittedLights.end(),
                                  [light](const FittedLight& f) { return f.light == light; });
        if (known == mFittedLights.end()) {
            mFittedLights.push_back({light, *input.method, {}});
        } else if (known->method != *input.method) {
            diagnostics.report(fx::DiagId::ParameterizationConflict, parameter.parameterizationLoc,
                               {parameter.light, lightParameterizationName(known->method)});
        }
    }
    for (FittedLight& fitted : mFittedLights)
        fitted.fit = fitLight(fitted.method, scene, sceneBounds, aspect, *fitted.light, mTunables,
                              mTunables.fitToVisibleSamples ? visible : nullptr);
    for (Binding& binding : mBindings) {
        binding.light = slotLight(binding.lightSlot);
        binding.active = binding.lightSlot < 0 || binding.light;
        if (binding.lightSlot < 0) continue;
        if (!binding.light) {
            const fx::ParameterInfo& parameter = mParameters[binding.parameter];
            diagnostics.report(fx::DiagId::ParameterNamesMissingLight, parameter.loc,
                               {parameter.name, mSlotNames[static_cast<size_t>(binding.lightSlot)]});
            continue;
        }
        const LightFit& fit = fittedLight(*binding.light).fit;
        binding.lightView = fit.view;
        binding.lightProjection = fit.projection;
        binding.lightCascades = fit.cascades;
        binding.lightFaceSelect = fit.faceSelect;
    }
}

const SemanticBinder::FittedLight& SemanticBinder::fittedLight(const Light& light) {
    for (const FittedLight& fitted : mFittedLights)
        if (fitted.light == &light) return fitted;
    mFittedLights.push_back(
        {&light, LightParameterization::Uniform,
         fitLight(LightParameterization::Uniform, *mScene, mSceneBounds, mAspect, light)});
    return mFittedLights.back();
}

LightFit SemanticBinder::lightFit(const Light& light) const {
    for (const FittedLight& fitted : mFittedLights)
        if (fitted.light == &light) return fitted.fit;
    return fitLight(LightParameterization::Uniform, *mScene, mSceneBounds, mAspect, light);
}

// A light without cascades (not Cascaded) binds as one cascade: its own matrices, the whole atlas, the
// camera's far plane.
void SemanticBinder::storeCascades(const Binding& binding, fx::Value& value) const {
    std::vector<LightView> cascades = binding.lightCascades;
    if (cascades.empty())
        cascades.push_back(
            {binding.lightView, binding.lightProjection, mScene->camera.nearPlane, mScene->camera.farPlane});
    const int count = static_cast<int>(cascades.size());
    std::vector<float> elements;
    for (int k = 0; k < count; ++k) {
        const LightView& cascade = cascades[static_cast<size_t>(k)];
        if (binding.kind == Kind::CascadeViewProjection) {
            const glm::mat4 viewProjection = cascade.projection * cascade.view;
            elements.insert(elements.end(), glm::value_ptr(viewProjection),
                            glm::value_ptr(viewProjection) + 16);
        } else if (binding.kind == Kind::CascadeAtlasRects) {
            const glm::vec4 rect = binding.lightCascades.empty() ? glm::vec4(0.0f, 0.0f, 1.0f, 1.0f)
                                   : cascade.atlasRect.z > 0.0f  ? cascade.atlasRect
                                                                 : cascadeAtlasRect(k, count);
            elements.insert(elements.end(), glm::value_ptr(rect), glm::value_ptr(rect) + 4);
        } else {
            elements.push_back(cascade.splitFar);
        }
    }
    if (binding.kind == Kind::CascadeViewProjection) {
        storeElements(value, elements, 4, 4);
    } else if (binding.kind == Kind::CascadeAtlasRects) {
        storeElements(value, elements, 1, 4);
    } else {
        // Split depths fill the parameter component by component (a float4 holds four cascades' ends).
        const size_t components = static_cast<size_t>(std::max(1, value.type.componentCount()));
        value.data.assign(components, elements.back());
        std::copy_n(elements.begin(), std::min(components, elements.size()), value.data.begin());
    }
}

// Element k is the property of the scene's light k (in world space, or the port's view space where the
// binding says so). A position is the light's as the scene gives it, also a directional light's (the
// single LightPosition binding gives the eye of the light's fitted view instead: it is bound with the
// light's matrices). Elements past the scene's last light are zero, so a loop over them adds no light.
void SemanticBinder::storeEachLight(const Binding& binding, const RenderPortView& port,
                                    fx::Value& value) const {
    const int count = value.type.arrayDims.empty() ? 1 : value.type.arrayDims.front();
    std::vector<float> elements(static_cast<size_t>(count) * 4, 0.0f);
    for (int k = 0; k < count && static_cast<size_t>(k) < mScene->lights.size(); ++k) {
        const Light& light = mScene->lights[static_cast<size_t>(k)];
        glm::vec4 element(0.0f);
        switch (binding.kind) {
            case Kind::LightPosition:
                element = glm::vec4(light.position, 1.0f);
                break;
            case Kind::LightDirection:
                element = glm::vec4(binding.towardsLight ? -light.direction : light.direction, 0.0f);
                break;
            case Kind::LightColor:
                element = glm::vec4(light.color, 1.0f);
                break;
            case Kind::LightAreaRadius:
                element = glm::vec4(light.areaRadius);
                break;
            case Kind::LightRange:
                element = glm::vec4(lightRange(light.position));
                break;
            default:
                break;
        }
        if (binding.viewSpace) element = port.view * element;
        std::copy_n(&element[0], 4, elements.begin() + k * 4);
    }
    storeElements(value, elements, 1, 4);
}

// A directional light's position is the eye of its fitted view: bound with the light's matrices.
glm::vec3 SemanticBinder::lightPosition(const Binding& binding) const {
    const Light& light = *binding.light;
    return light.type == Light::Type::Directional ? glm::vec3(glm::inverse(binding.lightView)[3])
                                                  : light.position;
}

// From `position` past the farthest point of the scene's bounding sphere: a point light that far reaches
// every object.
float SemanticBinder::lightRange(const glm::vec3& position) const {
    return glm::length(position - mSceneBounds.center()) + mSceneBounds.radius();
}

bool SemanticBinder::isBound(size_t parameter) const {
    return std::any_of(mBindings.begin(), mBindings.end(),
                       [parameter](const Binding& b) { return b.active && b.parameter == parameter; });
}

bool SemanticBinder::dependsOnObject(Kind kind) {
    return kind == Kind::World || kind == Kind::WorldView || kind == Kind::WorldViewProjection ||
           kind == Kind::WorldMatrixArray || kind == Kind::ObjectId || kind == Kind::ObjectColor;
}

bool SemanticBinder::isPerObject(size_t parameter) const {
    return std::any_of(mBindings.begin(), mBindings.end(), [parameter](const Binding& b) {
        return b.parameter == parameter && dependsOnObject(b.kind);
    });
}

bool SemanticBinder::derivesFromView(size_t parameter) const {
    return std::any_of(mBindings.begin(), mBindings.end(), [parameter](const Binding& b) {
        return b.parameter == parameter && dependsOnObject(b.kind) &&
               (b.kind == Kind::WorldView || b.kind == Kind::WorldViewProjection || b.lightSlot >= 0);
    });
}

void SemanticBinder::objectContext(const RenderPortView& port, const std::vector<bool>& used,
                                   std::vector<uint32_t>& out) const {
    const auto append = [&out](const glm::mat4& m) {
        const size_t at = out.size();
        out.resize(at + 16);
        std::memcpy(out.data() + at, &m[0][0], 16 * sizeof(float));
    };
    append(port.view);
    append(port.projection);
    out.push_back(static_cast<uint32_t>(port.lightIndex));
    out.push_back(static_cast<uint32_t>(port.cascade));
    for (const Binding& binding : mBindings) {
        if (!binding.active || !dependsOnObject(binding.kind) || binding.parameter >= used.size() ||
            !used[binding.parameter])
            continue;
        append(binding.lightView);
        append(binding.lightProjection);
        for (const LightView& cascade : binding.lightCascades) {
            append(cascade.view);
            append(cascade.projection);
        }
    }
}

bool SemanticBinder::projectionSource(size_t parameter, int& lightSlot) const {
    for (const Binding& b : mBindings) {
        if (b.parameter != parameter || b.kind == Kind::World) continue;
        if (b.kind != Kind::View && b.kind != Kind::Projection && b.kind != Kind::WorldView &&
            b.kind != Kind::ViewProjection && b.kind != Kind::WorldViewProjection)
            continue;
        lightSlot = b.lightSlot;
        return true;
    }
    return false;
}

void SemanticBinder::bind(const RenderPortView& port, const SceneObject* object, float time,
                          std::vector<fx::Value>& values, const std::vector<bool>& pinned, Scope scope,
                          const std::vector<bool>* used, ParameterStamps* stamps) const {
    const glm::mat4 world = object ? object->world : glm::mat4(1.0f);
    const auto bindOne = [&](const Binding& binding) {
        if (!binding.active || pinned[binding.parameter]) return;
        if (used && !(*used)[binding.parameter]) return;
        fx::Value& value = values[binding.parameter];
        if (stamps) mPrevious.assign(value.data.begin(), value.data.end());
        if (binding.member) {
            writeMember(binding, port, object, time, world, value);
        } else {
            write(binding, port, object, time, world, value);
        }
        if (stamps && value.data != mPrevious) stamps->touch(binding.parameter);
    };
    if (scope == Scope::All) {
        for (const Binding& binding : mBindings) bindOne(binding);
        return;
    }
    // A draw binds the few per-object bindings without walking past the others.
    const std::vector<size_t>& bindings = scope == Scope::PerObject  ? mObjectBindings
                                          : scope == Scope::PerFrame ? mFrameBindings
                                                                     : mPortBindings;
    for (size_t b : bindings) bindOne(mBindings[b]);
}

// The member's value, as write() gives a parameter of its type (an array of it where each element is a
// light's), copied into its place in each element of the struct's value; a binding not of each light
// writes the first element alone (the ambient of a light array's first light).
void SemanticBinder::writeMember(const Binding& binding, const RenderPortView& port,
                                 const SceneObject* object, float time, const glm::mat4& world,
                                 fx::Value& value) const {
    const fx::MemberBinding& member = *binding.member;
    mMemberValue.type = member.type;
    mMemberValue.type.arrayDims = binding.eachLight ? value.type.arrayDims : std::vector<int>{};
    write(binding, port, object, time, world, mMemberValue);
    const size_t count = static_cast<size_t>(member.type.componentCount());
    const size_t elements = count > 0 ? mMemberValue.data.size() / count : 0;
    for (size_t e = 0; e < elements; ++e) {
        const size_t at = member.firstComponent + e * member.elementStride;
        if (at + count > value.data.size()) break;
        std::copy_n(mMemberValue.data.begin() + static_cast<std::ptrdiff_t>(e * count), count,
                    value.data.begin() + static_cast<std::ptrdiff_t>(at));
    }
}

void SemanticBinder::write(const Binding& binding, const RenderPortView& port, const SceneObject* object,
                           float time, const glm::mat4& world, fx::Value& value) const {
    glm::mat4 view = port.view;
    glm::mat4 projection = port.projection;
    if (binding.eachLight) {
        storeEachLight(binding, port, value);
        return;
    }
    if (binding.light) {
        view = binding.lightView;
        projection = binding.lightProjection;
        // RenderPort=lightN.cascadeK: that light's matrices are cascade K's while the port is active.
        const bool cascadePort = port.cascade >= 0 &&
                                 port.lightIndex == static_cast<int>(binding.light - mScene->lights.data()) &&
                                 port.cascade < static_cast<int>(binding.lightCascades.size());
        if (cascadePort) {
            view = binding.lightCascades[static_cast<size_t>(port.cascade)].view;
            projection = binding.lightCascades[static_cast<size_t>(port.cascade)].projection;
        }
    }
    // glm composes column-vector transforms right to left: D3D's World*View*Proj is proj*view*world.
    glm::mat4 matrix(1.0f);
    switch (binding.kind) {
        case Kind::World:
            matrix = world;
            break;
        case Kind::View:
            matrix = view;
            break;
        case Kind::CubeFaceSelect:
            matrix = binding.lightFaceSelect;
            break;
        case Kind::Projection:
            matrix = projection;
            break;
        case Kind::WorldView:
            matrix = view * world;
            break;
        case Kind::ViewProjection:
            matrix = projection * view;
            break;
        case Kind::WorldViewProjection:
            matrix = projection * view * world;
            break;
        case Kind::WorldMatrixArray:
        case Kind::BonePalette: {
            const glm::mat4 element = binding.kind == Kind::WorldMatrixArray ? world : glm::mat4(1.0f);
            storeElements(value, std::span<const float>(glm::value_ptr(element), 16), 4, 4);
            return;
        }
        case Kind::ViewportPixelSize:
            storeVector(value, glm::vec4(port.viewportSize, 0.0f, 0.0f));
            return;
        case Kind::Time:
            storeVector(value, glm::vec4(time));
            return;
        case Kind::ResetPulse:
            storeVector(value, glm::vec4(mResetPulse ? 1.0f : 0.0f));
            return;
        case Kind::CameraPosition: {
            const glm::mat4 viewInverse = glm::inverse(view);
            storeVector(value, glm::vec4(glm::vec3(viewInverse[3]), 1.0f));
            return;
        }
        case Kind::ObjectId:
            storeVector(value, glm::vec4(object ? static_cast<float>(object->id) : 0.0f));
            return;
        case Kind::LightPosition: {
            const glm::vec3 position = lightPosition(binding);
            storeVector(
                value, binding.viewSpace ? port.view * glm::vec4(position, 1.0f) : glm::vec4(position, 1.0f));
            return;
        }
        case Kind::LightDirection: {
            const glm::vec4 direction(
                binding.towardsLight ? -binding.light->direction : binding.light->direction, 0.0f);
            storeVector(value, binding.viewSpace ? port.view * direction : direction);
            return;
        }
        case Kind::LightColor:
            storeVector(value, glm::vec4(binding.light->color, 1.0f));
            return;
        case Kind::LightAreaRadius:
            storeVector(value, glm::vec4(binding.light->areaRadius));
            return;
        case Kind::LightRange:
            storeVector(value, glm::vec4(lightRange(lightPosition(binding))));
            return;
        case Kind::ObjectColor:
            storeVector(value, glm::vec4(object ? object->color : glm::vec3(1.0f), 1.0f));
            return;
        case Kind::Ambient:
            storeVector(value, glm::vec4(mScene->ambient, 1.0f));
            return;
        case Kind::LightCount:
            storeVector(value, glm::vec4(static_cast<float>(
                                   std::min(static_cast<int>(mScene->lights.size()), mLightCountLimit))));
            return;
        case Kind::SceneHasClosedObjects:
            storeVector(value, glm::vec4(mHasClosedObjects ? 1.0f : 0.0f));
            return;
        case Kind::CascadeViewProjection:
        case Kind::CascadeAtlasRects:
        case Kind::CascadeSplitDepths:
            storeCascades(binding, value);
            return;
        default:  // the tunables, StandardsGlobal and None are never bound
            return;
    }
    if (binding.inverse) matrix = glm::inverse(matrix);
    if (binding.transpose) matrix = glm::transpose(matrix);
    storeMatrix(value, matrix);
}

}  // namespace runtime
