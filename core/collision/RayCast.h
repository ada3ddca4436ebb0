// Scene ray query: the closest body hit by a ray, found through the broadphase trees and an exact shape test.
// The editor's picking uses it; the caller supplies the per-body shape test, so no shape class is assumed here.
#pragma once

#include "collision/BroadPhase.h"
#include "geometry/RayCast.h"
#include "math/Types.h"

#include <cstdint>
#include <functional>
#include <optional>

namespace rl {

struct RayHit {
    bool hit = false;
    uint32_t bodyId = 0; // the id given to BroadPhase::createProxy
    ProxyKey proxy;
    Real distance = 0.0; // metres along the normalised ray direction
    Vec3 point{0.0};     // world space
    Vec3 normal{0.0};    // unit outward normal of the body's surface, world space
};

// Exact test of one body, called only for bodies whose fat box the ray reaches within maxDistance. Returns nullopt
// to report a miss, which is also how a caller filters bodies out (for example anchors, when picking).
using ShapeRayTest = std::function<std::optional<ShapeRayHit>(uint32_t bodyId, const Ray& ray, Real maxDistance)>;

// The closest hit within maxDistance (which may be infinite) over both trees. Ties in distance go to the smaller
// body id, so the answer does not depend on the tree layout. The ray direction is normalised here; an unusable ray
// (zero or non-finite direction, non-finite origin, NaN or negative maxDistance) hits nothing.
RayHit castRay(const BroadPhase& broadPhase, const Ray& ray, Real maxDistance, const ShapeRayTest& testShape);

} // namespace rl
