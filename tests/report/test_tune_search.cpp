// `shadowfx tune`'s search (report/TuneSearch.h) on synthetic objectives whose optimum is known: it finds
// it, keeps to the budget and to the number of evaluations, searches a log-scaled range by ratios, and
// proposes batches that each vary one parameter (what one bench sweep measures).
#include <report/TuneSearch.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace shadowfx::test::test_tune_search {
namespace {

using report::TuneParameter;
using report::TuneScore;
using report::TuneSetting;

// A filter-like pair: a float radius with its best error at 0.3, a sample count whose error falls toward 7
// and whose cost grows with it.
std::vector<TuneParameter> radiusAndSamples() {
    TuneParameter radius{"Radius", TuneParameter::Kind::Float, 0.0, 1.0, 0.01, false, 0.9};
    TuneParameter samples{"Samples", TuneParameter::Kind::Int, 1.0, 32.0, 0.0, false, 16.0};
    return {radius, samples};
}

report::TuneObjective bowl(int& calls) {
    return [&calls](const std::vector<TuneSetting>& settings, std::vector<TuneScore>& scores) {
        ++calls;
        for (const TuneSetting& s : settings)
            scores.push_back(
                {100.0 * (s[0] - 0.3) * (s[0] - 0.3) + (s[1] - 7.0) * (s[1] - 7.0) * 0.1, 1.0 + s[1]});
        return true;
    };
}

TEST(TuneSearch, FindsTheKnownOptimumWithoutBudget) {
    int calls = 0;
    report::TuneOptions options;
    options.evaluations = 40;
    const report::TuneResult result = report::tuneSearch(radiusAndSamples(), options, bowl(calls));
    ASSERT_TRUE(result.best);
    const TuneSetting& best = result.evaluations[*result.best].setting;
    EXPECT_NEAR(best[0], 0.3, 0.011);
    EXPECT_EQ(best[1], 7.0);
    EXPECT_LE(result.evaluations.size(), 40u);
    // The effect's own setting comes first, as the effect has it.
    EXPECT_EQ(result.evaluations[0].setting, (TuneSetting{0.9, 16.0}));
    EXPECT_LT(result.evaluations[*result.best].score.errorPercent, result.evaluations[0].score.errorPercent);
}

TEST(TuneSearch, TheBestIsAtOrUnderTheBudgetAndTheBestThere) {
    int calls = 0;
    report::TuneOptions options;
    options.evaluations = 60;
    options.budgetMs = 5.0;  // Samples <= 4
    const report::TuneResult result = report::tuneSearch(radiusAndSamples(), options, bowl(calls));
    ASSERT_TRUE(result.best);
    const report::TuneEvaluation& best = result.evaluations[*result.best];
    EXPECT_LE(best.score.frameMs, 5.0);
    EXPECT_TRUE(best.withinBudget);
    EXPECT_EQ(best.setting[1], 4.0);
    EXPECT_NEAR(best.setting[0], 0.3, 0.011);
    // The effect's own setting (16 samples) is over budget, and marked so.
    EXPECT_FALSE(result.evaluations[0].withinBudget);
    for (const report::TuneEvaluation& e : result.evaluations) {
        EXPECT_EQ(e.withinBudget, e.score.frameMs <= 5.0);
        if (e.withinBudget) {
            EXPECT_GE(e.score.errorPercent, best.score.errorPercent);
        }
    }
}

TEST(TuneSearch, AnImpossibleBudgetHasNoBest) {
    int calls = 0;
    report::TuneOptions options;
    options.evaluations = 12;
    options.budgetMs = 0.5;
    const report::TuneResult result = report::tuneSearch(radiusAndSamples(), options, bowl(calls));
    EXPECT_FALSE(result.best);
    EXPECT_FALSE(result.failed);
    EXPECT_EQ(result.evaluations.size(), 12u);
}

TEST(TuneSearch, KeepsToTheEvaluationsAndIsDeterministic) {
    for (int evaluations : {1, 3, 7, 20}) {
        int calls = 0;
        report::TuneOptions options;
        options.evaluations = evaluations;
        const report::TuneResult a = report::tuneSearch(radiusAndSamples(), options, bowl(calls));
        const report::TuneResult b = report::tuneSearch(radiusAndSamples(), options, bowl(calls));
        EXPECT_EQ(a.evaluations.size(), static_cast<size_t>(evaluations));
        ASSERT_EQ(a.evaluations.size(), b.evaluations.size());
        for (size_t e = 0; e < a.evaluations.size(); ++e)
            EXPECT_EQ(a.evaluations[e].setting, b.evaluations[e].setting);
        EXPECT_EQ(a.best, b.best);
    }
}

TEST(TuneSearch, EachBatchVariesOneParameterAndNoSettingIsMeasuredTwice) {
    std::vector<std::vector<TuneSetting>> batches;
    const report::TuneObjective objective = [&](const std::vector<TuneSetting>& settings,
                                                std::vector<TuneScore>& scores) {
        batches.push_back(settings);
        for (const TuneSetting& s : settings)
            scores.push_back({std::abs(s[0] - 0.42) + std::abs(s[1] - 3.0), 1.0});
        return true;
    };
    report::TuneOptions options;
    options.evaluations = 60;
    const report::TuneResult result = report::tuneSearch(radiusAndSamples(), options, objective);
    std::set<TuneSetting> seen;
    for (const report::TuneEvaluation& e : result.evaluations) EXPECT_TRUE(seen.insert(e.setting).second);
    for (const std::vector<TuneSetting>& batch : batches) {
        std::set<size_t> varied;
        for (const TuneSetting& s : batch)
            for (size_t i = 0; i < s.size(); ++i)
                if (s[i] != batch.front()[i]) varied.insert(i);
        EXPECT_LE(varied.size(), 1u);
    }
    // Steps below UIStep and whole samples end the search before the evaluations do.
    EXPECT_LT(result.evaluations.size(), 60u);
    ASSERT_TRUE(result.best);
    EXPECT_NEAR(result.evaluations[*result.best].setting[0], 0.42, 0.011);
    EXPECT_EQ(result.evaluations[*result.best].setting[1], 3.0);
}

TEST(TuneSearch, ALogScaledRangeIsSearchedByRatios) {
    const TuneParameter exponent{"Exponent", TuneParameter::Kind::Float, 1.0, 10000.0, 0.0, true, 1.0};
    std::vector<double> grid;
    const report::TuneObjective objective = [&](const std::vector<TuneSetting>& settings,
                                                std::vector<TuneScore>& scores) {
        for (const TuneSetting& s : settings) {
            if (grid.size() < 6) grid.push_back(s[0]);
            scores.push_back({std::abs(std::log10(s[0] / 37.0)), 1.0});
        }
        return true;
    };
    report::TuneOptions options;
    options.evaluations = 30;
    const report::TuneResult result = report::tuneSearch({exponent}, options, objective);
    // The effect's value (also the grid's first point, measured once), then one grid point per decade.
    ASSERT_EQ(grid.size(), 6u);
    grid.resize(5);
    EXPECT_EQ(grid, (std::vector<double>{1.0, 10.0, 100.0, 1000.0, 10000.0}));
    ASSERT_TRUE(result.best);
    EXPECT_NEAR(std::log10(result.evaluations[*result.best].setting[0] / 37.0), 0.0, 0.05);
}

TEST(TuneSearch, ABoolIsTriedBothWays) {
    const TuneParameter pcf{"PCF", TuneParameter::Kind::Bool, 0.0, 1.0, 0.0, false, 0.0};
    const report::TuneObjective objective = [](const std::vector<TuneSetting>& settings,
                                               std::vector<TuneScore>& scores) {
        for (const TuneSetting& s : settings) scores.push_back({s[0] > 0.5 ? 1.0 : 2.0, 1.0});
        return true;
    };
    const report::TuneResult result = report::tuneSearch({pcf}, report::TuneOptions{}, objective);
    ASSERT_EQ(result.evaluations.size(), 2u);
    ASSERT_TRUE(result.best);
    EXPECT_EQ(result.evaluations[*result.best].setting[0], 1.0);
    EXPECT_EQ(report::tuneSetLine({pcf}, result.evaluations[*result.best].setting), "--set PCF=true");
}

TEST(TuneSearch, AFailingObjectiveStopsTheSearch) {
    int calls = 0;
    const report::TuneObjective objective = [&](const std::vector<TuneSetting>&, std::vector<TuneScore>&) {
        ++calls;
        return false;
    };
    const report::TuneResult result =
        report::tuneSearch(radiusAndSamples(), report::TuneOptions{}, objective);
    EXPECT_TRUE(result.failed);
    EXPECT_EQ(calls, 1);
    EXPECT_TRUE(result.evaluations.empty());
}

TEST(TuneSearch, ValuesAreSnappedOntoWhatTheEffectReads) {
    const TuneParameter bias{"Bias", TuneParameter::Kind::Float, 0.0, 0.02, 0.0001, false, 0.003};
    EXPECT_DOUBLE_EQ(report::snapTuneValue(bias, 0.00312), 0.0031);
    EXPECT_DOUBLE_EQ(report::snapTuneValue(bias, -1.0), 0.0);
    EXPECT_DOUBLE_EQ(report::snapTuneValue(bias, 1.0), 0.02);
    EXPECT_EQ(report::formatTuneValue(bias, 0.0031), "0.0031");
    const TuneParameter samples{"Samples", TuneParameter::Kind::Int, 1.0, 32.0, 0.0, false, 16.0};
    EXPECT_EQ(report::snapTuneValue(samples, 7.4), 7.0);
    EXPECT_EQ(report::formatTuneValue(samples, 7.0), "7");
    // A range that is not a whole number of steps: the last lattice point inside.
    const TuneParameter width{"Width", TuneParameter::Kind::Float, 0.5, 8.0, 0.4, false, 1.0};
    EXPECT_LE(report::snapTuneValue(width, 8.0), 8.0);
    EXPECT_NEAR(report::snapTuneValue(width, 8.0), 7.7, 1e-9);
    EXPECT_EQ(report::tuneSetLine({bias, samples}, {0.0031, 7.0}), "--set Bias=0.0031 --set Samples=7");
}

}  // namespace
}  // namespace shadowfx::test::test_tune_search
