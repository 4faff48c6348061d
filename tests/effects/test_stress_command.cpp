// `shadowfx stress` as users script against it: the case list, usage errors, declared limitations reported
// as xfail without failing the run, an undeclared one failing it with an error image, a declaration that
// excuses only the criteria it names, an xpass failing --strict, the ordinary criterion's allowance for a
// case's demand on the fit's resolution, the JSON, and a peer through the same cases.
#include "CliRunner.h"
#include "OsgPeerAvailability.h"
#include "ScratchDirectory.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

namespace {

using shadowfx::test::kSource;
using shadowfx::test::run;
using shadowfx::test::RunResult;

nlohmann::json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

const nlohmann::json* find(const nlohmann::json& results, const std::string& technique,
                           const std::string& name) {
    for (const nlohmann::json& r : results)
        if (r["technique"] == technique && r["case"] == name) return &r;
    return nullptr;
}

TEST(StressCommand, ListsItsCasesAndRejectsUnknownOnes) {
    const RunResult list = run("stress --list");
    EXPECT_EQ(list.exitCode, 0) << list.output;
    for (const char* name : {"light-along-view", "zenith-camera-down", "grazing", "far-from-origin", "empty",
                             "point-bounds", "camera-move", "spot-inside-bounds"})
        EXPECT_NE(list.output.find(name), std::string::npos) << name;
    const RunResult unknown = run("stress effects/plain_lit.fx --cases no-such-case");
    EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("no case 'no-such-case'"), std::string::npos) << unknown.output;
    const RunResult unknownPeer = run("stress effects/plain_lit.fx --cases ordinary --peers no-such-peer");
    EXPECT_EQ(unknownPeer.exitCode, 2) << unknownPeer.output;
    EXPECT_NE(unknownPeer.output.find("unknown peer 'no-such-peer'"), std::string::npos)
        << unknownPeer.output;
}

// --peers osg: OpenSceneGraph's osgShadow through the same cases, scored against the same truth and judged
// by the same criteria, without failing the run. On the ordinary case a peer whose frame lines up with the
// G-buffer has a small error, which a blank, black or shifted frame does not (a fair share of the boxes'
// receivers lie in shadow); the orbit's 60 frames come back one per camera, for shimmer. With the camera
// inside a closed box the peer's view culls the box's back faces, as the effects' scene passes and the
// G-buffer do: drawing its inner faces instead hid the ground beyond from more than half the receivers.
TEST(StressCommand, PeerOsgRunsThroughTheSameCases) {
    SHADOWFX_REQUIRE_OSG_PEER();
    const shadowfx::test::ScratchDirectory scratch("stress_peer");
    const std::filesystem::path out = scratch.path();
    const RunResult result =
        run("stress effects/thesis_fxcomposer.fx --techniques main "
            "--cases ordinary,camera-move,empty,camera-inside-occluder --width 96 --height 72 --map-size "
            "2048 --peers osg --peer-techniques ShadowMap,VDSM-ortho-1 "
            "--out " +
            out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json json = readJson(out / "stress.json");
    const nlohmann::json* own = find(json["results"], "main", "ordinary");
    ASSERT_NE(own, nullptr);
    EXPECT_TRUE((*own)["peer"].is_null());
    for (const std::string technique : {"ShadowMap", "VDSM-ortho-1"}) {
        const nlohmann::json* ordinary = find(json["results"], technique, "ordinary");
        ASSERT_NE(ordinary, nullptr) << technique;
        EXPECT_EQ((*ordinary)["peer"], "osg/" + technique);
        EXPECT_EQ((*ordinary)["effect"], "osg");
        EXPECT_EQ((*ordinary)["receiver_pixels"], (*own)["receiver_pixels"]) << "the same truth";
        ASSERT_TRUE((*ordinary)["misclassified_percent"].is_number()) << ordinary->dump(2);
        EXPECT_LT((*ordinary)["false_light_percent"].get<double>(), 2.0) << ordinary->dump(2);
        EXPECT_LT((*ordinary)["false_shadow_percent"].get<double>(), 2.0) << ordinary->dump(2);
        const nlohmann::json* orbit = find(json["results"], technique, "camera-move");
        ASSERT_NE(orbit, nullptr) << technique;
        ASSERT_TRUE((*orbit)["shimmer_mean_percent"].is_number()) << orbit->dump(2);
        EXPECT_LT((*orbit)["misclassified_percent"].get<double>(), 2.0) << orbit->dump(2);
        const nlohmann::json* inside = find(json["results"], technique, "camera-inside-occluder");
        ASSERT_NE(inside, nullptr) << technique;
        ASSERT_TRUE((*inside)["misclassified_percent"].is_number()) << inside->dump(2);
        EXPECT_LT((*inside)["misclassified_percent"].get<double>(), 5.0) << inside->dump(2);
        const nlohmann::json* empty = find(json["results"], technique, "empty");
        ASSERT_NE(empty, nullptr) << technique;
        const std::string word = (*empty)["result"];
        EXPECT_TRUE(word == "pass" || word == "breaks") << word;
    }
    std::ifstream report(out / "report.md");
    const std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("### osg / ShadowMap"), std::string::npos) << text;
}

TEST(StressCommand, DeclaredLimitationsAreReportedWithoutFailingTheRun) {
    const shadowfx::test::ScratchDirectory scratch("stress_declared");
    const std::filesystem::path out = scratch.path();
    const RunResult result =
        run("stress effects/thesis_fxcomposer.fx --techniques main "
            "--cases ordinary,grazing,far-from-origin,empty --out " +
            out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json json = readJson(out / "stress.json");
    const nlohmann::json* grazing = find(json["results"], "main", "grazing");
    ASSERT_NE(grazing, nullptr);
    EXPECT_FALSE((*grazing)["pass"]);
    EXPECT_TRUE((*grazing)["expected_failure"]);
    EXPECT_GT((*grazing)["false_shadow_percent"].get<double>(), 10.0);  // acne, as declared
    const nlohmann::json* far = find(json["results"], "main", "far-from-origin");
    ASSERT_NE(far, nullptr);
    EXPECT_TRUE((*far)["pass"]) << far->dump();
    EXPECT_LT((*far)["misclassified_percent"].get<double>(), 0.2);
    const nlohmann::json* empty = find(json["results"], "main", "empty");
    ASSERT_NE(empty, nullptr);
    EXPECT_TRUE((*empty)["pass"]) << empty->dump();
    EXPECT_NE(result.output.find("xfail"), std::string::npos) << result.output;
}

// Each run reports the texel footprint of the effect's own light fit: with the light behind the viewer,
// LiSPSM's p95 footprint is a fraction of the runtime's uniform map's (the case's own footprint).
TEST(StressCommand, ReportsTheFootprintOfTheEffectsOwnFit) {
    const shadowfx::test::ScratchDirectory scratch("stress_footprint");
    const std::filesystem::path out = scratch.path();
    const RunResult result =
        run("stress effects/lispsm.fx --cases light-behind-viewer --out " + out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json json = readJson(out / "stress.json");
    const nlohmann::json* lispsm = find(json["results"], "bilinear", "light-behind-viewer");
    ASSERT_NE(lispsm, nullptr);
    ASSERT_TRUE((*lispsm)["p95_footprint"].is_number()) << lispsm->dump();
    double uniform = 0.0;
    for (const nlohmann::json& c : json["cases"])
        if (c["name"] == "light-behind-viewer") uniform = c["p95_footprint"].get<double>();
    EXPECT_GT(uniform, 10.0);
    EXPECT_LT((*lispsm)["p95_footprint"].get<double>(), 0.5 * uniform);
}

// A view-independent map where the casters behind the viewer throw their shadows at the camera: its error
// is many times its ordinary configuration's, and as much as its fit's sampling-limited error rises there,
// which the ordinary criterion allows; nothing is declared, and the run passes.
TEST(StressCommand, TheOrdinaryCriterionAllowsTheRiseOfTheFitsSamplingLimitedError) {
    const shadowfx::test::ScratchDirectory scratch("stress_sampling_limited");
    const std::filesystem::path out = scratch.path();
    const RunResult result =
        run("stress effects/thesis_fxcomposer.fx --techniques main --strict --width 240 "
            "--height 180 --cases light-behind-viewer --out " +
            out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json json = readJson(out / "stress.json");
    const nlohmann::json* main = find(json["results"], "main", "light-behind-viewer");
    ASSERT_NE(main, nullptr);
    EXPECT_EQ((*main)["result"], "pass") << main->dump();
    const double error = (*main)["misclassified_percent"].get<double>();
    const double ordinary = (*main)["ordinary_percent"].get<double>();
    const double rise = (*main)["sampling_limited_percent"].get<double>() -
                        (*main)["ordinary_sampling_limited_percent"].get<double>();
    EXPECT_GT(error, 3.0 * ordinary + 1.0);  // beyond the criterion's bound without the allowance
    EXPECT_LE(error, 3.0 * ordinary + 1.0 + rise);
}

// The thesis effect's text with its StressExpectedFailures annotations renamed, so that none applies.
std::string thesisWithoutDeclarations() {
    std::ifstream in(kSource + "/effects/thesis_fxcomposer.fx");
    std::stringstream text;
    text << in.rdbuf();
    std::string effect = text.str();
    const std::string key = "string StressExpectedFailures";
    for (size_t at = effect.find(key); at != std::string::npos; at = effect.find(key))
        effect.replace(at, key.size(), "string StressIgnoredNote");
    return effect;
}

TEST(StressCommand, AnUndeclaredFailureFailsTheRunAndWritesItsErrorImage) {
    // The thesis effect without its StressExpectedFailures annotations.
    const shadowfx::test::ScratchDirectory scratch("stress_undeclared");
    const std::filesystem::path dir = scratch.path();
    std::ofstream(dir / "undeclared.fx") << thesisWithoutDeclarations();
    const RunResult result =
        run("stress " + (dir / "undeclared.fx").string() +
            " -I effects --techniques main --cases grazing --out " + (dir / "out").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("FAIL"), std::string::npos) << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "errors" / "undeclared.main.grazing.png"));
}

// The uniform reference is part of a rule: one that is missing, or whose error cannot be measured, stops the
// run instead of letting every technique pass the comparison unchecked.
TEST(StressCommand, AUniformReferenceThatCannotBeEvaluatedIsAnError) {
    const shadowfx::test::ScratchDirectory scratch("stress_uniform");
    const std::string out = " --out " + (scratch.path() / "out").string();
    const RunResult missing =
        run("stress effects/pcf.fx --techniques bilinear --cases ordinary --uniform nowhere.fx:main" + out);
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("the uniform reference nowhere.fx does not exist"), std::string::npos)
        << missing.output;
    // plain_lit.fx draws no shadow and ignores SHADOWFX_VISIBILITY: it has no error to compare with.
    const RunResult blind =
        run("stress effects/pcf.fx --techniques bilinear --cases ordinary --uniform "
            "effects/plain_lit.fx:main" +
            out);
    EXPECT_EQ(blind.exitCode, 1) << blind.output;
    EXPECT_NE(blind.output.find("ignores SHADOWFX_VISIBILITY"), std::string::npos) << blind.output;
    // A reference technique that renders nothing to compare with: tests/runtime/test_stress_run.cpp.
}

// The thesis effect with its declarations replaced by `declaration` on technique main.
std::filesystem::path declaredEffect(const std::filesystem::path& dir, const std::string& declaration) {
    std::string effect = thesisWithoutDeclarations();
    const size_t open = effect.find('<', effect.find("technique main"));
    effect.insert(open + 1, "\n    string StressExpectedFailures = \"" + declaration + "\";");
    const std::filesystem::path path = dir / "declared.fx";
    std::ofstream(path) << effect;
    return path;
}

// A declaration excuses the criteria it names and no others: grazing fails on the error criteria, and a
// declaration naming only shimmer leaves it a FAIL.
TEST(StressCommand, ADeclarationExcusesOnlyTheCriteriaItNames) {
    const shadowfx::test::ScratchDirectory scratch("stress_criteria");
    const std::filesystem::path effect =
        declaredEffect(scratch.path(), "grazing [shimmer]: the wrong criterion");
    const RunResult result =
        run("stress " + effect.string() + " -I effects --techniques main --cases grazing --out " +
            (scratch.path() / "out").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const nlohmann::json json = readJson(scratch.path() / "out" / "stress.json");
    const nlohmann::json* grazing = find(json["results"], "main", "grazing");
    ASSERT_NE(grazing, nullptr);
    EXPECT_EQ((*grazing)["result"], "FAIL") << grazing->dump();
    EXPECT_EQ((*grazing)["excused_criteria"], nlohmann::json::array({"shimmer"}));
    EXPECT_NE((*grazing)["failed_criteria"], nlohmann::json::array()) << grazing->dump();

    const RunResult bare =
        run("stress " + declaredEffect(scratch.path(), "grazing: no criteria").string() +
            " -I effects --techniques main --cases ordinary --out " + (scratch.path() / "bare").string());
    EXPECT_EQ(bare.exitCode, 1) << bare.output;
    EXPECT_NE(bare.output.find("names no criteria"), std::string::npos) << bare.output;
}

// A declared limitation that passes is an xpass: reported, and a failure under --strict.
TEST(StressCommand, ADeclaredCaseThatPassesIsAnXpassThatFailsStrict) {
    const shadowfx::test::ScratchDirectory scratch("stress_xpass");
    const std::filesystem::path effect =
        declaredEffect(scratch.path(), "far-from-origin [ordinary]: declared, yet it passes");
    const std::string arguments = "stress " + effect.string() +
                                  " -I effects --techniques main --cases far-from-origin --out " +
                                  (scratch.path() / "out").string();
    const RunResult lenient = run(arguments);
    EXPECT_EQ(lenient.exitCode, 0) << lenient.output;
    EXPECT_NE(lenient.output.find("xpass"), std::string::npos) << lenient.output;
    const nlohmann::json json = readJson(scratch.path() / "out" / "stress.json");
    const nlohmann::json* far = find(json["results"], "main", "far-from-origin");
    ASSERT_NE(far, nullptr);
    EXPECT_EQ((*far)["result"], "xpass") << far->dump();
    const RunResult strict = run(arguments + " --strict");
    EXPECT_EQ(strict.exitCode, 1) << strict.output;
}

}  // namespace
