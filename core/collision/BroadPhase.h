// Broadphase: finds the body pairs whose fat boxes overlap, with dynamic bodies and static anchors in two trees.
// Keeps the full pair set up to date incrementally and reports what was added and removed, in a fixed order.
#pragma once

#include "collision/Aabb.h"
#include "collision/DynamicTree.h"
#include "common/Result.h"
#include "math/Types.h"

#include <compare>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace rl {

enum class ProxyKind : uint8_t { Dynamic = 0, Static = 1 };

// Names a proxy: which tree it lives in and its id there. Cheap to copy; invalid when proxy < 0.
struct ProxyKey {
    int32_t proxy = -1;
    ProxyKind kind = ProxyKind::Dynamic;

    bool isValid() const { return proxy >= 0; }
    auto operator<=>(const ProxyKey&) const = default;
};

// One overlapping pair. idA < idB are the body ids given at createProxy; the proxies are carried along so the
// caller need not look them up again.
struct BroadPhasePair {
    uint32_t idA = 0;
    uint32_t idB = 0;
    ProxyKey proxyA;
    ProxyKey proxyB;

    // Ordered by body ids first, so the order is the same whatever the tree layout happens to be.
    auto operator<=>(const BroadPhasePair&) const = default;
};

struct BroadPhaseSettings {
    DynamicTreeSettings dynamicTree;
    // Anchors do not move during a run, so they get tight boxes: a margin would only add false pairs.
    DynamicTreeSettings staticTree{0.0, 0.0};
};

// What the last updatePairs did, for the profile counters.
struct BroadPhaseStats {
    int32_t movedProxies = 0; // proxies that queried the trees
    int32_t candidates = 0;   // overlaps found by those queries, before removing duplicates
    int32_t addedPairs = 0;
    int32_t removedPairs = 0;
};

class BroadPhase {
public:
    explicit BroadPhase(const BroadPhaseSettings& settings = {});

    // Body ids must be unique among live proxies. Fails, changing nothing, when the box is not finite or inverted.
    Result<ProxyKey> createProxy(const Aabb& tightBox, uint32_t bodyId, ProxyKind kind);
    // The proxy's pairs leave pairs() at once and are not reported in removedPairs(): the caller destroying a body
    // drops its contacts itself.
    void destroyProxy(ProxyKey key);
    // displacement is the predicted motion over the next step (velocity * dt); it stretches the fat box.
    // Fails, changing nothing, when the box is not finite or inverted.
    Status moveProxy(ProxyKey key, const Aabb& tightBox, const Vec3& displacement);
    // moveProxy() in two halves (DynamicTree::fatBoxIfMoved()): proxies can be tested on several threads at once
    // while nothing changes the broadphase; then reinsertProxy() puts each one that needs it back with its new fat
    // box and marks it moved. A box that is not finite or inverted needs nothing: the proxy stays where it was.
    std::optional<Aabb> fatBoxIfMoved(ProxyKey key, const Aabb& tightBox, const Vec3& displacement) const;
    void reinsertProxy(ProxyKey key, const Aabb& fatBox);
    // Makes the proxy look for pairs at the next update even though its box did not change.
    void touchProxy(ProxyKey key);

    // Calls body(begin, end) for ranges that together cover [0, count) once each, on one thread or several.
    using ParallelFor = std::function<void(size_t count, const std::function<void(size_t begin, size_t end)>& body)>;

    // Brings pairs() up to date: only proxies created, reinserted or touched since the last call query the trees.
    // Afterwards pairs() holds exactly the pairs whose fat boxes overlap (never static with static), sorted.
    // parallelFor, if given, runs the queries split up in fixed chunks of the moved proxies; the pairs are the same.
    void updatePairs(const ParallelFor& parallelFor = {});

    std::span<const BroadPhasePair> pairs() const { return m_pairs; }
    // What the last updatePairs added to and removed from pairs(), both sorted.
    std::span<const BroadPhasePair> addedPairs() const { return m_added; }
    std::span<const BroadPhasePair> removedPairs() const { return m_removed; }
    const BroadPhaseStats& stats() const { return m_stats; }

    const DynamicTree& tree(ProxyKind kind) const { return m_trees[index(kind)]; }
    const Aabb& fatAabb(ProxyKey key) const { return m_trees[index(key.kind)].fatAabb(key.proxy); }
    uint32_t bodyId(ProxyKey key) const { return m_trees[index(key.kind)].userId(key.proxy); }
    int32_t proxyCount() const { return m_trees[0].proxyCount() + m_trees[1].proxyCount(); }

    // callback(ProxyKey) for every proxy whose fat box overlaps box, dynamic tree first; return false to stop.
    template <class Callback>
    void query(const Aabb& box, Callback&& callback) const;

    // As DynamicTree::rayCast over both trees; callback(ProxyKey, currentMaxFraction) returns the new maximum
    // fraction (negative: ignore, 0: stop). Clipping carries over from the dynamic tree to the static one.
    template <class Callback>
    void rayCast(const Vec3& origin, const Vec3& direction, Real maxFraction, Callback&& callback) const;

private:
    static int index(ProxyKind kind) { return static_cast<int>(kind); }
    bool isMoved(ProxyKey key) const { return m_moved[index(key.kind)][key.proxy] != 0; }
    void markMoved(ProxyKey key);
    void addCandidate(std::vector<BroadPhasePair>& to, ProxyKey a, ProxyKey b) const;
    void queryMoved(size_t first, size_t last, std::vector<BroadPhasePair>& to) const;
    void sortMoveBufferSpatially();

    DynamicTree m_trees[2];
    std::vector<uint8_t> m_moved[2]; // per proxy id: in the move buffer since the last update
    std::vector<ProxyKey> m_moveBuffer;
    std::vector<std::pair<uint64_t, ProxyKey>> m_sortKeys;
    std::vector<BroadPhasePair> m_candidates;
    std::vector<uint32_t> m_firstPair; // per body id: its first pair as idA in m_pairs (updatePairs())
    std::vector<std::vector<BroadPhasePair>> m_chunkCandidates; // per chunk of the move buffer (updatePairs())
    std::vector<BroadPhasePair> m_pairs;
    std::vector<BroadPhasePair> m_added;
    std::vector<BroadPhasePair> m_removed;
    std::vector<BroadPhasePair> m_scratch;
    BroadPhaseStats m_stats;
};

template <class Callback>
void BroadPhase::query(const Aabb& box, Callback&& callback) const {
    bool go = true;
    for (ProxyKind kind : {ProxyKind::Dynamic, ProxyKind::Static}) {
        if (!go)
            return;
        m_trees[index(kind)].query(box, [&](int32_t proxy) {
            go = callback(ProxyKey{proxy, kind});
            return go;
        });
    }
}

template <class Callback>
void BroadPhase::rayCast(const Vec3& origin, const Vec3& direction, Real maxFraction, Callback&& callback) const {
    bool stopped = false;
    for (ProxyKind kind : {ProxyKind::Dynamic, ProxyKind::Static}) {
        if (stopped)
            return;
        m_trees[index(kind)].rayCast(origin, direction, maxFraction, [&](int32_t proxy, Real currentMax) {
            const Real value = callback(ProxyKey{proxy, kind}, currentMax);
            if (value == 0.0)
                stopped = true;
            else if (value > 0.0 && value < maxFraction)
                maxFraction = value;
            return value;
        });
    }
}

} // namespace rl
