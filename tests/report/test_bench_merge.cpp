// `bench merge` (report/BenchMerge.h) on results made up here: shards join into the unsharded document
// (runs in run_index order, no shard mark, the first shard's ground truth), and everything that is not the
// N shards of one command is refused with a message naming the shards and the reason. Also the report
// writer (report/BenchReport.h) on the merged document.
#include "ScratchDirectory.h"

#include <report/BenchMerge.h>
#include <report/BenchShard.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace shadowfx::test::test_bench_merge {
namespace {

using report::Json;

// One run of a made-up bench: what the report writer reads, with recognisable figures.
Json makeRun(size_t index) {
    const Json spread{
        {"median", 1.0 + static_cast<double>(index)}, {"min", 1.0}, {"max", 2.0}, {"p25", 1.0}, {"p75", 2.0}};
    const Json timing{
        {"frame_time_ms", spread},
        {"gpu_time_ms", spread},
        {"work",
         Json{{"passes_run", 2}, {"passes_left_out", 0}, {"draws", 4}, {"culled", 0}, {"triangles", 100}}},
        {"passes", Json::array({Json{{"name", "map"}, {"gpu_ms", 0.5}, {"cpu_ms", 0.1}, {"draws", 2}}})},
        {"runtime_cpu_ms",
         Json{{"script", 0.1}, {"binding", 0.1}, {"preshader", 0.0}, {"gl", 0.2}, {"overhead", 0.2}}}};
    Json run{{"run_index", index},
             {"effect", "effects/pcf.fx"},
             {"effect_name", "pcf"},
             {"peer", nullptr},
             {"technique", "t" + std::to_string(index % 3)},
             {"scene", index < 6 ? "boxes" : "teapot"},
             {"map_size", index % 2 == 0 ? 256 : 512},
             {"map_size_honoured", true},
             {"width", 96},
             {"height", 72},
             {"gl_renderer", "llvmpipe"},
             {"frames", 1},
             {"warmup_frames", 0},
             {"leave_out", true},
             {"camera_orbit_degrees_per_frame", 0.0},
             {"first_frame_ms", 3.0}};
    for (const auto& [key, value] : timing.items()) run[key] = value;
    run["full_cost"] = timing;
    run["aliasing"] = Json{{"max_texel_footprint_px", 2.0},
                           {"mean_texel_footprint_px", 1.0},
                           {"p95_texel_footprint_px", 1.5},
                           {"pixels", 100}};
    run["ground_truth"] = Json{{"soft", false}, {"samples_per_pixel", 1}};
    run["error"] = Json{{"receiver_pixels", 1000},
                        {"false_shadow_pixels", static_cast<int>(index)},
                        {"false_light_pixels", 0},
                        {"false_shadow_percent", 0.1 * static_cast<double>(index)},
                        {"false_light_percent", 0.0},
                        {"misclassified_percent", 0.1 * static_cast<double>(index)},
                        {"mae", 0.001},
                        {"p95_abs_error", 0.0},
                        {"penumbra_pixels", 0},
                        {"penumbra_mae", nullptr}};
    run["error_image"] = nullptr;
    return run;
}

Json makeTruth(const std::string& scene, double seconds, bool cached) {
    return Json{{"scene", scene},
                {"soft", false},
                {"samples_per_pixel", 1},
                {"rays", 5000},
                {"normal_offset", 0.001},
                {"receiver_pixels", 4000},
                {"shadowed_receiver_pixels", 300},
                {"seconds", seconds},
                {"cached", cached}};
}

// The results document of a bench of `total` runs; shard K of N of it, or the whole with `count` 0.
Json makeResults(size_t total, int index, int count) {
    Json runs = Json::array();
    for (size_t i = 0; i < total; ++i)
        if (count == 0 || report::BenchShard{index, count}.takes(i)) runs.push_back(makeRun(i));
    return Json{{"schema_version", report::kBenchSchemaVersion},
                {"generator", "shadowfx bench"},
                {"gl_renderer", "llvmpipe"},
                {"backend", "egl"},
                {"config", Json{{"effects", Json::array({"effects/pcf.fx"})},
                                {"scenes", Json::array({"boxes", "teapot"})},
                                {"map_sizes", Json::array({256, 512})},
                                {"frames", 1},
                                {"warmup", 0},
                                {"width", 96},
                                {"height", 72},
                                {"camera_orbit_degrees_per_frame", 0.0},
                                {"time_axis", "full"}}},
                {"shard", count == 0 ? Json(nullptr)
                                     : Json{{"index", index}, {"count", count}, {"runs_total", total}}},
                // Each shard cast or read the truth in its own time.
                {"ground_truth", Json::array({makeTruth("boxes", 0.1 * index, index > 1),
                                              makeTruth("teapot", 0.2 * index, index > 1)})},
                {"runs", runs}};
}

std::vector<report::ShardResults> shardsOf(size_t total, int count) {
    std::vector<report::ShardResults> shards;
    for (int k = 1; k <= count; ++k)
        shards.push_back({"out/shard" + std::to_string(k), makeResults(total, k, count)});
    return shards;
}

// The refusal's message, which must name `expected`.
::testing::AssertionResult refused(const std::vector<report::ShardResults>& shards,
                                   const std::string& expected) {
    std::string error;
    const std::optional<Json> merged = report::mergeBenchShards(shards, error);
    if (merged)
        return ::testing::AssertionFailure() << "merged, expected a refusal naming '" << expected << "'";
    if (error.find(expected) == std::string::npos)
        return ::testing::AssertionFailure()
               << "refused with '" << error << "', which does not name '" << expected << "'";
    return ::testing::AssertionSuccess();
}

TEST(BenchMerge, ShardsJoinIntoTheUnshardedDocument) {
    const std::vector<report::ShardResults> shards = shardsOf(11, 3);
    std::string error;
    // In any order of the folders.
    const std::vector<report::ShardResults> shuffled{shards[2], shards[0], shards[1]};
    const std::optional<Json> merged = report::mergeBenchShards(shuffled, error);
    ASSERT_TRUE(merged) << error;
    Json whole = makeResults(11, 1, 0);
    EXPECT_EQ(*merged, whole);  // the truth as the first shard lists it, its own time included
    EXPECT_TRUE((*merged)["shard"].is_null());
    for (size_t i = 0; i < (*merged)["runs"].size(); ++i) EXPECT_EQ((*merged)["runs"][i]["run_index"], i);
}

TEST(BenchMerge, MoreShardsThanRunsLeavesSomeEmpty) {
    std::string error;
    const std::optional<Json> merged = report::mergeBenchShards(shardsOf(2, 4), error);
    ASSERT_TRUE(merged) << error;
    EXPECT_EQ((*merged)["runs"].size(), 2u);
}

TEST(BenchMerge, RefusesAMissingShard) {
    std::vector<report::ShardResults> shards = shardsOf(11, 4);
    shards.erase(shards.begin() + 1);
    shards.erase(shards.begin() + 2);
    EXPECT_TRUE(refused(shards, "missing shards 2/4, 4/4"));
}

TEST(BenchMerge, RefusesAShardGivenTwice) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards.push_back({"elsewhere/shard2", shards[1].results});
    EXPECT_TRUE(refused(shards, "shard 2/3 given twice: out/shard2 and elsewhere/shard2"));
}

TEST(BenchMerge, RefusesShardsOfAnotherCommand) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards[2].results["config"]["map_sizes"] = Json::array({1024});
    EXPECT_TRUE(refused(shards, "out/shard3 and out/shard1 are shards of different bench commands"));
    EXPECT_TRUE(refused(shards, "map_sizes"));
}

TEST(BenchMerge, RefusesShardsOfAnotherSplit) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards[2] = {"out/other", makeResults(11, 3, 4)};
    EXPECT_TRUE(refused(shards, "not one split of one command"));
}

TEST(BenchMerge, RefusesAnOutputThatIsNotAShard) {
    std::vector<report::ShardResults> shards = shardsOf(11, 2);
    shards.push_back({"out/whole", makeResults(11, 1, 0)});
    EXPECT_TRUE(refused(shards, "out/whole: not a shard"));
    EXPECT_TRUE(
        refused({{"out/empty", Json::object()}}, "out/empty: not the results.json of shadowfx bench"));
}

TEST(BenchMerge, RefusesAResultsFileWithoutTheFieldsItNeeds) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards[1].results["runs"][2].erase("error");
    EXPECT_TRUE(refused(shards, "out/shard2: results.json has no runs[].error"));
    shards = shardsOf(11, 3);
    shards[2].results["config"].erase("time_axis");
    EXPECT_TRUE(refused(shards, "out/shard3: results.json has no config.time_axis"));
    shards = shardsOf(11, 3);
    shards[0].results["runs"] = Json::object();
    EXPECT_TRUE(refused(shards, "out/shard1: results.json has no runs (an array)"));
}

TEST(BenchMerge, RefusesShardsFromDifferentRenderers) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards[1].results["gl_renderer"] = "NVIDIA H200";
    EXPECT_TRUE(refused(shards, "times from different machines do not compare"));
}

TEST(BenchMerge, RefusesShardsThatMeasuredDifferentTruths) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    shards[2].results["ground_truth"][1]["receiver_pixels"] = 3999;
    EXPECT_TRUE(refused(shards, "different ground truths of scene teapot (differing in: receiver_pixels)"));
}

TEST(BenchMerge, RefusesAnInterruptedOrEditedShard) {
    std::vector<report::ShardResults> shards = shardsOf(11, 3);
    Json& runs = shards[0].results["runs"];
    runs.erase(runs.begin() + 1);
    EXPECT_TRUE(refused(shards, "out/shard1: shard 1/3 holds 3 runs, its share of 11 is 4"));

    shards = shardsOf(11, 3);
    shards[1].results["runs"][0]["run_index"] = 3;  // shard 1's
    EXPECT_TRUE(refused(shards, "out/shard2: a run whose run_index 3 shard 2/3 does not take"));
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(BenchReport, WritesTheOutputsOfAMergeAndMarksAShard) {
    const ScratchDirectory scratch("bench_report");
    std::string note, error;
    ASSERT_TRUE(report::writeBenchOutputs(scratch.path(), makeResults(11, 1, 0), note, error)) << error;
    EXPECT_TRUE(note.empty()) << note;
    EXPECT_EQ(Json::parse(readText(scratch / "results.json")), makeResults(11, 1, 0));
    EXPECT_TRUE(std::filesystem::exists(scratch / "error_vs_time.svg"));
    const std::string whole = readText(scratch / "report.md");
    EXPECT_NE(whole.find("| teapot | pcf | t1 | 256 | 1.000 |"), std::string::npos) << whole;  // run 10
    EXPECT_EQ(whole.find("Shard "), std::string::npos);

    ASSERT_TRUE(report::writeBenchOutputs(scratch.path(), makeResults(11, 2, 3), note, error)) << error;
    const std::string shard = readText(scratch / "report.md");
    EXPECT_NE(shard.find("Shard 2 of 3: 4 of the command's 11 runs"), std::string::npos) << shard;
}

}  // namespace
}  // namespace shadowfx::test::test_bench_merge
