// CasterFootprints: the footprints in one light's NDC (IntersectionBody.h, LightFootprint) of the nodes and
// objects of a scene's tree, computed the first time a cull reaches them and kept while the tree and the
// light's matrix stand. A light's cull tests each box it reaches against the receiver region, and the
// region follows the camera: under a light that stands, a moving camera culls every frame. Kept, the
// footprints leave that cull comparisons of numbers, where each test transformed a box's eight corners.
// The lists are the ones casterReaches gives: the same footprints, compared the same way.
#pragma once

#include <runtime/InstanceBvh.h>
#include <runtime/IntersectionBody.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace runtime {

class CasterFootprints {
public:
    // True if the footprints kept are those of the tree state `treeStamp` under `lightViewProjection`
    // (the same floats, bit for bit).
    bool holds(uint64_t treeStamp, const glm::mat4& lightViewProjection) const;
    // Keeps the footprints of `bvh`, whose state `treeStamp` names, under `lightViewProjection` from now on:
    // those kept before are forgotten. The storage stays, so a light that moves allocates nothing once
    // the tables have grown to the tree.
    void reset(const InstanceBvh& bvh, uint64_t treeStamp, const glm::mat4& lightViewProjection);
    // Appends to `out` (ascending) the objects of `bvh` (the tree given to reset) whose casters reach
    // `region`: the list `bvh.query` gives with casterReaches under the kept light's matrix.
    void query(const InstanceBvh& bvh, const ReceiverRegion& region, std::vector<uint32_t>& out);

private:
    // A box's footprint, computed where the current generation has none yet.
    const LightFootprint& footprint(std::vector<LightFootprint>& footprints,
                                    std::vector<uint32_t>& generations, uint32_t index, const Aabb& box);

    bool mValid = false;
    uint64_t mTreeStamp = 0;
    glm::mat4 mLightViewProjection{1.0f};
    // Footprints per node and per object, each valid where its generation is the current one: a reset
    // forgets them all by counting on, without writing the tables.
    uint32_t mGeneration = 0;
    std::vector<LightFootprint> mNodes;
    std::vector<uint32_t> mNodeGenerations;
    std::vector<LightFootprint> mObjects;
    std::vector<uint32_t> mObjectGenerations;
};

}  // namespace runtime
