#include "collision/RayCast.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl {

static bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

RayHit castRay(const BroadPhase& broadPhase, const Ray& ray, Real maxDistance, const ShapeRayTest& testShape) {
    RayHit best;
    const Real length = glm::length(ray.direction);
    if (!testShape || !isFinite(ray.origin) || !(length > 0.0) || !std::isfinite(length) || std::isnan(maxDistance) ||
        maxDistance < 0.0)
        return best;
    const Ray unitRay{ray.origin, ray.direction / length};

    // With a unit direction, tree fractions are distances, so the best hit so far clips the traversal directly.
    broadPhase.rayCast(unitRay.origin, unitRay.direction, maxDistance, [&](ProxyKey key, Real currentMax) -> Real {
        const uint32_t id = broadPhase.bodyId(key);
        const std::optional<ShapeRayHit> h = testShape(id, unitRay, currentMax);
        // A shape test that returns garbage must not leak it into the answer.
        if (!h || !std::isfinite(h->distance) || h->distance < 0.0 || h->distance > currentMax || !isFinite(h->point) ||
            !isFinite(h->normal))
            return -1.0;
        const bool closer =
            !best.hit || h->distance < best.distance || (h->distance == best.distance && id < best.bodyId);
        if (closer) {
            best.hit = true;
            best.bodyId = id;
            best.proxy = key;
            best.distance = h->distance;
            best.point = h->point;
            best.normal = h->normal;
        }
        // Keep visiting boxes that start exactly at the best distance, for the tie rule. A hit at distance 0 must
        // not be returned as 0, which the tree reads as "stop" before the other ties at 0 are seen.
        return std::max(best.distance, std::numeric_limits<Real>::min());
    });
    return best;
}

} // namespace rl
