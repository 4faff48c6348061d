#include "CommandLine.h"
#include "EffectLibrary.h"

#include <runtime/RuntimeModules.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace shadowfx::cli {

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

void removeStaleOutput(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path, error)))
        std::filesystem::remove(path, error);
}

fx::ParseOptions effectParseOptions(const Arguments& args) {
    fx::ParseOptions options;
    options.includeDirs = args.all("-I");
    // The library comes last, as FX Composer's include paths came after the effect's own folder: a header
    // of the effect's own, or of an -I folder, with a library header's name wins.
    if (const std::filesystem::path library = effectLibraryDir(); !library.empty())
        options.includeDirs.push_back(library.string());
    for (const std::string& define : args.all("-D")) {
        const size_t eq = define.find('=');
        options.defines.emplace_back(define.substr(0, eq),
                                     eq == std::string::npos ? "1" : define.substr(eq + 1));
    }
    return options;
}

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
    auto it = mValues.find(name);
    return it == mValues.end() || it->second.empty() ? fallback : it->second.back();
}

int Arguments::intValue(const std::string& name, int fallback) const {
    const std::string text = value(name);
    if (text.empty()) return fallback;
    int result = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), result);
    return error == std::errc() && end == text.data() + text.size() ? result : -1;
}

std::vector<std::string> Arguments::all(const std::string& name) const {
    auto it = mValues.find(name);
    return it == mValues.end() ? std::vector<std::string>{} : it->second;
}

struct Parser {
    // Returns false and prints what is wrong on a usage error.
    // Arguments from argv[first] on (after the command's one or two words).
    static bool parse(const Command& command, int argc, char** argv, int first, Arguments& args) {
        auto contains = [](const std::vector<std::string>& list, const std::string& s) {
            return std::find(list.begin(), list.end(), s) != list.end();
        };
        for (int i = first; i < argc; ++i) {
            std::string arg = argv[i];
            std::string attached;
            // -Idir and -DNAME=VALUE, as compilers accept them; --name=value as well.
            if (arg.size() > 2 && (arg.rfind("-I", 0) == 0 || arg.rfind("-D", 0) == 0) && arg[1] != '-') {
                attached = arg.substr(2);
                arg = arg.substr(0, 2);
            } else if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
                attached = arg.substr(arg.find('=') + 1);
                arg = arg.substr(0, arg.find('='));
            }
            if (contains(command.valueOptions, arg) || contains(command.requiredOptions, arg)) {
                if (attached.empty()) {
                    if (i + 1 >= argc) {
                        std::cerr << "shadowfx " << command.name << ": option " << arg << " needs a value\n";
                        return false;
                    }
                    attached = argv[++i];
                }
                args.mValues[arg].push_back(attached);
            } else if (contains(command.flags, arg)) {
                args.mFlags[arg] = true;
            } else if (arg.size() > 1 && arg[0] == '-') {
                std::cerr << "shadowfx " << command.name << ": unknown option '" << arg << "' (see --help)\n";
                return false;
            } else {
                args.mPositional.push_back(arg);
            }
        }
        for (const std::string& required : command.requiredOptions) {
            if (args.value(required).empty()) {
                std::cerr << "shadowfx " << command.name << ": " << required << " is required (see --help)\n";
                return false;
            }
        }
        if (command.positionals >= 0 && args.positionalCount() != static_cast<size_t>(command.positionals)) {
            std::cerr << "shadowfx " << command.name << ": expected one " << command.positionalName
                      << " (see --help)\n";
            return false;
        }
        return true;
    }
};

namespace {
void printEffectOptions() {
    const std::filesystem::path library = effectLibraryDir();
    std::cout << "  -I DIR                include folder (repeatable)\n"
                 "  -D NAME[=VALUE]       preprocessor definition (repeatable; VALUE defaults to 1)\n"
                 "#include \"FILE\" looks beside the including file, beside the effect, in each -I folder,\n"
                 "then in the effect library: "
              << (library.empty()
                      ? std::string("not found (the tool is neither installed nor in its build tree)")
                      : library.string())
              << "\n(docs/effect-library/README.md).\n";
}

void printOverview(std::span<const Command> commands) {
    std::cout
        << "usage: shadowfx COMMAND [options]   (shadowfx COMMAND --help for its options)\n\ncommands:\n";
    size_t column = 10;
    for (const Command& c : commands) column = std::max(column, std::string(c.name).size() + 2);
    for (const Command& c : commands)
        std::cout << "  " << c.name << std::string(column - std::string(c.name).size(), ' ') << c.summary
                  << "\n";
}
}  // namespace

int dispatch(int argc, char** argv, std::span<const Command> commands) {
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" ||
        std::string(argv[1]) == "help") {
        printOverview(commands);
        return argc < 2 ? 2 : 0;
    }
    // A command of two words ("bench merge") is taken before the one-word command it starts with.
    std::string name = argv[1];
    int first = 2;
    if (argc > 2) {
        const std::string twoWords = name + " " + argv[2];
        for (const Command& command : commands)
            if (twoWords == command.name) {
                name = twoWords;
                first = 3;
            }
    }
    for (const Command& command : commands) {
        if (name != command.name) continue;
        for (int i = first; i < argc; ++i) {
            if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
                std::cout << command.summary << "\n" << command.usage;
                if (std::find(command.valueOptions.begin(), command.valueOptions.end(), "-I") !=
                    command.valueOptions.end())
                    printEffectOptions();
                return 0;
            }
        }
        Arguments args;
        if (!Parser::parse(command, argc, argv, first, args)) return 2;
        // A module the command needed (runtime/RuntimeModules.h) that could not be opened: its words, not an
        // abort.
        try {
            return command.run(args);
        } catch (const runtime::ModuleLoadError& e) {
            std::cerr << "shadowfx " << name << ": " << e.what() << "\n";
            return 1;
        }
    }
    std::cerr << "shadowfx: unknown command '" << name << "'\n";
    printOverview(commands);
    return 2;
}

}  // namespace shadowfx::cli
