// LiteralNumbers: see fx/LiteralNumbers.h.
#include <fx/LiteralNumbers.h>
#include <fx/RenderStates.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace fx {

std::optional<std::vector<float>> parseLiteralNumbers(std::string_view text) {
    std::string cleaned;
    for (char c : text) cleaned += (c == '{' || c == '}' || c == ',') ? ' ' : c;
    std::istringstream stream(cleaned);
    std::vector<float> numbers;
    std::string word;
    while (stream >> word) {
        if (equalsIgnoreCase(word, "true") || equalsIgnoreCase(word, "false")) {
            numbers.push_back(equalsIgnoreCase(word, "true") ? 1.0f : 0.0f);
            continue;
        }
        char* end = nullptr;
        const float number = std::strtof(word.c_str(), &end);
        if (end != word.c_str() + word.size() || !std::isfinite(number)) return std::nullopt;
        numbers.push_back(number);
    }
    return numbers;
}

}  // namespace fx
