// runtime::runConformance (runtime/ConformanceRun.h) called without the CLI: the rows it returns for a
// shipped effect, a technique that draws nothing (a blank frame is a FAIL of its render check, in the words
// report/ConformanceReport.h's summary tells blank frames by) and a file without techniques (a compile FAIL
// at its first line, never zero checks). The table, summary and JUnit made from rows are the report
// library's tests; `check`'s exit status, its tests in tests/effects/test_check_command.cpp.
#include "ScratchDirectory.h"

#include <report/ConformanceReport.h>
#include <runtime/ConformanceRun.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace shadowfx::test::test_conformance_run {
namespace {

namespace fs = std::filesystem;

runtime::ConformanceOptions oneBackend(const fs::path& out) {
    runtime::ConformanceOptions options;
    options.backends = {runtime::Backend::EGL};
    options.backendsNamed = true;
    options.outDir = out;
    return options;
}

const report::CheckRow* findRow(const runtime::ConformanceResult& result, const std::string& technique,
                                const std::string& scene, const std::string& check) {
    for (const report::CheckRow& row : result.rows)
        if (row.technique == technique && row.scene == scene && row.check == check) return &row;
    return nullptr;
}

// plain_lit.fx in `dir` with `from` replaced by `to`, its include folder beside it.
fs::path plainLitCopy(const fs::path& dir, const std::string& from, const std::string& to) {
    fs::copy(std::string(SHADOWFX_SOURCE_DIR) + "/effects/include", dir / "include",
             fs::copy_options::recursive);
    std::ifstream in(std::string(SHADOWFX_SOURCE_DIR) + "/effects/plain_lit.fx");
    std::stringstream text;
    text << in.rdbuf();
    std::string effect = text.str();
    const size_t at = effect.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) effect.replace(at, from.size(), to);
    const fs::path path = dir / "plain_lit.fx";
    std::ofstream(path) << effect;
    return path;
}

TEST(ConformanceRun, AShippedEffectRendersAndMatchesItsGoldens) {
    const ScratchDirectory scratch("conformance_shipped");
    runtime::ConformanceOptions options = oneBackend(scratch / "out");
    options.effects = {"effects/plain_lit.fx"};
    const runtime::ConformanceResult result = runtime::runConformance(options, {});
    EXPECT_TRUE(result.anyContext);
    EXPECT_FALSE(result.noTechniqueMatches);
    const report::CheckRow* render = findRow(result, "lit", "boxes", "render");
    ASSERT_NE(render, nullptr);
    EXPECT_EQ(render->outcome, report::CheckOutcome::Pass) << render->detail;
    EXPECT_EQ(render->backend, "egl");
    EXPECT_EQ(render->effect, "plain_lit");
    const report::CheckRow* golden = findRow(result, "lit", "boxes", "golden");
    ASSERT_NE(golden, nullptr);
    EXPECT_EQ(golden->outcome, report::CheckOutcome::Pass) << golden->detail;
    EXPECT_EQ(findRow(result, "lit", "boxes", "misclassified"), nullptr) << "plain_lit declares no shadows";
}

TEST(ConformanceRun, ABlankFrameFailsItsRenderCheck) {
    const ScratchDirectory scratch("conformance_blank");
    runtime::ConformanceOptions options = oneBackend(scratch / "out");
    // The technique clears and draws nothing.
    options.effects = {plainLitCopy(scratch.path(), "\"Pass=p0;\"", "\"\"").string()};
    const runtime::ConformanceResult result = runtime::runConformance(options, {});
    const report::CheckRow* render = findRow(result, "lit", "boxes", "render");
    ASSERT_NE(render, nullptr);
    EXPECT_EQ(render->outcome, report::CheckOutcome::Fail);
    EXPECT_EQ(render->detail.rfind(report::kBlankFrame, 0), 0u) << render->detail;
    EXPECT_NE(render->detail.find("constant colour"), std::string::npos) << render->detail;
}

// A file without techniques compiles (an effect pool's shared parameters), but there is nothing to check.
TEST(ConformanceRun, AFileWithoutTechniquesFailsAtItsFirstLine) {
    const ScratchDirectory scratch("conformance_no_techniques");
    const fs::path effect = scratch / "pool.fx";
    std::ofstream(effect) << "shared float4 AmbientColor : AMBIENT = {0.1, 0.1, 0.1, 1};\n";
    runtime::ConformanceOptions options = oneBackend(scratch / "out");
    options.effects = {effect.string()};
    const runtime::ConformanceResult result = runtime::runConformance(options, {});
    ASSERT_EQ(result.rows.size(), 1u);
    EXPECT_EQ(result.rows[0].check, "compile");
    EXPECT_EQ(result.rows[0].outcome, report::CheckOutcome::Fail);
    EXPECT_NE(result.rows[0].detail.find("pool.fx:1:1: error: the file has no techniques"), std::string::npos)
        << result.rows[0].detail;
}

}  // namespace
}  // namespace shadowfx::test::test_conformance_run
