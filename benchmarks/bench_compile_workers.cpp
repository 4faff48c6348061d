// bench_compile_workers: what the compile workers (fx/CompileWorkers.h) cost and give, in one run.
//   ColdCompile/InProcess  parse + compile every shipped effect (effects/*.fx), glslang and SPIRV-Cross in
//                          this process, one stage after another (no compile cache).
//   ColdCompile/Pool       the same through the worker pool (one worker per core, already started):
//                          the stages of an effect compile concurrently.
//   ColdCompile/PoolEffectsConcurrently  the same, the effects themselves compiled from as many threads
//                          as there are workers, as `check` and `bench` could.
//   StageRoundTrip/...     one small stage (the fragment shader of plain_lit.fx) in-process and through
//                          one warm worker: the difference is the protocol and process hop a reload pays.
//   PoolStartup            starting a fresh pool and compiling that one stage (the first compile of a run).
// Medians and ratios go into docs/results/ with the commit:
//   build/benchmarks/bench_compile_workers --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <fx/CompileWorkers.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include "StageCompile.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<std::string> shippedEffects() {
    std::vector<std::string> paths;
    for (const fs::directory_entry& e : fs::directory_iterator(fs::path(SHADOWFX_SOURCE_DIR) / "effects"))
        if (e.path().extension() == ".fx") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

size_t compileOne(const std::string& path, fx::CompileIsolation isolation, fx::CompileWorkers* workers) {
    fx::DiagnosticList diagnostics;
    auto effect = fx::parseEffectFile(path, {}, diagnostics);
    if (!effect) throw std::runtime_error(diagnostics.str());
    fx::CompileOptions options;
    options.isolation = isolation;
    options.workers = workers;
    auto compiled = fx::compileEffect(effect, options, diagnostics);
    if (!compiled) throw std::runtime_error(diagnostics.str());
    size_t stages = 0;
    for (const fx::CompiledTechnique& t : compiled->techniques) stages += 2 * t.passes.size();
    return stages;
}

fx::CompileWorkers& pool() {
    static fx::CompileWorkers workers;
    return workers;
}

void ColdCompile_InProcess(benchmark::State& state) {
    const std::vector<std::string> effects = shippedEffects();
    size_t stages = 0;
    for (auto _ : state)
        for (const std::string& path : effects)
            stages += compileOne(path, fx::CompileIsolation::InProcess, nullptr);
    state.counters["effects"] = static_cast<double>(effects.size());
    state.counters["stages"] =
        benchmark::Counter(static_cast<double>(stages), benchmark::Counter::kAvgIterations);
}

void ColdCompile_Pool(benchmark::State& state) {
    const std::vector<std::string> effects = shippedEffects();
    compileOne(effects.front(), fx::CompileIsolation::Workers, &pool());  // workers started
    size_t stages = 0;
    for (auto _ : state)
        for (const std::string& path : effects)
            stages += compileOne(path, fx::CompileIsolation::Workers, &pool());
    state.counters["workers"] = pool().maxWorkers();
    state.counters["stages"] =
        benchmark::Counter(static_cast<double>(stages), benchmark::Counter::kAvgIterations);
}

void ColdCompile_PoolEffectsConcurrently(benchmark::State& state) {
    const std::vector<std::string> effects = shippedEffects();
    compileOne(effects.front(), fx::CompileIsolation::Workers, &pool());
    for (auto _ : state) {
        std::atomic<size_t> next{0};
        std::vector<std::thread> threads;
        for (int t = 0; t < pool().maxWorkers(); ++t)
            threads.emplace_back([&] {
                for (size_t i = next++; i < effects.size(); i = next++)
                    compileOne(effects[i], fx::CompileIsolation::Workers, &pool());
            });
        for (std::thread& thread : threads) thread.join();
    }
    state.counters["workers"] = pool().maxWorkers();
}

// The fragment stage of plain_lit.fx's first pass, as the compiler hands it to a worker.
fx::StageJob smallStage() {
    fx::DiagnosticList diagnostics;
    auto effect =
        fx::parseEffectFile(std::string(SHADOWFX_SOURCE_DIR) + "/effects/plain_lit.fx", {}, diagnostics);
    fx::CompileOptions options;
    options.isolation = fx::CompileIsolation::InProcess;
    auto compiled = effect ? fx::compileEffect(effect, options, diagnostics) : nullptr;
    if (!compiled) throw std::runtime_error(diagnostics.str());
    fx::StageJob job;
    job.hlsl = compiled->techniques.front().passes.front().fragment.hlsl;
    job.stage = fx::ShaderStage::Fragment;
    job.entryPoint = "fx_main";
    job.cross.uniformBlockName = "fx_PsGlobals";
    job.cross.uniformBlockBinding = 1;
    return job;
}

void StageRoundTrip_InProcess(benchmark::State& state) {
    const fx::StageJob job = smallStage();
    for (auto _ : state) {
        fx::StageOutcome outcome = fx::compileStageInProcess(job);
        if (outcome.status != fx::StageOutcome::Status::Compiled) state.SkipWithError("stage failed");
        benchmark::DoNotOptimize(outcome);
    }
}

void StageRoundTrip_Worker(benchmark::State& state) {
    const std::vector<fx::StageJob> jobs = {smallStage()};
    pool().run(jobs);
    for (auto _ : state) {
        std::vector<fx::StageOutcome> outcomes = pool().run(jobs);
        if (outcomes.front().status != fx::StageOutcome::Status::Compiled)
            state.SkipWithError("stage failed");
        benchmark::DoNotOptimize(outcomes);
    }
}

void PoolStartup(benchmark::State& state) {
    const std::vector<fx::StageJob> jobs = {smallStage()};
    for (auto _ : state) {
        fx::CompileWorkers fresh(fx::CompileWorkerOptions{"", 1, 20000, 2048});
        benchmark::DoNotOptimize(fresh.run(jobs));
    }
}

}  // namespace

BENCHMARK(ColdCompile_InProcess)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(ColdCompile_Pool)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(ColdCompile_PoolEffectsConcurrently)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(StageRoundTrip_InProcess)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(30);
BENCHMARK(StageRoundTrip_Worker)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(30);
BENCHMARK(PoolStartup)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK_MAIN();
