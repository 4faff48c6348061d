// BenchMergeCommand: reads each shard's results.json, joins them (report/BenchMerge.h), copies the error
// images the runs name and writes results.json, report.md and error_vs_time.svg (report/BenchReport.h).
#include "BenchMergeCommand.h"

#include <report/BenchMerge.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

namespace shadowfx::cli {

const char* const kBenchMergeUsage =
    "usage: shadowfx bench merge OUT DIR...\n"
    "  Joins the output folders DIR... of `shadowfx bench --shard K/N`, every K of one N of one command,\n"
    "  into OUT: results.json, report.md, error_vs_time.svg and errors/*.png as the command run unsharded\n"
    "  would have written them (times aside). Refuses shards of different commands, shard counts, GL\n"
    "  renderers or ground truths, and a missing or repeated shard (docs/sharding.md).\n";

namespace {

std::optional<report::Json> readResults(const std::filesystem::path& dir, std::string& error) {
    const std::filesystem::path path = dir / "results.json";
    std::ifstream in(path);
    if (!in) {
        error = path.string() + ": cannot be read (not a bench output folder, or its shard did not finish)";
        return std::nullopt;
    }
    report::Json results = report::Json::parse(in, nullptr, false);
    if (results.is_discarded()) {
        error = path.string() + ": not valid JSON";
        return std::nullopt;
    }
    return results;
}

int merge(const Arguments& args) {
    if (args.positionalCount() < 2) {
        std::cerr << "shadowfx bench merge: expected OUT and at least one shard folder DIR (see --help)\n";
        return 2;
    }
    const std::filesystem::path outDir = args.positional(0);
    std::vector<report::ShardResults> shards;
    std::vector<std::filesystem::path> dirs;
    std::error_code fsError;
    for (size_t i = 1; i < args.positionalCount(); ++i) {
        const std::filesystem::path dir = args.positional(i);
        if (std::filesystem::equivalent(dir, outDir, fsError)) {
            std::cerr << "shadowfx bench merge: OUT " << outDir.string()
                      << " is also a shard folder: the merge "
                      << "would overwrite that shard's results\n";
            return 2;
        }
        std::string error;
        std::optional<report::Json> results = readResults(dir, error);
        if (!results) {
            std::cerr << "shadowfx bench merge: " << error << "\n";
            return 1;
        }
        shards.push_back({dir.string(), std::move(*results)});
        dirs.push_back(dir);
    }
    std::string error;
    const std::optional<report::Json> merged = report::mergeBenchShards(shards, error);
    if (!merged) {
        std::cerr << "shadowfx bench merge: " << error << "\n";
        return 1;
    }

    std::filesystem::create_directories(outDir / "errors", fsError);
    if (fsError) {
        std::cerr << "shadowfx bench merge: cannot create " << outDir.string() << ": " << fsError.message()
                  << "\n";
        return 1;
    }
    // The error images, in run order: where two runs share an image name (leave-out on and off of one
    // configuration draw the same image), the later run's copy stays, as in an unsharded run.
    std::map<size_t, std::filesystem::path> imageSource;  // run index -> its shard's folder
    for (size_t s = 0; s < shards.size(); ++s)
        for (const report::Json& run : shards[s].results["runs"])
            if (run["error_image"].is_string()) imageSource[run["run_index"].get<size_t>()] = dirs[s];
    for (const report::Json& run : (*merged)["runs"]) {
        if (!run["error_image"].is_string()) continue;
        const std::string image = run["error_image"].get<std::string>();
        const std::filesystem::path from = imageSource[run["run_index"].get<size_t>()] / image;
        std::filesystem::copy_file(from, outDir / image, std::filesystem::copy_options::overwrite_existing,
                                   fsError);
        if (fsError) {
            std::cerr << "shadowfx bench merge: cannot copy " << from.string() << ": " << fsError.message()
                      << "\n";
            return 1;
        }
    }

    std::string plotNote;
    if (!report::writeBenchOutputs(outDir, *merged, plotNote, error)) {
        std::cerr << "shadowfx bench merge: " << error << "\n";
        return 1;
    }
    if (!plotNote.empty()) std::cerr << "bench merge: " << plotNote << "\n";
    std::cerr << "bench merge: " << shards.size() << " shards, " << (*merged)["runs"].size() << " runs\n";
    std::cout << (outDir / "report.md").string() << "\n";
    return 0;
}

}  // namespace

int benchMergeCommand(const Arguments& args) {
    // Merging checks that the fields it and the report read are there (report/BenchMerge.h), not their
    // types: a value of the wrong type in an edited results.json surfaces as the JSON library's type error.
    try {
        return merge(args);
    } catch (const report::Json::exception& e) {
        std::cerr << "shadowfx bench merge: a results.json holds a value of the wrong type: " << e.what()
                  << "\n";
        return 1;
    }
}

}  // namespace shadowfx::cli
