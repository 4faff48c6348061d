// The compile workers (fx/CompileWorkers.h): glslang and SPIRV-Cross in worker processes. A crash, a hang
// or a killed worker costs the stage a located error and the next compile succeeds; the pool compiles the
// same GLSL as the in-process mode; the protocol rejects what it cannot read; with no worker executable
// the compiler warns and compiles in-process.
#include <fx/CompileWorkers.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>

#include "CompileProtocol.h"
#include "ScratchDirectory.h"
#include "WorkerCrashHook.h"
#include "SpirvToGlsl.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

namespace test_compile_workers {

namespace {

const std::string kSourceDir = SHADOWFX_SOURCE_DIR;

struct Compiled {
    std::unique_ptr<fx::CompiledEffect> effect;
    fx::DiagnosticList diagnostics;
};

Compiled compileSource(const std::string& source, fx::CompileWorkers* workers,
                       fx::CompileIsolation isolation = fx::CompileIsolation::Workers) {
    Compiled out;
    auto effect = fx::parseEffectSource(source, "test.fx", {}, out.diagnostics);
    if (!effect) return out;
    fx::CompileOptions options;
    options.isolation = isolation;
    options.workers = workers;
    out.effect = fx::compileEffect(effect, options, out.diagnostics);
    return out;
}

Compiled compileFile(const std::string& path, fx::CompileWorkers* workers,
                     fx::CompileIsolation isolation = fx::CompileIsolation::Workers) {
    Compiled out;
    auto effect = fx::parseEffectFile(path, {}, out.diagnostics);
    if (!effect) return out;
    fx::CompileOptions options;
    options.isolation = isolation;
    options.workers = workers;
    out.effect = fx::compileEffect(effect, options, out.diagnostics);
    return out;
}

// kGood compiles; in kHangs both stages contain kHangMarker, on which a worker hangs (the worker's test
// hook, SHADOWFX_COMPILE_WORKER_TEST_HANG), however fast or slow the machine is.
const char* kHangMarker = "fx_test_hang_here";
const std::string kGood =
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return float4(1, 0, 0, 1); }\n"
    "technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
const std::string kHangs =
    "float4 VS(float4 p : POSITION) : POSITION { float fx_test_hang_here = 1; return p * fx_test_hang_here; "
    "}\n"
    "float4 PS() : COLOR { float fx_test_hang_here = 1; return fx_test_hang_here; }\n"
    "technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

// Both stages of kHangs failed with `id` and `message`, at VS and at PS.
void expectBothStagesFailed(const Compiled& compiled, fx::DiagId id, const std::string& message) {
    EXPECT_EQ(compiled.effect, nullptr);
    ASSERT_EQ(compiled.diagnostics.errorCount(), 2u) << compiled.diagnostics.str();
    const std::vector<fx::Diagnostic>& items = compiled.diagnostics.items();
    EXPECT_EQ(items[0].id, id);
    EXPECT_EQ(items[1].id, id);
    EXPECT_EQ(items[0].loc.str(), "test.fx:1:8");
    EXPECT_EQ(items[1].loc.str(), "test.fx:2:8");
    EXPECT_EQ(items[0].message, message);
    EXPECT_EQ(items[1].message, message);
}

class HangHook {
public:
    HangHook() { setenv("SHADOWFX_COMPILE_WORKER_TEST_HANG", kHangMarker, 1); }
    ~HangHook() { unsetenv("SHADOWFX_COMPILE_WORKER_TEST_HANG"); }
};

TEST(CompileWorkers, TheWorkerExecutableIsFound) {
    fx::CompileWorkers workers;
    ASSERT_TRUE(workers.available());
    EXPECT_TRUE(std::filesystem::exists(workers.workerPath()));
    EXPECT_GE(workers.maxWorkers(), 1);
}

TEST(CompileWorkers, ACrashOfTheHlslCompilerIsALocatedErrorAtTheShaderFunction) {
    const shadowfx::test::WorkerCrashHook hook;  // before the workers start: they read it once
    fx::CompileWorkers workers;
    Compiled crashed = compileFile("tests/data/worker_crash.fx", &workers);
    EXPECT_EQ(crashed.effect, nullptr);
    ASSERT_EQ(crashed.diagnostics.errorCount(), 1u) << crashed.diagnostics.str();
    const fx::Diagnostic& d = crashed.diagnostics.items()[0];
    EXPECT_EQ(d.id, fx::DiagId::HlslCompilerCrashed);
    EXPECT_EQ(d.loc.str(), "tests/data/worker_crash.fx:9:8");  // PS's name
    EXPECT_EQ(d.message, "the HLSL compiler crashed on this shader (signal 11)");
    EXPECT_GE(workers.replacedWorkers(), 1u);

    Compiled good = compileSource(kGood, &workers);
    EXPECT_NE(good.effect, nullptr) << good.diagnostics.str();
}

TEST(CompileWorkers, AWorkerOverTheTimeLimitIsKilledAndTheNextCompileSucceeds) {
    HangHook hook;
    fx::CompileWorkers workers(fx::CompileWorkerOptions{"", 2, 2000, 2048});
    const auto start = std::chrono::steady_clock::now();
    Compiled hung = compileSource(kHangs, &workers);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expectBothStagesFailed(hung, fx::DiagId::HlslCompilerTimedOut,
                           "the HLSL compiler did not finish this shader within 2000 ms and was stopped");
    EXPECT_LT(seconds, 30.0);
    EXPECT_EQ(workers.replacedWorkers(), 2u);

    Compiled good = compileSource(kGood, &workers);
    EXPECT_NE(good.effect, nullptr) << good.diagnostics.str();
}

TEST(CompileWorkers, AWorkerKilledMidRequestIsALocatedErrorAndTheNextCompileSucceeds) {
    HangHook hook;
    fx::CompileWorkers workers(fx::CompileWorkerOptions{"", 2, 60000, 2048});
    std::atomic<bool> done{false};
    std::thread killer([&] {
        // Every worker hangs on its stage; SIGKILL whichever run until the compile returns (a worker
        // killed before its request arrived is replaced, and the replacement killed in turn).
        while (!done) {
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            for (pid_t pid : workers.workerPids()) kill(pid, SIGKILL);
        }
    });
    Compiled killed = compileSource(kHangs, &workers);
    done = true;
    killer.join();
    expectBothStagesFailed(killed, fx::DiagId::HlslCompilerCrashed,
                           "the HLSL compiler crashed on this shader (signal 9)");

    Compiled good = compileSource(kGood, &workers);
    EXPECT_NE(good.effect, nullptr) << good.diagnostics.str();
}

TEST(CompileWorkers, AWorkerKilledWhileIdleIsReplacedWithoutAnError) {
    fx::CompileWorkers workers(fx::CompileWorkerOptions{"", 1, 20000, 2048});
    ASSERT_NE(compileSource(kGood, &workers).effect, nullptr);
    ASSERT_EQ(workers.workerPids().size(), 1u);
    kill(workers.workerPids()[0], SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    Compiled again = compileSource(kGood, &workers);
    EXPECT_NE(again.effect, nullptr) << again.diagnostics.str();
    EXPECT_FALSE(again.diagnostics.hasErrors());
}

TEST(CompileWorkers, ThePoolCompilesWhatTheInProcessModeCompiles) {
    fx::CompileWorkers workers(fx::CompileWorkerOptions{"", 2, 20000, 2048});
    for (const char* name : {"effects/pcf.fx", "effects/cascades.fx", "effects/thesis_fxcomposer.fx"}) {
        Compiled pooled = compileFile(name, &workers);
        Compiled local = compileFile(name, nullptr, fx::CompileIsolation::InProcess);
        ASSERT_NE(pooled.effect, nullptr) << name << "\n" << pooled.diagnostics.str();
        ASSERT_NE(local.effect, nullptr) << name << "\n" << local.diagnostics.str();
        ASSERT_EQ(pooled.effect->techniques.size(), local.effect->techniques.size());
        size_t stages = 0;
        for (size_t t = 0; t < local.effect->techniques.size(); ++t) {
            const auto& a = pooled.effect->techniques[t].passes;
            const auto& b = local.effect->techniques[t].passes;
            ASSERT_EQ(a.size(), b.size());
            for (size_t p = 0; p < a.size(); ++p) {
                for (auto [x, y] :
                     {std::pair{&a[p].vertex, &b[p].vertex}, std::pair{&a[p].fragment, &b[p].fragment}}) {
                    EXPECT_EQ(x->glsl, y->glsl) << name;
                    EXPECT_EQ(x->uniformBlockSize, y->uniformBlockSize);
                    ASSERT_EQ(x->uniforms.size(), y->uniforms.size());
                    for (size_t u = 0; u < x->uniforms.size(); ++u) {
                        EXPECT_EQ(x->uniforms[u].name, y->uniforms[u].name);
                        EXPECT_EQ(x->uniforms[u].offset, y->uniforms[u].offset);
                        EXPECT_EQ(x->uniforms[u].index, y->uniforms[u].index);
                        EXPECT_EQ(x->uniforms[u].active, y->uniforms[u].active);
                    }
                    ASSERT_EQ(x->samplers.size(), y->samplers.size());
                    ASSERT_EQ(x->inputs.size(), y->inputs.size());
                    stages += !x->glsl.empty();
                }
            }
        }
        EXPECT_GT(stages, 1u) << name;
    }
}

TEST(CompileWorkers, WithoutAWorkerExecutableTheCompilerWarnsAndCompilesInProcess) {
    setenv("SHADOWFX_COMPILE_WORKER", "/nonexistent/shadowfx-compile-worker", 1);
    fx::CompileWorkers workers;
    unsetenv("SHADOWFX_COMPILE_WORKER");
    EXPECT_FALSE(workers.available());
    Compiled compiled = compileSource(kGood, &workers);
    EXPECT_NE(compiled.effect, nullptr) << compiled.diagnostics.str();
    ASSERT_EQ(compiled.diagnostics.items().size(), 1u);
    EXPECT_EQ(compiled.diagnostics.items()[0].id, fx::DiagId::CompileWorkerNotFound);
    EXPECT_EQ(compiled.diagnostics.items()[0].severity, fx::Severity::Warning);
}

TEST(CompileWorkers, AWorkerThatCannotBeExecutedIsAnErrorNotAHang) {
    fx::CompileWorkers workers(fx::CompileWorkerOptions{kSourceDir + "/README.md", 1, 20000, 2048});
    Compiled compiled = compileSource(kGood, &workers);
    EXPECT_EQ(compiled.effect, nullptr);
    ASSERT_TRUE(compiled.diagnostics.hasErrors());
    const fx::Diagnostic& d = compiled.diagnostics.items()[0];
    EXPECT_EQ(d.id, fx::DiagId::CompileWorkerFailed);
    EXPECT_EQ(d.message, "cannot start the HLSL compiler's worker '" + kSourceDir +
                             "/README.md' (exec: " + std::strerror(EACCES) + ")");
}

// The first error of compiling kGood through a worker script that reads its request's frame header and
// exits with `status` without answering.
fx::Diagnostic firstErrorOfAWorkerExitingWith(const char* name, int status) {
    const shadowfx::test::ScratchDirectory scratch(name);
    const std::string worker = (scratch / "worker.sh").string();
    std::ofstream(worker) << "#!/bin/sh\nhead -c " << fx::kFrameHeaderBytes << " >/dev/null\nexit " << status
                          << "\n";
    std::filesystem::permissions(worker, std::filesystem::perms::owner_all);
    fx::CompileWorkers workers(fx::CompileWorkerOptions{worker, 1, 20000, 2048});
    Compiled compiled = compileSource(kGood, &workers);
    EXPECT_EQ(compiled.effect, nullptr);
    EXPECT_TRUE(compiled.diagnostics.hasErrors());
    if (compiled.diagnostics.items().empty()) return {};
    const fx::Diagnostic d = compiled.diagnostics.items()[0];
    EXPECT_TRUE(d.loc.valid()) << compiled.diagnostics.str();
    return d;
}

// An exit without an answer: the status is the error's value, at the shader function, under its own id.
TEST(CompileWorkers, AWorkerThatExitsWithoutAnsweringIsAnErrorNamingItsStatus) {
    const fx::Diagnostic d = firstErrorOfAWorkerExitingWith("exiting_worker", 3);
    EXPECT_EQ(d.id, fx::DiagId::HlslCompilerExited);
    EXPECT_EQ(d.message, "the HLSL compiler's worker exited with status 3 on this shader without answering");
}

// The sanitizer status (a sanitized worker's report, which this script does not print) is that finding,
// under its own id, with the status as its value; never an ordinary exit.
TEST(CompileWorkers, AWorkerThatStopsOnASanitizerReportIsThatErrorNamingItsStatus) {
    const fx::Diagnostic d =
        firstErrorOfAWorkerExitingWith("sanitizer_report_worker", fx::kWorkerSanitizerExitStatus);
    EXPECT_EQ(d.id, fx::DiagId::CompileWorkerSanitizerReport);
    EXPECT_EQ(d.message,
              "the HLSL compiler's worker process stopped on a sanitizer report (exit status 86); the "
              "report is on standard error");
}

TEST(CompileProtocol, JobsAndOutcomesSurviveTheRoundTrip) {
    fx::StageJob job;
    job.hlsl = std::string("float4 main() : SV_Target { return 1; }\0tail", 45);
    job.stage = fx::ShaderStage::Fragment;
    job.entryPoint = "fx_main";
    job.cross.uniformBlockName = "fx_PsGlobals";
    job.cross.uniformBlockBinding = 1;
    job.cross.samplerUnits = {{"ShadowMap", 3}, {"Diffuse", 0}};
    job.cross.depthSamplers = {"ShadowMap"};
    std::optional<fx::StageJob> back = fx::decodeJob(fx::encodeJob(job));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->hlsl, job.hlsl);
    EXPECT_EQ(back->stage, job.stage);
    EXPECT_EQ(back->cross.samplerUnits, job.cross.samplerUnits);
    EXPECT_EQ(back->cross.depthSamplers, job.cross.depthSamplers);

    fx::StageOutcome outcome;
    outcome.status = fx::StageOutcome::Status::HlslFailed;
    outcome.messages = {{true, "a.fx", 3, 7, "'x' : undeclared identifier"}, {false, "", 0, 0, "w"}};
    outcome.program.glsl = "#version 450\n";
    outcome.program.uniforms.push_back({"Bias", {}, 0, {}, 16, 4, 0, 0, false, false, {}});
    fx::SamplerBinding sampler;
    sampler.glslName = "ShadowMap";
    sampler.unit = 3;
    sampler.depthCompare = true;
    sampler.read = false;  // declared, never read by the stage
    outcome.program.samplers.push_back(sampler);
    fx::SamplerBinding pair;  // a D3D10 (texture, sampler) pair
    pair.glslName = "fx_pair_Albedo_Linear";
    pair.pairTexture = "Albedo";
    pair.pairSampler = "Linear";
    outcome.program.samplers.push_back(pair);
    outcome.program.inputs.push_back({"TEXCOORD0", 2, 2, {fx::VertexStream::Texcoord, 0}});
    std::optional<fx::StageOutcome> o = fx::decodeOutcome(fx::encodeOutcome(outcome));
    ASSERT_TRUE(o);
    EXPECT_EQ(o->status, outcome.status);
    ASSERT_EQ(o->messages.size(), 2u);
    EXPECT_EQ(o->messages[0].column, 7);
    EXPECT_EQ(o->messages[0].text, outcome.messages[0].text);
    EXPECT_FALSE(o->messages[1].error);
    EXPECT_EQ(o->program.uniforms[0].offset, 16u);
    EXPECT_FALSE(o->program.uniforms[0].active);
    EXPECT_FALSE(o->program.uniforms[0].hlslColumnsContiguous);
    EXPECT_TRUE(o->program.samplers[0].depthCompare);
    ASSERT_EQ(o->program.samplers.size(), 2u);
    EXPECT_FALSE(o->program.samplers[0].read);
    EXPECT_TRUE(o->program.samplers[1].read);
    EXPECT_EQ(o->program.samplers[1].pairTexture, "Albedo");
    EXPECT_EQ(o->program.samplers[1].pairSampler, "Linear");
    EXPECT_EQ(o->program.inputs[0].components, 2);
    EXPECT_EQ(o->program.inputs[0].stream.stream, fx::VertexStream::Texcoord);
}

TEST(CompileProtocol, TruncatedOrForeignMessagesAreRejected) {
    fx::StageJob job;
    job.hlsl = "float4 main() : SV_Target { return 1; }";
    const std::string payload = fx::encodeJob(job);
    for (size_t cut = 0; cut < payload.size(); cut += 3)
        EXPECT_FALSE(fx::decodeJob(payload.substr(0, cut))) << cut;
    EXPECT_FALSE(fx::decodeJob(payload + "x"));
    std::string header = fx::frame(fx::FrameKind::Request, payload).substr(0, fx::kFrameHeaderBytes);
    EXPECT_TRUE(fx::parseFrameHeader(header.data()));
    std::string otherVersion = header;
    otherVersion[4] = 99;
    EXPECT_FALSE(fx::parseFrameHeader(otherVersion.data()));
    std::string otherMagic = header;
    otherMagic[0] = 'X';
    EXPECT_FALSE(fx::parseFrameHeader(otherMagic.data()));
}

TEST(SpirvToGlsl, ASpirvCrossThrowIsAnErrorNotATerminate) {
    // A SPIR-V header with a bound of 1 and one bogus instruction.
    const std::vector<uint32_t> spirv = {0x07230203, 0x00010000, 0, 1, 0, 0x00020000 | 9999};
    fx::StageProgram program;
    std::string error;
    EXPECT_FALSE(fx::spirvToGlsl(spirv, fx::ShaderStage::Fragment, {}, program, error));
    EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace test_compile_workers
