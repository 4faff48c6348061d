// StressReport: what `shadowfx stress` measured (runtime/StressRun.h fills it) and its outputs: the table
// it prints, stress.json and report.md. GL-free: the writers run on results made up in a test.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace report {

// [SECTION] Criteria: what passing means, as numbers.
// A case may be harder than its ordinary configuration, but not wholesale broken: its misclassified
// percentage may be at most kOrdinaryFactor times the ordinary one plus kOrdinarySlack points.
constexpr double kOrdinaryFactor = 3.0;
constexpr double kOrdinarySlack = 1.0;
// ... plus what the case asks of the effect's own light fit beyond the ordinary configuration: the rise of
// the fit's sampling-limited error (samplingLimitedRise). A case whose shadow boundaries the view sees where
// the fit's texels are large (a view-independent map whose casters throw their shadows at the camera) costs
// any map of that fit and size that much; a fit that follows the view keeps the rise small, so it is held to
// its ordinary error as before. Bias and filter failures do not raise it: it depends on the fit alone.
// No method may do worse than the uniform shadow map on the same case, beyond filtering noise.
constexpr double kUniformFactor = 1.5;
constexpr double kUniformSlack = 0.5;
// Shimmer: the mean share of receiver pixels whose shadow state flips between consecutive frames while the
// truth at that pixel does not, in percent. Every shipped method has a view-independent light fit, so
// each claims stability and is held to it.
constexpr double kShimmerLimit = 0.25;
// Error criteria need enough receiver pixels to mean something: one pixel of six is not 17 % of a method.
constexpr size_t kMinScoredReceivers = 1000;

// What a failed run failed on. A technique's declaration excuses the criteria it names (stressCriterionName)
// and no others; a failure to render or a non-finite value can never be excused.
enum class StressCriterion {
    Render,       // the effect does not compile, link or render, or a GL error
    Finite,       // a matrix, parameter or render-target texel is NaN or Inf
    LightVolume,  // receiver pixels outside the clip volume of a light fit
    Ordinary,     // the error against the case's ordinary configuration
    Uniform,      // the error against the uniform shadow map on the same case
    Shimmer,      // flips of steady pixels between frames of a temporal case
};

const char* stressCriterionName(StressCriterion criterion);
// The criterion a declaration may name `name` by; nullopt for render, finite and unknown names.
std::optional<StressCriterion> excusableCriterion(std::string_view name);

// One effect x technique x case.
struct StressOutcome {
    std::string effect;  // the effect file's name, or the peer's ("osg")
    std::string technique;
    std::string peer;  // "osg/<technique>" for another library's technique (`stress --peers`), else empty
    std::string caseName;
    bool pass = true;
    bool expectedFailure = false;  // the technique declares this case a known limitation
    std::string expectedBecause;
    std::vector<StressCriterion> excused;  // the criteria the declaration names
    std::vector<std::string> reasons;
    std::vector<StressCriterion> failed;            // one per reason
    std::optional<double> misclassified;            // percent of receiver pixels (mean over the frames)
    double falseShadow = 0.0, falseLight = 0.0;     // its two parts
    std::optional<double> ordinary;                 // the nearest ordinary case's, same effect and technique
    std::optional<double> uniform;                  // the uniform shadow map's, same case
    std::optional<double> shimmerMean, shimmerMax;  // percent, temporal cases
    std::optional<double> maxFootprint, p95Footprint;  // texels of the effect's own fit (first frame)
    // The sampling-limited error of the effect's own fit (runtime/ShadowMetrics.h, first frame), percent, on
    // this case and on its ordinary one.
    std::optional<double> samplingLimited, ordinarySamplingLimited;
    size_t receivers = 0;

    void fail(StressCriterion criterion, std::string reason) {
        pass = false;
        reasons.push_back(std::move(reason));
        failed.push_back(criterion);
    }
    // Failed, and only on criteria its declaration names.
    bool isExcused() const {
        return !pass && expectedFailure && std::all_of(failed.begin(), failed.end(), [&](StressCriterion c) {
            return std::find(excused.begin(), excused.end(), c) != excused.end();
        });
    }
    // "pass", "xpass" (declared, yet passed), "xfail" (failed only where declared) or "FAIL"; a peer's
    // technique "pass" or "breaks" (it declares nothing, and its failures do not fail the run).
    std::string result() const {
        if (!peer.empty()) return pass ? "pass" : "breaks";
        if (pass) return expectedFailure ? "xpass" : "pass";
        return isExcused() ? "xfail" : "FAIL";
    }
};

// What the case adds to the ordinary criterion's bound: how far the sampling-limited error of the effect's
// own fit rises from the ordinary configuration to the case, in points; 0 where either is unknown or it
// falls.
double samplingLimitedRise(const StressOutcome& outcome);

// One case as the run measured its configuration, whatever the effect.
struct StressCaseSummary {
    std::string name;
    std::string description;
    std::string ordinary;  // the case it is held to ("" for an ordinary case)
    size_t frames = 1;
    size_t receiverPixels = 0;  // of the first frame
    size_t outsideLightVolume = 0;
    double maxFootprint = 0.0;  // of the runtime's uniform map
    double p95Footprint = 0.0;
    std::optional<double> uniformMisclassified;  // the uniform reference's error, percent
};

struct StressResult {
    std::string renderer;
    int width = 0, height = 0, mapSize = 0;
    std::vector<StressCaseSummary> cases;  // every case run, ordinary ones first
    std::vector<StressOutcome> outcomes;   // the requested cases' runs
};

// The table of `result.outcomes`, one block per effect and technique: text (stdout) or markdown.
void writeStressTable(std::ostream& out, const StressResult& result, bool markdown);
// stress.json's document.
nlohmann::ordered_json stressJson(const StressResult& result);
// report.md: the run's configuration and the markdown table.
void writeStressMarkdown(std::ostream& out, const StressResult& result);

}  // namespace report
