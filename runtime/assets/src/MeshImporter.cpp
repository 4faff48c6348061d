// MeshImporter: assimp → runtime::Mesh.
//
// Conventions: assimp hands out right-handed, +y up, counter-clockwise front faces. shadowfx wants D3D's
// left-handed, clockwise (Mesh.h). aiProcess_ConvertToLeftHanded = MakeLeftHanded (mirror z) + FlipUVs (D3D's
// v grows downwards) + FlipWindingOrder. The winding flip is needed, not optional: mirroring negates the
// winding normal relative to the (mirrored) vertex normals, cross(Mb - Ma, Mc - Ma) = -M cross(b - a, c - a)
// for M = diag(1, 1, -1), and flipping the order restores cross(b - a, c - a) · n > 0, which is what a
// clockwise front face means in a left-handed world (tests/runtime/test_scene_file.cpp checks it).
#include <runtime/MeshImporter.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

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
        std::string hint;
        if (!package.empty()) {
            hint = " (installed by the Debian package '" + std::string(package) + "': apt-get install " +
                   std::string(package) + ", or run scripts/install-deps.sh)";
        }
        diagnostics.report(fx::DiagId::MeshFileNotFound, where, {path, hint});
        return std::nullopt;
    }

    Assimp::Importer importer;
    // Points and lines cannot cast or receive shadows: drop them rather than fail on mixed files.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // No aiProcess_GenSmoothNormals: assimp runs it after FlipWindingOrder yet still assumes
    // counter-clockwise fronts, so its normals come out inverted against the converted winding (generated
    // here instead).
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                     aiProcess_PreTransformVertices | aiProcess_ConvertToLeftHanded | aiProcess_SortByPType |
                     aiProcess_FindInvalidData | aiProcess_ValidateDataStructure;
    if (options.generateNormals) {
        importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
        flags |= aiProcess_RemoveComponent;
    }
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        diagnostics.report(fx::DiagId::MeshImportError, where, {path, importer.GetErrorString()});
        return std::nullopt;
    }

    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    bool allNormals = true, allTexcoords = true;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        allNormals = allNormals && in->HasNormals();
        allTexcoords = allTexcoords && in->HasTextureCoords(0);
    }
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        if (!(in->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            mesh.positions.emplace_back(in->mVertices[v].x, in->mVertices[v].y, in->mVertices[v].z);
            if (allNormals)
                mesh.normals.emplace_back(in->mNormals[v].x, in->mNormals[v].y, in->mNormals[v].z);
            if (allTexcoords)
                mesh.texcoords.emplace_back(in->mTextureCoords[0][v].x, in->mTextureCoords[0][v].y);
        }
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) continue;
            mesh.indices.insert(mesh.indices.end(),
                                {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    if (mesh.indices.empty()) {
        diagnostics.report(fx::DiagId::MeshWithoutTriangles, where, {path});
        return std::nullopt;
    }

    if (!allNormals) {
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
