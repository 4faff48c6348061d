// ShadowMeasurement: see ShadowMeasurement.h.
#include <runtime/ShadowMeasurement.h>

#include <fx/EffectCompiler.h>

#include <chrono>

namespace runtime {

bool measureSceneTruth(SceneTruth& t, Scene scene, int width, int height, const GroundTruthOptions& options,
                       fx::DiagnosticSink& sink, std::string& error) {
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
    const ShadowRayCaster caster(t.scene);
    t.truth = caster.compute(t.gbuffer, *t.light, options);
    t.receivers = receiverMask(t.gbuffer, *t.light);
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
}

std::shared_ptr<fx::CompiledEffect> compileVariant(const std::string& path, fx::ParseOptions options,
                                                   std::vector<std::pair<std::string, std::string>> extra,
                                                   fx::DiagnosticSink& sink, const std::string& technique) {
    for (auto& define : extra) options.defines.push_back(std::move(define));
    std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, options, sink);
    if (!effect) return nullptr;
    fx::CompileOptions compileOptions;
    compileOptions.technique = technique;
    return fx::compileEffect(effect, compileOptions, sink);
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
