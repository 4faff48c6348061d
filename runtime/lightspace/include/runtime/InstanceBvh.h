// InstanceBvh: a bounding-volume hierarchy over the world-space boxes of a scene's objects, so that a pass
// finds the objects it must draw without testing all of them (Scherzer 2005's forest: 10,000 trees).
//
// Built once per scene state (EffectRenderer rebuilds it when the scene's stamp changes); median split on
// the longest axis of the boxes' centres, up to four objects per leaf. Queries take a conservative box
// test and return object indices in ascending order, so culled draws keep the scene's draw order.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace runtime {

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// What a query's test says about a box: nothing in it counts, all of it counts (children are not tested
// again), or look closer.
enum class Overlap { Outside, Partial, Inside };

class InstanceBvh {
public:
    InstanceBvh() = default;
    // One box per object, indexed like Scene::objects; `present[i]` false leaves object i out (no mesh).
    InstanceBvh(std::vector<Aabb> boxes, const std::vector<bool>& present);

    // Appends to `out` (ascending) every present object whose box `test` does not reject.
    template <class Test>
    void query(const Test& test, std::vector<uint32_t>& out) const;
    // The same, with the tests given what they test by index: `nodeTest(node, box)` with the node's index
    // (below nodeCount()), `objectTest(object, box)` with the object's. A caller keeping what it derived
    // from each box (CasterFootprints) finds it there.
    template <class NodeTest, class ObjectTest>
    void query(const NodeTest& nodeTest, const ObjectTest& objectTest, std::vector<uint32_t>& out) const;

    size_t nodeCount() const { return mNodes.size(); }
    size_t objectCount() const { return mBoxes.size(); }  // present or not
    const Aabb& box(size_t object) const { return mBoxes[object]; }
    bool empty() const { return mNodes.empty(); }
    const Aabb& rootBox() const { return mNodes.front().box; }  // not when empty()

private:
    struct Node {
        Aabb box;
        uint32_t first = 0;  // leaf: first entry in mOrder; inner: index of the left child
        uint32_t count = 0;  // leaf: number of objects; 0 for an inner node (right child = left + 1)
    };
    void build(uint32_t index, uint32_t begin, uint32_t end);
    void collect(uint32_t node, std::vector<uint32_t>& out) const;
    // Puts out[start, end) (distinct object indices) in ascending order.
    void ascend(std::vector<uint32_t>& out, size_t start) const;

    std::vector<Aabb> mBoxes;
    std::vector<uint32_t> mOrder;  // object indices, grouped by leaf
    std::vector<Node> mNodes;
};

template <class Test>
void InstanceBvh::query(const Test& test, std::vector<uint32_t>& out) const {
    const auto byBox = [&test](uint32_t, const Aabb& box) { return test(box); };
    query(byBox, byBox, out);
}

template <class NodeTest, class ObjectTest>
void InstanceBvh::query(const NodeTest& nodeTest, const ObjectTest& objectTest,
                        std::vector<uint32_t>& out) const {
    if (mNodes.empty()) return;
    const size_t start = out.size();
    uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const uint32_t index = stack[--top];
        const Node& node = mNodes[index];
        const Overlap overlap = nodeTest(index, node.box);
        if (overlap == Overlap::Outside) continue;
        if (overlap == Overlap::Inside) {
            collect(index, out);
            continue;
        }
        if (node.count == 0) {
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
            continue;
        }
        for (uint32_t i = node.first; i < node.first + node.count; ++i)
            if (objectTest(mOrder[i], mBoxes[mOrder[i]]) != Overlap::Outside) out.push_back(mOrder[i]);
    }
    ascend(out, start);
}

// The world box of a local box under a transform (its eight corners transformed): conservative.
Aabb transformBox(const Aabb& local, const glm::mat4& world);

}  // namespace runtime
