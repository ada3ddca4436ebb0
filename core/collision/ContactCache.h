// Contact cache: carries the solver's accumulated impulses from last frame's manifold points to this frame's,
// matching by feature id first and by nearest point second, so that warm starting survives frame to frame.
#pragma once

#include "collision/Manifold.h"

#include <cstddef>
#include <cstdint>
#include <unordered_map>

namespace rl {

struct ContactCacheOptions {
    // A point whose feature id is new takes the impulses of the nearest old point within this distance (m, in
    // A's body frame). Ids change when a clipping feature changes while the contact itself has hardly moved.
    Real matchDistance = 0.01;
    // Nothing is carried when the normal turned more than this (cosine of 30 degrees): the old impulses were
    // pushing along a different direction and would kick the bodies.
    Real minNormalCosine = 0.8660254037844386;
};

// Copies normalImpulse from `previous` into the matching points of `current` (unmatched points start at zero), and
// the manifold's friction and twist impulses when any point matched. Returns how many points were matched.
int warmStart(const Manifold& previous, Manifold& current, const ContactCacheOptions& options = {});

// Manifolds of the current frame, keyed by the ordered body pair (bodyA, bodyB). The broadphase must report a
// pair in the same order every frame, or the cache sees a new pair.
class ContactCache {
public:
    explicit ContactCache(const ContactCacheOptions& options = {}) : m_options(options) {}

    void beginFrame() { ++m_frame; }
    // Warm-starts `fresh` from the pair's manifold of the last frame and stores it. The returned reference stays
    // valid until endFrame() removes the pair; the solver writes its accumulated impulses into it.
    Manifold& update(const Manifold& fresh);
    // Drops the pairs that were not updated since beginFrame().
    void endFrame();

    const Manifold* find(uint32_t bodyA, uint32_t bodyB) const;
    size_t size() const { return m_entries.size(); }
    void clear() { m_entries.clear(); }

private:
    struct Entry {
        Manifold manifold;
        uint64_t frame = 0;
    };
    static uint64_t key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

    ContactCacheOptions m_options;
    std::unordered_map<uint64_t, Entry> m_entries; // node-based: references survive insertions
    uint64_t m_frame = 0;
};

} // namespace rl
