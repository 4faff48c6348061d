// BenchCommand: `shadowfx bench` — every effect x scene x shadow-map size x technique rendered headlessly,
// its shadow term compared with the ray-cast ground truth, its frames timed; results.json, report.md,
// error_vs_time.svg and the error images in the output folder.
#pragma once

#include "CommandLine.h"

#include <runtime/BenchRun.h>

#include <string>

namespace shadowfx::cli {

extern const char* const kBenchUsage;
int benchCommand(const Arguments& args);

// The options that say how each run is rendered and scored, which `tune` passes on to its bench runs as
// bench reads them: --frames, --warmup, --width, --height, --backend, --area-samples, --area-radius,
// --light-angle-to-view, -I and -D, read over the defaults `options` holds. False when one is malformed,
// said on stderr as `shadowfx COMMAND: ...` (a usage error).
bool readBenchRunOptions(const Arguments& args, const std::string& command, runtime::BenchOptions& options);

}  // namespace shadowfx::cli
