// SceneCache: what a frame derives from the scene's objects alone (their bounds, a pass over every
// vertex; the BVH over their boxes; each object's mesh slot), kept while the scene stands still. A stamp of
// the objects is hashed every frame and the rest rebuilt only when it changes, so that everything read
// here always describes the scene the stamp was taken of.
#pragma once

#include <runtime/InstanceBvh.h>
#include <runtime/Scene.h>

#include <cstdint>
#include <map>
#include <vector>

namespace runtime {

class SceneCache {
public:
    // Takes `scene`'s stamp; rebuilds the bounds, the BVH and the mesh slots if it differs from the last.
    void update(const Scene& scene);

    // False before the first update().
    bool valid() const { return mValid; }
    // A stamp of everything about the objects a draw depends on (mesh, transform, colour, id, flags) and of
    // the scene's explicit bounds: equal stamps, equal objects.
    uint64_t stamp() const { return mStamp; }
    const Bounds& bounds() const { return mBounds; }
    const InstanceBvh& bvh() const { return mBvh; }
    // Per object: its mesh's index among the scene's distinct meshes (batching groups by it).
    const std::vector<uint32_t>& meshSlots() const { return mMeshSlots; }
    size_t meshCount() const { return mMeshCount; }
    // The objects with a mesh, in the scene's order: what a Draw=Geometry draws before culling, listed once
    // per scene state so that a culled pass does not walk every object.
    const std::vector<uint32_t>& drawable() const { return mDrawable; }

private:
    uint64_t mStamp = 0;
    bool mValid = false;
    Bounds mBounds;
    InstanceBvh mBvh;
    std::map<const Mesh*, Aabb> mMeshBoxes;
    std::vector<uint32_t> mMeshSlots;
    size_t mMeshCount = 0;
    std::vector<uint32_t> mDrawable;
};

}  // namespace runtime
