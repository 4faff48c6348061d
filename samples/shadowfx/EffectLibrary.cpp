#include "EffectLibrary.h"

#include <string>

namespace shadowfx::cli {

std::filesystem::path effectLibraryDir() {
    std::error_code ignored;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ignored);
    if (self.empty()) return {};
    const std::filesystem::path installed =
        self.parent_path().parent_path() / "share" / "shadowfx" / "effects";
    if (std::filesystem::is_directory(installed / "include", ignored)) return installed;
    // The source tree only serves the tool of its own build tree: an installed copy that lacks its library
    // must say so rather than read the tree it happened to be built from.
    const std::string buildDir = SHADOWFX_BUILD_DIR;
    const std::string selfPath = self.string();
    if (selfPath.compare(0, buildDir.size(), buildDir) == 0 &&
        std::filesystem::is_directory(std::filesystem::path(SHADOWFX_SOURCE_EFFECTS_DIR) / "include",
                                      ignored))
        return SHADOWFX_SOURCE_EFFECTS_DIR;
    return {};
}

}  // namespace shadowfx::cli
