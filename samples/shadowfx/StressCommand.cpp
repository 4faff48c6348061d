// StressCommand: `shadowfx stress`.
// [SECTION] Criteria    what passing means, as numbers
// [SECTION] Truth       per case (and per frame of a temporal case): G-buffer, ray-cast truth, light volume
// [SECTION] Runs        effect x technique x case: render, finite values, error, shimmer
// [SECTION] Output      the table on stdout, stress.json and report.md
//
// Effects are compiled with SHADOWFX_VISIBILITY (docs/scoring.md, "Measurement hooks"), so the frame is the
// shadow factor and can be scored against the truth; an effect that does not expose it gets the finite-value
// and GL checks only.
#include "StressCommand.h"
#include "EffectLibrary.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/GlContext.h>
#include <runtime/GroundTruth.h>
#include <runtime/LightParameterization.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/StressCases.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/NonFiniteScan.h>
#include <report/NumberFormat.h>
#include <runtime/ShadowMeasurement.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace shadowfx::cli {

const char* const kStressUsage =
    "usage: shadowfx stress [EFFECT.fx ...] [options]\n"
    "  EFFECT.fx ...         effects to stress (default: every effects/*.fx)\n"
    "  --effects LIST        the same, comma-separated\n"
    "  --cases LIST          cases to run, comma-separated (default: all; see --list)\n"
    "  --reduced             the reduced set (a quick look; CI runs every case)\n"
    "  --strict              a declared limitation that passes (xpass) fails the run too\n"
    "  --techniques LIST     only these techniques\n"
    "  --list                print the cases and exit\n"
    "  --width W, --height H frame size (default 320x240)\n"
    "  --map-size N          -D SHADOWFX_SHADOW_MAP_SIZE=N (default 1024)\n"
    "  --uniform FILE:TECH   the uniform shadow map every method is held to (default: the effect\n"
    "                        library's thesis_fxcomposer.fx:main, wherever stress runs from)\n"
    "  --backend NAME        auto, osmesa or egl (default auto)\n"
    "  --truth-cache DIR     read each case's ray-cast ground truth from DIR when it was cast before for\n"
    "                        the same inputs, else cast and store it there (docs/sharding.md)\n"
    "  --out DIR             stress.json, report.md and errors/*.png (failed runs) go here\n"
    "                        (default out/stress)\n"
    "exit status: 0 if every run passes or fails only where declared, 1 if one fails (or, with\n"
    "  --strict, passes where a failure is declared), 2 for usage errors\n";

namespace {

using Json = nlohmann::ordered_json;

// [SECTION] Criteria
// A case may be harder than its ordinary configuration, but not wholesale broken: its misclassified
// percentage may be at most kOrdinaryFactor times the ordinary one plus kOrdinarySlack points.
constexpr double kOrdinaryFactor = 3.0;
constexpr double kOrdinarySlack = 1.0;
// No method may do worse than the uniform shadow map on the same case, beyond filtering noise.
constexpr double kUniformFactor = 1.5;
constexpr double kUniformSlack = 0.5;
// Shimmer: the mean share of receiver pixels whose shadow state flips between consecutive frames while the
// truth at that pixel does not, in percent. Every shipped method has a view-independent light fit, so
// each claims stability and is held to it.
constexpr double kShimmerLimit = 0.25;
// Error criteria need enough receiver pixels to mean something: one pixel of six is not 17 % of a method.
constexpr size_t kMinScoredReceivers = 1000;
// Light volume: clip coordinates may exceed the volume by this fraction of w (rounding on its faces).
constexpr float kClipTolerance = 1e-3f;

// What a failed run failed on. A technique's declaration excuses the criteria it names (criterionName
// below) and no others; a failure to render or a non-finite value can never be excused.
enum class Criterion {
    Render,       // the effect does not compile, link or render, or a GL error
    Finite,       // a matrix, parameter or render-target texel is NaN or Inf
    LightVolume,  // receiver pixels outside the clip volume of a light fit
    Ordinary,     // the error against the case's ordinary configuration
    Uniform,      // the error against the uniform shadow map on the same case
    Shimmer,      // flips of steady pixels between frames of a temporal case
};

const char* criterionName(Criterion criterion) {
    switch (criterion) {
        case Criterion::Render:
            return "render";
        case Criterion::Finite:
            return "finite";
        case Criterion::LightVolume:
            return "light-volume";
        case Criterion::Ordinary:
            return "ordinary";
        case Criterion::Uniform:
            return "uniform";
        case Criterion::Shimmer:
            return "shimmer";
    }
    return "?";
}

std::optional<Criterion> excusableCriterion(std::string_view name) {
    for (Criterion c : {Criterion::LightVolume, Criterion::Ordinary, Criterion::Uniform, Criterion::Shimmer})
        if (name == criterionName(c)) return c;
    return std::nullopt;
}

// [SECTION] Truth

struct FrameTruth {
    runtime::Scene scene;  // the configuration the effect renders in this frame
    std::vector<float> visibility;
    std::vector<uint8_t> receivers;
    size_t receiverCount = 0;
};

struct CaseTruth {
    runtime::StressCase stressCase;
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
    std::optional<runtime::GBuffer> gbuffer;
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
size_t countOutsideLightVolume(const runtime::GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                               const glm::mat4& viewProjection) {
    size_t outside = 0;
    for (size_t i = 0; i < receivers.size(); ++i)
        if (receivers[i]) outside += insideClip(viewProjection, gbuffer.position[i]) ? 0 : 1;
    return outside;
}

std::optional<CaseTruth> computeTruth(runtime::StressCase stressCase, int width, int height, int mapSize,
                                      const runtime::TruthCache* cache, runtime::DiagnosticLog& sink) {
    CaseTruth truth;
    truth.stressCase = std::move(stressCase);
    const runtime::StressCase& c = truth.stressCase;
    std::vector<runtime::Camera> cameras = c.cameraPath;
    if (cameras.empty()) cameras.push_back(c.scene.camera);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);

    for (size_t f = 0; f < cameras.size(); ++f) {
        FrameTruth& frame = truth.frames.emplace_back();
        frame.scene = c.scene;
        frame.scene.camera = cameras[f];
        runtime::SceneTruth measured;
        std::string error;
        if (!runtime::measureSceneTruth(measured, c.truthScene ? *c.truthScene : frame.scene, width, height,
                                        {}, sink, error, cache))
            return std::nullopt;
        if (!measured.cacheNote.empty()) std::cerr << "stress: --truth-cache: " << measured.cacheNote << "\n";
        frame.visibility = std::move(measured.truth.visibility);
        frame.receivers = std::move(measured.receivers);
        std::optional<runtime::GBuffer> gbuffer = std::move(measured.gbuffer);
        frame.receiverCount =
            static_cast<size_t>(std::count(frame.receivers.begin(), frame.receivers.end(), 1));
        if (f != 0) continue;

        // The runtime's matrices for the configuration itself (not the truth's stand-in).
        const runtime::Scene& scene = frame.scene;
        const runtime::Bounds bounds = scene.bounds();
        if (!runtime::isFinite(scene.camera.view()) || !runtime::isFinite(scene.camera.projection(aspect)))
            truth.problems.emplace_back(Criterion::Finite, "camera matrix not finite");
        const auto uniformFit = [&](const runtime::Light& light) {
            return runtime::fitLight(runtime::LightParameterization::Uniform, scene, bounds, aspect, light);
        };
        for (const runtime::Light& sceneLight : scene.lights) {
            const runtime::LightFit fit = uniformFit(sceneLight);
            if (!runtime::isFinite(fit.view) || !runtime::isFinite(fit.projection))
                truth.problems.emplace_back(Criterion::Finite,
                                            "light '" + sceneLight.name + "' matrix not finite");
        }
        std::optional<runtime::GBuffer> own =
            c.truthScene ? runtime::renderGBuffer(scene, width, height, sink) : std::move(gbuffer);
        if (!own) return std::nullopt;
        const runtime::Light& sceneLight = scene.lights.at(0);
        const std::vector<uint8_t> receivers = runtime::receiverMask(*own, sceneLight);
        const runtime::LightFit fit = uniformFit(sceneLight);
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
        const runtime::AliasingMeasure aliasing =
            runtime::perspectiveAliasing(*own, receivers, lightView, lightProjection, mapSize);
        truth.maxFootprint = aliasing.maxFootprint;
        truth.p95Footprint = aliasing.p95Footprint;
        truth.gbuffer = std::move(own);
        truth.footprintReceivers = receivers;
    }
    return truth;
}

// [SECTION] Runs

struct Outcome {
    std::string effect;
    std::string technique;
    std::string caseName;
    bool pass = true;
    bool expectedFailure = false;  // the technique declares this case a known limitation
    std::string expectedBecause;
    std::vector<Criterion> excused;  // the criteria the declaration names
    std::vector<std::string> reasons;
    std::vector<Criterion> failed;                  // one per reason
    std::optional<double> misclassified;            // percent of receiver pixels (mean over the frames)
    double falseShadow = 0.0, falseLight = 0.0;     // its two parts
    std::optional<double> ordinary;                 // the nearest ordinary case's, same effect and technique
    std::optional<double> uniform;                  // the uniform shadow map's, same case
    std::optional<double> shimmerMean, shimmerMax;  // percent, temporal cases
    std::optional<double> maxFootprint, p95Footprint;  // texels of the effect's own fit (first frame)
    size_t receivers = 0;
    runtime::FrameImage errorImage;  // the last frame's (ShadowMetrics.h errorImage), written on failure

    void fail(Criterion criterion, std::string reason) {
        pass = false;
        reasons.push_back(std::move(reason));
        failed.push_back(criterion);
    }
    // Failed, and only on criteria its declaration names.
    bool isExcused() const {
        return !pass && expectedFailure && std::all_of(failed.begin(), failed.end(), [&](Criterion c) {
            return std::find(excused.begin(), excused.end(), c) != excused.end();
        });
    }
    // "pass", "xpass" (declared, yet passed), "xfail" (failed only where declared) or "FAIL".
    std::string result() const {
        if (pass) return expectedFailure ? "xpass" : "pass";
        return isExcused() ? "xfail" : "FAIL";
    }
};

Outcome runCase(runtime::EffectRenderer& renderer, bool exposesVisibility, const std::string& technique,
                const CaseTruth& truth, int width, int height, int mapSize, runtime::DiagnosticLog& sink) {
    Outcome outcome;
    outcome.caseName = truth.stressCase.name;
    outcome.technique = technique;
    for (const auto& [criterion, problem] : truth.problems) outcome.fail(criterion, problem);

    runtime::FrameOptions options;
    options.width = width;
    options.height = height;
    options.technique = technique;
    std::vector<std::vector<uint8_t>> shadowed;  // per frame: the effect's classification
    double errorSum = 0.0, falseShadowSum = 0.0, falseLightSum = 0.0;
    size_t scoredFrames = 0;
    for (const FrameTruth& frame : truth.frames) {
        if (!renderer.render(frame.scene, options, sink) || sink.failed()) {
            outcome.fail(Criterion::Render, "render failed: " + sink.takeErrors());
            return outcome;
        }
        // The light matrices this effect renders with (its Parameterization annotation,
        // docs/techniques/light-space-parameterizations.md), held to the same checks as the runtime's uniform
        // ones above.
        if (&frame == &truth.frames.front() && !frame.scene.lights.empty()) {
            const std::optional<runtime::LightFit> fit =
                renderer.lightFit(frame.scene, frame.scene.lights.front().name, options);
            if (fit && (!runtime::isFinite(fit->view) || !runtime::isFinite(fit->projection))) {
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
                    const runtime::AliasingMeasure aliasing = runtime::fitAliasing(
                        *truth.gbuffer, truth.footprintReceivers, frame.scene.camera.view(), *fit, mapSize);
                    if (aliasing.pixels > 0) {
                        outcome.maxFootprint = aliasing.maxFootprint;
                        outcome.p95Footprint = aliasing.p95Footprint;
                    }
                }
            }
        }
        if (std::optional<std::string> name = runtime::findNonFiniteParameter(renderer)) {
            outcome.fail(Criterion::Finite, "parameter " + *name + " not finite");
            return outcome;
        }
        if (std::optional<runtime::NonFiniteTexels> texels =
                runtime::findNonFiniteTexels(renderer, runtime::TextureScan::AllTextures)) {
            outcome.fail(Criterion::Finite, "NaN/Inf in render target " + texels->texture + "[" +
                                                std::to_string(texels->x) + "," + std::to_string(texels->y) +
                                                "]");
            return outcome;
        }
        if (!exposesVisibility) continue;
        const std::vector<float> visibility = runtime::visibilityFromFrame(renderer.readFrame());
        outcome.receivers = frame.receiverCount;
        if (frame.receiverCount > 0) {
            const runtime::ShadowErrors errors =
                runtime::compareVisibility(frame.visibility, visibility, frame.receivers);
            errorSum += errors.misclassifiedPercent;
            falseShadowSum += errors.falseShadowPercent;
            falseLightSum += errors.falseLightPercent;
            ++scoredFrames;
            outcome.errorImage =
                runtime::errorImage(renderer.readFrame(), frame.visibility, visibility, frame.receivers);
        }
        std::vector<uint8_t>& classes = shadowed.emplace_back(visibility.size());
        for (size_t i = 0; i < visibility.size(); ++i)
            classes[i] = visibility[i] < runtime::kShadowedBelow ? 1 : 0;
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
                const bool truthA = a.visibility[i] < runtime::kShadowedBelow;
                const bool truthB = b.visibility[i] < runtime::kShadowedBelow;
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
    if (outcome.ordinary && error > kOrdinaryFactor * *outcome.ordinary + kOrdinarySlack)
        outcome.fail(Criterion::Ordinary, "error " + report::formatPercent(error) + " > " +
                                              std::to_string(static_cast<int>(kOrdinaryFactor)) +
                                              "x the ordinary case's " +
                                              report::formatPercent(*outcome.ordinary) + " + 1 point");
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
                                                int mapSize, runtime::DiagnosticLog& sink) {
    const std::pair<std::string, std::string> size{"SHADOWFX_SHADOW_MAP_SIZE", std::to_string(mapSize)};
    EffectUnderTest effect;
    effect.path = path;
    effect.visibility = runtime::compileVariant(path, base, {size, {"SHADOWFX_VISIBILITY", "1"}}, sink);
    std::shared_ptr<fx::CompiledEffect> shaded = runtime::compileVariant(path, base, {size}, sink);
    if (!effect.visibility || !shaded) return std::nullopt;
    // The define changed some pixel shader: the frame is the shadow factor.
    effect.exposesVisibility = !runtime::sameFragmentShaders(*shaded, *effect.visibility);
    return effect;
}

// [SECTION] Output

std::vector<std::string> criterionNames(const std::vector<Criterion>& criteria) {
    std::vector<std::string> names;
    for (Criterion c : criteria) names.emplace_back(criterionName(c));
    return names;
}

Json optionalJson(const std::optional<double>& value) {
    return value ? Json(*value) : Json(nullptr);
}

std::string cell(const std::optional<double>& value) {
    return value ? report::formatPercent(*value) : "-";
}

void printTable(std::ostream& out, const std::vector<Outcome>& outcomes,
                const std::map<std::string, CaseTruth>& truths, bool markdown) {
    std::string current;
    for (const Outcome& o : outcomes) {
        const std::string heading = o.effect + " / " + o.technique;
        if (heading != current) {
            current = heading;
            if (markdown) {
                out << "\n### " << heading << "\n\n| case | result | misclassified | ordinary | uniform | "
                    << "p95 footprint | shimmer | why |\n|---|---|---|---|---|---|---|---|\n";
            } else {
                out << "\n"
                    << heading << "\n  " << std::left << std::setw(24) << "case" << std::setw(7) << "result"
                    << std::setw(15) << "misclassified" << std::setw(10) << "ordinary" << std::setw(10)
                    << "uniform" << std::setw(10) << "footprint" << std::setw(10) << "shimmer"
                    << "why\n";
            }
        }
        // The texel footprint of the effect's own fit where it has one, else of the runtime's uniform map.
        const CaseTruth& truth = truths.at(o.caseName);
        std::ostringstream footprint;
        footprint << std::fixed << std::setprecision(1) << o.p95Footprint.value_or(truth.p95Footprint);
        std::string why;
        for (const std::string& reason : o.reasons) why += (why.empty() ? "" : "; ") + reason;
        if (o.misclassified == std::nullopt && o.pass && o.receivers == 0) why = "no receiver pixels";
        if (o.misclassified && o.receivers < kMinScoredReceivers)
            why = std::to_string(o.receivers) + " receiver pixels: too few to judge the error";
        const std::string shimmer = o.shimmerMean ? report::formatPercent(*o.shimmerMean) : "-";
        const std::string result = o.result();
        if (o.expectedFailure) {
            std::string criteria;
            for (Criterion c : o.excused)
                criteria += (criteria.empty() ? "" : ", ") + std::string(criterionName(c));
            why +=
                (why.empty() ? "" : "; ") + std::string("declared [") + criteria + "]:" + o.expectedBecause;
        }
        if (markdown) {
            out << "| " << o.caseName << " | " << (result == "FAIL" ? "**FAIL**" : result) << " | "
                << cell(o.misclassified) << " | " << cell(o.ordinary) << " | " << cell(o.uniform) << " | "
                << footprint.str() << " | " << shimmer << " | " << why << " |\n";
        } else {
            out << "  " << std::left << std::setw(24) << o.caseName << std::setw(7) << result << std::setw(15)
                << cell(o.misclassified) << std::setw(10) << cell(o.ordinary) << std::setw(10)
                << cell(o.uniform) << std::setw(10) << footprint.str() << std::setw(10) << shimmer << why
                << "\n";
        }
    }
}

}  // namespace

int stressCommand(const Arguments& args) {
    if (args.flag("--list")) {
        for (const std::string& name : runtime::stressCaseNames()) {
            const runtime::StressCase c = *runtime::makeStressCase(name);
            std::cout << std::left << std::setw(24) << name << (c.reduced ? "[reduced] " : "          ")
                      << c.description << "\n";
        }
        return 0;
    }
    std::vector<std::string> effects;
    for (size_t i = 0; i < args.positionalCount(); ++i) effects.push_back(args.positional(i));
    for (const std::string& list : args.all("--effects"))
        for (const std::string& path : splitList(list)) effects.push_back(path);
    if (effects.empty()) {
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator("effects", error))
            if (entry.path().extension() == ".fx") effects.push_back(entry.path().string());
        std::sort(effects.begin(), effects.end());
        if (effects.empty()) {
            std::cerr << "shadowfx stress: no effects given and no effects/*.fx here\n";
            return 2;
        }
    }
    // A compiled file holds one variant; stress compiles its visibility variant from source.
    for (const std::string& path : effects) {
        if (fx::isCompiledEffectFile(path)) {
            std::cerr << path
                      << ": error: stress compiles the variants it scores from source: give the .fx file "
                      << "this compiled effect was compiled from\n";
            return 2;
        }
    }

    std::vector<std::string> caseNames =
        args.flag("--reduced") ? runtime::reducedStressCaseNames() : runtime::stressCaseNames();
    if (args.value("--cases") != "") caseNames = splitList(args.value("--cases"));
    // Every case's ordinary configuration runs too, first: the case is held to it.
    std::vector<std::string> ordered;
    for (const std::string& name : runtime::stressCaseNames()) {
        const bool wanted = std::find(caseNames.begin(), caseNames.end(), name) != caseNames.end();
        const bool needed = std::any_of(caseNames.begin(), caseNames.end(), [&](const std::string& other) {
            std::optional<runtime::StressCase> c = runtime::makeStressCase(other);
            return c && c->ordinary == name;
        });
        if (wanted || needed) ordered.push_back(name);
    }
    for (const std::string& name : caseNames) {
        if (!runtime::makeStressCase(name)) {
            std::cerr << "shadowfx stress: no case '" << name << "' (shadowfx stress --list)\n";
            return 2;
        }
    }
    const std::vector<std::string> techniqueFilter = splitList(args.value("--techniques"));
    const bool strict = args.flag("--strict");
    const int width = args.intValue("--width", 320), height = args.intValue("--height", 240);
    const int mapSize = args.intValue("--map-size", 1024);
    if (width <= 0 || height <= 0 || width > 4096 || height > 4096 || mapSize <= 0 || mapSize > 16384) {
        std::cerr << "shadowfx stress: --width/--height must be in 1..4096 and --map-size in 1..16384\n";
        return 2;
    }
    // The reference comes from the effect library, not the working directory: a rule whose reference is
    // missing cannot be evaluated, and that is an error, never a pass.
    const std::filesystem::path library = effectLibraryDir();
    const std::string uniformSpec =
        args.value("--uniform", library.empty() ? "" : (library / "thesis_fxcomposer.fx").string() + ":main");
    if (uniformSpec.empty()) {
        std::cerr << "shadowfx stress: no effect library found for the default --uniform: give --uniform "
                     "FILE:TECHNIQUE\n";
        return 2;
    }
    const size_t colon = uniformSpec.rfind(':');
    if (colon == std::string::npos) {
        std::cerr << "shadowfx stress: --uniform wants FILE:TECHNIQUE\n";
        return 2;
    }
    const std::string uniformPath = uniformSpec.substr(0, colon),
                      uniformTechnique = uniformSpec.substr(colon + 1);
    if (!std::filesystem::is_regular_file(uniformPath)) {
        std::cerr << "shadowfx stress: the uniform reference " << uniformPath << " does not exist\n";
        return 2;
    }
    const std::optional<runtime::Backend> backend = runtime::parseBackend(args.value("--backend", "auto"));
    if (!backend) {
        std::cerr << "shadowfx stress: --backend must be auto, osmesa or egl\n";
        return 2;
    }

    runtime::ContextOptions contextOptions;
    contextOptions.backend = *backend;
    std::string contextError;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext(contextOptions, contextError);
    if (!context) {
        std::cerr << "shadowfx stress: " << contextError << "\n";
        return 1;
    }
    std::cerr << "stress: " << context->renderer() << "\n";

    const std::filesystem::path outDir = args.value("--out", "out/stress");
    std::error_code fsError;
    std::filesystem::remove_all(outDir / "errors", fsError);
    std::filesystem::create_directories(outDir, fsError);
    if (fsError) {
        std::cerr << "shadowfx stress: cannot create " << outDir.string() << ": " << fsError.message()
                  << "\n";
        return 1;
    }

    runtime::DiagnosticLog sink;
    std::optional<runtime::TruthCache> truthCache;
    if (const std::string dir = args.value("--truth-cache"); !dir.empty()) truthCache.emplace(dir);
    std::map<std::string, CaseTruth> truths;
    for (const std::string& name : ordered) {
        std::cerr << "stress: ground truth for " << name << "\n";
        std::optional<CaseTruth> truth = computeTruth(*runtime::makeStressCase(name), width, height, mapSize,
                                                      truthCache ? &*truthCache : nullptr, sink);
        if (!truth) {
            std::cerr << "shadowfx stress: case " << name
                      << ": the ground truth failed: " << sink.takeErrors() << "\n";
            return 1;
        }
        truths.emplace(name, std::move(*truth));
    }

    const fx::ParseOptions parseOptions = effectParseOptions(args);

    // The uniform map's error per case, the bar every method is held to.
    std::map<std::string, double> uniformError;
    {
        std::optional<EffectUnderTest> uniform = compileForStress(uniformPath, parseOptions, mapSize, sink);
        std::unique_ptr<runtime::EffectRenderer> renderer =
            uniform ? runtime::EffectRenderer::create(uniform->visibility, sink) : nullptr;
        if (!renderer) {
            std::cerr << "shadowfx stress: the uniform reference " << uniformSpec
                      << " failed: " << sink.takeErrors() << "\n";
            return 1;
        }
        if (!uniform->exposesVisibility) {
            std::cerr << "shadowfx stress: the uniform reference " << uniformSpec
                      << " ignores SHADOWFX_VISIBILITY: its error cannot be measured (docs/scoring.md)\n";
            return 1;
        }
        for (const std::string& name : ordered) {
            Outcome o = runCase(*renderer, uniform->exposesVisibility, uniformTechnique, truths.at(name),
                                width, height, mapSize, sink);
            if (o.misclassified) {
                uniformError[name] = *o.misclassified;
            } else if (truths.at(name).frames.front().receiverCount > 0) {
                std::string why;
                for (const std::string& reason : o.reasons) why += (why.empty() ? "" : "; ") + reason;
                std::cerr << "shadowfx stress: the uniform reference " << uniformSpec << " gives no error on "
                          << name << ": " << why << "\n";
                return 1;
            }
        }
    }

    std::vector<Outcome> outcomes;
    bool anyFailed = false;
    for (const std::string& path : effects) {
        const std::string effectName = std::filesystem::path(path).filename().string();
        std::optional<EffectUnderTest> effect = compileForStress(path, parseOptions, mapSize, sink);
        std::unique_ptr<runtime::EffectRenderer> renderer =
            effect ? runtime::EffectRenderer::create(effect->visibility, sink) : nullptr;
        if (!renderer) {
            Outcome o;
            o.effect = effectName;
            o.technique = "*";
            o.caseName = ordered.front();
            o.fail(Criterion::Render, "does not compile or link: " + sink.takeErrors());
            outcomes.push_back(o);
            anyFailed = true;
            continue;
        }
        for (const fx::CompiledTechnique& technique : effect->visibility->techniques) {
            if (!techniqueFilter.empty() && std::find(techniqueFilter.begin(), techniqueFilter.end(),
                                                      technique.name) == techniqueFilter.end())
                continue;
            std::map<std::string, double> measured;
            std::vector<std::string> declarationErrors;
            const std::map<std::string, Declaration> known =
                expectedFailures(*effect->visibility, technique.name, declarationErrors);
            for (const auto& [name, declaration] : known)
                if (!runtime::makeStressCase(name))
                    declarationErrors.push_back("StressExpectedFailures of '" + technique.name +
                                                "' names no case '" + name + "' (shadowfx stress --list)");
            for (const std::string& error : declarationErrors)
                std::cerr << effectName << ": " << error << "\n";
            anyFailed = anyFailed || !declarationErrors.empty();
            for (const std::string& name : ordered) {
                std::cerr << "stress: " << effectName << " " << technique.name << " " << name << "\n";
                const CaseTruth& truth = truths.at(name);
                Outcome o = runCase(*renderer, effect->exposesVisibility, technique.name, truth, width,
                                    height, mapSize, sink);
                o.effect = effectName;
                if (o.misclassified) measured[name] = *o.misclassified;
                if (auto it = measured.find(truth.stressCase.ordinary); it != measured.end())
                    o.ordinary = it->second;
                if (auto it = uniformError.find(name); it != uniformError.end()) o.uniform = it->second;
                judge(o);
                if (!o.pass && o.errorImage.width > 0) {
                    const std::filesystem::path image = outDir / "errors" /
                                                        (std::filesystem::path(path).stem().string() + "." +
                                                         technique.name + "." + name + ".png");
                    std::error_code ignored;
                    std::filesystem::create_directories(image.parent_path(), ignored);
                    std::string error;
                    if (!runtime::writePng(o.errorImage, image.string(), error))
                        std::cerr << "shadowfx stress: " << error << "\n";
                }
                o.errorImage = {};
                if (auto it = known.find(name); it != known.end()) {
                    o.expectedFailure = true;
                    o.excused = it->second.criteria;
                    o.expectedBecause = it->second.because;
                }
                // Ordinary cases the user did not ask for ran only as references: their failures count,
                // an xpass of theirs is not judged.
                const bool requested = std::find(caseNames.begin(), caseNames.end(), name) != caseNames.end();
                const std::string result = o.result();
                anyFailed = anyFailed || result == "FAIL" || (strict && requested && result == "xpass");
                if (requested) outcomes.push_back(o);
            }
        }
    }

    printTable(std::cout, outcomes, truths, false);

    Json cases = Json::array();
    for (const std::string& name : ordered) {
        const CaseTruth& t = truths.at(name);
        cases.push_back(Json{{"name", name},
                             {"description", t.stressCase.description},
                             {"ordinary", t.stressCase.ordinary},
                             {"frames", t.frames.size()},
                             {"receiver_pixels", t.frames.front().receiverCount},
                             {"outside_light_volume", t.outsideLightVolume},
                             {"max_footprint", t.maxFootprint},
                             {"p95_footprint", t.p95Footprint},
                             {"uniform_misclassified_percent",
                              uniformError.count(name) ? Json(uniformError.at(name)) : Json(nullptr)}});
    }
    Json results = Json::array();
    for (const Outcome& o : outcomes)
        results.push_back(Json{{"effect", o.effect},
                               {"technique", o.technique},
                               {"case", o.caseName},
                               {"pass", o.pass},
                               {"result", o.result()},
                               {"expected_failure", o.expectedFailure},
                               {"excused_criteria", criterionNames(o.excused)},
                               {"reasons", o.reasons},
                               {"failed_criteria", criterionNames(o.failed)},
                               {"misclassified_percent", optionalJson(o.misclassified)},
                               {"false_shadow_percent", o.falseShadow},
                               {"false_light_percent", o.falseLight},
                               {"ordinary_percent", optionalJson(o.ordinary)},
                               {"uniform_percent", optionalJson(o.uniform)},
                               {"shimmer_mean_percent", optionalJson(o.shimmerMean)},
                               {"shimmer_max_percent", optionalJson(o.shimmerMax)},
                               {"max_footprint", optionalJson(o.maxFootprint)},
                               {"p95_footprint", optionalJson(o.p95Footprint)},
                               {"receiver_pixels", o.receivers}});
    const Json document{{"renderer", context->renderer()},
                        {"width", width},
                        {"height", height},
                        {"map_size", mapSize},
                        {"criteria",
                         {{"ordinary_factor", kOrdinaryFactor},
                          {"ordinary_slack_points", kOrdinarySlack},
                          {"uniform_factor", kUniformFactor},
                          {"uniform_slack_points", kUniformSlack},
                          {"shimmer_limit_percent", kShimmerLimit}}},
                        {"cases", cases},
                        {"results", results}};
    std::ofstream(outDir / "stress.json") << document.dump(2) << "\n";
    std::ofstream report(outDir / "report.md");
    report << "# shadowfx stress\n\nRenderer: " << context->renderer() << ", " << width << "x" << height
           << ", shadow maps " << mapSize << "².\n";
    printTable(report, outcomes, truths, true);
    std::cerr << "stress: " << (outDir / "stress.json").string() << ", " << (outDir / "report.md").string()
              << "\n";
    return anyFailed ? 1 : 0;
}

}  // namespace shadowfx::cli
