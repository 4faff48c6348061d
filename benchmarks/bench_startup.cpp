// bench_startup: what a user waits for before the tool does anything, measured as processes, the way a
// shell or a build system runs them.
//   Process/Help                 `shadowfx --help`: loading the CLI and its shared libraries.
//   Process/CompileThesis        `shadowfx compile effects/thesis_fxcomposer.fx`: parse, lower, compile every
//                                stage (through the compile workers) and print the GLSL.
//   Process/ReferenceToolchain   the same stages compiled by Debian's two command-line tools, one process
//                                each: `glslangValidator` (HLSL to SPIR-V) and `spirv-cross` (SPIR-V to
//                                GLSL 4.50), on the HLSL units shadowfx generates for the thesis effect.
// The ratio CompileThesis / ReferenceToolchain is the compile figure of docs/results/; medians from one run:
//   build/benchmarks/bench_startup --benchmark_repetitions=11 --benchmark_report_aggregates_only=true
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

const std::string kThesisEffect = std::string(SHADOWFX_SOURCE_DIR) + "/effects/thesis_fxcomposer.fx";

// Runs argv with stdout and stderr on /dev/null; a failing or signalled child fails the benchmark, so a
// broken tool can never look fast.
void run(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error("cannot start " + argv[0]);
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error(argv[0] + " failed");
}

struct ReferenceUnit {
    std::string hlslPath;
    std::string stage;  // glslangValidator's -S name
};

// The thesis effect's generated HLSL units, written once into a scratch folder. Every unit's entry point is
// the lowering's wrapper, fx_main.
const std::vector<ReferenceUnit>& thesisUnits() {
    static const std::vector<ReferenceUnit> units = [] {
        fx::DiagnosticList diagnostics;
        auto effect = fx::parseEffectFile(kThesisEffect, {}, diagnostics);
        if (!effect) throw std::runtime_error(diagnostics.str());
        auto compiled = fx::compileEffect(effect, {}, diagnostics);
        if (!compiled) throw std::runtime_error(diagnostics.str());
        const fs::path dir = fs::temp_directory_path() / "shadowfx-bench-startup";
        fs::create_directories(dir);
        std::vector<ReferenceUnit> out;
        for (const fx::CompiledTechnique& technique : compiled->techniques)
            for (const fx::CompiledPass& pass : technique.passes)
                for (const fx::StageProgram* stage : {&pass.vertex, &pass.fragment}) {
                    if (stage->entryPoint.empty()) continue;
                    if (stage->hlsl.find("fx_main(") == std::string::npos)
                        throw std::runtime_error("a generated unit without the fx_main entry point");
                    const fs::path path = dir / ("unit" + std::to_string(out.size()) + ".hlsl");
                    std::ofstream(path) << stage->hlsl;
                    out.push_back({path.string(), stage == &pass.vertex ? "vert" : "frag"});
                }
        return out;
    }();
    return units;
}

void Process_Help(benchmark::State& state) {
    for (auto _ : state) run({SHADOWFX_CLI, "--help"});
}

void Process_CompileThesis(benchmark::State& state) {
    for (auto _ : state) run({SHADOWFX_CLI, "compile", kThesisEffect});
}

void Process_ReferenceToolchain(benchmark::State& state) {
    const std::vector<ReferenceUnit>& units = thesisUnits();
    for (auto _ : state)
        for (const ReferenceUnit& unit : units) {
            const std::string spirv = unit.hlslPath + ".spv";
            run({"glslangValidator", "-D", "-V", "-S", unit.stage, "-e", "fx_main", "--hlsl-dx9-compatible",
                 "--auto-map-bindings", "--auto-map-locations", unit.hlslPath, "-o", spirv});
            run({"spirv-cross", spirv, "--version", "450", "--output", "/dev/null"});
        }
    state.counters["units"] = static_cast<double>(units.size());
}

}  // namespace

BENCHMARK(Process_Help)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(Process_CompileThesis)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(Process_ReferenceToolchain)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK_MAIN();
