// XmlText: text as XML character data or an attribute value, for check's JUnit report and bench's SVG plot.
#pragma once

#include <string>

namespace report {

// `text` with &, <, >, " and ' escaped and the control characters XML 1.0 forbids dropped.
std::string xmlEscape(const std::string& text);

}  // namespace report
