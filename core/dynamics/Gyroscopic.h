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
// w = w0 - J^-1 f(w0) with J = I + dt (skew(w0) I - skew(I w0)), as Catto presented it in 2015. Exact backward Euler
// dissipates |L| and energy (dot f with I w: |L1|^2 = L1 . L0), which is what makes it stable at any step. The loss is
// of order (dt |w x L| / |L|)^2 per step, which is large for a tumbling body: measured on tst_rotation's T-handle at
// 6 rad/s and 240 Hz it loses 8 % of |L| and 16 % of its energy in 20 s. So no integrator uses it for a whole step;
// Verlet uses it for its closing half step, where the explicit opening half cancels its leading error. Returns w0 when
// J is singular, which only happens for non-finite input.
Vec3 gyroscopicImplicit(const Vec3& bodyOmega, const Vec3& inertia, Real dt);

// Implicit midpoint on Euler's equations: I (w1 - w0) = -dt wm x (I wm), wm = (w0 + w1) / 2. Solved as backward Euler
// over dt/2 for wm (the same Newton iteration as above, repeated until the update, or the next one as Newton's
// quadratic convergence predicts it, is below 1e-14 of |w|, at most kMidpointMaxIterations times), then
// w1 = 2 wm - w0. Implicit midpoint keeps every quadratic invariant, here |L|^2 and
// the energy, exactly up to the Newton tolerance: dotting the equation with I wm gives |L1| = |L0|, with wm gives
// E1 = E0. So it is stable at any step like Catto's step, without its dissipation, and second order.
// Used by symplectic-euler.
Vec3 gyroscopicMidpoint(const Vec3& bodyOmega, const Vec3& inertia, Real dt);
inline constexpr int kMidpointMaxIterations = 8; // a bound only: Newton converges quadratically from w0

// One classical RK4 step of the coupled system q' = q (0, w)/2, w' = eulerAngularAcceleration(w) - damping w, with w in
// the body frame. Fourth order in both; the quaternion is renormalised at the end (RK4 does not keep |q| = 1).
void rotationRk4(Quat& orientation, Vec3& bodyOmega, const Vec3& inertia, Real damping, Real dt);

// The rotation by the vector theta (axis theta/|theta|, angle |theta|): the exponential map, exact for any angle. Used
// to advance an orientation by w dt, where it is exact for a constant w, so the update adds no error beyond that of
// holding w constant over the substep: first order with w taken at one end (the Euler methods), second with w at the
// middle (Verlet). A first-order update q + dt (0, w) q / 2 followed by normalisation would keep the same orders but
// shortens large rotations (to 2 atan(angle / 2)).
Quat rotationFromVector(const Vec3& theta);

// Applies SpeedLimits to one body's velocities for a substep of dt; returns true and counts when it changed them.
// Direction is kept, only the magnitude is reduced.
bool clampSpeeds(Vec3& linearVelocity, Vec3& angularVelocity, Real dt, const SpeedLimits& limits,
                 ClampCounters& counters);

} // namespace rl
