// Collision shapes of the narrowphase: spheres, boxes and convex polyhedra (solid hulls and flat two-sided polygons),
// with the rigid transform that places them, their support functions and their local bounds.
#pragma once

#include "collision/Aabb.h"
#include "common/Result.h"
#include "geometry/ConvexHull.h"
#include "math/Types.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace rl {

// Shape coordinates to world: x_world = position + rotation * x_local. A matrix, not a quaternion, because the
// narrowphase rotates many directions per query and a matrix does that in 9 multiplies.
struct Transform {
    Vec3 position{0.0};
    Mat3 rotation{1.0};

    static Transform fromQuat(const Vec3& position, const Quat& orientation) {
        return {position, glm::mat3_cast(glm::normalize(orientation))};
    }
    Vec3 apply(const Vec3& local) const { return position + rotation * local; }
    Vec3 applyInverse(const Vec3& world) const { return glm::transpose(rotation) * (world - position); }
    Vec3 rotate(const Vec3& v) const { return rotation * v; }
    Vec3 rotateInverse(const Vec3& v) const { return glm::transpose(rotation) * v; }
};

// One polygon face of a polyhedron: its vertex loop (counter-clockwise seen from outside) and its plane.
struct PolyFace {
    uint32_t first = 0; // into ConvexPolyhedron::faceVertices
    uint32_t count = 0;
    Vec3 normal{0.0};  // unit, outward
    Real offset = 0.0; // dot(normal, x) == offset on the face
};

// An edge with the two faces that meet at it. The Gauss-map pruning of the SAT edge query needs both normals.
struct PolyEdge {
    uint32_t v0 = 0;
    uint32_t v1 = 0;
    uint32_t face0 = 0; // the face that walks v0 -> v1
    uint32_t face1 = 0; // the face that walks v1 -> v0
};

// A convex polyhedron in shape coordinates. A flat one (a Blender plane used as an anchor) has two faces, the
// polygon and its reverse, and zero thickness; the narrowphase treats it as a two-sided thin floor.
struct ConvexPolyhedron {
    std::vector<Vec3> vertices;
    std::vector<PolyFace> faces;
    std::vector<uint32_t> faceVertices;
    std::vector<PolyEdge> edges;
    // For each vertex, its neighbours along edges: the support function climbs this graph on big hulls.
    std::vector<uint32_t> neighbourStart; // vertices.size() + 1 entries
    std::vector<uint32_t> neighbours;
    Vec3 centroid{0.0}; // vertex mean: an interior point (for flat shapes, a point of the polygon)
    // The vertices' bounding box, taken once: the SAT asks for the shapes' smallest widths on every call.
    Aabb bounds;
    bool flat = false;

    // Set when the polyhedron is a rectangular box: 8 vertices, 6 faces in three pairs of opposite faces at right
    // angles (to 1e-6, as exported cubes are), so the SAT can measure its axes by projection (see Sat.cpp).
    struct BoxFeatures {
        Vec3 center{0.0};
        Vec3 axis[3];        // unit, orthonormal, right-handed
        Real half[3] = {};   // half extents along the axes
        Real reach[3] = {};  // the largest |(v - center) . axis[i]| over the vertices: half[i] to within the fit
        uint32_t face[3][2]; // face index with normal +axis[i] ([i][0]) and -axis[i] ([i][1])
        uint32_t edge[3][4]; // edge index parallel to axis[i]: bit 0 set if it lies on the - side of axis[(i+1)%3],
                             // bit 1 if on the - side of axis[(i+2)%3]
    };
    bool isBox = false;
    BoxFeatures box;

    uint32_t supportIndex(const Vec3& direction) const;
    Vec3 support(const Vec3& direction) const { return vertices[supportIndex(direction)]; }
};

enum class ShapeKind : uint8_t { Sphere, Box, Polyhedron };

// A small value type: kind, sizes, and a shared immutable polyhedron (boxes carry one too, for the SAT and the
// face clipping, so every polyhedral path handles boxes and hulls alike).
struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    Real radius = 0.0;                                  // Sphere
    Vec3 halfExtents{0.0};                              // Box
    std::shared_ptr<const ConvexPolyhedron> polyhedron; // Box and Polyhedron

    // Support of the full shape, shape coordinates.
    Vec3 support(const Vec3& direction) const;
    // Support of the core used by GJK: spheres shrink to their centre, so GJK stays exact and margin-free and the
    // radius is added afterwards.
    Vec3 supportCore(const Vec3& direction) const;
    Real coreRadius() const { return kind == ShapeKind::Sphere ? radius : 0.0; }
    bool isPolyhedral() const { return kind != ShapeKind::Sphere; }
    bool isFlat() const { return polyhedron && polyhedron->flat; }

    Aabb localBounds() const;
    Aabb worldBounds(const Transform& xf) const;
    // An upper bound of dot(direction, x) over the shape's points x placed by xf, for a unit world direction: the
    // exact support for spheres and hulls; for a box, its centre plus its reaches along its axes, within rounding
    // (as worldBounds()), which takes no support query.
    Real reachAlong(const Transform& xf, const Vec3& direction) const;
    // Largest distance from the shape origin to any point of the shape: bounds the speed of a rotating point.
    Real boundingRadius() const;
    // Smallest width of the local bounds (0 for a flat polygon): the CCD criterion compares motion with it.
    Real minExtent() const;
    Vec3 centre() const { return polyhedron ? polyhedron->centroid : Vec3(0.0); }
};

// How far a (placed by xfA) and b (by xfB) overlap along the unit direction n, from A to B: reach of a along n plus
// reach of b along -n (Shape::reachAlong()). No point of the two is deeper in the other than this; negative: they are
// apart by at least its magnitude.
inline Real overlapAlongAxis(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                             const Vec3& n) {
    return a.reachAlong(xfA, n) + b.reachAlong(xfB, -n);
}

Result<Shape> makeSphere(Real radius);
Result<Shape> makeBox(const Vec3& halfExtents);
// Solid and flat hulls are accepted; empty, point and line hulls, open or non-finite hulls are errors.
Result<Shape> makeHull(const ConvexHull& hull);

// Hulls built by hand (until and besides computeConvexHull): a box's eight corners, a prism over a convex polygon.
ConvexHull boxHull(const Vec3& halfExtents);
ConvexHull prismHull(const std::vector<Vec3>& polygonXZ, Real halfHeight);        // polygon CCW seen from +y, y ignored
ConvexHull flatPolygonHull(const std::vector<Vec3>& polygon, const Vec3& normal); // CCW seen from +normal

} // namespace rl
