// The stress writers (report/StressReport.h) on results made up here: a run's result word from its
// declaration (pass, xpass, xfail only when every failed criterion is declared, FAIL), which criteria a
// declaration may name, the table's rows and why-column, stress.json's fields and report.md's heading.
#include <report/StressReport.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace shadowfx::test::test_stress_report {
namespace {

using report::StressCriterion;
using report::StressOutcome;

StressOutcome outcome(const std::string& caseName) {
    StressOutcome o;
    o.effect = "pcf.fx";
    o.technique = "bilinear";
    o.caseName = caseName;
    o.receivers = 5000;
    return o;
}

report::StressResult madeUpResult() {
    report::StressResult result;
    result.renderer = "made-up renderer";
    result.width = 96;
    result.height = 72;
    result.mapSize = 256;
    result.cases.push_back({"ordinary", "as built in", "", 1, 5000, 0, 3.25, 2.5, 0.5});
    result.cases.push_back({"grazing", "a low sun", "ordinary", 1, 4000, 0, 60.0, 51.625, std::nullopt});
    StressOutcome ordinary = outcome("ordinary");
    ordinary.misclassified = 0.042;
    ordinary.uniform = 0.5;
    result.outcomes.push_back(ordinary);
    StressOutcome grazing = outcome("grazing");
    grazing.misclassified = 32.2;
    grazing.falseShadow = 30.0;
    grazing.falseLight = 2.25;
    grazing.ordinary = 0.042;
    grazing.p95Footprint = 7.25;
    grazing.fail(StressCriterion::Ordinary, "error 32.2% > 3x the ordinary case's 0.042% + 1 point");
    grazing.expectedFailure = true;
    grazing.excused = {StressCriterion::Ordinary};
    grazing.expectedBecause = " acne on the ground";
    result.outcomes.push_back(grazing);
    return result;
}

TEST(StressReport, TheResultWordFollowsTheDeclaration) {
    StressOutcome passed = outcome("ordinary");
    EXPECT_EQ(passed.result(), "pass");
    passed.expectedFailure = true;
    EXPECT_EQ(passed.result(), "xpass");

    StressOutcome failed = outcome("grazing");
    failed.fail(StressCriterion::Ordinary, "too much error");
    EXPECT_EQ(failed.result(), "FAIL");
    failed.expectedFailure = true;
    failed.excused = {StressCriterion::Shimmer};
    EXPECT_EQ(failed.result(), "FAIL") << "a declaration excuses only the criteria it names";
    failed.excused.push_back(StressCriterion::Ordinary);
    EXPECT_EQ(failed.result(), "xfail");
    failed.fail(StressCriterion::Finite, "NaN");
    EXPECT_EQ(failed.result(), "FAIL") << "a criterion outside the declaration fails the run again";
}

// A peer's technique (`stress --peers`) declares nothing: it passes or breaks, and JSON names the peer.
TEST(StressReport, APeersRunPassesOrBreaks) {
    StressOutcome peer = outcome("grazing");
    peer.effect = "osg";
    peer.technique = "ShadowMap";
    peer.peer = "osg/ShadowMap";
    EXPECT_EQ(peer.result(), "pass");
    peer.fail(StressCriterion::Uniform, "error 40% > 1.5x the uniform map's 3% + 0.5 point");
    EXPECT_EQ(peer.result(), "breaks");
    report::StressResult result = madeUpResult();
    result.outcomes.push_back(peer);
    const nlohmann::ordered_json json = report::stressJson(result);
    EXPECT_TRUE(json["results"][0]["peer"].is_null());
    EXPECT_EQ(json["results"][2]["peer"], "osg/ShadowMap");
    EXPECT_EQ(json["results"][2]["result"], "breaks");
    std::ostringstream table;
    report::writeStressTable(table, result, true);
    EXPECT_NE(table.str().find("### osg / ShadowMap"), std::string::npos) << table.str();
    EXPECT_NE(table.str().find("| grazing | breaks |"), std::string::npos) << table.str();
}

TEST(StressReport, OnlyTheJudgedCriteriaCanBeExcused) {
    EXPECT_EQ(report::excusableCriterion("light-volume"), StressCriterion::LightVolume);
    EXPECT_EQ(report::excusableCriterion("ordinary"), StressCriterion::Ordinary);
    EXPECT_EQ(report::excusableCriterion("uniform"), StressCriterion::Uniform);
    EXPECT_EQ(report::excusableCriterion("shimmer"), StressCriterion::Shimmer);
    EXPECT_EQ(report::excusableCriterion("render"), std::nullopt);
    EXPECT_EQ(report::excusableCriterion("finite"), std::nullopt);
    EXPECT_EQ(report::excusableCriterion("Ordinary"), std::nullopt);
}

TEST(StressReport, TheTableHasARowPerRunWithItsWhy) {
    report::StressResult result = madeUpResult();
    StressOutcome few = outcome("few");
    few.misclassified = 4.0;
    few.receivers = 12;
    result.outcomes.push_back(few);
    StressOutcome none = outcome("empty");
    none.receivers = 0;
    result.outcomes.push_back(none);
    std::ostringstream text;
    report::writeStressTable(text, result, false);
    const std::string table = text.str();
    EXPECT_EQ(table.find("\npcf.fx / bilinear\n  case"), 0u) << table;
    // One heading for the effect and technique, then a row per case.
    EXPECT_EQ(table.find("pcf.fx / bilinear", 2), std::string::npos) << table;
    EXPECT_NE(table.find("  ordinary                pass   0.042%         -         0.500%    2.5       -"),
              std::string::npos)
        << table;
    // The effect's own footprint where it has one, else the case's; the declaration with its criteria.
    EXPECT_NE(table.find("  grazing                 xfail  32.2%          0.042%    -         7.2       -"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("; declared [ordinary]: acne on the ground\n"), std::string::npos) << table;
    EXPECT_NE(table.find("12 receiver pixels: too few to judge the error"), std::string::npos) << table;
    EXPECT_NE(table.find("no receiver pixels"), std::string::npos) << table;
}

TEST(StressReport, TheMarkdownReportNamesTheConfigurationAndBoldsFailures) {
    report::StressResult result = madeUpResult();
    result.outcomes[1].expectedFailure = false;
    std::ostringstream markdown;
    report::writeStressMarkdown(markdown, result);
    const std::string md = markdown.str();
    EXPECT_EQ(md.find("# shadowfx stress\n\nRenderer: made-up renderer, 96x72, shadow maps 256².\n"), 0u)
        << md;
    EXPECT_NE(md.find("\n### pcf.fx / bilinear\n\n| case | result |"), std::string::npos) << md;
    EXPECT_NE(md.find("| grazing | **FAIL** | 32.2% | 0.042% | - | 7.2 | - | error 32.2%"), std::string::npos)
        << md;
}

TEST(StressReport, TheJsonHoldsEveryCaseAndRun) {
    const nlohmann::ordered_json json = report::stressJson(madeUpResult());
    EXPECT_EQ(json["renderer"], "made-up renderer");
    EXPECT_EQ(json["map_size"], 256);
    EXPECT_EQ(json["criteria"]["ordinary_factor"], report::kOrdinaryFactor);
    EXPECT_EQ(json["criteria"]["shimmer_limit_percent"], report::kShimmerLimit);
    ASSERT_EQ(json["cases"].size(), 2u);
    EXPECT_EQ(json["cases"][0]["uniform_misclassified_percent"], 0.5);
    EXPECT_TRUE(json["cases"][1]["uniform_misclassified_percent"].is_null());
    EXPECT_EQ(json["cases"][1]["ordinary"], "ordinary");
    ASSERT_EQ(json["results"].size(), 2u);
    const nlohmann::ordered_json& grazing = json["results"][1];
    EXPECT_EQ(grazing["result"], "xfail");
    EXPECT_FALSE(grazing["pass"]);
    EXPECT_EQ(grazing["excused_criteria"], nlohmann::ordered_json::array({"ordinary"}));
    EXPECT_EQ(grazing["failed_criteria"], nlohmann::ordered_json::array({"ordinary"}));
    EXPECT_EQ(grazing["false_shadow_percent"], 30.0);
    EXPECT_EQ(grazing["p95_footprint"], 7.25);
    EXPECT_TRUE(grazing["shimmer_mean_percent"].is_null());
    EXPECT_TRUE(json["results"][0]["p95_footprint"].is_null());
    EXPECT_TRUE(grazing["sampling_limited_percent"].is_null());
}

// The ordinary criterion's allowance for what a case asks of the fit's resolution: the rise of its
// sampling-limited error from the ordinary configuration, never negative, none where either is unknown.
TEST(StressReport, TheSamplingLimitedRiseIsTheCasesExcessOverItsOrdinary) {
    StressOutcome o = outcome("light-behind-viewer");
    EXPECT_EQ(report::samplingLimitedRise(o), 0.0);
    o.samplingLimited = 6.5;
    EXPECT_EQ(report::samplingLimitedRise(o), 0.0);
    o.ordinarySamplingLimited = 1.25;
    EXPECT_EQ(report::samplingLimitedRise(o), 5.25);
    o.samplingLimited = 0.5;
    EXPECT_EQ(report::samplingLimitedRise(o), 0.0);
    report::StressResult result = madeUpResult();
    result.outcomes.push_back(o);
    const nlohmann::ordered_json json = report::stressJson(result);
    EXPECT_EQ(json["results"].back()["sampling_limited_percent"], 0.5);
    EXPECT_EQ(json["results"].back()["ordinary_sampling_limited_percent"], 1.25);
}

}  // namespace
}  // namespace shadowfx::test::test_stress_report
