#include "collision/Ccd.h"

#include "collision/Gjk.h"

#include <algorithm>
#include <cmath>

namespace rl {

Transform Motion::at(Real time) const {
    Transform xf;
    xf.position = start.position + linearVelocity * time;
    const Real angle = glm::length(angularVelocity) * time;
    if (angle > 0.0) {
        const Quat q = glm::angleAxis(angle, glm::normalize(angularVelocity));
        xf.rotation = glm::mat3_cast(q) * start.rotation;
    } else {
        xf.rotation = start.rotation;
    }
    return xf;
}

ToiResult timeOfImpact(const Shape& a, const Motion& motionA, const Shape& b, const Motion& motionB, Real dt,
                       const ToiOptions& options) {
    ToiResult result;
    if (!(dt > 0.0) || !std::isfinite(dt))
        return result;
    // A point of a rotating shape moves at most |omega| * r, r its distance from the rotation centre.
    const Real rA = a.boundingRadius(), rB = b.boundingRadius();
    const Real angularBound = glm::length(motionA.angularVelocity) * rA + glm::length(motionB.angularVelocity) * rB;
    const Vec3 relative = motionB.linearVelocity - motionA.linearVelocity;
    const Real target = std::max(options.targetSeparation, 0.0);
    const Real tolerance = std::max(options.tolerance, 1e-9);
    Real t = 0.0; // seconds into the step
    const int maxIterations = std::max(1, options.maxIterations);
    for (int iter = 0; iter < maxIterations; ++iter) {
        const Transform xa = motionA.at(t), xb = motionB.at(t);
        const GjkResult g = gjkDistance(a, xa, b, xb);
        result.iterations = iter + 1;
        result.distance = g.distance;
        if (g.coreDistance > 0.0)
            result.normal = g.normal;
        result.fraction = t / dt;
        if (g.distance <= target + tolerance) {
            result.status = (iter == 0 && g.distance < target - tolerance) ? ToiStatus::Overlapping : ToiStatus::Hit;
            return result;
        }
        // Along the current normal the gap closes no faster than this (Mirtich): the linear closing speed plus
        // the fastest a rotating support point can move. Advancing by gap / bound can never overshoot contact.
        const Real bound = -glm::dot(relative, g.normal) + angularBound;
        if (!(bound > 0.0)) {
            result.status = ToiStatus::Miss;
            result.fraction = 1.0;
            return result;
        }
        t += (g.distance - target) / bound;
        if (t >= dt) {
            result.status = ToiStatus::Miss;
            result.fraction = 1.0;
            return result;
        }
    }
    // The last measured time, whose distance is known; the advanced t would be safe too, but unmeasured.
    result.status = ToiStatus::NotConverged;
    return result;
}

bool needsCcd(const Shape& shape, const Vec3& linearVelocity, const Vec3& angularVelocity, Real dt,
              Real extentFraction) {
    const Real travel = (glm::length(linearVelocity) + glm::length(angularVelocity) * shape.boundingRadius()) * dt;
    return travel > extentFraction * shape.minExtent();
}

} // namespace rl
