// Volume, centre of mass and inertia tensor of closed polyhedra, exact by the divergence theorem.
// Flat shapes (Blender planes) have no volume; they report their area and area centroid instead.
#pragma once

#include "geometry/ConvexHull.h"
#include "math/Types.h"

#include <array>
#include <span>

namespace rl {

struct MassProperties {
    Real volume = 0.0;  // m^3; 0 for flat shapes
    Real area = 0.0;    // surface area (flat: one side)
    Vec3 centroid{0.0}; // centre of volume (flat: area centroid)
    Mat3 inertia{0.0};  // per unit density, about the centroid, in the input axes (kg m^2 per kg/m^3)
};

// Closed, consistently oriented (outward, counter-clockwise) triangle mesh.
MassProperties polyhedronMassProperties(std::span<const Vec3> vertices,
                                        std::span<const std::array<uint32_t, 3>> triangles);

// Mass properties of a hull. Solid hulls use the triangles they were built from (ConvexHull::triangleCorners), or
// their faces fan-triangulated when those are absent; flat ones report area data.
MassProperties hullMassProperties(const ConvexHull& hull);

// Inertia tensor moved from the centroid to another point (parallel axis), for a body of mass m.
Mat3 shiftInertia(const Mat3& inertiaAboutCentroid, Real mass, const Vec3& offsetFromCentroid);

// Inertia expressed in other axes: R * I * R^T.
Mat3 rotateInertia(const Mat3& inertia, const Mat3& rotation);

// Principal moments (ascending) and axes (columns) of a symmetric 3x3 tensor, by Jacobi rotations.
void principalAxes(const Mat3& inertia, Vec3& moments, Mat3& axes);

} // namespace rl
