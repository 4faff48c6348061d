// PerspectiveShadowCubeMap: the PSMCube fit (see the header; Kozlov 2004 §14.2.2).
// Computed in double precision, like PerspectiveShadowMap.cpp:
// near λ = 0 the cube coordinates of the receivers differ by a small fraction of their size.
#include <runtime/PerspectiveShadowCubeMap.h>
#include <runtime/PerspectiveShadowMap.h>

#include "LightSpaceMath.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace runtime {

namespace {

// A face's matrices that no draw survives: every vertex at clip (2, 0, 0, 1), outside x <= w.
LightView unusedFace() {
    LightView face;
    face.projection = glm::mat4(0.0f);
    face.projection[3][0] = 2.0f;
    face.projection[3][3] = 1.0f;
    face.serves = false;
    return face;
}

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull of `points` (Andrew's monotone chain), counter-clockwise, as indices.
std::vector<size_t> convexHull(const std::vector<glm::dvec2>& points) {
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
    });
    if (order.size() < 3) return order;
    std::vector<size_t> hull(2 * order.size());
    size_t k = 0;
    for (size_t i : order) {
        while (k >= 2 && cross2(points[hull[k - 2]], points[hull[k - 1]], points[i]) <= 0.0) --k;
        hull[k++] = i;
    }
    for (size_t j = order.size() - 1, lower = k + 1; j-- > 0;) {
        const size_t i = order[j];
        while (k >= lower && cross2(points[hull[k - 2]], points[hull[k - 1]], points[i]) <= 0.0) --k;
        hull[k++] = i;
    }
    hull.resize(k - 1);
    return hull;
}

// Sutherland-Hodgman: the part of a convex polygon (cube coordinates W of its vertices, which are affine
// along the polygon's edges) where dot(plane, W) >= 0.
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3>& polygon, const glm::dvec3& plane) {
    std::vector<glm::dvec3> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = glm::dot(plane, a), db = glm::dot(plane, b);
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
    }
    return out;
}

glm::dmat4 fromRows(const glm::dvec4& x, const glm::dvec4& y, const glm::dvec4& z, const glm::dvec4& w) {
    glm::dmat4 m(0.0);  // glm: m[column][row]
    for (int c = 0; c < 4; ++c) {
        m[c][0] = x[c];
        m[c][1] = y[c];
        m[c][2] = z[c];
        m[c][3] = w[c];
    }
    return m;
}

}  // namespace

LightFit fitPerspectiveShadowCubeMap(const Scene& scene, const Bounds& sceneBounds, float aspect,
                                     const Light& light, const LightTunables& tunables,
                                     CubeMapDetails* details) {
    LightFit fallback;
    const std::optional<PsmFrame> frame = psmFrame(scene, sceneBounds, aspect, light, tunables, fallback);
    // The sub-views: always six, so that an effect's passes are static.
    LightFit fit = fallback;
    fit.cubeFaces = true;
    fit.cascades.assign(kCubeFaces, unusedFace());
    const auto fallBack = [&]() {
        // Every point selects face 4 (W = (0, 0, 1)), which holds the fallback fit.
        fit.faceSelect = glm::mat4(0.0f);
        fit.faceSelect[3][2] = 1.0f;
        fit.cascades[4] =
            LightView{fallback.view, fallback.projection, 0.0f, 0.0f, true, glm::vec4(0, 0, 1, 1)};
        if (details) {
            *details = CubeMapDetails{};
            details->used[4] = true;
            details->facesUsed = 1;
        }
        return fit;
    };
    if (!frame) return fallBack();

    // The cube coordinates W as rows on world points, moved into Focused's light view (a row on world
    // points times the inverse view), where their z coefficient (along the light) is 0 up to rounding:
    // set it so, W is constant along each light ray.
    const glm::dvec3 ell(frame->lightPostPerspective);
    const double lambda = frame->lightPostPerspective.w;
    const double k = std::max(std::abs(lambda), 1e-9 * glm::length(ell));
    const glm::dmat4 toWorld = glm::transpose(frame->postPerspective);  // a PPS row times C
    const glm::dmat4 view(frame->focused.view);
    const glm::dmat4 fromView = glm::transpose(glm::inverse(view));
    glm::dvec4 cube[3] = {
        fromView * (toWorld * glm::dvec4(k * frame->ex, -k * glm::dot(frame->ex, frame->centre))),
        fromView * (toWorld * glm::dvec4(k * frame->ey, -k * glm::dot(frame->ey, frame->centre))),
        fromView * (toWorld * glm::dvec4(lambda * frame->axis, -glm::dot(frame->axis, ell)))};
    double largest = 0.0;
    for (glm::dvec4& row : cube) {
        row.z = 0.0;
        largest = std::max(largest, glm::length(row));
    }
    if (!(largest > 0.0) || !std::isfinite(largest)) return fallBack();
    for (glm::dvec4& row : cube) row /= largest;  // the dominant axis does not depend on the scale
    const auto cubeOf = [&](const glm::dvec4& v) {
        return glm::dvec3(glm::dot(cube[0], v), glm::dot(cube[1], v), glm::dot(cube[2], v));
    };

    // The receivers' hull across the light (W depends on light-view x, y only), and the depth range of B
    // with its casters along the light (light-view z).
    std::vector<glm::dvec2> across;
    for (const glm::vec3& p : frame->receivers)
        across.emplace_back(glm::dvec2(view * glm::dvec4(glm::dvec3(p), 1.0)));
    double tLo = std::numeric_limits<double>::max(), tHi = std::numeric_limits<double>::lowest();
    for (const glm::vec3& p : frame->body) {
        const double t = (view * glm::dvec4(glm::dvec3(p), 1.0)).z;
        tLo = std::min(tLo, t);
        tHi = std::max(tHi, t);
    }
    std::vector<glm::dvec3> hull;
    for (size_t i : convexHull(across)) hull.push_back(cubeOf(glm::dvec4(across[i], 0.0, 1.0)));

    CubeMapDetails found;
    found.lightPostPerspective = frame->lightPostPerspective;
    found.fellBack = false;
    for (int face = 0; face < kCubeFaces; ++face) {
        // Face 2 i + s looks along (-1)^s axis i; its image coordinates are the other two axes.
        const int i = face / 2, p = (i + 1) % 3, q = (i + 2) % 3;
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        glm::dvec3 axis(0.0), across1(0.0), across2(0.0);
        axis[i] = sign;
        across1[p] = 1.0;
        across2[q] = 1.0;
        // The face's pyramid: w = sign W_i >= |W_p|, |W_q|.
        std::vector<glm::dvec3> part = hull;
        for (const glm::dvec3& plane : {axis - across1, axis + across1, axis - across2, axis + across2})
            part = clip(part, plane);
        if (part.empty()) continue;
        glm::dvec2 lo(1.0), hi(-1.0);
        double wMin = std::numeric_limits<double>::max(), wMax = 0.0;
        for (const glm::dvec3& w : part) {
            const double depth = glm::dot(axis, w);
            wMax = std::max(wMax, depth);
            wMin = std::min(wMin, depth);
            // At the apex (w -> 0) the image runs to the pyramid's edges.
            const glm::dvec2 image = depth > 1e-12 * glm::length(w)
                                         ? glm::dvec2(w[p], w[q]) / depth
                                         : glm::dvec2(w[p] < 0.0 ? -1.0 : 1.0, w[q] < 0.0 ? -1.0 : 1.0);
            lo = glm::min(lo, glm::clamp(image, -1.0, 1.0));
            hi = glm::max(hi, glm::clamp(image, -1.0, 1.0));
        }
        if (!(wMax > 0.0)) continue;
        wMin = std::max(wMin, 1e-4 * wMax);  // Kozlov's near plane z_1
        // Widened so that rounding keeps boundary receivers inside. Relative only: as λ -> 0 the receivers'
        // images in the front face shrink with k (to ~1e-9 at λ = 0) and the rows are rescaled to them. A
        // receiver polygon that only touches the face (no extent) keeps a window of 1e-6 of its position.
        const glm::dvec2 margin =
            glm::max(1e-3 * (hi - lo), 1e-6 * glm::max(glm::abs(lo), glm::abs(hi)) + 1e-300);
        lo -= margin;
        hi += margin;
        const glm::dvec2 centre = 0.5 * (lo + hi), scale = 2.0 / (hi - lo);
        // Rows on light-view points, scaled so that w is at most 1 on the receivers.
        const glm::dvec4 w = (sign * cube[i]) / wMax;
        const glm::dvec4 x = (cube[p] / wMax - centre.x * w) * scale.x;
        const glm::dvec4 y = (cube[q] / wMax - centre.y * w) * scale.y;
        // Depth: the light-view z over w, linear along each light ray (w is constant along it), fitted to
        // [0, 1] over t in [tLo, tHi] and w in [wMin, wMax] (w rescaled: [wMin / wMax, 1]).
        const double w0 = wMin / wMax;
        double zLo = std::min({tLo / w0, tLo}), zHi = std::max({tHi / w0, tHi});
        if (!(zHi > zLo)) continue;
        const double zMargin = 1e-3 * (zHi - zLo);
        zLo -= zMargin;
        zHi += zMargin;
        const glm::dvec4 z = (glm::dvec4(0.0, 0.0, 1.0, 0.0) - zLo * w) / (zHi - zLo);
        const LightView faceView{frame->focused.view, glm::mat4(fromRows(x, y, z, w)), 0.0f, 0.0f, true};
        if (!isFinite(faceView.projection)) continue;
        fit.cascades[static_cast<size_t>(face)] = faceView;
        found.used[static_cast<size_t>(face)] = true;
        ++found.facesUsed;
    }
    if (found.facesUsed == 0) return fallBack();
    // The used faces share the atlas: one face gets all of it (then it is the single-map PSM's texels), up
    // to three a column each, four a 2 x 2 grid, five or six a 3 x 2 grid.
    const glm::vec2 grid = found.facesUsed <= 3 ? glm::vec2(found.facesUsed, 1)
                                                : (found.facesUsed == 4 ? glm::vec2(2, 2) : glm::vec2(3, 2));
    int slot = 0;
    for (LightView& face : fit.cascades) {
        if (!face.serves) continue;
        const glm::vec2 cell(float(slot % int(grid.x)), float(slot / int(grid.x)));
        face.atlasRect = glm::vec4(cell / grid, 1.0f / grid);
        ++slot;
    }
    fit.faceSelect = glm::mat4(fromRows(cube[0], cube[1], cube[2], glm::dvec4(0.0, 0.0, 0.0, 1.0)) * view);
    if (!isFinite(fit.faceSelect)) return fallBack();
    if (details) *details = found;
    return fit;
}

int cubeFaceOf(const LightFit& fit, const glm::vec3& world) {
    const glm::vec3 w(fit.faceSelect * glm::vec4(world, 1.0f));
    const glm::vec3 a = glm::abs(w);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (w[axis] < 0.0f ? 1 : 0);
}

}  // namespace runtime
