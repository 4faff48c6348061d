// ScratchDirectory: a new folder with a unique name under the system's temporary directory, removed with
// everything in it when the object goes. Tests write their outputs there instead of to fixed names, so
// that two suites running at once on one machine (a plain and a sanitized build, two checkouts) never
// read or delete each other's files.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace shadowfx::test {

class ScratchDirectory {
public:
    explicit ScratchDirectory(const std::string& prefix) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / ("shadowfx_" + prefix + "_XXXXXX")).string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder like " + pattern);
        mPath = pattern;
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(mPath, ignored);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& name) const { return mPath / name; }

private:
    std::filesystem::path mPath;
};

}  // namespace shadowfx::test
