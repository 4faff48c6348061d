// `shadowfx bench` end to end on a tiny configuration (one scene, a small frame, one frame per run): its
// results.json must validate against docs/results.schema.json, its report and images must exist, and its
// figures must be sane (the thesis effect's shadows are mostly right). Also the per-pass timings of
// FrameOptions::timePasses that the bench and the viewer read.
#include "CliRunner.h"
#include "OsgPeerAvailability.h"
#include "JsonSchema.h"
#include "ScratchDirectory.h"
#include <runtime/BuiltinScenes.h>
#include "EffectHarness.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>

namespace shadowfx::test::test_bench {
namespace {

using Json = nlohmann::json;

Json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    return Json::parse(in);
}

// The misclassified % an effect must stay under on `scene` of `results`: half its shadowed share of the
// receivers. A frame without shadows misclassifies exactly that share and a frame shadowed everywhere the
// rest, so both fail it, whatever the scene: on `boxes` at 96x72 only 1.5 % of the receivers are in shadow,
// and a fixed 5 % would pass a blank frame.
double misclassifiedBound(const Json& results, const std::string& scene) {
    for (const Json& truth : results["ground_truth"])
        if (truth["scene"] == scene)
            return 50.0 * truth["shadowed_receiver_pixels"].get<double>() /
                   truth["receiver_pixels"].get<double>();
    ADD_FAILURE() << "no ground truth for " << scene;
    return 0.0;
}

// The built tool's exit status, its output appended to `output` (CliRunner.h runs it).
int runTool(const std::string& arguments, std::string& output) {
    const shadowfx::test::RunResult result = shadowfx::test::run(arguments);
    output += result.output;
    return result.exitCode;
}

TEST(Bench, TinyRunWritesResultsThatValidateAgainstTheSchema) {
    const shadowfx::test::ScratchDirectory scratch("bench");
    const std::filesystem::path out = scratch / "out";
    std::string output;
    const int code = runTool(
        "bench --effects effects/thesis_fxcomposer.fx --scenes boxes --map-sizes 256,512 "
        "--frames 1 --warmup 0 --width 96 --height 72 --out " +
            out.string(),
        output);
    ASSERT_EQ(code, 0) << output;
    EXPECT_NE(output.find("report.md"), std::string::npos) << output;

    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    EXPECT_EQ(results["schema_version"], 2);
    EXPECT_EQ(results["config"]["time_axis"], "full");

    // thesis_fxcomposer has techniques main, its D3D11 twin main11 and hardware: 3 techniques x 2 sizes x
    // 1 scene.
    ASSERT_EQ(results["runs"].size(), 6u);
    for (const Json& run : results["runs"]) {
        EXPECT_TRUE(run["map_size_honoured"].get<bool>());
        ASSERT_TRUE(run["error"].is_object()) << "the thesis effect exposes SHADOWFX_VISIBILITY";
        EXPECT_GT(run["error"]["receiver_pixels"].get<int>(), 96 * 72 / 4);
        EXPECT_LT(run["error"]["misclassified_percent"].get<double>(), misclassifiedBound(results, "boxes"))
            << run.dump(2);
        EXPECT_GT(run["frame_time_ms"]["median"].get<double>(), 0.0);
        EXPECT_FALSE(run["passes"].empty());
        EXPECT_GT(run["aliasing"]["mean_texel_footprint_px"].get<double>(), 0.0);
        // The full cost draws every pass of the technique; the steady state (a static scene) reuses the
        // map, so it draws fewer of them and never more draws.
        const Json& full = run["full_cost"];
        const int passes = run["technique"] == "hardware" ? 2 : 3;
        EXPECT_EQ(full["work"]["passes_run"].get<int>(), passes) << run.dump(2);
        EXPECT_EQ(full["work"]["passes_left_out"].get<int>(), 0);
        EXPECT_EQ(full["passes"].size(), static_cast<size_t>(passes));
        EXPECT_GE(run["work"]["passes_left_out"].get<int>(), 1);
        EXPECT_EQ(run["work"]["passes_run"].get<int>() + run["work"]["passes_left_out"].get<int>(), passes);
        EXPECT_GT(full["work"]["draws"].get<int>(), run["work"]["draws"].get<int>());
        EXPECT_GT(full["frame_time_ms"]["median"].get<double>(), 0.0);
        ASSERT_TRUE(run["error_image"].is_string());
        EXPECT_TRUE(std::filesystem::exists(out / run["error_image"].get<std::string>()));
    }
    // Twice the map resolution: half the texel footprint (the same light frustum, the same pixels).
    const Json& small = results["runs"][0];  // runs go size by size, technique by technique: main first
    const Json& large = results["runs"][3];
    ASSERT_EQ(small["technique"], "main");
    ASSERT_EQ(large["technique"], "main");
    ASSERT_EQ(small["map_size"], 256);
    ASSERT_EQ(large["map_size"], 512);
    EXPECT_NEAR(large["aliasing"]["mean_texel_footprint_px"].get<double>() * 2.0,
                small["aliasing"]["mean_texel_footprint_px"].get<double>(), 1e-6);
    EXPECT_TRUE(std::filesystem::exists(out / "report.md"));
    EXPECT_TRUE(std::filesystem::exists(out / "error_vs_time.svg"));
}

// --set with several values is a sweep: one row per value in results.json, report.md and the plot, each
// naming its setting, and each rendered with its own value (the errors differ). A single value beside it
// stays as before sweeps: the rows name no setting for it. A cross product over the cap is a usage error
// that says how the count came about.
TEST(Bench, SetWithSeveralValuesSweepsInOneReport) {
    const shadowfx::test::ScratchDirectory scratch("bench_sweep");
    const std::filesystem::path out = scratch / "out";
    std::string output;
    ASSERT_EQ(runTool("bench --effects effects/esm.fx --scenes boxes --map-sizes 256 --frames 1 --warmup 0 "
                      "--width 96 --height 72 --set Exponent=10:40:x2 --set BlurTaps=3 --out " +
                          out.string(),
                      output),
              0)
        << output;
    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    ASSERT_EQ(results["runs"].size(), 3u) << results.dump(2);
    const std::vector<std::string> exponents{"10", "20", "40"};
    std::set<std::string> images;
    for (size_t i = 0; i < exponents.size(); ++i) {
        const Json& run = results["runs"][i];
        EXPECT_EQ(run["setting"], Json({{"Exponent", exponents[i]}})) << run.dump(2);
        ASSERT_TRUE(run["error"].is_object());
        ASSERT_TRUE(run["error_image"].is_string());
        images.insert(run["error_image"].get<std::string>());
    }
    EXPECT_EQ(images.size(), 3u) << "each setting has its own error image";
    EXPECT_NE(results["runs"][0]["error"]["mae"], results["runs"][2]["error"]["mae"])
        << "exponent 10 and 40 rendered alike: the sweep's values were not applied";
    std::ifstream report(out / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    for (const std::string& exponent : exponents)
        EXPECT_NE(text.find("| esm | esm (Exponent=" + exponent + ") | 256 |"), std::string::npos) << text;
    std::ifstream plot(out / "error_vs_time.svg");
    const std::string svg((std::istreambuf_iterator<char>(plot)), std::istreambuf_iterator<char>());
    for (const std::string& exponent : exponents)
        EXPECT_NE(svg.find("esm/esm (Exponent=" + exponent + ") 256</text>"), std::string::npos) << svg;

    output.clear();
    EXPECT_EQ(runTool("bench --effects effects/esm.fx --set Exponent=1:80:+1 --set BlurTaps=1,3 --out " +
                          out.string(),
                      output),
              2);
    EXPECT_NE(output.find("80 x 2 = 160 settings, more than 64"), std::string::npos) << output;
}

// The control of the bound above: an effect that draws no shadow at all (its visibility frame is 1
// everywhere) and one that shadows everything must score above the bound the thesis effect is held to on
// the same scene and frame, or the bound would pass a method whose shadows vanished.
TEST(Bench, ShadowlessAndAllShadowEffectsScoreAboveTheBound) {
    const shadowfx::test::ScratchDirectory scratch("bench_control");
    const std::filesystem::path out = scratch / "out";
    std::filesystem::create_directories(out);
    const std::filesystem::path effect = scratch / "control.fx";
    std::ofstream(effect) << R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 VS(float4 p : POSITION) : POSITION { return mul(float4(p.xyz, 1), WorldViewProjection); }
float4 Lit() : COLOR {
#ifdef SHADOWFX_VISIBILITY
    return float4(1, 1, 1, 1);
#else
    return float4(0.8, 0.8, 0.8, 1);
#endif
}
float4 Dark() : COLOR {
#ifdef SHADOWFX_VISIBILITY
    return float4(0, 0, 0, 1);
#else
    return float4(0.2, 0.2, 0.2, 1);
#endif
}
technique shadowless { pass p0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Lit(); } }
technique all_shadow { pass p0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Dark(); } }
)";
    std::string output;
    ASSERT_EQ(
        runTool("bench --effects " + effect.string() +
                    " --scenes boxes --map-sizes 256 --frames 1 --warmup 0 --width 96 --height 72 --out " +
                    out.string(),
                output),
        0)
        << output;
    const Json results = readJson(out / "results.json");
    ASSERT_EQ(results["runs"].size(), 2u) << results.dump(2);
    for (const Json& run : results["runs"]) {
        ASSERT_TRUE(run["error"].is_object()) << run.dump(2);
        EXPECT_GT(run["error"]["receiver_pixels"].get<int>(), 96 * 72 / 4);
        EXPECT_GT(run["error"]["misclassified_percent"].get<double>(), misclassifiedBound(results, "boxes"))
            << run["technique"] << " passes the bound the thesis effect is held to";
    }
}

TEST(Bench, UnknownSceneIsAnErrorThatNamesIt) {
    std::string output;
    const shadowfx::test::ScratchDirectory scratch("bench_bad");
    const std::filesystem::path out = scratch / "out";
    EXPECT_EQ(
        runTool("bench --effects effects/thesis_fxcomposer.fx --scenes no-such-scene --out " + out.string(),
                output),
        1);
    EXPECT_NE(output.find("no-such-scene"), std::string::npos) << output;
    output.clear();
    EXPECT_EQ(
        runTool("bench --effects effects/thesis_fxcomposer.fx --time fastest --out " + out.string(), output),
        2);
    EXPECT_NE(output.find("--time"), std::string::npos) << output;
}

// --scenes takes scene files as render and check do, mixed with built-in names: each is measured under its
// own name (the file's "name"), and a broken file stops the bench with its located error and no results.
TEST(Bench, ScenesTakeSceneFilesMixedWithBuiltinNames) {
    const shadowfx::test::ScratchDirectory scratch("bench_files");
    const std::filesystem::path out = scratch / "out";
    std::filesystem::create_directories(out);
    const std::filesystem::path scene = out / "pillar.json";
    std::ofstream(scene) << R"({
  "name": "pillar-on-plane",
  "objects": [
    {"name": "ground", "mesh": {"primitive": "plane", "size": 10}},
    {"name": "pillar", "mesh": {"primitive": "box", "size": 1.0}, "translate": [0, 1, 0], "scale": [1, 2, 1]}
  ],
  "camera": {"position": [0, 6, -8], "target": [0, 0, 0], "fov": 60, "near": 0.1, "far": 40},
  "lights": [{"name": "light0", "type": "directional", "direction": [0.5, -1, 0.3]}]
}
)";
    std::string output;
    ASSERT_EQ(runTool("bench --effects effects/thesis_fxcomposer.fx --techniques hardware --scenes " +
                          scene.string() +
                          ",dual-l --map-sizes 256 --frames 1 --warmup 0 --width 96 --height 72 "
                          "--out " +
                          out.string(),
                      output),
              0)
        << output;
    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    ASSERT_EQ(results["runs"].size(), 2u);
    EXPECT_EQ(results["runs"][0]["scene"], "pillar-on-plane");
    EXPECT_EQ(results["runs"][1]["scene"], "dual-l");
    EXPECT_EQ(results["ground_truth"][0]["scene"], "pillar-on-plane");
    const Json& error = results["runs"][0]["error"];
    ASSERT_TRUE(error.is_object());
    EXPECT_GT(error["receiver_pixels"].get<int>(), 96 * 72 / 4);
    EXPECT_LT(error["misclassified_percent"].get<double>(), misclassifiedBound(results, "pillar-on-plane"));

    // A file that is not JSON: its line and column, a non-zero exit, no results left behind.
    const std::filesystem::path broken = out / "broken.json";
    std::ofstream(broken) << "{\n  \"objects\": [\n    {\"mesh\": }\n  ]\n}\n";
    std::filesystem::remove(out / "results.json");
    output.clear();
    EXPECT_NE(runTool("bench --effects effects/thesis_fxcomposer.fx --scenes boxes," + broken.string() +
                          " --out " + out.string(),
                      output),
              0);
    EXPECT_NE(output.find(broken.string() + ":3:"), std::string::npos) << output;
    EXPECT_NE(output.find("error"), std::string::npos) << output;
    EXPECT_FALSE(std::filesystem::exists(out / "results.json"));

    // A file that does not exist is named as well.
    output.clear();
    EXPECT_NE(runTool("bench --effects effects/thesis_fxcomposer.fx --scenes " +
                          (out / "missing.json").string() + " --out " + out.string(),
                      output),
              0);
    EXPECT_NE(output.find("missing.json"), std::string::npos) << output;
}

// --peers osg: OpenSceneGraph's osgShadow on the same scene, scored against the same truth. With a map far
// finer than the frame the peer's shadow is all but exact, so its error is small only if its frame lines up
// with the G-buffer pixel for pixel: a frame off by a pixel, mirrored, blank or black fails the bound (the
// scene keeps a large part of its receivers in shadow).
TEST(Bench, PeerOsgRowsAreScoredAgainstTheSameTruth) {
    SHADOWFX_REQUIRE_OSG_PEER();
    const shadowfx::test::ScratchDirectory scratch("bench_peer");
    const std::filesystem::path out = scratch / "out";
    std::filesystem::create_directories(out);
    const std::filesystem::path scene = out / "wall.json";
    // A wall and a post with the light behind them: long shadows towards the camera, edges in both axes
    // (a quarter of the receivers in shadow).
    std::ofstream(scene) << R"({
  "name": "wall-and-post",
  "objects": [
    {"name": "ground", "mesh": {"primitive": "plane", "size": 12}},
    {"name": "wall", "mesh": {"primitive": "box", "size": 1.0}, "translate": [-1, 1.25, 0.5], "scale": [5, 2.5, 0.3]},
    {"name": "post", "mesh": {"primitive": "box", "size": 1.0}, "translate": [2.5, 1.5, -2], "scale": [0.8, 3, 0.8]}
  ],
  "camera": {"position": [0, 8, -9], "target": [0, 0, 0.5], "fov": 55, "near": 0.1, "far": 40},
  "lights": [{"name": "light0", "type": "directional", "direction": [0.3, -0.45, -0.8]}]
}
)";
    std::string output;
    ASSERT_EQ(
        runTool("bench --peers osg --peer-techniques ShadowMap,VDSM-ortho-1 --scenes " + scene.string() +
                    " --map-sizes 4096 --frames 1 --warmup 0 --width 96 --height 72 --out " + out.string(),
                output),
        0)
        << output;
    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    const Json& truth = results["ground_truth"][0];
    const double receivers = truth["receiver_pixels"].get<double>();
    ASSERT_GT(receivers, 96 * 72 / 3);
    EXPECT_GT(truth["shadowed_receiver_pixels"].get<double>(), 0.15 * receivers)
        << "the scene must keep a large part of its receivers in shadow, or a blank frame would pass";
    ASSERT_EQ(results["runs"].size(), 2u);
    for (const Json& run : results["runs"]) {
        ASSERT_TRUE(run["peer"].is_string()) << run.dump(2);
        EXPECT_EQ(run["peer"], "osg/" + run["technique"].get<std::string>());
        EXPECT_EQ(run["effect"], "osg");
        EXPECT_TRUE(run["map_size_honoured"].get<bool>()) << "the peer's depth textures: " << run.dump(2);
        ASSERT_TRUE(run["error"].is_object());
        EXPECT_EQ(run["error"]["receiver_pixels"].get<double>(), receivers);
        EXPECT_LT(run["error"]["misclassified_percent"].get<double>(), 1.0) << run.dump(2);
        EXPECT_GT(run["frame_time_ms"]["median"].get<double>(), 0.0);
        EXPECT_TRUE(run["gpu_time_ms"].is_null());
        ASSERT_TRUE(run["error_image"].is_string());
        EXPECT_TRUE(std::filesystem::exists(out / run["error_image"].get<std::string>()));
    }
    std::ifstream report(out / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("| osg | ShadowMap |"), std::string::npos) << text;

    output.clear();
    EXPECT_EQ(runTool("bench --peers osg --peer-techniques NoSuchTechnique --out " + out.string(), output),
              2);
    EXPECT_NE(output.find("NoSuchTechnique"), std::string::npos) << output;
}

// --light-angle-to-view turns the light, and the footprint is scored with each effect's own light fit: the
// focused map spends its texels on what the camera sees, so its texels cover fewer pixels than the uniform
// map's with the same size and filter.
TEST(Bench, LightAngleAndTheEffectsOwnFitForTheFootprint) {
    const shadowfx::test::ScratchDirectory scratch("bench_angle");
    const std::filesystem::path out = scratch / "out";
    std::string output;
    ASSERT_EQ(
        runTool("bench --effects effects/pcf.fx,effects/focused.fx --techniques bilinear --scenes boxes "
                "--frames 1 --warmup 0 --width 96 --height 72 --light-angle-to-view 90 --out " +
                    out.string(),
                output),
        0)
        << output;
    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    EXPECT_EQ(results["config"]["light_angle_to_view"].get<double>(), 90.0);
    ASSERT_EQ(results["runs"].size(), 2u);
    const Json& uniform = results["runs"][0];
    const Json& focused = results["runs"][1];
    ASSERT_EQ(focused["effect"], "effects/focused.fx");
    EXPECT_LT(focused["aliasing"]["mean_texel_footprint_px"].get<double>(),
              0.8 * uniform["aliasing"]["mean_texel_footprint_px"].get<double>());

    output.clear();
    EXPECT_EQ(
        runTool("bench --effects effects/pcf.fx --light-angle-to-view 200 --out " + out.string(), output), 2);
    EXPECT_NE(output.find("--light-angle-to-view"), std::string::npos) << output;
}

// --camera-orbit turns the camera before every frame: a view-dependent map (LiSPSM's) is redrawn each frame
// instead of reused, while the errors are still scored at the scene's own camera (the same as still).
TEST(Bench, CameraOrbitRedrawsViewDependentMaps) {
    const shadowfx::test::ScratchDirectory scratch("bench_orbit");
    const std::filesystem::path out = scratch / "out";
    auto runWith = [&](const std::string& orbit) {
        std::filesystem::remove_all(out);
        std::string output;
        EXPECT_EQ(runTool("bench --effects effects/lispsm.fx --scenes boxes --frames 2 --warmup 1 --width 96 "
                          "--height 72 --camera-orbit " +
                              orbit + " --out " + out.string(),
                          output),
                  0)
            << output;
        return readJson(out / "results.json");
    };
    const Json still = runWith("0");
    const Json orbiting = runWith("2");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(orbiting, schema, schema, "$"));
    EXPECT_EQ(orbiting["config"]["camera_orbit_degrees_per_frame"].get<double>(), 2.0);
    const Json& a = still["runs"][0];
    const Json& b = orbiting["runs"][0];
    EXPECT_GE(a["work"]["passes_left_out"].get<int>(), 1) << "a still camera reuses the map";
    EXPECT_EQ(b["work"]["passes_left_out"].get<int>(), 0) << "an orbiting one redraws it";
    EXPECT_EQ(a["error"]["misclassified_percent"], b["error"]["misclassified_percent"]);
}

// What may differ between two runs of one bench command, or between a sharded and an unsharded one: the
// times, and whether the ground truth was cast or read from --truth-cache. Everything else must be equal.
Json withoutTimes(Json value) {
    static const std::set<std::string> kTimeKeys{"first_frame_ms", "frame_time_ms",  "gpu_time_ms", "gpu_ms",
                                                 "cpu_ms",         "runtime_cpu_ms", "seconds",     "cached"};
    if (value.is_object()) {
        for (const std::string& key : kTimeKeys) value.erase(key);
        for (auto& [key, sub] : value.items()) sub = withoutTimes(sub);
    } else if (value.is_array()) {
        for (Json& sub : value) sub = withoutTimes(sub);
    }
    return value;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// report.md with every number replaced by '#': its structure, row order and names, not its times.
std::string withoutNumbers(const std::string& text) {
    return std::regex_replace(text, std::regex("[0-9]+([.][0-9]+)?"), "#");
}

// A small sweep (two scenes, two map sizes, two settings, leave-out on and off: 16 runs) as one run and as
// three shards sharing a truth cache, merged: the merged results.json must equal the single run's but for
// times, and so its report (numbers aside) and error images; merge must refuse what is not the three
// shards of this command.
TEST(BenchShards, ThreeShardsMergeIntoTheSingleRun) {
    const shadowfx::test::ScratchDirectory scratch("bench_shards");
    const std::string sweep =
        "bench --effects effects/esm.fx --scenes boxes,torus --map-sizes 256,512 --set Exponent=10,40 "
        "--leave-out on,off --frames 1 --warmup 0 --width 96 --height 72";
    std::string output;
    ASSERT_EQ(runTool(sweep + " --out " + (scratch / "single").string(), output), 0) << output;
    const Json single = readJson(scratch / "single/results.json");
    ASSERT_EQ(single["runs"].size(), 16u);
    EXPECT_TRUE(single["shard"].is_null());

    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    std::string shardDirs;
    for (int k = 1; k <= 3; ++k) {
        const std::filesystem::path dir = scratch / ("shard" + std::to_string(k));
        shardDirs += " " + dir.string();
        output.clear();
        ASSERT_EQ(runTool(sweep + " --shard " + std::to_string(k) + "/3 --truth-cache " +
                              (scratch / "truths").string() + " --out " + dir.string(),
                          output),
                  0)
            << output;
        const Json shard = readJson(dir / "results.json");
        EXPECT_TRUE(validate(shard, schema, schema, "$"));
        EXPECT_EQ(shard["shard"], Json({{"index", k}, {"count", 3}, {"runs_total", 16}}));
        EXPECT_EQ(shard["runs"].size(), k == 1 ? 6u : 5u);
        for (const Json& run : shard["runs"]) EXPECT_EQ(run["run_index"].get<int>() % 3, k - 1);
        // Shard 1 cast the truths; the later shards read them.
        for (const Json& truth : shard["ground_truth"]) EXPECT_EQ(truth["cached"], k > 1) << truth.dump();
        EXPECT_NE(readFile(dir / "report.md").find("Shard " + std::to_string(k) + " of 3"),
                  std::string::npos);
    }

    const std::filesystem::path merged = scratch / "merged";
    output.clear();
    ASSERT_EQ(runTool("bench merge " + merged.string() + shardDirs, output), 0) << output;
    const Json joined = readJson(merged / "results.json");
    EXPECT_TRUE(validate(joined, schema, schema, "$"));
    EXPECT_EQ(withoutTimes(joined), withoutTimes(single));
    EXPECT_EQ(withoutNumbers(readFile(merged / "report.md")),
              withoutNumbers(readFile(scratch / "single/report.md")));
    EXPECT_TRUE(std::filesystem::exists(merged / "error_vs_time.svg"));
    size_t images = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scratch / "single/errors")) {
        ++images;
        EXPECT_EQ(readFile(merged / "errors" / entry.path().filename()), readFile(entry.path()))
            << entry.path().filename();
    }
    EXPECT_EQ(images, 8u) << "one error image per setting, scene and map size";

    // Not the three shards of this command: refused, saying why.
    const auto refusal = [&](const std::string& dirs) {
        std::string text;
        EXPECT_EQ(runTool("bench merge " + (scratch / "refused").string() + dirs, text), 1) << text;
        return text;
    };
    const std::string one = (scratch / "shard1").string(), two = (scratch / "shard2").string();
    EXPECT_NE(refusal(" " + one + " " + two).find("missing shard 3/3 (of 3)"), std::string::npos);
    EXPECT_NE(refusal(shardDirs + " " + two).find("shard 2/3 given twice"), std::string::npos);
    EXPECT_NE(refusal(" " + one + " " + (scratch / "single").string()).find("not a shard"),
              std::string::npos);
    output.clear();
    ASSERT_EQ(runTool(sweep + " --map-sizes 256 --shard 3/3 --truth-cache " + (scratch / "truths").string() +
                          " --out " + (scratch / "other").string(),
                      output),
              0)
        << output;
    EXPECT_NE(refusal(" " + one + " " + two + " " + (scratch / "other").string())
                  .find("are shards of different bench commands (their config differs in: map_sizes)"),
              std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(scratch / "refused/results.json"));

    output.clear();
    EXPECT_EQ(runTool(sweep + " --shard 4/3 --out " + (scratch / "bad").string(), output), 2);
    EXPECT_NE(output.find("--shard '4/3': K must be between 1 and N"), std::string::npos) << output;
}

// --truth-cache: a second run reads the truth and scores exactly as the first; a corrupted entry is named,
// cast again and repaired, the errors again the same.
TEST(BenchShards, TruthCacheHitScoresAlikeAndACorruptEntryIsCastAgain) {
    const shadowfx::test::ScratchDirectory scratch("bench_truth_cache");
    const std::filesystem::path cache = scratch / "truths";
    const std::string bench =
        "bench --effects effects/thesis_fxcomposer.fx --techniques main --scenes boxes "
        "--map-sizes 256 --frames 1 --warmup 0 --width 96 --height 72 --truth-cache " +
        cache.string() + " --out ";
    std::string output;
    const auto runInto = [&](const std::string& name) {
        output.clear();
        EXPECT_EQ(runTool(bench + (scratch / name).string(), output), 0) << output;
        return readJson(scratch / name / "results.json");
    };
    const Json cast = runInto("cast");
    EXPECT_EQ(cast["ground_truth"][0]["cached"], false);
    const Json read = runInto("read");
    EXPECT_EQ(read["ground_truth"][0]["cached"], true) << output;
    EXPECT_NE(output.find("ground truth for boxes read from --truth-cache"), std::string::npos) << output;
    ASSERT_TRUE(cast["runs"][0]["error"].is_object());
    EXPECT_EQ(withoutTimes(read), withoutTimes(cast));

    // Flip one byte in the middle of every entry (there is one: one scene at one size).
    size_t entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cache)) {
        ++entries;
        std::fstream file(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
        const auto middle = static_cast<std::streamoff>(std::filesystem::file_size(entry.path()) / 2);
        file.seekg(middle);
        const char byte = static_cast<char>(file.get() ^ 0x10);
        file.seekp(middle);
        file.put(byte);
    }
    EXPECT_EQ(entries, 1u);
    const Json recast = runInto("recast");
    EXPECT_NE(output.find("checksum mismatch (corrupted): cast again"), std::string::npos) << output;
    EXPECT_EQ(recast["ground_truth"][0]["cached"], false);
    EXPECT_EQ(withoutTimes(recast), withoutTimes(cast));
    EXPECT_EQ(runInto("repaired")["ground_truth"][0]["cached"], true) << "the entry was written again";
}

TEST(PassTimings, TimedFramesReportEveryPassWithItsDraws) {
    std::unique_ptr<runtime::EffectRenderer> renderer =
        loadEffect(sourcePath("effects/thesis_fxcomposer.fx"), true);
    ASSERT_TRUE(renderer);
    const runtime::Scene scene = *runtime::makeBuiltinScene("boxes");
    fx::DiagnosticList diagnostics;
    runtime::FrameOptions options;
    options.width = 64;
    options.height = 48;
    options.technique = "main";
    options.leaveOut = false;  // every pass draws every object, every frame (no shadow map reused)
    runtime::FrameStats stats;
    ASSERT_TRUE(renderer->render(scene, options, diagnostics, &stats)) << diagnostics.str();
    EXPECT_TRUE(stats.passTimings.empty()) << "untimed frames pay for no queries";

    options.timePasses = true;
    ASSERT_TRUE(renderer->render(scene, options, diagnostics, &stats)) << diagnostics.str();
    ASSERT_EQ(stats.passTimings.size(), 3u);
    EXPECT_EQ(stats.passTimings[0].pass, "ClearShadowMap");
    EXPECT_EQ(stats.passTimings[1].pass, "RenderShadowMap");
    EXPECT_EQ(stats.passTimings[2].pass, "RenderScene");
    EXPECT_EQ(stats.passTimings[0].draws, 0);
    const int objects = static_cast<int>(scene.objects.size());
    EXPECT_EQ(stats.passTimings[1].draws, objects);
    EXPECT_EQ(stats.passTimings[2].draws, objects);
    uint64_t gpu = 0;
    for (const runtime::PassTiming& pass : stats.passTimings) gpu += pass.gpuNs;
    EXPECT_GT(gpu, 0u);
    EXPECT_GT(stats.cpu.totalNs, 0u);
    EXPECT_GT(stats.cpu.bindingNs, 0u);
    EXPECT_LE(stats.cpu.bindingNs + stats.cpu.preshaderNs + stats.cpu.glNs, stats.cpu.totalNs);
}

}  // namespace
}  // namespace shadowfx::test::test_bench
