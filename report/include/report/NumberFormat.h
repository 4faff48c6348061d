// NumberFormat: how the measuring tools write numbers into tables and reports, one way for all of them.
#pragma once

#include <string>

namespace report {

std::string formatFixed(double value, int digits);  // "0.125" for (0.125, 3)
// A percentage with three decimals below 10 and one above: "0.042%", "12.5%".
std::string formatPercent(double value);

}  // namespace report
