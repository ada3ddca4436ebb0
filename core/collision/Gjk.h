// GJK: distance, closest points and boolean overlap of two convex shapes placed by transforms.
// The core is exact and margin-free (spheres shrink to their centres), and every loop has an iteration bound.
#pragma once

#include "collision/Shape.h"
#include "math/Types.h"

namespace rl {

// One vertex of the simplex of the Minkowski difference A - B, with the support points that made it.
struct SimplexVertex {
    Vec3 a{0.0}; // support point of A (world)
    Vec3 b{0.0}; // support point of B (world)
    Vec3 w{0.0}; // a - b
};

struct GjkOptions {
    // GJK on polytopes ends in a finite number of steps; this bound only matters for degenerate input. The
    // 2,000-vertex test hull needed at most 9 (tst_gjk bigHull), so 64 leaves a wide margin.
    int maxIterations = 64;
};

enum class GjkStatus : uint8_t { Separated, Overlapping, MaxIterations };

struct GjkResult {
    GjkStatus status = GjkStatus::Separated;
    // Distance between the full shapes (radii included). Negative when only the radii overlap (sphere cases):
    // then it is the exact signed penetration. 0 when the cores overlap (touching included): ask EPA for depth.
    Real distance = 0.0;
    Real coreDistance = 0.0;    // distance between the cores
    Vec3 pointA{0.0};           // closest point on A, world
    Vec3 pointB{0.0};           // closest point on B, world
    Vec3 normal{0.0, 1.0, 0.0}; // unit, from A to B; meaningful when coreDistance > 0
    int iterations = 0;
    int simplexCount = 0;
    SimplexVertex simplex[4];
};

// Support of a shape's core in a world direction, as a world point.
inline Vec3 worldSupportCore(const Shape& s, const Transform& xf, const Vec3& direction) {
    return xf.apply(s.supportCore(xf.rotateInverse(direction)));
}

GjkResult gjkDistance(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                      const GjkOptions& options = {});

// Overlap of the full shapes; touching (distance 0) counts as overlapping, as closed sets do.
bool gjkOverlap(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                const GjkOptions& options = {});

// Relative size under which GJK calls the cores touching: |v| <= kGjkTouchTolerance * (size of the problem).
inline constexpr Real kGjkTouchTolerance = 1e-10;

} // namespace rl
