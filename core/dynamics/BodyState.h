// Runtime state of N rigid bodies in structure-of-arrays form: the hot arrays the integrators and the contact solver
// sweep every substep, kept apart from the bookkeeping that is only read when a body is created, exported or inspected.
#pragma once

#include "common/Result.h"
#include "geometry/ConvexHull.h"
#include "math/Types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rl {

enum BodyFlag : uint8_t {
    kBodyStatic = 1u << 0, // infinite mass and inertia; never integrated
    kBodyAwake = 1u << 1,  // integrated and solved; a sleeping body is skipped until something wakes it
    // Round: where a contact holds it, its surface stays where its centre puts it however it turns (a ball), or
    // however it turns about BodyInfo::rollAxis (a cylinder, a cone), so the solver measures the contacts' separations
    // without that rotation (anchorTurn()).
    kBodyRound = 1u << 2,
};

// Why the inertia is stored as a diagonal in the principal frame (and not as a full body-frame tensor):
// - the body frame is chosen to be the principal frame, so the rotation that diagonalises the tensor is folded into
//   `orientation`. The inverse inertia is then 3 numbers instead of 6, its inverse is a division per axis, and the
//   implicit gyroscopic step (Gyroscopic.h) works on a diagonal matrix, which keeps its 3x3 Newton solve cheap;
// - the price is that `orientation` is not the user's shape orientation. The constant rotation between the two is
//   kept in the bookkeeping (`BodyInfo::shapeFromPrincipal`), and shapeOrientation() undoes it for exports.
// Positions are the centre of mass, again for the solver's sake; the shape origin is recovered the same way.

// The speed clamp. It exists so that a bad contact or a stiff setting cannot produce a runaway body that tunnels
// through the world or overflows to infinity; a scene that hits it is not simulated faithfully, and the counters
// below say so. The values are limits on what one substep may do, not physical constants.
struct SpeedLimits {
    // m/s. Well above DESIGN.md's fastest example body ("Shot", 300 m/s).
    Real maxLinearSpeed = 1000.0;
    // rad per substep: 45 degrees, the value Box2D uses. Past it the contact points and normals the solver linearised
    // at the start of the substep no longer describe where the body is, so faster spins are clamped, not solved
    // wrongly.
    Real maxRotationPerSubstep = 0.25 * kPi;
};

// How often the clamp changed a velocity since the counters were last reset. Non-zero means "this run was clamped".
struct ClampCounters {
    uint64_t linear = 0;
    uint64_t angular = 0;
    bool operator==(const ClampCounters&) const = default;
};

// Bookkeeping: read when a body is created, exported or shown in the inspector, never in the substep loop.
struct BodyInfo {
    Real mass = 0.0;                          // kg; 0 for static bodies
    Vec3 principalMoments{0.0};               // kg m^2, in the order of the principal frame's axes
    Quat shapeFromPrincipal = identityQuat(); // rotation from shape coordinates to the principal frame
    Vec3 comInShape{0.0};                     // centre of mass in shape coordinates
    // Principal-frame unit axis about which the shape is round (kBodyRound), or zero: round about every axis.
    Vec3 rollAxis{0.0};
};

// The contact solver sets up its rows once a step, with the bodies' inverse inertias at the step's start, and applies
// their impulses through each body's inverse inertia at the pose of the current substep. Where the two differ, a row's
// true velocity change per unit impulse K differs from the set-up one, and a sweep's correction of a row overshoots by
// m K - 1 (m its set-up mass): past 1, the row's impulse grows without bound. A needle of 20 x 0.2 x 0.2 cm (moments
// 5,000 to 1) landing on a floor spinning at 250 rad/s about its length and tumbling at 50 reached 1e124 rad/s within
// one step; of 540 rods of 5:1 to 100:1 dropped on a floor turning, 71 were thrown faster than 20 m/s or to infinity
// (2026-12-07; none since). A change B of the inverse inertia changes any K by at most |B| / (least inverse moment) of
// it. So where the drift since the step start passes this fraction of the least inverse moment, the solver takes the
// least inverse moment times the identity for the rest of the step: no K is then above its set-up value (the start's
// inverse inertia is at least that in every direction), so the sweeps converge, and the body turns under contact
// impulses as if as hard to turn about every axis as about its hardest. A body that spins about an axis of symmetry
// (a rod about its length, a top) does not drift.
inline constexpr Real kSolverInertiaDrift = 0.45;

// What a new body needs. Inertia is a full tensor about the centre of mass in *world* axes at the given orientation,
// as BodyProperties and MassProperties produce it; addBody() diagonalises it.
struct BodyInit {
    Vec3 centerOfMass{0.0};            // world
    Quat orientation = identityQuat(); // shape coordinates -> world
    Vec3 comInShape{0.0};              // centre of mass in shape coordinates (bookkeeping only)
    Real mass = 1.0;                   // kg, ignored for static bodies
    Mat3 inertia{1.0};                 // kg m^2, world axes, about the centre of mass; ignored for static bodies
    Vec3 linearVelocity{0.0};          // m/s, world
    Vec3 angularVelocity{0.0};         // rad/s, world
    Real linearDamping = 0.0;          // 1/s, added to the world's
    Real angularDamping = 0.0;         // 1/s, added to the world's
    bool isStatic = false;
    bool round = false; // kBodyRound
};

// The swing of a turn split as swing * twist, the twist about the unit axis.
Quat withoutTwist(const Quat& turn, const Vec3& axis);

struct BodyState {
    // ---- hot: swept by the integrators and the solver every substep, indexed by body ----
    std::vector<Vec3> position;        // centre of mass, world
    std::vector<Quat> orientation;     // principal frame -> world
    std::vector<Vec3> linearVelocity;  // m/s, world
    std::vector<Vec3> angularVelocity; // rad/s, world
    std::vector<Real> invMass;         // 1/kg; 0 for static bodies
    std::vector<Vec3> invInertia;      // 1/(kg m^2), diagonal in the principal frame; 0 for static bodies
    std::vector<Real> linearDamping;   // 1/s
    std::vector<Real> angularDamping;  // 1/s
    std::vector<uint8_t> flags;        // BodyFlag bits

    // ---- substep scratch: written by integrateVelocities(), read by integratePositions() (Integrator.h) ----
    // The motion the smooth forces alone prescribe over the substep. The position phase adds what the contact solver
    // changed on top of it, so each integrator keeps its own accuracy where no contact acts.
    std::vector<Vec3> smoothLinearVelocity;
    std::vector<Vec3> smoothDisplacement;
    std::vector<Vec3> smoothAngularVelocity;
    // World-frame rotation over the substep; written for explicit Euler and RK4 only (see Integrator.cpp).
    std::vector<Quat> smoothRotation;

    // ---- bookkeeping ----
    std::vector<BodyInfo> info;
    SpeedLimits limits;
    ClampCounters clampCounters;

    uint32_t size() const { return static_cast<uint32_t>(position.size()); }
    void clear(); // removes every body and resets the clamp counters; the limits are settings and stay
    void reserve(uint32_t n);

    // Makes this state a copy of the bodies `ids` of `from`, as bodies 0 .. ids.size() - 1 in that order: what the
    // integrators read and write (the smooth scratch is sized, not copied). A substep loop then runs over one
    // contiguous run of memory, and threads that take neighbouring runs share no cache line but the one between them.
    void gather(const BodyState& from, std::span<const uint32_t> ids);
    // The same in two parts, so that threads can share the copying out: sizeFor() sizes this state for `count`
    // bodies of `from`, then gatherRange() copies bodies ids[first .. last - 1]; ranges may be copied at once.
    void sizeFor(const BodyState& from, size_t count);
    void gatherRange(const BodyState& from, std::span<const uint32_t> ids, size_t first, size_t last);
    // Writes the motion (position, orientation and velocities) of bodies 0 .. ids.size() - 1 back to `to`'s bodies
    // ids: the inverse of gather() for what a step changes.
    void scatterMotion(BodyState& to, std::span<const uint32_t> ids) const;
    // The same for bodies first .. last - 1 only: threads may write disjoint ranges at once.
    void scatterMotionRange(BodyState& to, std::span<const uint32_t> ids, size_t first, size_t last) const;

    // Validates the definition (finite numbers, positive mass, positive-definite inertia satisfying the triangle
    // inequality); bad input is an Error and leaves the state unchanged. Returns the new body's index.
    Result<uint32_t> addBody(const BodyInit& init);

    bool isStatic(uint32_t i) const { return (flags[i] & kBodyStatic) != 0; }
    bool isAwake(uint32_t i) const { return (flags[i] & kBodyAwake) != 0; }
    // Awake and not static: the bodies the integrators move.
    bool isMoving(uint32_t i) const { return (flags[i] & (kBodyStatic | kBodyAwake)) == kBodyAwake; }
    bool isRound(uint32_t i) const { return (flags[i] & kBodyRound) != 0; }

    // The rotation the contact solver turns body i's anchors by since the step began, when it was at
    // `startOrientation`: its turn normalize(q q0*), or for a round body none of it (round about every axis) or the
    // turn without its part about rollAxis (the swing of a swing-twist split).
    Mat3 anchorTurn(uint32_t i, const Quat& startOrientation) const;
    // The same for a turn `turn` from `startOrientation` that the body has not taken yet (a prediction).
    Quat anchorTurnQuat(uint32_t i, const Quat& turn, const Quat& startOrientation) const;
    Mat3 worldInverseInertia(uint32_t i) const;
    // Velocity of the body's material point at `point` (world): v + w x (point - centre of mass).
    Vec3 pointVelocity(uint32_t i, const Vec3& point) const {
        return linearVelocity[i] + glm::cross(angularVelocity[i], point - position[i]);
    }
    // The three inverse moments agree to 1e-12 relative: worldInverseInertia() is then the first times the identity
    // in every pose.
    bool hasIsotropicInverseInertia(uint32_t i) const;
    // The inverse inertia the contact solver takes for the body at its current pose, in a step that began with the
    // body at `stepStart` (see kSolverInertiaDrift): the world inverse inertia, or, where that has drifted too far
    // from the step start's, the least inverse moment times the identity.
    Mat3 solverInverseInertia(uint32_t i, const Quat& stepStart) const;
    // Whether solverInverseInertia() takes the least inverse moment: the world inverse inertia has drifted since
    // `stepStart` by more than kSolverInertiaDrift times the least inverse moment, as measured by |[T, D]| (Frobenius),
    // T the cross-product matrix of t = twice the vector part of the turn in the principal frame (2 sin(angle / 2)
    // times the axis) and D the principal inverse moments: at least |R D R^T - D| for any turn R (a check over 200,000
    // random turns and moments found the ratio at most 1, 2026-12-07).
    bool solverInertiaDrifted(uint32_t i, const Quat& stepStart) const;
    // The least inverse moment times the identity: what solverInverseInertia() takes where the inertia drifted.
    Mat3 leastInverseInertia(uint32_t i) const;
    Mat3 worldInertia(uint32_t i) const;
    Real kineticEnergy(uint32_t i) const;                           // translational + rotational, J
    Real rotationalEnergy(uint32_t i) const;                        // J
    Vec3 angularMomentum(uint32_t i) const;                         // about the body's centre of mass, world, kg m^2/s
    Vec3 angularMomentumAbout(uint32_t i, const Vec3& point) const; // spin plus orbital part m (x - p) x v
    Real totalKineticEnergy() const;
    Vec3 totalAngularMomentum(const Vec3& point) const;

    // The user's view of the body: the orientation of its shape coordinates and where their origin is in the world.
    Quat shapeOrientation(uint32_t i) const;
    Vec3 shapeOrigin(uint32_t i) const;
};

// Inertia from the hull: mass, centre of mass and inertia of a solid hull (geometry/MassProperties.h, exact by the
// divergence theorem) at the given density, placed by the shape's position and orientation. Velocities, damping and
// flags are left at their defaults. Fails for flat or empty hulls and for densities that are not finite and positive.
Result<BodyInit> bodyInitFromHull(const ConvexHull& hull, Real density, const Vec3& shapePosition,
                                  const Quat& shapeOrientation);

} // namespace rl
