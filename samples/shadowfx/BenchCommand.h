// BenchCommand: `shadowfx bench` — every effect x scene x shadow-map size x technique rendered headlessly,
// its shadow term compared with the ray-cast ground truth, its frames timed; results.json, report.md,
// error_vs_time.svg and the error images in the output folder.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kBenchUsage;
int benchCommand(const Arguments& args);

}  // namespace shadowfx::cli
