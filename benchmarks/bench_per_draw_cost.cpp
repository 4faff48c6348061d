// bench_per_draw_cost: what the effect layer costs. The thesis effect's `main` frame (effects/
// thesis_fxcomposer.fx) rendered by shadowfx (EffectRenderer, leave-out culling on, nothing reused: the
// full cost bench reports), once with batching (one instanced draw per mesh, FrameOptions::batching) and
// once without (every object alone), and by the same frame written by hand against GL 4.5
// (HandWrittenFrame.h: the same GLSL, meshes, culled lists and states, object by object), rotating the
// order frame by frame so that all three see the same machine load. Per scene (boxes, forest-fifth,
// forest) the counters are the medians of
//   frame_ms / single_frame_ms / hand_frame_ms   wall time of one frame, glFinish included;
//   cpu_ms / single_cpu_ms / hand_cpu_ms         CPU time of the calling thread until the frame is issued
//                                                (before glFinish): on llvmpipe this includes the driver's
//                                                vertex work;
//   frame_ratio, cpu_ratio (single_…)            shadowfx batched (unbatched) ÷ hand-written;
//   runtime_cpu_ms, single_runtime_cpu_ms        the runtime's own CPU time (script, binding, preshaders:
//                                                FrameStats::cpu less its GL share, from extra frames with
//                                                FrameOptions::timePasses);
//   map_draws, scene_draws, single_draws, hand_draws   draws per pass (batched) and per frame.
//
//   build/benchmarks/bench_per_draw_cost [--width=W --height=H --map-size=N --frames=N]
//   [--only=shadowfx|single|hand] (default 512x512, a 2048² map, 10 frames per side; --width=128
//   --height=128 --map-size=512 for a quick run on llvmpipe; --only renders one side, for perf record)
#include "HandWrittenFrame.h"

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlApi.h>
#include <runtime/GlContext.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Settings {
    int width = 512;
    int height = 512;
    int mapSize = 2048;
    int frames = 10;
    std::string only;  // "shadowfx", "single" or "hand": render that side alone (for a profiler), no ratios
} gSettings;

runtime::GlContext& context() {
    static std::unique_ptr<runtime::GlContext> shared = [] {
        std::string error;
        auto created = runtime::createContext(runtime::ContextOptions{}, error);
        if (!created) throw std::runtime_error("no GL context: " + error);
        return created;
    }();
    shared->makeCurrent();
    return *shared;
}

double threadCpuMs() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) * 1e-6;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

struct Sample {
    double wallMs = 0, cpuMs = 0;
};

template <typename Issue>
Sample timeFrame(Issue&& issue) {
    const auto start = Clock::now();
    const double cpuStart = threadCpuMs();
    issue();
    const double cpu = threadCpuMs() - cpuStart;
    gl::Finish();
    return {std::chrono::duration<double, std::milli>(Clock::now() - start).count(), cpu};
}

void PerDrawCost(benchmark::State& state, const std::string& sceneName) {
    context();
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene(sceneName);
    if (!scene) {
        state.SkipWithError(("no scene " + sceneName).c_str());
        return;
    }
    fx::DiagnosticList diagnostics;
    fx::ParseOptions parse;
    parse.defines = {{"SHADOWFX_SHADOW_MAP_SIZE", std::to_string(gSettings.mapSize)}};
    auto effect =
        fx::parseEffectFile(SHADOWFX_SOURCE_DIR "/effects/thesis_fxcomposer.fx", parse, diagnostics);
    std::shared_ptr<const fx::CompiledEffect> compiled =
        effect ? fx::compileEffect(effect, fx::CompileOptions{}, diagnostics) : nullptr;
    std::unique_ptr<runtime::EffectRenderer> renderer =
        compiled ? runtime::EffectRenderer::create(compiled, diagnostics) : nullptr;
    std::string error;
    std::unique_ptr<shadowfx::baseline::HandWrittenFrame> hand =
        compiled ? shadowfx::baseline::HandWrittenFrame::create(*compiled, *scene, gSettings.width,
                                                                gSettings.height, error)
                 : nullptr;
    if (!renderer || !hand) {
        state.SkipWithError((diagnostics.str() + error).c_str());
        return;
    }
    runtime::FrameOptions options;
    options.width = gSettings.width;
    options.height = gSettings.height;
    options.technique = "main";
    options.reuseTargets = false;
    runtime::FrameOptions single = options;
    single.batching = false;
    for (int warm = 0; warm < 2; ++warm) {
        renderer->render(*scene, options, diagnostics);
        renderer->render(*scene, single, diagnostics);
        hand->render(*scene);
        gl::Finish();
    }
    std::vector<double> wall, cpu, singleWall, singleCpu, handWall, handCpu;
    int rotation = 0;
    for (auto _ : state) {
        const auto batchedFrame = [&] {
            return timeFrame([&] { renderer->render(*scene, options, diagnostics); });
        };
        const auto singleFrame = [&] {
            return timeFrame([&] { renderer->render(*scene, single, diagnostics); });
        };
        const auto handFrame = [&] { return timeFrame([&] { hand->render(*scene); }); };
        if (!gSettings.only.empty()) {
            const Sample alone = gSettings.only == "hand"     ? handFrame()
                                 : gSettings.only == "single" ? singleFrame()
                                                              : batchedFrame();
            state.SetIterationTime(alone.wallMs * 1e-3);
            continue;
        }
        // Rotate the order so that none always runs right after another's GPU work.
        Sample ours, alone, theirs;
        for (int k = 0; k < 3; ++k) {
            switch ((rotation + k) % 3) {
                case 0:
                    ours = batchedFrame();
                    break;
                case 1:
                    alone = singleFrame();
                    break;
                default:
                    theirs = handFrame();
                    break;
            }
        }
        rotation = (rotation + 1) % 3;
        wall.push_back(ours.wallMs);
        cpu.push_back(ours.cpuMs);
        singleWall.push_back(alone.wallMs);
        singleCpu.push_back(alone.cpuMs);
        handWall.push_back(theirs.wallMs);
        handCpu.push_back(theirs.cpuMs);
        state.SetIterationTime((ours.wallMs + alone.wallMs + theirs.wallMs) * 1e-3);
    }
    // The runtime's own share, from frames that time it (their queries make them unfit for the above).
    const auto ownCpu = [&](const runtime::FrameOptions& frameOptions, runtime::FrameStats& stats) {
        std::vector<double> own;
        runtime::FrameOptions timed = frameOptions;
        timed.timePasses = true;
        for (int i = 0; i < 5; ++i) {
            renderer->render(*scene, timed, diagnostics, &stats);
            own.push_back(static_cast<double>(stats.cpu.totalNs - stats.cpu.glNs) * 1e-6);
        }
        return median(own);
    };
    runtime::FrameStats stats, singleStats;
    const double runtimeCpu = ownCpu(options, stats);
    const double singleRuntimeCpu = ownCpu(single, singleStats);
    if (diagnostics.hasErrors()) state.SkipWithError(diagnostics.str().c_str());
    if (wall.empty()) return;
    const double frameMs = median(wall), singleFrameMs = median(singleWall), handFrameMs = median(handWall);
    const double cpuMs = median(cpu), singleCpuMs = median(singleCpu), handCpuMs = median(handCpu);
    state.counters["frame_ms"] = frameMs;
    state.counters["single_frame_ms"] = singleFrameMs;
    state.counters["hand_frame_ms"] = handFrameMs;
    state.counters["frame_ratio"] = frameMs / handFrameMs;
    state.counters["single_frame_ratio"] = singleFrameMs / handFrameMs;
    state.counters["cpu_ms"] = cpuMs;
    state.counters["single_cpu_ms"] = singleCpuMs;
    state.counters["hand_cpu_ms"] = handCpuMs;
    state.counters["cpu_ratio"] = cpuMs / handCpuMs;
    state.counters["single_cpu_ratio"] = singleCpuMs / handCpuMs;
    state.counters["runtime_cpu_ms"] = runtimeCpu;
    state.counters["single_runtime_cpu_ms"] = singleRuntimeCpu;
    for (const runtime::PassStats& pass : stats.passes) {
        if (pass.pass == "RenderShadowMap") state.counters["map_draws"] = pass.draws;
        if (pass.pass == "RenderScene") state.counters["scene_draws"] = pass.draws;
    }
    state.counters["draws"] = stats.draws;
    state.counters["single_draws"] = singleStats.draws;
    state.counters["hand_draws"] = hand->shadowDraws() + hand->sceneDraws();
}

// --width=W --height=H --map-size=N --frames=N, taken out before Google Benchmark reads the rest.
void readSettings(int& argc, char** argv) {
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        const auto value = [&](const char* flag, int& into) {
            const size_t length = std::strlen(flag);
            if (std::strncmp(argv[i], flag, length) != 0 || argv[i][length] != '=') return false;
            into = std::max(1, std::atoi(argv[i] + length + 1));
            return true;
        };
        if (std::strncmp(argv[i], "--only=", 7) == 0) {
            gSettings.only = argv[i] + 7;
            continue;
        }
        if (value("--width", gSettings.width) || value("--height", gSettings.height) ||
            value("--map-size", gSettings.mapSize) || value("--frames", gSettings.frames))
            continue;
        argv[kept++] = argv[i];
    }
    argc = kept;
}

}  // namespace

int main(int argc, char** argv) {
    readSettings(argc, argv);
    for (const char* scene : {"boxes", "forest-fifth", "forest"})
        benchmark::RegisterBenchmark(
            ("PerDrawCost/" + std::string(scene)).c_str(),
            [name = std::string(scene)](benchmark::State& state) { PerDrawCost(state, name); })
            ->Iterations(gSettings.frames)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
