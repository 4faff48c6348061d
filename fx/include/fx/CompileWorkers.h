// CompileWorkers: a small pool of compile worker processes that run glslang (HLSL -> SPIR-V) and
// SPIRV-Cross (SPIR-V -> GLSL) for the effect compiler, so that a crash, a hang or a runaway allocation
// in either library costs one stage a located error instead of the whole process (the way Unreal's
// ShaderCompileWorker and Chromium's GPU process isolate their shader compilers). Workers are separate
// executables (`shadowfx-compile-worker`), started with fork + exec on first use, kept alive between
// compiles, and replaced when one dies. The stages of an effect compile concurrently across the pool.
// Thread-safe. See docs/compile-workers.md.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <sys/types.h>

namespace fx {

struct StageJob;      // fx/src/StageCompile.h
struct StageOutcome;  // fx/src/StageCompile.h

struct CompileWorkerOptions {
    std::string workerPath;       // "" = findCompileWorker()
    int maxWorkers = 0;           // 0 = one per core
    int timeLimitMs = 20000;      // per stage; a worker over it is killed and replaced
    size_t memoryLimitMb = 2048;  // address-space limit of a worker (setrlimit); 0 = none
};

// Where the worker executable is: $SHADOWFX_COMPILE_WORKER, else beside the running executable, else the
// install's libexec directory, else the build tree it was built in. "" if none of these exists.
std::string findCompileWorker();

class CompileWorkers {
public:
    explicit CompileWorkers(CompileWorkerOptions options = {});
    ~CompileWorkers();  // closes every worker's stream (they exit) and reaps them
    CompileWorkers(const CompileWorkers&) = delete;
    CompileWorkers& operator=(const CompileWorkers&) = delete;

    // The process-wide pool the effect compiler uses unless CompileOptions names another.
    static CompileWorkers& shared();

    // False if there is no worker executable: the compiler then compiles in-process and warns.
    bool available() const;
    const std::string& workerPath() const;
    int maxWorkers() const;
    int timeLimitMs() const;

    // Runs every job, up to maxWorkers() at a time; outcomes in job order. Never throws.
    std::vector<StageOutcome> run(const std::vector<StageJob>& jobs);

    // Processes of the running workers (idle or busy) and how many were replaced after a crash or a
    // timeout: for tests and for `shadowfx` diagnostics.
    std::vector<pid_t> workerPids() const;
    size_t replacedWorkers() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace fx
