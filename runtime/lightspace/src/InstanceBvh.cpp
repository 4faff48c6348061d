#include <runtime/InstanceBvh.h>

#include <algorithm>
#include <limits>

namespace runtime {

namespace {

constexpr uint32_t kLeafSize = 4;

Aabb emptyBox() {
    return {glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest())};
}

void grow(Aabb& box, const Aabb& other) {
    box.min = glm::min(box.min, other.min);
    box.max = glm::max(box.max, other.max);
}

}  // namespace

Aabb transformBox(const Aabb& local, const glm::mat4& world) {
    Aabb box = emptyBox();
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z);
        const glm::vec3 w = glm::vec3(world * glm::vec4(p, 1.0f));
        box.min = glm::min(box.min, w);
        box.max = glm::max(box.max, w);
    }
    return box;
}

InstanceBvh::InstanceBvh(std::vector<Aabb> boxes, const std::vector<bool>& present)
    : mBoxes(std::move(boxes)) {
    for (uint32_t i = 0; i < mBoxes.size(); ++i)
        if (i < present.size() && present[i]) mOrder.push_back(i);
    if (mOrder.empty()) return;
    mNodes.emplace_back();
    build(0, 0, static_cast<uint32_t>(mOrder.size()));
}

// Fills node `index` with mOrder[begin, end): a leaf, or two adjacent children split at the median.
void InstanceBvh::build(uint32_t index, uint32_t begin, uint32_t end) {
    Aabb box = emptyBox();
    Aabb centres = emptyBox();
    for (uint32_t i = begin; i < end; ++i) {
        const Aabb& b = mBoxes[mOrder[i]];
        grow(box, b);
        const glm::vec3 c = (b.min + b.max) * 0.5f;
        grow(centres, Aabb{c, c});
    }
    mNodes[index].box = box;
    if (end - begin <= kLeafSize) {
        mNodes[index].first = begin;
        mNodes[index].count = end - begin;
        return;
    }
    const glm::vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(mOrder.begin() + begin, mOrder.begin() + middle, mOrder.begin() + end,
                     [this, axis](uint32_t a, uint32_t b) {
                         return mBoxes[a].min[axis] + mBoxes[a].max[axis] <
                                mBoxes[b].min[axis] + mBoxes[b].max[axis];
                     });
    const uint32_t left = static_cast<uint32_t>(mNodes.size());
    mNodes[index].first = left;
    mNodes[index].count = 0;
    mNodes.emplace_back();
    mNodes.emplace_back();
    build(left, begin, middle);
    build(left + 1, middle, end);
}

void InstanceBvh::ascend(std::vector<uint32_t>& out, size_t start) const {
    const size_t found = out.size() - start;
    const size_t words = (mBoxes.size() + 63) / 64;
    // A camera's frustum over a large scene finds thousands of objects: marked in a bit set and read back
    // in order, one pass over the scene's words, where sorting them was 4 % of the runtime's own samples
    // on a 10,000-object forest. A few objects are sorted.
    if (found < 2 * words) {
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(start), out.end());
        return;
    }
    thread_local std::vector<uint64_t> marks;  // kept between queries: a frame's culls allocate nothing
    marks.assign(words, 0);
    for (size_t i = start; i < out.size(); ++i) marks[out[i] / 64] |= uint64_t(1) << (out[i] % 64);
    out.resize(start);
    for (size_t word = 0; word < words; ++word)
        for (uint64_t bits = marks[word]; bits != 0; bits &= bits - 1)
            out.push_back(static_cast<uint32_t>(word * 64 + static_cast<size_t>(__builtin_ctzll(bits))));
}

void InstanceBvh::collect(uint32_t index, std::vector<uint32_t>& out) const {
    const Node& node = mNodes[index];
    if (node.count == 0) {
        collect(node.first, out);
        collect(node.first + 1, out);
        return;
    }
    out.insert(out.end(), mOrder.begin() + node.first, mOrder.begin() + node.first + node.count);
}

}  // namespace runtime
