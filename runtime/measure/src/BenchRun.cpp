// BenchRun: see BenchRun.h.
//
// [SECTION] Result records  one run's error and timing as the result records hold them
// [SECTION] Statistics      median and spread of the timed frames
// [SECTION] Runs            ground truth per scene, then effect x map size x scene x technique, then peers
//
// With a shard only the runs report/BenchShard.h deals to it are measured, each record keeping its
// run_index. With a truth cache each scene's ground truth is read from it when it was cast before
// (runtime/TruthCache.h).
#include <runtime/BenchRun.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/DiagnosticLog.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/ParameterSweep.h>
#include <runtime/PeerRun.h>
#include <runtime/Scene.h>
#include <runtime/SceneFile.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/ShadowMetrics.h>
#include <runtime/TruthCache.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

namespace runtime {

// The file's helpers in a namespace named after it: in a unity build (SHADOWFX_UNITY_LIBS) this file shares
// its translation unit with others of the library, and its safeName (which replaces '.') would be ambiguous
// with GoldenImages.cpp's runtime::safeName (which keeps it).
namespace bench_run {
namespace {

using Clock = std::chrono::steady_clock;
using report::BenchSpread;

// [SECTION] Result records

// One run's shadow error, for shadowfx's runs and the peers' alike.
report::BenchShadowError errorRecord(const ShadowErrors& errors) {
    report::BenchShadowError e;
    e.receiverPixels = errors.receiverPixels;
    e.falseShadowPixels = errors.falseShadowPixels;
    e.falseLightPixels = errors.falseLightPixels;
    e.falseShadowPercent = errors.falseShadowPercent;
    e.falseLightPercent = errors.falseLightPercent;
    e.misclassifiedPercent = errors.misclassifiedPercent;
    e.mae = errors.meanAbsoluteError;
    e.p95AbsError = errors.p95AbsoluteError;
    e.penumbraPixels = errors.penumbraPixels;
    if (errors.penumbraPixels > 0) e.penumbraMae = errors.penumbraMeanAbsoluteError;
    return e;
}

// [SECTION] Statistics

// Linear-interpolated quantiles (type 7, as numpy's default).
BenchSpread spreadOf(std::vector<double> values) {
    BenchSpread s;
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
    FrameStats counted;
};

// Renders `warmup` + `frames` frames of `scene` (the camera turned `cameraOrbit` degrees more before each)
// and the counting frame. False once a frame fails; the sink says why.
bool timeFrames(EffectRenderer& renderer, const Scene& scene, const FrameOptions& options, int warmup,
                int frames, float cameraOrbit, DiagnosticLog& sink, TimedFrames& out) {
    // One scene edited in place (the renderer's caches see only the camera move).
    Scene moving = scene;
    const auto orbitTo = [&](int step) {
        const glm::vec3 offset = scene.camera.position - scene.camera.target;
        const glm::mat4 turn =
            glm::rotate(glm::mat4(1.0f), glm::radians(cameraOrbit * step), glm::vec3(0.0f, 1.0f, 0.0f));
        moving.camera.position = scene.camera.target + glm::vec3(turn * glm::vec4(offset, 0.0f));
    };
    for (int frame = 0; frame < warmup + frames; ++frame) {
        FrameStats stats;
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
            for (const PassTiming& pass : stats.passTimings) {
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
    FrameOptions countOptions = options;
    countOptions.timePasses = false;
    countOptions.countTexels = true;
    if (cameraOrbit != 0.0f) orbitTo(warmup + frames + 1);
    return renderer.render(moving, countOptions, sink, &out.counted) && sink.errors() == 0;
}

// The times, work and passes of one set of timed frames.
report::BenchTiming timingRecord(const TimedFrames& t) {
    const FrameStats& counted = t.counted;
    report::BenchTiming timing;
    for (size_t p = 0; p < t.passNames.size(); ++p) {
        report::BenchPassTiming& pass = timing.passes.emplace_back();
        pass.name = t.passNames[p];
        pass.gpuMs = spreadOf(t.passGpu[p]).median;
        pass.cpuMs = spreadOf(t.passCpu[p]).median;
        pass.draws = t.passDraws[p];
        if (p < counted.passes.size()) {
            const PassStats& work = counted.passes[p];
            pass.work = report::BenchPassWork{work.leftOut, work.culled, work.triangles, work.texelsWritten};
        }
    }
    timing.frameTimeMs = spreadOf(t.frameMs);
    timing.gpuTimeMs = spreadOf(t.gpuMs);
    timing.work = report::BenchFrameWork{counted.passesRun, counted.passesLeftOut, counted.draws,
                                         counted.culled, counted.triangles};
    timing.runtimeCpuMs = report::BenchRuntimeCpu{spreadOf(t.script).median, spreadOf(t.binding).median,
                                                  spreadOf(t.preshader).median, spreadOf(t.gl).median,
                                                  spreadOf(t.overhead).median};
    return timing;
}

// Receivers the ground truth classifies as shadowed: what a blank (all-lit) frame would get wrong.
int64_t shadowedReceivers(const SceneTruth& t) {
    int64_t count = 0;
    for (size_t i = 0; i < t.receivers.size() && i < t.truth.visibility.size(); ++i)
        count += t.receivers[i] && t.truth.visibility[i] < kShadowedBelow ? 1 : 0;
    return count;
}

// The direction at `degrees` from the camera's view direction V, turned toward straight down: cos G V +
// sin G D, D the downward direction perpendicular to V (any horizontal one if V is vertical).
glm::vec3 directionAtAngleToView(const Camera& camera, float degrees) {
    const glm::vec3 view = glm::normalize(camera.target - camera.position);
    glm::vec3 down = glm::vec3(0.0f, -1.0f, 0.0f) - glm::dot(glm::vec3(0.0f, -1.0f, 0.0f), view) * view;
    if (glm::length(down) < 1e-3f) down = glm::cross(view, glm::vec3(1.0f, 0.0f, 0.0f));
    const float g = glm::radians(degrees);
    return glm::normalize(std::cos(g) * view + std::sin(g) * glm::normalize(down));
}

}  // namespace
}  // namespace bench_run

BenchResult runBench(const BenchOptions& o, const BenchLog& log) {
    using namespace bench_run;
    const auto note = [&](const std::string& text) {
        if (log.note) log.note(text);
    };
    const auto usageError = [](std::string why) {
        return BenchResult{BenchStatus::UsageError, std::move(why), {}};
    };
    const auto failed = [](std::string why) { return BenchResult{BenchStatus::Failed, std::move(why), {}}; };
    const std::vector<std::string>& effects = o.effects;
    const std::vector<std::string>& sceneNames = o.scenes;
    const std::vector<int>& mapSizes = o.mapSizes;
    // A host file draws one frame whatever the technique: one run, named after what draws the frame.
    const std::vector<std::string> techniqueFilter =
        o.host && o.techniques.empty() ? std::vector<std::string>{o.host->frame.back().technique}
                                       : o.techniques;
    const std::vector<bool>& leaveOutModes = o.leaveOutModes;
    const int frames = o.frames, warmup = o.warmup, width = o.width, height = o.height;
    const float cameraOrbit = o.cameraOrbit;
    const std::optional<report::BenchShard>& shard = o.shard;
    std::optional<TruthCache> truthCache;
    if (!o.truthCacheDir.empty()) truthCache.emplace(o.truthCacheDir);

    const std::filesystem::path& outDir = o.outDir;
    std::error_code fsError;
    std::filesystem::create_directories(outDir / "errors", fsError);
    if (fsError) return failed("cannot create " + outDir.string() + ": " + fsError.message());

    // Each distinct diagnostic once: the same warning comes back every frame of every run.
    DiagnosticLog sink(log.diagnostic);
    std::unique_ptr<GlContext> ownContext;
    GlContext* context = o.context;
    if (context) {
        context->makeCurrent();
    } else {
        ContextOptions contextOptions;
        contextOptions.backend = o.backend;
        std::string contextError;
        ownContext = createContext(contextOptions, contextError);
        if (!ownContext) return failed(contextError);
        context = ownContext.get();
    }
    const std::string glRenderer = context->renderer();
    note(glRenderer);

    // Every scene loaded first: a scene that cannot be loaded stops the bench before anything is measured.
    // A .json name is a scene file (its errors are located: file:line:column); any other name is a built-in
    // scene, whose own diagnostic names a missing mesh file and the Debian package that ships it.
    std::vector<Scene> scenes;
    for (const std::string& name : sceneNames) {
        const int errorsBefore = sink.errors();
        std::optional<Scene> scene = loadScene(name, sink);
        if (!scene || sink.errors() > errorsBefore) {
            std::string why =
                "cannot load scene '" + name + "' (a scene file ending in .json, or a built-in scene:";
            for (const std::string& known : builtinSceneNames()) why += " " + known;
            return failed(why + ")");
        }
        scenes.push_back(std::move(*scene));
    }
    // Ground truth, once per scene: it depends on neither the effect nor the map size.
    report::BenchResults results;
    std::vector<SceneTruth> truths;
    truths.reserve(sceneNames.size());  // SceneTruth::light points into its own scene
    for (size_t i = 0; i < sceneNames.size(); ++i) {
        const std::string& name = sceneNames[i];
        Scene& scene = scenes[i];
        if (o.areaRadius)
            for (Light& light : scene.lights) light.areaRadius = *o.areaRadius;
        if (o.lightAngleToView)
            for (Light& light : scene.lights)
                if (light.type == Light::Type::Directional)
                    light.direction = directionAtAngleToView(scene.camera, *o.lightAngleToView);
        note("ground truth for " + name + " (" + std::to_string(scene.triangleCount()) + " triangles)...");
        SceneTruth& t = truths.emplace_back();
        std::string truthError;
        if (!measureSceneTruth(t, std::move(scene), width, height, o.truth, sink, truthError,
                               truthCache ? &*truthCache : nullptr))
            return failed(truthError);
        if (!t.cacheNote.empty()) note("--truth-cache: " + t.cacheNote);
        if (t.cached) note("ground truth for " + name + " read from --truth-cache");
        results.groundTruth.push_back({t.scene.name, t.truth.soft, t.truth.samplesPerPixel, t.truth.raysCast,
                                       o.truth.normalOffset * std::max(t.scene.bounds().radius(), 1e-3f),
                                       std::count(t.receivers.begin(), t.receivers.end(), uint8_t{1}),
                                       shadowedReceivers(t), t.seconds, t.cached});
    }

    const fx::ParseOptions& baseOptions = o.parseOptions;

    // --set applies to each effect that has the parameter; one that no effect has is a usage error. A
    // later --set of the same parameter replaces an earlier one.
    std::vector<ParameterSweep> sweeps;
    size_t settingCount = 1;
    for (const std::string& assignment : o.set) {
        std::string sweepError;
        std::optional<ParameterSweep> sweep = parseSweep(assignment, sweepError);
        if (!sweep) return usageError("--set " + sweepError);
        std::erase_if(sweeps, [&](const ParameterSweep& s) { return s.parameter == sweep->parameter; });
        sweeps.push_back(std::move(*sweep));
    }
    std::string product;
    for (const ParameterSweep& sweep : sweeps) {
        settingCount *= sweep.values.size();
        product += (product.empty() ? "" : " x ") + std::to_string(sweep.values.size());
    }
    if (settingCount > kMaxSweepSettings)
        return usageError("--set: " + product + " = " + std::to_string(settingCount) +
                          " settings, more than " + std::to_string(kMaxSweepSettings) +
                          " (each setting is a run of every effect, scene, map size and technique): sweep "
                          "fewer values or split the bench");
    std::set<std::string> assignedSomewhere;

    // Compile every variant first: a broken effect stops the bench before any time is spent measuring.
    // The variants compile concurrently across the compile workers.
    std::vector<VariantRequest> requests;
    for (const std::string& effect : effects)
        for (int mapSize : mapSizes) {
            const std::string size = std::to_string(mapSize);
            requests.push_back({effect, {{"SHADOWFX_SHADOW_MAP_SIZE", size}}, ""});
            requests.push_back(
                {effect, {{"SHADOWFX_SHADOW_MAP_SIZE", size}, {"SHADOWFX_VISIBILITY", "1"}}, ""});
        }
    std::vector<CompiledVariant> compiled = compileVariants(requests, baseOptions);
    for (const CompiledVariant& c : compiled) forward(c.diagnostics, sink);
    std::map<std::pair<std::string, int>, EffectVariant> variants;
    size_t runCount = 0;
    size_t request = 0;
    for (const std::string& effect : effects) {
        for (int mapSize : mapSizes) {
            EffectVariant variant;
            const std::string size = std::to_string(mapSize);
            variant.timed = compiled[request++].effect;
            variant.visibility = compiled[request++].effect;
            if (!variant.timed || !variant.visibility || sink.errors() > 0) return failed("");
            variant.exposesVisibility =
                !sameFragmentShaders(*variant.timed, *variant.visibility) || (o.host && o.host->visibility);
            for (const fx::TextureDesc& texture : variant.timed->textures)
                variant.honoursMapSize =
                    variant.honoursMapSize || (texture.width == mapSize && texture.height == mapSize);
            if (!variant.exposesVisibility && mapSize == mapSizes.front())
                note(effect + " does not use SHADOWFX_VISIBILITY: timed only, no error figures");
            // An effect that ignores the size would give the same run once per size.
            if (!variant.honoursMapSize && mapSize != mapSizes.front()) continue;
            if (!variant.honoursMapSize)
                note(effect + " has no " + size + "x" + size +
                     " render target (SHADOWFX_SHADOW_MAP_SIZE unused): run at its own size only");
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
    if (runCount == 0 && !effects.empty()) return usageError("no technique matches --techniques");
    for (const Peer& peer : o.peers) runCount += peer.techniques.size() * mapSizes.size() * truths.size();

    std::vector<report::BenchRunRecord>& runs = results.runs;
    const size_t runsHere = shard ? shard->runsOf(runCount) : runCount;
    size_t runsDone = 0;
    const auto progress = [&](const std::string& run) {
        if (log.progress) log.progress(++runsDone, runsHere, run);
    };
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
            std::unique_ptr<EffectRenderer> timed = EffectRenderer::create(variant.timed, sink);
            std::unique_ptr<EffectRenderer> visibility = EffectRenderer::create(variant.visibility, sink);
            if (!timed || !visibility ||
                (o.host && (!timed->setHostFile(o.host, sink) || !visibility->setHostFile(o.host, sink))))
                return failed("");
            // Each setting of the sweeps is its own set of runs; its label names it in every output.
            std::vector<std::string> swept;
            for (const Setting& setting : settingsFor(*variant.timed, sweeps, swept)) {
                for (const auto& [name, value] : setting) {
                    if (!timed->setParameterFromText(name, value, sink) ||
                        !visibility->setParameterFromText(name, value, sink))
                        return failed("");
                    assignedSomewhere.insert(name);
                }
                const std::string label = settingLabel(setting, swept);
                for (const SceneTruth& t : truths) {
                    // The footprint of the map this effect renders: its parameterization of the light.
                    FrameOptions fitOptions;
                    fitOptions.width = width;
                    fitOptions.height = height;
                    const std::optional<LightFit> fit = timed->lightFit(t.scene, t.light->name, fitOptions);
                    const Bounds bounds = t.scene.bounds();
                    // A cascaded map or a cube map: each receiver in the texels of its own cascade's or
                    // face's tile.
                    const AliasingMeasure aliasing =
                        fit ? fitAliasing(t.gbuffer, t.receivers, t.scene.camera.view(), *fit, mapSize)
                            : perspectiveAliasing(t.gbuffer, t.receivers, t.light->view(bounds),
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
                            progress(effectName + " " + technique.name + (label.empty() ? "" : " " + label) +
                                     " on " + t.scene.name + ", map " + std::to_string(mapSize) +
                                     (leaveOut ? "" : ", no leave-out"));
                            FrameOptions options;
                            options.width = width;
                            options.height = height;
                            options.technique = technique.name;
                            options.timePasses = true;
                            options.leaveOut = leaveOut;
                            options.batching = o.batching;
                            // Full cost first: its first frame finds nothing cached. Without leave-out
                            // nothing is reused either way, and the one set of frames is both.
                            FrameOptions fullOptions = options;
                            fullOptions.reuseTargets = false;
                            TimedFrames full, steady;
                            const bool ok = timeFrames(*timed, t.scene, fullOptions, warmup, frames,
                                                       cameraOrbit, sink, full) &&
                                            (!leaveOut || timeFrames(*timed, t.scene, options, warmup, frames,
                                                                     cameraOrbit, sink, steady));
                            if (!ok) return failed("");
                            if (!leaveOut) steady = full;
                            // The shaded frame the error image is drawn over: at the scene's own camera.
                            if (cameraOrbit != 0.0f) {
                                FrameOptions stillOptions = options;
                                stillOptions.timePasses = false;
                                if (!timed->render(t.scene, stillOptions, sink) || sink.errors() > 0)
                                    return failed("");
                            }
                            const FrameImage shaded = timed->readFrame();

                            report::BenchRunRecord record;
                            record.runIndex = runIndex;
                            record.effect = effect;
                            record.effectName = effectName;
                            record.technique = technique.name;
                            record.scene = t.scene.name;
                            record.mapSize = mapSize;
                            record.mapSizeHonoured = variant.honoursMapSize;
                            record.width = width;
                            record.height = height;
                            record.glRenderer = glRenderer;
                            record.frames = frames;
                            record.warmupFrames = warmup;
                            record.leaveOut = leaveOut;
                            record.cameraOrbitDegreesPerFrame = cameraOrbit;
                            record.firstFrameMs = full.firstFrameMs;
                            if (!label.empty()) {
                                record.setting.emplace();
                                for (const auto& [name, value] : setting)
                                    if (std::find(swept.begin(), swept.end(), name) != swept.end())
                                        record.setting->emplace_back(name, value);
                            }
                            record.steady = timingRecord(steady);
                            record.fullCost = timingRecord(full);
                            record.aliasing =
                                report::BenchAliasing{aliasing.maxFootprint, aliasing.meanFootprint,
                                                      aliasing.p95Footprint, aliasing.pixels};
                            record.truthSoft = t.truth.soft;
                            record.truthSamplesPerPixel = t.truth.samplesPerPixel;
                            if (variant.exposesVisibility) {
                                FrameOptions visibilityOptions = options;
                                visibilityOptions.timePasses = false;
                                const std::optional<VisibilityScore> score =
                                    scoreVisibility(*visibility, t, t.truth, visibilityOptions, sink);
                                if (!score || sink.errors() > 0) return failed("");
                                const std::vector<float>& effectVisibility = score->visibility;
                                const ShadowErrors& errors = score->errors;
                                record.error = errorRecord(errors);
                                const std::string image =
                                    "errors/" +
                                    safeName(effectName + "_" + technique.name + "_" + t.scene.name + "_" +
                                             std::to_string(mapSize) + (label.empty() ? "" : "_" + label)) +
                                    ".png";
                                std::string writeError;
                                if (writePng(
                                        errorImage(shaded, t.truth.visibility, effectVisibility, t.receivers),
                                        (outDir / image).string(), writeError)) {
                                    record.errorImage = image;
                                } else {
                                    note(writeError);
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
    for (const Peer& peer : o.peers) {
        const std::filesystem::path workDir = outDir / "peers" / peer.name;
        std::filesystem::create_directories(workDir, fsError);
        for (int mapSize : mapSizes) {
            for (size_t scene = 0; scene < truths.size(); ++scene) {
                const SceneTruth& t = truths[scene];
                for (const std::string& technique : peer.techniques) {
                    const size_t runIndex = nextRunIndex++;
                    if (!measuredHere(runIndex)) continue;
                    progress(peer.name + " " + technique + " on " + t.scene.name + ", map " +
                             std::to_string(mapSize));
                    PeerRequest request{
                        peer.program, sceneNames[scene], technique, mapSize, width, height, frames, warmup};
                    std::string peerError;
                    const std::optional<PeerResult> result = runPeer(request, t, workDir, peerError);
                    if (!result) return failed("--peers " + peer.name + ": " + peerError);
                    const ShadowErrors errors =
                        compareVisibility(t.truth.visibility, result->visibility, t.receivers);
                    report::BenchRunRecord record;
                    record.runIndex = runIndex;
                    record.effect = peer.name;
                    record.effectName = peer.name;
                    record.peer = peer.name + "/" + technique;
                    record.technique = technique;
                    record.scene = t.scene.name;
                    record.mapSize = mapSize;
                    record.mapSizeHonoured = result->mapSizeHonoured;
                    record.width = width;
                    record.height = height;
                    record.glRenderer = result->glRenderer;
                    record.peerLibraryVersion = result->libraryVersion;
                    record.frames = frames;
                    record.warmupFrames = warmup;
                    record.firstFrameMs = result->frameMs.front();
                    // Only frame times: osgShadow redraws every map each frame, so its frames are full cost.
                    record.steady.frameTimeMs = spreadOf(result->frameMs);
                    record.fullCost = record.steady;
                    record.truthSoft = t.truth.soft;
                    record.truthSamplesPerPixel = t.truth.samplesPerPixel;
                    record.error = errorRecord(errors);
                    // The error image over the peer's own frame (its visibility in grey).
                    FrameImage frame;
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
                    if (writePng(errorImage(frame, t.truth.visibility, result->visibility, t.receivers),
                                 (outDir / image).string(), writeError)) {
                        record.errorImage = image;
                    } else {
                        note(writeError);
                    }
                    runs.push_back(std::move(record));
                }
            }
        }
    }
    for (const ParameterSweep& sweep : sweeps)
        if (assignedSomewhere.count(sweep.parameter) == 0)
            return usageError("--set " + sweep.parameter + ": no effect has a parameter '" + sweep.parameter +
                              "'");

    results.glRenderer = glRenderer;
    results.backend = std::string(backendName(context->backend()));
    report::BenchConfig& config = results.config;
    config.effects = effects;
    config.scenes = sceneNames;
    config.mapSizes = mapSizes;
    config.techniques = techniqueFilter;
    config.set = o.set;
    config.frames = frames;
    config.warmup = warmup;
    config.width = width;
    config.height = height;
    config.areaSamples = o.truth.areaSamples;
    config.areaRadius = o.areaRadius;
    config.lightAngleToView = o.lightAngleToView;
    config.peers = o.peerNames;
    config.peerTechniques = o.peerTechniqueFilter;
    config.cameraOrbitDegreesPerFrame = cameraOrbit;
    config.leaveOut = leaveOutModes;
    config.timeAxis = o.timeAxis;
    config.batching = o.batching;
    results.shard = shard;
    results.runsTotal = runCount;
    return BenchResult{BenchStatus::Measured, "", std::move(results)};
}

}  // namespace runtime
