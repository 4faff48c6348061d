// NumberFormat: see NumberFormat.h.
#include <report/NumberFormat.h>

#include <iomanip>
#include <sstream>

namespace report {

std::string formatFixed(double value, int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

std::string formatPercent(double value) {
    return formatFixed(value, value < 10.0 ? 3 : 1) + "%";
}

}  // namespace report
