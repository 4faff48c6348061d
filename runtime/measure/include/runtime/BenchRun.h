// BenchRun: the measurement of `shadowfx bench` (and of any tool that sweeps bench runs): every effect x
// scene x shadow-map size x technique (x --set setting x leave-out mode) rendered headlessly, its shadow
// term compared with the ray-cast ground truth, its frames timed; then the peers' techniques on the same
// scenes and truth. The result is report::BenchResults, which report/BenchResults.h turns into the results
// document (docs/results.schema.json) and report/BenchReport.h into results.json, report.md and
// error_vs_time.svg; the error images are written while measuring.
//
// Each effect is compiled twice per map size: as written (the timed frames) and with SHADOWFX_VISIBILITY
// (one frame whose colour is the shadow factor, scored against the ground truth). Timing the visibility
// variant instead would leave out the effect's shading and so understate its cost; scoring the shaded frame
// would confuse shading with shadowing. The two variants share every shadow computation by construction
// (the define only changes what the final pass returns).
#pragma once

#include <fx/HostFile.h>
#include <fx/EffectParser.h>
#include <report/BenchResults.h>
#include <report/BenchShard.h>
#include <runtime/GlContext.h>
#include <runtime/GroundTruth.h>
#include <runtime/PeerRun.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace runtime {

// What to measure, as the options of `shadowfx bench` say it (docs/cli.md); every field is recorded in the
// results document's `config`.
struct BenchOptions {
    std::vector<std::string> effects;       // effect files (.fx or compiled)
    std::vector<std::string> scenes;        // built-in scene names or scene files (.json)
    std::vector<int> mapSizes{1024};        // passed as -D SHADOWFX_SHADOW_MAP_SIZE=N
    std::vector<std::string> techniques;    // only these (empty: every technique of every effect)
    std::vector<bool> leaveOutModes{true};  // a run per mode, leave-out on before off
    std::string timeAxis = "full";          // what the plot's time is: "full" or "steady"
    int frames = 10;                        // timed frames per run
    int warmup = 2;                         // untimed frames before them
    int width = 640;
    int height = 480;
    Backend backend = Backend::Auto;  // of the context bench creates, unless `context` is given
    // An application's context (createContext) to measure in, as the pass API draws in the application's
    // context: made current and left current, holding the application's own objects untouched; bench then
    // creates none. Null: bench creates a context of `backend` for the run and destroys it after.
    GlContext* context = nullptr;
    GroundTruthOptions truth;
    std::optional<float> areaRadius;        // every light's areaRadius, when given
    std::optional<float> lightAngleToView;  // degrees: every directional light turned from the view
    float cameraOrbit = 0.0f;               // degrees the camera turns before each timed frame
    std::vector<std::string> set;           // PARAM=VALUES, as given (ParameterSweep.h)
    fx::ParseOptions parseOptions;          // -I and -D
    std::vector<Peer> peers;
    std::vector<std::string> peerNames;            // as --peers gave them, for `config`
    std::vector<std::string> peerTechniqueFilter;  // as --peer-techniques gave them, for `config`
    std::optional<report::BenchShard> shard;       // measure only its runs
    std::string truthCacheDir;                     // TruthCache.h; empty: cast every truth
    bool batching = true;
    std::filesystem::path outDir;  // errors/*.png and the peers' work files go here
    // --host: every effect drawn as the host file's application drew it; its "visibility" scores an effect
    // without SHADOWFX_VISIBILITY, and its last step's technique names the run (docs/host-files.md).
    std::shared_ptr<const fx::HostFile> host;
};

// What a run says while it runs. Each may be empty.
struct BenchLog {
    std::function<void(const std::string&)> note;        // a line for the user ("ground truth for ...")
    std::function<void(const std::string&)> diagnostic;  // each distinct diagnostic once (DiagnosticLog)
    std::function<void(size_t done, size_t total, const std::string& run)> progress;  // before each run
};

enum class BenchStatus {
    Measured,
    UsageError,  // the options cannot be measured as given (a --set no effect has, no technique matches)
    Failed,      // a context, scene, effect, frame or peer failed
};

struct BenchResult {
    BenchStatus status = BenchStatus::Failed;
    std::string error;             // why, unless Measured; empty when the diagnostics said it
    report::BenchResults results;  // what was measured, when Measured
};

BenchResult runBench(const BenchOptions& options, const BenchLog& log);

}  // namespace runtime
