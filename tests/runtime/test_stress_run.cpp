// runtime::runStress (runtime/StressRun.h) called without the CLI: a run held to the case's uniform map
// passes and carries the uniform map's error; a uniform reference whose error cannot be measured stops the
// run with why, instead of letting every technique pass the comparison unchecked. The table and files made
// from the result are the report library's tests; `stress`'s exit status and flags,
// tests/effects/test_stress_command.cpp.
#include "ScratchDirectory.h"

#include <runtime/StressRun.h>

#include <gtest/gtest.h>

#include <string>

namespace shadowfx::test::test_stress_run {
namespace {

runtime::StressOptions ordinaryCase() {
    runtime::StressOptions options;
    options.effects = {"effects/pcf.fx"};
    options.techniques = {"bilinear"};
    options.cases = {"ordinary"};
    options.width = 160;
    options.height = 120;
    options.mapSize = 1024;
    options.uniformPath = "effects/thesis_fxcomposer.fx";
    options.uniformTechnique = "main";
    return options;
}

TEST(StressRun, AnOrdinaryRunPassesAndCarriesTheUniformMapsError) {
    const runtime::StressRun run = runtime::runStress(ordinaryCase(), {});
    ASSERT_TRUE(run.measured) << run.error;
    EXPECT_FALSE(run.failed);
    ASSERT_EQ(run.result.cases.size(), 1u);
    ASSERT_TRUE(run.result.cases[0].uniformMisclassified);
    EXPECT_GT(run.result.cases[0].receiverPixels, report::kMinScoredReceivers);
    ASSERT_EQ(run.result.outcomes.size(), 1u);
    const report::StressOutcome& outcome = run.result.outcomes[0];
    EXPECT_EQ(outcome.effect, "pcf.fx");
    EXPECT_EQ(outcome.result(), "pass");
    ASSERT_TRUE(outcome.misclassified);
    ASSERT_TRUE(outcome.uniform);
    EXPECT_EQ(*outcome.uniform, *run.result.cases[0].uniformMisclassified);
    EXPECT_TRUE(run.errorImages.empty());
}

TEST(StressRun, AUniformReferenceWithoutAnErrorStopsTheRun) {
    // plain_lit.fx draws no shadow and ignores SHADOWFX_VISIBILITY: it has no error to compare with.
    runtime::StressOptions blind = ordinaryCase();
    blind.uniformPath = "effects/plain_lit.fx";
    const runtime::StressRun blindRun = runtime::runStress(blind, {});
    EXPECT_FALSE(blindRun.measured);
    EXPECT_NE(blindRun.error.find("ignores SHADOWFX_VISIBILITY"), std::string::npos) << blindRun.error;
    // A technique the reference does not have renders nothing to compare with either.
    runtime::StressOptions absent = ordinaryCase();
    absent.uniformTechnique = "nosuchtechnique";
    const runtime::StressRun absentRun = runtime::runStress(absent, {});
    EXPECT_FALSE(absentRun.measured);
    EXPECT_NE(absentRun.error.find("gives no error on ordinary"), std::string::npos) << absentRun.error;
}

}  // namespace
}  // namespace shadowfx::test::test_stress_run
