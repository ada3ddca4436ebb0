// The four integrators for the smooth part of the motion (gravity, damping, torque-free rotation with the gyroscopic
// term), each split into a velocity phase and a position phase so that the contact solver can run between the two.
#pragma once

#include "dynamics/BodyState.h"
#include "dynamics/ContactSolver.h"
#include "math/Types.h"
#include "scene/WorldSettings.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace rl {

// How the integrators meet the velocity solver. The world's substep is
//     integrateVelocities -> warm start, solve contacts -> integratePositions -> relax
// The velocity phase applies the smooth forces and records, per body, the velocity and the displacement they alone
// prescribe over the substep (BodyState's scratch arrays). The position phase then looks at what the solver did:
//  - a body whose velocity the solver left alone moves by its integrator's own displacement and rotation, so free
//    flight keeps each scheme's textbook accuracy;
//  - a body whose velocity the solver (or the speed clamp) changed moves with the solved velocity, x += v dt and q by
//    w dt. That is the assumption the solver's non-penetration and friction rows are built on. Keeping the smooth
//    displacement and adding the solver's change times dt instead would lift a body resting on the ground by
//    |g| dt^2 / 2 every substep under RK4 (its displacement v0 dt + g dt^2/2 is not v1 dt).
// So wherever a contact acts, every scheme is first order in position, as any velocity-level solver is; the schemes
// differ in free flight, in rotation and in damping.
//
//   explicit-euler    velocity phase: records x += v_old dt, then v += (a - c v) dt.
//                     Orientation advances by w_old, and w keeps its body-frame components (explicit Euler on
//                     (q, w_body)). Rotation: explicit Euler on Euler's equations, which gains |L| and energy every
//                     step (see Gyroscopic.h). The original project's scheme. First order.
//   symplectic-euler  velocity phase: v = (v + a dt) / (1 + c dt) (implicit damping, stable for any c), gyroscopic
//                     term by implicit midpoint (keeps |L| and energy; Gyroscopic.h says why not Catto's one-step
//                     backward Euler). position phase: x += v dt, q advances by the new w: the solver's own
//                     assumption, so for it both branches above are the same. Box2D's scheme for the translation.
//                     First order; symplectic for position-dependent forces, so oscillators keep their energy.
//   verlet            velocity Verlet as kick-drift-kick. velocity phase: half kick v += (a - c v) dt/2, gyroscopic
//                     half step explicit. The solver sees the half-kicked velocity. position phase: drift x += v dt,
//                     q advances by the mid-step w, then the closing half kick v = (v + a dt/2) / (1 + c dt/2) with
//                     the gyroscopic half step implicit (the adjoint of the opening half, which makes the pair
//                     symmetric). Second order; exact in position for constant gravity. Because the closing kick
//                     runs after the solver, a body resting on the ground ends the substep with v = g dt/2 into it;
//                     the next solve (or the world's relax pass) removes it before it can move the body.
//   rk4               velocity phase: classical RK4 on (x, v) with a(x) - c v, and on (q, w_body) with Euler's
//                     equations; records the RK4 displacement and rotation. Fourth order in free flight (exact in
//                     position for constant gravity without damping).
//
// Stiff damping: where c h > 1 for a (half) step h, an explicit update 1 - c h would flip the velocity's sign and, past
// c h = 2, amplify it (RK4's bound is about 2.78). There every scheme uses the exact solution of v' = a - c v for that
// (half) step instead, which keeps the terminal velocity a / c right and no bad setting can produce NaN. It is a
// safety net, not an accuracy regime anyone should run in.

struct BodyRange {
    uint32_t begin = 0;
    uint32_t end = 0; // one past the last
};

inline BodyRange allBodies(const BodyState& state) {
    return {0, state.size()};
}

// World-level damping rates, 1/s. Each body's own rates (BodyState::linearDamping...) are added: two independent linear
// drags add like parallel dashpots.
struct Damping {
    Real linear = 0.0;
    Real angular = 0.0;
};

// ---- The substep phases for bodies (only awake, non-static bodies in the range are touched) ----
// Disjoint ranges touch disjoint array elements, except BodyState::clampCounters, which every call may increment: run
// ranges of one state on several threads only with the clamp counters made per thread first.

// Applies gravity, damping and (when rotationEnabled) the gyroscopic term over dt, records the smooth motion, and
// applies BodyState::limits, counting in BodyState::clampCounters. When rotation is disabled (the original project's
// linear-only mode), angular velocity and orientation are left exactly as they are.
void integrateVelocities(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                         Integrator integrator, bool rotationEnabled);

// Advances positions and orientations; for verlet also applies the closing half kick.
void integratePositions(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                        Integrator integrator, bool rotationEnabled);

// The same two phases for a list of body indices (the world's islands solved with their own substep count and on
// their own threads). Indices that are out of range, asleep or static are skipped. The clamp is counted in
// `clampCounters` instead of the state's, so that disjoint lists can run on several threads. With symplectic Euler
// these leave the smooth motion (smoothDisplacement ...) as it was: that scheme's position phase does not read it,
// and the bodies move as under the range overloads, to the bit.
void integrateVelocities(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                         const Damping& damping, Integrator integrator, bool rotationEnabled,
                         ClampCounters& clampCounters);
void integratePositions(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                        const Damping& damping, Integrator integrator, bool rotationEnabled);

// Symplectic Euler's velocity phase of the world's substeps for the listed bodies (the list overload of
// integrateVelocities()), then each body's velocities to the contact solver: solver[k + 1].v, and .w (zero without
// rotation). The same bits as those two steps; lanes as below.
void symplecticVelocitiesForSolver(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                                   const Damping& damping, bool rotationEnabled, ClampCounters& clampCounters,
                                   std::span<SolverBody> solver, int lanes = 0);

// Symplectic Euler's position phase of the world's substeps for the listed bodies, with what the contact solver keeps
// of each (solver[k + 1] for body k): first the velocities the solver left are taken (v, and w with rotation), then
// the position phase runs (integratePositions() with Integrator::SymplecticEuler; bodies that are not moving keep
// their pose), then solver[k + 1].dp and .dR get the motion since startPosition[k] and startOrientation[k] (.dR as
// BodyState::anchorTurn() gives it), and with rotation .invInertia the inverse inertia at the new pose (where
// SolverBody::isotropic is set, the body's first inverse moment times the identity, as
// BodyState::worldInverseInertia() gives a body with isotropic inertia), or where that drifted too far from the step
// start's, the least inverse moment times the identity (BodyState::solverInverseInertia(), kSolverInertiaDrift). The
// numbers of those steps one after the other, to the bit; eight or four bodies at a time where the CPU has the vector
// units. lanes: 0 for the widest the CPU has, 4 to keep to four, 1 for one body at a time (the reference the tests
// compare with).
void symplecticPositionsForSolver(BodyState& state, std::span<const uint32_t> bodies, Real dt, bool rotationEnabled,
                                  std::span<const Vec3> startPosition, std::span<const Quat> startOrientation,
                                  std::span<SolverBody> solver, int lanes = 0);

// Both phases with no solver in between: the free motion over one substep.
void integrateSmooth(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                     Integrator integrator, bool rotationEnabled);

// ---- The translation kernel, shared by the bodies above and by the accuracy study's 1D problems ----
// One particle (V = Real or Vec3) under x'' = a(x) - c x'. Same two phases and same scratch as above: the velocity
// phase writes the smooth displacement and velocity, the position phase checks whether anything changed v in between.

namespace detail {
// Principal moments equal to 1e-12 relative: the gyroscopic torque w x (I w) is then below 1e-12 |I| |w|^2, and the
// integrators turn such a body (a cube, a sphere) without it.
inline bool isotropicMoments(const Vec3& inertia) {
    const Real tolerance = 1e-12 * inertia.x;
    return std::abs(inertia.y - inertia.x) <= tolerance && std::abs(inertia.z - inertia.x) <= tolerance;
}
// True where an explicit decay over h would overshoot (see "Stiff damping" above).
inline bool isStiff(Real c, Real h) {
    return c * h > 1.0;
}
// Decay factor of an explicit step over h: 1 - c h, or the exact exp(-c h) where that would overshoot.
inline Real explicitDecay(Real c, Real h) {
    return isStiff(c, h) ? std::exp(-c * h) : 1.0 - c * h;
}
// Decay factor of an implicit step over h: 1 / (1 + c h). Stable for any c >= 0.
inline Real implicitDecay(Real c, Real h) {
    return 1.0 / (1.0 + c * h);
}
// v' = a - c v over h: explicit Euler, or the exact solution where explicit Euler would overshoot.
template <class V>
V explicitKick(const V& v, const V& a, Real c, Real h) {
    if (!isStiff(c, h))
        return v * (1.0 - c * h) + a * h;
    const Real decay = std::exp(-c * h);
    return a / c + (v - a / c) * decay;
}
} // namespace detail

template <class V, class Accel>
void translationVelocityPhase(Integrator integrator, const V& x, V& v, Real dt, Real c, const Accel& accel,
                              V& smoothDisplacement, V& smoothVelocity) {
    switch (integrator) {
    case Integrator::ExplicitEuler:
        smoothDisplacement = v * dt;
        v = detail::explicitKick(v, accel(x), c, dt);
        break;
    case Integrator::SymplecticEuler:
        v = (v + accel(x) * dt) * detail::implicitDecay(c, dt);
        smoothDisplacement = v * dt;
        break;
    case Integrator::Verlet:
        v = detail::explicitKick(v, accel(x), c, 0.5 * dt);
        smoothDisplacement = v * dt;
        break;
    case Integrator::Rk4: {
        if (detail::isStiff(c, dt)) {
            // Stiff damping: exact solution of v' = a - c v with a frozen at x (see the header comment).
            const V a = accel(x);
            const Real decay = std::exp(-c * dt);
            smoothDisplacement = a * (dt / c) + (v - a / c) * ((1.0 - decay) / c);
            v = a / c + (v - a / c) * decay;
            break;
        }
        const V a1 = accel(x) - v * c;
        const V v1 = v;
        const V x2 = x + v1 * (0.5 * dt);
        const V v2 = v + a1 * (0.5 * dt);
        const V a2 = accel(x2) - v2 * c;
        const V x3 = x + v2 * (0.5 * dt);
        const V v3 = v + a2 * (0.5 * dt);
        const V a3 = accel(x3) - v3 * c;
        const V x4 = x + v3 * dt;
        const V v4 = v + a3 * dt;
        const V a4 = accel(x4) - v4 * c;
        smoothDisplacement = (v1 + v2 * 2.0 + v3 * 2.0 + v4) * (dt / 6.0);
        v = v + (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (dt / 6.0);
        break;
    }
    }
    smoothVelocity = v;
}

template <class V, class Accel>
void translationPositionPhase(Integrator integrator, V& x, V& v, Real dt, Real c, const Accel& accel,
                              const V& smoothDisplacement, const V& smoothVelocity) {
    if (v == smoothVelocity)
        x = x + smoothDisplacement;
    else
        x = x + v * dt; // the solver or the clamp changed v: move with it (see above)
    if (integrator == Integrator::Verlet)
        v = (v + accel(x) * (0.5 * dt)) * detail::implicitDecay(c, 0.5 * dt);
}

// One free step of the kernel (no solver between the phases).
template <class V, class Accel>
void translationStep(Integrator integrator, V& x, V& v, Real dt, Real c, const Accel& accel) {
    V displacement = v;
    V velocity = v;
    translationVelocityPhase(integrator, x, v, dt, c, accel, displacement, velocity);
    translationPositionPhase(integrator, x, v, dt, c, accel, displacement, velocity);
}

} // namespace rl
