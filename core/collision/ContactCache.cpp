#include "collision/ContactCache.h"

#include <limits>

namespace rl {

int warmStart(const Manifold& previous, Manifold& current, const ContactCacheOptions& options) {
    for (int i = 0; i < current.pointCount; ++i)
        current.points[i].normalImpulse = 0.0;
    current.frictionImpulse = Vec3(0.0);
    current.twistImpulse = 0.0;
    current.heldImpulses = previous.heldImpulses; // (the impulses carried keep what they were solved with)
    if (previous.pointCount == 0 || glm::dot(previous.normal, current.normal) < options.minNormalCosine)
        return 0;
    bool used[4] = {false, false, false, false};
    int matchOf[4] = {-1, -1, -1, -1};
    // Ids first: they name the same pair of features, which is the best evidence of the same contact.
    for (int i = 0; i < current.pointCount; ++i) {
        for (int j = 0; j < previous.pointCount; ++j) {
            if (!used[j] && previous.points[j].featureId == current.points[i].featureId) {
                used[j] = true;
                matchOf[i] = j;
                break;
            }
        }
    }
    // Then the nearest unused old point, in A's frame where a resting contact does not move.
    const Real maxD2 = options.matchDistance * options.matchDistance;
    for (int i = 0; i < current.pointCount; ++i) {
        if (matchOf[i] >= 0)
            continue;
        Real best = maxD2;
        for (int j = 0; j < previous.pointCount; ++j) {
            const Vec3 d = previous.points[j].localA - current.points[i].localA;
            const Real d2 = glm::dot(d, d);
            if (!used[j] && d2 <= best) {
                best = d2;
                matchOf[i] = j;
            }
        }
        if (matchOf[i] >= 0)
            used[matchOf[i]] = true;
    }
    int matched = 0;
    for (int i = 0; i < current.pointCount; ++i) {
        if (matchOf[i] < 0)
            continue;
        const ContactPoint& old = previous.points[matchOf[i]];
        current.points[i].normalImpulse = old.normalImpulse;
        ++matched;
    }
    // The manifold's friction goes with it while any point persists: it is the same contact patch.
    if (matched > 0) {
        current.frictionImpulse = previous.frictionImpulse;
        current.twistImpulse = previous.twistImpulse;
    }
    return matched;
}

Manifold& ContactCache::update(const Manifold& fresh) {
    auto [it, inserted] = m_entries.try_emplace(key(fresh.bodyA, fresh.bodyB));
    Entry& e = it->second;
    Manifold next = fresh;
    if (inserted || e.frame + 1 < m_frame)
        warmStart(Manifold{}, next, m_options); // new or interrupted contact: start cold
    else
        warmStart(e.manifold, next, m_options);
    e.manifold = next;
    e.frame = m_frame;
    return e.manifold;
}

void ContactCache::endFrame() {
    for (auto it = m_entries.begin(); it != m_entries.end();) {
        if (it->second.frame != m_frame)
            it = m_entries.erase(it);
        else
            ++it;
    }
}

const Manifold* ContactCache::find(uint32_t bodyA, uint32_t bodyB) const {
    auto it = m_entries.find(key(bodyA, bodyB));
    return it == m_entries.end() ? nullptr : &it->second.manifold;
}

} // namespace rl
