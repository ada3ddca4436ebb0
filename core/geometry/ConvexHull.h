// Convex hull of a point set (3D quickhull) with coplanar faces merged into polygons.
// Robust to duplicate and coplanar points; a flat point set yields a two-sided polygon.
#pragma once

#include "math/Types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rl {

struct HullFace {
    std::vector<uint32_t> vertices; // indices into ConvexHull::vertices, counter-clockwise seen from outside
    Vec3 normal{0.0};               // unit outward normal
    Real offset = 0.0;              // plane: dot(normal, x) == offset
};

enum class HullDimension { Empty, Point, Line, Flat, Solid };

struct ConvexHull {
    HullDimension dimension = HullDimension::Empty;
    std::vector<Vec3> vertices;   // only the points that are hull vertices
    std::vector<HullFace> faces;  // Solid: closed polyhedron. Flat: two faces, the polygon and its reverse.
    std::vector<uint32_t> inputIndex; // for each hull vertex, the index of the input point it came from

    bool isSolid() const { return dimension == HullDimension::Solid; }
};

struct HullOptions {
    // Distance tolerance relative to the point set's extent: points closer than this to a face are coplanar.
    Real relativeTolerance = 1e-10;
};

// Never fails: degenerate input gives a lower dimension. Non-finite input points are ignored.
ConvexHull computeConvexHull(std::span<const Vec3> points, const HullOptions& options = {});

} // namespace rl
