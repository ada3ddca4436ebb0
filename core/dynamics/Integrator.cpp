#include "dynamics/Integrator.h"

#include "dynamics/Gyroscopic.h"

#include <cmath>

namespace rl {

namespace {

// Body-frame inertia from the stored inverse. Callers only reach here for dynamic bodies, whose inverse is positive.
Vec3 inertiaOf(const BodyState& state, uint32_t i) {
    return state.info[i].principalMoments;
}

// Symplectic Euler's angular velocity over dt with damping rate c: the implicit midpoint gyroscopic step.
void symplecticAngularVelocity(BodyState& state, uint32_t i, Real dt, Real c) {
    const Vec3 inertia = inertiaOf(state, i);
    Vec3& w = state.angularVelocity[i];
    if (detail::isotropicMoments(inertia)) {
        // w x (I w) vanishes when the three moments are equal (a cube, a sphere): no gyroscopic term, and no need to
        // go to the body frame and back. Cubes are most of every stacking scene.
        w *= detail::implicitDecay(c, dt);
    } else {
        const Quat q = state.orientation[i];
        w = q * (gyroscopicMidpoint(glm::conjugate(q) * w, inertia, dt) * detail::implicitDecay(c, dt));
    }
}

// BodyState::limits on one body's velocities; without rotation its angular velocity is neither read nor written.
void clampBody(BodyState& state, uint32_t i, Real dt, bool rotationEnabled, ClampCounters& clampCounters) {
    Vec3 angular = rotationEnabled ? state.angularVelocity[i] : Vec3(0.0);
    clampSpeeds(state.linearVelocity[i], angular, dt, state.limits, clampCounters);
    if (rotationEnabled)
        state.angularVelocity[i] = angular;
}

void angularVelocityPhase(BodyState& state, uint32_t i, Real dt, Real c, Integrator integrator) {
    const Quat q = state.orientation[i];
    const Vec3 inertia = inertiaOf(state, i);
    Vec3& w = state.angularVelocity[i];
    // The body-frame angular velocity, taken only in the cases below that use it.
    const auto bodyFrame = [&] { return glm::conjugate(q) * w; };
    Vec3 wb;
    switch (integrator) {
    case Integrator::ExplicitEuler:
        state.smoothRotation[i] = rotationFromVector(w * dt); // the orientation advances with the old w
        wb = gyroscopicExplicit(bodyFrame(), inertia, dt) * detail::explicitDecay(c, dt);
        w = q * wb;
        break;
    case Integrator::SymplecticEuler:
        symplecticAngularVelocity(state, i, dt, c);
        break; // the rotation over the substep is rotationFromVector(w dt), taken in positionPhase()
    case Integrator::Verlet:
        wb = gyroscopicExplicit(bodyFrame(), inertia, 0.5 * dt) * detail::explicitDecay(c, 0.5 * dt);
        w = q * wb;
        break; // likewise
    case Integrator::Rk4: {
        wb = bodyFrame();
        Quat qEnd = q;
        if (detail::isStiff(c, dt)) {
            // Stiff damping (see Integrator.h): RK4 for the torque-free part, exact decay for the damping.
            rotationRk4(qEnd, wb, inertia, 0.0, dt);
            wb *= std::exp(-c * dt);
        } else {
            rotationRk4(qEnd, wb, inertia, c, dt);
        }
        w = qEnd * wb;
        state.smoothRotation[i] = glm::normalize(qEnd * glm::conjugate(q));
        break;
    }
    }
    state.smoothAngularVelocity[i] = w;
}

// One body's velocity phase; the callers check that the step is valid and that the body moves.
void velocityPhase(BodyState& state, uint32_t i, Real dt, const Vec3& gravity, const Damping& damping,
                   Integrator integrator, bool rotationEnabled, ClampCounters& clampCounters) {
    const auto gravityField = [&gravity](const Vec3&) { return gravity; };
    const Real c = damping.linear + state.linearDamping[i];
    translationVelocityPhase(integrator, state.position[i], state.linearVelocity[i], dt, c, gravityField,
                             state.smoothDisplacement[i], state.smoothLinearVelocity[i]);
    if (rotationEnabled)
        angularVelocityPhase(state, i, dt, damping.angular + state.angularDamping[i], integrator);
    // The clamp runs after the smooth update so that gravity cannot push a body past it; whatever it removes the
    // position phase treats like a solver change.
    clampBody(state, i, dt, rotationEnabled, clampCounters);
}

void positionPhase(BodyState& state, uint32_t i, Real dt, const Vec3& gravity, const Damping& damping,
                   Integrator integrator, bool rotationEnabled) {
    const auto gravityField = [&gravity](const Vec3&) { return gravity; };
    const Real c = damping.linear + state.linearDamping[i];
    translationPositionPhase(integrator, state.position[i], state.linearVelocity[i], dt, c, gravityField,
                             state.smoothDisplacement[i], state.smoothLinearVelocity[i]);
    if (!rotationEnabled)
        return;
    Quat& q = state.orientation[i];
    Vec3& w = state.angularVelocity[i];
    const Quat before = q;
    // Symplectic Euler and Verlet turn about the current w (changed by the solver or the clamp, or not), so their
    // velocity phase leaves the rotation to this one: a body in contact then takes one sine and cosine per
    // substep, not two. Explicit Euler (the old w) and RK4 (its own end orientation) use the velocity phase's.
    const bool turnsWithW = integrator == Integrator::SymplecticEuler || integrator == Integrator::Verlet;
    if (!turnsWithW && w == state.smoothAngularVelocity[i])
        q = glm::normalize(state.smoothRotation[i] * q);
    else
        q = glm::normalize(rotationFromVector(w * dt) * q);
    if (integrator == Integrator::ExplicitEuler) {
        // Explicit Euler's state is (q, w in the body frame): the new w keeps its body-frame components while the
        // body turns by the old w. (For the other schemes q turns about w itself, which leaves w as it is.)
        w = q * (glm::conjugate(before) * w);
    }
    if (integrator == Integrator::Verlet) {
        const Real ca = damping.angular + state.angularDamping[i];
        const Vec3 wb = glm::conjugate(q) * w;
        w = q * (gyroscopicImplicit(wb, inertiaOf(state, i), 0.5 * dt) * detail::implicitDecay(ca, 0.5 * dt));
    }
}

// Symplectic Euler's two phases for the world's substeps (the span overloads below): the numbers of velocityPhase()
// and positionPhase() with that scheme, without the smooth motion, which only the other schemes' position phases
// read. (Symplectic Euler's position phase moves by v dt, which is the stored displacement whenever v is the stored
// velocity.) Over ramps.obj's first 120 frames on one thread, integrate_velocities went from 28.1-29.0 to 18.4-18.8 ms
// and integrate_positions from 63.7-65.6 to 53.2-53.4 ms (three interleaved runs each, the same frames, 2026-11-29).
void symplecticVelocityPhase(BodyState& state, uint32_t i, Real dt, const Vec3& gravity, const Damping& damping,
                             bool rotationEnabled, ClampCounters& clampCounters) {
    Vec3& v = state.linearVelocity[i];
    v = (v + gravity * dt) * detail::implicitDecay(damping.linear + state.linearDamping[i], dt);
    if (rotationEnabled)
        symplecticAngularVelocity(state, i, dt, damping.angular + state.angularDamping[i]);
    clampBody(state, i, dt, rotationEnabled, clampCounters);
}

void symplecticPositionPhase(BodyState& state, uint32_t i, Real dt, bool rotationEnabled) {
    state.position[i] = state.position[i] + state.linearVelocity[i] * dt;
    if (rotationEnabled) {
        Quat& q = state.orientation[i];
        q = glm::normalize(rotationFromVector(state.angularVelocity[i] * dt) * q);
    }
}

} // namespace

void integrateVelocities(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                         Integrator integrator, bool rotationEnabled) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        return; // a step of no time (or a broken one) moves nothing
    const uint32_t end = std::min(range.end, state.size());
    for (uint32_t i = range.begin; i < end; ++i)
        if (state.isMoving(i))
            velocityPhase(state, i, dt, gravity, damping, integrator, rotationEnabled, state.clampCounters);
}

void integrateVelocities(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                         const Damping& damping, Integrator integrator, bool rotationEnabled,
                         ClampCounters& clampCounters) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        return;
    if (integrator == Integrator::SymplecticEuler) {
        for (uint32_t i : bodies)
            if (i < state.size() && state.isMoving(i))
                symplecticVelocityPhase(state, i, dt, gravity, damping, rotationEnabled, clampCounters);
        return;
    }
    for (uint32_t i : bodies)
        if (i < state.size() && state.isMoving(i))
            velocityPhase(state, i, dt, gravity, damping, integrator, rotationEnabled, clampCounters);
}

void integratePositions(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                        Integrator integrator, bool rotationEnabled) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        return;
    const uint32_t end = std::min(range.end, state.size());
    for (uint32_t i = range.begin; i < end; ++i)
        if (state.isMoving(i))
            positionPhase(state, i, dt, gravity, damping, integrator, rotationEnabled);
}

void integratePositions(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                        const Damping& damping, Integrator integrator, bool rotationEnabled) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        return;
    if (integrator == Integrator::SymplecticEuler) {
        for (uint32_t i : bodies)
            if (i < state.size() && state.isMoving(i))
                symplecticPositionPhase(state, i, dt, rotationEnabled);
        return;
    }
    for (uint32_t i : bodies)
        if (i < state.size() && state.isMoving(i))
            positionPhase(state, i, dt, gravity, damping, integrator, rotationEnabled);
}

void integrateSmooth(BodyState& state, BodyRange range, Real dt, const Vec3& gravity, const Damping& damping,
                     Integrator integrator, bool rotationEnabled) {
    integrateVelocities(state, range, dt, gravity, damping, integrator, rotationEnabled);
    integratePositions(state, range, dt, gravity, damping, integrator, rotationEnabled);
}

} // namespace rl
