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
    std::vector<Vec3> vertices;       // only the points that are hull vertices
    std::vector<HullFace> faces;      // Solid: closed polyhedron. Flat: two faces, the polygon and its reverse.
    std::vector<uint32_t> inputIndex; // for each hull vertex, the index of the input point it came from
    // Absolute distance tolerance the hull was built with (m). Every input point lies behind every face plane, and
    // the vertices of a face lie on its plane, to within a few of these or of faceTolerance, whichever is larger.
    Real tolerance = 0.0;
    // Distance within which the vertices of a merged face lie of its plane (>= tolerance; see HullOptions).
    Real faceTolerance = 0.0;
    // Solid hulls: the hull's triangles before faces were merged, three corners each (input coordinates), for mass
    // properties that do not depend on how a face bent within faceTolerance is split.
    std::vector<Vec3> triangleCorners;

    bool isSolid() const { return dimension == HullDimension::Solid; }
};

struct HullOptions {
    // Distance tolerance relative to the point set's extent (bounding-box diagonal): points closer than this to a
    // face are coplanar. It never goes below the rounding of the coordinates (a small object far from the origin).
    // Non-positive or non-finite values mean the default.
    Real relativeTolerance = 1e-10;
    // Triangles merge into one polygon face while their vertices lie within min(2e-6 m, this x the extent) of one
    // plane (2e-6 m: the rounding of six-decimal coordinates, as Blender writes them) and the outline stays convex.
    // Looser than relativeTolerance because the input is rounded; ConvexHull::faceTolerance reports the value used.
    Real faceMergeTolerance = 1e-4;
};

// Never fails: degenerate input gives a lower dimension. Non-finite input points are ignored. A point set thinner
// than 64 tolerances is Flat (its faces then lie within that thickness of the points). Solid faces are convex
// polygons: triangles within the tolerance of one plane are merged when their outline stays convex.
ConvexHull computeConvexHull(std::span<const Vec3> points, const HullOptions& options = {});

} // namespace rl
