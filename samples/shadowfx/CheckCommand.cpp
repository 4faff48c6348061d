// CheckCommand: `shadowfx check`: its options read into runtime::ConformanceOptions, the run
// (runtime/ConformanceRun.h), and the table, the per-effect summary, the count line and JUnit written
// (report/ConformanceReport.h).
//
// An effect library ported from FX Composer thus gets one table of compile, link, GL-error, NaN and
// blank-frame results per technique (`shadowfx check lib/*.fx --junit out.xml`), and one line per effect:
// drawn, blank or failed, with a summary line.
#include "CheckCommand.h"
#include "HostOption.h"

#include <fx/CompiledEffectFile.h>
#include <fx/EffectParser.h>
#include <report/ConformanceReport.h>
#include <runtime/ConformanceRun.h>
#include <runtime/DiagnosticLog.h>

#include <algorithm>
#include <fstream>
#include <iostream>

namespace shadowfx::cli {

const char* const kCheckUsage =
    "usage: shadowfx check EFFECT.fx [EFFECT.fx ...] [options]\n"
    "  (a compiled EFFECT.sfxo is rendered and held to its goldens as it was compiled; its shadows\n"
    "  are scored from the .fx only, which compiles the SHADOWFX_VISIBILITY variant)\n"
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
    "  --no-batching         draw every object alone, not one instanced draw per mesh (the same "
    "images)\n" SHADOWFX_HOST_OPTION_HELP
    "Technique annotations read: string ExpectScenes, float ExpectMisclassifiedBelow (percent of receiver\n"
    "pixels, hard-shadow truth), float ExpectPenumbraMaeBelow (mean |error| over the penumbra of an area\n"
    "light), float ExpectAreaRadius (the light's areaRadius for the penumbra check), int ExpectMapSize,\n"
    "bool ExpectShadows (docs/scoring.md). A bound is a number for every scene or a string of per-scene\n"
    "bounds: \"dual-l=0.25, teapot=0.12\". Goldens:\n"
    "EFFECT_DIR/golden/EFFECT/TECHNIQUE/SCENE.png, written there by --update; an effect without that folder\n"
    "yet is NOT_SUPPORTED for goldens (docs/measurement.md).\n"
    "Exit status: 0 if nothing FAILs, 1 on any FAIL, 2 on usage errors.\n";

int checkCommand(const Arguments& args) {
    std::vector<std::string> effects;
    for (size_t i = 0; i < args.positionalCount(); ++i) effects.push_back(args.positional(i));
    if (effects.empty()) {
        std::cerr << "shadowfx check: expected one or more effect files (see --help)\n";
        return 2;
    }
    const fx::ParseOptions parseOptions = effectParseOptions(args);
    // Each distinct warning and error once on stderr.
    const auto printDiagnostic = [](const std::string& text) { std::cerr << text << "\n"; };
    if (args.flag("--list-techniques")) {
        runtime::DiagnosticLog sink(printDiagnostic);
        int status = 0;
        for (const std::string& path : effects) {
            sink.mark();
            if (fx::isCompiledEffectFile(path)) {
                std::unique_ptr<fx::CompiledEffect> compiled = fx::readCompiledEffectFile(path, sink);
                if (!compiled || sink.failed()) {
                    status = 1;
                    continue;
                }
                for (const fx::CompiledTechnique& technique : compiled->techniques)
                    std::cout << technique.name << "\n";
                continue;
            }
            std::shared_ptr<fx::Effect> effect = fx::parseEffectFile(path, parseOptions, sink);
            if (!effect || sink.failed()) {
                status = 1;
                continue;
            }
            for (const fx::Technique& technique : effect->techniques) std::cout << technique.name << "\n";
        }
        return status;
    }

    runtime::ConformanceOptions o;
    o.effects = effects;
    o.parseOptions = parseOptions;
    o.width = args.intValue("--width", 320);
    o.height = args.intValue("--height", 240);
    o.update = args.flag("--update");
    o.requireGoldens = args.flag("--require-goldens");
    o.batching = !args.flag("--no-batching");
    o.scenes = splitList(args.value("--scenes"));
    o.outDir = args.value("--out", "out/check");
    fx::DiagnosticList hostDiagnostics;
    bool hostRead = true;
    o.host = readHostOption(args, hostDiagnostics, hostRead);
    if (!hostRead) {
        std::cerr << hostDiagnostics.str();
        return 1;
    }
    o.areaSamples = args.intValue("--area-samples", 256);
    o.truthCacheDir = args.value("--truth-cache");
    if (const std::string text = args.value("--area-radius"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(value >= 0.0f && value < 1e6f)) {
            std::cerr << "shadowfx check: --area-radius: '" << text << "' is not a radius >= 0\n";
            return 2;
        }
        o.areaRadius = value;
    }
    if (o.width <= 0 || o.height <= 0 || o.width > 16384 || o.height > 16384 || o.areaSamples < 1) {
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

    o.backends = backends;
    o.backendsNamed = backendsNamed;
    o.techniques = techniqueFilter;
    runtime::ConformanceLog log;
    log.note = [](const std::string& text) { std::cerr << "check: " << text << "\n"; };
    log.diagnostic = printDiagnostic;
    const runtime::ConformanceResult result = runtime::runConformance(o, log);
    if (result.noTechniqueMatches) {
        std::cerr << "shadowfx check: no technique of the effects matches --technique\n";
        return 2;
    }
    report::writeCheckTable(std::cout, result.rows);
    report::writeEffectSummary(std::cout, result.rows);
    std::cout << "\n";
    report::writeCheckCounts(std::cout, result.rows);
    if (const std::string junit = args.value("--junit"); !junit.empty()) {
        std::ofstream xml(junit);
        report::writeJunit(xml, result.rows);
        if (!xml) {
            std::cerr << "shadowfx check: cannot write " << junit << "\n";
            return 1;
        }
    }
    if (!result.anyContext) {
        std::cerr << "shadowfx check: no backend could create a GL context: nothing was rendered\n";
        return 1;
    }
    const bool anyFail = std::any_of(result.rows.begin(), result.rows.end(), [](const report::CheckRow& r) {
        return r.outcome == report::CheckOutcome::Fail;
    });
    return anyFail ? 1 : 0;
}

}  // namespace shadowfx::cli
