// MeshImporter: mesh files → runtime::Mesh. assimp reads them in its own module (MeshFileModule.h), opened
// on the first file; what is left here needs no assimp: the missing-file hint, normals, rotation and size.
#include <runtime/MeshImporter.h>
#include <runtime/RuntimeModules.h>

#include <private/runtime/MeshFileModule.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace runtime {

namespace {

struct KnownAssetRoot {
    std::string_view prefix;
    std::string_view package;
};

// Where Debian's data packages install what the built-in scenes read.
constexpr KnownAssetRoot kKnownAssetRoots[] = {
    {"/usr/share/glmark2/", "glmark2-data"},
    {"/usr/share/assimp/models/", "assimp-testmodels"},
};

// Opened on the first mesh file, and kept: a failed open is tried again on the next file.
const MeshFileModule* meshFileModule() {
    static const MeshFileModule* module = reinterpret_cast<MeshFileModuleEntry>(
        openModuleEntry("meshimport", "mesh import (assimp)", kMeshFileModuleEntry))();
    return module;
}

}  // namespace

std::string_view debianPackageForAsset(std::string_view path) {
    for (const auto& root : kKnownAssetRoots)
        if (path.substr(0, root.prefix.size()) == root.prefix) return root.package;
    return {};
}

glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotateDegrees,
                           const glm::vec3& scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotateDegrees.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotateDegrees.x), glm::vec3(1, 0, 0));
    m = glm::rotate(m, glm::radians(rotateDegrees.z), glm::vec3(0, 0, 1));
    return glm::scale(m, scale);
}

std::optional<Mesh> importMesh(const std::string& path, const MeshImportOptions& options,
                               fx::DiagnosticSink& diagnostics, const fx::SourceLoc& where) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        const std::string_view package = debianPackageForAsset(path);
        if (package.empty())
            diagnostics.report(fx::DiagId::MeshFileNotFound, where, {path});
        else
            diagnostics.report(fx::DiagId::MeshFileNotInstalled, where, {path, std::string(package)});
        return std::nullopt;
    }

    const MeshFileModule* module = nullptr;
    try {
        module = meshFileModule();
    } catch (const ModuleLoadError& e) {
        const fx::DiagId id = e.reason == ModuleLoadError::Reason::Missing ? fx::DiagId::MeshModuleMissing
                              : e.reason == ModuleLoadError::Reason::Refused
                                  ? fx::DiagId::MeshModuleUnloadable
                                  : fx::DiagId::MeshModuleEntryMissing;
        diagnostics.report(id, where, {path, e.file, e.detail});
        return std::nullopt;
    }
    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    std::string error;
    if (!module->read(path, options.generateNormals, mesh, error)) {
        diagnostics.report(fx::DiagId::MeshImportError, where, {path, error});
        return std::nullopt;
    }
    if (mesh.indices.empty()) {
        diagnostics.report(fx::DiagId::MeshWithoutTriangles, where, {path});
        return std::nullopt;
    }

    if (mesh.normals.empty()) {
        // Area-weighted smooth normals from the final (clockwise-front) winding: cross(b - a, c - a) points
        // out of the front face (Mesh.h), its length is twice the area.
        mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            const glm::vec3 n =
                glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            mesh.normals[a] += n;
            mesh.normals[b] += n;
            mesh.normals[c] += n;
        }
        for (auto& n : mesh.normals)
            n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
    }

    // Bake the rotation, then the normalisation (which needs the rotated bounds).
    if (options.rotateDegrees != glm::vec3(0.0f)) {
        const glm::mat3 rotation(composeTransform(glm::vec3(0.0f), options.rotateDegrees, glm::vec3(1.0f)));
        for (auto& p : mesh.positions) p = rotation * p;
        for (auto& n : mesh.normals) n = rotation * n;
    }
    if (options.normalizeSize > 0.0f) {
        const glm::vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax();
        const glm::vec3 extent = hi - lo;
        const float largest = std::max({extent.x, extent.y, extent.z});
        const float scale = largest > 0.0f ? options.normalizeSize / largest : 1.0f;
        const glm::vec3 base((lo.x + hi.x) * 0.5f, lo.y, (lo.z + hi.z) * 0.5f);
        for (auto& p : mesh.positions) p = (p - base) * scale;  // uniform: normals unchanged
    }
    mesh.closed = options.closed.value_or(false);
    return mesh;
}

}  // namespace runtime
