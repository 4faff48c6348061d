// `shadowfx tune` end to end on a tiny configuration (a small frame and map, one scene, a shipped technique
// with two tweakables, a few settings): its best setting must score no worse than the effect's own when
// `bench` measures both independently, and exactly as tune reported; its results.json must validate against
// docs/results.schema.json. Bad input (an unknown technique, an option bench would refuse, nothing to search,
// a budget nothing meets, a log scale over a range reaching 0) fails with a message that says so and a
// non-zero status.
#include "CliRunner.h"
#include "JsonSchema.h"
#include "ScratchDirectory.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace shadowfx::test::test_tune {
namespace {

using Json = nlohmann::json;

Json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    return Json::parse(in);
}

const std::string kTiny = " --scenes dual-l --width 96 --height 72 --frames 1 --warmup 0";

// The misclassified % of bias.fx's slope_shader on dual-l measured by bench with `set` (--set options).
double benchError(const std::filesystem::path& out, const std::filesystem::path& truthCache,
                  const std::string& set) {
    const RunResult bench =
        run("bench --effects effects/bias.fx --techniques slope_shader --map-sizes 256" + kTiny +
            " --truth-cache " + truthCache.string() + " --out " + out.string() + " " + set);
    EXPECT_EQ(bench.exitCode, 0) << bench.output;
    const Json results = readJson(out / "results.json");
    EXPECT_EQ(results["runs"].size(), 1u);
    return results["runs"][0]["error"]["misclassified_percent"].get<double>();
}

TEST(Tune, TheBestSettingIsNoWorseThanTheEffectsOwnAndReproducible) {
    const ScratchDirectory scratch("tune");
    const std::filesystem::path out = scratch / "out";
    const RunResult tune = run("tune effects/bias.fx --technique slope_shader --map-size 256" + kTiny +
                               " --evaluations 6 --grid 3 --budget-ms 60000 --out " + out.string());
    ASSERT_EQ(tune.exitCode, 0) << tune.output;

    const Json results = readJson(out / "results.json");
    const Json schema = readJson(std::filesystem::path(SHADOWFX_SOURCE_DIR) / "docs/results.schema.json");
    EXPECT_TRUE(validate(results, schema, schema, "$"));
    EXPECT_EQ(results["generator"], "shadowfx tune");
    const Json& search = results["tune"];
    ASSERT_EQ(search["parameters"].size(), 2u);
    EXPECT_EQ(search["parameters"][0]["name"], "Bias");
    EXPECT_EQ(search["parameters"][1]["name"], "SlopeScale");
    ASSERT_GE(search["evaluations"].size(), 2u);
    EXPECT_LE(search["evaluations"].size(), 6u);
    // The effect's own setting first, as the effect declares it; one bench run per setting and scene.
    EXPECT_EQ(search["evaluations"][0]["setting"], (Json{{"Bias", "0.003"}, {"SlopeScale", "2"}}));
    EXPECT_EQ(results["runs"].size(), search["evaluations"].size());
    EXPECT_TRUE(std::filesystem::exists(out / "error_vs_time.svg"));
    std::ifstream surface(out / "error_surface.svg");
    const std::string svg((std::istreambuf_iterator<char>(surface)), std::istreambuf_iterator<char>());
    EXPECT_NE(svg.find("Bias</text>"), std::string::npos);
    EXPECT_NE(svg.find("SlopeScale</text>"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(out / "report.md"));

    ASSERT_TRUE(search["best"].is_number_integer());
    const Json& best = search["evaluations"][search["best"].get<size_t>()];
    EXPECT_TRUE(best["within_budget"].get<bool>());
    std::string set;
    std::getline(std::ifstream(out / "best.txt"), set);
    EXPECT_EQ(set, search["set"].get<std::string>());
    EXPECT_EQ(set.rfind("--set Bias=", 0), 0u) << set;
    EXPECT_NE(tune.output.find("\n" + set + "\n"), std::string::npos) << "the --set line on stdout";

    // Measured again by bench alone: the effect's own setting, and the best as tune printed it.
    const double own = benchError(scratch / "own", out / "truth-cache", "");
    const double tuned = benchError(scratch / "tuned", out / "truth-cache", set);
    EXPECT_LE(tuned, own);
    EXPECT_NEAR(tuned, best["misclassified_percent"].get<double>(), 1e-9);
    EXPECT_NEAR(own, search["evaluations"][0]["misclassified_percent"].get<double>(), 1e-9);
    // Not an empty frame's error: under half the share of shadowed receivers.
    const Json& truth = results["ground_truth"][0];
    EXPECT_LT(tuned, 50.0 * truth["shadowed_receiver_pixels"].get<double>() /
                         truth["receiver_pixels"].get<double>());
}

TEST(Tune, AnUnknownTechniqueIsAUsageError) {
    const ScratchDirectory scratch("tune_unknown");
    const RunResult tune =
        run("tune effects/bias.fx --technique no_such" + kTiny + " --out " + (scratch / "out").string());
    EXPECT_EQ(tune.exitCode, 2) << tune.output;
    EXPECT_NE(tune.output.find("has no technique 'no_such' (it has: constant slope_state"), std::string::npos)
        << tune.output;
}

// The options passed on to each bench run are read as bench reads them, before anything is measured.
TEST(Tune, AMalformedRunOptionIsAUsageErrorBeforeAnythingIsMeasured) {
    const ScratchDirectory scratch("tune_options");
    const RunResult tune = run("tune effects/bias.fx --technique slope_shader" + kTiny +
                               " --light-angle-to-view 200 --out " + (scratch / "out").string());
    EXPECT_EQ(tune.exitCode, 2) << tune.output;
    EXPECT_NE(tune.output.find("shadowfx tune: --light-angle-to-view: '200' is not an angle in [0, 180]"),
              std::string::npos)
        << tune.output;
    EXPECT_FALSE(std::filesystem::exists(scratch / "out" / "batches")) << "nothing measured";
}

TEST(Tune, ABudgetNoSettingMeetsFails) {
    const ScratchDirectory scratch("tune_budget");
    const RunResult tune = run("tune effects/bias.fx --technique constant --map-size 256" + kTiny +
                               " --evaluations 2 --budget-ms 0.0001 --out " + (scratch / "out").string());
    EXPECT_EQ(tune.exitCode, 1) << tune.output;
    EXPECT_NE(tune.output.find("no setting measured is at or under --budget-ms 0.0001"), std::string::npos)
        << tune.output;
    EXPECT_EQ(tune.output.find("--set "), std::string::npos) << "no best setting printed: " << tune.output;
    EXPECT_TRUE(readJson(scratch / "out" / "results.json")["tune"]["best"].is_null());
}

// A technique reading no tweakable, and one whose tweakable asks for a log scale from 0: the minimal
// effect is written here.
TEST(Tune, NothingToSearchAndAnUnusableScaleAreSaid) {
    const ScratchDirectory scratch("tune_input");
    const std::filesystem::path effect = scratch / "tune_input.fx";
    std::ofstream(effect) << R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float Gain = 1.0;
float Exponent <
    float UIMin = 0.0; float UIMax = 100.0; string UIScale = "log";
> = 10.0;
float4 PositionVS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 GainPS() : COLOR { return float4(Gain, 0, 0, 1); }
float4 ExponentPS() : COLOR { return float4(Exponent, 0, 0, 1); }
technique plain { pass P { VertexShader = compile vs_3_0 PositionVS(); PixelShader = compile ps_3_0 GainPS(); } }
technique logged { pass P { VertexShader = compile vs_3_0 PositionVS(); PixelShader = compile ps_3_0 ExponentPS(); } }
)";
    const RunResult plain =
        run("tune " + effect.string() + " --technique plain" + kTiny + " --out " + (scratch / "a").string());
    EXPECT_EQ(plain.exitCode, 2) << plain.output;
    EXPECT_NE(plain.output.find("technique 'plain' of " + effect.string() + " reads no tweakable to search"),
              std::string::npos)
        << plain.output;

    const RunResult logged =
        run("tune " + effect.string() + " --technique logged" + kTiny + " --out " + (scratch / "b").string());
    EXPECT_EQ(logged.exitCode, 1) << logged.output;
    EXPECT_NE(logged.output.find("tune_input.fx:3:"), std::string::npos)
        << "located at Exponent: " << logged.output;
    EXPECT_NE(logged.output.find("a log scale needs UIMin > 0, and 'Exponent' has UIMin 0"),
              std::string::npos)
        << logged.output;
}

}  // namespace
}  // namespace shadowfx::test::test_tune
