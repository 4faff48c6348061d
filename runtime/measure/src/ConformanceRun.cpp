// ConformanceRun: see ConformanceRun.h.
//
// [SECTION] Expectations  the Expect* annotations of a technique
// [SECTION] Goldens       where a technique's golden image for a renderer lives, and --update
// [SECTION] Frame checks  NaN/Inf in render targets, blank or constant frames
// [SECTION] Runs          compile once, then per backend: ground truth per scene, render, check
#include <runtime/ConformanceRun.h>

#include <fx/EffectCompiler.h>
#include <fx/Preshader.h>
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
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

namespace runtime {

namespace {

using report::CheckOutcome;
using report::CheckRow;
using report::kBlankFrame;
using report::kWarnFraction;
using Outcome = report::CheckOutcome;

// ExpectScenes and per-scene bounds are comma-separated lists: "dual-l, teapot", "dual-l=0.25, teapot=0.12".
std::vector<std::string> commaSeparated(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

// [SECTION] Expectations

// A scene as the table and per-scene bounds name it: a scene file's stem, a built-in scene's name.
std::string sceneLabel(const std::string& scene) {
    return scene.size() > 5 && scene.compare(scene.size() - 5, 5, ".json") == 0
               ? std::filesystem::path(scene).stem().string()
               : scene;
}

// A bound for every scene, or one per scene where a technique's error differs by scene (a number, or a
// string "dual-l=0.25, teapot=0.12").
struct SceneBound {
    std::optional<double> everyScene;
    std::map<std::string, double> perScene;  // by scene label (a scene file's stem)

    bool declared() const { return everyScene || !perScene.empty(); }
    std::optional<double> forScene(const std::string& scene) const {
        if (everyScene) return everyScene;
        const auto found = perScene.find(scene);
        return found == perScene.end() ? std::nullopt : std::optional<double>(found->second);
    }
};

struct Expectations {
    std::vector<std::string> scenes{"boxes"};
    SceneBound misclassifiedBelow;    // percent of receiver pixels
    SceneBound penumbraMaeBelow;      // mean |visibility - truth| over the penumbra, area lights
    std::optional<float> areaRadius;  // light0's areaRadius for the penumbra check
    std::optional<int> mapSize;       // SHADOWFX_SHADOW_MAP_SIZE for the check's renders
    bool shadows = true;              // false: compile, render, non-blank and golden only
};

// Reads the Expect* annotations of `technique` (names case-insensitive, as annotation lookups are). A value
// of the wrong kind or an unknown Expect* name is an InvalidAnnotation error at the annotation; false then.
bool readExpectations(const fx::Technique& technique, Expectations& out, fx::DiagnosticSink& sink) {
    bool ok = true;
    // A misspelt expectation would silently check nothing.
    static const std::set<std::string> kKnown{"expectscenes",           "expectmisclassifiedbelow",
                                              "expectpenumbramaebelow", "expectarearadius",
                                              "expectmapsize",          "expectshadows"};
    for (const fx::Annotation& a : technique.annotations) {
        std::string lower = a.name;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower.rfind("expect", 0) == 0 && kKnown.count(lower) == 0) {
            sink.report(fx::DiagId::InvalidAnnotation, a.loc,
                        {a.name,
                         "not an expectation shadowfx check knows (ExpectScenes, ExpectMisclassifiedBelow, "
                         "ExpectPenumbraMaeBelow, ExpectAreaRadius, ExpectMapSize, ExpectShadows)"});
            ok = false;
        }
    }
    auto number = [&](const char* name) -> std::optional<double> {
        const fx::Annotation* a = technique.annotation(name);
        if (!a) return std::nullopt;
        const fx::TypeDesc scalar;  // float
        std::optional<fx::Value> value =
            a->value.kind == fx::Expr::Kind::String
                ? std::nullopt
                : fx::evaluate(
                      a->value, [](std::string_view) -> const fx::Value* { return nullptr; }, &scalar,
                      nullptr);
        if (!value || !std::isfinite(value->asFloat())) {
            sink.report(fx::DiagId::InvalidAnnotation, a->loc, {name, "expected a number"});
            ok = false;
            return std::nullopt;
        }
        return value->asFloat();
    };
    if (const fx::Annotation* a = technique.annotation("ExpectScenes")) {
        if (a->value.kind != fx::Expr::Kind::String || commaSeparated(a->value.text).empty()) {
            sink.report(fx::DiagId::InvalidAnnotation, a->loc,
                        {"ExpectScenes", "expected a string of comma-separated scene names or .json files"});
            ok = false;
        } else {
            out.scenes = commaSeparated(a->value.text);
            for (std::string& scene : out.scenes) {
                scene.erase(0, scene.find_first_not_of(" \t"));
                scene.erase(scene.find_last_not_of(" \t") + 1);
            }
        }
    }
    // A number, or "scene=bound, ..." naming each scene of ExpectScenes once (a misspelt or forgotten scene
    // would silently check nothing).
    auto bound = [&](const char* name) {
        SceneBound result;
        const fx::Annotation* a = technique.annotation(name);
        if (!a || a->value.kind != fx::Expr::Kind::String) {
            result.everyScene = number(name);
            return result;
        }
        auto invalid = [&](const std::string& why) {
            sink.report(fx::DiagId::InvalidAnnotation, a->loc, {name, why});
            ok = false;
            return SceneBound{};
        };
        for (std::string entry : commaSeparated(a->value.text)) {
            const size_t eq = entry.find('=');
            std::string scene = entry.substr(0, eq);
            scene.erase(0, scene.find_first_not_of(" \t"));
            scene.erase(scene.find_last_not_of(" \t") + 1);
            const std::string text = eq == std::string::npos ? "" : entry.substr(eq + 1);
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (scene.empty() || text.empty() || *end != '\0' || !std::isfinite(value))
                return invalid("expected a number, or per-scene bounds \"SCENE=BOUND, ...\", got '" + entry +
                               "'");
            const std::string label = sceneLabel(scene);
            if (std::none_of(out.scenes.begin(), out.scenes.end(),
                             [&](const std::string& listed) { return sceneLabel(listed) == label; }))
                return invalid("scene '" + scene + "' is not one of ExpectScenes");
            if (!result.perScene.emplace(label, value).second)
                return invalid("scene '" + scene + "' is given twice");
        }
        for (const std::string& listed : out.scenes)
            if (result.perScene.count(sceneLabel(listed)) == 0)
                return invalid("no bound for scene '" + listed + "' of ExpectScenes");
        return result;
    };
    out.misclassifiedBelow = bound("ExpectMisclassifiedBelow");
    out.penumbraMaeBelow = bound("ExpectPenumbraMaeBelow");
    if (std::optional<double> radius = number("ExpectAreaRadius")) {
        if (!(*radius > 0.0 && *radius < 1e6)) {
            sink.report(fx::DiagId::InvalidAnnotation, technique.annotation("ExpectAreaRadius")->loc,
                        {"ExpectAreaRadius", "expected a radius above 0"});
            ok = false;
        } else {
            out.areaRadius = static_cast<float>(*radius);
        }
    }
    if (std::optional<double> size = number("ExpectMapSize")) {
        if (*size < 1 || *size > 16384 || *size != std::floor(*size)) {
            sink.report(fx::DiagId::InvalidAnnotation, technique.annotation("ExpectMapSize")->loc,
                        {"ExpectMapSize", "expected an integer between 1 and 16384"});
            ok = false;
        } else {
            out.mapSize = static_cast<int>(*size);
        }
    }
    if (std::optional<double> shadows = number("ExpectShadows")) out.shadows = *shadows != 0.0;
    return ok;
}

// [SECTION] Goldens
//
// EFFECT_DIR/golden/EFFECT/renderer.txt names the renderer key the plain goldens were made with (its first
// line; the second records the full GL_RENDERER string). A technique's goldens are
// golden/EFFECT/TECHNIQUE/SCENE.png for that renderer and SCENE.KEY.png for any other renderer KEY; a
// renderer with neither is NOT_SUPPORTED (FAIL with --require-goldens). The key is the first word of
// GL_RENDERER in lower case ("llvmpipe (LLVM 15.0.6, 256 bits)" -> llvmpipe): OSMesa and EGL on Mesa's
// llvmpipe share one set.

std::string rendererKey(const std::string& glRenderer) {
    std::string key;
    for (char c : glRenderer) {
        if (std::isalnum(static_cast<unsigned char>(c))) {
            key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else if (!key.empty()) {
            break;
        }
    }
    return key.empty() ? "unknown" : key;
}

std::string safeName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    return text;
}

struct GoldenPlace {
    std::filesystem::path path;   // where the golden is or would be
    bool forThisRenderer = true;  // false: the renderer has no goldens (NOT_SUPPORTED)
    std::string note;             // why not
};

std::string readRendererKey(const std::filesystem::path& effectGoldens) {
    std::ifstream file(effectGoldens / "renderer.txt");
    std::string key;
    std::getline(file, key);
    key.erase(key.find_last_not_of(" \t\r") + 1);
    return key;
}

GoldenPlace findGolden(const std::filesystem::path& effectGoldens, const std::string& technique,
                       const std::string& scene, const std::string& key) {
    const std::filesystem::path folder = effectGoldens / safeName(technique);
    GoldenPlace place;
    place.path = folder / (safeName(scene) + "." + key + ".png");
    if (std::filesystem::exists(place.path)) return place;
    const std::string referenceKey = readRendererKey(effectGoldens);
    place.path = folder / (safeName(scene) + ".png");
    if (referenceKey.empty() || referenceKey == key) return place;  // missing renderer.txt: made for us
    place.forThisRenderer = false;
    place.note = "no goldens for renderer '" + key + "' (they were made with '" + referenceKey + "')";
    return place;
}

// Where --update writes: the plain name for the reference renderer (the first to write, recorded in
// renderer.txt), SCENE.KEY.png for any other.
std::filesystem::path goldenToWrite(const std::filesystem::path& effectGoldens, const std::string& technique,
                                    const std::string& scene, const std::string& key,
                                    const std::string& glRenderer) {
    std::string referenceKey = readRendererKey(effectGoldens);
    if (referenceKey.empty()) {
        std::filesystem::create_directories(effectGoldens);
        std::ofstream(effectGoldens / "renderer.txt") << key << "\n# made with: " << glRenderer << "\n";
        referenceKey = key;
    }
    const std::filesystem::path folder = effectGoldens / safeName(technique);
    std::filesystem::create_directories(folder);
    return folder / (safeName(scene) + (referenceKey == key ? "" : "." + key) + ".png");
}

// [SECTION] Frame checks

// The first render target holding NaN or Inf, as "render target NAME holds N NaN/Inf values"; "" if none
// does.
std::string nonFiniteTargets(const EffectRenderer& renderer) {
    const std::optional<NonFiniteTexels> found = findNonFiniteTexels(renderer, TextureScan::RenderTargets);
    if (!found) return "";
    return "render target " + found->texture + " holds " + std::to_string(found->count) + " NaN/Inf values";
}

// "" if the frame shows something; else why it is blank (beginning with report::kBlankFrame): one colour everywhere, or fewer than 0.1% of the
// pixels differ from the most common colour (the clear colour, in practice).
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

}  // namespace

ConformanceResult runConformance(const ConformanceOptions& o, const ConformanceLog& log) {
    const auto note = [&](const std::string& text) {
        if (log.note) log.note(text);
    };
    // Each distinct warning and error once; a failing step names its first error in its result.
    DiagnosticLog sink(log.diagnostic);
    const fx::ParseOptions& parseOptions = o.parseOptions;
    const std::vector<std::string>& techniqueFilter = o.techniques;
    Settings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.update = o.update;
    settings.requireGoldens = o.requireGoldens;
    settings.batching = o.batching;
    settings.sceneOverride = o.scenes;
    settings.outDir = o.outDir;
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
                plan.carriesExpectations =
                    plan.carriesExpectations ||
                    (a.name.size() > 6 && fx::equalsIgnoreCase(a.name.substr(0, 6), "Expect"));
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
            requests.push_back({path, defines, t.name});
            if (t.expect.shadows) {
                defines.emplace_back("SHADOWFX_VISIBILITY", "1");
                requests.push_back({path, defines, t.name});
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
