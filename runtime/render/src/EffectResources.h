// EffectResources: what an EffectRenderer owns between frames, as the parts that own it, each a class that
// keeps its own invariants (FX11's EffectLoad resolves a compiled effect into runtime structures once,
// its EffectRuntime changes only what changed):
// - ParameterValues: the values, their change stamps and pinned flags, changed only by writers that
//   touch the stamp (per frame: semantics, scripts; any time: the application, a pool);
// - PassPrograms: every pass's programs, preshaders and stream-output capture (at load; variants on first
//   use);
// - EffectTextures: the sampled textures, the render targets sized per frame and the framebuffers that
//   attach them (a target reallocated leaves no framebuffer on the old one);
// - StorageResources: buffers, counters and read-write textures, kept between frames and dispatches;
// - EffectSamplers: the GL samplers (at load, unchanged after);
// - SceneCache: the scene's bounds and BVH, rebuilt when its objects change.
// Resolved once beside them: the semantic binder and each technique's pass uses. What
// is left as plain members is working storage (frameScratch, framePlan: overwritten by each frame, kept
// for its allocations), what the application's passes keep between begin() and end(), and the history of
// the render targets' contents, which every change of what passes read outside the plan (setTexture,
// setApplicationTexture, setBuffer) clears.
#pragma once

#include "AnnotationTable.h"
#include "BatchedPass.h"
#include "CullCache.h"
#include "EffectSamplers.h"
#include "EffectTextures.h"
#include <private/runtime/FramePlan.h>
#include <runtime/Framebuffer.h>
#include <runtime/GpuBuffer.h>
#include <runtime/GpuMesh.h>
#include <runtime/GpuProgram.h>
#include <runtime/GpuTexture.h>
#include <runtime/GlStateSnapshot.h>
#include <runtime/InstanceBvh.h>
#include "HostScene.h"
#include "PassPrograms.h"
#include "ParameterValues.h"
#include "PassUse.h"
#include "SceneCache.h"
#include "ScriptInterpreter.h"
#include "StorageResources.h"
#include "PoolMembership.h"
#include <runtime/SamplerObject.h>
#include <runtime/StreamOutBuffers.h>
#include "SemanticBinder.h"
#include "VisibleSamplePass.h"

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <runtime/EffectRenderer.h>
#include <runtime/Scene.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace runtime {

class EffectResources {
public:
    // Links every pass's program, compiles nothing (the effect is compiled), creates textures, storage and
    // samplers. nullptr if a program does not link, a file texture cannot be read or a buffer or image
    // cannot be made; the diagnostics say why.
    static std::unique_ptr<EffectResources> create(std::shared_ptr<const fx::CompiledEffect> compiled,
                                                   fx::DiagnosticSink& diagnostics);

    const fx::CompiledEffect& effect() const { return *mCompiled; }
    const std::vector<fx::ParameterInfo>& parameterInfo() const { return mCompiled->parameters; }
    std::optional<size_t> findParameter(std::string_view name) const;
    // The current value of a parameter by name; nullptr if there is none.
    const fx::Value* find(std::string_view name) const;

    // [SECTION] Parameters
    ParameterValues values;  // with their change stamps and pinned flags
    PoolMembership pool;     // the `shared` parameters' values, with the other effects of a pool

    // [SECTION] Resolved once, when the effect is created (names as indices, kept for the effect's life)
    std::unique_ptr<SemanticBinder> binder;      // the semantics, classified; prepared for each frame
    std::vector<std::vector<PassUse>> passUses;  // [technique][pass]
    // The technique the last frame ran for FrameOptions::technique, where the choice reads no parameter.
    struct TechniqueChoice {
        bool valid = false;
        std::string requested;
        size_t technique = 0;
    } techniqueChoice;

    // [SECTION] GL resources
    // Every pass's programs, preshaders and stream-output capture, made at load.
    std::unique_ptr<PassPrograms> programs;
    // The textures the effect samples and renders into, with the frame's targets and their framebuffers.
    std::unique_ptr<EffectTextures> textures;
    // The buffers and read-write textures behind the buffer and image parameters, with their views.
    std::unique_ptr<StorageResources> storage;
    EffectSamplers samplers;  // made at load, unchanged after
    GpuMesh quad;
    HostScenePainter hostScene;  // ScriptExternal=color
    std::unique_ptr<UniformRing> uniformRing;

    // [SECTION] The application's passes (runtime/EffectPass.h)
    AnnotationTable annotations;
    // What EffectTechnique::begin() captured and EffectPass::apply() bound, until end(): written by those
    // (EffectPass.cpp, ComputeDispatch.cpp) alone.
    struct ApplicationFrame {
        std::optional<size_t> begun;           // the technique between begin() and end()
        bool saving = false;                   // begin() saved the state: end() restores `saved`
        std::optional<GlStateSnapshot> saved;  // what end() restores (kept after it for its storage)
        // The application's framebuffer and viewport, for passes whose script binds the frame's targets.
        bool targetKnown = false;
        GLint framebuffer = 0;
        std::array<GLint, 4> viewport{};
        int depthBits = 24;       // of the application's depth buffer (DepthBias, RenderStateApplier.h)
        int boundDepthBits = 24;  // of the depth target bound now
        std::optional<std::pair<size_t, size_t>> applied;  // the technique and pass last applied
        std::vector<fx::Value> arguments;                  // its compile arguments' values
    } application;
    // Per technique: the state its begin() saves (EffectTechnique::stateMask), made on its first begin().
    std::vector<std::optional<GlStateMask>> techniqueStateMasks;

    // [SECTION] Between frames
    // The next frame is a reset frame (FXCOMPOSER_RESETPULSE reads true in it): the first one after the
    // effect is created, and the first after EffectRenderer::reset().
    bool resetPending = true;
    // The technique the last frame ran: a frame that runs another starts a picture as a reset frame does.
    std::optional<size_t> lastTechnique;
    // The scene as last rendered: its bounds and BVH, rebuilt only when its objects change.
    SceneCache sceneCache;
    // The culling volumes' visible lists, kept while the scene and the volume stand still.
    CullCache cullCache;
    // FrameExecutor's working lists, kept between frames so that a frame like the last allocates nothing.
    struct FrameScratch {
        std::vector<uint32_t> visible;  // the objects the current draw draws
        std::vector<bool> perObject;    // per parameter: bound per object in the current pass
        std::vector<uint32_t> context;  // batching's per-object context (SemanticBinder::objectContext)
        struct Batch {
            uint32_t first;  // its first object
            size_t offset;   // in `instances`
            size_t count;
        };
        std::vector<Batch> batches;          // batching's instanced draws of the current draw
        std::vector<size_t> batchOfMesh;     // per mesh slot: its batch in the current draw, or npos
        std::vector<size_t> objectBatch;     // per visible object: its batch
        std::vector<uint32_t> instances;     // the instance lists, batch after batch
        std::vector<fx::Value> arguments;    // the current draw's compile arguments
        ParameterValues planValues;          // the dry run's copy of the parameter values (PlanRecorder)
        std::vector<float> planClearColor;   // the dry run's clear colour
        std::vector<bool> neededTargets;     // per parameter: a render target the frame's plan uses
        std::vector<glm::vec3> cameraBody;   // the camera's intersection body, for the plan's regions
        std::vector<int> outputTargets;      // FrameOptions::outputTargets, resolved
        std::vector<glm::vec3> sliceBody;    // PlanRecorder: a cascade slice's intersection body
        std::vector<uint32_t> sliceObjects;  // PlanRecorder: the objects in a cascade slice
        std::vector<GLuint> timerQueries;    // PassTimer's queries of the frame

        // The names `outputTargets` was resolved from.
        std::vector<std::string> outputTargetNames;
        // The loops open while the dry run or the run walks the script.
        ScriptLoopStack scriptLoops;
    } frameScratch;
    // The frame's plan, kept between frames for its storage (EffectRenderer::render rebuilds it).
    FramePlan framePlan;
    // What each render target holds after the frames so far (FramePlan): how light passes are reused.
    std::map<int, TargetHistory> targetHistory;
    // Fits to what the camera sees (LightFitVisibleSamples): the pre-pass that finds the samples.
    VisibleSamplePass visibleSamplePass;

    GpuMesh& gpuMesh(const std::shared_ptr<const Mesh>& mesh);
    // The binder with its lights fitted for a frame of `scene` at width x height, outside render(): what
    // EffectRenderer::lightFit and a host file's frame see. A fit to what the camera sees runs its own
    // pre-pass (GL work). The annotations' mistakes are render()'s to report.
    const SemanticBinder& fitLights(const Scene& scene, int width, int height);
    // EffectRenderer::setTexture (EffectTextures::set), and what earlier frames drew from the old texels
    // no longer reused.
    bool setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics);
    // EffectVariable::setTexture (EffectTextures::setApplicationTexture), and the same.
    void setApplicationTexture(size_t parameter, GLuint name, GLenum target);
    // EffectRenderer::setBuffer (StorageResources::set), and what earlier frames drew from the old
    // contents no longer reused.
    bool setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                   fx::DiagnosticSink& diagnostics);

private:
    std::shared_ptr<const fx::CompiledEffect> mCompiled;
    std::unordered_map<std::string, size_t> mParameterIndex;
    std::map<const Mesh*, std::pair<std::shared_ptr<const Mesh>, GpuMesh>> mMeshes;
};

}  // namespace runtime
