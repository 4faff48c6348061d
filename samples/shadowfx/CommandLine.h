// CommandLine: the subcommand table and argument parsing shared by the shadowfx subcommands.
#pragma once

#include <fx/EffectParser.h>

#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace shadowfx::cli {

class Arguments {
public:
    const std::string& positional(size_t index) const { return mPositional.at(index); }
    size_t positionalCount() const { return mPositional.size(); }
    bool flag(const std::string& name) const { return mFlags.count(name) > 0; }
    // The last value given for an option, or `fallback`.
    std::string value(const std::string& name, const std::string& fallback = "") const;
    int intValue(const std::string& name, int fallback) const;
    std::vector<std::string> all(const std::string& name) const;  // every value of a repeatable option

private:
    friend struct Parser;
    std::vector<std::string> mPositional;
    std::map<std::string, std::vector<std::string>> mValues;
    std::map<std::string, bool> mFlags;
};

struct Command {
    const char* name;
    const char* summary;
    const char* usage;
    std::vector<std::string> requiredOptions;  // options that must be given (with a value)
    std::vector<std::string> valueOptions;     // options that take a value
    std::vector<std::string> flags;            // options without a value
    std::function<int(const Arguments&)> run;
    // Number of positional arguments (effect files) the command takes; -1 = any (`bench --effects
    // effects/*.fx`, where the shell's glob leaves every file after the first as a positional argument).
    int positionals = 1;
    const char* positionalName = "effect file";  // what the positional argument is, for usage errors
};

// "a,b,,c" -> {"a", "b", "c"}: the comma-separated lists of --scenes, --techniques, --effects, ...
std::vector<std::string> splitList(const std::string& text);

// Removes an output file a command is about to write, so that a failed run leaves nothing behind that
// looks like a success; only a regular file: `--out /dev/null` (or a FIFO, or a link) is left alone, since
// the tool may run as root and must never delete a device node.
void removeStaleOutput(const std::string& path);

// The preprocessor options every effect-reading subcommand takes: -I DIR and -D NAME[=VALUE] (VALUE 1),
// with the effect library (EffectLibrary.h) searched after the -I folders. A command that has -I among its
// value options gets both listed in its --help.
fx::ParseOptions effectParseOptions(const Arguments& args);

// Parses argv for the named subcommand and runs it. Exit codes: the command's; 2 for usage errors.
int dispatch(int argc, char** argv, std::span<const Command> commands);

}  // namespace shadowfx::cli
