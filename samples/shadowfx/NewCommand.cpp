// NewCommand: `shadowfx new`. The skeletons are effects of the installed effect library
// (EffectLibrary.h, templates/*.fx) with `$NAME` standing for the new effect's name: each renders a shadow,
// carries the measurement hooks, UI annotations and loose Expect* bounds, and so passes `check` (after
// `check --update`), `bench` and `stress --reduced` as written (tests/InstalledAuthoring.py).
#include "NewCommand.h"
#include "EffectLibrary.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

namespace shadowfx::cli {

const char* const kNewUsage =
    "usage: shadowfx new NAME [--from pcf|vsm|minimal]\n"
    "  NAME                  the effect's name: writes NAME.fx in the current folder (never overwrites)\n"
    "  --from SKELETON       pcf (default): a depth map and 2x2 bilinear PCF; vsm: a blurred moments map\n"
    "                        and the Chebyshev bound, for filterable maps; minimal: one depth test\n"
    "The skeleton renders a shadow and passes check (after check --update), bench and stress as written;\n"
    "its header comment lists the commands (docs/authoring.md).\n";

int newCommand(const Arguments& args) {
    const std::string name = args.positional(0);
    // The name becomes a file name and is written into comments: letters, digits, '_' and '-'.
    if (!std::regex_match(name, std::regex("[A-Za-z_][A-Za-z0-9_-]*"))) {
        std::cerr << "shadowfx new: NAME must start with a letter or '_' and hold only letters, digits, '_' "
                     "and '-', got '"
                  << name << "'\n";
        return 2;
    }
    const std::string from = args.value("--from", "pcf");
    if (from != "pcf" && from != "vsm" && from != "minimal") {
        std::cerr << "shadowfx new: --from must be pcf, vsm or minimal, got '" << from << "'\n";
        return 2;
    }
    const std::filesystem::path library = effectLibraryDir();
    const std::filesystem::path skeleton = library / "templates" / (from + ".fx");
    std::ifstream in(skeleton);
    if (library.empty() || !in) {
        std::cerr << "shadowfx new: no skeleton '" << from << "' in the effect library"
                  << (library.empty() ? std::string(" (no library found)") : " (" + skeleton.string() + ")")
                  << "\n";
        return 1;
    }
    std::stringstream text;
    text << in.rdbuf();
    std::string effect = text.str();
    for (size_t at = effect.find("$NAME"); at != std::string::npos;
         at = effect.find("$NAME", at + name.size()))
        effect.replace(at, 5, name);

    const std::filesystem::path out = name + ".fx";
    if (std::filesystem::exists(out)) {
        std::cerr << "shadowfx new: " << out.string() << " already exists\n";
        return 1;
    }
    std::ofstream file(out);
    file << effect;
    if (!file.flush()) {
        std::cerr << "shadowfx new: cannot write " << out.string() << "\n";
        return 1;
    }
    std::cout << "wrote " << out.string() << " (from the " << from << " skeleton). Next:\n"
              << "  shadowfx render " << name << ".fx --scene teapot --out " << name << ".png\n"
              << "  shadowfx check " << name << ".fx --update && shadowfx check " << name << ".fx\n"
              << "  shadowfx bench --effects " << name << ".fx --scenes dual-l,teapot --out bench\n"
              << "  shadowfx stress " << name << ".fx --reduced\n";
    return 0;
}

}  // namespace shadowfx::cli
