// BenchResults: what a bench run measured (runtime/BenchRun.h fills it), as types rather than JSON, and
// the one function that turns it into the results document (docs/results.schema.json) that BenchReport.h
// writes as results.json. Each struct holds the fields of one object of the schema, in its order; a field
// the document writes as null is an empty optional here.
#pragma once

#include <report/BenchReport.h>
#include <report/BenchShard.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace report {

// Median, extremes and quartiles of a run's frames (linear-interpolated quantiles, numpy's default).
struct BenchSpread {
    double median = 0, min = 0, max = 0, p25 = 0, p75 = 0;
};

// What the counting frame (one untimed frame like the timed ones) did in one pass.
struct BenchPassWork {
    std::string leftOut;  // "" ran; else why it was left out (runtime/FrameStats.h)
    int culled = 0;
    uint64_t triangles = 0;
    uint64_t texelsWritten = 0;
};

// One executed pass: medians over the timed frames, and the counting frame's work where it ran the pass.
struct BenchPassTiming {
    std::string name;
    double gpuMs = 0.0;
    double cpuMs = 0.0;
    int draws = 0;
    std::optional<BenchPassWork> work;
};

// The counting frame's totals.
struct BenchFrameWork {
    int passesRun = 0;
    int passesLeftOut = 0;
    int draws = 0;
    int culled = 0;
    uint64_t triangles = 0;
};

// Medians of where the runtime's CPU time went per frame.
struct BenchRuntimeCpu {
    double script = 0.0, binding = 0.0, preshader = 0.0, gl = 0.0, overhead = 0.0;
};

// One set of timed frames: the steady state (targets reused) or the full cost (nothing reused). A peer's
// frames have only their frame times.
struct BenchTiming {
    BenchSpread frameTimeMs;
    std::optional<BenchSpread> gpuTimeMs;
    std::optional<BenchFrameWork> work;
    std::vector<BenchPassTiming> passes;
    std::optional<BenchRuntimeCpu> runtimeCpuMs;
};

// A run's shadow term against the ground truth (runtime/ShadowMetrics.h, ShadowErrors).
struct BenchShadowError {
    size_t receiverPixels = 0;
    size_t falseShadowPixels = 0;
    size_t falseLightPixels = 0;
    double falseShadowPercent = 0.0;
    double falseLightPercent = 0.0;
    double misclassifiedPercent = 0.0;
    double mae = 0.0;
    double p95AbsError = 0.0;
    size_t penumbraPixels = 0;
    std::optional<double> penumbraMae;  // none without penumbra pixels
};

// Screen pixels per shadow-map texel over the receivers (runtime/ShadowMetrics.h, AliasingMeasure).
struct BenchAliasing {
    double maxTexelFootprintPx = 0.0;
    double meanTexelFootprintPx = 0.0;
    double p95TexelFootprintPx = 0.0;
    size_t pixels = 0;
};

// One run: an effect's technique (or a peer's) on one scene at one map size.
struct BenchRunRecord {
    size_t runIndex = 0;  // its place in the unsharded order (BenchShard.h)
    std::string effect;   // the effect file, or the peer's name
    std::string effectName;
    std::optional<std::string> peer;  // "osg/technique" for a peer's run
    std::string technique;
    std::string scene;
    int mapSize = 0;
    bool mapSizeHonoured = false;
    int width = 0;
    int height = 0;
    std::string glRenderer;
    std::optional<std::string> peerLibraryVersion;  // a peer's run only
    int frames = 0;
    int warmupFrames = 0;
    bool leaveOut = false;
    double cameraOrbitDegreesPerFrame = 0.0;
    double firstFrameMs = 0.0;
    // In a sweep, the value of each swept parameter (none outside a sweep).
    std::optional<std::vector<std::pair<std::string, std::string>>> setting;
    BenchTiming steady;
    BenchTiming fullCost;
    std::optional<BenchAliasing> aliasing;
    bool truthSoft = false;
    int truthSamplesPerPixel = 1;
    std::optional<BenchShadowError> error;  // none for an effect without SHADOWFX_VISIBILITY
    std::optional<std::string> errorImage;  // relative to the output directory
};

// The ground truth of one scene.
struct BenchTruthRecord {
    std::string scene;
    bool soft = false;
    int samplesPerPixel = 1;
    uint64_t rays = 0;
    double normalOffset = 0.0;
    int64_t receiverPixels = 0;
    int64_t shadowedReceiverPixels = 0;
    double seconds = 0.0;
    bool cached = false;
};

// The options the runs were measured with, as `shadowfx bench` took them (docs/cli.md).
struct BenchConfig {
    std::vector<std::string> effects;
    std::vector<std::string> scenes;
    std::vector<int> mapSizes;
    std::vector<std::string> techniques;
    std::vector<std::string> set;
    int frames = 0;
    int warmup = 0;
    int width = 0;
    int height = 0;
    int areaSamples = 1;
    std::optional<double> areaRadius;
    std::optional<double> lightAngleToView;
    std::vector<std::string> peers;
    std::vector<std::string> peerTechniques;
    double cameraOrbitDegreesPerFrame = 0.0;
    std::vector<bool> leaveOut;
    std::string timeAxis;
    bool batching = true;
};

struct BenchResults {
    std::string glRenderer;
    std::string backend;  // "egl" or "osmesa"
    BenchConfig config;
    std::optional<BenchShard> shard;  // the share of the runs measured, with the whole command's run count
    size_t runsTotal = 0;             // runs of the whole command (written with the shard)
    std::vector<BenchTruthRecord> groundTruth;
    std::vector<BenchRunRecord> runs;
};

// The results document of `results` (schema_version kBenchSchemaVersion, generator "shadowfx bench").
Json benchResultsJson(const BenchResults& results);

}  // namespace report
