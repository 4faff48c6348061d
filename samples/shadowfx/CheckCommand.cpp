// CheckCommand: `shadowfx check`.
//
// [SECTION] Results       outcomes and one row per (backend, effect, technique, scene, check)
// [SECTION] Expectations  the Expect* annotations of a technique
// [SECTION] Goldens       where a technique's golden image for a renderer lives, and --update
// [SECTION] Frame checks  NaN/Inf in render targets, blank or constant frames
// [SECTION] Output        the table, JUnit XML, the images of a failure
// [SECTION] Runs          compile once, then per backend: ground truth per scene, render, check
//
// Outcomes: PASS; QUALITY_WARNING (passes, but a measured value is above 80% of its bound, or the technique
// of a shadowing effect declares no ExpectMisclassifiedBelow); NOT_SUPPORTED (the check cannot run here: a
// backend that creates no context, a penumbra bound on a scene without an area light, no goldens for this
// renderer, an effect from elsewhere that carries no expectations and no goldens); FAIL. Only FAIL makes the
// exit status 1. An effect library ported from FX Composer thus gets one table of compile, link, GL-error,
// NaN and blank-frame results per technique (`shadowfx check lib/*.fx --junit out.xml`), and one line per
// effect: drawn, blank or failed, with a summary line.
#include "CheckCommand.h"
#include <report/XmlText.h>

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <fx/Preshader.h>
#include <fx/RenderStates.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlContext.h>
#include <runtime/GroundTruth.h>
#include <runtime/ImageCompare.h>
#include <runtime/SceneFile.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/NonFiniteScan.h>
#include <report/NumberFormat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <string_view>
#include <set>
#include <sstream>
#include <unordered_map>

namespace shadowfx::cli {

const char* const kCheckUsage =
    "usage: shadowfx check EFFECT.fx [EFFECT.fx ...] [options]\n"
    "  --technique LIST      only these techniques (comma-separated or repeated; default: all)\n"
    "  --scenes LIST         scenes for every technique, overriding their ExpectScenes annotations\n"
    "                        (built-in names or scene .json files; default: ExpectScenes, else boxes)\n"
    "  --backend LIST        all, osmesa, egl or a comma-separated list (default all: each one that\n"
    "                        creates a context; one that cannot is NOT_SUPPORTED, a named one that\n"
    "                        cannot FAILs; no context at all exits 1)\n"
    "  --junit FILE          also write the results as JUnit XML\n"
    "  --out DIR             images of failures: "
    "DIR/EFFECT/TECHNIQUE/SCENE.{result,reference,errormask}.png\n"
    "                        (default out/check)\n"
    "  --update              write the golden images of this renderer instead of comparing (never in CI)\n"
    "  --require-goldens     a renderer without goldens FAILs instead of NOT_SUPPORTED\n"
    "  --width W, --height H frame size (default 320x240, the size goldens are made at)\n"
    "  --area-samples N      ground-truth light samples per pixel for area lights (default 256)\n"
    "  --truth-cache DIR     read each scene's ray-cast ground truth from DIR when it was cast before for\n"
    "                        the same inputs, else cast and store it there (docs/sharding.md)\n"
    "  --area-radius R       the penumbra checks give every scene's light this areaRadius, overriding\n"
    "                        ExpectAreaRadius (0: no area light, the penumbra rows NOT_SUPPORTED)\n"
    "  --list-techniques     print each effect's technique names, one per line, and exit\n"
    "  --no-batching         draw every object alone, not one instanced draw per mesh (the same images)\n"
    "Technique annotations read: string ExpectScenes, float ExpectMisclassifiedBelow (percent of receiver\n"
    "pixels, hard-shadow truth), float ExpectPenumbraMaeBelow (mean |error| over the penumbra of an area\n"
    "light), float ExpectAreaRadius (the light's areaRadius for the penumbra check), int ExpectMapSize,\n"
    "bool ExpectShadows (docs/scoring.md). A bound is a number for every scene or a string of per-scene\n"
    "bounds: \"dual-l=0.25, teapot=0.12\". Goldens:\n"
    "EFFECT_DIR/golden/EFFECT/TECHNIQUE/SCENE.png, written there by --update; an effect without that folder\n"
    "yet is NOT_SUPPORTED for goldens (docs/measurement.md).\n"
    "Exit status: 0 if nothing FAILs, 1 on any FAIL, 2 on usage errors.\n";

namespace {

// [SECTION] Results

enum class Outcome { Pass, QualityWarning, NotSupported, Fail };

const char* outcomeName(Outcome outcome) {
    switch (outcome) {
        case Outcome::Pass:
            return "PASS";
        case Outcome::QualityWarning:
            return "QUALITY_WARNING";
        case Outcome::NotSupported:
            return "NOT_SUPPORTED";
        case Outcome::Fail:
            return "FAIL";
    }
    return "?";
}

struct CheckResult {
    std::string backend;  // "osmesa", "egl", or "-" for checks before any backend (compile)
    std::string effect;   // the file's stem
    std::string technique;
    std::string scene;
    std::string check;  // render, misclassified, penumbra, golden, compile, expectations, backend
    Outcome outcome = Outcome::Pass;
    std::string detail;
};

// A measured value against its "below" bound: FAIL at or above it, QUALITY_WARNING above 80% of it.
constexpr double kWarnFraction = 0.8;
Outcome judge(double measured, double bound) {
    if (!(measured < bound)) return Outcome::Fail;  // NaN fails too
    return measured > kWarnFraction * bound ? Outcome::QualityWarning : Outcome::Pass;
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
        if (a->value.kind != fx::Expr::Kind::String || splitList(a->value.text).empty()) {
            sink.report(fx::DiagId::InvalidAnnotation, a->loc,
                        {"ExpectScenes", "expected a string of comma-separated scene names or .json files"});
            ok = false;
        } else {
            out.scenes = splitList(a->value.text);
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
        for (std::string entry : splitList(a->value.text)) {
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
std::string nonFiniteTargets(const runtime::EffectRenderer& renderer) {
    const std::optional<runtime::NonFiniteTexels> found =
        runtime::findNonFiniteTexels(renderer, runtime::TextureScan::RenderTargets);
    if (!found) return "";
    return "render target " + found->texture + " holds " + std::to_string(found->count) + " NaN/Inf values";
}

// How blankness() begins its answer: the effect summary tells a blank frame from a failure by it.
constexpr std::string_view kBlankFrame = "the frame is ";

// "" if the frame shows something; else why it is blank: one colour everywhere, or fewer than 0.1% of the
// pixels differ from the most common colour (the clear colour, in practice).
std::string blankness(const runtime::FrameImage& frame) {
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

// [SECTION] Output

// One line per effect, for a run over a library (`check lib/*.fx`): `drawn` when every frame it rendered
// shows something, `blank` with the first blank frame, `failed` with the first error that kept it from
// compiling or rendering; then `N effects: A drawn, B blank, C failed`. Expectations and goldens are the
// table's business: this says whether the effects draw at all.
void printEffectSummary(const std::vector<CheckResult>& results) {
    struct EffectStatus {
        std::string failure;  // technique: first compile or render error
        std::string blank;    // technique: first blank frame
    };
    std::vector<std::string> order;
    std::map<std::string, EffectStatus> status;
    for (const CheckResult& r : results) {
        if (!status.count(r.effect)) order.push_back(r.effect);
        EffectStatus& s = status[r.effect];
        if (r.outcome != Outcome::Fail || (r.check != "compile" && r.check != "render")) continue;
        std::string& slot = r.detail.rfind(kBlankFrame, 0) == 0 ? s.blank : s.failure;
        if (slot.empty()) slot = (r.technique == "-" ? "" : r.technique + ": ") + r.detail;
    }
    size_t drawn = 0, blank = 0, failed = 0;
    std::cout << "\n";
    for (const std::string& effect : order) {
        const EffectStatus& s = status[effect];
        if (!s.failure.empty()) {
            ++failed;
            std::cout << effect << ": failed: " << s.failure.substr(0, s.failure.find('\n')) << "\n";
        } else if (!s.blank.empty()) {
            ++blank;
            std::cout << effect << ": blank: " << s.blank << "\n";
        } else {
            ++drawn;
            std::cout << effect << ": drawn\n";
        }
    }
    std::cout << order.size() << (order.size() == 1 ? " effect: " : " effects: ") << drawn << " drawn, "
              << blank << " blank, " << failed << " failed\n";
}

void printTable(const std::vector<CheckResult>& results) {
    const std::vector<std::string> header{"RESULT", "BACKEND", "EFFECT", "TECHNIQUE",
                                          "SCENE",  "CHECK",   "DETAIL"};
    std::vector<size_t> widths(header.size());
    auto cells = [](const CheckResult& r) {
        return std::vector<std::string>{
            outcomeName(r.outcome), r.backend, r.effect, r.technique, r.scene, r.check, r.detail};
    };
    for (size_t c = 0; c < header.size(); ++c) widths[c] = header[c].size();
    for (const CheckResult& r : results) {
        const std::vector<std::string> row = cells(r);
        for (size_t c = 0; c + 1 < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    }
    auto print = [&](const std::vector<std::string>& row) {
        for (size_t c = 0; c < row.size(); ++c) {
            std::cout << row[c];
            if (c + 1 < row.size()) std::cout << std::string(widths[c] - row[c].size() + 2, ' ');
        }
        std::cout << "\n";
    };
    print(header);
    for (const CheckResult& r : results) print(cells(r));
}

// JUnit XML as Jenkins, GitLab and GitHub's test reporters read it: one <testsuite> per effect, one
// <testcase> per row (classname EFFECT.TECHNIQUE, name SCENE.CHECK[BACKEND]); FAIL is <failure>,
// NOT_SUPPORTED <skipped>, QUALITY_WARNING a passing case with the warning in <system-out>.
bool writeJunit(const std::string& path, const std::vector<CheckResult>& results) {
    std::vector<std::string> effects;
    for (const CheckResult& r : results)
        if (std::find(effects.begin(), effects.end(), r.effect) == effects.end()) effects.push_back(r.effect);
    auto count = [&](const std::string* effect, Outcome outcome) {
        return std::count_if(results.begin(), results.end(), [&](const CheckResult& r) {
            return (!effect || r.effect == *effect) && r.outcome == outcome;
        });
    };
    auto total = [&](const std::string* effect) {
        return std::count_if(results.begin(), results.end(),
                             [&](const CheckResult& r) { return !effect || r.effect == *effect; });
    };
    std::ofstream xml(path);
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml << "<testsuites name=\"shadowfx check\" tests=\"" << total(nullptr) << "\" failures=\""
        << count(nullptr, Outcome::Fail) << "\" skipped=\"" << count(nullptr, Outcome::NotSupported)
        << "\" errors=\"0\">\n";
    for (const std::string& effect : effects) {
        xml << "  <testsuite name=\"" << report::xmlEscape(effect) << "\" tests=\"" << total(&effect)
            << "\" failures=\"" << count(&effect, Outcome::Fail) << "\" skipped=\""
            << count(&effect, Outcome::NotSupported) << "\" errors=\"0\">\n";
        for (const CheckResult& r : results) {
            if (r.effect != effect) continue;
            xml << "    <testcase classname=\"" << report::xmlEscape(r.effect + "." + r.technique)
                << "\" name=\"" << report::xmlEscape(r.scene + "." + r.check + "[" + r.backend + "]") << "\"";
            switch (r.outcome) {
                case Outcome::Pass:
                    xml << "/>\n";
                    break;
                case Outcome::QualityWarning:
                    xml << ">\n      <system-out>QUALITY_WARNING: " << report::xmlEscape(r.detail)
                        << "</system-out>\n    </testcase>\n";
                    break;
                case Outcome::NotSupported:
                    xml << ">\n      <skipped message=\"NOT_SUPPORTED: " << report::xmlEscape(r.detail)
                        << "\"/>\n    </testcase>\n";
                    break;
                case Outcome::Fail:
                    xml << ">\n      <failure type=\"FAIL\" message=\"" << report::xmlEscape(r.detail)
                        << "\">" << report::xmlEscape(r.detail) << "</failure>\n    </testcase>\n";
                    break;
            }
        }
        xml << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
    return static_cast<bool>(xml);
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
// for an area light the soft one in runtime::SceneTruth::truth.
struct CheckScene {
    runtime::SceneTruth measured;
    runtime::GroundTruth hard;
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
    runtime::GroundTruthOptions truthOptions;
    std::optional<runtime::TruthCache> truthCache;  // --truth-cache
    runtime::FuzzyCompareOptions compare;
};

class Checker {
public:
    Checker(const Settings& settings, runtime::DiagnosticLog& sink) : mSettings(settings), mSink(sink) {}

    std::vector<CheckResult>& results() { return mResults; }

    void add(std::string backend, const std::string& effect, std::string technique, std::string scene,
             std::string check, Outcome outcome, std::string detail) {
        mResults.push_back(CheckResult{std::move(backend), effect, std::move(technique), std::move(scene),
                                       std::move(check), outcome, std::move(detail)});
    }

    // False if the backend creates no context: its rows are NOT_SUPPORTED, or FAIL where the user named
    // the backend (`required`).
    bool runBackend(runtime::Backend backend, bool required, const std::vector<EffectPlan>& effects) {
        const std::string backendLabel(runtime::backendName(backend));
        runtime::ContextOptions contextOptions;
        contextOptions.backend = backend;
        std::string contextError;
        std::unique_ptr<runtime::GlContext> context = runtime::createContext(contextOptions, contextError);
        if (!context) {
            for (const EffectPlan& effect : effects)
                add(backendLabel, effect.name, "-", "-", "backend",
                    required ? Outcome::Fail : Outcome::NotSupported, contextError);
            return false;
        }
        const std::string glRenderer = context->renderer();
        const std::string key = rendererKey(glRenderer);
        std::cerr << "check: " << backendLabel << ": " << glRenderer << "\n";
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
                std::unique_ptr<runtime::EffectRenderer> shaded =
                    runtime::EffectRenderer::create(technique.variants.shaded, mSink);
                std::unique_ptr<runtime::EffectRenderer> visibility;
                if (shaded && technique.expect.shadows && technique.variants.exposesVisibility)
                    visibility = runtime::EffectRenderer::create(technique.variants.visibility, mSink);
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
        std::optional<runtime::Scene> loaded = runtime::loadScene(name, mSink);
        if (!loaded) {
            scene->error = mSink.firstError("no scene '" + name + "'");
            return scene;
        }
        if (areaRadius)
            for (runtime::Light& light : loaded->lights) light.areaRadius = *areaRadius;
        const runtime::TruthCache* cache = mSettings.truthCache ? &*mSettings.truthCache : nullptr;
        if (!runtime::measureSceneTruth(scene->measured, std::move(*loaded), mSettings.width,
                                        mSettings.height, mSettings.truthOptions, mSink, scene->error, cache))
            return scene;
        const runtime::SceneTruth& t = scene->measured;
        if (!t.cacheNote.empty()) std::cerr << "check: --truth-cache: " << t.cacheNote << "\n";
        scene->soft = t.light->areaRadius > 0.0f;
        if (areaRadius) return scene;
        if (scene->soft) {
            runtime::Light point = *t.light;
            point.areaRadius = 0.0f;
            bool cached = false;
            std::string note;
            scene->hard = runtime::castOrReadTruth(t.scene, point, t.gbuffer, mSettings.truthOptions, cache,
                                                   cached, note);
            if (!note.empty()) std::cerr << "check: --truth-cache: " << note << "\n";
        } else {
            scene->hard = t.truth;
        }
        return scene;
    }

    void checkScene(const std::string& backend, const std::string& key, const std::string& glRenderer,
                    const EffectPlan& effect, const TechniquePlan& technique, const std::string& sceneName,
                    const CheckScene& scene, const CheckScene& penumbraScene, runtime::EffectRenderer& shaded,
                    runtime::EffectRenderer* visibility) {
        removeStaleImages(effect.name, technique.name, sceneName);
        const size_t firstRow = mResults.size();
        auto row = [&](const std::string& check, Outcome outcome, std::string detail) {
            add(backend, effect.name, technique.name, sceneName, check, outcome, std::move(detail));
        };
        if (!scene.error.empty()) {
            row("render", Outcome::Fail, scene.error);
            return;
        }
        const runtime::SceneTruth& t = scene.measured;
        runtime::FrameOptions frameOptions;
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
        const runtime::FrameImage frame = shaded.readFrame();
        std::string problem = nonFiniteTargets(shaded);
        if (problem.empty()) problem = blankness(frame);
        row("render", problem.empty() ? Outcome::Pass : Outcome::Fail,
            problem.empty() ? "no GL errors, targets finite, frame not blank" : problem);

        // Expectations against the ground truth.
        std::optional<runtime::VisibilityScore> hardScore, softScore;
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
                hardScore = runtime::scoreVisibility(*visibility, t, scene.hard, frameOptions, mSink);
                if (penumbraMaeBelow && penumbraScene.error.empty() && penumbraScene.soft && hardScore)
                    softScore = runtime::scoreVisibility(*visibility, penumbraScene.measured,
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
                const runtime::ShadowErrors& e = hardScore->errors;
                row("misclassified", judge(e.misclassifiedPercent, *misclassifiedBelow),
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
                    const runtime::SceneTruth& soft = penumbraScene.measured;
                    const double blankMae =
                        runtime::compareVisibility(soft.truth.visibility,
                                                   std::vector<float>(soft.truth.visibility.size(), 1.0f),
                                                   soft.receivers)
                            .penumbraMeanAbsoluteError;
                    if (!(*penumbraMaeBelow < blankMae)) {
                        row("penumbra", Outcome::Fail,
                            "the bound " + report::formatFixed(*penumbraMaeBelow, 4) +
                                " passes a frame without shadows (penumbra MAE " +
                                report::formatFixed(blankMae, 4) + "): it checks nothing");
                    } else {
                        row("penumbra", judge(mae, *penumbraMaeBelow),
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
        std::optional<runtime::FrameImage> golden;
        std::optional<runtime::FuzzyCompareResult> comparison;
        bool compare = true;
        if (mSettings.update) {
            const std::string path =
                goldenToWrite(effect.goldens, technique.name, sceneName, key, glRenderer).string();
            if (mWritten.insert(path).second) {
                std::string error;
                const bool written = runtime::writePng(frame, path, error);
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
            } else if (!(golden = runtime::readPng(place.path.string(), error))) {
                row("golden", Outcome::Fail, error);
            } else {
                comparison = runtime::fuzzyCompare(*golden, frame, mSettings.compare);
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
                            const runtime::FrameImage& frame,
                            const std::optional<runtime::FrameImage>& golden,
                            const std::optional<runtime::FuzzyCompareResult>& comparison,
                            const runtime::SceneTruth& t, const CheckScene& checkScene,
                            const std::optional<runtime::VisibilityScore>& score) {
        const std::string base = imageBase(effect, technique, scene);
        if (!mImagesWritten.insert(base).second) return;
        std::error_code fsError;
        std::filesystem::create_directories(std::filesystem::path(base).parent_path(), fsError);
        std::string error;
        bool ok = runtime::writePng(frame, base + ".result.png", error);
        if (ok && golden) ok = runtime::writePng(*golden, base + ".reference.png", error);
        if (ok && comparison && !comparison->matches && comparison->sameSize) {
            ok = runtime::writePng(comparison->errorMask, base + ".errormask.png", error);
        } else if (ok && score) {
            ok = runtime::writePng(
                runtime::errorImage(frame, checkScene.hard.visibility, score->visibility, t.receivers),
                base + ".errormask.png", error);
        }
        if (!ok) std::cerr << "check: " << error << "\n";
        std::cerr << "check: images of the failure: " << base << ".*.png\n";
    }

    const Settings& mSettings;
    runtime::DiagnosticLog& mSink;
    std::vector<CheckResult> mResults;
    std::set<std::string> mWritten;        // goldens written by this --update run
    std::set<std::string> mImagesWritten;  // failure images written by this run
};

}  // namespace

int checkCommand(const Arguments& args) {
    std::vector<std::string> effects;
    for (size_t i = 0; i < args.positionalCount(); ++i) effects.push_back(args.positional(i));
    if (effects.empty()) {
        std::cerr << "shadowfx check: expected one or more effect files (see --help)\n";
        return 2;
    }
    // A compiled file holds one variant, with the definitions it was compiled with; check compiles the
    // variants it scores (SHADOWFX_VISIBILITY, the expected map size) from source.
    for (const std::string& path : effects) {
        if (fx::isCompiledEffectFile(path)) {
            std::cerr << path
                      << ": error: check compiles the variants it scores from source: give the .fx file "
                      << "this compiled effect was compiled from\n";
            return 2;
        }
    }
    const fx::ParseOptions parseOptions = effectParseOptions(args);
    // Each distinct warning and error once on stderr; a failing step names its first error in its result.
    runtime::DiagnosticLog sink([](const std::string& text) { std::cerr << text << "\n"; });

    if (args.flag("--list-techniques")) {
        int status = 0;
        for (const std::string& path : effects) {
            sink.mark();
            std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, parseOptions, sink);
            if (!effect || sink.failed()) {
                status = 1;
                continue;
            }
            for (const fx::Technique& technique : effect->techniques) std::cout << technique.name << "\n";
        }
        return status;
    }

    Settings settings;
    settings.width = args.intValue("--width", 320);
    settings.height = args.intValue("--height", 240);
    settings.update = args.flag("--update");
    settings.requireGoldens = args.flag("--require-goldens");
    settings.batching = !args.flag("--no-batching");
    settings.sceneOverride = splitList(args.value("--scenes"));
    settings.outDir = args.value("--out", "out/check");
    settings.truthOptions.areaSamples = args.intValue("--area-samples", 256);
    if (const std::string dir = args.value("--truth-cache"); !dir.empty()) settings.truthCache.emplace(dir);
    if (const std::string text = args.value("--area-radius"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(value >= 0.0f && value < 1e6f)) {
            std::cerr << "shadowfx check: --area-radius: '" << text << "' is not a radius >= 0\n";
            return 2;
        }
        settings.areaRadius = value;
    }
    if (settings.width <= 0 || settings.height <= 0 || settings.width > 16384 || settings.height > 16384 ||
        settings.truthOptions.areaSamples < 1) {
        std::cerr
            << "shadowfx check: --width and --height must be between 1 and 16384, --area-samples >= 1\n";
        return 2;
    }
    std::vector<runtime::Backend> backends;
    const std::vector<std::string> backendNames = splitList(args.value("--backend", "all"));
    // Backends the user named (not through "all") must create a context.
    const bool backendsNamed =
        std::find(backendNames.begin(), backendNames.end(), "all") == backendNames.end();
    for (const std::string& name : backendNames) {
        if (name == "all") {
            for (runtime::Backend b : {runtime::Backend::EGL, runtime::Backend::OSMesa})
                backends.push_back(b);
            continue;
        }
        const std::optional<runtime::Backend> backend = runtime::parseBackend(name);
        if (!backend || *backend == runtime::Backend::GLFW || *backend == runtime::Backend::Auto) {
            std::cerr << "shadowfx check: --backend must be all, osmesa, egl or a list of them\n";
            return 2;
        }
        if (std::find(backends.begin(), backends.end(), *backend) == backends.end())
            backends.push_back(*backend);
    }
    if (backends.empty()) {
        std::cerr << "shadowfx check: --backend names no backend\n";
        return 2;
    }
    std::vector<std::string> techniqueFilter;
    for (const std::string& list : args.all("--technique"))
        for (const std::string& name : splitList(list)) techniqueFilter.push_back(name);

    // Parse and compile everything first (no GL needed): compile errors are FAILs with their location.
    Checker checker(settings, sink);
    std::vector<EffectPlan> plans;
    struct PendingCompile {
        size_t plan, technique;  // indices into plans and its techniques
        size_t request;          // the shaded variant's; the visibility variant's follows when expected
    };
    std::vector<PendingCompile> pending;
    std::vector<runtime::VariantRequest> requests;
    size_t matched = 0;  // techniques to check, plus effects that failed to parse
    for (const std::string& path : effects) {
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
    std::vector<runtime::CompiledVariant> compiled = runtime::compileVariants(requests, parseOptions);
    for (const PendingCompile& p : pending) {
        TechniquePlan& t = plans[p.plan].techniques[p.technique];
        sink.mark();
        runtime::forward(compiled[p.request].diagnostics, sink);
        t.variants.shaded = compiled[p.request].effect;
        if (t.variants.shaded && !sink.failed() && t.expect.shadows) {
            runtime::forward(compiled[p.request + 1].diagnostics, sink);
            t.variants.visibility = compiled[p.request + 1].effect;
            t.variants.exposesVisibility =
                t.variants.visibility &&
                !runtime::sameFragmentShaders(*t.variants.shaded, *t.variants.visibility);
        }
        if (!t.variants.shaded || sink.failed()) {
            t.variants.shaded.reset();
            checker.add("-", plans[p.plan].name, t.name, "-", "compile", Outcome::Fail,
                        sink.firstError("the technique does not compile"));
        }
    }
    if (matched == 0 && !techniqueFilter.empty()) {
        std::cerr << "shadowfx check: no technique of the effects matches --technique\n";
        return 2;
    }

    bool anyContext = false;
    for (runtime::Backend backend : backends)
        anyContext = checker.runBackend(backend, backendsNamed, plans) || anyContext;

    const std::vector<CheckResult>& results = checker.results();
    printTable(results);
    printEffectSummary(results);
    std::map<Outcome, size_t> counts;
    for (const CheckResult& r : results) ++counts[r.outcome];
    std::cout << "\n"
              << results.size() << " checks: " << counts[Outcome::Pass] << " PASS, "
              << counts[Outcome::QualityWarning] << " QUALITY_WARNING, " << counts[Outcome::NotSupported]
              << " NOT_SUPPORTED, " << counts[Outcome::Fail] << " FAIL\n";
    if (!args.value("--junit").empty()) {
        const std::string junit = args.value("--junit");
        if (!writeJunit(junit, results)) {
            std::cerr << "shadowfx check: cannot write " << junit << "\n";
            return 1;
        }
    }
    if (!anyContext) {
        std::cerr << "shadowfx check: no backend could create a GL context: nothing was rendered\n";
        return 1;
    }
    return counts[Outcome::Fail] > 0 ? 1 : 0;
}

}  // namespace shadowfx::cli
