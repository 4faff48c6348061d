// HostFrame: the frame a host file describes (fx/HostFile.h), drawn as the application drew it:
// through the pass API (EffectTechnique::begin, EffectPass::apply and commitChanges, EffectVariable's
// setters), with the targets it created and its own draws of the scene's meshes between the passes.
// EffectRenderer::render(Scene) runs it in place of the SAS host when a host file is set.
#pragma once

#include <runtime/EffectRenderer.h>
#include <runtime/GpuTexture.h>
#include <fx/HostFile.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace runtime {

class HostFrame {
public:
    explicit HostFrame(std::shared_ptr<const fx::HostFile> host) : mHost(std::move(host)) {}

    // Draws the frame into the renderer's frame target (what readFrame() reads). For an effect compiled
    // with SHADOWFX_VISIBILITY, a host file with "visibility" makes the frame the shadow factor instead
    // (docs/host-files.md, "Scoring"). False, with diagnostics, where a step cannot run.
    bool render(EffectRenderer& renderer, EffectResources& resources, const Scene& scene,
                const FrameOptions& options, fx::DiagnosticSink& diagnostics);

private:
    struct Target {
        GpuTexture color;
        GpuTexture depth;
    };
    // The frame's steps once; steps that draw into `unshadowed` targets only clear them.
    bool drawSteps(EffectRenderer& renderer, EffectResources& resources, const Scene& scene,
                   const FrameOptions& options, const std::set<std::string>& unshadowed,
                   fx::DiagnosticSink& diagnostics);
    void ensureTargets(EffectRenderer& renderer, int width, int height);

    std::shared_ptr<const fx::HostFile> mHost;
    std::map<std::string, Target> mTargets;
    // The parameters the scored frames hold at the visibility section's constants.
    std::set<std::string> mOverridden;
};

}  // namespace runtime
