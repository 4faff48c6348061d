// makeTeapot: Newell's teapot from its 32 bicubic Bezier patches (TeapotData.h), tessellated.
//
// Steps: expand the stored quarters/halves to the 32 patches; evaluate each patch on an (N+1) x (N+1) grid;
// wind every triangle so that cross(b - a, c - a) points to the outer side (D3D front faces are clockwise in
// a left-handed world, see Mesh.cpp); average face normals over coincident positions so the shading is
// smooth across patch seams; rotate to +y up, centre on the origin and scale to `size`.
//
// Outer side: the patch table does not promise a consistent parameter orientation (mirrored copies flip it,
// and the bottom runs against the body), so each patch's side is decided once, where a geometric hint is
// reliable: for a surface of revolution, the left-hand normal of its profile in the (r, z) half-plane
// (TeapotData.h lists every profile in the same sense along the silhouette, so the left is always the
// outside, including the inner face of the rim's lip); for the handle and spout tubes, the direction from the
// centre of their first cross-section. Each triangle then follows the patch's parametric normal, which stays
// right through folds like the spout's lip. Below a tessellation of 6 that lip is undersampled.

#include <runtime/Mesh.h>

#include "TangentFrame.h"
#include "TeapotData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace runtime {

namespace {

using ControlGrid = std::array<std::array<glm::vec3, 4>, 4>;  // [row][column], z-up original units

struct Patch {
    ControlGrid cp;
    int profile = -1;  // index into teapot::kProfiles for surfaces of revolution, -1 for the tubes
};

glm::vec4 bernstein(float t) {
    float s = 1.0f - t;
    return {s * s * s, 3.0f * s * s * t, 3.0f * s * t * t, t * t * t};
}

glm::vec4 bernsteinDerivative(float t) {
    float s = 1.0f - t;
    return {-3.0f * s * s, 3.0f * s * s - 6.0f * s * t, 6.0f * s * t - 3.0f * t * t, 3.0f * t * t};
}

// u runs along the rows (down a profile / along a tube), v along the columns (around).
glm::vec3 evaluate(const ControlGrid& cp, float u, float v) {
    glm::vec4 bu = bernstein(u), bv = bernstein(v);
    glm::vec3 p(0.0f);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p += cp[i][j] * (bu[i] * bv[j]);
    return p;
}

// dP/du x dP/dv: the patch's own orientation, continuous over the patch (also through folds such as the
// spout's lip, where a geometric rule of thumb for "outside" would flip).
glm::vec3 parametricNormal(const ControlGrid& cp, float u, float v) {
    glm::vec4 bu = bernstein(u), bv = bernstein(v), du = bernsteinDerivative(u), dv = bernsteinDerivative(v);
    glm::vec3 pu(0.0f), pv(0.0f);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            pu += cp[i][j] * (du[i] * bv[j]);
            pv += cp[i][j] * (bu[i] * dv[j]);
        }
    }
    return glm::cross(pu, pv);
}

// Which side is outside at (u, v), in the original z-up frame (see the file comment).
glm::vec3 outwardHint(const Patch& patch, float u, float v) {
    glm::vec3 p = evaluate(patch.cp, u, v);
    if (patch.profile < 0) {
        glm::vec3 centre = (evaluate(patch.cp, u, 0.0f) + evaluate(patch.cp, u, 1.0f)) * 0.5f;
        return p - centre;
    }
    glm::vec4 db = bernsteinDerivative(u);
    float dr = 0.0f, dz = 0.0f;
    for (int i = 0; i < 4; ++i) {
        dr += db[i] * teapot::kProfiles[patch.profile][i].r;
        dz += db[i] * teapot::kProfiles[patch.profile][i].z;
    }
    glm::vec2 radial(p.x, p.y);
    float length = glm::length(radial);
    radial = length > 1e-6f ? radial / length : glm::vec2(0.0f);
    return glm::vec3(-dz * radial.x, -dz * radial.y, dr);  // (-dz, dr): left of the direction (dr, dz)
}

// +1 if the patch's parametric normal points outside, -1 if not. Decided where the hint is reliable: the
// middle of a surface of revolution (the profile rule is exact there), the first cross-section of a tube
// (where it leaves the body: round, not yet folded into the spout's lip).
float patchSide(const Patch& patch) {
    const float u = patch.profile < 0 ? 0.05f : 0.5f;
    return glm::dot(parametricNormal(patch.cp, u, 0.5f), outwardHint(patch, u, 0.5f)) < 0.0f ? -1.0f : 1.0f;
}

std::vector<Patch> expandPatches() {
    std::vector<Patch> patches;
    const float k = teapot::kCircleHandle;
    const glm::vec2 quarter[4] = {{1.0f, 0.0f}, {1.0f, -k}, {k, -1.0f}, {0.0f, -1.0f}};
    for (int profile = 0; profile < 6; ++profile) {
        for (int quadrant = 0; quadrant < 4; ++quadrant) {
            Patch patch;
            patch.profile = profile;
            for (int i = 0; i < 4; ++i) {
                const auto& pp = teapot::kProfiles[profile][i];
                for (int j = 0; j < 4; ++j) {
                    glm::vec2 xy = quarter[j] * pp.r;
                    for (int q = 0; q < quadrant; ++q) xy = glm::vec2(xy.y, -xy.x);  // -90 degrees about z
                    patch.cp[i][j] = glm::vec3(xy, pp.z);
                }
            }
            patches.push_back(patch);
        }
    }
    for (const auto& half : teapot::kTubePatches) {
        for (float mirror : {1.0f, -1.0f}) {
            Patch patch;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    patch.cp[i][j] = glm::vec3(half[i][j].x, mirror * half[i][j].y, half[i][j].z);
            patches.push_back(patch);
        }
    }
    return patches;
}

// z-up (Newell's frame) to y-up; a rotation about x, so it keeps windings and the teapot's spout at +x.
glm::vec3 toYUp(const glm::vec3& p) {
    return glm::vec3(p.x, p.z, -p.y);
}

}  // namespace

Mesh makeTeapot(float size, int tessellation) {
    const int n = std::max(tessellation, 1);
    const int row = n + 1;
    Mesh mesh;
    mesh.name = "teapot";
    mesh.closed =
        false;  // the lid does not meet the rim, the spout is open, handle and spout pierce the body

    std::vector<glm::vec3> dPdu, dPdv;  // grid differences, for the tangents
    for (const Patch& patch : expandPatches()) {
        const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
        const float side = patchSide(patch);
        std::vector<glm::vec3> grid(row * row);
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) grid[i * row + j] = evaluate(patch.cp, float(i) / n, float(j) / n);
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                auto at = [&](int ii, int jj) {
                    return toYUp(grid[std::clamp(ii, 0, n) * row + std::clamp(jj, 0, n)]);
                };
                mesh.positions.push_back(at(i, j));
                mesh.texcoords.emplace_back(float(j) / n, float(i) / n);
                dPdu.push_back(at(i, j + 1) - at(i, j - 1));  // texture u runs along the columns
                dPdv.push_back(at(i + 1, j) - at(i - 1, j));
            }
        }
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const uint32_t a = base + i * row + j, b = a + 1, c = a + row + 1, d = a + row;
                const glm::vec3 outward =
                    toYUp(parametricNormal(patch.cp, (i + 0.5f) / n, (j + 0.5f) / n) * side);
                for (auto tri : {std::array<uint32_t, 3>{a, b, c}, std::array<uint32_t, 3>{a, c, d}}) {
                    const auto& p = mesh.positions;
                    glm::vec3 winding = glm::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]);
                    // Collapsed corners at the lid's knob and the bottom's centre give zero-area triangles.
                    if (glm::dot(winding, winding) < 1e-14f) continue;
                    if (glm::dot(winding, outward) < 0.0f) std::swap(tri[1], tri[2]);
                    mesh.indices.insert(mesh.indices.end(), tri.begin(), tri.end());
                }
            }
        }
    }

    // Smooth normals, in two passes. First per patch: area-weighted face normals summed over the vertices of
    // one patch at one position (its collapsed rows at the knob and the bottom's centre are one point). Then
    // across patches: coincident vertices of different patches share their normals so the 32 patches shade
    // as one surface, but only where those normals roughly agree: the handle's and spout's ends touch the
    // body at single points, and averaging across that crease would bend both.
    auto key = [](const glm::vec3& p) {
        auto q = [](float x) { return static_cast<long>(std::lround(x * 1e4f)); };
        return std::make_tuple(q(p.x), q(p.y), q(p.z));
    };
    const size_t vertexCount = mesh.positions.size();
    const size_t verticesPerPatch = size_t(row) * size_t(row);
    std::map<std::tuple<long, long, long, size_t>, glm::vec3> patchSums;
    auto patchKey = [&](uint32_t v) {
        return std::tuple_cat(key(mesh.positions[v]), std::make_tuple(v / verticesPerPatch));
    };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const auto& p = mesh.positions;
        const uint32_t* tri = &mesh.indices[t];
        glm::vec3 faceNormal = glm::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]);
        for (int k = 0; k < 3; ++k) patchSums[patchKey(tri[k])] += faceNormal;
    }
    std::vector<glm::vec3> patchNormals(vertexCount, glm::vec3(0.0f));
    std::map<std::tuple<long, long, long>, std::vector<uint32_t>> coincident;
    for (uint32_t v = 0; v < vertexCount; ++v) {
        glm::vec3 sum = patchSums[patchKey(v)];
        if (glm::dot(sum, sum) > 0.0f) patchNormals[v] = glm::normalize(sum);
        coincident[key(mesh.positions[v])].push_back(v);
    }
    mesh.normals.resize(vertexCount);
    mesh.tangents.resize(vertexCount);
    for (uint32_t v = 0; v < vertexCount; ++v) {
        glm::vec3 sum(0.0f);
        for (uint32_t other : coincident[key(mesh.positions[v])])
            if (glm::dot(patchNormals[other], patchNormals[v]) > 0.5f)
                sum += patchNormals[other];  // within 60 degrees
        mesh.normals[v] = glm::dot(sum, sum) > 0.0f ? glm::normalize(sum) : glm::vec3(0, 1, 0);
        mesh.tangents[v] = tangentFrame(mesh.normals[v], dPdu[v], dPdv[v]);
    }

    // Centre on the origin; `size` is the largest extent (handle to spout tip).
    glm::vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax();
    glm::vec3 centre = (lo + hi) * 0.5f;
    glm::vec3 extent = hi - lo;
    float scale = size / std::max({extent.x, extent.y, extent.z, 1e-6f});
    for (auto& p : mesh.positions) p = (p - centre) * scale;
    return mesh;
}

}  // namespace runtime
