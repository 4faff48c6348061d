// RuntimeModules: see RuntimeModules.h. The folders come from the build (runtime/CMakeLists.txt defines
// them for this file only).
#include <runtime/RuntimeModules.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

namespace runtime {

namespace fs = std::filesystem;

std::vector<std::string> moduleSearchDirs() {
    if (const char* env = std::getenv("SHADOWFX_MODULE_DIR"); env && *env) return {env};
    std::vector<std::string> dirs;
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
        dirs.push_back((self.parent_path() / SHADOWFX_MODULE_DIR_FROM_BINDIR).lexically_normal().string());
    for (const char* dir : {SHADOWFX_INSTALL_MODULE_DIR, SHADOWFX_BUILD_TREE_MODULE_DIR})
        if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
    return dirs;
}

void* openModuleEntry(const std::string& name, const std::string& purpose, const char* symbol) {
    static std::mutex mutex;
    static std::map<std::string, void*> opened;  // file name -> dlopen handle
    const std::string file = "libshadowfx_" + name + ".so";
    const std::lock_guard lock(mutex);
    void* handle = opened[file];
    std::string tried;
    for (const std::string& dir : handle ? std::vector<std::string>{} : moduleSearchDirs()) {
        const std::string path = (fs::path(dir) / file).string();
        tried += (tried.empty() ? "" : ", ") + path;
        std::error_code ec;
        if (!fs::exists(path, ec)) continue;
        // RTLD_LOCAL: a module's dependencies (assimp's zlib, Embree's TBB) stay out of the program's symbol
        // namespace.
        handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* message = dlerror();
            const std::string reason = message ? message : "the dynamic loader refused it";
            throw ModuleLoadError(ModuleLoadError::Reason::Refused, path, reason,
                                  "cannot load the " + purpose + " module " + path + ": " + reason);
        }
        opened[file] = handle;
        break;
    }
    if (!handle) {
        throw ModuleLoadError(ModuleLoadError::Reason::Missing, file, tried,
                              "the " + purpose + " module " + file + " is missing: looked for " + tried +
                                  " (SHADOWFX_MODULE_DIR names the folder that holds it)");
    }
    dlerror();
    void* entry = dlsym(handle, symbol);
    if (!entry) {
        throw ModuleLoadError(ModuleLoadError::Reason::NoEntryPoint, file, symbol,
                              "the " + purpose + " module " + file + " has no entry point '" + symbol +
                                  "': it was built from another version of shadowfx");
    }
    return entry;
}

}  // namespace runtime
