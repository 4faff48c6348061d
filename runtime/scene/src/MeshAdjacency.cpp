// Edge and adjacency index lists of a triangle list (see Mesh.h).
#include <runtime/Mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

namespace runtime {
namespace {

// The welded index of every vertex: the first vertex within a small distance (1e-5 of the mesh's extent,
// at least 1e-6) in every coordinate, as D3DX's GenerateAdjacency welds within an epsilon. Generated
// meshes repeat their seam vertices with positions that differ in the last bits (sin(2 pi) is not 0).
std::vector<uint32_t> weld(const std::vector<glm::vec3>& positions) {
    glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : positions)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            low = glm::min(low, p), high = glm::max(high, p);
    const glm::vec3 extent = glm::max(high - low, glm::vec3(0.0f));
    const float epsilon = std::max(1e-5f * std::max(extent.x, std::max(extent.y, extent.z)), 1e-6f);
    // Cells of the epsilon's size: a vertex's partner lies in its cell or a neighbouring one.
    using Cell = std::array<int64_t, 3>;
    std::map<Cell, std::vector<uint32_t>> cells;
    std::vector<uint32_t> welded(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 q = (positions[i] - low) / epsilon;
        welded[i] = static_cast<uint32_t>(i);
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) continue;  // welds to nothing
        const Cell cell{static_cast<int64_t>(std::floor(q.x)), static_cast<int64_t>(std::floor(q.y)),
                        static_cast<int64_t>(std::floor(q.z))};
        uint32_t found = static_cast<uint32_t>(i);
        for (int64_t dx = -1; dx <= 1 && found == i; ++dx)
            for (int64_t dy = -1; dy <= 1 && found == i; ++dy)
                for (int64_t dz = -1; dz <= 1 && found == i; ++dz) {
                    auto it = cells.find(Cell{cell[0] + dx, cell[1] + dy, cell[2] + dz});
                    if (it == cells.end()) continue;
                    for (uint32_t other : it->second) {
                        const glm::vec3 d = glm::abs(positions[other] - positions[i]);
                        if (std::max(d.x, std::max(d.y, d.z)) <= epsilon) {
                            found = welded[other];
                            break;
                        }
                    }
                }
        welded[i] = found;
        cells[cell].push_back(static_cast<uint32_t>(i));
    }
    return welded;
}

using Edge = std::pair<uint32_t, uint32_t>;  // welded indices, smaller first

Edge edgeOf(uint32_t a, uint32_t b) {
    return a < b ? Edge{a, b} : Edge{b, a};
}

bool validTriangle(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices, size_t t) {
    return indices[t] < positions.size() && indices[t + 1] < positions.size() &&
           indices[t + 2] < positions.size();
}

}  // namespace

std::vector<uint32_t> edgeIndices(const std::vector<glm::vec3>& positions,
                                  const std::vector<uint32_t>& indices) {
    const std::vector<uint32_t> welded = weld(positions);
    std::map<Edge, bool> seen;
    std::vector<uint32_t> lines;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (!validTriangle(positions, indices, t)) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
            if (welded[a] == welded[b] || !seen.try_emplace(edgeOf(welded[a], welded[b]), true).second)
                continue;
            lines.push_back(a);
            lines.push_back(b);
        }
    }
    return lines;
}

std::vector<uint32_t> adjacencyIndices(const std::vector<glm::vec3>& positions,
                                       const std::vector<uint32_t>& indices) {
    const std::vector<uint32_t> welded = weld(positions);
    // Per welded edge: the opposite vertex of each triangle on it (up to two; a third marks it shared).
    struct Sides {
        uint32_t opposite[2] = {0, 0};
        size_t triangle[2] = {0, 0};
        int count = 0;
    };
    std::map<Edge, Sides> edges;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (!validTriangle(positions, indices, t)) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3], c = indices[t + (k + 2) % 3];
            if (welded[a] == welded[b]) continue;
            Sides& sides = edges[edgeOf(welded[a], welded[b])];
            if (sides.count < 2) {
                sides.opposite[sides.count] = c;
                sides.triangle[sides.count] = t;
            }
            ++sides.count;
        }
    }
    std::vector<uint32_t> out;
    out.reserve(indices.size() * 2);
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (!validTriangle(positions, indices, t)) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3], c = indices[t + (k + 2) % 3];
            uint32_t across = c;  // no single neighbour: the triangle itself, wound backwards
            if (welded[a] != welded[b]) {
                const Sides& sides = edges[edgeOf(welded[a], welded[b])];
                if (sides.count == 2) across = sides.opposite[sides.triangle[0] == t ? 1 : 0];
            }
            out.push_back(a);
            out.push_back(across);
        }
    }
    return out;
}

}  // namespace runtime
