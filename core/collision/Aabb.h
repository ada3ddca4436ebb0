// Axis-aligned bounding box: the currency of the broadphase trees and of ray culling.
// Small and trivially copyable on purpose, so that tree nodes stay compact and can be copied freely.
#pragma once

#include "math/Types.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl {

struct Aabb {
    Vec3 min{0.0};
    Vec3 max{0.0};

    static Aabb fromCenterHalfExtents(const Vec3& center, const Vec3& halfExtents) {
        return {center - halfExtents, center + halfExtents};
    }

    Vec3 center() const { return 0.5 * (min + max); }
    Vec3 halfExtents() const { return 0.5 * (max - min); }

    // A box is usable by the trees only when it is finite and not inverted; NaN fails every comparison here.
    bool isValid() const {
        for (int i = 0; i < 3; ++i) {
            if (!(min[i] <= max[i]) || !std::isfinite(min[i]) || !std::isfinite(max[i]))
                return false;
        }
        return true;
    }

    // Full surface area. The SAH only compares areas, so the factor 2 does not matter, but keeping the true
    // area makes the tree's cost figure meaningful when printed.
    Real surfaceArea() const {
        const Vec3 d = max - min;
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }

    bool contains(const Aabb& other) const {
        return min.x <= other.min.x && min.y <= other.min.y && min.z <= other.min.z && other.max.x <= max.x &&
               other.max.y <= max.y && other.max.z <= max.z;
    }

    bool contains(const Vec3& p) const {
        return min.x <= p.x && min.y <= p.y && min.z <= p.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }

    // Touching counts as overlapping so that resting contact is never lost between frames.
    bool overlaps(const Aabb& other) const {
        return min.x <= other.max.x && other.min.x <= max.x && min.y <= other.max.y && other.min.y <= max.y &&
               min.z <= other.max.z && other.min.z <= max.z;
    }

    // The widest gap between the two boxes along an axis: how far apart they are at least (negative: they overlap).
    Real gapTo(const Aabb& other) const {
        const Vec3 gap = glm::max(other.min - max, min - other.max);
        return std::max({gap.x, gap.y, gap.z});
    }

    Aabb fattened(Real margin) const { return {min - Vec3(margin), max + Vec3(margin)}; }

    // Grows the box along a predicted displacement, so a body moving steadily stays inside it for a few steps.
    Aabb extendedBy(const Vec3& displacement) const {
        Aabb r = *this;
        for (int i = 0; i < 3; ++i) {
            if (displacement[i] < 0.0)
                r.min[i] += displacement[i];
            else
                r.max[i] += displacement[i];
        }
        return r;
    }

    bool operator==(const Aabb&) const = default;
};

inline Aabb unionOf(const Aabb& a, const Aabb& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

// Slab test for the segment origin + t * direction, t in [0, tMax]. On a hit, tEnter is where the segment enters
// the box (0 when the origin is inside). Zero direction components are handled explicitly: dividing by them would
// give 0 * inf = NaN when the origin lies exactly on a slab plane.
inline bool raySlab(const Aabb& box, const Vec3& origin, const Vec3& direction, Real tMax, Real& tEnter) {
    Real lo = 0.0;
    Real hi = tMax;
    for (int i = 0; i < 3; ++i) {
        const Real d = direction[i];
        if (std::abs(d) < std::numeric_limits<Real>::min()) {
            if (origin[i] < box.min[i] || origin[i] > box.max[i])
                return false;
            continue;
        }
        const Real inv = 1.0 / d;
        Real t1 = (box.min[i] - origin[i]) * inv;
        Real t2 = (box.max[i] - origin[i]) * inv;
        if (t1 > t2)
            std::swap(t1, t2);
        lo = std::max(lo, t1);
        hi = std::min(hi, t2);
        if (lo > hi)
            return false;
    }
    tEnter = lo;
    return true;
}

} // namespace rl
