// Signed distance of two convex shapes: GJK when apart, EPA when the cores overlap, and the SAT on hull faces when
// EPA gives up. This is the one query the narrowphase and the tests use to ask "how far apart, along what?".
#pragma once

#include "collision/Epa.h"
#include "collision/Gjk.h"
#include "collision/Shape.h"

namespace rl {

enum class PenetrationMethod : uint8_t { Gjk, Epa, SatFallback, Analytic };

struct PenetrationOptions {
    GjkOptions gjk;
    EpaOptions epa;
};

struct PenetrationResult {
    Real separation = 0.0;      // distance when apart, minus the depth when overlapping
    Vec3 normal{0.0, 1.0, 0.0}; // unit, from A to B
    Vec3 pointA{0.0};           // witness on A, world: pointB - pointA == separation * normal
    Vec3 pointB{0.0};
    // Epa with epaStatus BudgetExceeded: EPA ran out of faces on a pair too big for the SAT fallback (see
    // kSatFallbackMaxEdgePairs); the depth is then EPA's lower bound, a little short of the exact one.
    PenetrationMethod method = PenetrationMethod::Gjk;
    EpaStatus epaStatus = EpaStatus::Converged; // what EPA reported when it ran
};

PenetrationResult signedDistance(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                                 const PenetrationOptions& options = {});

} // namespace rl
