// ShadowMeasurement: the measurement core `shadowfx bench`, `check` and `stress` share — the ray-cast
// ground truth of a scene, the two compiled variants of an effect (as written, and with
// SHADOWFX_VISIBILITY so that its final pass writes the shadow factor) and the scoring of one visibility
// frame against the truth (runtime/GroundTruth.h, runtime/ShadowMetrics.h).
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/EffectParser.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/Scene.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/TruthCache.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace runtime {

// A scene with its G-buffer, the visibility of its light0 (or first light) and its receiver pixels.
// `light` points into `scene`: keep a SceneTruth where it was filled (no copies or moves).
struct SceneTruth {
    Scene scene;
    const Light* light = nullptr;
    GBuffer gbuffer;
    GroundTruth truth;
    std::vector<uint8_t> receivers;
    double seconds = 0.0;  // G-buffer and rays (or reading the cached truth)
    bool cached = false;   // the truth was read from a TruthCache, not cast
    // What the measurer should hear about the cache: an entry rejected (and cast again), or one that could
    // not be stored. Empty when there was nothing to say.
    std::string cacheNote;
};

// Fills `t` for `scene` at width x height (needs a current GL context). With a `cache`, the truth is read
// from it when it holds an intact entry for exactly these inputs, else cast and stored there
// (TruthCache.h). False with `error` set if the scene has no light, its G-buffer cannot be rendered or the
// ray-cast module cannot be opened (runtime/RuntimeModules.h).
bool measureSceneTruth(SceneTruth& t, Scene scene, int width, int height, const GroundTruthOptions& options,
                       fx::DiagnosticSink& sink, std::string& error, const TruthCache* cache = nullptr);

// The truth of `light` over `gbuffer` in `scene`: from `cache` when it has it (`cached` set), else cast and
// stored there; without a cache, cast. `note` as SceneTruth::cacheNote. Throws ModuleLoadError as
// ShadowRayCaster does.
GroundTruth castOrReadTruth(const Scene& scene, const Light& light, const GBuffer& gbuffer,
                            const GroundTruthOptions& options, const TruthCache* cache, bool& cached,
                            std::string& note);

// Parses and compiles the effect at `path` with `options` plus the `extra` preprocessor definitions; only
// `technique` when one is named. A compiled effect file (fx/EffectFile.h) is read as it was compiled: the
// definitions apply to source only.
std::shared_ptr<fx::CompiledEffect> compileVariant(const std::string& path, fx::ParseOptions options,
                                                   std::vector<std::pair<std::string, std::string>> extra,
                                                   fx::DiagnosticSink& sink,
                                                   const std::string& technique = "");

// One compileVariant call, for compileVariants.
struct VariantRequest {
    std::string path;
    std::vector<std::pair<std::string, std::string>> extra;
    std::string technique;
};

// What compileVariants gives for one request: the effect (null on failure) and its diagnostics.
struct CompiledVariant {
    std::shared_ptr<fx::CompiledEffect> effect;
    fx::DiagnosticList diagnostics;
};

// compileVariant for every request, several at once (as many as fx's compile workers; each effect's
// stages spread over them too). Nothing is reported: the caller passes each request's diagnostics on.
std::vector<CompiledVariant> compileVariants(const std::vector<VariantRequest>& requests,
                                             const fx::ParseOptions& options);
// Reports every diagnostic of `list` into `sink`.
void forward(const fx::DiagnosticList& list, fx::DiagnosticSink& sink);

// True if every pass of `a` and `b` has the same pixel shader: then SHADOWFX_VISIBILITY changed nothing and
// the effect exposes no shadow term to score.
bool sameFragmentShaders(const fx::CompiledEffect& a, const fx::CompiledEffect& b);

// Renders one frame of the SHADOWFX_VISIBILITY variant and scores its red channel against `truth`
// (which may be `t.truth` or another truth of the same G-buffer, e.g. a hard one for an area light).
struct VisibilityScore {
    std::vector<float> visibility;  // the effect's, per pixel
    ShadowErrors errors;
};
std::optional<VisibilityScore> scoreVisibility(EffectRenderer& visibilityRenderer, const SceneTruth& t,
                                               const GroundTruth& truth, const FrameOptions& options,
                                               fx::DiagnosticSink& sink);

}  // namespace runtime
