#include <runtime/ParameterSweep.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace runtime {

namespace {

// A range never expands to more values than this: a typo like 0:1e9:1 is an error, not a hang.
constexpr size_t kMaxRangeValues = 1000;

std::optional<double> number(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value)) return std::nullopt;
    return value;
}

// Six significant digits, as a parameter value reads in a report: 0.001 * 3 is "0.003", not
// "0.0030000000000000001".
std::string formatValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// START:STOP:STEP into `out`; false with `error` set.
bool expandRange(const std::string& item, std::vector<std::string>& out, std::string& error) {
    const size_t first = item.find(':');
    const size_t second = item.find(':', first + 1);
    const std::optional<double> start = number(item.substr(0, first));
    // number("") is nullopt, as a missing STOP must be; a conditional nullopt here instead reads to GCC, once
    // inlined beside the other files of a unity batch, as maybe uninitialized where *stop is read below.
    const std::optional<double> stop =
        number(second == std::string::npos ? std::string() : item.substr(first + 1, second - first - 1));
    std::string step = second == std::string::npos ? "" : item.substr(second + 1);
    const bool multiply = !step.empty() && (step[0] == 'x' || step[0] == '*');
    if (!step.empty() && (multiply || step[0] == '+')) step.erase(0, 1);
    const std::optional<double> by = number(step);
    if (!start || !stop || !by || (multiply ? !(*by > 1.0) : !(*by > 0.0)) || *stop < *start ||
        (multiply && !(*start > 0.0))) {
        error = "'" + item +
                "' is not a range START:STOP:STEP with START <= STOP and STEP +S (S > 0) or xF (F > 1, START "
                "> 0)";
        return false;
    }
    // Each value from the start (not by repeated steps), so that rounding does not drift past STOP.
    const double tolerance = 1e-9 * std::max(std::abs(*start), std::abs(*stop));
    for (size_t i = 0;; ++i) {
        const double value =
            multiply ? *start * std::pow(*by, static_cast<double>(i)) : *start + *by * static_cast<double>(i);
        if (value > *stop + tolerance) break;
        if (i == kMaxRangeValues) {
            error = "'" + item + "' gives more than " + std::to_string(kMaxRangeValues) + " values";
            return false;
        }
        out.push_back(formatValue(value));
    }
    return true;
}

}  // namespace

std::optional<ParameterSweep> parseSweep(const std::string& assignment, std::string& error) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        error = "expects PARAM=VALUE, got '" + assignment + "'";
        return std::nullopt;
    }
    ParameterSweep sweep;
    sweep.parameter = assignment.substr(0, eq);
    sweep.text = assignment.substr(eq + 1);
    // Items: split at commas outside braces.
    std::vector<std::string> items;
    std::string item;
    int depth = 0;
    for (char c : sweep.text) {
        depth += c == '{' ? 1 : c == '}' ? -1 : 0;
        if (c == ',' && depth == 0) {
            items.push_back(item);
            item.clear();
        } else {
            item += c;
        }
    }
    items.push_back(item);
    if (depth != 0) {
        error = sweep.parameter + ": unbalanced braces in '" + sweep.text + "'";
        return std::nullopt;
    }
    // One value, as render --set takes it (a string parameter's text may hold a colon).
    std::vector<std::string> range;
    std::string rangeError;
    if (items.size() == 1 && (item.find(':') == std::string::npos || !expandRange(item, range, rangeError))) {
        sweep.values = items;
        return sweep;
    }
    for (std::string& part : items) {
        part.erase(0, part.find_first_not_of(" \t"));
        part.erase(part.find_last_not_of(" \t") + 1);
        if (part.empty()) {
            error = sweep.parameter + ": an empty value in '" + sweep.text + "'";
            return std::nullopt;
        }
        if (part.front() == '{') {
            sweep.explicitSweep = true;
            sweep.values.push_back(part);
        } else if (part.find(':') != std::string::npos) {
            sweep.explicitSweep = true;
            std::string rangeError;
            if (!expandRange(part, sweep.values, rangeError)) {
                error = sweep.parameter + ": " + rangeError;
                return std::nullopt;
            }
        } else {
            sweep.values.push_back(part);
        }
    }
    return sweep;
}

std::vector<std::string> sweepValues(const ParameterSweep& sweep, int components) {
    if (sweep.values.size() > 1 && !sweep.explicitSweep && components > 1) return {sweep.text};
    return sweep.values;
}

std::vector<Setting> settingsFor(const fx::CompiledEffect& effect, const std::vector<ParameterSweep>& sweeps,
                                 std::vector<std::string>& swept) {
    std::vector<Setting> settings{Setting{}};
    for (const ParameterSweep& sweep : sweeps) {
        const auto found =
            std::find_if(effect.parameters.begin(), effect.parameters.end(),
                         [&](const fx::ParameterInfo& p) { return p.name == sweep.parameter; });
        if (found == effect.parameters.end()) continue;
        const std::vector<std::string> values = sweepValues(sweep, found->type.componentCount());
        if (values.size() > 1) swept.push_back(sweep.parameter);
        std::vector<Setting> product;
        for (const Setting& setting : settings) {
            for (const std::string& value : values) {
                Setting extended = setting;
                extended.emplace_back(sweep.parameter, value);
                product.push_back(std::move(extended));
            }
        }
        settings = std::move(product);
    }
    return settings;
}

std::string settingLabel(const Setting& setting, const std::vector<std::string>& swept) {
    std::string label;
    for (const auto& [name, value] : setting) {
        if (std::find(swept.begin(), swept.end(), name) == swept.end()) continue;
        label += (label.empty() ? "" : ", ") + name + "=" + value;
    }
    return label;
}

}  // namespace runtime
