// BenchCommand: `shadowfx bench`.
//
// [SECTION] Diagnostics each distinct message once
// [SECTION] Statistics  median and spread of the timed frames
// [SECTION] Runs        ground truth per scene, then effect x map size x scene x technique
// [SECTION] Output      results.json, report.md, error_vs_time.svg (report/BenchReport.h)
//
// With --shard K/N only the runs report/BenchShard.h deals to shard K are measured, each record keeping its
// run_index; `bench merge` (BenchMergeCommand.cpp) joins the shards. With --truth-cache DIR each scene's
// ground truth is read from DIR when it was cast before (runtime/TruthCache.h).
//
// Each effect is compiled twice per map size: as written (the timed frames) and with SHADOWFX_VISIBILITY
// (one frame whose colour is the shadow factor, scored against the ground truth). Timing the visibility
// variant instead would leave out the effect's shading and so understate its cost; scoring the shaded frame
// would confuse shading with shadowing. The two variants share every shadow computation by construction
// (the define only changes what the final pass returns).
#include "BenchCommand.h"
#include "ParameterSweep.h"
#include "PeerRun.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/GlContext.h>
#include <runtime/GroundTruth.h>
#include <runtime/Scene.h>
#include <runtime/SceneFile.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/TruthCache.h>
#include <report/BenchReport.h>
#include <report/BenchShard.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
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
    "  --out DIR             results.json, report.md, error_vs_time.svg and errors/*.png go here\n";

namespace {

using Clock = std::chrono::steady_clock;
using Json = report::Json;

// [SECTION] Result records

// One run's shadow error as results.json writes it, for shadowfx's runs and the peers' alike.
Json errorJson(const runtime::ShadowErrors& errors) {
    return Json{
        {"receiver_pixels", errors.receiverPixels},
        {"false_shadow_pixels", errors.falseShadowPixels},
        {"false_light_pixels", errors.falseLightPixels},
        {"false_shadow_percent", errors.falseShadowPercent},
        {"false_light_percent", errors.falseLightPercent},
        {"misclassified_percent", errors.misclassifiedPercent},
        {"mae", errors.meanAbsoluteError},
        {"p95_abs_error", errors.p95AbsoluteError},
        {"penumbra_pixels", errors.penumbraPixels},
        {"penumbra_mae", errors.penumbraPixels > 0 ? Json(errors.penumbraMeanAbsoluteError) : Json(nullptr)}};
}

// [SECTION] Statistics

struct Spread {
    double median = 0, min = 0, max = 0, p25 = 0, p75 = 0;
};

// Linear-interpolated quantiles (type 7, as numpy's default).
Spread spreadOf(std::vector<double> values) {
    Spread s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    auto quantile = [&](double q) {
        const double position = q * static_cast<double>(values.size() - 1);
        const size_t below = static_cast<size_t>(position);
        const size_t above = std::min(below + 1, values.size() - 1);
        return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
    };
    s.median = quantile(0.5);
    s.min = values.front();
    s.max = values.back();
    s.p25 = quantile(0.25);
    s.p75 = quantile(0.75);
    return s;
}

Json toJson(const Spread& s) {
    return Json{{"median", s.median}, {"min", s.min}, {"max", s.max}, {"p25", s.p25}, {"p75", s.p75}};
}

double ms(uint64_t ns) {
    return static_cast<double>(ns) * 1e-6;
}

// [SECTION] Runs

struct EffectVariant {
    std::shared_ptr<fx::CompiledEffect> timed;
    std::shared_ptr<fx::CompiledEffect> visibility;
    bool exposesVisibility = false;  // the define changed some pixel shader
    bool honoursMapSize = false;     // some render target has the requested size
};

std::string safeName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return text;
}

// The timed frames of one run in one reuse mode (FrameOptions::reuseTargets), and one more frame like them,
// untimed, that counts their work (occlusion queries would perturb the timing).
struct TimedFrames {
    double firstFrameMs = 0.0;
    std::vector<double> frameMs, gpuMs, script, binding, preshader, gl, overhead;
    std::vector<std::string> passNames;
    std::vector<std::vector<double>> passGpu, passCpu;
    std::vector<int> passDraws;
    runtime::FrameStats counted;
};

// Renders `warmup` + `frames` frames of `scene` (the camera turned `cameraOrbit` degrees more before each)
// and the counting frame. False once a frame fails; the sink says why.
bool timeFrames(runtime::EffectRenderer& renderer, const runtime::Scene& scene,
                const runtime::FrameOptions& options, int warmup, int frames, float cameraOrbit,
                runtime::DiagnosticLog& sink, TimedFrames& out) {
    // One scene edited in place (the renderer's caches see only the camera move).
    runtime::Scene moving = scene;
    const auto orbitTo = [&](int step) {
        const glm::vec3 offset = scene.camera.position - scene.camera.target;
        const glm::mat4 turn =
            glm::rotate(glm::mat4(1.0f), glm::radians(cameraOrbit * step), glm::vec3(0.0f, 1.0f, 0.0f));
        moving.camera.position = scene.camera.target + glm::vec3(turn * glm::vec4(offset, 0.0f));
    };
    for (int frame = 0; frame < warmup + frames; ++frame) {
        runtime::FrameStats stats;
        if (cameraOrbit != 0.0f) orbitTo(frame + 1);
        const auto start = Clock::now();
        // With timePasses, render() returns once the GPU has finished the frame.
        if (!renderer.render(moving, options, sink, &stats) || sink.errors() > 0) return false;
        const double wall = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (frame == 0) out.firstFrameMs = wall;
        if (frame < warmup) continue;
        out.frameMs.push_back(wall);
        double gpu = 0.0;
        if (out.passNames.empty()) {
            for (const runtime::PassTiming& pass : stats.passTimings) {
                out.passNames.push_back(pass.pass);
                out.passDraws.push_back(pass.draws);
            }
            out.passGpu.resize(out.passNames.size());
            out.passCpu.resize(out.passNames.size());
        }
        for (size_t p = 0; p < stats.passTimings.size() && p < out.passNames.size(); ++p) {
            out.passGpu[p].push_back(ms(stats.passTimings[p].gpuNs));
            out.passCpu[p].push_back(ms(stats.passTimings[p].cpuNs));
            gpu += ms(stats.passTimings[p].gpuNs);
        }
        out.gpuMs.push_back(gpu);
        out.script.push_back(ms(stats.cpu.scriptNs()));
        out.binding.push_back(ms(stats.cpu.bindingNs));
        out.preshader.push_back(ms(stats.cpu.preshaderNs));
        out.gl.push_back(ms(stats.cpu.glNs));
        out.overhead.push_back(ms(stats.cpu.scriptNs() + stats.cpu.bindingNs + stats.cpu.preshaderNs));
    }
    runtime::FrameOptions countOptions = options;
    countOptions.timePasses = false;
    countOptions.countTexels = true;
    if (cameraOrbit != 0.0f) orbitTo(warmup + frames + 1);
    return renderer.render(moving, countOptions, sink, &out.counted) && sink.errors() == 0;
}

// frame_time_ms, gpu_time_ms, work, passes and runtime_cpu_ms of one set of timed frames.
Json timingJson(const TimedFrames& t) {
    const runtime::FrameStats& counted = t.counted;
    Json passes = Json::array();
    for (size_t p = 0; p < t.passNames.size(); ++p) {
        Json pass{{"name", t.passNames[p]},
                  {"gpu_ms", spreadOf(t.passGpu[p]).median},
                  {"cpu_ms", spreadOf(t.passCpu[p]).median},
                  {"draws", t.passDraws[p]}};
        if (p < counted.passes.size()) {
            const runtime::PassStats& work = counted.passes[p];
            pass["left_out"] = work.leftOut;
            pass["culled"] = work.culled;
            pass["triangles"] = work.triangles;
            pass["texels_written"] = work.texelsWritten;
        }
        passes.push_back(std::move(pass));
    }
    return Json{{"frame_time_ms", toJson(spreadOf(t.frameMs))},
                {"gpu_time_ms", toJson(spreadOf(t.gpuMs))},
                {"work", Json{{"passes_run", counted.passesRun},
                              {"passes_left_out", counted.passesLeftOut},
                              {"draws", counted.draws},
                              {"culled", counted.culled},
                              {"triangles", counted.triangles}}},
                {"passes", passes},
                {"runtime_cpu_ms", Json{{"script", spreadOf(t.script).median},
                                        {"binding", spreadOf(t.binding).median},
                                        {"preshader", spreadOf(t.preshader).median},
                                        {"gl", spreadOf(t.gl).median},
                                        {"overhead", spreadOf(t.overhead).median}}}};
}

class Progress {
public:
    explicit Progress(size_t total) : mTotal(total), mTty(isatty(fileno(stderr))) {}
    void show(const std::string& what) {
        ++mDone;
        std::ostringstream line;
        line << "bench: [" << mDone << "/" << mTotal << "] " << what;
        if (mTty) {
            std::cerr << "\r\033[K" << line.str() << std::flush;
        } else {
            std::cerr << line.str() << "\n";
        }
    }
    void end() {
        if (mTty) std::cerr << "\n";
    }

private:
    size_t mTotal;
    size_t mDone = 0;
    bool mTty;
};

// Receivers the ground truth classifies as shadowed: what a blank (all-lit) frame would get wrong.
int64_t shadowedReceivers(const runtime::SceneTruth& t) {
    int64_t count = 0;
    for (size_t i = 0; i < t.receivers.size() && i < t.truth.visibility.size(); ++i)
        count += t.receivers[i] && t.truth.visibility[i] < runtime::kShadowedBelow ? 1 : 0;
    return count;
}

// The direction at `degrees` from the camera's view direction V, turned toward straight down: cos G V +
// sin G D, D the downward direction perpendicular to V (any horizontal one if V is vertical).
glm::vec3 directionAtAngleToView(const runtime::Camera& camera, float degrees) {
    const glm::vec3 view = glm::normalize(camera.target - camera.position);
    glm::vec3 down = glm::vec3(0.0f, -1.0f, 0.0f) - glm::dot(glm::vec3(0.0f, -1.0f, 0.0f), view) * view;
    if (glm::length(down) < 1e-3f) down = glm::cross(view, glm::vec3(1.0f, 0.0f, 0.0f));
    const float g = glm::radians(degrees);
    return glm::normalize(std::cos(g) * view + std::sin(g) * glm::normalize(down));
}

}  // namespace

int benchCommand(const Arguments& args) {
    std::vector<std::string> effects;
    for (const std::string& list : args.all("--effects"))
        for (const std::string& effect : splitList(list)) effects.push_back(effect);
    for (size_t i = 0; i < args.positionalCount(); ++i) effects.push_back(args.positional(i));
    const std::vector<std::string> sceneNames = splitList(args.value("--scenes", "boxes"));
    std::vector<int> mapSizes;
    for (const std::string& size : splitList(args.value("--map-sizes", "1024"))) {
        char* end = nullptr;
        const long value = std::strtol(size.c_str(), &end, 10);
        if (*end != '\0' || value < 1 || value > 16384) {
            std::cerr << "shadowfx bench: --map-sizes: '" << size << "' is not a size between 1 and 16384\n";
            return 2;
        }
        mapSizes.push_back(static_cast<int>(value));
    }
    const std::vector<std::string> techniqueFilter = splitList(args.value("--techniques"));
    std::vector<bool> leaveOutModes;
    for (const std::string& mode :
         splitList(args.flag("--no-leave-out") ? "off" : args.value("--leave-out", "on"))) {
        if (mode != "on" && mode != "off") {
            std::cerr << "shadowfx bench: --leave-out expects on, off or on,off, got '" << mode << "'\n";
            return 2;
        }
        leaveOutModes.push_back(mode == "on");
    }
    if (leaveOutModes.empty()) leaveOutModes.push_back(true);
    const std::string timeAxis = args.value("--time", "full");
    if (timeAxis != "full" && timeAxis != "steady") {
        std::cerr << "shadowfx bench: --time expects full or steady, got '" << timeAxis << "'\n";
        return 2;
    }
    const int frames = args.intValue("--frames", 10);
    const int warmup = args.intValue("--warmup", 2);
    const int width = args.intValue("--width", 640);
    const int height = args.intValue("--height", 480);
    // Peers: each name's program, found where this build put it, and the techniques to run.
    struct Peer {
        std::string name;
        std::string program;
        std::vector<std::string> techniques;
    };
    std::vector<Peer> peers;
    const std::vector<std::string> peerTechniqueFilter = splitList(args.value("--peer-techniques"));
    for (const std::string& name : splitList(args.value("--peers"))) {
        Peer peer{name, findPeerProgram(name), {}};
        if (name != "osg") {
            std::cerr << "shadowfx bench: --peers: unknown peer '" << name << "' (known: osg)\n";
            return 2;
        }
        if (peer.program.empty()) {
            std::cerr << "shadowfx bench: --peers " << name << ": shadowfx-" << name
                      << "-peer was not built (OpenSceneGraph was not found when configuring; "
                         "scripts/install-deps.sh installs libopenscenegraph-dev)\n";
            return 2;
        }
        const std::vector<std::string> offered = peerTechniques(peer.program);
        if (offered.empty()) {
            std::cerr << "shadowfx bench: --peers " << name << ": " << peer.program << " does not run\n";
            return 1;
        }
        for (const std::string& technique : offered)
            if (peerTechniqueFilter.empty() ||
                std::find(peerTechniqueFilter.begin(), peerTechniqueFilter.end(), technique) !=
                    peerTechniqueFilter.end())
                peer.techniques.push_back(technique);
        peers.push_back(std::move(peer));
    }
    for (const std::string& technique : peerTechniqueFilter) {
        bool offered = false;
        for (const Peer& peer : peers)
            offered = offered || std::find(peer.techniques.begin(), peer.techniques.end(), technique) !=
                                     peer.techniques.end();
        if (!offered) {
            std::cerr << "shadowfx bench: --peer-techniques: no peer offers '" << technique << "'\n";
            return 2;
        }
    }
    if ((effects.empty() && peers.empty()) || sceneNames.empty() || mapSizes.empty()) {
        std::cerr
            << "shadowfx bench: needs --effects or --peers, and non-empty --scenes and --map-sizes (see "
               "--help)\n";
        return 2;
    }
    if (frames < 1 || warmup < 0 || width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        std::cerr << "shadowfx bench: --frames must be >= 1, --warmup >= 0, the size between 1 and 16384\n";
        return 2;
    }
    const std::optional<runtime::Backend> backend = runtime::parseBackend(args.value("--backend", "auto"));
    if (!backend || *backend == runtime::Backend::GLFW) {
        std::cerr << "shadowfx bench: --backend must be auto, osmesa or egl\n";
        return 2;
    }
    runtime::GroundTruthOptions truthOptions;
    truthOptions.areaSamples = args.intValue("--area-samples", 256);
    std::optional<float> areaRadius;
    if (const std::string text = args.value("--area-radius"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(value >= 0.0f && value < 1e6f)) {
            std::cerr << "shadowfx bench: --area-radius: '" << text << "' is not a radius >= 0\n";
            return 2;
        }
        areaRadius = value;
    }
    std::optional<float> lightAngle;
    if (const std::string text = args.value("--light-angle-to-view"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(value >= 0.0f && value <= 180.0f)) {
            std::cerr << "shadowfx bench: --light-angle-to-view: '" << text
                      << "' is not an angle in [0, 180]\n";
            return 2;
        }
        lightAngle = value;
    }

    float cameraOrbit = 0.0f;  // degrees per frame
    if (const std::string text = args.value("--camera-orbit"); !text.empty()) {
        char* end = nullptr;
        const float value = std::strtof(text.c_str(), &end);
        if (*end != '\0' || !(std::abs(value) <= 180.0f)) {
            std::cerr << "shadowfx bench: --camera-orbit: '" << text << "' is not an angle in [-180, 180]\n";
            return 2;
        }
        cameraOrbit = value;
    }

    std::optional<report::BenchShard> shard;
    if (const std::string text = args.value("--shard"); !text.empty()) {
        std::string shardError;
        shard = report::parseBenchShard(text, shardError);
        if (!shard) {
            std::cerr << "shadowfx bench: --shard " << shardError << "\n";
            return 2;
        }
    }
    std::optional<runtime::TruthCache> truthCache;
    if (const std::string dir = args.value("--truth-cache"); !dir.empty()) truthCache.emplace(dir);

    const std::filesystem::path outDir = args.value("--out");
    std::error_code fsError;
    std::filesystem::create_directories(outDir / "errors", fsError);
    if (fsError) {
        std::cerr << "shadowfx bench: cannot create " << outDir.string() << ": " << fsError.message() << "\n";
        return 1;
    }

    // Each distinct diagnostic once: the same warning comes back every frame of every run.
    runtime::DiagnosticLog sink([](const std::string& text) { std::cerr << "\n" << text << "\n"; });
    runtime::ContextOptions contextOptions;
    contextOptions.backend = *backend;
    std::string contextError;
    std::unique_ptr<runtime::GlContext> context = runtime::createContext(contextOptions, contextError);
    if (!context) {
        std::cerr << "shadowfx bench: " << contextError << "\n";
        return 1;
    }
    const std::string glRenderer = context->renderer();
    std::cerr << "bench: " << glRenderer << "\n";

    // Every scene loaded first: a scene that cannot be loaded stops the bench before anything is measured.
    // A .json name is a scene file (its errors are located: file:line:column); any other name is a built-in
    // scene, whose own diagnostic names a missing mesh file and the Debian package that ships it.
    std::vector<runtime::Scene> scenes;
    for (const std::string& name : sceneNames) {
        const int errorsBefore = sink.errors();
        std::optional<runtime::Scene> scene = runtime::loadScene(name, sink);
        if (!scene || sink.errors() > errorsBefore) {
            std::cerr << "shadowfx bench: cannot load scene '" << name
                      << "' (a scene file ending in .json, or a built-in scene:";
            for (const std::string& known : runtime::builtinSceneNames()) std::cerr << " " << known;
            std::cerr << ")\n";
            return 1;
        }
        scenes.push_back(std::move(*scene));
    }
    // Ground truth, once per scene: it depends on neither the effect nor the map size.
    std::vector<runtime::SceneTruth> truths;
    truths.reserve(sceneNames.size());  // runtime::SceneTruth::light points into its own scene
    Json truthJson = Json::array();
    for (size_t i = 0; i < sceneNames.size(); ++i) {
        const std::string& name = sceneNames[i];
        runtime::Scene& scene = scenes[i];
        if (areaRadius)
            for (runtime::Light& light : scene.lights) light.areaRadius = *areaRadius;
        if (lightAngle)
            for (runtime::Light& light : scene.lights)
                if (light.type == runtime::Light::Type::Directional)
                    light.direction = directionAtAngleToView(scene.camera, *lightAngle);
        std::cerr << "bench: ground truth for " << name << " (" << scene.triangleCount()
                  << " triangles)...\n";
        runtime::SceneTruth& t = truths.emplace_back();
        std::string truthError;
        if (!runtime::measureSceneTruth(t, std::move(scene), width, height, truthOptions, sink, truthError,
                                        truthCache ? &*truthCache : nullptr)) {
            std::cerr << "shadowfx bench: " << truthError << "\n";
            return 1;
        }
        if (!t.cacheNote.empty()) std::cerr << "bench: --truth-cache: " << t.cacheNote << "\n";
        if (t.cached) std::cerr << "bench: ground truth for " << name << " read from --truth-cache\n";
        truthJson.push_back(
            Json{{"scene", t.scene.name},
                 {"soft", t.truth.soft},
                 {"samples_per_pixel", t.truth.samplesPerPixel},
                 {"rays", t.truth.raysCast},
                 {"normal_offset", truthOptions.normalOffset * std::max(t.scene.bounds().radius(), 1e-3f)},
                 {"receiver_pixels", std::count(t.receivers.begin(), t.receivers.end(), uint8_t{1})},
                 {"shadowed_receiver_pixels", shadowedReceivers(t)},
                 {"seconds", t.seconds},
                 {"cached", t.cached}});
    }

    const fx::ParseOptions baseOptions = effectParseOptions(args);

    // --set applies to each effect that has the parameter; one that no effect has is a usage error. A
    // later --set of the same parameter replaces an earlier one.
    std::vector<ParameterSweep> sweeps;
    size_t settingCount = 1;
    for (const std::string& assignment : args.all("--set")) {
        std::string sweepError;
        std::optional<ParameterSweep> sweep = parseSweep(assignment, sweepError);
        if (!sweep) {
            std::cerr << "shadowfx bench: --set " << sweepError << "\n";
            return 2;
        }
        std::erase_if(sweeps, [&](const ParameterSweep& s) { return s.parameter == sweep->parameter; });
        sweeps.push_back(std::move(*sweep));
    }
    std::string product;
    for (const ParameterSweep& sweep : sweeps) {
        settingCount *= sweep.values.size();
        product += (product.empty() ? "" : " x ") + std::to_string(sweep.values.size());
    }
    if (settingCount > kMaxSweepSettings) {
        std::cerr << "shadowfx bench: --set: " << product << " = " << settingCount << " settings, more than "
                  << kMaxSweepSettings
                  << " (each setting is a run of every effect, scene, map size and technique): sweep fewer "
                     "values or split the bench\n";
        return 2;
    }
    std::set<std::string> assignedSomewhere;

    // Compile every variant first: a broken effect stops the bench before any time is spent measuring.
    // The variants compile concurrently across the compile workers.
    std::vector<runtime::VariantRequest> requests;
    for (const std::string& effect : effects)
        for (int mapSize : mapSizes) {
            const std::string size = std::to_string(mapSize);
            requests.push_back({effect, {{"SHADOWFX_SHADOW_MAP_SIZE", size}}, ""});
            requests.push_back(
                {effect, {{"SHADOWFX_SHADOW_MAP_SIZE", size}, {"SHADOWFX_VISIBILITY", "1"}}, ""});
        }
    std::vector<runtime::CompiledVariant> compiled = runtime::compileVariants(requests, baseOptions);
    for (const runtime::CompiledVariant& c : compiled) runtime::forward(c.diagnostics, sink);
    std::map<std::pair<std::string, int>, EffectVariant> variants;
    size_t runCount = 0;
    size_t request = 0;
    for (const std::string& effect : effects) {
        for (int mapSize : mapSizes) {
            EffectVariant variant;
            const std::string size = std::to_string(mapSize);
            variant.timed = compiled[request++].effect;
            variant.visibility = compiled[request++].effect;
            if (!variant.timed || !variant.visibility || sink.errors() > 0) return 1;
            variant.exposesVisibility = !runtime::sameFragmentShaders(*variant.timed, *variant.visibility);
            for (const fx::TextureDesc& texture : variant.timed->textures)
                variant.honoursMapSize =
                    variant.honoursMapSize || (texture.width == mapSize && texture.height == mapSize);
            if (!variant.exposesVisibility && mapSize == mapSizes.front())
                std::cerr << "bench: " << effect
                          << " does not use SHADOWFX_VISIBILITY: timed only, no error figures\n";
            // An effect that ignores the size would give the same run once per size.
            if (!variant.honoursMapSize && mapSize != mapSizes.front()) continue;
            if (!variant.honoursMapSize)
                std::cerr << "bench: " << effect << " has no " << size << "x" << size
                          << " render target (SHADOWFX_SHADOW_MAP_SIZE unused): run at its own size only\n";
            std::vector<std::string> swept;
            const size_t settings = settingsFor(*variant.timed, sweeps, swept).size();
            for (const fx::CompiledTechnique& technique : variant.timed->techniques) {
                if (techniqueFilter.empty() || std::find(techniqueFilter.begin(), techniqueFilter.end(),
                                                         technique.name) != techniqueFilter.end())
                    runCount += settings * truths.size() * leaveOutModes.size();
            }
            variants.emplace(std::make_pair(effect, mapSize), std::move(variant));
        }
    }
    if (runCount == 0 && !effects.empty()) {
        std::cerr << "shadowfx bench: no technique matches --techniques\n";
        return 2;
    }
    for (const Peer& peer : peers) runCount += peer.techniques.size() * mapSizes.size() * truths.size();

    Json runs = Json::array();
    Progress progress(shard ? shard->runsOf(runCount) : runCount);
    // Each run's place in the unsharded order, counted through the same loops whether or not this shard
    // measures it (report/BenchShard.h).
    size_t nextRunIndex = 0;
    const auto measuredHere = [&](size_t runIndex) { return !shard || shard->takes(runIndex); };
    for (const std::string& effect : effects) {
        const std::string effectName = std::filesystem::path(effect).stem().string();
        for (int mapSize : mapSizes) {
            auto found = variants.find({effect, mapSize});
            if (found == variants.end()) continue;
            EffectVariant& variant = found->second;
            std::unique_ptr<runtime::EffectRenderer> timed =
                runtime::EffectRenderer::create(variant.timed, sink);
            std::unique_ptr<runtime::EffectRenderer> visibility =
                runtime::EffectRenderer::create(variant.visibility, sink);
            if (!timed || !visibility) return 1;
            // Each setting of the sweeps is its own set of runs; its label names it in every output.
            std::vector<std::string> swept;
            for (const Setting& setting : settingsFor(*variant.timed, sweeps, swept)) {
                for (const auto& [name, value] : setting) {
                    if (!timed->setParameterFromText(name, value, sink) ||
                        !visibility->setParameterFromText(name, value, sink))
                        return 1;
                    assignedSomewhere.insert(name);
                }
                const std::string label = settingLabel(setting, swept);
                for (const runtime::SceneTruth& t : truths) {
                    // The footprint of the map this effect renders: its parameterization of the light.
                    runtime::FrameOptions fitOptions;
                    fitOptions.width = width;
                    fitOptions.height = height;
                    const std::optional<runtime::LightFit> fit =
                        timed->lightFit(t.scene, t.light->name, fitOptions);
                    const runtime::Bounds bounds = t.scene.bounds();
                    // A cascaded map or a cube map: each receiver in the texels of its own cascade's or
                    // face's tile.
                    const runtime::AliasingMeasure aliasing =
                        fit ? runtime::fitAliasing(t.gbuffer, t.receivers, t.scene.camera.view(), *fit,
                                                   mapSize)
                            : runtime::perspectiveAliasing(t.gbuffer, t.receivers, t.light->view(bounds),
                                                           t.light->projection(bounds), mapSize);
                    for (const fx::CompiledTechnique& technique : variant.timed->techniques) {
                        if (!techniqueFilter.empty() &&
                            std::find(techniqueFilter.begin(), techniqueFilter.end(), technique.name) ==
                                techniqueFilter.end())
                            continue;
                        // Leave-out on before off: a frame without leave-out leaves maps that an "on" run's
                        // first frame could reuse, and that first frame is meant to find nothing cached.
                        for (const bool leaveOut : leaveOutModes) {
                            const size_t runIndex = nextRunIndex++;
                            if (!measuredHere(runIndex)) continue;
                            progress.show(effectName + " " + technique.name +
                                          (label.empty() ? "" : " " + label) + " on " + t.scene.name +
                                          ", map " + std::to_string(mapSize) +
                                          (leaveOut ? "" : ", no leave-out"));
                            runtime::FrameOptions options;
                            options.width = width;
                            options.height = height;
                            options.technique = technique.name;
                            options.timePasses = true;
                            options.leaveOut = leaveOut;
                            options.batching = !args.flag("--no-batching");
                            // Full cost first: its first frame finds nothing cached. Without leave-out
                            // nothing is reused either way, and the one set of frames is both.
                            runtime::FrameOptions fullOptions = options;
                            fullOptions.reuseTargets = false;
                            TimedFrames full, steady;
                            const bool ok = timeFrames(*timed, t.scene, fullOptions, warmup, frames,
                                                       cameraOrbit, sink, full) &&
                                            (!leaveOut || timeFrames(*timed, t.scene, options, warmup, frames,
                                                                     cameraOrbit, sink, steady));
                            if (!ok) {
                                progress.end();
                                return 1;
                            }
                            if (!leaveOut) steady = full;
                            // The shaded frame the error image is drawn over: at the scene's own camera.
                            if (cameraOrbit != 0.0f) {
                                runtime::FrameOptions stillOptions = options;
                                stillOptions.timePasses = false;
                                if (!timed->render(t.scene, stillOptions, sink) || sink.errors() > 0) {
                                    progress.end();
                                    return 1;
                                }
                            }
                            const runtime::FrameImage shaded = timed->readFrame();

                            Json record{{"run_index", runIndex},
                                        {"effect", effect},
                                        {"effect_name", effectName},
                                        {"peer", nullptr},
                                        {"technique", technique.name},
                                        {"scene", t.scene.name},
                                        {"map_size", mapSize},
                                        {"map_size_honoured", variant.honoursMapSize},
                                        {"width", width},
                                        {"height", height},
                                        {"gl_renderer", glRenderer},
                                        {"frames", frames},
                                        {"warmup_frames", warmup},
                                        {"leave_out", leaveOut},
                                        {"camera_orbit_degrees_per_frame", cameraOrbit},
                                        {"first_frame_ms", full.firstFrameMs}};
                            if (!label.empty()) {
                                Json values = Json::object();
                                for (const auto& [name, value] : setting)
                                    if (std::find(swept.begin(), swept.end(), name) != swept.end())
                                        values[name] = value;
                                record["setting"] = values;
                            }
                            // The steady state keeps the fields' names of schema 1; the full cost sits
                            // beside.
                            const Json steadyJson = timingJson(steady);
                            for (const auto& [key, value] : steadyJson.items()) record[key] = value;
                            record["full_cost"] = timingJson(full);
                            record["aliasing"] = Json{{"max_texel_footprint_px", aliasing.maxFootprint},
                                                      {"mean_texel_footprint_px", aliasing.meanFootprint},
                                                      {"p95_texel_footprint_px", aliasing.p95Footprint},
                                                      {"pixels", aliasing.pixels}};
                            record["ground_truth"] =
                                Json{{"soft", t.truth.soft}, {"samples_per_pixel", t.truth.samplesPerPixel}};
                            record["error"] = nullptr;
                            record["error_image"] = nullptr;
                            if (variant.exposesVisibility) {
                                runtime::FrameOptions visibilityOptions = options;
                                visibilityOptions.timePasses = false;
                                const std::optional<runtime::VisibilityScore> score =
                                    runtime::scoreVisibility(*visibility, t, t.truth, visibilityOptions,
                                                             sink);
                                if (!score || sink.errors() > 0) {
                                    progress.end();
                                    return 1;
                                }
                                const std::vector<float>& effectVisibility = score->visibility;
                                const runtime::ShadowErrors& errors = score->errors;
                                record["error"] = errorJson(errors);
                                const std::string image =
                                    "errors/" +
                                    safeName(effectName + "_" + technique.name + "_" + t.scene.name + "_" +
                                             std::to_string(mapSize) + (label.empty() ? "" : "_" + label)) +
                                    ".png";
                                std::string writeError;
                                if (runtime::writePng(runtime::errorImage(shaded, t.truth.visibility,
                                                                          effectVisibility, t.receivers),
                                                      (outDir / image).string(), writeError)) {
                                    record["error_image"] = image;
                                } else {
                                    std::cerr << "\nbench: " << writeError << "\n";
                                }
                            }
                            runs.push_back(std::move(record));
                        }
                    }
                }
            }
        }
    }
    // [SECTION] Peers: the same scenes, map sizes, frame counts and truth; the peer's frame is scored as an
    // effect's visibility frame is.
    for (const Peer& peer : peers) {
        const std::filesystem::path workDir = outDir / "peers" / peer.name;
        std::filesystem::create_directories(workDir, fsError);
        for (int mapSize : mapSizes) {
            for (size_t scene = 0; scene < truths.size(); ++scene) {
                const runtime::SceneTruth& t = truths[scene];
                for (const std::string& technique : peer.techniques) {
                    const size_t runIndex = nextRunIndex++;
                    if (!measuredHere(runIndex)) continue;
                    progress.show(peer.name + " " + technique + " on " + t.scene.name + ", map " +
                                  std::to_string(mapSize));
                    PeerRequest request{
                        peer.program, sceneNames[scene], technique, mapSize, width, height, frames, warmup};
                    std::string peerError;
                    const std::optional<PeerResult> result = runPeer(request, t, workDir, peerError);
                    if (!result) {
                        progress.end();
                        std::cerr << "shadowfx bench: --peers " << peer.name << ": " << peerError << "\n";
                        return 1;
                    }
                    const runtime::ShadowErrors errors =
                        runtime::compareVisibility(t.truth.visibility, result->visibility, t.receivers);
                    const Spread frameTimes = spreadOf(result->frameMs);
                    Json record{{"run_index", runIndex},
                                {"effect", peer.name},
                                {"effect_name", peer.name},
                                {"peer", peer.name + "/" + technique},
                                {"technique", technique},
                                {"scene", t.scene.name},
                                {"map_size", mapSize},
                                {"map_size_honoured", result->mapSizeHonoured},
                                {"width", width},
                                {"height", height},
                                {"gl_renderer", result->glRenderer},
                                {"peer_library_version", result->libraryVersion},
                                {"frames", frames},
                                {"warmup_frames", warmup},
                                {"leave_out", false},
                                {"camera_orbit_degrees_per_frame", 0.0},
                                {"first_frame_ms", result->frameMs.front()},
                                {"frame_time_ms", toJson(frameTimes)},
                                {"gpu_time_ms", nullptr},
                                {"work", nullptr},
                                {"passes", Json::array()},
                                {"runtime_cpu_ms", nullptr},
                                // osgShadow redraws every map each frame: its frames are full cost.
                                {"full_cost", Json{{"frame_time_ms", toJson(frameTimes)},
                                                   {"gpu_time_ms", nullptr},
                                                   {"work", nullptr},
                                                   {"passes", Json::array()},
                                                   {"runtime_cpu_ms", nullptr}}},
                                {"aliasing", nullptr},
                                {"ground_truth", Json{{"soft", t.truth.soft},
                                                      {"samples_per_pixel", t.truth.samplesPerPixel}}},
                                {"error", errorJson(errors)},
                                {"error_image", nullptr}};
                    // The error image over the peer's own frame (its visibility in grey).
                    runtime::FrameImage frame;
                    frame.width = width;
                    frame.height = height;
                    frame.rgba.resize(result->visibility.size() * 4);
                    for (size_t i = 0; i < result->visibility.size(); ++i) {
                        const auto grey = static_cast<uint8_t>(result->visibility[i] * 255.0f + 0.5f);
                        frame.rgba[i * 4] = frame.rgba[i * 4 + 1] = frame.rgba[i * 4 + 2] = grey;
                        frame.rgba[i * 4 + 3] = 255;
                    }
                    const std::string image = "errors/" +
                                              safeName(peer.name + "_" + technique + "_" + t.scene.name +
                                                       "_" + std::to_string(mapSize)) +
                                              ".png";
                    std::string writeError;
                    if (runtime::writePng(
                            runtime::errorImage(frame, t.truth.visibility, result->visibility, t.receivers),
                            (outDir / image).string(), writeError)) {
                        record["error_image"] = image;
                    } else {
                        std::cerr << "\nbench: " << writeError << "\n";
                    }
                    runs.push_back(std::move(record));
                }
            }
        }
    }
    progress.end();
    for (const ParameterSweep& sweep : sweeps) {
        if (assignedSomewhere.count(sweep.parameter) == 0) {
            std::cerr << "shadowfx bench: --set " << sweep.parameter << ": no effect has a parameter '"
                      << sweep.parameter << "'\n";
            return 2;
        }
    }

    Json results{
        {"schema_version", report::kBenchSchemaVersion},
        {"generator", "shadowfx bench"},
        {"gl_renderer", glRenderer},
        {"backend", std::string(runtime::backendName(context->backend()))},
        {"config", Json{{"effects", effects},
                        {"scenes", sceneNames},
                        {"map_sizes", mapSizes},
                        {"techniques", techniqueFilter},
                        {"set", args.all("--set")},
                        {"frames", frames},
                        {"warmup", warmup},
                        {"width", width},
                        {"height", height},
                        {"area_samples", truthOptions.areaSamples},
                        {"area_radius", areaRadius ? Json(*areaRadius) : Json(nullptr)},
                        {"light_angle_to_view", lightAngle ? Json(*lightAngle) : Json(nullptr)},
                        {"peers", splitList(args.value("--peers"))},
                        {"peer_techniques", peerTechniqueFilter},
                        {"camera_orbit_degrees_per_frame", cameraOrbit},
                        {"leave_out", leaveOutModes},
                        {"time_axis", timeAxis},
                        {"batching", !args.flag("--no-batching")}}},
        {"shard", shard ? Json{{"index", shard->index}, {"count", shard->count}, {"runs_total", runCount}}
                        : Json(nullptr)},
        {"ground_truth", truthJson},
        {"runs", runs}};
    std::string plotNote, writeError;
    if (!report::writeBenchOutputs(outDir, results, plotNote, writeError)) {
        std::cerr << "shadowfx bench: " << writeError << "\n";
        return 1;
    }
    if (!plotNote.empty()) std::cerr << "bench: " << plotNote << "\n";
    std::cout << (outDir / "report.md").string() << "\n";
    return 0;
}

}  // namespace shadowfx::cli
