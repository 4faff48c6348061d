// TuneSearch: see TuneSearch.h.
#include <report/TuneSearch.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace report {

namespace {

// Where `value` lies between the parameter's ends on its scale: 0 at UIMin, 1 at UIMax.
double positionOf(const TuneParameter& p, double value) {
    if (p.max <= p.min) return 0.0;
    if (p.logScale) return std::log(value / p.min) / std::log(p.max / p.min);
    return (value - p.min) / (p.max - p.min);
}

double valueAt(const TuneParameter& p, double position) {
    position = std::clamp(position, 0.0, 1.0);
    if (p.logScale) return p.min * std::pow(p.max / p.min, position);
    return p.min + position * (p.max - p.min);
}

// The smallest move on the parameter's scale that can still give a new value: a step of UIStep (1 for an
// int) where the scale is finest (at UIMax on a log scale); a ten-thousandth of the range without a step.
double resolutionOf(const TuneParameter& p) {
    const double range = p.max - p.min;
    if (range <= 0.0) return 1.0;
    double finest = p.step;
    if (p.kind == TuneParameter::Kind::Int) finest = std::max(finest, 1.0);
    if (finest <= 0.0) return 1e-4;
    if (p.logScale) return std::log(p.max / (p.max - std::min(finest, range))) / std::log(p.max / p.min);
    return finest / range;
}

class Search {
public:
    Search(const std::vector<TuneParameter>& parameters, const TuneOptions& options,
           const TuneObjective& objective)
        : mParameters(parameters), mOptions(options), mObjective(objective) {}

    TuneResult run() {
        TuneSetting initial;
        for (const TuneParameter& p : mParameters) initial.push_back(snapTuneValue(p, p.initial));
        if (!measure({initial})) return std::move(mResult);
        const int gridPoints = std::max(mOptions.gridPoints, 2);
        for (size_t i = 0; i < mParameters.size() && remaining() > 0; ++i) {
            const TuneParameter& p = mParameters[i];
            std::vector<double> values;
            if (p.kind == TuneParameter::Kind::Bool) {
                values = {0.0, 1.0};
            } else {
                for (int k = 0; k < gridPoints; ++k)
                    values.push_back(valueAt(p, static_cast<double>(k) / (gridPoints - 1)));
            }
            if (!measureAlong(i, values)) return std::move(mResult);
        }
        // Coordinate descent (a compass search): each parameter tried a step either side of the best, the
        // step kept while it finds a better setting and halved when it does not. It starts at half a grid
        // step, and so also walks back a parameter whose grid ran while another held a worse value.
        std::vector<double> steps(mParameters.size(), 0.5 / (gridPoints - 1));
        while (remaining() > 0) {
            bool anyStepLeft = false;
            for (size_t i = 0; i < mParameters.size() && remaining() > 0; ++i) {
                const TuneParameter& p = mParameters[i];
                // Rounding onto the lattice: a move of half its spacing still reaches the next value.
                if (p.kind == TuneParameter::Kind::Bool || steps[i] < 0.5 * resolutionOf(p)) continue;
                anyStepLeft = true;
                const std::optional<size_t> before = mResult.best;
                const double here = positionOf(p, current()[i]);
                if (!measureAlong(i, {valueAt(p, here - steps[i]), valueAt(p, here + steps[i])}))
                    return std::move(mResult);
                if (mResult.best == before) steps[i] *= 0.5;
            }
            if (!anyStepLeft) break;
        }
        return std::move(mResult);
    }

private:
    int remaining() const { return mOptions.evaluations - static_cast<int>(mResult.evaluations.size()); }

    // The best setting within budget, else the fastest: where the next batch moves from.
    const TuneSetting& current() const {
        if (mResult.best) return mResult.evaluations[*mResult.best].setting;
        size_t fastest = 0;
        for (size_t e = 1; e < mResult.evaluations.size(); ++e)
            if (mResult.evaluations[e].score.frameMs < mResult.evaluations[fastest].score.frameMs)
                fastest = e;
        return mResult.evaluations[fastest].setting;
    }

    // The current setting with parameter `index` at each of `values`, new settings only.
    bool measureAlong(size_t index, const std::vector<double>& values) {
        std::vector<TuneSetting> batch;
        for (double value : values) {
            TuneSetting setting = current();
            setting[index] = snapTuneValue(mParameters[index], value);
            const bool fresh = std::find(batch.begin(), batch.end(), setting) == batch.end();
            if (fresh && mSeen.count(setting) == 0) batch.push_back(std::move(setting));
        }
        return measure(std::move(batch));
    }

    bool measure(std::vector<TuneSetting> batch) {
        if (batch.size() > static_cast<size_t>(std::max(remaining(), 0)))
            batch.resize(std::max(remaining(), 0));
        if (batch.empty()) return true;
        std::vector<TuneScore> scores;
        if (!mObjective(batch, scores) || scores.size() != batch.size()) {
            mResult.failed = true;
            return false;
        }
        for (size_t s = 0; s < batch.size(); ++s) {
            mSeen.insert(batch[s]);
            TuneEvaluation evaluation{
                batch[s], scores[s], !mOptions.budgetMs || scores[s].frameMs <= *mOptions.budgetMs, mBatches};
            mResult.evaluations.push_back(std::move(evaluation));
            const TuneEvaluation& added = mResult.evaluations.back();
            if (!added.withinBudget) continue;
            const size_t index = mResult.evaluations.size() - 1;
            if (!mResult.best) {
                mResult.best = index;
                continue;
            }
            const TuneScore& best = mResult.evaluations[*mResult.best].score;
            if (added.score.errorPercent < best.errorPercent ||
                (added.score.errorPercent == best.errorPercent && added.score.frameMs < best.frameMs))
                mResult.best = index;
        }
        ++mBatches;
        return true;
    }

    const std::vector<TuneParameter>& mParameters;
    const TuneOptions& mOptions;
    const TuneObjective& mObjective;
    TuneResult mResult;
    std::set<TuneSetting> mSeen;
    int mBatches = 0;
};

}  // namespace

std::string formatTuneValue(const TuneParameter& parameter, double value) {
    switch (parameter.kind) {
        case TuneParameter::Kind::Bool:
            return value >= 0.5 ? "true" : "false";
        case TuneParameter::Kind::Int:
            return std::to_string(static_cast<long long>(std::llround(value)));
        case TuneParameter::Kind::Float:
            break;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value == 0.0 ? 0.0 : value);  // no "-0"
    return text;
}

double snapTuneValue(const TuneParameter& parameter, double value) {
    if (parameter.kind == TuneParameter::Kind::Bool) return value >= 0.5 ? 1.0 : 0.0;
    value = std::clamp(value, parameter.min, std::max(parameter.min, parameter.max));
    if (parameter.step > 0.0) {
        value = parameter.min + std::round((value - parameter.min) / parameter.step) * parameter.step;
        // A lattice point past UIMax when the range is not a whole number of steps: the last one inside.
        if (value > parameter.max) value -= parameter.step;
        value = std::max(value, parameter.min);
    }
    if (parameter.kind == TuneParameter::Kind::Int) value = std::round(value);
    return std::strtod(formatTuneValue(parameter, value).c_str(), nullptr);
}

std::string tuneSetLine(const std::vector<TuneParameter>& parameters, const TuneSetting& setting) {
    std::string text;
    for (size_t i = 0; i < parameters.size() && i < setting.size(); ++i)
        text += (text.empty() ? "--set " : " --set ") + parameters[i].name + "=" +
                formatTuneValue(parameters[i], setting[i]);
    return text;
}

TuneResult tuneSearch(const std::vector<TuneParameter>& parameters, const TuneOptions& options,
                      const TuneObjective& objective) {
    return Search(parameters, options, objective).run();
}

}  // namespace report
