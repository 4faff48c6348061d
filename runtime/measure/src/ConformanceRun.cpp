// ConformanceRun: see ConformanceRun.h.
//
// [SECTION] Frame checks  NaN/Inf in render targets, blank or constant frames
// [SECTION] Runs          compile once, then per backend: ground truth per scene, render, check
#include <runtime/ConformanceRun.h>

#include "CheckExpectations.h"
#include "GoldenImages.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <report/NumberFormat.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GroundTruth.h>
#include <runtime/ImageCompare.h>
#include <runtime/NonFiniteScan.h>
#include <runtime/SceneFile.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/TruthCache.h>

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace runtime {

namespace {

using report::CheckOutcome;
using report::CheckRow;
using report::kBlankFrame;
using report::kWarnFraction;
using Outcome = report::CheckOutcome;

// [SECTION] Frame checks

// Whether an annotation of this name is one of check's expectations (ExpectScenes, ExpectMapSize, ...), read
// the same way from a source effect and from a compiled file.
bool namesExpectation(std::string_view name) {
    return name.size() > 6 && fx::equalsIgnoreCase(name.substr(0, 6), "Expect");
}

// The first render target holding NaN or Inf, as "render target NAME holds N NaN/Inf values"; "" if none
// does.
std::string nonFiniteTargets(const EffectRenderer& renderer) {
    const std::optional<NonFiniteTexels> found = findNonFiniteTexels(renderer, TextureScan::RenderTargets);
    if (!found) return "";
    return "render target " + found->texture + " holds " + std::to_string(found->count) + " NaN/Inf values";
}

// "" if the frame shows something; else why it is blank (beginning with report::kBlankFrame): one colour
// everywhere, or fewer than 0.1% of the pixels differ from the most common colour (the clear colour, in
// practice).
std::string blankness(const FrameImage& frame) {
    std::unordered_map<uint32_t, size_t> counts;
    const size_t pixels = static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height);
    for (size_t i = 0; i < pixels; ++i) {
        const uint8_t* p = &frame.rgba[i * 4];
        ++counts[static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
                 static_cast<uint32_t>(p[2]) << 16];
    }
    if (counts.size() <= 1) return std::string(kBlankFrame) + "one constant colour";
    size_t dominant = 0;
    for (const auto& entry : counts) dominant = std::max(dominant, entry.second);
    const size_t others = pixels - dominant;
    if (others * 1000 < pixels)
        return std::string(kBlankFrame) + "blank: only " + std::to_string(others) + " of " +
               std::to_string(pixels) + " pixels differ from its most common colour";
    return "";
}

// [SECTION] Runs

struct Variants {
    std::shared_ptr<fx::CompiledEffect> shaded;
    std::shared_ptr<fx::CompiledEffect> visibility;  // with SHADOWFX_VISIBILITY
    bool exposesVisibility = false;
    // Read from a compiled effect file: the one variant it holds, so no SHADOWFX_VISIBILITY variant.
    bool fromCompiledFile = false;
};

struct TechniquePlan {
    std::string name;
    Expectations expect;
    Variants variants;
};

struct EffectPlan {
    std::string path;
    std::string name;               // stem
    std::filesystem::path goldens;  // EFFECT_DIR/golden/EFFECT
    std::vector<TechniquePlan> techniques;
    // False for an effect from elsewhere (an FX Composer library): no Expect* annotation and no goldens.
    // Its techniques get the render checks only; shadow quality and goldens are NOT_SUPPORTED.
    bool carriesExpectations = true;
};

// A scene with the truths the checks need: `hard` for ExpectMisclassifiedBelow (the light as a point), and
// for an area light the soft one in SceneTruth::truth.
struct CheckScene {
    SceneTruth measured;
    GroundTruth hard;
    bool soft = false;
    std::string error;  // why the scene could not be loaded or measured
};

// A scene name as ExpectScenes or --scenes give it: built-in, or a .json file relative to the effect's
// folder, else to the working directory.
std::string resolveScene(const std::string& scene, const std::filesystem::path& effectDir) {
    if (scene.size() < 5 || scene.compare(scene.size() - 5, 5, ".json") != 0) return scene;
    const std::filesystem::path nextToEffect = effectDir / scene;
    if (std::filesystem::path(scene).is_relative() && std::filesystem::exists(nextToEffect))
        return nextToEffect.string();
    return scene;
}

struct Settings {
    int width = 320;
    int height = 240;
    bool update = false;
    bool requireGoldens = false;
    bool batching = true;
    std::vector<std::string> sceneOverride;
    std::optional<float> areaRadius;  // --area-radius: the penumbra checks' light size, over ExpectAreaRadius
    std::filesystem::path outDir;
    GroundTruthOptions truthOptions;
    std::optional<TruthCache> truthCache;  // --truth-cache
    FuzzyCompareOptions compare;
    std::shared_ptr<const fx::HostFile> host;  // --host
};

class Checker {
public:
    Checker(const Settings& settings, DiagnosticLog& sink, std::function<void(const std::string&)> note)
        : mSettings(settings), mSink(sink), mNote(std::move(note)) {}

    std::vector<CheckRow>& results() { return mResults; }

    void add(std::string backend, const std::string& effect, std::string technique, std::string scene,
             std::string check, Outcome outcome, std::string detail) {
        mResults.push_back(CheckRow{std::move(backend), effect, std::move(technique), std::move(scene),
                                    std::move(check), outcome, std::move(detail)});
    }

    // False if the backend creates no context: its rows are NOT_SUPPORTED, or FAIL where the user named
    // the backend (`required`).
    bool runBackend(Backend backend, bool required, const std::vector<EffectPlan>& effects) {
        const std::string backendLabel(backendName(backend));
        ContextOptions contextOptions;
        contextOptions.backend = backend;
        std::string contextError;
        std::unique_ptr<GlContext> context = createContext(contextOptions, contextError);
        if (!context) {
            for (const EffectPlan& effect : effects)
                add(backendLabel, effect.name, "-", "-", "backend",
                    required ? Outcome::Fail : Outcome::NotSupported, contextError);
            return false;
        }
        const std::string glRenderer = context->renderer();
        const std::string key = rendererKey(glRenderer);
        mNote(backendLabel + ": " + glRenderer);
        // By resolved name and the areaRadius given to its lights (-1: as the scene declares it), this
        // context's.
        std::map<std::pair<std::string, float>, std::unique_ptr<CheckScene>> scenes;
        const auto measured = [&](const std::string& resolved, std::optional<float> areaRadius) {
            std::unique_ptr<CheckScene>& scene = scenes[{resolved, areaRadius.value_or(-1.0f)}];
            if (!scene) scene = measureScene(resolved, areaRadius);
            return scene.get();
        };

        for (const EffectPlan& effect : effects) {
            for (const TechniquePlan& technique : effect.techniques) {
                if (!technique.variants.shaded) continue;  // did not compile: reported already
                mSink.mark();
                std::unique_ptr<EffectRenderer> shaded =
                    EffectRenderer::create(technique.variants.shaded, mSink);
                std::unique_ptr<EffectRenderer> visibility;
                if (shaded && technique.expect.shadows && technique.variants.exposesVisibility)
                    visibility = EffectRenderer::create(technique.variants.visibility, mSink);
                if (mSettings.host && shaded && !shaded->setHostFile(mSettings.host, mSink)) shaded.reset();
                if (mSettings.host && visibility && !visibility->setHostFile(mSettings.host, mSink))
                    shaded.reset();
                if (!shaded || mSink.failed()) {
                    add(backendLabel, effect.name, technique.name, "-", "link", Outcome::Fail,
                        mSink.firstError("the effect's programs do not link"));
                    continue;
                }
                const std::filesystem::path effectDir = std::filesystem::path(effect.path).parent_path();
                const std::vector<std::string>& names =
                    mSettings.sceneOverride.empty() ? technique.expect.scenes : mSettings.sceneOverride;
                for (const std::string& sceneName : names) {
                    const std::string resolved = resolveScene(sceneName, effectDir);
                    const CheckScene* scene = measured(resolved, std::nullopt);
                    // The penumbra bound holds for the light size it was measured at: the scene with that
                    // areaRadius, its own where neither the command nor the technique gives one.
                    const std::optional<float> areaRadius =
                        mSettings.areaRadius ? mSettings.areaRadius : technique.expect.areaRadius;
                    const CheckScene* penumbraScene =
                        technique.expect.penumbraMaeBelow.declared() && areaRadius
                            ? measured(resolved, areaRadius)
                            : scene;
                    checkScene(backendLabel, key, glRenderer, effect, technique, sceneLabel(sceneName),
                               *scene, *penumbraScene, *shaded, visibility.get());
                }
            }
        }
        return true;
    }

private:
    // `areaRadius`: every light gets it, for the penumbra check alone (no hard truth is cast then).
    std::unique_ptr<CheckScene> measureScene(const std::string& name, std::optional<float> areaRadius) {
        auto scene = std::make_unique<CheckScene>();
        mSink.mark();
        std::optional<Scene> loaded = loadScene(name, mSink);
        if (!loaded) {
            scene->error = mSink.firstError("no scene '" + name + "'");
            return scene;
        }
        if (areaRadius)
            for (Light& light : loaded->lights) light.areaRadius = *areaRadius;
        const TruthCache* cache = mSettings.truthCache ? &*mSettings.truthCache : nullptr;
        if (!measureSceneTruth(scene->measured, std::move(*loaded), mSettings.width, mSettings.height,
                               mSettings.truthOptions, mSink, scene->error, cache))
            return scene;
        const SceneTruth& t = scene->measured;
        if (!t.cacheNote.empty()) mNote("--truth-cache: " + t.cacheNote);
        scene->soft = t.light->areaRadius > 0.0f;
        if (areaRadius) return scene;
        if (scene->soft) {
            Light point = *t.light;
            point.areaRadius = 0.0f;
            bool cached = false;
            std::string note;
            scene->hard =
                castOrReadTruth(t.scene, point, t.gbuffer, mSettings.truthOptions, cache, cached, note);
            if (!note.empty()) mNote("--truth-cache: " + note);
        } else {
            scene->hard = t.truth;
        }
        return scene;
    }

    void checkScene(const std::string& backend, const std::string& key, const std::string& glRenderer,
                    const EffectPlan& effect, const TechniquePlan& technique, const std::string& sceneName,
                    const CheckScene& scene, const CheckScene& penumbraScene, EffectRenderer& shaded,
                    EffectRenderer* visibility) {
        removeStaleImages(effect.name, technique.name, sceneName);
        const size_t firstRow = mResults.size();
        auto row = [&](const std::string& check, Outcome outcome, std::string detail) {
            add(backend, effect.name, technique.name, sceneName, check, outcome, std::move(detail));
        };
        if (!scene.error.empty()) {
            row("render", Outcome::Fail, scene.error);
            return;
        }
        const SceneTruth& t = scene.measured;
        FrameOptions frameOptions;
        frameOptions.width = mSettings.width;
        frameOptions.height = mSettings.height;
        frameOptions.technique = technique.name;
        frameOptions.batching = mSettings.batching;

        // Compiles, links and renders without GL errors; no NaN in any target; not blank.
        mSink.mark();
        if (!shaded.render(t.scene, frameOptions, mSink) || mSink.failed()) {
            row("render", Outcome::Fail, mSink.firstError("the frame could not be rendered"));
            return;
        }
        const FrameImage frame = shaded.readFrame();
        std::string problem = nonFiniteTargets(shaded);
        if (problem.empty()) problem = blankness(frame);
        row("render", problem.empty() ? Outcome::Pass : Outcome::Fail,
            problem.empty() ? "no GL errors, targets finite, frame not blank" : problem);

        // Expectations against the ground truth.
        std::optional<VisibilityScore> hardScore, softScore;
        const Expectations& expect = technique.expect;
        const std::optional<double> misclassifiedBelow = expect.misclassifiedBelow.forScene(sceneName);
        const std::optional<double> penumbraMaeBelow = expect.penumbraMaeBelow.forScene(sceneName);
        if (expect.shadows && effect.carriesExpectations) {
            const bool expects = expect.misclassifiedBelow.declared() || expect.penumbraMaeBelow.declared();
            if (!expects) {
                row("misclassified", Outcome::QualityWarning,
                    "the technique declares no ExpectMisclassifiedBelow (or ExpectShadows = false)");
            } else if (technique.variants.fromCompiledFile) {
                row("expectations", Outcome::NotSupported,
                    "a compiled effect file holds the variant it was compiled with, not the "
                    "SHADOWFX_VISIBILITY variant the scores need: check the .fx file to score its shadows");
            } else if (!visibility) {
                row("expectations", Outcome::Fail,
                    "expectations declared, but the effect's pixel shaders ignore SHADOWFX_VISIBILITY "
                    "(docs/scoring.md, \"Measurement hooks\")");
            } else {
                mSink.mark();
                hardScore = scoreVisibility(*visibility, t, scene.hard, frameOptions, mSink);
                if (penumbraMaeBelow && penumbraScene.error.empty() && penumbraScene.soft && hardScore)
                    softScore = scoreVisibility(*visibility, penumbraScene.measured,
                                                penumbraScene.measured.truth, frameOptions, mSink);
                if (!hardScore || mSink.failed()) {
                    row("expectations", Outcome::Fail,
                        mSink.firstError("the SHADOWFX_VISIBILITY variant could not be rendered"));
                    hardScore.reset();
                }
            }
            // Per-scene bounds name the scenes of ExpectScenes; --scenes may check others.
            const auto noBoundHere = [&](const char* check, const char* annotation) {
                row(check, Outcome::NotSupported,
                    std::string(annotation) + " gives bounds for other scenes, none for this one");
            };
            if (hardScore && expect.misclassifiedBelow.declared() && !misclassifiedBelow)
                noBoundHere("misclassified", "ExpectMisclassifiedBelow");
            if (hardScore && misclassifiedBelow) {
                const ShadowErrors& e = hardScore->errors;
                row("misclassified", report::judgeBelow(e.misclassifiedPercent, *misclassifiedBelow),
                    report::formatFixed(e.misclassifiedPercent, 3) + " % misclassified, expected below " +
                        report::formatFixed(*misclassifiedBelow, 3) + " % (false shadow " +
                        report::formatFixed(e.falseShadowPercent, 3) + " %, false light " +
                        report::formatFixed(e.falseLightPercent, 3) + " %, " +
                        std::to_string(e.receiverPixels) + " receiver pixels)");
            }
            if (hardScore && expect.penumbraMaeBelow.declared() && !penumbraMaeBelow)
                noBoundHere("penumbra", "ExpectPenumbraMaeBelow");
            if (hardScore && penumbraMaeBelow) {
                if (!penumbraScene.error.empty()) {
                    row("penumbra", Outcome::Fail, penumbraScene.error);
                } else if (!penumbraScene.soft) {
                    row("penumbra", Outcome::NotSupported,
                        "the scene's light has no areaRadius: no penumbra to measure (declare "
                        "ExpectAreaRadius "
                        "or give --area-radius; docs/scoring.md)");
                } else if (!softScore) {
                    row("penumbra", Outcome::Fail,
                        mSink.firstError("the SHADOWFX_VISIBILITY variant could not be rendered"));
                } else if (softScore->errors.penumbraPixels == 0) {
                    row("penumbra", Outcome::NotSupported, "no receiver pixel of the scene is in penumbra");
                } else {
                    // The penumbra MAE, as bench reports it: over all receivers the fully lit and umbra
                    // pixels would hide how well the penumbra itself is drawn.
                    const double mae = softScore->errors.penumbraMeanAbsoluteError;
                    // A bound that a frame without shadows meets checks nothing.
                    const SceneTruth& soft = penumbraScene.measured;
                    const double blankMae =
                        compareVisibility(soft.truth.visibility,
                                          std::vector<float>(soft.truth.visibility.size(), 1.0f),
                                          soft.receivers)
                            .penumbraMeanAbsoluteError;
                    if (!(*penumbraMaeBelow < blankMae)) {
                        row("penumbra", Outcome::Fail,
                            "the bound " + report::formatFixed(*penumbraMaeBelow, 4) +
                                " passes a frame without shadows (penumbra MAE " +
                                report::formatFixed(blankMae, 4) + "): it checks nothing");
                    } else {
                        row("penumbra", report::judgeBelow(mae, *penumbraMaeBelow),
                            "penumbra MAE " + report::formatFixed(mae, 4) + ", expected below " +
                                report::formatFixed(*penumbraMaeBelow, 4) + " (" +
                                std::to_string(softScore->errors.penumbraPixels) +
                                " penumbra pixels, areaRadius " +
                                report::formatFixed(penumbraScene.measured.light->areaRadius, 3) + ", " +
                                std::to_string(penumbraScene.measured.truth.samplesPerPixel) +
                                " light samples per pixel)");
                    }
                }
            }
        }

        // The golden image. --update writes it (once per run: a second backend of the same renderer then
        // compares against what the first wrote).
        std::optional<FrameImage> golden;
        std::optional<FuzzyCompareResult> comparison;
        bool compare = true;
        if (mSettings.update) {
            const std::string path =
                goldenToWrite(effect.goldens, technique.name, sceneName, key, glRenderer).string();
            if (mWritten.insert(path).second) {
                std::string error;
                const bool written = writePng(frame, path, error);
                row("golden", written ? Outcome::Pass : Outcome::Fail, written ? "written " + path : error);
                compare = false;
            }
        }
        if (compare) {
            const GoldenPlace place = findGolden(effect.goldens, technique.name, sceneName, key);
            std::string error;
            if (!effect.carriesExpectations) {
                row("golden", mSettings.requireGoldens ? Outcome::Fail : Outcome::NotSupported,
                    "the effect has no goldens (" + effect.goldens.string() + ")");
            } else if (!place.forThisRenderer) {
                row("golden", mSettings.requireGoldens ? Outcome::Fail : Outcome::NotSupported, place.note);
            } else if (!std::filesystem::exists(effect.goldens)) {
                // A new effect: no renderer has goldens yet, which is this renderer having none.
                row("golden", mSettings.requireGoldens ? Outcome::Fail : Outcome::NotSupported,
                    "no goldens yet: shadowfx check --update writes them to " + effect.goldens.string());
            } else if (!std::filesystem::exists(place.path)) {
                row("golden", Outcome::Fail,
                    "missing golden " + place.path.string() + " (write it with shadowfx check --update)");
            } else if (!(golden = readPng(place.path.string(), error))) {
                row("golden", Outcome::Fail, error);
            } else {
                comparison = fuzzyCompare(*golden, frame, mSettings.compare);
                const double bound = mSettings.compare.threshold;
                Outcome outcome = comparison->matches ? Outcome::Pass : Outcome::Fail;
                if (outcome == Outcome::Pass && comparison->failingFraction > kWarnFraction * bound)
                    outcome = Outcome::QualityWarning;
                const std::string detail =
                    !comparison->sameSize
                        ? "golden is " + std::to_string(golden->width) + "x" +
                              std::to_string(golden->height) + ", the frame " + std::to_string(frame.width) +
                              "x" + std::to_string(frame.height)
                        : std::to_string(comparison->failingPixels) + " pixels differ (" +
                              report::formatFixed(100.0 * comparison->failingFraction, 3) + " %, at most " +
                              report::formatFixed(100.0 * bound, 3) + " % allowed), max error " +
                              report::formatFixed(comparison->maxError, 3);
                row("golden", outcome, detail + " vs " + place.path.string());
            }
        }

        bool failed = false;
        for (size_t i = firstRow; i < mResults.size(); ++i)
            failed = failed || mResults[i].outcome == Outcome::Fail;
        if (failed)
            writeFailureImages(effect.name, technique.name, sceneName, frame, golden, comparison, t, scene,
                               hardScore);
    }

    std::string imageBase(const std::string& effect, const std::string& technique,
                          const std::string& scene) const {
        return (mSettings.outDir / safeName(effect) / safeName(technique) / safeName(scene)).string();
    }

    // Images an earlier run left for this scene would read as this run's failure.
    void removeStaleImages(const std::string& effect, const std::string& technique,
                           const std::string& scene) {
        const std::string base = imageBase(effect, technique, scene);
        if (mImagesWritten.count(base) > 0) return;
        std::error_code ignored;
        for (const char* kind : {".result.png", ".reference.png", ".errormask.png"})
            std::filesystem::remove(base + kind, ignored);
    }

    // OUT/EFFECT/TECHNIQUE/SCENE.{result,reference,errormask}.png, once per run (the first failing backend):
    // the errormask is the golden comparison's when it failed, else the shadow error image (false shadow
    // red, false light blue).
    void writeFailureImages(const std::string& effect, const std::string& technique, const std::string& scene,
                            const FrameImage& frame, const std::optional<FrameImage>& golden,
                            const std::optional<FuzzyCompareResult>& comparison, const SceneTruth& t,
                            const CheckScene& checkScene, const std::optional<VisibilityScore>& score) {
        const std::string base = imageBase(effect, technique, scene);
        if (!mImagesWritten.insert(base).second) return;
        std::error_code fsError;
        std::filesystem::create_directories(std::filesystem::path(base).parent_path(), fsError);
        std::string error;
        bool ok = writePng(frame, base + ".result.png", error);
        if (ok && golden) ok = writePng(*golden, base + ".reference.png", error);
        if (ok && comparison && !comparison->matches && comparison->sameSize) {
            ok = writePng(comparison->errorMask, base + ".errormask.png", error);
        } else if (ok && score) {
            ok = writePng(errorImage(frame, checkScene.hard.visibility, score->visibility, t.receivers),
                          base + ".errormask.png", error);
        }
        if (!ok) mNote(error);
        mNote("images of the failure: " + base + ".*.png");
    }

    const Settings& mSettings;
    DiagnosticLog& mSink;
    std::function<void(const std::string&)> mNote;
    std::vector<CheckRow> mResults;
    std::set<std::string> mWritten;        // goldens written by this --update run
    std::set<std::string> mImagesWritten;  // failure images written by this run
};

// A compiled effect file's techniques, with the effect it holds as their shaded variant: it renders and
// meets goldens as it stands, but the scores need the SHADOWFX_VISIBILITY variant, which only its source
// compiles. The techniques (or the file that failed to read) to count as matched.
size_t planCompiledFile(const std::string& path, const std::vector<std::string>& techniqueFilter,
                        Checker& checker, DiagnosticLog& sink, EffectPlan& plan) {
    std::shared_ptr<fx::CompiledEffect> compiled = fx::readCompiledEffectFile(path, sink);
    if (!compiled || sink.failed()) {
        checker.add("-", plan.name, "-", "-", "compile", Outcome::Fail,
                    sink.firstError("cannot read " + path));
        return 1;
    }
    if (compiled->techniques.empty()) {
        sink.report(fx::DiagId::NoTechniques, fx::SourceLoc{path, 1, 1});
        checker.add("-", plan.name, "-", "-", "compile", Outcome::Fail, sink.firstError(""));
        return 1;
    }
    plan.carriesExpectations = std::filesystem::exists(plan.goldens);
    for (const fx::CompiledTechnique& technique : compiled->techniques)
        for (const fx::AnnotationValue& a : technique.annotations)
            plan.carriesExpectations = plan.carriesExpectations || namesExpectation(a.name);
    for (const fx::CompiledTechnique& technique : compiled->techniques) {
        if (!techniqueFilter.empty() && std::find(techniqueFilter.begin(), techniqueFilter.end(),
                                                  technique.name) == techniqueFilter.end())
            continue;
        TechniquePlan& t = plan.techniques.emplace_back();
        t.name = technique.name;
        sink.mark();
        if (!readExpectations(technique, t.expect, sink)) {
            checker.add("-", plan.name, t.name, "-", "expectations", Outcome::Fail, sink.firstError(""));
            continue;
        }
        t.variants.shaded = compiled;
        t.variants.fromCompiledFile = true;
    }
    return plan.techniques.size();
}

}  // namespace

ConformanceResult runConformance(const ConformanceOptions& o, const ConformanceLog& log) {
    const auto note = [&](const std::string& text) {
        if (log.note) log.note(text);
    };
    // Each distinct warning and error once; a failing step names its first error in its result.
    DiagnosticLog sink(log.diagnostic);
    const fx::ParseOptions& parseOptions = o.parseOptions;
    // A host file draws one frame whatever the technique, from the techniques it names: the whole effect
    // compiles, and one check named after what draws the frame checks it, as bench runs it.
    const std::vector<std::string> techniqueFilter =
        o.host && o.techniques.empty() && !o.host->frame.empty()
            ? std::vector<std::string>{o.host->frame.back().technique}
            : o.techniques;
    Settings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.update = o.update;
    settings.requireGoldens = o.requireGoldens;
    settings.batching = o.batching;
    settings.sceneOverride = o.scenes;
    settings.outDir = o.outDir;
    settings.host = o.host;
    settings.truthOptions.areaSamples = o.areaSamples;
    if (!o.truthCacheDir.empty()) settings.truthCache.emplace(o.truthCacheDir);
    settings.areaRadius = o.areaRadius;
    ConformanceResult result;

    // Parse and compile everything first (no GL needed): compile errors are FAILs with their location.
    Checker checker(settings, sink, note);
    std::vector<EffectPlan> plans;
    struct PendingCompile {
        size_t plan, technique;  // indices into plans and its techniques
        size_t request;          // the shaded variant's; the visibility variant's follows when expected
    };
    std::vector<PendingCompile> pending;
    std::vector<VariantRequest> requests;
    size_t matched = 0;  // techniques to check, plus effects that failed to parse
    for (const std::string& path : o.effects) {
        EffectPlan plan;
        plan.path = path;
        plan.name = std::filesystem::path(path).stem().string();
        plan.goldens = std::filesystem::path(path).parent_path() / "golden" / plan.name;
        sink.mark();
        if (fx::isCompiledEffectFile(path)) {
            matched += planCompiledFile(path, techniqueFilter, checker, sink, plan);
            if (!plan.techniques.empty()) plans.push_back(std::move(plan));
            continue;
        }
        std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, parseOptions, sink);
        if (!effect || sink.failed()) {
            checker.add("-", plan.name, "-", "-", "compile", Outcome::Fail,
                        sink.firstError("cannot parse " + path));
            ++matched;  // reported: --technique cannot be judged on an effect that does not parse
            continue;
        }
        if (effect->techniques.empty()) {  // it compiles (an effect pool's parameters), but draws nothing
            sink.report(fx::DiagId::NoTechniques, fx::SourceLoc{path, 1, 1});
            checker.add("-", plan.name, "-", "-", "compile", Outcome::Fail, sink.firstError(""));
            ++matched;
            continue;
        }
        plan.carriesExpectations = std::filesystem::exists(plan.goldens);
        for (const fx::Technique& technique : effect->techniques)
            for (const fx::Annotation& a : technique.annotations)
                plan.carriesExpectations = plan.carriesExpectations || namesExpectation(a.name);
        for (const fx::Technique& technique : effect->techniques) {
            if (!techniqueFilter.empty() && std::find(techniqueFilter.begin(), techniqueFilter.end(),
                                                      technique.name) == techniqueFilter.end())
                continue;
            TechniquePlan& t = plan.techniques.emplace_back();
            t.name = technique.name;
            sink.mark();
            if (!readExpectations(technique, t.expect, sink)) {
                checker.add("-", plan.name, t.name, "-", "expectations", Outcome::Fail, sink.firstError(""));
                continue;
            }
            std::vector<std::pair<std::string, std::string>> defines;
            if (t.expect.mapSize)
                defines.emplace_back("SHADOWFX_SHADOW_MAP_SIZE", std::to_string(*t.expect.mapSize));
            pending.push_back({plans.size(), plan.techniques.size() - 1, requests.size()});
            const std::string kept = o.host ? "" : t.name;  // the technique compiled alone
            requests.push_back({path, defines, kept});
            if (t.expect.shadows) {
                defines.emplace_back("SHADOWFX_VISIBILITY", "1");
                requests.push_back({path, defines, kept});
            }
        }
        matched += plan.techniques.size();
        plans.push_back(std::move(plan));
    }
    // Every variant of every effect compiles concurrently across the compile workers; the results are
    // judged in the order above.
    std::vector<CompiledVariant> compiled = compileVariants(requests, parseOptions);
    for (const PendingCompile& p : pending) {
        TechniquePlan& t = plans[p.plan].techniques[p.technique];
        sink.mark();
        forward(compiled[p.request].diagnostics, sink);
        t.variants.shaded = compiled[p.request].effect;
        if (t.variants.shaded && !sink.failed() && t.expect.shadows) {
            forward(compiled[p.request + 1].diagnostics, sink);
            t.variants.visibility = compiled[p.request + 1].effect;
            t.variants.exposesVisibility =
                t.variants.visibility && !sameFragmentShaders(*t.variants.shaded, *t.variants.visibility);
        }
        if (!t.variants.shaded || sink.failed()) {
            t.variants.shaded.reset();
            checker.add("-", plans[p.plan].name, t.name, "-", "compile", Outcome::Fail,
                        sink.firstError("the technique does not compile"));
        }
    }
    if (matched == 0 && !techniqueFilter.empty()) {
        result.noTechniqueMatches = true;
        return result;
    }

    for (Backend backend : o.backends)
        result.anyContext = checker.runBackend(backend, o.backendsNamed, plans) || result.anyContext;
    result.rows = std::move(checker.results());
    return result;
}

}  // namespace runtime
