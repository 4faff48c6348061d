// AssimpMeshReader: libshadowfx_meshimport.so, the only code that links assimp (MeshFileModule.h).
//
// Conventions: assimp hands out right-handed, +y up, counter-clockwise front faces. shadowfx wants D3D's
// left-handed, clockwise (Mesh.h). aiProcess_ConvertToLeftHanded = MakeLeftHanded (mirror z) + FlipUVs (D3D's
// v grows downwards) + FlipWindingOrder. The winding flip is needed, not optional: mirroring negates the
// winding normal relative to the (mirrored) vertex normals, cross(Mb - Ma, Mc - Ma) = -M cross(b - a, c - a)
// for M = diag(1, 1, -1), and flipping the order restores cross(b - a, c - a) · n > 0, which is what a
// clockwise front face means in a left-handed world (tests/runtime/test_scene_file.cpp checks it).
#include <private/runtime/MeshFileModule.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace runtime {

namespace {

bool readMeshFile(const std::string& path, bool dropNormals, Mesh& mesh, std::string& error) {
    Assimp::Importer importer;
    // Points and lines cannot cast or receive shadows: drop them rather than fail on mixed files.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // No aiProcess_GenSmoothNormals: assimp runs it after FlipWindingOrder yet still assumes
    // counter-clockwise fronts, so its normals come out inverted against the converted winding (the
    // importer generates them instead).
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                     aiProcess_PreTransformVertices | aiProcess_ConvertToLeftHanded | aiProcess_SortByPType |
                     aiProcess_FindInvalidData | aiProcess_ValidateDataStructure;
    if (dropNormals) {
        importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
        flags |= aiProcess_RemoveComponent;
    }
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        error = importer.GetErrorString();
        return false;
    }

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
    return true;
}

constexpr MeshFileModule kModule{readMeshFile};

}  // namespace

}  // namespace runtime

extern "C" __attribute__((visibility("default"))) const runtime::MeshFileModule* shadowfx_meshimport_v1() {
    return &runtime::kModule;
}
