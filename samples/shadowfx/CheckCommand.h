// CheckCommand: `shadowfx check` — effect conformance. Every technique of every effect is rendered
// headlessly on every available backend and checked: it compiles, links and renders without GL errors,
// no render target holds NaN or Inf, the frame is not blank, the expectations the technique declares in
// its annotations hold against the ray-cast ground truth, and the frame matches its golden image (fuzzy
// comparison, runtime/ImageCompare.h). Results as a table and as JUnit XML; exit 1 on any FAIL.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kCheckUsage;
int checkCommand(const Arguments& args);

}  // namespace shadowfx::cli
