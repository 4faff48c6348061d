// RuntimeModules: the shared modules shadowfx opens when a program first needs them, so that only the work
// that uses a heavy dependency pays for loading it. libshadowfx_meshimport.so reads mesh files through
// assimp (runtime/MeshImporter.h), libshadowfx_raycast.so casts the ground truth's shadow rays through
// Embree (runtime/GroundTruth.h); every other program and command (`shadowfx --help`, `compile`, a scene
// of built-in shapes) never maps either library.
//
// A module is looked for, in this order, in:
//   1. $SHADOWFX_MODULE_DIR alone, when it is set (a relocated install, or a check of the missing case);
//   2. lib/shadowfx beside the running program's bin/ (an install, wherever its prefix was moved);
//   3. the library directory of the install this build was configured for (<libdir>/shadowfx);
//   4. the module directory of the build tree that built these libraries.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace runtime {

// A module that is in none of the folders searched, that the dynamic loader refused, or that lacks its
// entry point; what() names the module, what it is for and every path tried. `detail` is what the reason
// names: the paths tried (Missing), the dynamic loader's message (Refused), the entry point (NoEntryPoint).
class ModuleLoadError : public std::runtime_error {
public:
    enum class Reason { Missing, Refused, NoEntryPoint };
    ModuleLoadError(Reason reason, std::string file, std::string detail, const std::string& what)
        : std::runtime_error(what), reason(reason), file(std::move(file)), detail(std::move(detail)) {}

    Reason reason;
    std::string file;  // libshadowfx_<name>.so, or the path the dynamic loader refused
    std::string detail;
};

// The folders searched, in order (above), without duplicates.
std::vector<std::string> moduleSearchDirs();

// The module's entry point: the address of `symbol` in libshadowfx_<name>.so from the first folder that has
// that file. Opened once per process and never closed (the ray caster's worker threads outlive any one
// call). `purpose` says what the module is for, in the error. Throws ModuleLoadError.
void* openModuleEntry(const std::string& name, const std::string& purpose, const char* symbol);

}  // namespace runtime
