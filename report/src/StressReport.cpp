// StressReport: see StressReport.h.
#include <report/NumberFormat.h>
#include <report/StressReport.h>

#include <iomanip>
#include <sstream>

namespace report {

using Json = nlohmann::ordered_json;

const char* stressCriterionName(StressCriterion criterion) {
    switch (criterion) {
        case StressCriterion::Render:
            return "render";
        case StressCriterion::Finite:
            return "finite";
        case StressCriterion::LightVolume:
            return "light-volume";
        case StressCriterion::Ordinary:
            return "ordinary";
        case StressCriterion::Uniform:
            return "uniform";
        case StressCriterion::Shimmer:
            return "shimmer";
    }
    return "?";
}

std::optional<StressCriterion> excusableCriterion(std::string_view name) {
    for (StressCriterion c : {StressCriterion::LightVolume, StressCriterion::Ordinary,
                              StressCriterion::Uniform, StressCriterion::Shimmer})
        if (name == stressCriterionName(c)) return c;
    return std::nullopt;
}

namespace {

std::vector<std::string> criterionNames(const std::vector<StressCriterion>& criteria) {
    std::vector<std::string> names;
    for (StressCriterion c : criteria) names.emplace_back(stressCriterionName(c));
    return names;
}

Json optionalJson(const std::optional<double>& value) {
    return value ? Json(*value) : Json(nullptr);
}

std::string cell(const std::optional<double>& value) {
    return value ? formatPercent(*value) : "-";
}

const StressCaseSummary* findCase(const StressResult& result, const std::string& name) {
    for (const StressCaseSummary& c : result.cases)
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace

double samplingLimitedRise(const StressOutcome& outcome) {
    if (!outcome.samplingLimited || !outcome.ordinarySamplingLimited) return 0.0;
    return std::max(0.0, *outcome.samplingLimited - *outcome.ordinarySamplingLimited);
}

void writeStressTable(std::ostream& out, const StressResult& result, bool markdown) {
    std::string current;
    for (const StressOutcome& o : result.outcomes) {
        const std::string heading = o.effect + " / " + o.technique;
        if (heading != current) {
            current = heading;
            if (markdown) {
                out << "\n### " << heading << "\n\n| case | result | misclassified | ordinary | uniform | "
                    << "p95 footprint | shimmer | why |\n|---|---|---|---|---|---|---|---|\n";
            } else {
                out << "\n"
                    << heading << "\n  " << std::left << std::setw(24) << "case" << std::setw(7) << "result"
                    << std::setw(15) << "misclassified" << std::setw(10) << "ordinary" << std::setw(10)
                    << "uniform" << std::setw(10) << "footprint" << std::setw(10) << "shimmer"
                    << "why\n";
            }
        }
        // The texel footprint of the effect's own fit where it has one, else of the runtime's uniform map.
        const StressCaseSummary* summary = findCase(result, o.caseName);
        std::ostringstream footprint;
        footprint << std::fixed << std::setprecision(1)
                  << o.p95Footprint.value_or(summary ? summary->p95Footprint : 0.0);
        std::string why;
        for (const std::string& reason : o.reasons) why += (why.empty() ? "" : "; ") + reason;
        if (o.misclassified == std::nullopt && o.pass && o.receivers == 0) why = "no receiver pixels";
        if (o.misclassified && o.receivers < kMinScoredReceivers)
            why = std::to_string(o.receivers) + " receiver pixels: too few to judge the error";
        const std::string shimmer = o.shimmerMean ? formatPercent(*o.shimmerMean) : "-";
        const std::string outcome = o.result();
        if (o.expectedFailure) {
            std::string criteria;
            for (StressCriterion c : o.excused)
                criteria += (criteria.empty() ? "" : ", ") + std::string(stressCriterionName(c));
            why +=
                (why.empty() ? "" : "; ") + std::string("declared [") + criteria + "]:" + o.expectedBecause;
        }
        if (markdown) {
            out << "| " << o.caseName << " | " << (outcome == "FAIL" ? "**FAIL**" : outcome) << " | "
                << cell(o.misclassified) << " | " << cell(o.ordinary) << " | " << cell(o.uniform) << " | "
                << footprint.str() << " | " << shimmer << " | " << why << " |\n";
        } else {
            out << "  " << std::left << std::setw(24) << o.caseName << std::setw(7) << outcome
                << std::setw(15) << cell(o.misclassified) << std::setw(10) << cell(o.ordinary)
                << std::setw(10) << cell(o.uniform) << std::setw(10) << footprint.str() << std::setw(10)
                << shimmer << why << "\n";
        }
    }
}

Json stressJson(const StressResult& result) {
    Json cases = Json::array();
    for (const StressCaseSummary& c : result.cases) {
        cases.push_back(Json{{"name", c.name},
                             {"description", c.description},
                             {"ordinary", c.ordinary},
                             {"frames", c.frames},
                             {"receiver_pixels", c.receiverPixels},
                             {"outside_light_volume", c.outsideLightVolume},
                             {"max_footprint", c.maxFootprint},
                             {"p95_footprint", c.p95Footprint},
                             {"uniform_misclassified_percent", optionalJson(c.uniformMisclassified)}});
    }
    Json results = Json::array();
    for (const StressOutcome& o : result.outcomes)
        results.push_back(Json{{"effect", o.effect},
                               {"technique", o.technique},
                               {"peer", o.peer.empty() ? Json(nullptr) : Json(o.peer)},
                               {"case", o.caseName},
                               {"pass", o.pass},
                               {"result", o.result()},
                               {"expected_failure", o.expectedFailure},
                               {"excused_criteria", criterionNames(o.excused)},
                               {"reasons", o.reasons},
                               {"failed_criteria", criterionNames(o.failed)},
                               {"misclassified_percent", optionalJson(o.misclassified)},
                               {"false_shadow_percent", o.falseShadow},
                               {"false_light_percent", o.falseLight},
                               {"ordinary_percent", optionalJson(o.ordinary)},
                               {"uniform_percent", optionalJson(o.uniform)},
                               {"shimmer_mean_percent", optionalJson(o.shimmerMean)},
                               {"shimmer_max_percent", optionalJson(o.shimmerMax)},
                               {"max_footprint", optionalJson(o.maxFootprint)},
                               {"p95_footprint", optionalJson(o.p95Footprint)},
                               {"sampling_limited_percent", optionalJson(o.samplingLimited)},
                               {"ordinary_sampling_limited_percent", optionalJson(o.ordinarySamplingLimited)},
                               {"receiver_pixels", o.receivers}});
    return Json{{"renderer", result.renderer},
                {"width", result.width},
                {"height", result.height},
                {"map_size", result.mapSize},
                {"criteria",
                 {{"ordinary_factor", kOrdinaryFactor},
                  {"ordinary_slack_points", kOrdinarySlack},
                  {"uniform_factor", kUniformFactor},
                  {"uniform_slack_points", kUniformSlack},
                  {"shimmer_limit_percent", kShimmerLimit}}},
                {"cases", cases},
                {"results", results}};
}

void writeStressMarkdown(std::ostream& out, const StressResult& result) {
    out << "# shadowfx stress\n\nRenderer: " << result.renderer << ", " << result.width << "x"
        << result.height << ", shadow maps " << result.mapSize << "².\n";
    writeStressTable(out, result, true);
}

}  // namespace report
