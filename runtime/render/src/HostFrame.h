// HostFrame: the frame a host file describes (fx/HostFile.h), drawn as the application drew it:
// through the pass API (EffectTechnique::begin, EffectPass::apply and commitChanges, EffectVariable's
// setters), with the targets it created and its own draws of the scene's meshes between the passes.
// EffectRenderer::render(Scene) runs it in place of the SAS host when a host file is set.
#pragma once

#include <runtime/EffectPass.h>
#include <runtime/EffectRenderer.h>
#include <runtime/EffectVariable.h>
#include <runtime/GpuTexture.h>
#include <fx/HostFile.h>

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace runtime {

class HostFrame {
public:
    // Resolves the file's names once: its parameters, techniques and passes against `renderer`'s effect
    // (fx::checkHostFile found them), its steps' targets and ports against its own lists. A frame looks up
    // no name but the scene's lights, and those only when the scene's lights are renamed.
    HostFrame(std::shared_ptr<const fx::HostFile> host, EffectRenderer& renderer);

    // Draws the frame into the renderer's frame target (what readFrame() reads). For an effect compiled
    // with SHADOWFX_VISIBILITY, a host file with "visibility" makes the frame the shadow factor instead
    // (docs/host-files.md, "Scoring"). False, with diagnostics, where a step cannot run.
    bool render(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                fx::DiagnosticSink& diagnostics);

    // A value's names as indices: the parameter's handle and the lights it reads (mLightNames' indices).
    struct Value {
        const fx::HostParameter* parameter = nullptr;
        EffectVariable variable;
        int light = -1;                 // HostValue::light
        std::vector<int> factorLights;  // per HostValue::factors entry: its light, or -1
        fx::Value staged;               // of the variable's type: the value set, built in place each time
    };
    // A render port's matrices: the camera's, or a light's as RenderPort=lightN gets them.
    struct PortMatrices {
        glm::mat4 view{1.0f};
        glm::mat4 projection{1.0f};
    };

private:
    struct Target {
        GpuTexture color;
        GpuTexture depth;
        EffectVariable texture;  // the parameter it is given to (HostTarget::texture), or invalid
    };
    struct Step {
        EffectTechnique technique;
        std::vector<size_t> passes;            // the passes it applies, in order
        int target = -1;                       // mTargets' index, -1 for the frame
        int port = -1;                         // mLightNames' index, -1 for the camera
        std::vector<EffectVariable> dispatch;  // per HostStep::dispatch term: its parameter, or invalid
        bool unshadowed = false;  // its target is listed in the visibility section's "unshadowed"
    };
    // The frame's steps once; with `leaveUnshadowed`, steps that draw into unshadowed targets only clear
    // them.
    bool drawSteps(EffectResources& resources, const Scene& scene, const FrameOptions& options,
                   bool leaveUnshadowed, fx::DiagnosticSink& diagnostics);
    void ensureTargets(int width, int height);
    int lightIndex(const std::string& name);
    Value resolve(const fx::HostParameter& parameter, EffectRenderer& renderer);
    // mSceneLights for `scene`, by name only where the names of its lights changed since the last frame.
    void resolveSceneLights(const Scene& scene);

    std::shared_ptr<const fx::HostFile> mHost;
    std::vector<Target> mTargets;  // HostFile::targets' order
    std::vector<Value> mParameters;
    std::vector<Value> mVisibilitySet;
    std::vector<Step> mSteps;
    // The file has a visibility section and the effect was compiled with SHADOWFX_VISIBILITY: each frame
    // is the shadow factor. Read from the effect's provenance once, here, not per frame.
    bool mScored = false;
    std::vector<std::string> mLightNames;  // every light the file names, once
    // Per mLightNames entry: the projection the file gives it (the last that names it), or null.
    std::vector<const fx::HostLightProjection*> mLightProjections;
    std::vector<int> mSceneLights;  // per mLightNames entry: its index in Scene::lights, -1 where missing
    std::vector<std::string> mSceneLightNames;  // the scene's light names mSceneLights was resolved for
    bool mSceneLightsResolved = false;
    // Per effect parameter: held at the visibility section's constants while the scored frames run.
    std::vector<bool> mOverridden;
    // A frame's working lists, per mLightNames entry, kept between frames for their storage: the scene's
    // light, its matrices and whether they are fitted yet.
    std::vector<const Light*> mSceneLightsDrawn;
    std::vector<PortMatrices> mLightMatrices;
    std::vector<bool> mLightsFitted;
};

}  // namespace runtime
