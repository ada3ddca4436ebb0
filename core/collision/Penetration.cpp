#include "collision/Penetration.h"

#include "collision/Sat.h"

#include <cmath>
#include <limits>

namespace rl {

namespace {

// A point inside a convex polyhedron leaves it fastest through the nearest face plane: exact, no iteration.
PenetrationResult pointInPolyhedron(const Vec3& pointWorld, const Shape& poly, const Transform& xf) {
    const ConvexPolyhedron& P = *poly.polyhedron;
    const Vec3 local = xf.applyInverse(pointWorld);
    Real best = -std::numeric_limits<Real>::infinity();
    Vec3 n(0.0, 1.0, 0.0);
    for (const PolyFace& f : P.faces) {
        const Real sep = glm::dot(f.normal, local) - f.offset;
        if (sep > best) {
            best = sep;
            n = f.normal;
        }
    }
    PenetrationResult r;
    r.separation = best;     // <= 0 inside
    r.normal = xf.rotate(n); // outward from the polyhedron
    r.pointA = pointWorld;
    r.pointB = pointWorld - best * r.normal;
    r.method = PenetrationMethod::SatFallback;
    return r;
}

} // namespace

PenetrationResult signedDistance(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                                 const PenetrationOptions& options) {
    PenetrationResult r;
    const GjkResult gjk = gjkDistance(a, xfA, b, xfB, options.gjk);
    if (gjk.coreDistance > 0.0) {
        r.separation = gjk.distance;
        r.normal = gjk.normal;
        r.pointA = gjk.pointA;
        r.pointB = gjk.pointB;
        r.method = PenetrationMethod::Gjk;
        return r;
    }
    const Real rA = a.coreRadius(), rB = b.coreRadius();
    if (!a.isPolyhedral() && !b.isPolyhedral()) {
        // Coincident centres: every direction is as good; +y is the documented choice.
        r.separation = -(rA + rB);
        r.normal = Vec3(0.0, 1.0, 0.0);
        r.pointA = xfA.position + rA * r.normal;
        r.pointB = xfB.position - rB * r.normal;
        r.method = PenetrationMethod::Analytic;
        return r;
    }
    const EpaResult epa = epaPenetration(a, xfA, b, xfB, gjk, options.epa);
    r.epaStatus = epa.status;
    if (epa.status == EpaStatus::Converged ||
        (epa.status == EpaStatus::BudgetExceeded && a.isPolyhedral() && b.isPolyhedral() && !satAffordable(a, b))) {
        r.separation = -epa.depth;
        r.normal = epa.normal;
        r.pointA = epa.pointA;
        r.pointB = epa.pointB;
        r.method = PenetrationMethod::Epa;
        return r;
    }
    // Fallbacks: exact and non-iterative, so they cannot fail in turn.
    if (!a.isPolyhedral()) {
        PenetrationResult p = pointInPolyhedron(xfA.position, b, xfB);
        r.normal = -p.normal;
        r.separation = p.separation - rA;
        r.pointA = xfA.position + rA * r.normal;
        r.pointB = p.pointB;
        r.method = PenetrationMethod::SatFallback;
        r.epaStatus = epa.status;
        return r;
    }
    if (!b.isPolyhedral()) {
        PenetrationResult p = pointInPolyhedron(xfB.position, a, xfA);
        r.normal = p.normal;
        r.separation = p.separation - rB;
        r.pointB = xfB.position - rB * r.normal;
        r.pointA = p.pointB;
        r.method = PenetrationMethod::SatFallback;
        r.epaStatus = epa.status;
        return r;
    }
    const SatResult sat = satPolyhedra(a, xfA, b, xfB);
    r.separation = sat.separation;
    r.normal = sat.normal;
    r.method = PenetrationMethod::SatFallback;
    if (sat.feature == SatFeature::EdgePair) {
        r.pointA = sat.pointA;
        r.pointB = sat.pointB;
    } else if (sat.feature == SatFeature::FaceA) {
        r.pointB = worldSupportCore(b, xfB, -sat.normal);
        r.pointA = r.pointB - sat.separation * sat.normal;
    } else {
        r.pointA = worldSupportCore(a, xfA, sat.normal);
        r.pointB = r.pointA + sat.separation * sat.normal;
    }
    return r;
}

} // namespace rl
