// Contact manifold generation for a pair of shapes: the normal from SAT (or GJK/EPA), the incident face clipped
// against the reference face, and a reduction to the four points that keep the largest area.
#pragma once

#include "collision/Epa.h"
#include "collision/Manifold.h"
#include "collision/Shape.h"

#include <optional>

namespace rl {

// How polyhedron pairs (boxes and hulls) find their contact normal and features. Both are exact. The SAT's edge
// query costs edgesA * edgesB, GJK/EPA grows with the vertex count only. bench_narrowphase measured the SAT faster
// for box-box (12 x 12 edge pairs) and GJK/EPA faster for 32-vertex hulls (48 x 48), so Auto takes the SAT up to
// box-box size (and for flat anchors, whose side rule lives in the SAT) and GJK/EPA above it, falling back to the
// SAT when EPA gives up.
enum class PolyhedronMethod : uint8_t { Auto, Sat, GjkEpa };

// Auto uses the SAT while edgesA * edgesB is at most this: the box-box count.
inline constexpr size_t kSatMaxEdgePairs = 144;

struct CollideOptions {
    PolyhedronMethod method = PolyhedronMethod::Auto;
    // Face contacts win over edge contacts (and A's face over B's) unless the other axis separates more by this much
    // (m) plus a fraction of the incumbent's separation (see SatOptions). A face patch is more stable to stack on
    // than a single edge point, and near ties would otherwise flicker frame to frame: with 0.1 mm and no relative
    // part, a box resting tilted on another in the 1,000-box pile switched between A's face, B's face and an edge
    // every frame and kept the pile creeping at 0.17 m/s (issue 4). Gregorius (GDC 2015) uses half the linear slop
    // and 0.98 / 0.9. The absolute part is capped at 1 % of the smaller shape, and flat polygons keep 0.1 mm with no
    // relative part (Sat.cpp says why).
    Real faceBias = 0.0025;
    Real faceRelative = 0.98;
    Real edgeRelative = 0.9;
    EpaOptions epa; // when EPA runs out of budget the SAT answers instead
    // A contact between two edges that overlap is one point at the edges' witnesses, unless the speculative distance
    // is at least this (m): then the faces facing each other along the axis are clipped as for edges apart
    // (separations no deeper than the edges' overlap), so that the far side of a shape turning or closing fast
    // meets the other within the step. At rest the one point is kept: clipped at any speed, three of the first 116
    // seeds' piles of 1,000 boxes (scenes::randomBoxes()) still moved after 10 s, none with the one point; from
    // twice the speculative distance on (World::collidePair()), 5 of seeds 1-288 against 2 (2026-12-06).
    Real clipOverlappingEdgesFrom = std::numeric_limits<Real>::infinity();
};

// Fills `out` (normal from A to B, up to 4 points, separation < 0 in penetration) and returns true when the
// shapes touch or are closer than speculativeDistance; points with 0 < separation <= speculativeDistance are
// speculative contacts for the solver. out.bodyA/bodyB are left alone; impulses are zeroed (see ContactCache).
// localA/localB are in each shape's coordinates: pass transforms whose origin is the body's centre of mass.
// Non-finite transforms give no contact rather than NaN.
// On false, out.normal is either zero or a unit axis (A to B) along which the shapes are apart by more than
// speculativeDistance: the world keeps it and tests it first next step (see World::collidePair()).
bool collide(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, Real speculativeDistance,
             Manifold& out, const CollideOptions& options = {});

// How far a point outside a shape is from its surface along the unit direction d: the ray's entry distance, or none
// if the ray misses the shape or starts inside it. A flat polygon is hit within its outline, from either side.
std::optional<Real> distanceAlong(const Shape& s, const Transform& xf, const Vec3& origin, const Vec3& d);

// Points for the corners a turning body brings into contact within the step. A manifold holds the features nearest at
// the step's start; a hull turning fast (a tumbling cone's rim, of which the reduction keeps four corners; a cylinder
// tumbling end over end) brings others down within the step, which the solver, following the manifold's anchors as
// they turn, does not see until the next step, after they have gone in. For each side with a turn (its rotation over
// the step about its centre of mass, the origin of its transform; identity for none), the corner nearest the other
// side in the pose half way through the turn and in the turned pose is a candidate; it counts if, turned, it comes
// nearer than every point of the manifold by more than 1 mm, and if the other shape is straight ahead of it along the
// normal (its gap is that distance: a corner over nothing is left out). The manifold is then reduced to four again
// as collide() does, the nearest by the gaps once turned. Spheres and empty manifolds are left alone.
void addTurnedSupports(const Shape& a, const Transform& xfA, const Quat& turnA, const Shape& b, const Transform& xfB,
                       const Quat& turnB, Manifold& m);

// The reduction on its own, for the tests: picks up to 4 of `count` points lying on a plane with unit normal
// `normal`: the deepest, then the farthest touching point if any other touches while some are apart, then greedily
// the largest area, then single swaps while the area grows. On 500 random sets of touching points tst_manifold
// measured at least 0.889 of the best quadrilateral through the deepest point. Writes the chosen indices, returns
// how many.
int reduceContactPoints(const Vec3* points, const Real* separations, int count, const Vec3& normal, int chosen[4]);

} // namespace rl
