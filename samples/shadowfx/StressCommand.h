// StressCommand: `shadowfx stress` — every effect's techniques through the extreme configurations of
// runtime/StressCases.h, each checked for finite values, GL errors, light-volume coverage, error against
// the ray-cast truth (held to the nearest ordinary case and to the uniform shadow map) and shimmer.
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kStressUsage;
int stressCommand(const Arguments& args);

}  // namespace shadowfx::cli
