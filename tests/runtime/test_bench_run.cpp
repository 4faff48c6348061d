// runtime::runBench (runtime/BenchRun.h) called as an application or another tool calls it, without the
// CLI: its results document holds a run per technique and leave-out mode in run_index order, each shadow
// term scored against the truth, error images written; a shard measures only its runs; options that cannot
// be measured are usage errors that say why.
#include "ScratchDirectory.h"

#include <runtime/BenchRun.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace shadowfx::test {
namespace {

runtime::BenchOptions tinyBench(const std::filesystem::path& out) {
    runtime::BenchOptions options;
    options.effects = {"effects/pcf.fx"};
    options.scenes = {"boxes"};
    options.mapSizes = {256};
    options.techniques = {"bilinear", "hardware"};
    options.frames = 1;
    options.warmup = 0;
    options.width = 96;
    options.height = 72;
    options.outDir = out;
    return options;
}

TEST(BenchRun, MeasuresEachTechniqueAndLeaveOutModeInRunIndexOrder) {
    const ScratchDirectory scratch("bench_run");
    runtime::BenchOptions options = tinyBench(scratch.path());
    options.leaveOutModes = {true, false};
    size_t progressCalls = 0;
    runtime::BenchLog log;
    log.progress = [&](size_t done, size_t total, const std::string&) {
        ++progressCalls;
        EXPECT_EQ(done, progressCalls);
        EXPECT_EQ(total, 4u);
    };
    const runtime::BenchResult result = runtime::runBench(options, log);
    ASSERT_EQ(result.status, runtime::BenchStatus::Measured) << result.error;
    EXPECT_EQ(progressCalls, 4u);
    const report::Json& runs = result.document["runs"];
    ASSERT_EQ(runs.size(), 4u);
    for (size_t i = 0; i < runs.size(); ++i) {
        EXPECT_EQ(runs[i]["run_index"], i);
        EXPECT_EQ(runs[i]["technique"], i < 2 ? "bilinear" : "hardware");
        EXPECT_EQ(runs[i]["leave_out"], i % 2 == 0);
        ASSERT_TRUE(runs[i]["error"].is_object()) << runs[i].dump();
        // A shadow map of the boxes scene gets most receivers right, and not all by being blank.
        EXPECT_LT(runs[i]["error"]["misclassified_percent"].get<double>(), 5.0);
        EXPECT_GT(result.document["ground_truth"][0]["shadowed_receiver_pixels"].get<int>(), 0);
        EXPECT_TRUE(std::filesystem::exists(scratch.path() / runs[i]["error_image"].get<std::string>()));
    }
    EXPECT_EQ(result.document["schema_version"], report::kBenchSchemaVersion);
    EXPECT_TRUE(result.document["shard"].is_null());
}

TEST(BenchRun, AShardMeasuresOnlyItsRuns) {
    const ScratchDirectory scratch("bench_run_shard");
    runtime::BenchOptions options = tinyBench(scratch.path());
    std::string error;
    options.shard = report::parseBenchShard("2/2", error);
    ASSERT_TRUE(options.shard) << error;
    const runtime::BenchResult result = runtime::runBench(options, {});
    ASSERT_EQ(result.status, runtime::BenchStatus::Measured) << result.error;
    ASSERT_EQ(result.document["runs"].size(), 1u);
    EXPECT_EQ(result.document["runs"][0]["run_index"], 1);
    EXPECT_EQ(result.document["shard"]["runs_total"], 2);
}

TEST(BenchRun, OptionsThatCannotBeMeasuredAreUsageErrors) {
    const ScratchDirectory scratch("bench_run_usage");
    runtime::BenchOptions noTechnique = tinyBench(scratch.path());
    noTechnique.techniques = {"no-such-technique"};
    const runtime::BenchResult none = runtime::runBench(noTechnique, {});
    EXPECT_EQ(none.status, runtime::BenchStatus::UsageError);
    EXPECT_EQ(none.error, "no technique matches --techniques");

    runtime::BenchOptions unknownParameter = tinyBench(scratch.path());
    unknownParameter.set = {"NoSuchParameter=1,2"};
    const runtime::BenchResult unknown = runtime::runBench(unknownParameter, {});
    EXPECT_EQ(unknown.status, runtime::BenchStatus::UsageError);
    EXPECT_EQ(unknown.error, "--set NoSuchParameter: no effect has a parameter 'NoSuchParameter'");

    runtime::BenchOptions noScene = tinyBench(scratch.path());
    noScene.scenes = {"no-such-scene"};
    const runtime::BenchResult failed = runtime::runBench(noScene, {});
    EXPECT_EQ(failed.status, runtime::BenchStatus::Failed);
    EXPECT_NE(failed.error.find("cannot load scene 'no-such-scene'"), std::string::npos) << failed.error;
}

}  // namespace
}  // namespace shadowfx::test
