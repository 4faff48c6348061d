// runtime::runBench (runtime/BenchRun.h) called as an application or another tool calls it, without the
// CLI: its results hold a run per technique and leave-out mode in run_index order, each shadow term scored
// against the truth, error images written; a shard measures only its runs; options that cannot
// be measured are usage errors that say why. An application measures in its own context, which stays current
// with its objects.
#include "ScratchDirectory.h"

#include <runtime/BenchRun.h>
#include <runtime/GlApi.h>
#include <runtime/GlContext.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace shadowfx::test::test_bench_run {
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
    const std::vector<report::BenchRunRecord>& runs = result.results.runs;
    ASSERT_EQ(runs.size(), 4u);
    ASSERT_EQ(result.results.groundTruth.size(), 1u);
    for (size_t i = 0; i < runs.size(); ++i) {
        EXPECT_EQ(runs[i].runIndex, i);
        EXPECT_EQ(runs[i].technique, i < 2 ? "bilinear" : "hardware");
        EXPECT_EQ(runs[i].leaveOut, i % 2 == 0);
        ASSERT_TRUE(runs[i].error);
        // A shadow map of the boxes scene gets most receivers right, and not all by being blank.
        EXPECT_LT(runs[i].error->misclassifiedPercent, 5.0);
        EXPECT_GT(result.results.groundTruth[0].shadowedReceiverPixels, 0);
        ASSERT_TRUE(runs[i].errorImage);
        EXPECT_TRUE(std::filesystem::exists(scratch.path() / *runs[i].errorImage));
    }
    EXPECT_FALSE(result.results.shard);
}

// As the pass API draws in the application's context, bench measures in it when given one: the results name
// its renderer and backend, and afterwards it is still current with the application's objects in it (a
// context of bench's own would have been destroyed, leaving no texture of the application's current).
TEST(BenchRun, MeasuresInTheApplicationsContext) {
    std::string error;
    const std::unique_ptr<runtime::GlContext> context = runtime::createContext({}, error);
    ASSERT_TRUE(context) << error;
    GLuint texture = 0;
    gl::GenTextures(1, &texture);
    gl::BindTexture(GL_TEXTURE_2D, texture);  // a name becomes a texture when first bound
    gl::BindTexture(GL_TEXTURE_2D, 0);
    ASSERT_TRUE(gl::IsTexture(texture));

    const ScratchDirectory scratch("bench_run_context");
    runtime::BenchOptions options = tinyBench(scratch.path());
    options.techniques = {"bilinear"};
    options.context = context.get();
    const runtime::BenchResult result = runtime::runBench(options, {});
    ASSERT_EQ(result.status, runtime::BenchStatus::Measured) << result.error;
    ASSERT_EQ(result.results.runs.size(), 1u);
    ASSERT_TRUE(result.results.runs[0].error);
    EXPECT_LT(result.results.runs[0].error->misclassifiedPercent, 5.0);
    EXPECT_EQ(result.results.backend, runtime::backendName(context->backend()));
    EXPECT_EQ(result.results.glRenderer, context->renderer());
    EXPECT_TRUE(gl::IsTexture(texture));
    gl::DeleteTextures(1, &texture);
}

TEST(BenchRun, AShardMeasuresOnlyItsRuns) {
    const ScratchDirectory scratch("bench_run_shard");
    runtime::BenchOptions options = tinyBench(scratch.path());
    std::string error;
    options.shard = report::parseBenchShard("2/2", error);
    ASSERT_TRUE(options.shard) << error;
    const runtime::BenchResult result = runtime::runBench(options, {});
    ASSERT_EQ(result.status, runtime::BenchStatus::Measured) << result.error;
    ASSERT_EQ(result.results.runs.size(), 1u);
    EXPECT_EQ(result.results.runs[0].runIndex, 1u);
    ASSERT_TRUE(result.results.shard);
    EXPECT_EQ(result.results.runsTotal, 2u);
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
}  // namespace shadowfx::test::test_bench_run
