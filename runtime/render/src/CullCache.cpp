// CullCache: see CullCache.h.
#include "CullCache.h"

#include <cstring>

namespace runtime {

// Bitwise equality of the matrices and regions: the same camera gives the same floats frame after frame.
bool CullCache::same(const Volume& a, const Volume& b) {
    if (a.sceneStamp != b.sceneStamp || a.lightPort != b.lightPort ||
        std::memcmp(&a.viewProjection, &b.viewProjection, sizeof(glm::mat4)) != 0)
        return false;
    if (!a.lightPort) return true;
    const ReceiverRegion& r = a.region;
    const ReceiverRegion& s = b.region;
    return std::memcmp(&r.min, &s.min, sizeof(r.min)) == 0 &&
           std::memcmp(&r.max, &s.max, sizeof(r.max)) == 0 &&
           std::memcmp(&r.maxDepth, &s.maxDepth, sizeof(float)) == 0 && r.empty == s.empty &&
           r.full == s.full && r.castersBehindLightPlaneCastNothing == s.castersBehindLightPlaneCastNothing;
}

const std::vector<uint32_t>* CullCache::find(const Volume& volume) {
    for (Entry& entry : mEntries) {
        if (entry.valid && same(entry.volume, volume)) {
            entry.lastUse = ++mClock;
            return &entry.visible;
        }
    }
    return nullptr;
}

std::vector<uint32_t>& CullCache::insert(const Volume& volume) {
    Entry* oldest = &mEntries.front();
    for (Entry& entry : mEntries)
        if (!entry.valid || (oldest->valid && entry.lastUse < oldest->lastUse)) oldest = &entry;
    oldest->valid = true;
    oldest->volume = volume;
    oldest->lastUse = ++mClock;
    oldest->visible.clear();
    return oldest->visible;
}

void CullCache::reserve(size_t objects) {
    for (Entry& entry : mEntries) entry.visible.reserve(objects);
}

CasterFootprints& CullCache::footprints(const InstanceBvh& bvh, uint64_t sceneStamp,
                                        const glm::mat4& lightViewProjection) {
    Light* oldest = &mLights.front();
    for (Light& light : mLights) {
        if (light.footprints.holds(sceneStamp, lightViewProjection)) {
            light.lastUse = ++mClock;
            return light.footprints;
        }
        if (light.lastUse < oldest->lastUse) oldest = &light;
    }
    oldest->lastUse = ++mClock;
    oldest->footprints.reset(bvh, sceneStamp, lightViewProjection);
    return oldest->footprints;
}

}  // namespace runtime
