// The conformance writers (report/ConformanceReport.h) on rows made up here: a measured value against its
// bound, the aligned table, the per-effect summary (drawn, blank, failed) with its count line, the checks'
// count line, and JUnit XML (failure, skipped, a warning in system-out, escaped text, per-suite counts).
#include <report/ConformanceReport.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace shadowfx::test::test_conformance_report {
namespace {

using report::CheckOutcome;
using report::CheckRow;

std::vector<CheckRow> madeUpRows() {
    return {
        {"-", "broken", "-", "-", "compile", CheckOutcome::Fail,
         "broken.fx:1:30: error: undeclared name\nmore"},
        {"osmesa", "pcf", "bilinear", "boxes", "render", CheckOutcome::Pass, "no GL errors"},
        {"osmesa", "pcf", "bilinear", "boxes", "misclassified", CheckOutcome::QualityWarning, "0.9 % < 1 %"},
        {"osmesa", "pcf", "bilinear", "boxes", "golden", CheckOutcome::NotSupported, "no goldens for 'x'"},
        {"osmesa", "blank", "main", "boxes", "render", CheckOutcome::Fail,
         "the frame is one constant colour"},
        {"egl", "blank", "main", "boxes", "golden", CheckOutcome::Fail, "3 pixels differ <&> \"here\""},
    };
}

TEST(ConformanceReport, AValueIsJudgedAgainstItsBound) {
    EXPECT_EQ(report::judgeBelow(0.5, 1.0), CheckOutcome::Pass);
    EXPECT_EQ(report::judgeBelow(0.8, 1.0), CheckOutcome::Pass);
    EXPECT_EQ(report::judgeBelow(0.81, 1.0), CheckOutcome::QualityWarning);
    EXPECT_EQ(report::judgeBelow(1.0, 1.0), CheckOutcome::Fail);
    EXPECT_EQ(report::judgeBelow(std::nan(""), 1.0), CheckOutcome::Fail);
    EXPECT_STREQ(report::checkOutcomeName(CheckOutcome::QualityWarning), "QUALITY_WARNING");
    EXPECT_STREQ(report::checkOutcomeName(CheckOutcome::NotSupported), "NOT_SUPPORTED");
}

TEST(ConformanceReport, TheTableAlignsEveryColumnButTheLast) {
    std::ostringstream out;
    report::writeCheckTable(out, madeUpRows());
    const std::string table = out.str();
    EXPECT_EQ(table.find("RESULT           BACKEND  EFFECT  TECHNIQUE  SCENE  CHECK          DETAIL\n"), 0u)
        << table;
    EXPECT_NE(
        table.find("\nQUALITY_WARNING  osmesa   pcf     bilinear   boxes  misclassified  0.9 % < 1 %\n"),
        std::string::npos)
        << table;
    EXPECT_NE(table.find("\nFAIL             egl      blank   main       boxes  golden         3 pixels"),
              std::string::npos)
        << table;
}

TEST(ConformanceReport, TheSummarySaysWhetherEachEffectDraws) {
    std::ostringstream out;
    report::writeEffectSummary(out, madeUpRows());
    EXPECT_EQ(out.str(),
              "\nbroken: failed: broken.fx:1:30: error: undeclared name\n"
              "pcf: drawn\n"
              "blank: blank: main: the frame is one constant colour\n"
              "3 effects: 1 drawn, 1 blank, 1 failed\n");
    std::ostringstream one;
    report::writeEffectSummary(one, {madeUpRows()[1]});
    EXPECT_EQ(one.str(), "\npcf: drawn\n1 effect: 1 drawn, 0 blank, 0 failed\n");
}

TEST(ConformanceReport, TheCountLineCountsEveryOutcome) {
    std::ostringstream out;
    report::writeCheckCounts(out, madeUpRows());
    EXPECT_EQ(out.str(), "6 checks: 1 PASS, 1 QUALITY_WARNING, 1 NOT_SUPPORTED, 3 FAIL\n");
}

TEST(ConformanceReport, JunitHasASuitePerEffectAndACasePerRow) {
    std::ostringstream out;
    report::writeJunit(out, madeUpRows());
    const std::string xml = out.str();
    EXPECT_EQ(xml.find("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"shadowfx check\" "
                       "tests=\"6\" failures=\"3\" skipped=\"1\" errors=\"0\">\n"),
              0u)
        << xml;
    EXPECT_NE(xml.find("<testsuite name=\"pcf\" tests=\"3\" failures=\"0\" skipped=\"1\" errors=\"0\">"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<testcase classname=\"pcf.bilinear\" name=\"boxes.render[osmesa]\"/>"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<system-out>QUALITY_WARNING: 0.9 % &lt; 1 %</system-out>"), std::string::npos) << xml;
    EXPECT_NE(xml.find("<skipped message=\"NOT_SUPPORTED: no goldens for &apos;x&apos;\"/>"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<failure type=\"FAIL\" message=\"3 pixels differ &lt;&amp;&gt; &quot;here&quot;\">"),
              std::string::npos)
        << xml;
    EXPECT_EQ(xml.substr(xml.size() - 14), "</testsuites>\n") << xml;
}

}  // namespace
}  // namespace shadowfx::test::test_conformance_report
