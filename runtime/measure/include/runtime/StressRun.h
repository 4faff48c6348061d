// StressRun: the measurement of `shadowfx stress`: effects through extreme configurations (StressCases.h),
// each technique x case rendered and held to its criteria (and, with peers, each of their techniques)
// (report/StressReport.h): finite values, the light volume, its error against the case's ordinary
// configuration and against the uniform shadow map, shimmer.
//
// Effects are compiled with SHADOWFX_VISIBILITY (docs/scoring.md, "Measurement hooks"), so the frame is the
// shadow factor and can be scored against the truth; an effect that does not expose it gets the finite-value
// and GL checks only.
#pragma once

#include <fx/EffectParser.h>
#include <report/StressReport.h>
#include <runtime/FrameImage.h>
#include <runtime/GlContext.h>
#include <runtime/PeerRun.h>

#include <filesystem>

#include <functional>
#include <string>
#include <vector>

namespace runtime {

struct StressOptions {
    std::vector<std::string> effects;     // effect source files
    std::vector<std::string> cases;       // the cases asked for (their ordinary cases run too)
    std::vector<std::string> techniques;  // only these (empty: all)
    bool strict = false;                  // a declared limitation that passes fails the run too
    int width = 320, height = 240, mapSize = 1024;
    std::string uniformPath;       // the uniform shadow map every method is held to
    std::string uniformTechnique;  // its technique
    Backend backend = Backend::Auto;
    fx::ParseOptions parseOptions;  // -I and -D
    std::string truthCacheDir;      // TruthCache.h; empty: cast every truth
    // Other libraries' techniques run through the same cases (PeerRun.h), and where their frames and logs
    // go (a folder per peer).
    std::vector<Peer> peers;
    std::filesystem::path peerWorkDir;
};

// A failed run's error image (ShadowMetrics.h errorImage, the last frame's).
struct StressErrorImage {
    std::string effectStem;  // the effect file's name without its extension
    std::string technique;
    std::string caseName;
    FrameImage image;
};

struct StressLog {
    std::function<void(const std::string&)> note;     // a line for the user ("ground truth for ...")
    std::function<void(const std::string&)> problem;  // a line that says what is wrong with an input
};

struct StressRun {
    bool measured = false;
    std::string error;  // why not, unless measured
    report::StressResult result;
    std::vector<StressErrorImage> errorImages;
    bool failed = false;  // some run failed (or, strict, passed where a failure is declared)
};

StressRun runStress(const StressOptions& options, const StressLog& log);

}  // namespace runtime
