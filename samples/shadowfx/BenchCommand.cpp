// BenchCommand: `shadowfx bench`: its options read into runtime::BenchOptions, the run
// (runtime/BenchRun.h), its outputs written (report/BenchReport.h) and its progress shown.
//
// With --shard K/N only the runs report/BenchShard.h deals to shard K are measured; `bench merge`
// (BenchMergeCommand.cpp) joins the shards.
#include "BenchCommand.h"
#include "HostOption.h"
#include "PeerProgram.h"

#include <report/BenchReport.h>
#include <report/BenchResults.h>
#include <report/BenchShard.h>
#include <runtime/BenchRun.h>
#include <runtime/PeerRun.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace shadowfx::cli {

const char* const kBenchUsage =
    "usage: shadowfx bench --effects EFFECT.fx[,...] [--peers osg] --out DIR [options]\n"
    "       shadowfx bench merge OUT DIR...   (joins the outputs of --shard runs: bench merge --help)\n"
    "  --effects LIST        effect files, comma-separated (a shell glob works too: --effects effects/*.fx)\n"
    "  --scenes LIST         built-in scene names or scene files (.json), comma-separated (default boxes)\n"
    "  --map-sizes LIST      shadow-map sizes, passed as -D SHADOWFX_SHADOW_MAP_SIZE=N (default 1024)\n"
    "  --techniques LIST     only these techniques (default: every technique of every effect)\n"
    "  --frames N            timed frames per run, after the warm-up (default 10)\n"
    "  --warmup N            untimed frames first (default 2)\n"
    "  --width W, --height H frame size (default 640x480)\n"
    "  --area-samples N      ground-truth light samples per pixel for area lights (default 256)\n"
    "  --area-radius R       give every light of every scene this areaRadius (0: hard shadows); the\n"
    "                        ground truth is then soft (penumbra error of filtering methods)\n"
    "  --light-angle-to-view G  turn every directional light to G degrees (0-180) from the camera's view\n"
    "                        direction, in the vertical plane of the view: 0 = along the view (light behind\n"
    "                        the viewer), 90 = straight down for a level camera (the gamma sweep of\n"
    "                        docs/techniques/light-space-parameterizations.md)\n"
    "  --camera-orbit DEG    turn the camera DEG degrees about its target (around the vertical) before each\n"
    "                        warm-up and timed frame, so that view-dependent shadow maps are redrawn every\n"
    "                        frame as in a walk-through (default 0: a still camera, whose maps leave-out\n"
    "                        reuses); errors are scored at the scene's own camera\n"
    "  --time full|steady    the time error_vs_time.svg plots (default full): full = every pass drawn\n"
    "                        each frame, nothing reused (what a moving light or moving objects cost);\n"
    "                        steady = leave-out reusing unchanged shadow maps (a static scene); both are\n"
    "                        timed and reported either way\n"
    "  --leave-out LIST      on, off or on,off: leave-out (culling, dead and cached passes) as a run\n"
    "                        dimension; on,off times both in one run (default on)\n"
    "  --no-leave-out        the same as --leave-out off\n"
    "  --no-batching         draw every object alone instead of one instanced draw per mesh (the image is\n"
    "                        the same; for comparing the per-draw cost)\n"
    "  --backend NAME        auto, osmesa or egl (default auto)\n"
    "  --set PARAM=VALUE     set a parameter of every effect that has it (repeatable): --set Bias=0.002\n"
    "  --set PARAM=V1,V2,... a sweep: one run per value, each a row of the one report and plot;\n"
    "                        ranges START:STOP:xF (times F) or START:STOP:+S (plus S), STOP included:\n"
    "                        --set Exponent=10:80:x2 is 10,20,40,80. Several sweeps run their cross\n"
    "                        product (at most 64 settings); a vector's sweep braces each value:\n"
    "                        --set LightColor={1,0,0},{0,1,0} (docs/measurement.md, \"Sweeps\")\n"
    "  --peers LIST          also run other libraries' shadow techniques on the same scenes and map sizes,\n"
    "                        scored against the same ground truth: osg (OpenSceneGraph's osgShadow, built\n"
    "                        when OpenSceneGraph was found; docs/peers.md). --effects may then be left out\n"
    "  --peer-techniques LIST  only these of the peers' techniques (default: all; the peer lists them)\n"
    "  --shard K/N           measure only shard K of N of the runs (1 <= K <= N): run index i belongs to\n"
    "                        shard (i mod N) + 1; join the N outputs with `shadowfx bench merge`\n"
    "                        (docs/sharding.md)\n"
    "  --truth-cache DIR     read each scene's ray-cast ground truth from DIR when it was cast before with\n"
    "                        the same scene, light, camera, frame size and options; cast and store it\n"
    "                        there otherwise (an entry that is stale or corrupt is cast again, never used)\n"
    "  --out DIR             results.json, report.md, error_vs_time.svg and errors/*.png go "
    "here\n" SHADOWFX_HOST_OPTION_HELP
    "                        (its \"visibility\" scores it; the run is named after the last step's "
    "technique)\n";

namespace {

// One line per run; on a terminal, one line rewritten in place.
class Progress {
public:
    Progress() : mTty(isatty(fileno(stderr))) {}
    void show(size_t done, size_t total, const std::string& run) {
        std::cerr << (mTty ? "\r\033[K" : "") << "bench: [" << done << "/" << total << "] " << run
                  << (mTty ? "" : "\n") << std::flush;
        mOpen = mTty;
    }
    // Ends the line a terminal's progress is on, before anything else is printed.
    void end() {
        if (mOpen) std::cerr << "\n";
        mOpen = false;
    }

private:
    bool mTty;
    bool mOpen = false;
};

// An angle option in [-limit, limit] (or [0, limit] when `nonNegative`); false, said, if malformed.
bool readAngle(const Arguments& args, const std::string& command, const char* option, float limit,
               bool nonNegative, std::optional<float>& out) {
    const std::string text = args.value(option);
    if (text.empty()) return true;
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (*end != '\0' || !(std::abs(value) <= limit && (!nonNegative || value >= 0.0f))) {
        std::cerr << "shadowfx " << command << ": " << option << ": '" << text << "' is not an angle in ["
                  << (nonNegative ? "0" : "-" + std::to_string(static_cast<int>(limit))) << ", "
                  << static_cast<int>(limit) << "]\n";
        return false;
    }
    out = value;
    return true;
}

}  // namespace

bool readBenchRunOptions(const Arguments& args, const std::string& command, runtime::BenchOptions& o) {
    o.frames = args.intValue("--frames", o.frames);
    o.warmup = args.intValue("--warmup", o.warmup);
    o.width = args.intValue("--width", o.width);
    o.height = args.intValue("--height", o.height);
    if (o.frames < 1 || o.warmup < 0 || o.width <= 0 || o.height <= 0 || o.width > 16384 ||
        o.height > 16384) {
        std::cerr << "shadowfx " << command
                  << ": --frames must be >= 1, --warmup >= 0, the size between 1 and 16384\n";
        return false;
    }
    const std::optional<runtime::Backend> backend = runtime::parseBackend(args.value("--backend", "auto"));
    if (!backend || *backend == runtime::Backend::GLFW) {
        std::cerr << "shadowfx " << command << ": --backend must be auto, osmesa or egl\n";
        return false;
    }
    o.backend = *backend;
    o.truth.areaSamples = args.intValue("--area-samples", o.truth.areaSamples);
    if (const std::string text = args.value("--area-radius"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(value >= 0.0f && value < 1e6f)) {
            std::cerr << "shadowfx " << command << ": --area-radius: '" << text << "' is not a radius >= 0\n";
            return false;
        }
        o.areaRadius = value;
    }
    if (!readAngle(args, command, "--light-angle-to-view", 180.0f, true, o.lightAngleToView)) return false;
    o.parseOptions = effectParseOptions(args);
    return true;
}

int benchCommand(const Arguments& args) {
    runtime::BenchOptions o;
    for (const std::string& list : args.all("--effects"))
        for (const std::string& effect : splitList(list)) o.effects.push_back(effect);
    for (size_t i = 0; i < args.positionalCount(); ++i) o.effects.push_back(args.positional(i));
    o.scenes = splitList(args.value("--scenes", "boxes"));
    o.mapSizes.clear();
    for (const std::string& size : splitList(args.value("--map-sizes", "1024"))) {
        char* end = nullptr;
        const long value = std::strtol(size.c_str(), &end, 10);
        if (*end != '\0' || value < 1 || value > 16384) {
            std::cerr << "shadowfx bench: --map-sizes: '" << size << "' is not a size between 1 and 16384\n";
            return 2;
        }
        o.mapSizes.push_back(static_cast<int>(value));
    }
    o.techniques = splitList(args.value("--techniques"));
    o.leaveOutModes.clear();
    for (const std::string& mode :
         splitList(args.flag("--no-leave-out") ? "off" : args.value("--leave-out", "on"))) {
        if (mode != "on" && mode != "off") {
            std::cerr << "shadowfx bench: --leave-out expects on, off or on,off, got '" << mode << "'\n";
            return 2;
        }
        o.leaveOutModes.push_back(mode == "on");
    }
    if (o.leaveOutModes.empty()) o.leaveOutModes.push_back(true);
    o.timeAxis = args.value("--time", "full");
    if (o.timeAxis != "full" && o.timeAxis != "steady") {
        std::cerr << "shadowfx bench: --time expects full or steady, got '" << o.timeAxis << "'\n";
        return 2;
    }
    // Peers: each name's program, found where this build put it, and the techniques to run.
    o.peerNames = splitList(args.value("--peers"));
    o.peerTechniqueFilter = splitList(args.value("--peer-techniques"));
    int peerStatus = 0;
    o.peers = selectPeers("bench", o.peerNames, o.peerTechniqueFilter, peerStatus);
    if (peerStatus != 0) return peerStatus;
    if ((o.effects.empty() && o.peers.empty()) || o.scenes.empty() || o.mapSizes.empty()) {
        std::cerr
            << "shadowfx bench: needs --effects or --peers, and non-empty --scenes and --map-sizes (see "
               "--help)\n";
        return 2;
    }
    if (!readBenchRunOptions(args, "bench", o)) return 2;
    std::optional<float> cameraOrbit;
    if (!readAngle(args, "bench", "--camera-orbit", 180.0f, false, cameraOrbit)) return 2;
    o.cameraOrbit = cameraOrbit.value_or(0.0f);  // degrees per frame
    if (const std::string text = args.value("--shard"); !text.empty()) {
        std::string shardError;
        o.shard = report::parseBenchShard(text, shardError);
        if (!o.shard) {
            std::cerr << "shadowfx bench: --shard " << shardError << "\n";
            return 2;
        }
    }
    o.truthCacheDir = args.value("--truth-cache");
    o.set = args.all("--set");
    o.batching = !args.flag("--no-batching");
    o.outDir = args.value("--out");
    fx::DiagnosticList hostDiagnostics;
    bool hostRead = true;
    o.host = readHostOption(args, hostDiagnostics, hostRead);
    if (!hostRead) {
        std::cerr << hostDiagnostics.str();
        return 1;
    }

    Progress progress;
    runtime::BenchLog log;
    log.note = [&](const std::string& text) {
        progress.end();
        std::cerr << "bench: " << text << "\n";
    };
    log.diagnostic = [](const std::string& text) { std::cerr << "\n" << text << "\n"; };
    log.progress = [&](size_t done, size_t total, const std::string& run) {
        progress.show(done, total, run);
    };
    const runtime::BenchResult result = runtime::runBench(o, log);
    progress.end();
    if (result.status != runtime::BenchStatus::Measured) {
        if (!result.error.empty()) std::cerr << "shadowfx bench: " << result.error << "\n";
        return result.status == runtime::BenchStatus::UsageError ? 2 : 1;
    }
    std::string plotNote, writeError;
    if (!report::writeBenchOutputs(o.outDir, report::benchResultsJson(result.results), plotNote,
                                   writeError)) {
        std::cerr << "shadowfx bench: " << writeError << "\n";
        return 1;
    }
    if (!plotNote.empty()) std::cerr << "bench: " << plotNote << "\n";
    std::cout << (o.outDir / "report.md").string() << "\n";
    return 0;
}

}  // namespace shadowfx::cli
