// IntersectionBody: the part of the scene a camera sees, B = view frustum ∩ scene bounds (Scherzer §4.1),
// and the culling tests built on it:
// - a camera pass draws an object only if its box meets the view frustum;
// - a light pass draws a caster only if its box, extruded away from the light, meets B: a shadow can
//   only fall on a receiver the camera sees if the caster lies between that receiver and the light.
// The light test works in the light's normalized device coordinates, where "away from the light" is
// +z at fixed x, y for directional (orthographic) and spot (perspective) lights alike. B enters as the
// light-space box of its vertices (a conservative superset of B), widened by a few shadow-map texels so
// that filter kernels (PCF, jitter) around a receiver's texel still read the same values.
#pragma once

#include <runtime/InstanceBvh.h>

#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace runtime {

// A convex volume as inward-facing planes (n · p + d >= 0 inside).
struct ConvexVolume {
    std::array<glm::vec4, 6> planes;  // a frustum's: held in place, so that culling allocates nothing
};

// The six planes of a D3D clip volume (-w <= x, y <= w, 0 <= z <= w) of `viewProjection` (glm form).
ConvexVolume frustumPlanes(const glm::mat4& viewProjection);

// Does `box` meet the volume? Conservative: Outside only if a plane separates it with a margin.
Overlap overlapVolume(const ConvexVolume& volume, const Aabb& box);

// The vertices of B = frustum(viewProjection) ∩ bounds: corners of each inside the other and the points
// where the edges of one cross the faces of the other. Empty when they do not meet.
std::vector<glm::vec3> intersectionBodyPoints(const glm::mat4& viewProjection, const Bounds& bounds);
// The same into `points` (emptied first, its storage kept: a caller planning every frame reuses it).
void intersectionBodyPoints(const glm::mat4& viewProjection, const Bounds& bounds,
                            std::vector<glm::vec3>& points);

// Where in a light's NDC (its view-projection's clip volume) the receivers of B read the shadow map.
struct ReceiverRegion {
    glm::vec2 min{-1.0f};
    glm::vec2 max{1.0f};
    float maxDepth = 1.0f;  // the farthest receiver's NDC depth; casters wholly beyond cast on nothing seen
    bool empty = false;     // B is empty: no caster matters
    bool full = true;       // the whole light frustum (nothing culled but what lies outside it)
    // A caster wholly at clip w <= 0 (behind a spot light, behind LiSPSM's warp centre) cannot shadow a
    // receiver: set where the light's fit says so (LightFit::shinesIntoPositiveW).
    bool castersBehindLightPlaneCastNothing = false;

    // True if every receiver `other` serves is served by this region too.
    bool contains(const ReceiverRegion& other) const;
};

// The region of `points` (B) in the light's NDC, clamped to the light frustum (receivers outside it read
// the clamped edge texels) and widened by `padTexels` texels of a `mapSize` map.
ReceiverRegion receiverRegion(const std::vector<glm::vec3>& points, const glm::mat4& lightViewProjection,
                              glm::vec2 mapSize, float padTexels);
// The whole light frustum: what a map must cover to serve any viewpoint.
ReceiverRegion fullLightRegion();

// Can a caster in `box`, extruded away from the light, meet the region? Conservative.
Overlap casterReaches(const ReceiverRegion& region, const glm::mat4& lightViewProjection, const Aabb& box);

// What casterReaches reads of a box: its corners' extent in the light's NDC. Apart from the region, so
// that a cull under a light that stands keeps it while the receivers move (CasterFootprints.h).
struct LightFootprint {
    glm::vec2 lo{0.0f};  // NDC x, y of the corners: set only where no corner is behind
    glm::vec2 hi{0.0f};
    float nearest = 0.0f;  // NDC depth of the corners: likewise
    float farthest = 0.0f;
    int behind = 0;  // corners at clip w <= 0: behind the light's plane
};
LightFootprint lightFootprint(const glm::mat4& lightViewProjection, const Aabb& box);
// casterReaches for the box whose footprint this is: the same comparisons, the same answer.
Overlap casterReaches(const ReceiverRegion& region, const LightFootprint& footprint);

}  // namespace runtime
