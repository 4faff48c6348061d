// ShadowMeasurement: see ShadowMeasurement.h.
#include <runtime/ShadowMeasurement.h>
#include <runtime/RuntimeModules.h>

#include <fx/CompileWorkers.h>
#include <fx/EffectFile.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace runtime {

GroundTruth castOrReadTruth(const Scene& scene, const Light& light, const GBuffer& gbuffer,
                            const GroundTruthOptions& options, const TruthCache* cache, bool& cached,
                            std::string& note) {
    cached = false;
    note.clear();
    if (!cache) return ShadowRayCaster(scene).compute(gbuffer, light, options);
    const uint64_t key = truthKey(scene, light, gbuffer, options);
    TruthCache::Lookup lookup = cache->load(key, gbuffer.width, gbuffer.height);
    if (lookup.truth) {
        cached = true;
        return std::move(*lookup.truth);
    }
    if (!lookup.rejected.empty()) note = lookup.rejected + ": cast again";
    GroundTruth truth = ShadowRayCaster(scene).compute(gbuffer, light, options);
    std::string storeError;
    if (!cache->store(key, truth, storeError)) note += (note.empty() ? "" : "; ") + storeError;
    return truth;
}

bool measureSceneTruth(SceneTruth& t, Scene scene, int width, int height, const GroundTruthOptions& options,
                       fx::DiagnosticSink& sink, std::string& error, const TruthCache* cache) {
    t.scene = std::move(scene);
    t.light = t.scene.findLight("light0");
    if (!t.light && !t.scene.lights.empty()) t.light = &t.scene.lights[0];
    if (!t.light) {
        error = "scene '" + t.scene.name + "' has no light";
        return false;
    }
    const auto start = std::chrono::steady_clock::now();
    std::optional<GBuffer> gbuffer = renderGBuffer(t.scene, width, height, sink);
    if (!gbuffer) {
        error = "the G-buffer of scene '" + t.scene.name + "' could not be rendered";
        return false;
    }
    t.gbuffer = std::move(*gbuffer);
    try {
        t.truth = castOrReadTruth(t.scene, *t.light, t.gbuffer, options, cache, t.cached, t.cacheNote);
    } catch (const ModuleLoadError& e) {
        error = e.what();
        return false;
    }
    t.receivers = receiverMask(t.gbuffer, *t.light);
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

std::shared_ptr<fx::CompiledEffect> compileVariant(const std::string& path, fx::ParseOptions options,
                                                   std::vector<std::pair<std::string, std::string>> extra,
                                                   fx::DiagnosticSink& sink, const std::string& technique) {
    for (auto& define : extra) options.defines.push_back(std::move(define));
    fx::CompileOptions compileOptions;
    compileOptions.technique = technique;
    return fx::loadEffectFile(path, options, compileOptions, sink);
}

std::vector<CompiledVariant> compileVariants(const std::vector<VariantRequest>& requests,
                                             const fx::ParseOptions& options) {
    std::vector<CompiledVariant> compiled(requests.size());
    std::atomic<size_t> next{0};
    auto drain = [&] {
        for (size_t i = next++; i < requests.size(); i = next++)
            compiled[i].effect = compileVariant(requests[i].path, options, requests[i].extra,
                                                compiled[i].diagnostics, requests[i].technique);
    };
    const size_t threadCount =
        std::min(requests.size(), static_cast<size_t>(fx::CompileWorkers::shared().maxWorkers()));
    std::vector<std::thread> threads;
    for (size_t t = 1; t < threadCount; ++t) threads.emplace_back(drain);
    drain();
    for (std::thread& thread : threads) thread.join();
    return compiled;
}

void forward(const fx::DiagnosticList& list, fx::DiagnosticSink& sink) {
    for (const fx::Diagnostic& diagnostic : list.items()) sink.report(diagnostic);
}

bool sameFragmentShaders(const fx::CompiledEffect& a, const fx::CompiledEffect& b) {
    if (a.techniques.size() != b.techniques.size()) return false;
    for (size_t t = 0; t < a.techniques.size(); ++t) {
        if (a.techniques[t].passes.size() != b.techniques[t].passes.size()) return false;
        for (size_t p = 0; p < a.techniques[t].passes.size(); ++p)
            if (a.techniques[t].passes[p].fragment.glsl != b.techniques[t].passes[p].fragment.glsl)
                return false;
    }
    return true;
}

std::optional<VisibilityScore> scoreVisibility(EffectRenderer& visibilityRenderer, const SceneTruth& t,
                                               const GroundTruth& truth, const FrameOptions& options,
                                               fx::DiagnosticSink& sink) {
    FrameOptions frame = options;
    frame.timePasses = false;
    if (!visibilityRenderer.render(t.scene, frame, sink)) return std::nullopt;
    VisibilityScore score;
    score.visibility = visibilityFromFrame(visibilityRenderer.readFrame());
    score.errors = compareVisibility(truth.visibility, score.visibility, t.receivers);
    return score;
}

}  // namespace runtime
