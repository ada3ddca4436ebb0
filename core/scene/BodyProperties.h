// Physical properties derived from a body definition: collision hull, volume, mass, centre of mass, inertia, warnings.
// Derived data is recomputed from the definition whenever it is needed; definitions never cache it.
#pragma once

#include "common/Result.h"
#include "geometry/ConvexHull.h"
#include "math/Types.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace rl {

struct BodyProperties {
    ConvexHull hull;            // collision hull in shape coordinates (empty for spheres, which collide exactly)
    Real volume = 0.0;          // m^3 of the collision shape; 0 for a flat anchor
    Real density = 0.0;         // kg/m^3 actually used (mass / volume when the mass is overridden)
    Real mass = 0.0;            // kg; computed for anchors too, though the world treats them as immovable
    Vec3 com{0.0};              // centre of mass in world space (a flat anchor: its area centroid)
    Mat3 inertia{0.0};          // kg m^2, world axes, about the centre of mass
    Vec3 principalMoments{0.0}; // ascending
    Vec3 vertexMean{0.0};       // world position of the plain mean of the shape's vertices (the .bake reference point)
    int hullVertexCount = 0;    // 0 for spheres
    bool flat = false;          // zero thickness (only valid for anchors)
    bool concave = false;       // the mesh is not convex; it is simulated as its convex hull
    std::vector<std::string> warnings;
};

// Fails (naming the body) for shapes that cannot be simulated: a dynamic body without volume, non-finite numbers,
// non-positive sizes, densities or masses.
Result<BodyProperties> computeBodyProperties(const Scene& scene, const BodyDef& body);

// The points of the body's shape in shape coordinates (box corners, hull points, mesh vertices; a sphere's centre).
std::vector<Vec3> shapePoints(const ShapeDef& shape);

// Rigid transform from shape coordinates to world coordinates.
inline Vec3 shapeToWorld(const BodyDef& body, const Vec3& p) {
    return body.position + body.orientation * p;
}

} // namespace rl
