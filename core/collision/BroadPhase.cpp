#include "collision/BroadPhase.h"

#include <algorithm>
#include <cassert>

namespace rl {

BroadPhase::BroadPhase(const BroadPhaseSettings& settings)
    : m_trees{DynamicTree(settings.dynamicTree), DynamicTree(settings.staticTree)} {}

static Error badBox(uint32_t bodyId) {
    Error e;
    e.object = "body " + std::to_string(bodyId);
    e.message = "bounding box is not finite or has min > max";
    return e;
}

void BroadPhase::markMoved(ProxyKey key) {
    std::vector<uint8_t>& flags = m_moved[index(key.kind)];
    if (flags[key.proxy] == 0) {
        flags[key.proxy] = 1;
        m_moveBuffer.push_back(key);
    }
}

Result<ProxyKey> BroadPhase::createProxy(const Aabb& tightBox, uint32_t bodyId, ProxyKind kind) {
    if (!tightBox.isValid())
        return badBox(bodyId);
    const ProxyKey key{m_trees[index(kind)].createProxy(tightBox, bodyId), kind};
    std::vector<uint8_t>& flags = m_moved[index(kind)];
    if (flags.size() <= static_cast<size_t>(key.proxy))
        flags.resize(static_cast<size_t>(key.proxy) + 1, 0);
    markMoved(key);
    return key;
}

void BroadPhase::destroyProxy(ProxyKey key) {
    assert(m_trees[index(key.kind)].isProxy(key.proxy));
    // The id may be reused by the next createProxy, so nothing may refer to it after this.
    if (isMoved(key)) {
        m_moved[index(key.kind)][key.proxy] = 0;
        std::erase(m_moveBuffer, key);
    }
    std::erase_if(m_pairs, [&](const BroadPhasePair& p) { return p.proxyA == key || p.proxyB == key; });
    m_trees[index(key.kind)].destroyProxy(key.proxy);
}

Status BroadPhase::moveProxy(ProxyKey key, const Aabb& tightBox, const Vec3& displacement) {
    DynamicTree& tree = m_trees[index(key.kind)];
    assert(tree.isProxy(key.proxy));
    if (!tightBox.isValid())
        return badBox(tree.userId(key.proxy));
    if (tree.moveProxy(key.proxy, tightBox, displacement))
        markMoved(key);
    return Ok{};
}

std::optional<Aabb> BroadPhase::fatBoxIfMoved(ProxyKey key, const Aabb& tightBox, const Vec3& displacement) const {
    const DynamicTree& tree = m_trees[index(key.kind)];
    assert(tree.isProxy(key.proxy));
    if (!tightBox.isValid())
        return std::nullopt;
    return tree.fatBoxIfMoved(key.proxy, tightBox, displacement);
}

void BroadPhase::reinsertProxy(ProxyKey key, const Aabb& fatBox) {
    m_trees[index(key.kind)].reinsertProxy(key.proxy, fatBox);
    markMoved(key);
}

void BroadPhase::touchProxy(ProxyKey key) {
    assert(m_trees[index(key.kind)].isProxy(key.proxy));
    markMoved(key);
}

void BroadPhase::addCandidate(std::vector<BroadPhasePair>& to, ProxyKey a, ProxyKey b) const {
    const uint32_t idA = bodyId(a);
    const uint32_t idB = bodyId(b);
    if (idA < idB)
        to.push_back({idA, idB, a, b});
    else
        to.push_back({idB, idA, b, a});
}

// Each overlap involving a moved proxy is found from exactly one side: when both proxies moved, only the query of
// the dynamic one with the larger id (or the dynamic one, against a static) records it. Reads the trees and the
// moved flags only, so chunks of the move buffer can be queried at once.
void BroadPhase::queryMoved(size_t first, size_t last, std::vector<BroadPhasePair>& to) const {
    const DynamicTree& dynamicTree = m_trees[index(ProxyKind::Dynamic)];
    const DynamicTree& staticTree = m_trees[index(ProxyKind::Static)];
    for (size_t m = first; m < last; ++m) {
        const ProxyKey key = m_moveBuffer[m];
        const Aabb box = fatAabb(key);
        if (key.kind == ProxyKind::Dynamic) {
            dynamicTree.query(box, [&](int32_t other) {
                const ProxyKey otherKey{other, ProxyKind::Dynamic};
                if (other == key.proxy || (isMoved(otherKey) && other < key.proxy))
                    return true;
                addCandidate(to, key, otherKey);
                return true;
            });
            staticTree.query(box, [&](int32_t other) {
                addCandidate(to, key, ProxyKey{other, ProxyKind::Static});
                return true;
            });
        } else {
            dynamicTree.query(box, [&](int32_t other) {
                const ProxyKey otherKey{other, ProxyKind::Dynamic};
                if (!isMoved(otherKey))
                    addCandidate(to, key, otherKey);
                return true;
            });
        }
    }
}

// Spreads the bits of a 21-bit integer so that three of them interleave into a 63-bit Morton code.
static uint64_t spreadBits(uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

// Queries are bound by fetching tree nodes from memory. Issuing them in Morton order of the box centres makes
// consecutive queries walk the same nodes while they are still in cache. The pair list is sorted afterwards, so
// the order of queries never shows in the result.
void BroadPhase::sortMoveBufferSpatially() {
    if (m_moveBuffer.size() < 64)
        return;
    Aabb bounds = fatAabb(m_moveBuffer.front());
    for (const ProxyKey key : m_moveBuffer)
        bounds = unionOf(bounds, fatAabb(key));
    const Vec3 extent = bounds.max - bounds.min;
    const Real scale = static_cast<Real>(0x1fffff) / std::max({extent.x, extent.y, extent.z, 1e-9});
    m_sortKeys.clear();
    for (const ProxyKey key : m_moveBuffer) {
        const Vec3 c = (fatAabb(key).center() - bounds.min) * scale;
        const uint64_t code = spreadBits(static_cast<uint64_t>(c.x)) | spreadBits(static_cast<uint64_t>(c.y)) << 1 |
                              spreadBits(static_cast<uint64_t>(c.z)) << 2;
        m_sortKeys.push_back({code, key});
    }
    std::sort(m_sortKeys.begin(), m_sortKeys.end());
    for (size_t i = 0; i < m_sortKeys.size(); ++i)
        m_moveBuffer[i] = m_sortKeys[i].second;
}

void BroadPhase::updatePairs(const ParallelFor& parallelFor) {
    m_candidates.clear();
    m_added.clear();
    m_removed.clear();
    m_stats = {};
    m_stats.movedProxies = static_cast<int32_t>(m_moveBuffer.size());
    sortMoveBufferSpatially();

    // Split up, the move buffer is queried in chunks of kChunk proxies, each into its own list; the lists are then
    // joined in chunk order, so the candidates do not depend on how the chunks were shared out.
    constexpr size_t kChunk = 64;
    const size_t chunks = (m_moveBuffer.size() + kChunk - 1) / kChunk;
    if (parallelFor && chunks > 1) {
        if (m_chunkCandidates.size() < chunks)
            m_chunkCandidates.resize(chunks);
        parallelFor(chunks, [&](size_t begin, size_t end) {
            for (size_t c = begin; c < end; ++c) {
                m_chunkCandidates[c].clear();
                queryMoved(c * kChunk, std::min(m_moveBuffer.size(), (c + 1) * kChunk), m_chunkCandidates[c]);
            }
        });
        for (size_t c = 0; c < chunks; ++c)
            m_candidates.insert(m_candidates.end(), m_chunkCandidates[c].begin(), m_chunkCandidates[c].end());
    } else {
        queryMoved(0, m_moveBuffer.size(), m_candidates);
    }
    m_stats.candidates = static_cast<int32_t>(m_candidates.size());

    // Which candidates are new: each is looked up among the current pairs, where the pairs of one first body are one
    // run of the sorted list (m_firstPair[idA] .. m_firstPair[idA + 1]), sorted by the second body. Only the new ones
    // are sorted. (Sorting every candidate took 39 us a step, and merging them with the kept pairs part of another
    // 28 us: medians of ramps.obj's first 120 frames on one thread, 2026-11-27.) A pair can be found from both sides
    // (a moved anchor and a moved body), so the new ones are made unique.
    const uint32_t idCount = m_pairs.empty() ? 0 : m_pairs.back().idA + 1;
    m_firstPair.assign(static_cast<size_t>(idCount) + 1, 0);
    for (const BroadPhasePair& p : m_pairs)
        ++m_firstPair[p.idA + 1];
    for (uint32_t id = 0; id < idCount; ++id)
        m_firstPair[id + 1] += m_firstPair[id];
    for (const BroadPhasePair& c : m_candidates) {
        bool known = false;
        if (c.idA < idCount) {
            // A run can be long (a floor with a low id pairs with every body on it): search it by halves.
            const auto first = m_pairs.begin() + m_firstPair[c.idA], last = m_pairs.begin() + m_firstPair[c.idA + 1];
            const auto at =
                std::lower_bound(first, last, c.idB, [](const BroadPhasePair& p, uint32_t idB) { return p.idB < idB; });
            known = at != last && at->idB == c.idB;
        }
        if (!known)
            m_added.push_back(c);
    }
    // Body ids are unique among live proxies, so they decide the order (BroadPhasePair's operator<); compared as one
    // 64-bit key, the first step's sort, where every pair is new, stays cheap.
    const auto key = [](const BroadPhasePair& p) { return uint64_t(p.idA) << 32 | p.idB; };
    std::sort(m_added.begin(), m_added.end(),
              [&](const BroadPhasePair& l, const BroadPhasePair& r) { return key(l) < key(r); });
    m_added.erase(std::unique(m_added.begin(), m_added.end()), m_added.end());

    // One walk over the pairs drops those that ended and puts the new ones in their places. Old pairs can only stop
    // overlapping if one of their proxies got a new fat box, i.e. moved.
    m_scratch.clear();
    m_scratch.reserve(m_pairs.size() + m_added.size());
    size_t next = 0;
    for (const BroadPhasePair& p : m_pairs) {
        if ((isMoved(p.proxyA) || isMoved(p.proxyB)) && !fatAabb(p.proxyA).overlaps(fatAabb(p.proxyB))) {
            m_removed.push_back(p);
            continue;
        }
        for (const uint64_t at = key(p); next < m_added.size() && key(m_added[next]) < at; ++next)
            m_scratch.push_back(m_added[next]);
        m_scratch.push_back(p);
    }
    m_scratch.insert(m_scratch.end(), m_added.begin() + static_cast<std::ptrdiff_t>(next), m_added.end());
    std::swap(m_pairs, m_scratch);

    for (const ProxyKey key : m_moveBuffer)
        m_moved[index(key.kind)][key.proxy] = 0;
    m_moveBuffer.clear();
    m_stats.addedPairs = static_cast<int32_t>(m_added.size());
    m_stats.removedPairs = static_cast<int32_t>(m_removed.size());
}

} // namespace rl
