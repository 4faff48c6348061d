// ParameterSweep: `bench --set PARAM=VALUES`, one run per value.
//
// VALUES is one value (as `render --set` takes it) or a sweep: values separated by commas outside braces,
// each a value or a range START:STOP:STEP (STOP included; STEP `xF` multiplies by F > 1, `+S` or `S` adds
// S > 0). `Exponent=10,20,40,80`, `Exponent=10:80:x2` and `Bias=0.001:0.004:+0.001` all sweep. For a
// vector parameter a bare list of numbers stays one value (`LightColor=1,0.5,0.5`, as before sweeps);
// its sweep puts each value in braces (`LightColor={1,0,0},{0,1,0}`). Several sweeps form their cross
// product, per effect over the parameters that effect has.
#pragma once

#include <fx/CompiledEffect.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace runtime {

// At most this many settings (the cross product of every sweep): each is a full set of runs.
inline constexpr size_t kMaxSweepSettings = 64;

struct ParameterSweep {
    std::string parameter;
    std::string text;                 // VALUES as given
    std::vector<std::string> values;  // the items, ranges expanded
    bool explicitSweep = false;       // a range or a braced value: a sweep whatever the parameter's type
};

// Parses PARAM=VALUES; nullopt with `error` set (without the option's name) if it is malformed.
std::optional<ParameterSweep> parseSweep(const std::string& assignment, std::string& error);

// The values `sweep` gives a parameter of `components` components (1 for a scalar).
std::vector<std::string> sweepValues(const ParameterSweep& sweep, int components);

// One run's assignments, in the order the sweeps were given.
using Setting = std::vector<std::pair<std::string, std::string>>;

// The cross product of `sweeps` over the parameters `effect` has (one empty setting if it has none);
// `swept` receives the names of the parameters that take more than one value in it.
std::vector<Setting> settingsFor(const fx::CompiledEffect& effect, const std::vector<ParameterSweep>& sweeps,
                                 std::vector<std::string>& swept);

// "Exponent=10, Bias=0.002": the assignments of `setting` to parameters in `swept`; "" if none.
std::string settingLabel(const Setting& setting, const std::vector<std::string>& swept);

}  // namespace runtime
