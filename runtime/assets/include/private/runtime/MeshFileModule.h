// MeshFileModule: what libshadowfx_meshimport.so (runtime/assets/module/) offers MeshImporter.cpp, which
// opens it on the first mesh file (runtime/RuntimeModules.h). Built by this build tree beside the library
// that opens it, so the two share one compiler and one standard library: the table passes C++ types.
#pragma once

#include <runtime/Mesh.h>

#include <string>

namespace runtime {

struct MeshFileModule {
    // Reads every triangle of the file at `path` (node transforms baked in, converted to Mesh.h's
    // left-handed, clockwise conventions) into `mesh`'s positions, indices and, where every mesh of the file
    // has them, normals (unless `dropNormals`) and first texture coordinates. False with `error` set when
    // assimp cannot read the file.
    bool (*read)(const std::string& path, bool dropNormals, Mesh& mesh, std::string& error);
};

// The module's entry point, extern "C": raise the version with any change to MeshFileModule, so that a
// module of another version is refused by name rather than called wrongly.
using MeshFileModuleEntry = const MeshFileModule* (*)();
inline constexpr const char* kMeshFileModuleEntry = "shadowfx_meshimport_v1";

}  // namespace runtime
