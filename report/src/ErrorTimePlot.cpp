#include <report/ErrorTimePlot.h>
#include <report/LabelPlacement.h>
#include <report/XmlText.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace report {

namespace {

// The canvas: the plot on the left, the legend and the table of numbered labels on the right.
constexpr double kWidth = 1100, kHeight = 750;
constexpr double kPlotLeft = 80, kPlotRight = 760, kPlotTop = 50, kPlotBottom = 690;
constexpr double kLegendLeft = 780;
constexpr const char* kFont = "font-family=\"DejaVu Sans Mono, monospace\"";

// Colour-blind-safe scene colours (Okabe & Ito 2008).
constexpr const char* kSceneColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                         "#E69F00", "#56B4E9", "#F0E442", "#000000"};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// 1, 2 or 5 times a power of ten, about range / 6.
double niceStep(double range) {
    const double raw = range / 6.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= raw) return m * power;
    return 10.0 * power;
}

struct Axes {
    double logLo = 0, logHi = 1;  // log10 of the time range
    double errorHi = 1;

    double x(double timeMs) const {
        return kPlotLeft + (std::log10(timeMs) - logLo) / (logHi - logLo) * (kPlotRight - kPlotLeft);
    }
    double y(double percent) const { return kPlotBottom - percent / errorHi * (kPlotBottom - kPlotTop); }
};

Axes axesFor(const std::vector<PlotPoint>& points) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, errorHi = 0.0;
    for (const PlotPoint& p : points) {
        const double t = std::log10(std::max(p.timeMs, 1e-6));
        lo = std::min(lo, t);
        hi = std::max(hi, t);
        errorHi = std::max(errorHi, p.errorPercent);
    }
    // At least a third of a decade, and room for the markers at both ends.
    if (hi - lo < 0.3) {
        const double middle = (lo + hi) / 2.0;
        lo = middle - 0.15;
        hi = middle + 0.15;
    }
    const double pad = 0.06 * (hi - lo);
    Axes axes{lo - pad, hi + pad, errorHi > 0.0 ? errorHi * 1.1 : 1.0};
    return axes;
}

void writeAxes(std::ostream& svg, const Axes& axes, const std::string& timeAxis) {
    svg << "<g class=\"grid\" stroke=\"#dddddd\" stroke-width=\"1\">\n";
    std::ostringstream tickLabels;
    for (int power = static_cast<int>(std::floor(axes.logLo));
         power <= static_cast<int>(std::ceil(axes.logHi)); ++power) {
        for (double m : {1.0, 2.0, 5.0}) {
            const double value = m * std::pow(10.0, power);
            const double log = std::log10(value);
            if (log < axes.logLo || log > axes.logHi) continue;
            const double x = axes.x(value);
            svg << "<line x1=\"" << x << "\" y1=\"" << kPlotTop << "\" x2=\"" << x << "\" y2=\""
                << kPlotBottom << "\"/>\n";
            tickLabels << "<text x=\"" << x << "\" y=\"" << kPlotBottom + 16 << "\" text-anchor=\"middle\">"
                       << number(value) << "</text>\n";
        }
    }
    const double step = niceStep(axes.errorHi);
    for (double value = 0.0; value <= axes.errorHi + 1e-12; value += step) {
        const double y = axes.y(value);
        svg << "<line x1=\"" << kPlotLeft << "\" y1=\"" << y << "\" x2=\"" << kPlotRight << "\" y2=\"" << y
            << "\"/>\n";
        tickLabels << "<text x=\"" << kPlotLeft - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
                   << number(value) << "</text>\n";
    }
    svg << "</g>\n<rect x=\"" << kPlotLeft << "\" y=\"" << kPlotTop << "\" width=\"" << kPlotRight - kPlotLeft
        << "\" height=\"" << kPlotBottom - kPlotTop << "\" fill=\"none\" stroke=\"#000000\"/>\n";
    svg << "<g class=\"ticks\" " << kFont << " font-size=\"11\">\n" << tickLabels.str() << "</g>\n";
    svg << "<g " << kFont << " font-size=\"12\">\n"
        << "<text x=\"" << (kPlotLeft + kPlotRight) / 2 << "\" y=\"" << kPlotBottom + 40
        << "\" text-anchor=\"middle\">median frame time, " << xmlEscape(timeAxis)
        << " (ms, log scale)</text>\n"
        << "<text transform=\"translate(" << kPlotLeft - 50 << " " << (kPlotTop + kPlotBottom) / 2
        << ") rotate(-90)\" text-anchor=\"middle\">misclassified receiver pixels (%)</text>\n"
        << "<text x=\"" << kWidth / 2
        << "\" y=\"28\" text-anchor=\"middle\" font-size=\"14\">Shadow error "
           "against frame time (one marker per effect/technique/setting/scene/map size)</text>\n</g>\n";
}

}  // namespace

std::vector<size_t> paretoFront(const std::vector<std::pair<double, double>>& points) {
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return points[a].first != points[b].first ? points[a].first < points[b].first
                                                  : points[a].second < points[b].second;
    });
    std::vector<size_t> front;
    double bestError = std::numeric_limits<double>::infinity();
    for (size_t i : order) {
        if (points[i].second < bestError) {
            front.push_back(i);
            bestError = points[i].second;
        }
    }
    return front;
}

bool writeErrorTimePlot(const std::string& path, const std::vector<PlotPoint>& points,
                        const std::string& timeAxis, std::string& error) {
    const Axes axes = axesFor(points);
    std::map<std::string, size_t> sceneColour;  // by scene, in order of first appearance
    std::vector<std::string> scenes;
    for (const PlotPoint& p : points)
        if (sceneColour.emplace(p.scene, scenes.size()).second) scenes.push_back(p.scene);

    std::vector<std::pair<double, double>> pixels;
    std::vector<std::string> labels;
    for (const PlotPoint& p : points) {
        pixels.emplace_back(axes.x(std::max(p.timeMs, 1e-6)), axes.y(p.errorPercent));
        labels.push_back(p.label);
    }
    const LabelStyle style;
    const Box area{kPlotLeft, kPlotTop, kPlotRight - kPlotLeft, kPlotBottom - kPlotTop};
    const std::vector<PlacedLabel> placed = placeLabels(pixels, labels, area, style);

    // The legend, then the table of the labels that are numbers in the plot: the canvas grows to hold them.
    std::vector<std::string> table;
    for (size_t i = 0; i < placed.size(); ++i)
        if (placed[i].kind != PlacedLabel::Kind::Text)
            table.push_back(std::to_string(i + 1) + "  " + labels[i]);
    double width = kWidth;
    for (const std::string& row : table)
        width = std::max(width, kLegendLeft + static_cast<double>(row.size()) * style.charWidth + 10.0);
    const double tableTop = kPlotTop + 20.0 * static_cast<double>(scenes.size() + 1) + 30.0;
    const double height = std::max(kHeight, tableTop + 15.0 * static_cast<double>(table.size() + 1) + 10.0);

    std::ofstream svg(path);
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    writeAxes(svg, axes, timeAxis);

    // One Pareto front per scene, as steps: runs of different scenes are not alternatives to each other.
    for (const std::string& scene : scenes) {
        std::vector<std::pair<double, double>> scenePoints;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i].scene == scene) scenePoints.push_back(pixels[i]);
        std::vector<std::pair<double, double>> front;
        // Pixels: x grows with time, y falls with error, so "more exact" is a larger y.
        std::vector<std::pair<double, double>> asTimeError;
        for (const auto& [x, y] : scenePoints) asTimeError.emplace_back(x, -y);
        for (size_t i : paretoFront(asTimeError)) front.push_back(scenePoints[i]);
        svg << "<path class=\"pareto\" fill=\"none\" stroke=\"#444444\" stroke-width=\"2\" "
               "stroke-dasharray=\"6 4\" d=\"";
        for (size_t i = 0; i < front.size(); ++i) {
            if (i == 0) {
                svg << "M" << front[i].first << " " << front[i].second;
            } else {
                svg << " H" << front[i].first << " V" << front[i].second;
            }
        }
        svg << "\"/>\n";
    }

    // Markers, then leader lines and labels over them.
    for (size_t i = 0; i < points.size(); ++i)
        svg << "<circle class=\"marker\" cx=\"" << pixels[i].first << "\" cy=\"" << pixels[i].second
            << "\" r=\"" << style.markerRadius << "\" fill=\""
            << kSceneColours[sceneColour[points[i].scene] % 8]
            << "\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
    svg << "<g " << kFont << " font-size=\"11\">\n";
    for (size_t i = 0; i < placed.size(); ++i) {
        const PlacedLabel& label = placed[i];
        if (label.kind == PlacedLabel::Kind::TableOnly) continue;
        const Box& b = label.box;
        if (label.leader) {
            // To the nearest point of the box.
            const double x = std::clamp(pixels[i].first, b.x, b.x + b.width);
            const double y = std::clamp(pixels[i].second, b.y, b.y + b.height);
            svg << "<line class=\"leader\" x1=\"" << pixels[i].first << "\" y1=\"" << pixels[i].second
                << "\" x2=\"" << x << "\" y2=\"" << y << "\" stroke=\"#888888\" stroke-width=\"0.8\"/>\n";
        }
        const std::string text = label.kind == PlacedLabel::Kind::Text ? labels[i] : std::to_string(i + 1);
        svg << "<rect class=\"label-box\" x=\"" << b.x << "\" y=\"" << b.y << "\" width=\"" << b.width
            << "\" height=\"" << b.height << "\" fill=\"#ffffff\" fill-opacity=\"0.85\"/>\n"
            << "<text class=\"label\" x=\"" << b.x + style.padding << "\" y=\""
            << b.y + style.padding + 0.8 * style.lineHeight << "\">" << xmlEscape(text) << "</text>\n";
    }
    // The legend: a marker per scene, the fronts' line style, then the numbered labels.
    double y = kPlotTop + 10;
    for (const std::string& scene : scenes) {
        svg << "<circle cx=\"" << kLegendLeft + 6 << "\" cy=\"" << y << "\" r=\"" << style.markerRadius
            << "\" fill=\"" << kSceneColours[sceneColour[scene] % 8] << "\"/>\n<text x=\"" << kLegendLeft + 18
            << "\" y=\"" << y + 4 << "\">scene " << xmlEscape(scene) << "</text>\n";
        y += 20;
    }
    svg << "<line x1=\"" << kLegendLeft << "\" y1=\"" << y << "\" x2=\"" << kLegendLeft + 14 << "\" y2=\""
        << y << "\" stroke=\"#444444\" stroke-width=\"2\" stroke-dasharray=\"6 4\"/>\n<text x=\""
        << kLegendLeft + 18 << "\" y=\"" << y + 4 << "\">Pareto front (per scene)</text>\n";
    if (!table.empty()) {
        svg << "<text x=\"" << kLegendLeft << "\" y=\"" << tableTop << "\">numbered points:</text>\n";
        for (size_t row = 0; row < table.size(); ++row)
            svg << "<text class=\"table-row\" x=\"" << kLegendLeft << "\" y=\""
                << tableTop + 15.0 * static_cast<double>(row + 1) << "\">" << xmlEscape(table[row])
                << "</text>\n";
    }
    svg << "</g>\n</svg>\n";
    if (!svg) {
        error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace report
