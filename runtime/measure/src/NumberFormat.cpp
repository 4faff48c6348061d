// NumberFormat: see NumberFormat.h.
#include <runtime/NumberFormat.h>

#include <iomanip>
#include <sstream>

namespace runtime {

std::string formatFixed(double value, int digits) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

std::string formatPercent(double value) {
    return formatFixed(value, value < 10.0 ? 3 : 1) + "%";
}

}  // namespace runtime
