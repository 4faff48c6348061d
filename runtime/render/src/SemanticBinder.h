// SemanticBinder: gives effect parameters with standard semantics their values for each draw.
//
// Matrices: World, View, Projection, WorldView, ViewProjection, WorldViewProjection, each also with the
// suffixes Inverse, Transpose and InverseTranspose (case-insensitive, as in D3DX/SAS). A parameter
// annotated `string frustum = "light0";` (or `string Object = "light0";`) sees that light's view and
// projection instead of the current render port's. Other semantics: ViewportPixelSize, Time,
// CameraPosition, ObjectId, FXCOMPOSER_RESETPULSE (true in a reset frame); light properties
// Position/LightPosition, Direction/LightDirection and LightColor, LightAreaRadius/LightSize (the light's
// areaRadius in world units, for soft-shadow filters), LightRange (from the light past the scene's
// farthest point) (light named by an Object/frustum annotation, default
// light0); Diffuse/MaterialDiffuse (the object's colour; with an Object annotation, the light's colour) and
// Ambient (the scene's ambient light), LightCount (the scene's lights, at most the shortest per-light
// array). A light matrix may also carry `string Parameterization = "Uniform" | "Focused" | "LiSPSM" |
// "TSM";` (runtime/LightParameterization.h): that light's matrices, for every
// parameter and for RenderPort=lightN, are then the provider's fit, with tunables from the parameters with
// semantics LiSPSMNScale, LiSPSMNOpt (a string), LiSPSMDepthExtent, LiSPSMMiddleVector, LightPancaking,
// TSMFocus, PSMSlideBack, PSMMaxWarpRatio, CascadeCount, CascadeSplitLambda, CascadeBlend and
// LightFitVisibleSamples (a bool: fit to the samples the camera sees, runtime/VisibleSamples.h). A `Cascaded`
// light's sub-views (runtime/CascadedShadowMaps.h) bind to arrays: CascadeViewProjection (float4x4[K], each
// cascade's view x projection, what RenderPort=lightN.cascadeK renders with), CascadeAtlasRects (float4[K]:
// u0, v0, du, dv of its atlas tile) and CascadeSplitDepths (floats, e.g. a float4: the view depth where each
// cascade ends; components past the last cascade repeat its value). A `PSMCube` light's six faces
// (runtime/PerspectiveShadowCubeMap.h) bind to the same arrays, plus CubeFaceSelect (float4x4: world -> the
// cube frame whose dominant axis picks a point's face). Scene-driven choices: SceneHasClosedObjects (true
// if any object's mesh is closed: a second depth layer can matter) and LightAreaRadius (0 = no soft-shadow
// filter needed). A parameter without a semantic whose name follows D3D applications' conventions
// (`gWorldViewProj`, `g_mWorld`, `matView`, `gEyePosW`; without an initializer also lights, colours and
// the light count: `g_LightDir[3]`, `g_MaterialDiffuseColor`, `g_nNumLights`) is bound as the semantic it
// spells; an array of a light's property holds one element per light of the scene. The members of a
// light or material struct without a semantic (fx::ParameterInfo::memberBindings) are bound as their
// names spell in the struct's context, each written into its place in the struct's value. The compiler
// classifies each parameter (fx::ParameterInfo::standard, fx/ParameterSemantics.h): the binder reads no
// semantic's text.
#pragma once

#include <fx/Diagnostics.h>
#include <fx/CompiledEffect.h>
#include <fx/Value.h>
#include <runtime/LightParameterization.h>
#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

// Change stamps of parameter values: stamps[i] changes whenever the value of parameter i does. A stamp is
// never given twice (one clock for every copy of the values), so equal stamps mean equal values: what the
// runtime's preshader cache compares to run a program only when one of its inputs changed.
struct ParameterStamps {
    std::vector<uint64_t> stamps;
    std::shared_ptr<uint64_t> clock = std::make_shared<uint64_t>(0);

    void touch(size_t parameter) { stamps[parameter] = ++*clock; }
};

// What the current pass renders from (the camera, or a light for RenderPort=lightN) and into.
struct RenderPortView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec2 viewportSize{1.0f};
    bool shinesIntoPositiveW = true;  // LightFit::shinesIntoPositiveW of a light port (true for the camera)
    // RenderPort=lightN.cascadeK: the light (its index in Scene::lights) and K; -1 otherwise. While such a
    // port is active, the light's annotated View/Projection parameters see cascade K's matrices.
    int lightIndex = -1;
    int cascade = -1;
};

class SemanticBinder {
public:
    // Builds the bindings of the parameters' semantics as the compiler classified them and registers the
    // lights they name, once, when the effect is created: a frame looks up no semantic and no light by
    // name. Parameters with semantics the runtime does not know are left alone (they are the user's own).
    // `lights` (fx::CompiledEffect::lights) take the first slots, in order: slot k is lights[k], the index
    // the compiler gave RenderPort=lightN (fx::ScriptCommand::light) and the parameters' semantics
    // (fx::SemanticBinding::light).
    SemanticBinder(const std::vector<fx::ParameterInfo>& parameters, const std::vector<std::string>& lights);

    // The slot of a light an effect names (`RenderPort=light0`, a `frustum`/`Object` annotation), registered
    // when the effect is created; prepare() resolves every slot against the frame's scene.
    int lightSlot(std::string_view lightName);
    // The frame's light in a slot, or null where the scene has no light of that name.
    const Light* slotLight(int slot) const;

    // Prepares a frame of `scene`: resolves the light slots (by name only when the scene's lights differ
    // from the last frame's), reads the parameterization tunables from `values` (the current parameter
    // values), and fits each named light once for the frame.
    // `sceneBounds` is scene.bounds(), which costs a pass over every vertex: the caller computes it once.
    // `aspect` (the frame's width / height) serves view-dependent light fits. `visible` (may be null): what
    // the camera sees this frame, for the fits of an effect that asks for it (wantsVisibleSamples).
    // Mistakes of the annotations and the scene are reported to `diagnostics` every frame. `stamps` (of
    // `values`): a string tunable is read again only when its parameter changed.
    void prepare(const Scene& scene, const Bounds& sceneBounds, float aspect,
                 const std::vector<fx::Value>& values, const ParameterStamps& stamps,
                 fx::DiagnosticSink& diagnostics, const VisibleSamples* visible = nullptr);

    // True if a parameter with semantic LightFitVisibleSamples is set: the frame must find the visible
    // samples (VisibleSamplePass) before the lights are fitted.
    bool wantsVisibleSamples(const std::vector<fx::Value>& values) const;

    // Which bindings one bind() call writes: the frame's once before its script runs (PerFrame: the reset
    // pulse, which a script's LoopByCount may read), the port's values once per pass (PerPort) and only
    // what depends on the object per draw (PerObject: World*, ObjectId, Diffuse).
    enum class Scope { All, PerFrame, PerPort, PerObject };

    // Whether the frame bind() writes for is a reset frame: FXCOMPOSER_RESETPULSE's value.
    void setResetPulse(bool resetPulse) { mResetPulse = resetPulse; }

    // Writes the values of every bound parameter that is not pinned into `values` (one per parameter).
    // `object` may be null (Draw=Buffer), then World is the identity. `used` (one flag per parameter, may
    // be null) restricts binding to the parameters a pass reads.
    // `stamps` (may be null) are touched for the parameters whose value changed.
    void bind(const RenderPortView& port, const SceneObject* object, float time,
              std::vector<fx::Value>& values, const std::vector<bool>& pinned, Scope scope = Scope::All,
              const std::vector<bool>* used = nullptr, ParameterStamps* stamps = nullptr) const;

    // True if the parameter's bound value depends on the drawn object.
    bool isPerObject(size_t parameter) const;
    // True if the parameter's per-object value also derives from the port's or a light's matrices
    // (WorldView and WorldViewProjection with their variants, or any per-object binding annotated with a
    // light): what a moving camera changes. The other per-object values (World and its variants, ObjectId,
    // the object's colour) derive from the object alone.
    bool derivesFromView(size_t parameter) const;
    // What the per-object values of the parameters `used` selects derive from besides the object (the
    // port's matrices and cascade, the matrices of annotated lights), appended to `out` as bit patterns:
    // equal contexts and equal objects bind equal values (what batching's per-object records are kept by).
    void objectContext(const RenderPortView& port, const std::vector<bool>& used,
                       std::vector<uint32_t>& out) const;
    // For a View/Projection-derived matrix (View, Projection, WorldView, ViewProjection,
    // WorldViewProjection and their variants): the slot of the light it is annotated with, or -1 for the
    // render port's matrices. False for any other parameter. What culling checks a pass projects with.
    bool projectionSource(size_t parameter, int& lightSlot) const;

    // The matrices of a light as this effect parameterizes it (Uniform unless an annotation says
    // otherwise): what RenderPort=lightN renders with, the same as the annotated parameters see.
    LightFit lightFit(const Light& light) const;

    size_t boundCount() const { return mBindings.size(); }
    bool isBound(size_t parameter) const;

    // What a parameter's semantic gives it, as the compiler classified it.
    using Kind = fx::SemanticKind;

private:
    struct Binding {
        size_t parameter;
        Kind kind;
        bool inverse = false;
        bool transpose = false;
        int lightSlot = -1;         // frustum/Object annotation (matrices), or the light of a light property
        bool eachLight = false;     // fx::SemanticBinding::eachLight: element k is the scene's light k
        bool viewSpace = false;     // fx::SemanticBinding::viewSpace
        bool towardsLight = false;  // fx::SemanticBinding::towardsLight: a direction negated
        // A member of a struct parameter (fx::ParameterInfo::memberBindings), null for the parameter.
        const fx::MemberBinding* member = nullptr;
        // Per frame (prepare()): the slot's light, null where the binding is not written this frame.
        const Light* light = nullptr;
        bool active = true;
        glm::mat4 lightView{1.0f};  // the light's matrices, fitted once: they do not change within a frame
        glm::mat4 lightProjection{1.0f};
        std::vector<LightView> lightCascades{};  // the light's cascades or cube faces, else empty
        glm::mat4 lightFaceSelect{0.0f};         // a PSMCube fit's LightFit::faceSelect
    };
    // A parameter a light fit reads: a tunable, or the `Parameterization` annotation of a light.
    struct FitInput {
        size_t parameter = 0;
        Kind tunable = Kind::None;      // a tunable's kind (LispsmNScale ... LightFitVisibleSamples)
        int parameterizationSlot = -1;  // a Parameterization annotation's light, or -1
        std::optional<LightParameterization> method;
        // LiSPSMNOpt: the choice its string names (nullopt: none), read at the parameter's stamp `readAt`.
        static constexpr uint64_t kNeverRead = ~uint64_t(0);
        uint64_t readAt = kNeverRead;
        std::optional<LispsmN> lispsmN;
    };
    static bool dependsOnObject(Kind kind);
    void addBinding(size_t parameter, const fx::SemanticBinding& standard, const fx::MemberBinding* member);
    void write(const Binding& binding, const RenderPortView& port, const SceneObject* object, float time,
               const glm::mat4& world, fx::Value& value) const;
    void writeMember(const Binding& binding, const RenderPortView& port, const SceneObject* object,
                     float time, const glm::mat4& world, fx::Value& value) const;
    glm::vec3 lightPosition(const Binding& binding) const;
    float lightRange(const glm::vec3& position) const;

    void resolveLights(const Scene& scene);

    struct FittedLight {
        const Light* light;
        LightParameterization method;
        LightFit fit;
    };
    const FittedLight& fittedLight(const Light& light);
    void storeCascades(const Binding& binding, fx::Value& value) const;
    void storeEachLight(const Binding& binding, const RenderPortView& port, fx::Value& value) const;

    const std::vector<fx::ParameterInfo>& mParameters;
    const Scene* mScene = nullptr;
    Bounds mSceneBounds;
    float mAspect = 1.0f;
    LightTunables mTunables;
    std::vector<FitInput> mFitInputs;
    std::vector<FittedLight> mFittedLights;  // one per light any parameter names, fitted once per frame
    bool mHasClosedObjects = false;
    // LightCount's most: the fewest elements of the effect's per-light arrays (a loop over that many
    // lights indexes no element past their ends), or no limit without such arrays.
    int mLightCountLimit = std::numeric_limits<int>::max();
    std::vector<Binding> mBindings;
    std::vector<size_t> mObjectBindings;  // indices in mBindings of those that depend on the object
    std::vector<size_t> mFrameBindings;   // of those whose value is the frame's (ResetPulse)
    std::vector<size_t> mPortBindings;    // and of the others
    bool mResetPulse = false;
    // The light slots: the names the effect uses, and per frame the scene's light of each (by index into
    // Scene::lights, resolved again only when the names of the scene's lights change).
    std::vector<std::string> mSlotNames;
    std::vector<int> mSlotIndices;
    std::vector<const Light*> mSlotLights;
    std::vector<std::string> mResolvedLightNames;
    bool mResolved = false;
    mutable std::vector<float> mPrevious;  // bind(): a value before it is written, to see whether it changed
    mutable fx::Value mMemberValue;        // writeMember(): the member's value before it is copied in place
};

}  // namespace runtime
