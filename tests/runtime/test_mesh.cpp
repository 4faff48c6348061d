// Mesh generators: D3D winding (front faces clockwise in a left-handed world, i.e. cross(b - a, c - a) points
// outward), normals, closedness, bounds, triangle counts, texcoords and tangents.
#include <runtime/Mesh.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace test_mesh {

using namespace runtime;

namespace {

using Key = std::tuple<long, long, long>;

// Positions equal up to rounding share a key: seams and poles duplicate vertices that are one point.
Key weldKey(const glm::vec3& p) {
    auto q = [](float x) { return static_cast<long>(std::lround(x * 1e3f)); };
    return {q(p.x), q(p.y), q(p.z)};
}

glm::vec3 faceNormal(const Mesh& mesh, size_t triangle) {
    const auto& p = mesh.positions;
    const auto* idx = &mesh.indices[triangle * 3];
    return glm::cross(p[idx[1]] - p[idx[0]], p[idx[2]] - p[idx[0]]);
}

// Every triangle has area, and its winding normal agrees with each of its vertex normals.
testing::AssertionResult windingAgreesWithNormals(const Mesh& mesh) {
    if (mesh.normals.size() != mesh.positions.size()) return testing::AssertionFailure() << "normals missing";
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::vec3 n = faceNormal(mesh, t);
        if (glm::length(n) < 1e-9f)
            return testing::AssertionFailure() << "triangle " << t << " is degenerate";
        n = glm::normalize(n);
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.indices[t * 3 + k];
            float d = glm::dot(n, mesh.normals[v]);
            if (!(d > 0.0f)) {
                return testing::AssertionFailure()
                       << mesh.name << ": triangle " << t << " winds against the normal of vertex " << v
                       << " (dot " << d << ")";
            }
        }
    }
    return testing::AssertionSuccess();
}

// Over welded positions, no directed edge is used twice (orientation is consistent across triangles) and,
// for closed meshes, every directed edge has its reverse (each edge shared by exactly two triangles).
testing::AssertionResult edgesConsistent(const Mesh& mesh, bool requireClosed) {
    std::map<std::pair<Key, Key>, int> directed;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            Key a = weldKey(mesh.positions[mesh.indices[t * 3 + k]]);
            Key b = weldKey(mesh.positions[mesh.indices[t * 3 + (k + 1) % 3]]);
            if (a == b) return testing::AssertionFailure() << "triangle " << t << " has a collapsed edge";
            if (++directed[{a, b}] > 1)
                return testing::AssertionFailure() << "directed edge used twice at triangle " << t;
        }
    }
    if (requireClosed) {
        for (const auto& [edge, count] : directed) {
            if (!directed.count({edge.second, edge.first}))
                return testing::AssertionFailure() << mesh.name << ": an edge belongs to one triangle only";
        }
    }
    return testing::AssertionSuccess();
}

// Divergence theorem: positive when cross(b - a, c - a) points outward everywhere.
double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::dvec3 a = mesh.positions[mesh.indices[t * 3]], b = mesh.positions[mesh.indices[t * 3 + 1]],
                   c = mesh.positions[mesh.indices[t * 3 + 2]];
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

testing::AssertionResult tangentsValid(const Mesh& mesh) {
    if (mesh.tangents.size() != mesh.positions.size())
        return testing::AssertionFailure() << "tangents missing";
    if (mesh.texcoords.size() != mesh.positions.size())
        return testing::AssertionFailure() << "texcoords missing";
    for (size_t v = 0; v < mesh.tangents.size(); ++v) {
        glm::vec3 t(mesh.tangents[v]);
        if (std::abs(glm::length(t) - 1.0f) > 1e-3f)
            return testing::AssertionFailure() << "tangent " << v << " not unit";
        if (std::abs(glm::dot(t, mesh.normals[v])) > 1e-3f)
            return testing::AssertionFailure() << "tangent " << v << " not perpendicular to the normal";
        if (std::abs(mesh.tangents[v].w) != 1.0f)
            return testing::AssertionFailure() << "handedness of " << v << " not +-1";
    }
    return testing::AssertionSuccess();
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// Möller-Trumbore, either side; the t of the hit along origin + t * dir.
std::optional<float> rayHit(const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& a,
                            const glm::vec3& b, const glm::vec3& c) {
    glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;
    glm::vec3 s = origin - a;
    float u = glm::dot(s, p) / det;
    if (u < 0 || u > 1) return std::nullopt;
    glm::vec3 q = glm::cross(s, e1);
    float v = glm::dot(dir, q) / det;
    if (v < 0 || u + v > 1) return std::nullopt;
    return glm::dot(e2, q) / det;
}

}  // namespace

TEST(Mesh, PlaneFacesUpWithD3DTexcoords) {
    for (int divisions : {1, 4, 7}) {
        Mesh plane = makePlane(6.0f, 4.0f, divisions);
        EXPECT_EQ(plane.triangleCount(), size_t(2 * divisions * divisions));
        EXPECT_EQ(plane.positions.size(), size_t((divisions + 1) * (divisions + 1)));
        EXPECT_FALSE(plane.closed);
        EXPECT_TRUE(windingAgreesWithNormals(plane));
        EXPECT_TRUE(edgesConsistent(plane, false));
        EXPECT_TRUE(tangentsValid(plane));
        expectNear(plane.boundsMin(), glm::vec3(-3.0f, 0.0f, -2.0f), 1e-5f);
        expectNear(plane.boundsMax(), glm::vec3(3.0f, 0.0f, 2.0f), 1e-5f);
        for (size_t t = 0; t < plane.triangleCount(); ++t) EXPECT_GT(faceNormal(plane, t).y, 0.0f);
        for (size_t v = 0; v < plane.positions.size(); ++v) {
            // Seen from above with +z at the top of the image, (0,0) is the top-left corner: u follows +x, v
            // -z.
            EXPECT_NEAR(plane.texcoords[v].x, plane.positions[v].x / 6.0f + 0.5f, 1e-5f);
            EXPECT_NEAR(plane.texcoords[v].y, 0.5f - plane.positions[v].z / 4.0f, 1e-5f);
            expectNear(glm::vec3(plane.tangents[v]), glm::vec3(1, 0, 0), 1e-5f);
        }
    }
}

TEST(Mesh, BoxIsClosedAndOutward) {
    const glm::vec3 size(2.0f, 3.0f, 4.0f);
    Mesh box = makeBox(size);
    EXPECT_EQ(box.triangleCount(), 12u);
    EXPECT_TRUE(box.closed);
    EXPECT_TRUE(windingAgreesWithNormals(box));
    EXPECT_TRUE(edgesConsistent(box, true));
    EXPECT_TRUE(tangentsValid(box));
    EXPECT_NEAR(signedVolume(box), size.x * size.y * size.z, 1e-4);
    expectNear(box.boundsMin(), -size * 0.5f, 1e-6f);
    expectNear(box.boundsMax(), size * 0.5f, 1e-6f);
    // Every face's normal is the axis its vertices lie on, pointing away from the centre.
    for (size_t v = 0; v < box.positions.size(); ++v) {
        glm::vec3 n = box.normals[v];
        EXPECT_NEAR(glm::dot(box.positions[v], n), glm::dot(glm::abs(n), size * 0.5f), 1e-5f);
    }
}

TEST(Mesh, SphereIsClosedAndOutward) {
    for (auto [slices, stacks] : {std::pair{32, 16}, std::pair{3, 2}, std::pair{7, 5}}) {
        const float radius = 1.5f;
        Mesh sphere = makeSphere(radius, slices, stacks);
        EXPECT_EQ(sphere.triangleCount(), size_t(2 * slices * (stacks - 1)));
        EXPECT_TRUE(sphere.closed);
        EXPECT_TRUE(windingAgreesWithNormals(sphere));
        EXPECT_TRUE(edgesConsistent(sphere, true));
        EXPECT_TRUE(tangentsValid(sphere));
        EXPECT_GT(signedVolume(sphere), 0.0);
        EXPECT_LT(signedVolume(sphere), 4.0 / 3.0 * glm::pi<double>() * std::pow(radius, 3.0));  // inscribed
        for (size_t v = 0; v < sphere.positions.size(); ++v) {
            expectNear(sphere.normals[v], sphere.positions[v] / radius, 1e-5f);
        }
        // The poles are vertices: the y extent is exact whatever the tessellation.
        EXPECT_NEAR(sphere.boundsMin().y, -radius, 1e-5f);
        EXPECT_NEAR(sphere.boundsMax().y, radius, 1e-5f);
    }
    Mesh fine = makeSphere(2.0f, 64, 32);
    EXPECT_NEAR(signedVolume(fine), 4.0 / 3.0 * glm::pi<double>() * 8.0,
                0.02 * 4.0 / 3.0 * glm::pi<double>() * 8.0);
    expectNear(fine.boundsMin(), glm::vec3(-2.0f), 1e-4f);
    expectNear(fine.boundsMax(), glm::vec3(2.0f), 1e-4f);
}

TEST(Mesh, TorusIsClosedAndOutward) {
    const float major = 2.0f, minor = 0.5f;
    for (auto [majorSegments, minorSegments] : {std::pair{48, 24}, std::pair{5, 3}}) {
        Mesh torus = makeTorus(major, minor, majorSegments, minorSegments);
        EXPECT_EQ(torus.triangleCount(), size_t(2 * majorSegments * minorSegments));
        EXPECT_TRUE(torus.closed);
        EXPECT_TRUE(windingAgreesWithNormals(torus));
        EXPECT_TRUE(edgesConsistent(torus, true));
        EXPECT_TRUE(tangentsValid(torus));
        EXPECT_GT(signedVolume(torus), 0.0);
    }
    Mesh torus = makeTorus(major, minor, 96, 48);
    const double volume = 2.0 * glm::pi<double>() * glm::pi<double>() * major * minor * minor;
    EXPECT_NEAR(signedVolume(torus), volume, 0.02 * volume);
    // In the xz plane: the y extent is the tube's diameter.
    expectNear(torus.boundsMin(), glm::vec3(-(major + minor), -minor, -(major + minor)), 1e-3f);
    expectNear(torus.boundsMax(), glm::vec3(major + minor, minor, major + minor), 1e-3f);
    for (size_t v = 0; v < torus.positions.size(); ++v) {
        // The normal points from the tube's centre circle to the vertex.
        glm::vec3 p = torus.positions[v];
        glm::vec3 ring = glm::normalize(glm::vec3(p.x, 0.0f, p.z)) * major;
        expectNear(torus.normals[v], (p - ring) / minor, 1e-4f);
    }
}

TEST(Mesh, TeapotIsNewellsShapeFacingOutward) {
    const float size = 3.0f;
    // From 6 on: at 4 the spout's lip, which folds over within one row of a patch, is undersampled and a
    // triangle spanning the fold faces away from the smooth normals there.
    for (int tessellation : {6, 8, 12}) {
        Mesh teapot = makeTeapot(size, tessellation);
        EXPECT_FALSE(teapot.closed);
        // 32 patches of 2 n^2 triangles, less the zero-area ones where rows collapse (lid knob, bottom
        // centre).
        EXPECT_LE(teapot.triangleCount(), size_t(32 * 2 * tessellation * tessellation));
        EXPECT_GT(teapot.triangleCount(), size_t(28 * 2 * tessellation * tessellation));
        EXPECT_TRUE(windingAgreesWithNormals(teapot));
        EXPECT_TRUE(edgesConsistent(teapot, false));
        EXPECT_TRUE(tangentsValid(teapot));

        // Centred, largest extent = size, +y up, and the classic proportions. In Newell's units the height is
        // exactly 3.15 (lid knob and bottom centre lie on the surface) and the depth 4 (the body's widest
        // circle, r = 2 at z = 0.9), while the width is under the 6.525 of the control points (the handle's
        // and spout's outermost ones are not on the surface).
        glm::vec3 lo = teapot.boundsMin(), hi = teapot.boundsMax();
        expectNear((lo + hi) * 0.5f, glm::vec3(0.0f), 1e-4f);
        EXPECT_NEAR(hi.x - lo.x, size, 1e-4f);
        const float unitsToSize = (hi.y - lo.y) / 3.15f;
        EXPECT_NEAR(hi.z - lo.z, 4.0f * unitsToSize,
                    0.01f * size);  // the quadrant's 0.56 circle bulges a bit
        EXPECT_LT(size / unitsToSize, 6.525f);
        EXPECT_GT(size / unitsToSize, 6.0f);
        // The spout tip is the +x extreme and sits high; the handle is at -x.
        size_t tip = 0;
        for (size_t v = 0; v < teapot.positions.size(); ++v)
            if (teapot.positions[v].x > teapot.positions[tip].x) tip = v;
        EXPECT_GT(teapot.positions[tip].y, 0.0f);
    }

    // Outward faces: a ray leaving a front face along its normal travels through the air outside, so the
    // first surface it meets (if any) must face it. A few rays fail where the surface is open (the gap
    // between lid and rim) or where the handle and spout run inside the body.
    Mesh teapot = makeTeapot(size, 8);
    int facing = 0, backwards = 0;
    for (size_t t = 0; t < teapot.triangleCount(); ++t) {
        const auto* idx = &teapot.indices[t * 3];
        glm::vec3 centre =
            (teapot.positions[idx[0]] + teapot.positions[idx[1]] + teapot.positions[idx[2]]) / 3.0f;
        glm::vec3 dir = glm::normalize(faceNormal(teapot, t));
        std::optional<float> nearest;
        size_t nearestTriangle = 0;
        for (size_t s = 0; s < teapot.triangleCount(); ++s) {
            if (s == t) continue;
            const auto* j = &teapot.indices[s * 3];
            auto hit =
                rayHit(centre, dir, teapot.positions[j[0]], teapot.positions[j[1]], teapot.positions[j[2]]);
            if (hit && *hit > 1e-4f && (!nearest || *hit < *nearest)) {
                nearest = hit;
                nearestTriangle = s;
            }
        }
        if (!nearest) continue;
        (glm::dot(faceNormal(teapot, nearestTriangle), dir) < 0.0f ? facing : backwards)++;
    }
    const int escaping = int(teapot.triangleCount()) - facing - backwards;
    EXPECT_GT(escaping, int(teapot.triangleCount()) / 2);  // most of an outer surface sees the sky
    EXPECT_LT(backwards, int(teapot.triangleCount()) / 20)
        << facing << " facing, " << backwards << " backwards";
}

TEST(Mesh, EmptyMeshBoundsAreZero) {
    Mesh empty;
    expectNear(empty.boundsMin(), glm::vec3(0.0f), 0.0f);
    expectNear(empty.boundsMax(), glm::vec3(0.0f), 0.0f);
    EXPECT_EQ(empty.triangleCount(), 0u);
}
}  // namespace test_mesh
