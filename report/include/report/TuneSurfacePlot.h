// TuneSurfacePlot: `shadowfx tune`'s error_surface.svg — the error surface the search saw, one panel per
// parameter: every setting measured at its value of that parameter (its own scale, log where UIScale asks)
// against its misclassified % (log scale), filled when within the budget, hollow when over, the best in
// red. A panel is the surface seen along one axis: a column of points at one value is the other
// parameters' spread there.
#pragma once

#include <report/TuneSearch.h>

#include <string>
#include <vector>

namespace report {

// Writes the plot to `path`. False with `error` set if the file cannot be written.
bool writeTuneSurfacePlot(const std::string& path, const std::vector<TuneParameter>& parameters,
                          const TuneResult& result, std::string& error);

}  // namespace report
