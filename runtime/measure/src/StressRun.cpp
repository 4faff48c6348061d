// StressRun: see StressRun.h.
//
// [SECTION] Truth  per case (and per frame of a temporal case): G-buffer, ray-cast truth, light volume
// [SECTION] Runs   effect x technique x case: render, finite values, error, shimmer; then each peer's
//                  techniques through the same cases
#include <runtime/StressRun.h>

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <report/NumberFormat.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/LightParameterization.h>
#include <runtime/NonFiniteScan.h>
#include <runtime/PeerRun.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/StressCases.h>
#include <runtime/TruthCache.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace runtime {

namespace {

using report::excusableCriterion;
using Criterion = report::StressCriterion;
using Outcome = report::StressOutcome;
using report::kMinScoredReceivers;
using report::kOrdinaryFactor;
using report::kOrdinarySlack;
using report::kShimmerLimit;
using report::kUniformFactor;
using report::kUniformSlack;

// Light volume: clip coordinates may exceed the volume by this fraction of w (rounding on its faces).
constexpr float kClipTolerance = 1e-3f;

// [SECTION] Truth

struct FrameTruth {
    Scene scene;  // the configuration the effect renders in this frame
    std::vector<float> visibility;
    std::vector<uint8_t> receivers;
    size_t receiverCount = 0;
};

struct CaseTruth {
    StressCase stressCase;
    std::vector<FrameTruth> frames;
    // Of the runtime's own matrices, whatever the effect.
    std::vector<std::pair<Criterion, std::string>> problems;
    size_t lightVolumeReceivers = 0;
    size_t outsideLightVolume = 0;
    double maxFootprint = 0.0;  // of the runtime's uniform map
    double p95Footprint = 0.0;
    // World positions of the first frame's receiver pixels: each effect's own light fit must cover them.
    std::vector<glm::vec3> receiverPositions;
    // The first frame's G-buffer and receivers, for the texel footprint of each effect's own fit.
    std::optional<GBuffer> gbuffer;
    std::vector<uint8_t> footprintReceivers;
};

// Is `world` inside the clip volume of `viewProjection` (up to kClipTolerance)?
bool insideClip(const glm::mat4& viewProjection, const glm::vec3& world) {
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    const float slack = kClipTolerance * std::abs(clip.w);
    return clip.w > 0.0f && std::abs(clip.x) <= clip.w + slack && std::abs(clip.y) <= clip.w + slack &&
           clip.z >= -slack && clip.z <= clip.w + slack;
}

// Receivers of `gbuffer` outside the clip volume of the light's view and projection.
size_t countOutsideLightVolume(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                               const glm::mat4& viewProjection) {
    size_t outside = 0;
    for (size_t i = 0; i < receivers.size(); ++i)
        if (receivers[i]) outside += insideClip(viewProjection, gbuffer.position[i]) ? 0 : 1;
    return outside;
}

std::optional<CaseTruth> computeTruth(StressCase stressCase, int width, int height, int mapSize,
                                      const TruthCache* cache, DiagnosticLog& sink,
                                      const std::function<void(const std::string&)>& note) {
    CaseTruth truth;
    truth.stressCase = std::move(stressCase);
    const StressCase& c = truth.stressCase;
    std::vector<Camera> cameras = c.cameraPath;
    if (cameras.empty()) cameras.push_back(c.scene.camera);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);

    for (size_t f = 0; f < cameras.size(); ++f) {
        FrameTruth& frame = truth.frames.emplace_back();
        frame.scene = c.scene;
        frame.scene.camera = cameras[f];
        SceneTruth measured;
        std::string error;
        if (!measureSceneTruth(measured, c.truthScene ? *c.truthScene : frame.scene, width, height, {}, sink,
                               error, cache))
            return std::nullopt;
        if (!measured.cacheNote.empty()) note("--truth-cache: " + measured.cacheNote);
        frame.visibility = std::move(measured.truth.visibility);
        frame.receivers = std::move(measured.receivers);
        std::optional<GBuffer> gbuffer = std::move(measured.gbuffer);
        frame.receiverCount =
            static_cast<size_t>(std::count(frame.receivers.begin(), frame.receivers.end(), 1));
        if (f != 0) continue;

        // The runtime's matrices for the configuration itself (not the truth's stand-in).
        const Scene& scene = frame.scene;
        const Bounds bounds = scene.bounds();
        if (!isFinite(scene.camera.view()) || !isFinite(scene.camera.projection(aspect)))
            truth.problems.emplace_back(Criterion::Finite, "camera matrix not finite");
        const auto uniformFit = [&](const Light& light) {
            return fitLight(LightParameterization::Uniform, scene, bounds, aspect, light);
        };
        for (const Light& sceneLight : scene.lights) {
            const LightFit fit = uniformFit(sceneLight);
            if (!isFinite(fit.view) || !isFinite(fit.projection))
                truth.problems.emplace_back(Criterion::Finite,
                                            "light '" + sceneLight.name + "' matrix not finite");
        }
        std::optional<GBuffer> own =
            c.truthScene ? renderGBuffer(scene, width, height, sink) : std::move(gbuffer);
        if (!own) return std::nullopt;
        const Light& sceneLight = scene.lights.at(0);
        const std::vector<uint8_t> receivers = receiverMask(*own, sceneLight);
        const LightFit fit = uniformFit(sceneLight);
        const glm::mat4& lightView = fit.view;
        const glm::mat4& lightProjection = fit.projection;
        truth.lightVolumeReceivers = static_cast<size_t>(std::count(receivers.begin(), receivers.end(), 1));
        truth.outsideLightVolume = countOutsideLightVolume(*own, receivers, lightProjection * lightView);
        for (size_t i = 0; i < receivers.size(); ++i)
            if (receivers[i]) truth.receiverPositions.push_back(own->position[i]);
        if (truth.outsideLightVolume > 0)
            truth.problems.emplace_back(Criterion::LightVolume,
                                        std::to_string(truth.outsideLightVolume) +
                                            " receiver pixels outside the light's clip volume");
        const AliasingMeasure aliasing =
            perspectiveAliasing(*own, receivers, lightView, lightProjection, mapSize);
        truth.maxFootprint = aliasing.maxFootprint;
        truth.p95Footprint = aliasing.p95Footprint;
        truth.gbuffer = std::move(own);
        truth.footprintReceivers = receivers;
    }
    return truth;
}

// [SECTION] Runs

// Scores a run's visibility frames, one per frame of the case, against the case's truth: the error
// (mean over the frames with receivers) and, for a temporal case, the shimmer between consecutive frames.
void scoreFrames(Outcome& outcome, const CaseTruth& truth, const std::vector<std::vector<float>>& frames) {
    std::vector<std::vector<uint8_t>> shadowed;  // per frame: the run's classification
    double errorSum = 0.0, falseShadowSum = 0.0, falseLightSum = 0.0;
    size_t scoredFrames = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
        const FrameTruth& frame = truth.frames[f];
        const std::vector<float>& visibility = frames[f];
        outcome.receivers = frame.receiverCount;
        if (frame.receiverCount > 0) {
            const ShadowErrors errors = compareVisibility(frame.visibility, visibility, frame.receivers);
            errorSum += errors.misclassifiedPercent;
            falseShadowSum += errors.falseShadowPercent;
            falseLightSum += errors.falseLightPercent;
            ++scoredFrames;
        }
        std::vector<uint8_t>& classes = shadowed.emplace_back(visibility.size());
        for (size_t i = 0; i < visibility.size(); ++i) classes[i] = visibility[i] < kShadowedBelow ? 1 : 0;
    }
    if (scoredFrames > 0) {
        outcome.misclassified = errorSum / static_cast<double>(scoredFrames);
        outcome.falseShadow = falseShadowSum / static_cast<double>(scoredFrames);
        outcome.falseLight = falseLightSum / static_cast<double>(scoredFrames);
    }

    if (shadowed.size() > 1) {
        double sum = 0.0, worst = 0.0;
        for (size_t f = 1; f < shadowed.size(); ++f) {
            const FrameTruth &a = truth.frames[f - 1], &b = truth.frames[f];
            size_t steady = 0, flips = 0;
            for (size_t i = 0; i < shadowed[f].size(); ++i) {
                if (!a.receivers[i] || !b.receivers[i]) continue;
                const bool truthA = a.visibility[i] < kShadowedBelow;
                const bool truthB = b.visibility[i] < kShadowedBelow;
                if (truthA != truthB) continue;
                ++steady;
                flips += shadowed[f - 1][i] != shadowed[f][i] ? 1 : 0;
            }
            const double share =
                steady ? 100.0 * static_cast<double>(flips) / static_cast<double>(steady) : 0.0;
            sum += share;
            worst = std::max(worst, share);
        }
        outcome.shimmerMean = sum / static_cast<double>(shadowed.size() - 1);
        outcome.shimmerMax = worst;
        if (*outcome.shimmerMean > kShimmerLimit)
            outcome.fail(Criterion::Shimmer, "shimmer " + report::formatPercent(*outcome.shimmerMean) +
                                                 " of steady pixels flip per frame (limit " +
                                                 report::formatPercent(kShimmerLimit) + ")");
    }
}

// `errorImage`: the last scored frame's error image.
Outcome runCase(EffectRenderer& renderer, bool exposesVisibility, const std::string& technique,
                const CaseTruth& truth, int width, int height, int mapSize, DiagnosticLog& sink,
                FrameImage& errorImage) {
    Outcome outcome;
    outcome.caseName = truth.stressCase.name;
    outcome.technique = technique;
    for (const auto& [criterion, problem] : truth.problems) outcome.fail(criterion, problem);

    FrameOptions options;
    options.width = width;
    options.height = height;
    options.technique = technique;
    std::vector<std::vector<float>> visibilities;  // per frame, where the effect exposes its visibility
    for (const FrameTruth& frame : truth.frames) {
        if (!renderer.render(frame.scene, options, sink) || sink.failed()) {
            outcome.fail(Criterion::Render, "render failed: " + sink.takeErrors());
            return outcome;
        }
        // The light matrices this effect renders with (its Parameterization annotation,
        // docs/techniques/light-space-parameterizations.md), held to the same checks as the runtime's uniform
        // ones above.
        if (&frame == &truth.frames.front() && !frame.scene.lights.empty()) {
            const std::optional<LightFit> fit =
                renderer.lightFit(frame.scene, frame.scene.lights.front().name, options);
            if (fit && (!isFinite(fit->view) || !isFinite(fit->projection))) {
                outcome.fail(Criterion::Finite, "the effect's light matrix is not finite");
            } else if (fit) {
                const glm::mat4 viewProjection = fit->projection * fit->view;
                size_t outside = 0;
                for (const glm::vec3& p : truth.receiverPositions)
                    outside += insideClip(viewProjection, p) ? 0 : 1;
                if (outside > 0)
                    outcome.fail(Criterion::LightVolume,
                                 std::to_string(outside) +
                                     " receiver pixels outside the clip volume of the effect's light fit");
                if (truth.gbuffer) {
                    const AliasingMeasure aliasing = fitAliasing(*truth.gbuffer, truth.footprintReceivers,
                                                                 frame.scene.camera.view(), *fit, mapSize);
                    if (aliasing.pixels > 0) {
                        outcome.maxFootprint = aliasing.maxFootprint;
                        outcome.p95Footprint = aliasing.p95Footprint;
                    }
                    if (frame.receiverCount > 0)
                        outcome.samplingLimited =
                            samplingLimitedError(*truth.gbuffer, frame.receivers, frame.visibility,
                                                 frame.scene.camera.view(), *fit, mapSize);
                }
            }
        }
        if (std::optional<std::string> name = findNonFiniteParameter(renderer)) {
            outcome.fail(Criterion::Finite, "parameter " + *name + " not finite");
            return outcome;
        }
        if (std::optional<NonFiniteTexels> texels = findNonFiniteTexels(renderer, TextureScan::AllTextures)) {
            outcome.fail(Criterion::Finite, "NaN/Inf in render target " + texels->texture + "[" +
                                                std::to_string(texels->x) + "," + std::to_string(texels->y) +
                                                "]");
            return outcome;
        }
        if (!exposesVisibility) continue;
        const FrameImage rendered = renderer.readFrame();
        visibilities.push_back(visibilityFromFrame(rendered));
        if (frame.receiverCount > 0)
            errorImage =
                runtime::errorImage(rendered, frame.visibility, visibilities.back(), frame.receivers);
    }
    scoreFrames(outcome, truth, visibilities);
    return outcome;
}

// A peer's technique on a case (PeerRun.h): the peer renders the case by name, one frame per camera, and
// its frames are scored as an effect's are. The runtime's own matrices and an effect's light fit do not
// concern it: where the peer fails to render, that is its render failure. `errorImage` over the peer's
// last scored frame (its visibility in grey).
Outcome runPeerCase(const Peer& peer, const std::string& technique, const CaseTruth& truth, int width,
                    int height, int mapSize, const std::filesystem::path& workDir, FrameImage& errorImage) {
    Outcome outcome;
    outcome.effect = peer.name;
    outcome.peer = peer.name + "/" + technique;
    outcome.caseName = truth.stressCase.name;
    outcome.technique = technique;
    // One warm-up frame: osgShadow's draw-bounds LiSPSM fits its map to the previous frame's depth.
    const PeerRequest request{peer.program, truth.stressCase.name, technique, mapSize, width, height, 1, 1};
    std::string error;
    const std::optional<std::vector<std::vector<float>>> frames =
        runPeerOnStressCase(request, truth.frames.size(), workDir, error);
    if (!frames) {
        // The log's last line says why; the whole log stays in the work folder.
        while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
        const size_t lastLine = error.rfind('\n');
        outcome.fail(
            Criterion::Render,
            "the peer failed: " + (lastLine == std::string::npos ? error : error.substr(lastLine + 1)));
        return outcome;
    }
    scoreFrames(outcome, truth, *frames);
    for (size_t f = 0; f < frames->size(); ++f) {
        const FrameTruth& frame = truth.frames[f];
        if (frame.receiverCount == 0) continue;
        FrameImage grey;
        grey.width = width;
        grey.height = height;
        grey.rgba.resize((*frames)[f].size() * 4);
        for (size_t i = 0; i < (*frames)[f].size(); ++i) {
            const auto value = static_cast<uint8_t>((*frames)[f][i] * 255.0f + 0.5f);
            grey.rgba[i * 4] = grey.rgba[i * 4 + 1] = grey.rgba[i * 4 + 2] = value;
            grey.rgba[i * 4 + 3] = 255;
        }
        errorImage = runtime::errorImage(grey, frame.visibility, (*frames)[f], frame.receivers);
    }
    return outcome;
}

// A technique's declared known limitations, each naming the criteria it excuses:
// `string StressExpectedFailures = "grazing [ordinary, uniform]: why; case2 [shimmer]: why";`.
struct Declaration {
    std::vector<Criterion> criteria;
    std::string because;
};

// The declarations of `technique`; a malformed one (no criteria, or one that cannot be excused) is an
// error in `errors`, so that a declaration never excuses more than it says.
std::map<std::string, Declaration> expectedFailures(const fx::CompiledEffect& effect,
                                                    const std::string& technique,
                                                    std::vector<std::string>& errors) {
    const auto trim = [](std::string text) {
        text.erase(0, text.find_first_not_of(" \t"));
        text.erase(text.find_last_not_of(" \t") + 1);
        return text;
    };
    std::map<std::string, Declaration> cases;
    for (const fx::CompiledTechnique& t : effect.techniques) {
        const fx::AnnotationValue* a =
            t.name == technique ? fx::findAnnotation(t.annotations, "StressExpectedFailures") : nullptr;
        if (!a || a->value.type.base != fx::BaseType::String) continue;
        std::stringstream entries(a->value.string);
        for (std::string entry; std::getline(entries, entry, ';');) {
            const size_t colon = entry.find(':');
            std::string head = trim(entry.substr(0, colon));
            if (head.empty()) continue;
            const size_t open = head.find('['), close = head.find(']');
            if (open == std::string::npos || close == std::string::npos || close < open) {
                errors.push_back("StressExpectedFailures of '" + technique + "': '" + head +
                                 "' names no criteria (write 'CASE [CRITERION, ...]: why')");
                continue;
            }
            Declaration& declaration = cases[trim(head.substr(0, open))];
            std::stringstream names(head.substr(open + 1, close - open - 1));
            for (std::string name; std::getline(names, name, ',');) {
                if (std::optional<Criterion> c = excusableCriterion(trim(name)))
                    declaration.criteria.push_back(*c);
                else
                    errors.push_back("StressExpectedFailures of '" + technique + "': '" + trim(name) +
                                     "' is not a criterion a declaration can excuse (light-volume, "
                                     "ordinary, uniform, shimmer)");
            }
            declaration.because = colon == std::string::npos ? "" : entry.substr(colon + 1);
        }
    }
    return cases;
}

// Holds a measured outcome to the ordinary case's and the uniform map's errors.
void judge(Outcome& outcome) {
    if (!outcome.misclassified || outcome.receivers < kMinScoredReceivers) return;
    const double error = *outcome.misclassified;
    const double resolution = report::samplingLimitedRise(outcome);
    if (outcome.ordinary && error > kOrdinaryFactor * *outcome.ordinary + kOrdinarySlack + resolution)
        outcome.fail(
            Criterion::Ordinary,
            "error " + report::formatPercent(error) + " > " +
                std::to_string(static_cast<int>(kOrdinaryFactor)) + "x the ordinary case's " +
                report::formatPercent(*outcome.ordinary) + " + 1 point" +
                (resolution > 0.0 ? " + the fit's sampling-limited rise " + report::formatPercent(resolution)
                                  : std::string()));
    if (!outcome.uniform)
        outcome.fail(Criterion::Uniform,
                     "the uniform map's error on this case is unknown: the comparison cannot be evaluated");
    else if (error > kUniformFactor * *outcome.uniform + kUniformSlack)
        outcome.fail(Criterion::Uniform, "error " + report::formatPercent(error) +
                                             " > 1.5x the uniform map's " +
                                             report::formatPercent(*outcome.uniform) + " + 0.5 point");
}

struct EffectUnderTest {
    std::string path;
    std::shared_ptr<fx::CompiledEffect> visibility;
    bool exposesVisibility = false;
};

std::optional<EffectUnderTest> compileForStress(const std::string& path, const fx::ParseOptions& base,
                                                int mapSize, DiagnosticLog& sink) {
    const std::pair<std::string, std::string> size{"SHADOWFX_SHADOW_MAP_SIZE", std::to_string(mapSize)};
    EffectUnderTest effect;
    effect.path = path;
    // A compiled file is the one variant it was compiled with: its frame is the shadow factor where that
    // variant is the SHADOWFX_VISIBILITY one (its provenance says), else its error goes unscored, as that
    // of an effect that ignores the define.
    if (fx::isCompiledEffectFile(path)) {
        effect.visibility = compileVariant(path, base, {}, sink);
        if (!effect.visibility) return std::nullopt;
        const auto& defines = effect.visibility->provenance.defines;
        effect.exposesVisibility = std::any_of(defines.begin(), defines.end(), [](const auto& define) {
            return define.first == "SHADOWFX_VISIBILITY" && define.second != "0";
        });
        return effect;
    }
    effect.visibility = compileVariant(path, base, {size, {"SHADOWFX_VISIBILITY", "1"}}, sink);
    std::shared_ptr<fx::CompiledEffect> shaded = compileVariant(path, base, {size}, sink);
    if (!effect.visibility || !shaded) return std::nullopt;
    // The define changed some pixel shader: the frame is the shadow factor.
    effect.exposesVisibility = !sameFragmentShaders(*shaded, *effect.visibility);
    return effect;
}

// [SECTION] Truth       per case (and per frame of a temporal case): G-buffer, ray-cast truth, light volume
// [SECTION] Runs        effect x technique x case: render, finite values, error, shimmer
}  // namespace

StressRun runStress(const StressOptions& o, const StressLog& log) {
    const auto note = [&](const std::string& text) {
        if (log.note) log.note(text);
    };
    const auto problem = [&](const std::string& text) {
        if (log.problem) log.problem(text);
    };
    StressRun run;
    const auto failed = [&](std::string why) {
        run.error = std::move(why);
        return std::move(run);
    };
    const int width = o.width, height = o.height, mapSize = o.mapSize;
    const std::string uniformSpec = o.uniformPath + ":" + o.uniformTechnique;
    // Every case's ordinary configuration runs too, first: the case is held to it.
    std::vector<std::string> ordered;
    for (const std::string& name : stressCaseNames()) {
        const bool wanted = std::find(o.cases.begin(), o.cases.end(), name) != o.cases.end();
        const bool needed = std::any_of(o.cases.begin(), o.cases.end(), [&](const std::string& other) {
            std::optional<StressCase> c = makeStressCase(other);
            return c && c->ordinary == name;
        });
        if (wanted || needed) ordered.push_back(name);
    }

    ContextOptions contextOptions;
    contextOptions.backend = o.backend;
    std::string contextError;
    std::unique_ptr<GlContext> context = createContext(contextOptions, contextError);
    if (!context) return failed(contextError);
    note(context->renderer());

    DiagnosticLog sink;
    std::optional<TruthCache> truthCache;
    if (!o.truthCacheDir.empty()) truthCache.emplace(o.truthCacheDir);
    std::map<std::string, CaseTruth> truths;
    for (const std::string& name : ordered) {
        note("ground truth for " + name);
        std::optional<CaseTruth> truth = computeTruth(*makeStressCase(name), width, height, mapSize,
                                                      truthCache ? &*truthCache : nullptr, sink, note);
        if (!truth) return failed("case " + name + ": the ground truth failed: " + sink.takeErrors());
        truths.emplace(name, std::move(*truth));
    }

    // The uniform map's error per case, the bar every method is held to.
    std::map<std::string, double> uniformError;
    {
        std::optional<EffectUnderTest> uniform =
            compileForStress(o.uniformPath, o.parseOptions, mapSize, sink);
        std::unique_ptr<EffectRenderer> renderer =
            uniform ? EffectRenderer::create(uniform->visibility, sink) : nullptr;
        if (!renderer)
            return failed("the uniform reference " + uniformSpec + " failed: " + sink.takeErrors());
        if (!uniform->exposesVisibility)
            return failed("the uniform reference " + uniformSpec +
                          " ignores SHADOWFX_VISIBILITY: its error cannot be measured (docs/scoring.md)");
        for (const std::string& name : ordered) {
            FrameImage unused;
            Outcome u = runCase(*renderer, uniform->exposesVisibility, o.uniformTechnique, truths.at(name),
                                width, height, mapSize, sink, unused);
            if (u.misclassified) {
                uniformError[name] = *u.misclassified;
            } else if (truths.at(name).frames.front().receiverCount > 0) {
                std::string why;
                for (const std::string& reason : u.reasons) why += (why.empty() ? "" : "; ") + reason;
                return failed("the uniform reference " + uniformSpec + " gives no error on " + name + ": " +
                              why);
            }
        }
    }

    std::vector<Outcome>& outcomes = run.result.outcomes;
    bool& anyFailed = run.failed;
    for (const std::string& path : o.effects) {
        const std::string effectName = std::filesystem::path(path).filename().string();
        std::optional<EffectUnderTest> effect = compileForStress(path, o.parseOptions, mapSize, sink);
        std::unique_ptr<EffectRenderer> renderer =
            effect ? EffectRenderer::create(effect->visibility, sink) : nullptr;
        if (!renderer) {
            Outcome failure;
            failure.effect = effectName;
            failure.technique = "*";
            failure.caseName = ordered.front();
            failure.fail(Criterion::Render, "does not compile or link: " + sink.takeErrors());
            outcomes.push_back(failure);
            anyFailed = true;
            continue;
        }
        for (const fx::CompiledTechnique& technique : effect->visibility->techniques) {
            if (!o.techniques.empty() &&
                std::find(o.techniques.begin(), o.techniques.end(), technique.name) == o.techniques.end())
                continue;
            std::map<std::string, double> measured, samplingLimited;
            std::vector<std::string> declarationErrors;
            const std::map<std::string, Declaration> known =
                expectedFailures(*effect->visibility, technique.name, declarationErrors);
            for (const auto& [name, declaration] : known)
                if (!makeStressCase(name))
                    declarationErrors.push_back("StressExpectedFailures of '" + technique.name +
                                                "' names no case '" + name + "' (shadowfx stress --list)");
            for (const std::string& error : declarationErrors) problem(effectName + ": " + error);
            anyFailed = anyFailed || !declarationErrors.empty();
            for (const std::string& name : ordered) {
                note(effectName + " " + technique.name + " " + name);
                const CaseTruth& truth = truths.at(name);
                FrameImage image;
                Outcome outcome = runCase(*renderer, effect->exposesVisibility, technique.name, truth, width,
                                          height, mapSize, sink, image);
                outcome.effect = effectName;
                if (outcome.misclassified) measured[name] = *outcome.misclassified;
                if (outcome.samplingLimited) samplingLimited[name] = *outcome.samplingLimited;
                if (auto it = measured.find(truth.stressCase.ordinary); it != measured.end())
                    outcome.ordinary = it->second;
                if (auto it = samplingLimited.find(truth.stressCase.ordinary); it != samplingLimited.end())
                    outcome.ordinarySamplingLimited = it->second;
                if (auto it = uniformError.find(name); it != uniformError.end()) outcome.uniform = it->second;
                judge(outcome);
                if (!outcome.pass && image.width > 0)
                    run.errorImages.push_back(StressErrorImage{std::filesystem::path(path).stem().string(),
                                                               technique.name, name, std::move(image)});
                if (auto it = known.find(name); it != known.end()) {
                    outcome.expectedFailure = true;
                    outcome.excused = it->second.criteria;
                    outcome.expectedBecause = it->second.because;
                }
                // Ordinary cases the user did not ask for ran only as references: their failures count,
                // an xpass of theirs is not judged.
                const bool requested = std::find(o.cases.begin(), o.cases.end(), name) != o.cases.end();
                const std::string result = outcome.result();
                anyFailed = anyFailed || result == "FAIL" || (o.strict && requested && result == "xpass");
                if (requested) outcomes.push_back(outcome);
            }
        }
    }

    // The peers' techniques through the same cases and truth, held to the same criteria (their own ordinary
    // case's error, the uniform map's): the report shows where they break. Their failures are theirs, not
    // the run's.
    for (const Peer& peer : o.peers) {
        const std::filesystem::path workDir = o.peerWorkDir / peer.name;
        std::error_code fsError;
        std::filesystem::create_directories(workDir, fsError);
        if (fsError) return failed("cannot create " + workDir.string() + ": " + fsError.message());
        for (const std::string& technique : peer.techniques) {
            std::map<std::string, double> measured;
            for (const std::string& name : ordered) {
                note(peer.name + " " + technique + " " + name);
                const CaseTruth& truth = truths.at(name);
                FrameImage image;
                Outcome outcome = runPeerCase(peer, technique, truth, width, height, mapSize, workDir, image);
                if (outcome.misclassified) measured[name] = *outcome.misclassified;
                if (auto it = measured.find(truth.stressCase.ordinary); it != measured.end())
                    outcome.ordinary = it->second;
                if (auto it = uniformError.find(name); it != uniformError.end()) outcome.uniform = it->second;
                judge(outcome);
                if (!outcome.pass && image.width > 0)
                    run.errorImages.push_back(StressErrorImage{peer.name, technique, name, std::move(image)});
                if (std::find(o.cases.begin(), o.cases.end(), name) != o.cases.end())
                    outcomes.push_back(outcome);
            }
        }
    }

    report::StressResult& result = run.result;
    result.renderer = context->renderer();
    result.width = width;
    result.height = height;
    result.mapSize = mapSize;
    for (const std::string& name : ordered) {
        const CaseTruth& t = truths.at(name);
        report::StressCaseSummary& c = result.cases.emplace_back();
        c.name = name;
        c.description = t.stressCase.description;
        c.ordinary = t.stressCase.ordinary;
        c.frames = t.frames.size();
        c.receiverPixels = t.frames.front().receiverCount;
        c.outsideLightVolume = t.outsideLightVolume;
        c.maxFootprint = t.maxFootprint;
        c.p95Footprint = t.p95Footprint;
        if (auto it = uniformError.find(name); it != uniformError.end()) c.uniformMisclassified = it->second;
    }
    run.measured = true;
    return run;
}

}  // namespace runtime
