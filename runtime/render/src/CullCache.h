// CullCache: the objects each culling volume of the recent frames kept, so that culling costs what the
// scene's change costs. A draw culls against the camera's frustum or a light's receiver region
// (FrameExecutor::cull); while the scene's objects (the scene cache's stamp), the volume's view-projection
// and its region stand still, the list is the same and is not traversed again, and passes of one frame that
// cull against the same volume share one traversal. A light's volume whose region moved is culled again, from
// the footprints of the tree kept for its matrix (CasterFootprints).
#pragma once

#include <runtime/CasterFootprints.h>
#include <runtime/IntersectionBody.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace runtime {

class CullCache {
public:
    // What a culling volume is: the scene it culls, its view-projection, whether it is a light's (then
    // `region` is the receiver region its casters must reach).
    struct Volume {
        uint64_t sceneStamp = 0;
        glm::mat4 viewProjection{1.0f};
        bool lightPort = false;
        ReceiverRegion region;
    };

    // The kept list of `volume`, or null where none is kept.
    const std::vector<uint32_t>* find(const Volume& volume);
    // A list to fill for `volume` (emptied), taking the place of the least recently used one: its storage
    // is reused, so a moving camera allocates nothing once the lists have grown.
    std::vector<uint32_t>& insert(const Volume& volume);
    // Gives every list room for `objects` (the scene's object count): a list then never grows, and a
    // volume first culled frames after the first allocates nothing either.
    void reserve(size_t objects);
    // The footprints of `bvh` (the scene of `sceneStamp`) under a light's matrix: those kept for it, or
    // the least recently used light's reset for it.
    CasterFootprints& footprints(const InstanceBvh& bvh, uint64_t sceneStamp,
                                 const glm::mat4& lightViewProjection);

private:
    // A frame culls against a few volumes (the camera, each light or cascade it renders).
    static constexpr size_t kEntries = 8;
    struct Entry {
        bool valid = false;
        Volume volume;
        uint64_t lastUse = 0;
        std::vector<uint32_t> visible;
    };
    static bool same(const Volume& a, const Volume& b);

    std::array<Entry, kEntries> mEntries;
    // A frame culls against a light or a few (a cascade's maps).
    static constexpr size_t kLights = 4;
    struct Light {
        uint64_t lastUse = 0;
        CasterFootprints footprints;
    };
    std::array<Light, kLights> mLights;
    uint64_t mClock = 0;
};

}  // namespace runtime
