// CasterFootprints: see the header.
#include <runtime/CasterFootprints.h>

#include <algorithm>
#include <cstring>

namespace runtime {

bool CasterFootprints::holds(uint64_t treeStamp, const glm::mat4& lightViewProjection) const {
    return mValid && mTreeStamp == treeStamp &&
           std::memcmp(&mLightViewProjection, &lightViewProjection, sizeof(glm::mat4)) == 0;
}

void CasterFootprints::reset(const InstanceBvh& bvh, uint64_t treeStamp,
                             const glm::mat4& lightViewProjection) {
    mValid = true;
    mTreeStamp = treeStamp;
    mLightViewProjection = lightViewProjection;
    if (++mGeneration == 0) {  // wrapped: generation 0 would match tables written 2^32 resets ago
        std::fill(mNodeGenerations.begin(), mNodeGenerations.end(), 0u);
        std::fill(mObjectGenerations.begin(), mObjectGenerations.end(), 0u);
        mGeneration = 1;
    }
    if (mNodes.size() != bvh.nodeCount()) {
        mNodes.resize(bvh.nodeCount());
        mNodeGenerations.assign(bvh.nodeCount(), 0u);
    }
    if (mObjects.size() != bvh.objectCount()) {
        mObjects.resize(bvh.objectCount());
        mObjectGenerations.assign(bvh.objectCount(), 0u);
    }
}

const LightFootprint& CasterFootprints::footprint(std::vector<LightFootprint>& footprints,
                                                  std::vector<uint32_t>& generations, uint32_t index,
                                                  const Aabb& box) {
    if (generations[index] != mGeneration) {
        footprints[index] = lightFootprint(mLightViewProjection, box);
        generations[index] = mGeneration;
    }
    return footprints[index];
}

void CasterFootprints::query(const InstanceBvh& bvh, const ReceiverRegion& region,
                             std::vector<uint32_t>& out) {
    // casterReaches rejects everything for an empty region before it transforms anything.
    if (region.empty) return;
    bvh.query(
        [&](uint32_t node, const Aabb& box) {
            return casterReaches(region, footprint(mNodes, mNodeGenerations, node, box));
        },
        [&](uint32_t object, const Aabb& box) {
            return casterReaches(region, footprint(mObjects, mObjectGenerations, object, box));
        },
        out);
}

}  // namespace runtime
