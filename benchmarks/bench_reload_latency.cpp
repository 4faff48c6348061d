// bench_reload_latency: how long after saving an effect the viewer shows the change. Measures, headlessly
// (EGL or OSMesa), the path `shadowfx view` takes: the save (a temporary file renamed over the original,
// as editors do) -> FileWatcher sees it and waits out the debounce -> ReloadableEffect parses, compiles
// what the CompileCache lacks and links -> EffectRenderer renders -> the frame is read back and differs.
//
// Two edits of effects/thesis_fxcomposer.fx (copied to a temporary folder with its includes):
//   OnePassEdit  changes a constant in RenderScenePS (one stage to compile),
//   IncludeEdit  changes a constant in include/lighting.fxh (the stages that use it).
// Every edit writes a new constant, so the compile cache never has the result. Counters: median and p90
// of the latency over the edits (the goal: median under 100 ms for the one-pass edit), and the
// median reload time alone (parse + compile + link), which excludes the watcher's 50 ms debounce.
//
//   build/benchmarks/bench_reload_latency
#include <runtime/BuiltinScenes.h>
#include <runtime/EffectRenderer.h>
#include <runtime/GlContext.h>
#include <runtime/ReloadableEffect.h>
#include <runtime/Scene.h>

#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kEdits = 20;

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void saveLikeAnEditor(const fs::path& path, const std::string& text) {
    const fs::path temporary = path.string() + ".tmp~";
    std::ofstream(temporary) << text;
    fs::rename(temporary, path);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("'" + from + "' not found");
    return text.replace(at, from.size(), to);
}

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

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}
double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[std::min(values.size() - 1, static_cast<size_t>(p * values.size()))];
}

enum class Edit { OnePass, Include };

void measureEdits(benchmark::State& state, Edit edit) {
    context();
    const fs::path dir = fs::temp_directory_path() / ("shadowfx_reload_latency_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path effects = fs::path(SHADOWFX_SOURCE_DIR) / "effects";
    fs::copy(effects / "thesis_fxcomposer.fx", dir / "thesis.fx");
    fs::copy(effects / "include", dir / "include", fs::copy_options::recursive);
    const fs::path edited = edit == Edit::OnePass ? dir / "thesis.fx" : dir / "include" / "lighting.fxh";
    const std::string original = readText(edited);

    runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    runtime::FrameOptions options;
    options.width = 800;
    options.height = 600;
    runtime::ReloadableEffect effect((dir / "thesis.fx").string());
    if (!effect.reload()) {
        state.SkipWithError(effect.errorText().c_str());
        return;
    }
    fx::DiagnosticList diagnostics;
    effect.renderer()->render(scene, options, diagnostics);
    std::vector<uint8_t> previous = effect.renderer()->readFrame().rgba;

    std::vector<double> latencies, reloads, frames;
    int editIndex = 0;
    for (auto _ : state) {
        // A constant never used before: the compile cache cannot have the changed stage.
        const float factor = 0.5f + 0.02f * static_cast<float>(editIndex++);
        char constant[64];
        std::snprintf(constant, sizeof constant, "float4(%.3f, %.3f, 1, 1)", factor, factor);
        const std::string text =
            edit == Edit::OnePass
                ? replaced(original, "return Shade(IN, GetShadow(IN.LP));",
                           std::string("return Shade(IN, GetShadow(IN.LP)) * ") + constant + ";")
                : replaced(
                      original, "return lit(dot(N, L), dot(N, H), specularPower);",
                      std::string("return lit(dot(N, L), dot(N, H), specularPower) * ") + constant + ";");

        const Clock::time_point saved = Clock::now();
        saveLikeAnEditor(edited, text);
        runtime::ReloadableEffect::Result result = runtime::ReloadableEffect::Result::Unchanged;
        while (result == runtime::ReloadableEffect::Result::Unchanged) {
            result = effect.reloadIfChanged(std::chrono::milliseconds(5000));
        }
        if (result != runtime::ReloadableEffect::Result::Reloaded) {
            state.SkipWithError(("reload failed: " + effect.errorText()).c_str());
            break;
        }
        const Clock::time_point reloaded = Clock::now();
        diagnostics.clear();
        effect.renderer()->render(scene, options, diagnostics);
        std::vector<uint8_t> frame = effect.renderer()->readFrame().rgba;
        const double seconds = std::chrono::duration<double>(Clock::now() - saved).count();
        if (frame == previous) {
            state.SkipWithError("the frame after the edit did not change");
            break;
        }
        previous = std::move(frame);
        state.SetIterationTime(seconds);
        latencies.push_back(seconds * 1e3);
        const runtime::ReloadableEffect::ReloadStats& stats = effect.lastStats();
        reloads.push_back(stats.parseMs + stats.compileMs + stats.createMs);
        frames.push_back(std::chrono::duration<double, std::milli>(Clock::now() - reloaded).count());
        state.counters["stages_compiled"] = static_cast<double>(stats.cacheMisses);
    }
    state.counters["median_ms"] = median(latencies);
    state.counters["p90_ms"] = percentile(latencies, 0.9);
    state.counters["reload_median_ms"] = median(reloads);
    state.counters["frame_median_ms"] = median(frames);  // render + read back of the first new frame
    fs::remove_all(dir);
}

void OnePassEdit(benchmark::State& state) {
    measureEdits(state, Edit::OnePass);
}
void IncludeEdit(benchmark::State& state) {
    measureEdits(state, Edit::Include);
}

BENCHMARK(OnePassEdit)->Iterations(kEdits)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(IncludeEdit)->Iterations(kEdits)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
