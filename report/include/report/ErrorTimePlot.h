// ErrorTimePlot: `shadowfx bench`'s error_vs_time.svg — misclassified % against median frame time (log
// scale), one marker per run coloured by scene, the Pareto front of each scene, and every run's label
// placed where it covers no other label or marker (LabelPlacement.h): beside its marker, further out with a
// leader line, or as a number listed in the table beside the plot.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace report {

struct PlotPoint {
    double timeMs = 0;
    double errorPercent = 0;
    std::string label;
    std::string scene;
};

// Points on the Pareto front of (time, error): no other run is at least as fast and strictly more exact.
std::vector<size_t> paretoFront(const std::vector<std::pair<double, double>>& points);

// Writes the plot to `path`; `timeAxis` names the frame time plotted. False with `error` set if the file
// cannot be written.
bool writeErrorTimePlot(const std::string& path, const std::vector<PlotPoint>& points,
                        const std::string& timeAxis, std::string& error);

}  // namespace report
