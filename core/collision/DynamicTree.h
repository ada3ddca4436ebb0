// Dynamic AABB tree: a bounding volume hierarchy of fattened boxes, updated incrementally as proxies move.
// Insertion picks the sibling by the surface area heuristic and tree rotations keep the cost low (as Box2D does).
#pragma once

#include "collision/Aabb.h"
#include "math/Types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rl {

struct DynamicTreeSettings {
    // Added on every side of the tight box. A body that jitters by less than this never touches the tree.
    Real margin = 0.1;
    // The fat box is also stretched along the predicted displacement times this factor, so a body moving
    // steadily is reinserted every few steps rather than every step.
    Real displacementMultiplier = 2.0;
};

namespace detail {

// Traversal stack: a fixed inline buffer that spills to the heap only for pathological trees. Each node is pushed
// at most once per traversal, so a traversal is bounded by the node count.
class NodeStack {
public:
    void push(int32_t node) {
        if (m_size < static_cast<int32_t>(m_inline.size()))
            m_inline[m_size] = node;
        else
            m_spill.push_back(node);
        ++m_size;
    }
    int32_t pop() {
        --m_size;
        if (m_size < static_cast<int32_t>(m_inline.size()))
            return m_inline[m_size];
        const int32_t v = m_spill.back();
        m_spill.pop_back();
        return v;
    }
    bool empty() const { return m_size == 0; }

private:
    std::array<int32_t, 128> m_inline; // left uninitialised: it is written before it is read
    std::vector<int32_t> m_spill;
    int32_t m_size = 0;
};

} // namespace detail

class DynamicTree {
public:
    static constexpr int32_t kNullNode = -1;

    explicit DynamicTree(const DynamicTreeSettings& settings = {});

    // The tight box must be valid (Aabb::isValid); BroadPhase checks that for callers. Returns the proxy id,
    // which stays valid until destroyProxy. Ids of destroyed proxies are reused.
    int32_t createProxy(const Aabb& tightBox, uint32_t userId);
    void destroyProxy(int32_t proxyId);

    // Returns true when the proxy was reinserted with a new fat box (its tight box left the old one, or the old one
    // had become much too large). Returns false, and changes nothing, otherwise.
    bool moveProxy(int32_t proxyId, const Aabb& tightBox, const Vec3& displacement);
    // moveProxy() in two halves: fatBoxIfMoved() only reads the proxy's own node, so many proxies can be tested at
    // once while nothing reinserts; it returns the fat box to reinsert with, or nothing when the old box still
    // serves. reinsertProxy() then changes the tree. moveProxy() is the one followed by the other.
    std::optional<Aabb> fatBoxIfMoved(int32_t proxyId, const Aabb& tightBox, const Vec3& displacement) const;
    void reinsertProxy(int32_t proxyId, const Aabb& fatBox);

    const Aabb& fatAabb(int32_t proxyId) const { return m_nodes[proxyId].box; }
    uint32_t userId(int32_t proxyId) const { return m_nodes[proxyId].userId; }
    bool isProxy(int32_t proxyId) const {
        return proxyId >= 0 && proxyId < static_cast<int32_t>(m_nodes.size()) && m_nodes[proxyId].height == 0;
    }

    // Calls callback(proxyId) for every proxy whose fat box overlaps box; the callback returns false to stop.
    template <class Callback>
    void query(const Aabb& box, Callback&& callback) const;

    // Casts the segment origin + t * direction, t in [0, maxFraction], nearer subtrees first. For each proxy whose
    // fat box the segment reaches, callback(proxyId, currentMaxFraction) returns: a negative value to ignore the
    // proxy, 0 to stop, or a fraction that clips the segment (returning currentMaxFraction just continues).
    template <class Callback>
    void rayCast(const Vec3& origin, const Vec3& direction, Real maxFraction, Callback&& callback) const;

    // Calls callback(proxyId) for every proxy, in node order (deterministic for a given history of calls).
    template <class Callback>
    void forEachProxy(Callback&& callback) const;

    int32_t proxyCount() const { return m_proxyCount; }
    int32_t height() const { return m_root == kNullNode ? 0 : m_nodes[m_root].height; }
    int32_t nodeCount() const { return m_nodeCount; }
    // Sum of internal node areas over the root area: the SAH cost of the tree, lower is better.
    Real areaRatio() const;
    const DynamicTreeSettings& settings() const { return m_settings; }

    void clear();

    // Checks parents, child links, heights, that every internal box contains its children's boxes, proxy and free
    // counts. For tests; walks the whole tree. On failure, describes the first problem found.
    bool validate(std::string* problem = nullptr) const;

private:
    // One cache line per node: traversals are bound by memory, not arithmetic. A leaf has no children, so its
    // second child slot holds the user id.
    struct alignas(64) Node {
        Aabb box;
        int32_t parent = kNullNode; // next free node while on the free list
        int32_t child1 = kNullNode;
        union {
            int32_t child2 = kNullNode;
            uint32_t userId; // leaves only
        };
        int32_t height = -1; // 0 leaf, -1 free

        bool isLeaf() const { return height == 0; }
    };

    int32_t allocateNode();
    void freeNode(int32_t node);
    void insertLeaf(int32_t leaf);
    void removeLeaf(int32_t leaf);
    int32_t findBestSibling(const Aabb& box) const;
    void refitUpwards(int32_t node);
    void shrinkUpwards(int32_t node);
    void rotate(int32_t node);
    void swapChildWithGrandchild(int32_t parent, int32_t child, int32_t other, int32_t grandchild);
    void swapGrandchildren(int32_t parent, int32_t grandchildOfFirst, int32_t grandchildOfSecond);
    void refitNode(int32_t node);
    Vec3 predictedStretch(const Vec3& displacement) const;

    DynamicTreeSettings m_settings;
    std::vector<Node> m_nodes;
    int32_t m_root = kNullNode;
    int32_t m_freeList = kNullNode;
    int32_t m_nodeCount = 0;
    int32_t m_proxyCount = 0;
};

template <class Callback>
void DynamicTree::query(const Aabb& box, Callback&& callback) const {
    if (m_root == kNullNode)
        return;
    detail::NodeStack stack;
    stack.push(m_root);
    while (!stack.empty()) {
        const int32_t index = stack.pop();
        const Node& node = m_nodes[index];
        if (!node.box.overlaps(box))
            continue;
        if (node.isLeaf()) {
            if (!callback(index))
                return;
        } else {
            stack.push(node.child1);
            stack.push(node.child2);
        }
    }
}

template <class Callback>
void DynamicTree::rayCast(const Vec3& origin, const Vec3& direction, Real maxFraction, Callback&& callback) const {
    if (m_root == kNullNode || !(maxFraction > 0.0))
        return;
    detail::NodeStack stack;
    stack.push(m_root);
    while (!stack.empty()) {
        const int32_t index = stack.pop();
        const Node& node = m_nodes[index];
        Real enter = 0.0;
        // Re-tested on pop because maxFraction may have been clipped since the node was pushed.
        if (!raySlab(node.box, origin, direction, maxFraction, enter))
            continue;
        if (node.isLeaf()) {
            const Real value = callback(index, maxFraction);
            if (value == 0.0)
                return;
            if (value > 0.0 && value < maxFraction)
                maxFraction = value;
            continue;
        }
        Real enter1 = 0.0;
        Real enter2 = 0.0;
        const bool hit1 = raySlab(m_nodes[node.child1].box, origin, direction, maxFraction, enter1);
        const bool hit2 = raySlab(m_nodes[node.child2].box, origin, direction, maxFraction, enter2);
        // Push the farther child first so the nearer one is visited first and clips the segment early.
        if (hit1 && hit2) {
            if (enter1 <= enter2) {
                stack.push(node.child2);
                stack.push(node.child1);
            } else {
                stack.push(node.child1);
                stack.push(node.child2);
            }
        } else if (hit1) {
            stack.push(node.child1);
        } else if (hit2) {
            stack.push(node.child2);
        }
    }
}

template <class Callback>
void DynamicTree::forEachProxy(Callback&& callback) const {
    const int32_t n = static_cast<int32_t>(m_nodes.size());
    for (int32_t i = 0; i < n; ++i) {
        if (m_nodes[i].isLeaf())
            callback(i);
    }
}

} // namespace rl
