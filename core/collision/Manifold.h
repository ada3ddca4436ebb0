// Contact manifolds: up to four points per touching pair, with feature ids so that points persist frame to frame
// and carry their accumulated impulses for warm starting. This is the contract between collision and the solver.
#pragma once

#include "math/Types.h"

#include <array>
#include <cstdint>

namespace rl {

struct ContactPoint {
    Vec3 localA{0.0};       // contact point on A, in A's body frame (relative to A's centre of mass)
    Vec3 localB{0.0};       // contact point on B, in B's body frame
    Vec3 position{0.0};     // world midpoint between the two witness points
    Real separation = 0.0;  // signed distance along the normal; negative means penetration (m)
    uint32_t featureId = 0; // identifies the pair of features (faces/edges/vertices) that made the point
    // Solver state carried across frames by the contact cache (warm starting). Friction is the manifold's.
    Real normalImpulse = 0.0;
};

struct Manifold {
    uint32_t bodyA = 0;
    uint32_t bodyB = 0;
    Vec3 normal{0.0, 1.0, 0.0}; // unit, world space, pointing from A to B
    int pointCount = 0;
    std::array<ContactPoint, 4> points{};
    // Friction is solved once per manifold, at its friction centre (ContactSolver): the accumulated tangent impulse
    // (world axes, in the contact plane) and the twist impulse about the normal, carried for warm starting.
    Vec3 frictionImpulse{0.0};
    Real twistImpulse = 0.0;
    // The impulses were solved with a side held still or made heavier (shock propagation, World::contactHold()):
    // they start no step in which the contact does not hold, where they would fall on the light side whole.
    bool heldImpulses = false;
};

} // namespace rl
