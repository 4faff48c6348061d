// TuneCommand: `shadowfx tune` — a technique's tweakables searched (report/TuneSearch.h) for the least
// misclassified % at or under a frame-time budget. Each batch of settings the search proposes differs in one
// parameter, and is measured as one bench run (runtime/BenchRun.h) sweeping that parameter, the others set:
// the same runs, truth and scoring as `bench`, with the ray-cast truth cast once and read from --truth-cache
// after.
// The runs of every batch make the output's results.json, report.md and error_vs_time.svg (a bench results
// document with a `tune` section, report/BenchReport.h), the search's settings error_surface.svg
// (report/TuneSurfacePlot.h); the best setting is printed as a --set line.
#include "TuneCommand.h"
#include "BenchCommand.h"
#include "TunableParameters.h"

#include <runtime/BenchRun.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/ShadowMeasurement.h>
#include <report/BenchReport.h>
#include <report/BenchResults.h>
#include <report/TuneSearch.h>
#include <report/TuneSurfacePlot.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace shadowfx::cli {

const char* const kTuneUsage =
    "usage: shadowfx tune EFFECT.fx --technique NAME --scenes LIST --out DIR [options]\n"
    "  --technique NAME      the technique whose tweakables are searched (float, int and bool scalars it\n"
    "                        reads, within UIMin..UIMax; docs/effect-format.md, \"Tuning annotations\")\n"
    "  --scenes LIST         built-in scene names or scene files (.json), comma-separated: the error is the\n"
    "                        mean misclassified % over them\n"
    "  --budget-ms X         only settings whose full-cost frame time is at most X ms on every scene\n"
    "  --evaluations N       settings measured at most, the effect's own included (default 24)\n"
    "  --grid N              values of each parameter's coarse grid, ends included (default 5)\n"
    "  --map-size N          shadow-map size, as bench's --map-sizes (default 1024)\n"
    "  --frames N, --warmup N, --width W, --height H, --backend NAME, --area-samples N\n"
    "                        as bench's (defaults 5, 1, 640x480, auto, 256)\n"
    "  --area-radius R, --light-angle-to-view G\n"
    "                        as bench's: every light given area radius R (a soft truth), every\n"
    "                        directional light turned to G degrees from the view\n"
    "  --truth-cache DIR     where the ray-cast truth is kept between batches (default DIR/truth-cache)\n"
    "  --out DIR             results.json, report.md, error_vs_time.svg, error_surface.svg, best.txt;\n"
    "                        each batch's bench output under DIR/batches/\n"
    "The best setting is printed on stdout as `--set NAME=VALUE ...`, which render, bench and check take.\n";

namespace {

using Json = report::Json;

struct Batches {
    const runtime::BenchOptions& bench;  // every batch's options but its --set and output folder
    const std::vector<report::TuneParameter>& parameters;
    std::filesystem::path outDir;
    Json first;  // the first batch's results: the document's header
    Json runs = Json::array();
    int count = 0;

    // One bench run of `settings`: a sweep of the one parameter they differ in, the others set. Its output
    // is written to DIR/batches/N as `bench` writes it.
    bool measure(const std::vector<report::TuneSetting>& settings, std::vector<report::TuneScore>& scores) {
        const std::string name = "batches/" + std::to_string(count++);
        runtime::BenchOptions options = bench;
        options.outDir = outDir / name;
        std::vector<std::vector<std::string>> texts(settings.size());
        for (size_t i = 0; i < parameters.size(); ++i) {
            std::string values;
            for (size_t s = 0; s < settings.size(); ++s) {
                texts[s].push_back(report::formatTuneValue(parameters[i], settings[s][i]));
                if (s == 0 || settings[s][i] != settings[0][i])
                    values += (s == 0 ? "" : ",") + texts[s].back();
            }
            options.set.push_back(parameters[i].name + "=" + values);
        }
        runtime::BenchLog log;
        log.note = [](const std::string& text) { std::cerr << "tune: " << text << "\n"; };
        log.diagnostic = [](const std::string& text) { std::cerr << text << "\n"; };
        const runtime::BenchResult result = runtime::runBench(options, log);
        if (result.status != runtime::BenchStatus::Measured) {
            if (!result.error.empty()) std::cerr << "shadowfx tune: " << result.error << "\n";
            return false;
        }
        const Json results = report::benchResultsJson(result.results);
        std::string plotNote, writeError;
        if (!report::writeBenchOutputs(options.outDir, results, plotNote, writeError)) {
            std::cerr << "shadowfx tune: " << writeError << "\n";
            return false;
        }
        if (first.is_null()) first = results;
        for (size_t s = 0; s < settings.size(); ++s) {
            double error = 0.0, slowest = 0.0;
            int scenes = 0;
            for (const Json& run : results["runs"]) {
                // A sweep's runs name the swept parameter's value; a batch of one has no sweep.
                bool matches = true;
                if (run.contains("setting"))
                    for (size_t i = 0; i < parameters.size(); ++i)
                        if (run["setting"].contains(parameters[i].name))
                            matches = matches && run["setting"][parameters[i].name] == texts[s][i];
                if (!matches) continue;
                if (!run["error"].is_object()) {
                    std::cerr << "shadowfx tune: " << bench.effects.front()
                              << " does not expose its shadow term (SHADOWFX_VISIBILITY): nothing to score "
                                 "(docs/scoring.md)\n";
                    return false;
                }
                error += run["error"]["misclassified_percent"].get<double>();
                slowest = std::max(slowest, run["full_cost"]["frame_time_ms"]["median"].get<double>());
                ++scenes;
                Json tuned = run;
                Json setting = Json::object();
                for (size_t i = 0; i < parameters.size(); ++i) setting[parameters[i].name] = texts[s][i];
                tuned["setting"] = setting;
                tuned["run_index"] = runs.size();
                if (tuned["error_image"].is_string())
                    tuned["error_image"] = name + "/" + tuned["error_image"].get<std::string>();
                runs.push_back(std::move(tuned));
            }
            if (scenes == 0) return false;
            scores.push_back({error / scenes, slowest});
        }
        return true;
    }
};

Json evaluationJson(const std::vector<report::TuneParameter>& parameters, const report::TuneEvaluation& e) {
    Json setting = Json::object();
    for (size_t i = 0; i < parameters.size(); ++i)
        setting[parameters[i].name] = report::formatTuneValue(parameters[i], e.setting[i]);
    return Json{{"setting", setting},
                {"misclassified_percent", e.score.errorPercent},
                {"frame_time_ms", e.score.frameMs},
                {"within_budget", e.withinBudget},
                {"batch", e.batch}};
}

}  // namespace

int tuneCommand(const Arguments& args) {
    const std::string effect = args.positional(0);
    const std::string technique = args.value("--technique");
    report::TuneOptions options;
    options.evaluations = args.intValue("--evaluations", 24);
    options.gridPoints = args.intValue("--grid", 5);
    if (const std::string text = args.value("--budget-ms"); !text.empty()) {
        char* end = nullptr;
        const double budget = std::strtod(text.c_str(), &end);
        if (*end != '\0' || !(budget > 0.0)) {
            std::cerr << "shadowfx tune: --budget-ms: '" << text << "' is not a time in ms above 0\n";
            return 2;
        }
        options.budgetMs = budget;
    }
    const int mapSize = args.intValue("--map-size", 1024);
    if (options.evaluations < 1 || options.gridPoints < 2 || mapSize < 1 || mapSize > 16384) {
        std::cerr
            << "shadowfx tune: --evaluations must be >= 1, --grid >= 2 and --map-size between 1 and 16384\n";
        return 2;
    }
    const std::filesystem::path outDir = args.value("--out");
    runtime::BenchOptions bench;
    bench.effects = {effect};
    bench.techniques = {technique};
    bench.scenes = splitList(args.value("--scenes"));
    bench.mapSizes = {mapSize};
    bench.truthCacheDir = args.value("--truth-cache", (outDir / "truth-cache").string());
    // tune's defaults, fewer frames than bench's: a search measures many settings.
    bench.frames = 5;
    bench.warmup = 1;
    if (!readBenchRunOptions(args, "tune", bench)) return 2;

    // The effect compiled once here for its parameters; each batch's bench compiles it again, as bench does.
    runtime::DiagnosticLog sink([](const std::string& text) { std::cerr << text << "\n"; });
    const std::shared_ptr<fx::CompiledEffect> compiled = runtime::compileVariant(
        effect, bench.parseOptions, {{"SHADOWFX_SHADOW_MAP_SIZE", std::to_string(mapSize)}}, sink);
    if (!compiled || sink.errors() > 0) return 1;
    const auto found = std::find_if(compiled->techniques.begin(), compiled->techniques.end(),
                                    [&](const fx::CompiledTechnique& t) { return t.name == technique; });
    if (found == compiled->techniques.end()) {
        std::cerr << "shadowfx tune: " << effect << " has no technique '" << technique << "' (it has:";
        for (const fx::CompiledTechnique& t : compiled->techniques) std::cerr << " " << t.name;
        std::cerr << ")\n";
        return 2;
    }
    const std::vector<report::TuneParameter> parameters = tunableParameters(*compiled, *found, sink);
    if (sink.errors() > 0) return 1;
    if (parameters.empty()) {
        std::cerr << "shadowfx tune: technique '" << technique << "' of " << effect
                  << " reads no tweakable to search (a float or int scalar with UIMin and UIMax, or a bool; "
                     "docs/effect-format.md, \"Tuning annotations\")\n";
        return 2;
    }
    std::cerr << "tune: searching";
    for (const report::TuneParameter& p : parameters) std::cerr << " " << p.name;
    std::cerr << " in at most " << options.evaluations << " settings\n";

    Batches batches{.bench = bench,
                    .parameters = parameters,
                    .outDir = outDir,
                    .first = Json(),
                    .runs = Json::array(),
                    .count = 0};
    const report::TuneResult result = report::tuneSearch(
        parameters, options,
        [&](const std::vector<report::TuneSetting>& settings, std::vector<report::TuneScore>& scores) {
            return batches.measure(settings, scores);
        });
    if (result.failed) {
        std::cerr << "shadowfx tune: a bench run failed (above); the batches measured so far are in "
                  << (outDir / "batches").string() << "\n";
        return 1;
    }

    Json parametersJson = Json::array();
    for (const report::TuneParameter& p : parameters)
        parametersJson.push_back(Json{{"name", p.name},
                                      {"kind", p.kind == report::TuneParameter::Kind::Bool  ? "bool"
                                               : p.kind == report::TuneParameter::Kind::Int ? "int"
                                                                                            : "float"},
                                      {"min", p.min},
                                      {"max", p.max},
                                      {"step", p.step},
                                      {"scale", p.logScale ? "log" : "linear"},
                                      {"initial", report::formatTuneValue(p, p.initial)}});
    Json evaluations = Json::array();
    for (const report::TuneEvaluation& e : result.evaluations)
        evaluations.push_back(evaluationJson(parameters, e));
    const std::string setArguments =
        result.best ? report::tuneSetLine(parameters, result.evaluations[*result.best].setting) : "";
    Json document = batches.first;
    document["generator"] = "shadowfx tune";
    document["config"]["set"] = Json::array();
    document["runs"] = batches.runs;
    document["tune"] = Json{{"effect", effect},
                            {"technique", technique},
                            {"budget_ms", options.budgetMs ? Json(*options.budgetMs) : Json(nullptr)},
                            {"max_evaluations", options.evaluations},
                            {"grid_points", options.gridPoints},
                            {"parameters", parametersJson},
                            {"evaluations", evaluations},
                            {"best", result.best ? Json(*result.best) : Json(nullptr)},
                            {"set", result.best ? Json(setArguments) : Json(nullptr)}};
    std::string plotNote, writeError;
    if (!report::writeBenchOutputs(outDir, document, plotNote, writeError)) {
        std::cerr << "shadowfx tune: " << writeError << "\n";
        return 1;
    }
    if (std::string surfaceError; !report::writeTuneSurfacePlot((outDir / "error_surface.svg").string(),
                                                                parameters, result, surfaceError))
        std::cerr << "tune: " << surfaceError << ": no error_surface.svg\n";
    if (!result.best) {
        double fastest = result.evaluations.front().score.frameMs;
        for (const report::TuneEvaluation& e : result.evaluations)
            fastest = std::min(fastest, e.score.frameMs);
        std::cerr << "shadowfx tune: no setting measured is at or under --budget-ms " << *options.budgetMs
                  << " (the fastest took " << fastest << " ms); " << (outDir / "results.json").string()
                  << " has every setting measured\n";
        return 1;
    }
    const report::TuneEvaluation& best = result.evaluations[*result.best];
    const report::TuneEvaluation& initial = result.evaluations.front();
    std::cerr << "tune: " << result.evaluations.size()
              << " settings measured; the effect's own: " << initial.score.errorPercent << "% in "
              << initial.score.frameMs << " ms; the best: " << best.score.errorPercent << "% in "
              << best.score.frameMs << " ms\n";
    std::ofstream(outDir / "best.txt") << setArguments << "\n";
    std::cout << setArguments << "\n";
    return 0;
}

}  // namespace shadowfx::cli
