// BenchReport: the files of a `shadowfx bench` output directory made from its results document (what
// results.json holds, docs/results.schema.json): results.json itself, report.md and error_vs_time.svg.
// `bench` writes them after measuring and `bench merge` after joining shards (BenchMerge.h): one writer,
// so that a merged output reads exactly as an unsharded run's.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace report {

using Json = nlohmann::ordered_json;

// results.json's schema_version (docs/results.schema.json).
constexpr int kBenchSchemaVersion = 2;

// The run's technique and, in a sweep, the setting of its parameters: "main (Exponent=10)".
std::string techniqueLabel(const Json& run);

// Writes results.json, error_vs_time.svg and report.md of `results` into `outDir`. `plotNote`: why there is
// no plot (no run has an error figure, or the SVG could not be written), else empty; the report says it
// too. False with `error` set when results.json cannot be written.
bool writeBenchOutputs(const std::filesystem::path& outDir, const Json& results, std::string& plotNote,
                       std::string& error);

}  // namespace report
