#include "collision/DynamicTree.h"

#include <cassert>

namespace rl {

DynamicTree::DynamicTree(const DynamicTreeSettings& settings) : m_settings(settings) {}

void DynamicTree::clear() {
    m_nodes.clear();
    m_root = kNullNode;
    m_freeList = kNullNode;
    m_nodeCount = 0;
    m_proxyCount = 0;
}

int32_t DynamicTree::allocateNode() {
    int32_t index;
    if (m_freeList != kNullNode) {
        index = m_freeList;
        m_freeList = m_nodes[index].parent;
    } else {
        index = static_cast<int32_t>(m_nodes.size());
        m_nodes.emplace_back();
    }
    m_nodes[index] = Node{};
    m_nodes[index].height = 0;
    ++m_nodeCount;
    return index;
}

void DynamicTree::freeNode(int32_t node) {
    m_nodes[node].height = -1;
    m_nodes[node].child1 = kNullNode;
    m_nodes[node].child2 = kNullNode;
    m_nodes[node].parent = m_freeList;
    m_freeList = node;
    --m_nodeCount;
}

Vec3 DynamicTree::predictedStretch(const Vec3& displacement) const {
    const Vec3 d = m_settings.displacementMultiplier * displacement;
    // A non-finite prediction must not poison the tree; fall back to the margin alone.
    if (std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))
        return d;
    return Vec3(0.0);
}

int32_t DynamicTree::createProxy(const Aabb& tightBox, uint32_t userId) {
    assert(tightBox.isValid());
    const int32_t proxy = allocateNode();
    m_nodes[proxy].box = tightBox.fattened(m_settings.margin);
    m_nodes[proxy].userId = userId;
    insertLeaf(proxy);
    ++m_proxyCount;
    return proxy;
}

void DynamicTree::destroyProxy(int32_t proxyId) {
    assert(isProxy(proxyId));
    removeLeaf(proxyId);
    freeNode(proxyId);
    --m_proxyCount;
}

bool DynamicTree::moveProxy(int32_t proxyId, const Aabb& tightBox, const Vec3& displacement) {
    const std::optional<Aabb> fat = fatBoxIfMoved(proxyId, tightBox, displacement);
    if (!fat)
        return false;
    reinsertProxy(proxyId, *fat);
    return true;
}

std::optional<Aabb> DynamicTree::fatBoxIfMoved(int32_t proxyId, const Aabb& tightBox, const Vec3& displacement) const {
    assert(isProxy(proxyId) && tightBox.isValid());
    const Node& node = m_nodes[proxyId];
    const Vec3 stretch = predictedStretch(displacement);
    const Aabb fat = tightBox.fattened(m_settings.margin).extendedBy(stretch);
    // Keep the old box while it still holds the body, unless it is much larger than what the body needs now
    // (a fast body that stopped): an oversized box would report pairs that are far apart. The allowance also
    // reaches back along the motion, because a steadily moving body's old box trails it by up to one stretch.
    const Aabb largest = fat.fattened(4.0 * m_settings.margin).extendedBy(-stretch);
    if (node.box.contains(tightBox) && largest.contains(node.box))
        return std::nullopt;
    return fat;
}

void DynamicTree::reinsertProxy(int32_t proxyId, const Aabb& fatBox) {
    assert(isProxy(proxyId) && fatBox.isValid());
    removeLeaf(proxyId);
    m_nodes[proxyId].box = fatBox;
    insertLeaf(proxyId);
}

// Greedy descent by the surface area heuristic. Placing the leaf as a sibling of node N costs the area of the new
// parent plus the growth of every ancestor of N (the inherited cost). Descending into a child can at best cost the
// growth of that child, so that is the lower bound we compare against stopping here.
int32_t DynamicTree::findBestSibling(const Aabb& box) const {
    const Real leafArea = box.surfaceArea();
    int32_t index = m_root;
    Real inherited = 0.0;
    while (!m_nodes[index].isLeaf()) {
        const Node& node = m_nodes[index];
        const Real area = node.box.surfaceArea();
        const Real combinedArea = unionOf(node.box, box).surfaceArea();
        const Real costHere = combinedArea + inherited;
        const Real inheritedBelow = inherited + (combinedArea - area);

        auto childCost = [&](int32_t child) {
            const Node& c = m_nodes[child];
            const Real combined = unionOf(c.box, box).surfaceArea();
            if (c.isLeaf())
                return combined + inheritedBelow;
            // The leaf ends up deeper, under a new parent no smaller than itself: grow the child at least, and
            // the new parent there costs at least the leaf's own area.
            return (combined - c.box.surfaceArea()) + leafArea + inheritedBelow;
        };
        const Real cost1 = childCost(node.child1);
        const Real cost2 = childCost(node.child2);
        if (costHere <= cost1 && costHere <= cost2)
            break;
        index = cost1 <= cost2 ? node.child1 : node.child2;
        inherited = inheritedBelow;
    }
    return index;
}

void DynamicTree::insertLeaf(int32_t leaf) {
    if (m_root == kNullNode) {
        m_root = leaf;
        m_nodes[leaf].parent = kNullNode;
        return;
    }
    const Aabb leafBox = m_nodes[leaf].box;
    const int32_t sibling = findBestSibling(leafBox);
    const int32_t oldParent = m_nodes[sibling].parent;
    const int32_t newParent = allocateNode();
    {
        Node& p = m_nodes[newParent];
        p.parent = oldParent;
        p.box = unionOf(leafBox, m_nodes[sibling].box);
        p.height = m_nodes[sibling].height + 1;
        p.child1 = sibling;
        p.child2 = leaf;
    }
    if (oldParent != kNullNode) {
        Node& op = m_nodes[oldParent];
        (op.child1 == sibling ? op.child1 : op.child2) = newParent;
    } else {
        m_root = newParent;
    }
    m_nodes[sibling].parent = newParent;
    m_nodes[leaf].parent = newParent;
    refitUpwards(oldParent);
}

void DynamicTree::removeLeaf(int32_t leaf) {
    if (leaf == m_root) {
        m_root = kNullNode;
        return;
    }
    const int32_t parent = m_nodes[leaf].parent;
    const int32_t grandparent = m_nodes[parent].parent;
    const int32_t sibling = m_nodes[parent].child1 == leaf ? m_nodes[parent].child2 : m_nodes[parent].child1;
    if (grandparent != kNullNode) {
        Node& g = m_nodes[grandparent];
        (g.child1 == parent ? g.child1 : g.child2) = sibling;
        m_nodes[sibling].parent = grandparent;
        freeNode(parent);
        shrinkUpwards(grandparent);
    } else {
        m_root = sibling;
        m_nodes[sibling].parent = kNullNode;
        freeNode(parent);
    }
    m_nodes[leaf].parent = kNullNode;
}

void DynamicTree::refitNode(int32_t index) {
    Node& node = m_nodes[index];
    const Node& c1 = m_nodes[node.child1];
    const Node& c2 = m_nodes[node.child2];
    node.box = unionOf(c1.box, c2.box);
    node.height = 1 + std::max(c1.height, c2.height);
}

// After a removal the ancestors can only shrink. Once a node comes out unchanged, so do all above it, so the walk
// stops there. No rotations here: the reinsertion that usually follows rotates along its own path.
void DynamicTree::shrinkUpwards(int32_t index) {
    while (index != kNullNode) {
        Node& node = m_nodes[index];
        const Aabb oldBox = node.box;
        const int32_t oldHeight = node.height;
        refitNode(index);
        if (node.box == oldBox && node.height == oldHeight)
            return;
        index = node.parent;
    }
}

// After an insertion the ancestors can only grow. Each is refitted after its children and then rotated; the walk
// stops at the first one that comes out unchanged, so it is at most the tree height long and usually much shorter.
void DynamicTree::refitUpwards(int32_t index) {
    while (index != kNullNode) {
        Node& node = m_nodes[index];
        const Aabb oldBox = node.box;
        const int32_t oldHeight = node.height;
        refitNode(index);
        rotate(index);
        if (node.box == oldBox && node.height == oldHeight)
            return;
        index = m_nodes[index].parent;
    }
}

void DynamicTree::swapChildWithGrandchild(int32_t parent, int32_t child, int32_t other, int32_t grandchild) {
    // Before: parent{child, other{grandchild, w}}. After: parent{grandchild, other{child, w}}.
    Node& p = m_nodes[parent];
    (p.child1 == child ? p.child1 : p.child2) = grandchild;
    m_nodes[grandchild].parent = parent;
    Node& o = m_nodes[other];
    (o.child1 == grandchild ? o.child1 : o.child2) = child;
    m_nodes[child].parent = other;
    refitNode(other);
    refitNode(parent);
}

void DynamicTree::swapGrandchildren(int32_t parent, int32_t a, int32_t b) {
    const int32_t pa = m_nodes[a].parent;
    const int32_t pb = m_nodes[b].parent;
    Node& na = m_nodes[pa];
    (na.child1 == a ? na.child1 : na.child2) = b;
    Node& nb = m_nodes[pb];
    (nb.child1 == b ? nb.child1 : nb.child2) = a;
    m_nodes[a].parent = pb;
    m_nodes[b].parent = pa;
    refitNode(pa);
    refitNode(pb);
    refitNode(parent);
}

// A rotation swaps a child of A with a grandchild (or two grandchildren). A's box stays the same because it has
// the same leaves; only the areas of A's children change, so the cheapest swap that shrinks them lowers the SAH
// cost of the whole tree.
void DynamicTree::rotate(int32_t iA) {
    const Node& a = m_nodes[iA];
    if (a.height < 2)
        return;
    const int32_t iB = a.child1;
    const int32_t iC = a.child2;
    const Node& b = m_nodes[iB];
    const Node& c = m_nodes[iC];
    const Real areaB = b.box.surfaceArea();
    const Real areaC = c.box.surfaceArea();

    enum Swap { None, BF, BG, CD, CE, DF, DG };
    Swap best = None;
    // Ignore gains that are only rounding noise, so equal-cost configurations do not flip back and forth.
    Real bestCost = -1e-12 * a.box.surfaceArea();

    auto consider = [&](Swap s, Real cost) {
        if (cost < bestCost) {
            bestCost = cost;
            best = s;
        }
    };
    if (!c.isLeaf()) {
        const Node& f = m_nodes[c.child1];
        const Node& g = m_nodes[c.child2];
        consider(BF, unionOf(b.box, g.box).surfaceArea() - areaC);
        consider(BG, unionOf(b.box, f.box).surfaceArea() - areaC);
    }
    if (!b.isLeaf()) {
        const Node& d = m_nodes[b.child1];
        const Node& e = m_nodes[b.child2];
        consider(CD, unionOf(c.box, e.box).surfaceArea() - areaB);
        consider(CE, unionOf(c.box, d.box).surfaceArea() - areaB);
        if (!c.isLeaf()) {
            const Node& f = m_nodes[c.child1];
            const Node& g = m_nodes[c.child2];
            consider(DF, unionOf(f.box, e.box).surfaceArea() + unionOf(d.box, g.box).surfaceArea() - areaB - areaC);
            consider(DG, unionOf(g.box, e.box).surfaceArea() + unionOf(f.box, d.box).surfaceArea() - areaB - areaC);
        }
    }
    switch (best) {
    case None:
        break;
    case BF:
        swapChildWithGrandchild(iA, iB, iC, m_nodes[iC].child1);
        break;
    case BG:
        swapChildWithGrandchild(iA, iB, iC, m_nodes[iC].child2);
        break;
    case CD:
        swapChildWithGrandchild(iA, iC, iB, m_nodes[iB].child1);
        break;
    case CE:
        swapChildWithGrandchild(iA, iC, iB, m_nodes[iB].child2);
        break;
    case DF:
        swapGrandchildren(iA, m_nodes[iB].child1, m_nodes[iC].child1);
        break;
    case DG:
        swapGrandchildren(iA, m_nodes[iB].child1, m_nodes[iC].child2);
        break;
    }
}

Real DynamicTree::areaRatio() const {
    if (m_root == kNullNode)
        return 0.0;
    const Real rootArea = m_nodes[m_root].box.surfaceArea();
    Real total = 0.0;
    for (const Node& node : m_nodes) {
        if (node.height > 0)
            total += node.box.surfaceArea();
    }
    return rootArea > 0.0 ? total / rootArea : 0.0;
}

bool DynamicTree::validate(std::string* problem) const {
    auto fail = [&](const std::string& what, int32_t node) {
        if (problem)
            *problem = what + " at node " + std::to_string(node);
        return false;
    };
    const int32_t capacity = static_cast<int32_t>(m_nodes.size());
    int32_t freeCount = 0;
    for (int32_t i = m_freeList; i != kNullNode; i = m_nodes[i].parent) {
        if (i < 0 || i >= capacity || m_nodes[i].height != -1)
            return fail("bad free list entry", i);
        if (++freeCount > capacity)
            return fail("cycle in free list", i);
    }
    if (freeCount + m_nodeCount != capacity)
        return fail("node count does not match free list", m_freeList);
    if (m_root == kNullNode)
        return m_nodeCount == 0 && m_proxyCount == 0 ? true : fail("empty root but nodes in use", kNullNode);
    if (m_nodes[m_root].parent != kNullNode)
        return fail("root has a parent", m_root);

    int32_t visited = 0;
    int32_t leaves = 0;
    detail::NodeStack stack;
    stack.push(m_root);
    while (!stack.empty()) {
        const int32_t i = stack.pop();
        if (++visited > m_nodeCount)
            return fail("more nodes reachable than allocated (cycle?)", i);
        const Node& node = m_nodes[i];
        if (node.height < 0)
            return fail("free node reachable", i);
        if (!node.box.isValid())
            return fail("invalid box", i);
        if (node.isLeaf()) {
            ++leaves;
            continue;
        }
        const int32_t c1 = node.child1;
        const int32_t c2 = node.child2;
        if (c1 < 0 || c1 >= capacity || c2 < 0 || c2 >= capacity || c1 == c2)
            return fail("bad child index", i);
        if (m_nodes[c1].parent != i || m_nodes[c2].parent != i)
            return fail("child does not point back to parent", i);
        if (node.height != 1 + std::max(m_nodes[c1].height, m_nodes[c2].height))
            return fail("wrong height", i);
        if (!node.box.contains(m_nodes[c1].box) || !node.box.contains(m_nodes[c2].box))
            return fail("box does not contain its children", i);
        stack.push(c1);
        stack.push(c2);
    }
    if (visited != m_nodeCount)
        return fail("unreachable nodes in use", m_root);
    if (leaves != m_proxyCount)
        return fail("leaf count does not match proxy count", m_root);
    return true;
}

} // namespace rl
