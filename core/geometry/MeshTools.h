// Mesh utilities: primitive meshes (box, UV sphere, cylinder, cone), hull triangulation, closed-mesh volume,
// welding, and the concavity test behind the importer's "concave mesh collides as its hull" warning.
#pragma once

#include "geometry/ConvexHull.h"
#include "geometry/TriangleMesh.h"
#include "math/Types.h"

#include <array>
#include <cstdint>
#include <span>

namespace rl {

// Default for isConcave: a dent shallower than 0.1% of the mesh's size is not worth a warning, and OBJ exporters
// round coordinates to about six digits, so tighter tests would flag convex meshes written to a file.
inline constexpr Real kConcavityRelativeTolerance = 1e-3;

// Primitives, centred on the origin, Y-up, counter-clockwise from outside, vertices shared between triangles.
// Non-finite or non-positive sizes give an empty mesh; segment and ring counts are clamped to [3, 1024] / [2, 1024].
TriangleMesh makeBoxMesh(Vec3 halfExtents);
TriangleMesh makeUvSphereMesh(Real radius, int segments, int rings);
// Axis along Y, caps at y = -halfHeight and y = +halfHeight.
TriangleMesh makeCylinderMesh(Real radius, Real halfHeight, int segments);
// Base disc at y = -halfHeight, apex at y = +halfHeight (the bounding box is centred, not the centre of mass).
TriangleMesh makeConeMesh(Real radius, Real halfHeight, int segments);

// A hull's faces fan-triangulated, outward. A flat hull gives both sides (a closed sheet of zero volume).
TriangleMesh hullMesh(const ConvexHull& hull);

// Vertices at exactly the same position merged, unused ones dropped, and triangles that collapse removed.
// Importers that copy a vertex per face corner (assimp's OBJ reader) need this before topology checks.
TriangleMesh weldVertices(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles);

// True when, after welding equal positions, every edge is shared by exactly two triangles in opposite directions.
bool isClosedMesh(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles);

// Volume enclosed by a closed mesh (divergence theorem), positive for either winding. Only meaningful when the mesh
// is closed; triangles with indices out of range are ignored.
Real closedMeshVolume(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles);

// True when the mesh is not its own convex hull: a mesh vertex lies inside the hull deeper than the tolerance times
// the hull's size, or the closed mesh encloses less volume than the hull by more than that fraction. For a flat
// hull the test is done in its plane (an L-shaped sheet is concave). Points and lines are never concave.
bool isConcave(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles,
               const ConvexHull& hull, Real relativeTolerance = kConcavityRelativeTolerance);

} // namespace rl
