// EffectResources: what an EffectRenderer owns between frames. Created once from the compiled effect (the
// way FX11's EffectLoad turns a compiled effect into runtime structures once): one GpuProgram and one
// PassPreshaders per pass, the effect's textures and samplers, the parameter values with their change
// stamps; render targets sized per frame, GPU meshes per scene mesh, the scene's BVH and what each render
// target holds after the frames so far.
#pragma once

#include "AnnotationTable.h"
#include "BatchedPass.h"
#include "CullCache.h"
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
#include "ScriptInterpreter.h"
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

// A storage buffer's `int ElementCount = N;` (1 without it); nullopt, with a diagnostic at the parameter,
// for a count outside 1..2^28.
std::optional<size_t> declaredElementCount(const fx::ParameterInfo& parameter,
                                           fx::DiagnosticSink& diagnostics);

class EffectResources {
public:
    // Links every pass's program, compiles nothing (the effect is compiled), creates textures and samplers.
    // nullptr if a program does not link or a file texture cannot be read; the diagnostics say why.
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
    std::unique_ptr<SemanticBinder> binder;          // the semantics, classified; prepared for each frame
    std::unique_ptr<ScriptOperands> scriptOperands;  // what the scripts' commands name
    std::vector<std::vector<PassUse>> passUses;      // [technique][pass]
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
    std::map<size_t, GpuBuffer> buffers;  // by buffer parameter index (Buffer<T>, ...)
    // The hidden counter (one uint) of each structured read-write buffer (RWStructuredBuffer,
    // AppendStructuredBuffer, ConsumeStructuredBuffer), by parameter index: zero at load and kept between
    // frames and dispatches, as FX11 binds unordered access views keeping their counters; setBuffer sets it
    // to the number of elements given.
    std::map<size_t, GpuBuffer> counters;
    // The textures of the RWTexture1D, RWTexture2D, RWTexture3D and RWTexture2DArray parameters, by
    // parameter index (StorageImages.cpp): made at load, kept between frames. An RWBuffer's storage is in
    // `buffers`, with the buffer texture its image binds.
    std::map<size_t, GpuTexture> images;
    // Compute dispatches so far: what a pass reading storage buffers or images reads changes with them,
    // which the frame plan's signatures take in (PlanRecorder::draw) so that leave-out never keeps such a
    // pass's last result.
    uint64_t computeDispatches = 0;
    // `string ViewOf = "Resource";` on a StructuredBuffer, ByteAddressBuffer or Texture2D: the parameter
    // reads the read-write resource named (FX11's shader-resource view of the buffer or texture a compute
    // pass writes through its unordered access view), by index. Made at load (StorageImages.cpp).
    std::map<size_t, size_t> resourceViews;
    // The resource `parameter` reads: the one it is a view of, else its own.
    size_t viewedResource(size_t parameter) const {
        auto view = resourceViews.find(parameter);
        return view == resourceViews.end() ? parameter : view->second;
    }
    std::map<size_t, SamplerObject> samplers;
    std::map<size_t, SamplerObject> comparisonSamplers;
    // fx::CompiledEffect::passSamplers as GL samplers, by index (SamplerBinding::passSampler).
    std::vector<SamplerObject> passSamplers;
    std::vector<SamplerObject> passComparisonSamplers;
    GpuMesh quad;
    HostScenePainter hostScene;  // ScriptExternal=color
    std::unique_ptr<UniformRing> uniformRing;

    // [SECTION] The application's passes (runtime/EffectPass.h)
    AnnotationTable annotations;
    // A GL texture of the application's given to a texture parameter (EffectVariable::setTexture), bound
    // wherever the parameter is sampled instead of the effect's own; the application keeps it alive.
    struct ApplicationTexture {
        GLuint name = 0;
        GLenum target = GL_TEXTURE_2D;
    };
    std::map<size_t, ApplicationTexture> applicationTextures;
    struct ApplicationFrame {
        std::optional<size_t> begun;           // the technique between begin() and end()
        std::optional<GlStateSnapshot> saved;  // what end() restores
        // The application's framebuffer and viewport, for passes whose script binds the frame's targets.
        bool targetKnown = false;
        GLint framebuffer = 0;
        std::array<GLint, 4> viewport{};
        int depthBits = 24;       // of the application's depth buffer (DepthBias, RenderStateApplier.h)
        int boundDepthBits = 24;  // of the depth target bound now
        std::optional<std::pair<size_t, size_t>> applied;  // the technique and pass last applied
        std::vector<fx::Value> arguments;                  // its compile arguments' values
    } application;

    // [SECTION] Between frames
    // The scene as last rendered: a stamp of its objects, its bounds (a pass over every vertex) and the
    // BVH over its objects' boxes, rebuilt only when the stamp changes (see sceneStamp()).
    struct SceneCache {
        uint64_t stamp = 0;
        bool valid = false;
        Bounds bounds;
        InstanceBvh bvh;
        std::map<const Mesh*, Aabb> meshBoxes;
        // Per object: its mesh's index among the scene's distinct meshes (batching groups by it).
        std::vector<uint32_t> meshSlots;
        size_t meshCount = 0;
    } sceneCache;
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
    // EffectRenderer::setTexture (EffectTextures::set), and what earlier frames drew from the old texels
    // no longer reused.
    bool setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics);
    // The textures of the read-write texture parameters a pass uses, at their Width, Height, Depth and
    // ArraySize annotations, and the buffers of its RWBuffer parameters at their ElementCount, in the format
    // their code declares (StorageImages.cpp). False, with a diagnostic, for a format or size shadowfx
    // cannot make.
    bool createImages(fx::DiagnosticSink& diagnostics);
    // EffectRenderer::setBuffer.
    bool setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                   fx::DiagnosticSink& diagnostics);
    void updateSceneCache(const Scene& scene);

private:
    bool createDefaultBuffers(fx::DiagnosticSink& diagnostics);

    std::shared_ptr<const fx::CompiledEffect> mCompiled;
    std::unordered_map<std::string, size_t> mParameterIndex;
    std::map<const Mesh*, std::pair<std::shared_ptr<const Mesh>, GpuMesh>> mMeshes;
};

}  // namespace runtime
