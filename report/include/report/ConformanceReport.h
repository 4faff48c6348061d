// ConformanceReport: what `shadowfx check` found (runtime/ConformanceRun.h fills it), one row per (backend,
// effect, technique, scene, check), and its outputs: the table, the per-effect summary, the count line and
// JUnit XML. GL-free: the writers run on rows made up in a test.
//
// Outcomes: PASS; QUALITY_WARNING (passes, but a measured value is above 80% of its bound, or the technique
// of a shadowing effect declares no ExpectMisclassifiedBelow); NOT_SUPPORTED (the check cannot run here);
// FAIL. Only FAIL makes the exit status 1.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace report {

enum class CheckOutcome { Pass, QualityWarning, NotSupported, Fail };

const char* checkOutcomeName(CheckOutcome outcome);  // "PASS", "QUALITY_WARNING", ...

struct CheckRow {
    std::string backend;  // "osmesa", "egl", or "-" for checks before any backend (compile)
    std::string effect;   // the file's stem
    std::string technique;
    std::string scene;
    std::string check;  // render, misclassified, penumbra, golden, compile, link, expectations, backend
    CheckOutcome outcome = CheckOutcome::Pass;
    std::string detail;
};

// A measured value against its "below" bound: FAIL at or above it (NaN too), QUALITY_WARNING above
// kWarnFraction of it.
constexpr double kWarnFraction = 0.8;
CheckOutcome judgeBelow(double measured, double bound);

// How a render row's detail begins when the frame is blank: the effect summary tells a blank frame from a
// failure by it.
constexpr std::string_view kBlankFrame = "the frame is ";

// The table: a header and one aligned row per check.
void writeCheckTable(std::ostream& out, const std::vector<CheckRow>& rows);
// One line per effect, for a run over a library (`check lib/*.fx`): `drawn` when every frame it rendered
// shows something, `blank` with the first blank frame, `failed` with the first error that kept it from
// compiling or rendering; then `N effects: A drawn, B blank, C failed`. Expectations and goldens are the
// table's business: this says whether the effects draw at all.
void writeEffectSummary(std::ostream& out, const std::vector<CheckRow>& rows);
// "N checks: A PASS, B QUALITY_WARNING, C NOT_SUPPORTED, D FAIL".
void writeCheckCounts(std::ostream& out, const std::vector<CheckRow>& rows);
// JUnit XML as Jenkins, GitLab and GitHub's test reporters read it: one <testsuite> per effect, one
// <testcase> per row (classname EFFECT.TECHNIQUE, name SCENE.CHECK[BACKEND]); FAIL is <failure>,
// NOT_SUPPORTED <skipped>, QUALITY_WARNING a passing case with the warning in <system-out>.
void writeJunit(std::ostream& xml, const std::vector<CheckRow>& rows);

}  // namespace report
