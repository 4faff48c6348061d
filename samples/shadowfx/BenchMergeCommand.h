// BenchMergeCommand: `shadowfx bench merge OUT DIR...`, the outputs of `bench --shard K/N` joined into one
// (report/BenchMerge.h).
#pragma once

#include "CommandLine.h"

namespace shadowfx::cli {

extern const char* const kBenchMergeUsage;
int benchMergeCommand(const Arguments& args);

}  // namespace shadowfx::cli
