// Torque-free rotation in the body (principal) frame: Euler's equations I w' = -w x (I w), stepped explicitly,
// implicitly (one Newton iteration, after Catto's GDC 2015 talk) or by RK4 together with the orientation; and the
// clamp.
#pragma once

#include "dynamics/BodyState.h"
#include "math/Types.h"

namespace rl {

// Right-hand side of Euler's equations for a diagonal inertia: w' = -I^-1 (w x I w). Body frame.
Vec3 eulerAngularAcceleration(const Vec3& bodyOmega, const Vec3& inertia);

// w + dt * w'. Used by explicit Euler. It gains energy and |L| every step: |L1|^2 = |L0|^2 + dt^2 |w0 x L0|^2, so a
// tumbling body spins up without bound. Kept because it is what the original project did.
Vec3 gyroscopicExplicit(const Vec3& bodyOmega, const Vec3& inertia, Real dt);

// Backward Euler on Euler's equations, f(w) = I (w - w0) + dt w x (I w) = 0, solved by one Newton iteration from w0:
// w = w0 - J^-1 f(w0) with J = I + dt (skew(w0) I - skew(I w0)). Exact backward Euler dissipates |L| and energy
// (dot f with I w: |L1|^2 = L1 . L0), which is what makes it stable at any step; one Newton iteration keeps that
// behaviour while the Newton error (of order dt^3 per step) stays below the method's own first-order error.
// Returns w0 when J is singular, which only happens for non-finite input.
Vec3 gyroscopicImplicit(const Vec3& bodyOmega, const Vec3& inertia, Real dt);

// One classical RK4 step of the coupled system q' = q (0, w)/2, w' = eulerAngularAcceleration(w) - damping w, with w in
// the body frame. Fourth order in both; the quaternion is renormalised at the end (RK4 does not keep |q| = 1).
void rotationRk4(Quat& orientation, Vec3& bodyOmega, const Vec3& inertia, Real damping, Real dt);

// The rotation by the vector theta (axis theta/|theta|, angle |theta|), exact: the exponential map. Used to advance an
// orientation by w dt. It is exact for a constant w, so the orientation update adds no error of its own beyond what
// using one w over the substep costs: first order with w taken at one end (the Euler methods), second with w at the
// middle (Verlet). Normalising a first-order update q + dt q w / 2 instead would be just as accurate but distorts
// large rotations; the exponential map stays correct up to the clamp's quarter turn.
Quat rotationFromVector(const Vec3& theta);

// Applies SpeedLimits to one body's velocities for a substep of dt; returns true and counts when it changed them.
// Direction is kept, only the magnitude is reduced.
bool clampSpeeds(Vec3& linearVelocity, Vec3& angularVelocity, Real dt, const SpeedLimits& limits,
                 ClampCounters& counters);

} // namespace rl
