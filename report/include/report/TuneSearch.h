// TuneSearch: `shadowfx tune`'s search of a technique's tweakables for the least error within a frame-time
// budget. GL-free and deterministic: it proposes settings, a caller-supplied objective measures them
// (the command: bench runs scored by the ray-cast truth; a test: a formula), and the same answers give the
// same search.
//
// The search, within a fixed number of evaluations:
//   1. the effect's own setting (the reference the result must beat);
//   2. a coarse grid per parameter in turn (`gridPoints` values over UIMin..UIMax, on the parameter's scale),
//      the others held at the best setting so far;
//   3. coordinate descent (a compass search): each parameter tried a step either side of the best, starting
//      at half a grid step, the step kept while it finds a better setting and halved when it does not, until
//      every step is below UIStep (1 for an int) or the evaluations run out.
// Each batch differs from the best setting in one parameter only, so the command measures it as one bench
// sweep. The best setting is the one with the least error among those at or under the budget (ties: the
// faster, then the earlier); until one is found, the fastest setting is where the search moves from.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace report {

struct TuneParameter {
    enum class Kind { Float, Int, Bool };
    std::string name;
    Kind kind = Kind::Float;
    double min = 0.0;       // UIMin (Bool: 0)
    double max = 1.0;       // UIMax (Bool: 1)
    double step = 0.0;      // UIStep: values are UIMin + k * UIStep; 0: any value (Int: whole numbers)
    bool logScale = false;  // `string UIScale = "log";`: grid and refinement by ratios (needs min > 0)
    double initial = 0.0;   // the effect's value, the search's start
};

// One value per parameter, in the order of the parameters.
using TuneSetting = std::vector<double>;

struct TuneScore {
    double errorPercent = 0.0;  // the mean misclassified % over the scenes
    double frameMs = 0.0;       // the frame time held against the budget (the command: the slowest scene's)
};

struct TuneOptions {
    int evaluations = 24;            // settings measured at most, the effect's own included
    int gridPoints = 5;              // values of a parameter's coarse grid, its ends included (>= 2)
    std::optional<double> budgetMs;  // none: every setting is within budget
};

struct TuneEvaluation {
    TuneSetting setting;
    TuneScore score;
    bool withinBudget = true;
    int batch = 0;  // the batch (one objective call) that measured it
};

struct TuneResult {
    std::vector<TuneEvaluation> evaluations;  // in the order measured; [0] is the effect's own setting
    std::optional<size_t> best;               // none when no setting is at or under the budget
    bool failed = false;                      // the objective failed: the search stopped there
};

// Measures `settings` (all differing from one setting in one parameter), one score per setting in order;
// false stops the search (the objective says why to its caller).
using TuneObjective =
    std::function<bool(const std::vector<TuneSetting>& settings, std::vector<TuneScore>& scores)>;

// The value as the effect reads it from text (`--set Name=value`): "true"/"false", a whole number, or a
// number with 6 significant digits. The search keeps only values that this text gives back exactly.
std::string formatTuneValue(const TuneParameter& parameter, double value);

// `value` moved onto the parameter's values: within UIMin..UIMax, onto the UIStep lattice, whole for Int,
// 0 or 1 for Bool, and as formatTuneValue writes it.
double snapTuneValue(const TuneParameter& parameter, double value);

// "--set Bias=0.003 --set SlopeScale=2": the setting as the options render, bench and check take.
std::string tuneSetLine(const std::vector<TuneParameter>& parameters, const TuneSetting& setting);

TuneResult tuneSearch(const std::vector<TuneParameter>& parameters, const TuneOptions& options,
                      const TuneObjective& objective);

}  // namespace report
