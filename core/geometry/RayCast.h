// Ray casts against single convex shapes placed in the world: sphere, oriented box and convex hull.
// They give the exact first hit (distance, point, outward normal) that scene queries and editor picking report.
#pragma once

#include "geometry/ConvexHull.h"
#include "math/Types.h"

#include <optional>

namespace rl {

// A half-line. The direction need not be unit length (it is normalised); distances are in metres along it.
struct Ray {
    Vec3 origin{0.0};
    Vec3 direction{0.0, 0.0, -1.0};
};

struct ShapeRayHit {
    Real distance = 0.0; // from the ray origin, metres
    Vec3 point{0.0};     // world space
    Vec3 normal{0.0};    // unit outward surface normal at the point, world space
};

// What a ray that starts inside a solid shape reports.
enum class RayStartInside {
    // A hit at distance 0, at the origin, with normal = -direction: the shapes are treated as solid, which is what
    // overlap-style queries want.
    Hit,
    // No hit: picking from a camera inside a large anchor should see the bodies beyond it.
    Ignore,
};

// Each function returns nullopt when the ray misses within maxDistance, and also for unusable input: a zero or
// non-finite direction, a non-finite origin, a NaN maxDistance, or a degenerate shape. maxDistance may be infinite.
// Grazing rays (tangent to a sphere, along a face) count as hits.
std::optional<ShapeRayHit> raySphere(const Ray& ray, Real maxDistance, const Vec3& center, Real radius,
                                     RayStartInside inside = RayStartInside::Hit);

// A box with the given half extents, centred at center and rotated by orientation.
std::optional<ShapeRayHit> rayBox(const Ray& ray, Real maxDistance, const Vec3& center, const Quat& orientation,
                                  const Vec3& halfExtents, RayStartInside inside = RayStartInside::Hit);

// A hull in body coordinates, placed by world = position + orientation * body. Solid hulls are clipped against
// their face planes. Flat hulls (a Blender plane used as an anchor) are two-sided: the normal faces the ray, and
// a ray can never start inside them. Empty, point and line hulls have no surface and are never hit.
std::optional<ShapeRayHit> rayHull(const Ray& ray, Real maxDistance, const ConvexHull& hull, const Vec3& position,
                                   const Quat& orientation, RayStartInside inside = RayStartInside::Hit);

} // namespace rl
