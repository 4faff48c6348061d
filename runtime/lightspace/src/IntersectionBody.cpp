#include <runtime/IntersectionBody.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace runtime {

namespace {

// Relative slack of the plane tests: culling must never drop an object a rasterizer would still touch.
constexpr float kPlaneSlack = 1e-4f;

float planeDistance(const glm::vec4& plane, const glm::vec3& p) {
    return glm::dot(glm::vec3(plane), p) + plane.w;
}

std::array<glm::vec3, 8> boxCorners(const glm::vec3& lo, const glm::vec3& hi) {
    std::array<glm::vec3, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[static_cast<size_t>(i)] =
            glm::vec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    return corners;
}

// Edges of a box-like polyhedron whose corners are numbered by the bits x=1, y=2, z=4.
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

}  // namespace

ConvexVolume frustumPlanes(const glm::mat4& m) {
    // Rows of the row-vector matrix are glm's columns' components: clip.x = dot(row0, p) etc.
    const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]);
    const glm::vec4 r1(m[0][1], m[1][1], m[2][1], m[3][1]);
    const glm::vec4 r2(m[0][2], m[1][2], m[2][2], m[3][2]);
    const glm::vec4 r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    ConvexVolume volume;
    volume.planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
    for (glm::vec4& plane : volume.planes) {
        const float length = glm::length(glm::vec3(plane));
        if (length > 0.0f) plane /= length;
    }
    return volume;
}

Overlap overlapVolume(const ConvexVolume& volume, const Aabb& box) {
    const glm::vec3 centre = (box.min + box.max) * 0.5f;
    const glm::vec3 half = (box.max - box.min) * 0.5f;
    const float scale = glm::length(centre) + glm::length(half) + 1.0f;
    bool inside = true;
    for (const glm::vec4& plane : volume.planes) {
        const glm::vec3 n(plane);
        const float reach = glm::dot(glm::abs(n), half);
        const float distance = planeDistance(plane, centre);
        const float slack = kPlaneSlack * (scale + std::abs(plane.w));
        if (distance + reach < -slack) return Overlap::Outside;
        if (distance - reach < slack) inside = false;
    }
    return inside ? Overlap::Inside : Overlap::Partial;
}

std::vector<glm::vec3> intersectionBodyPoints(const glm::mat4& viewProjection, const Bounds& bounds) {
    std::vector<glm::vec3> points;
    intersectionBodyPoints(viewProjection, bounds, points);
    return points;
}

void intersectionBodyPoints(const glm::mat4& viewProjection, const Bounds& bounds,
                            std::vector<glm::vec3>& points) {
    const glm::mat4 inverse = glm::inverse(viewProjection);
    std::array<glm::vec3, 8> frustum;
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 ndc((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : 0.0f, 1.0f);
        const glm::vec4 p = inverse * ndc;
        frustum[static_cast<size_t>(i)] = glm::vec3(p) / p.w;
    }
    const std::array<glm::vec3, 8> box = boxCorners(bounds.min, bounds.max);
    const ConvexVolume planes = frustumPlanes(viewProjection);
    const float boxSlack = 1e-4f * (bounds.radius() + 1.0f);
    const auto inBox = [&](const glm::vec3& p) {
        return glm::all(glm::greaterThanEqual(p, bounds.min - boxSlack)) &&
               glm::all(glm::lessThanEqual(p, bounds.max + boxSlack));
    };
    const auto inFrustum = [&](const glm::vec3& p) {
        const float slack = kPlaneSlack * (glm::length(p) + 1.0f);
        return std::all_of(planes.planes.begin(), planes.planes.end(),
                           [&](const glm::vec4& plane) { return planeDistance(plane, p) >= -slack; });
    };

    points.clear();
    for (const glm::vec3& p : frustum)
        if (inBox(p)) points.push_back(p);
    for (const glm::vec3& p : box)
        if (inFrustum(p)) points.push_back(p);
    // Frustum edges against the box's six faces.
    for (const auto& edge : kEdges) {
        const glm::vec3 a = frustum[static_cast<size_t>(edge[0])], b = frustum[static_cast<size_t>(edge[1])];
        for (int axis = 0; axis < 3; ++axis) {
            for (const float value : {bounds.min[axis], bounds.max[axis]}) {
                const float denominator = b[axis] - a[axis];
                if (denominator == 0.0f) continue;
                const float t = (value - a[axis]) / denominator;
                if (t < 0.0f || t > 1.0f) continue;
                glm::vec3 p = a + t * (b - a);
                p[axis] = value;
                if (inBox(p)) points.push_back(p);
            }
        }
    }
    // Box edges against the frustum's six planes.
    for (const auto& edge : kEdges) {
        const glm::vec3 a = box[static_cast<size_t>(edge[0])], b = box[static_cast<size_t>(edge[1])];
        for (const glm::vec4& plane : planes.planes) {
            const float da = planeDistance(plane, a), db = planeDistance(plane, b);
            if ((da < 0.0f) == (db < 0.0f) || da == db) continue;
            const glm::vec3 p = a + (da / (da - db)) * (b - a);
            if (inFrustum(p)) points.push_back(p);
        }
    }
}

bool ReceiverRegion::contains(const ReceiverRegion& other) const {
    if (other.empty || full) return true;
    if (empty || other.full) return false;
    return min.x <= other.min.x && min.y <= other.min.y && max.x >= other.max.x && max.y >= other.max.y &&
           maxDepth >= other.maxDepth;
}

ReceiverRegion fullLightRegion() {
    ReceiverRegion region;
    region.maxDepth = std::numeric_limits<float>::infinity();
    return region;
}

ReceiverRegion receiverRegion(const std::vector<glm::vec3>& points, const glm::mat4& lightViewProjection,
                              glm::vec2 mapSize, float padTexels) {
    ReceiverRegion region;
    if (points.empty()) {
        region.empty = true;
        region.full = false;
        return region;
    }
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    float depth = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : points) {
        const glm::vec4 clip = lightViewProjection * glm::vec4(p, 1.0f);
        if (clip.w <= 1e-6f) return fullLightRegion();  // behind a spot light: no bounded region
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        lo = glm::min(lo, glm::vec2(ndc));
        hi = glm::max(hi, glm::vec2(ndc));
        depth = std::max(depth, ndc.z);
    }
    // Two NDC units span the map: one texel is 2 / size.
    const glm::vec2 pad = padTexels * 2.0f / glm::max(mapSize, glm::vec2(1.0f));
    region.full = false;
    region.min = glm::clamp(lo, glm::vec2(-1.0f), glm::vec2(1.0f)) - pad;
    region.max = glm::clamp(hi, glm::vec2(-1.0f), glm::vec2(1.0f)) + pad;
    region.maxDepth = depth + 1e-4f * (std::abs(depth) + 1.0f);
    return region;
}

LightFootprint lightFootprint(const glm::mat4& lightViewProjection, const Aabb& box) {
    LightFootprint footprint;
    const std::array<glm::vec3, 8> corners = boxCorners(box.min, box.max);
    // Each corner transformed once: the light's cull tests every node of the scene's tree it reaches.
    std::array<glm::vec4, 8> clips;
    for (size_t i = 0; i < corners.size(); ++i) {
        clips[i] = lightViewProjection * glm::vec4(corners[i], 1.0f);
        footprint.behind += clips[i].w <= 1e-6f ? 1 : 0;
    }
    if (footprint.behind > 0) return footprint;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    float nearest = std::numeric_limits<float>::max(), farthest = std::numeric_limits<float>::lowest();
    for (const glm::vec4& clip : clips) {
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        lo = glm::min(lo, glm::vec2(ndc));
        hi = glm::max(hi, glm::vec2(ndc));
        nearest = std::min(nearest, ndc.z);
        farthest = std::max(farthest, ndc.z);
    }
    footprint.lo = lo;
    footprint.hi = hi;
    footprint.nearest = nearest;
    footprint.farthest = farthest;
    return footprint;
}

Overlap casterReaches(const ReceiverRegion& region, const LightFootprint& footprint) {
    if (region.empty) return Overlap::Outside;
    if (footprint.behind == 8 && region.castersBehindLightPlaneCastNothing) return Overlap::Outside;
    if (footprint.behind > 0) return Overlap::Partial;  // crosses the light's plane: keep, look closer
    const glm::vec2 regionMin = region.full ? glm::vec2(-1.0f) : region.min;
    const glm::vec2 regionMax = region.full ? glm::vec2(1.0f) : region.max;
    const float slack = 1e-5f;
    const glm::vec2 lo = footprint.lo, hi = footprint.hi;
    if (hi.x < regionMin.x - slack || hi.y < regionMin.y - slack || lo.x > regionMax.x + slack ||
        lo.y > regionMax.y + slack || footprint.nearest > region.maxDepth)
        return Overlap::Outside;
    if (lo.x >= regionMin.x && lo.y >= regionMin.y && hi.x <= regionMax.x && hi.y <= regionMax.y &&
        footprint.farthest <= region.maxDepth)
        return Overlap::Inside;
    return Overlap::Partial;
}

Overlap casterReaches(const ReceiverRegion& region, const glm::mat4& lightViewProjection, const Aabb& box) {
    if (region.empty) return Overlap::Outside;
    return casterReaches(region, lightFootprint(lightViewProjection, box));
}

}  // namespace runtime
