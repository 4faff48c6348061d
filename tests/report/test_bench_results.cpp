// report::benchResultsJson (report/BenchResults.h) on results made up here: the document validates against
// docs/results.schema.json, holds every figure where results.json has always held it (an effect's run with
// its sweep setting and error, a peer's run with frame times only, a shard), writes null for what was not
// measured, and goes through the report writer into results.json unchanged.
#include "JsonSchema.h"
#include "ScratchDirectory.h"

#include <report/BenchResults.h>

#include <gtest/gtest.h>

#include <fstream>

namespace shadowfx::test::test_bench_results {
namespace {

using report::Json;

report::BenchTiming timing(double frameMs) {
    report::BenchTiming t;
    t.frameTimeMs = {frameMs, frameMs - 0.5, frameMs + 0.5, frameMs - 0.25, frameMs + 0.25};
    t.gpuTimeMs = report::BenchSpread{1.5, 1.0, 2.0, 1.25, 1.75};
    t.work = report::BenchFrameWork{2, 1, 7, 3, 1200};
    t.passes.push_back({"map", 0.75, 0.125, 3, report::BenchPassWork{"cached", 1, 600, 65536}});
    t.passes.push_back({"lit", 0.5, 0.25, 4, std::nullopt});
    t.runtimeCpuMs = report::BenchRuntimeCpu{0.1, 0.2, 0.05, 0.3, 0.35};
    return t;
}

report::BenchResults madeUpResults() {
    report::BenchResults results;
    results.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6";
    results.backend = "egl";
    report::BenchConfig& c = results.config;
    c.effects = {"effects/pcf.fx"};
    c.scenes = {"boxes"};
    c.mapSizes = {256, 512};
    c.techniques = {};
    c.set = {"Bias=0.001,0.002"};
    c.frames = 5;
    c.warmup = 1;
    c.width = 96;
    c.height = 72;
    c.areaSamples = 64;
    c.areaRadius = 0.25;
    c.peers = {"osg"};
    c.peerTechniques = {"pssm"};
    c.cameraOrbitDegreesPerFrame = 1.5;
    c.leaveOut = {true, false};
    c.timeAxis = "full";
    c.batching = false;
    results.shard = report::BenchShard{2, 3};
    results.runsTotal = 7;
    results.groundTruth.push_back({"boxes", true, 64, 442368, 0.0125, 5000, 1200, 2.5, false});

    report::BenchRunRecord run;
    run.runIndex = 1;
    run.effect = "effects/pcf.fx";
    run.effectName = "pcf";
    run.technique = "bilinear";
    run.scene = "boxes";
    run.mapSize = 512;
    run.mapSizeHonoured = true;
    run.width = 96;
    run.height = 72;
    run.glRenderer = results.glRenderer;
    run.frames = 5;
    run.warmupFrames = 1;
    run.leaveOut = true;
    run.cameraOrbitDegreesPerFrame = 1.5;
    run.firstFrameMs = 40.0;
    run.setting = {{{"Bias", "0.002"}}};
    run.steady = timing(3.0);
    run.fullCost = timing(9.0);
    run.aliasing = report::BenchAliasing{4.5, 1.25, 3.0, 4800};
    run.truthSoft = true;
    run.truthSamplesPerPixel = 64;
    run.error = report::BenchShadowError{5000, 40, 60, 0.8, 1.2, 2.0, 0.03, 0.25, 700, 0.125};
    run.errorImage = "errors/pcf_bilinear_boxes_512_Bias_0.002.png";
    results.runs.push_back(run);

    report::BenchRunRecord peer;
    peer.runIndex = 4;
    peer.effect = peer.effectName = "osg";
    peer.peer = "osg/pssm";
    peer.technique = "pssm";
    peer.scene = "boxes";
    peer.mapSize = 512;
    peer.width = 96;
    peer.height = 72;
    peer.glRenderer = results.glRenderer;
    peer.peerLibraryVersion = "3.6.5";
    peer.frames = 5;
    peer.warmupFrames = 1;
    peer.firstFrameMs = 12.0;
    peer.steady.frameTimeMs = {6.0, 5.0, 7.0, 5.5, 6.5};
    peer.fullCost = peer.steady;
    peer.truthSoft = true;
    peer.truthSamplesPerPixel = 64;
    peer.error = report::BenchShadowError{5000, 10, 20, 0.2, 0.4, 0.6, 0.01, 0.0, 0, std::nullopt};
    results.runs.push_back(peer);
    return results;
}

std::vector<std::string> keysOf(const Json& object) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : object.items()) keys.push_back(key);
    return keys;
}

nlohmann::json readSchema() {
    std::ifstream in(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    return nlohmann::json::parse(in);
}

TEST(BenchResults, TheDocumentValidatesAgainstTheSchema) {
    const nlohmann::json document = nlohmann::json::parse(report::benchResultsJson(madeUpResults()).dump());
    const nlohmann::json schema = readSchema();
    EXPECT_TRUE(validate(document, schema, schema, "$"));

    // Nothing optional measured: no shard, no peers, an effect without SHADOWFX_VISIBILITY.
    report::BenchResults plain = madeUpResults();
    plain.shard.reset();
    plain.config.areaRadius.reset();
    plain.runs.pop_back();
    plain.runs[0].setting.reset();
    plain.runs[0].error.reset();
    plain.runs[0].errorImage.reset();
    const nlohmann::json plainDocument = nlohmann::json::parse(report::benchResultsJson(plain).dump());
    EXPECT_TRUE(validate(plainDocument, schema, schema, "$"));
}

TEST(BenchResults, AnEffectsRunHoldsItsFiguresInResultsJsonOrder) {
    const Json document = report::benchResultsJson(madeUpResults());
    EXPECT_EQ(keysOf(document),
              (std::vector<std::string>{"schema_version", "generator", "gl_renderer", "backend", "config",
                                        "shard", "ground_truth", "runs"}));
    EXPECT_EQ(document["schema_version"], report::kBenchSchemaVersion);
    EXPECT_EQ(document["generator"], "shadowfx bench");
    EXPECT_EQ(document["shard"], (Json{{"index", 2}, {"count", 3}, {"runs_total", 7}}));
    EXPECT_EQ(document["config"]["area_radius"], 0.25);
    EXPECT_TRUE(document["config"]["light_angle_to_view"].is_null());
    EXPECT_EQ(document["config"]["leave_out"], Json::array({true, false}));
    EXPECT_EQ(document["ground_truth"][0]["shadowed_receiver_pixels"], 1200);

    const Json& run = document["runs"][0];
    EXPECT_EQ(keysOf(run), (std::vector<std::string>{"run_index",
                                                     "effect",
                                                     "effect_name",
                                                     "peer",
                                                     "technique",
                                                     "scene",
                                                     "map_size",
                                                     "map_size_honoured",
                                                     "width",
                                                     "height",
                                                     "gl_renderer",
                                                     "frames",
                                                     "warmup_frames",
                                                     "leave_out",
                                                     "camera_orbit_degrees_per_frame",
                                                     "first_frame_ms",
                                                     "setting",
                                                     "frame_time_ms",
                                                     "gpu_time_ms",
                                                     "work",
                                                     "passes",
                                                     "runtime_cpu_ms",
                                                     "full_cost",
                                                     "aliasing",
                                                     "ground_truth",
                                                     "error",
                                                     "error_image"}));
    EXPECT_TRUE(run["peer"].is_null());
    EXPECT_EQ(run["setting"], (Json{{"Bias", "0.002"}}));
    EXPECT_EQ(run["frame_time_ms"]["median"], 3.0);
    EXPECT_EQ(run["full_cost"]["frame_time_ms"]["median"], 9.0);
    EXPECT_EQ(run["passes"][0], (Json{{"name", "map"},
                                      {"gpu_ms", 0.75},
                                      {"cpu_ms", 0.125},
                                      {"draws", 3},
                                      {"left_out", "cached"},
                                      {"culled", 1},
                                      {"triangles", 600},
                                      {"texels_written", 65536}}));
    // A pass the counting frame did not run has its times only.
    EXPECT_EQ(keysOf(run["passes"][1]), (std::vector<std::string>{"name", "gpu_ms", "cpu_ms", "draws"}));
    EXPECT_EQ(run["work"]["triangles"], 1200);
    EXPECT_EQ(run["runtime_cpu_ms"]["overhead"], 0.35);
    EXPECT_EQ(run["aliasing"]["p95_texel_footprint_px"], 3.0);
    EXPECT_EQ(run["ground_truth"], (Json{{"soft", true}, {"samples_per_pixel", 64}}));
    EXPECT_EQ(run["error"]["misclassified_percent"], 2.0);
    EXPECT_EQ(run["error"]["penumbra_mae"], 0.125);
    EXPECT_EQ(run["error_image"], "errors/pcf_bilinear_boxes_512_Bias_0.002.png");
}

TEST(BenchResults, APeersRunHasFrameTimesOnlyAndNullWhereNothingWasMeasured) {
    const Json document = report::benchResultsJson(madeUpResults());
    const Json& peer = document["runs"][1];
    EXPECT_EQ(peer["peer"], "osg/pssm");
    EXPECT_EQ(peer["peer_library_version"], "3.6.5");
    EXPECT_FALSE(peer.contains("setting"));
    EXPECT_FALSE(document["runs"][0].contains("peer_library_version"));
    for (const Json* timing : {&peer, &peer["full_cost"]}) {
        EXPECT_EQ((*timing)["frame_time_ms"]["median"], 6.0);
        EXPECT_TRUE((*timing)["gpu_time_ms"].is_null());
        EXPECT_TRUE((*timing)["work"].is_null());
        EXPECT_EQ((*timing)["passes"], Json::array());
        EXPECT_TRUE((*timing)["runtime_cpu_ms"].is_null());
    }
    EXPECT_TRUE(peer["aliasing"].is_null());
    EXPECT_TRUE(peer["error"]["penumbra_mae"].is_null());  // no penumbra pixels
    EXPECT_TRUE(peer["error_image"].is_null());
    EXPECT_TRUE(report::benchResultsJson(report::BenchResults{})["shard"].is_null());
}

TEST(BenchResults, TheReportWriterWritesTheDocumentAsResultsJson) {
    const ScratchDirectory scratch("bench_results");
    const Json document = report::benchResultsJson(madeUpResults());
    std::string plotNote, error;
    ASSERT_TRUE(report::writeBenchOutputs(scratch.path(), document, plotNote, error)) << error;
    std::ifstream in(scratch.path() / "results.json");
    EXPECT_EQ(Json::parse(in), document);
}

}  // namespace
}  // namespace shadowfx::test::test_bench_results
