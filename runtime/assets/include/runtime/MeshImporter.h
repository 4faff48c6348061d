// MeshImporter: mesh files (OBJ, glTF 2, PLY, 3DS, and whatever else assimp reads) as one runtime::Mesh in
// shadowfx's conventions (Mesh.h: left-handed, +y up, clockwise front faces, triangles only).
#pragma once

#include <runtime/Mesh.h>

#include <fx/Diagnostics.h>

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace runtime {

struct MeshImportOptions {
    float normalizeSize = 0.0f;  // > 0: scaled so its largest extent is this, its base centred on the origin
    glm::vec3 rotateDegrees{
        0.0f};  // baked in first (yaw-pitch-roll as a scene object's "rotate"), e.g. z-up files
    std::optional<bool> closed;    // assimp cannot tell watertight meshes: the caller says so
    bool generateNormals = false;  // ignore the file's normals, smooth ones from the winding (glmark2's
                                   // bunny.obj has inward normals, assimp's spider.obj mixed ones)
};

// Imports every mesh of the file (node transforms baked in) into one Mesh. nullopt after reporting at
// `where` MeshFileNotFound (MeshFileNotInstalled naming the Debian package of a known asset), the mesh
// import module's MeshModuleMissing, MeshModuleUnloadable or MeshModuleEntryMissing, assimp's
// MeshImportError, or MeshWithoutTriangles.
std::optional<Mesh> importMesh(const std::string& path, const MeshImportOptions& options,
                               fx::DiagnosticSink& diagnostics, const fx::SourceLoc& where = {});

// The Debian package that installs a file under `path` ("glmark2-data", "assimp-testmodels"), or "" if none
// is known: what a missing-asset error tells the user to install.
std::string_view debianPackageForAsset(std::string_view path);

// World matrix (glm column-vector form) of translate * yaw(y) * pitch(x) * roll(z) * scale, angles in
// degrees: D3DXMatrixRotationYawPitchRoll's order, shared by scene files, mesh import and the built-in
// scenes.
glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotateDegrees,
                           const glm::vec3& scale);

}  // namespace runtime
