// Separating-axis test between convex polyhedra: face normals of both and edge-pair axes pruned on the Gauss map
// (Gregorius, GDC 2013). Exact for polyhedra; the manifold builder uses its features, and EPA falls back to it.
#pragma once

#include "collision/Shape.h"

#include <cstdint>
#include <limits>

namespace rl {

enum class SatFeature : uint8_t { FaceA, FaceB, EdgePair };

struct SatOptions {
    // Stop as soon as an axis separates by more than this: the pair is then of no interest.
    Real earlyOut = std::numeric_limits<Real>::infinity();
    // Face axes win over edge axes (and A's faces over B's) unless the other is deeper by this much. Preferring
    // faces keeps the manifold from flickering between one edge point and a face patch on near ties. 0 gives the
    // exact maximum, which the depth tests use.
    Real faceBias = 0.0;
    // ... plus these fractions of the incumbent's separation (Gregorius, GDC 2015: 0.98 for B's faces against A's,
    // 0.9 for edges against faces). In deep or shallow contact alike, a near tie then keeps the face: nearly parallel
    // faces of a stack otherwise flip between A's face, B's face and an edge pair frame to frame, each with new
    // feature ids, so warm starting is lost and the pile never comes to rest. 1 gives the plain absolute bias.
    Real faceRelative = 1.0;
    Real edgeRelative = 1.0;
    // Two boxes are measured by projection onto their axes (the same axes and choice, a few times faster). Off:
    // the general query, which tests compare it with.
    bool useBoxes = true;
};

struct SatResult {
    Real separation = -std::numeric_limits<Real>::infinity(); // > 0 separated, < 0 penetration depth (negated)
    Vec3 normal{0.0, 1.0, 0.0};                               // world, unit, from A to B
    SatFeature feature = SatFeature::FaceA;
    uint32_t face = 0;  // FaceA: A's face, FaceB: B's face
    uint32_t edgeA = 0; // EdgePair
    uint32_t edgeB = 0;
    Vec3 pointA{0.0}; // EdgePair: closest points of the two edges, world
    Vec3 pointB{0.0};
    // FaceA and FaceB: the other shape's best face axis, which lost the choice (normal world, from A to B; separation
    // -infinity if none). Where the two nearly tie at an angle, the faces meet rim to rim (collidePolyhedra()).
    Real rivalSeparation = -std::numeric_limits<Real>::infinity();
    Vec3 rivalNormal{0.0};
};

// Both shapes must be polyhedral (boxes or hulls). A flat polygon only offers the face whose normal points to the
// other shape's centre, so a body on a thin floor is pushed back to the side it is on.
SatResult satPolyhedra(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                       const SatOptions& options = {});

// The SAT's edge query visits edgesA * edgesB pairs. Above this many, an EPA that ran out of budget keeps its own
// bracketed answer (depth between its lower and upper bound) instead of falling back to the quadratic SAT;
// a degenerate EPA still falls back, whatever the cost, because it has no answer at all.
inline constexpr size_t kSatFallbackMaxEdgePairs = size_t(1) << 20;

inline bool satAffordable(const Shape& a, const Shape& b) {
    return a.polyhedron->edges.size() * b.polyhedron->edges.size() <= kSatFallbackMaxEdgePairs;
}

// Closest points of segments p0-p1 and q0-q1 (Ericson 5.1.9), used for edge contacts.
void closestPointsSegments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& onP, Vec3& onQ);

} // namespace rl
