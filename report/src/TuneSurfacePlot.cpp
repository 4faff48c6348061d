// TuneSurfacePlot: see TuneSurfacePlot.h.
#include <report/TuneSurfacePlot.h>
#include <report/XmlText.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace report {

namespace {

constexpr int kColumns = 3;
constexpr double kPanelWidth = 340, kPanelHeight = 250;
constexpr double kLeft = 60, kRight = 15, kTop = 30, kBottom = 40;  // margins inside a panel
constexpr const char* kFont = "font-family=\"DejaVu Sans Mono, monospace\"";

// The panel's x: the parameter's range on its scale.
double xPosition(const TuneParameter& p, double value) {
    if (p.max <= p.min) return 0.5;
    if (p.logScale) return std::log(value / p.min) / std::log(p.max / p.min);
    return (value - p.min) / (p.max - p.min);
}

}  // namespace

bool writeTuneSurfacePlot(const std::string& path, const std::vector<TuneParameter>& parameters,
                          const TuneResult& result, std::string& error) {
    // The error axis: whole decades around every error above 0 (an error of 0 sits on the axis).
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const TuneEvaluation& e : result.evaluations)
        if (e.score.errorPercent > 0.0) {
            lo = std::min(lo, e.score.errorPercent);
            hi = std::max(hi, e.score.errorPercent);
        }
    const double decadeLo = hi > 0.0 ? std::floor(std::log10(lo)) : -2.0;
    const double decadeHi = hi > 0.0 ? std::max(std::ceil(std::log10(hi)), decadeLo + 1.0) : 0.0;
    const double plotWidth = kPanelWidth - kLeft - kRight, plotHeight = kPanelHeight - kTop - kBottom;
    const auto yOf = [&](double percent) {
        const double log = percent > 0.0 ? std::log10(percent) : decadeLo;
        return kTop + (decadeHi - log) / (decadeHi - decadeLo) * plotHeight;
    };

    const int rows = (static_cast<int>(parameters.size()) + kColumns - 1) / kColumns;
    const int columns = std::min(kColumns, std::max(static_cast<int>(parameters.size()), 1));
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << columns * kPanelWidth << "\" height=\""
        << rows * kPanelHeight + 30 << "\" " << kFont << " font-size=\"11\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"10\" y=\"" << rows * kPanelHeight + 20
        << "\">misclassified % (log) of every setting measured; filled: within the budget, hollow: over, "
           "red: the best</text>\n";
    for (size_t i = 0; i < parameters.size(); ++i) {
        const TuneParameter& p = parameters[i];
        const double originX = static_cast<double>(i % kColumns) * kPanelWidth;
        const double originY = static_cast<double>(i / kColumns) * kPanelHeight;
        svg << "<g class=\"panel\" transform=\"translate(" << originX << "," << originY << ")\">\n"
            << "<text x=\"" << kLeft << "\" y=\"18\" font-weight=\"bold\">" << xmlEscape(p.name)
            << (p.logScale ? " (log)" : "") << "</text>\n"
            << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotWidth << "\" height=\""
            << plotHeight << "\" fill=\"none\" stroke=\"#888888\"/>\n";
        for (double decade = decadeLo; decade <= decadeHi; decade += 1.0) {
            const double y = yOf(std::pow(10.0, decade));
            svg << "<line x1=\"" << kLeft << "\" x2=\"" << kLeft + plotWidth << "\" y1=\"" << y << "\" y2=\""
                << y << "\" stroke=\"#dddddd\"/>\n"
                << "<text x=\"" << kLeft - 4 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
                << formatTuneValue(TuneParameter{}, std::pow(10.0, decade)) << "</text>\n";
        }
        for (const double end : {p.min, p.max})
            svg << "<text x=\"" << kLeft + xPosition(p, end) * plotWidth << "\" y=\""
                << kTop + plotHeight + 15 << "\" text-anchor=\"middle\">" << formatTuneValue(p, end)
                << "</text>\n";
        for (size_t e = 0; e < result.evaluations.size(); ++e) {
            const TuneEvaluation& evaluation = result.evaluations[e];
            const bool best = result.best && *result.best == e;
            const std::string colour = best ? "#D55E00" : "#0072B2";
            svg << "<circle class=\"" << (best ? "best" : "setting") << "\" cx=\""
                << kLeft + xPosition(p, evaluation.setting[i]) * plotWidth << "\" cy=\""
                << yOf(evaluation.score.errorPercent) << "\" r=\"" << (best ? 5 : 3.5) << "\" stroke=\""
                << colour << "\" fill=\"" << (evaluation.withinBudget ? colour : "none") << "\"><title>"
                << xmlEscape(tuneSetLine(parameters, evaluation.setting)) << ": "
                << formatTuneValue(TuneParameter{}, evaluation.score.errorPercent) << "%, "
                << formatTuneValue(TuneParameter{}, evaluation.score.frameMs) << " ms</title></circle>\n";
        }
        svg << "</g>\n";
    }
    svg << "</svg>\n";
    std::ofstream out(path);
    out << svg.str();
    if (!out) {
        error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace report
