// SceneCache: see SceneCache.h.
#include "SceneCache.h"

#include <private/runtime/FramePlan.h>

#include <bit>
#include <cstring>

namespace runtime {

namespace {

// Four independent lanes of (lane ^ word) * odd, rotated: each step is a bijection of the lane for a
// given word and of the word for a given lane, so any one changed word changes the stamp, and the lanes
// do not wait for each other. Chained hashCombine calls cost 10,000 objects about half a millisecond a
// frame, most of a batched frame's own CPU time.
class StampHasher {
public:
    void add(uint64_t word) {
        uint64_t& lane = mLanes[mNext++ & 3];
        lane = std::rotl((lane ^ word) * 0x9E3779B97F4A7C15ull, 29);
    }
    void addBytes(const void* data, size_t size) {
        const auto* bytes = static_cast<const uint8_t*>(data);
        size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            uint64_t word;
            std::memcpy(&word, bytes + i, 8);
            add(word);
        }
        uint64_t tail = size;
        for (; i < size; ++i) tail = (tail << 8) | bytes[i];
        add(tail);
    }
    uint64_t finish() const {
        uint64_t h = hashCombine(0, mNext);
        for (uint64_t lane : mLanes) h = hashCombine(h, lane);
        return h;
    }

private:
    uint64_t mLanes[4] = {0x243F6A8885A308D3ull, 0x13198A2E03707344ull, 0xA4093822299F31D0ull,
                          0x082EFA98EC4E6C89ull};
    uint64_t mNext = 0;
};

// A stamp of everything about the scene's objects a draw depends on (mesh, transform, colour, id, flags)
// and of its explicit bounds. Hashed every frame rather than kept as a revision counter that every
// editor of a Scene would have to bump: 10,000 objects are about 1 MB of hashing, a tenth of a
// millisecond.
uint64_t sceneStamp(const Scene& scene) {
    StampHasher h;
    h.add(scene.objects.size());
    for (const SceneObject& object : scene.objects) {
        h.add(reinterpret_cast<uintptr_t>(object.mesh.get()));
        if (object.mesh) h.add(object.mesh->indices.size() ^ (object.mesh->positions.size() << 32));
        h.addBytes(&object.world, sizeof(object.world));
        h.addBytes(&object.color, sizeof(object.color));
        h.add((uint64_t(object.id) << 2) | (object.castsShadow ? 1u : 0u) |
              (object.receivesShadow ? 2u : 0u));
    }
    if (scene.explicitBounds) h.addBytes(&*scene.explicitBounds, sizeof(Bounds));
    return h.finish();
}

}  // namespace

void SceneCache::update(const Scene& scene) {
    const uint64_t stamp = sceneStamp(scene);
    if (mValid && mStamp == stamp) return;
    mStamp = stamp;
    mValid = true;
    mBounds = scene.bounds();
    mMeshBoxes.clear();
    std::vector<Aabb> boxes(scene.objects.size());
    std::vector<bool> present(scene.objects.size(), false);
    std::map<const Mesh*, uint32_t> slots;
    mMeshSlots.assign(scene.objects.size(), 0);
    mDrawable.clear();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.mesh) {
            mMeshSlots[i] =
                slots.emplace(object.mesh.get(), static_cast<uint32_t>(slots.size())).first->second;
            mDrawable.push_back(static_cast<uint32_t>(i));
        }
        if (!object.mesh || object.mesh->positions.empty()) continue;
        auto it = mMeshBoxes.find(object.mesh.get());
        if (it == mMeshBoxes.end())
            it = mMeshBoxes
                     .emplace(object.mesh.get(), Aabb{object.mesh->boundsMin(), object.mesh->boundsMax()})
                     .first;
        boxes[i] = transformBox(it->second, object.world);
        present[i] = true;
    }
    mMeshCount = slots.size();
    mBvh = InstanceBvh(std::move(boxes), present);
}

}  // namespace runtime
