// TuneCommand: `shadowfx tune` — a technique's tweakables searched for the least misclassified % at or under
// a frame-time budget, each setting measured by bench's runs against the ray-cast truth; the best setting as
// a --set line, results.json, report.md and error_vs_time.svg in the output folder.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kTuneUsage;
int tuneCommand(const Arguments& args);

}  // namespace shadowfx::cli
