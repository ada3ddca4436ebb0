#include "dynamics/Gyroscopic.h"

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

Quat halfRate(const Quat& q, const Vec3& bodyOmega) {
    return 0.5 * (q * Quat(0.0, bodyOmega.x, bodyOmega.y, bodyOmega.z));
}

// One Newton iteration on f(w) = I (w - w0) + h w x (I w) = 0 from the current guess w; returns |update|.
// J = I + h (skew(w) I - skew(I w)) is I plus a term of order h |w| I, so it is far from singular for any step the
// clamp allows; a singular or non-finite J (only from non-finite input) leaves w as it is.
// J is solved by its adjugate: with rows r0, r1, r2, J^-1 has the columns r1 x r2, r2 x r0, r0 x r1 over
// det J = r0 . (r1 x r2). Written out, J's off-diagonal entries are h w_k (I_a - I_b); glm's general inverse and
// determinant took twice the arithmetic.
Real backwardEulerNewtonStep(const Vec3& w0, Vec3& w, const Vec3& inertia, Real h) {
    const Vec3 momentum = inertia * w;
    const Vec3 residual = inertia * (w - w0) + h * glm::cross(w, momentum);
    const Vec3 hw = h * w;
    const Vec3 r0(inertia.x, hw.z * (inertia.z - inertia.y), hw.y * (inertia.z - inertia.y));
    const Vec3 r1(hw.z * (inertia.x - inertia.z), inertia.y, hw.x * (inertia.x - inertia.z));
    const Vec3 r2(hw.y * (inertia.y - inertia.x), hw.x * (inertia.y - inertia.x), inertia.z);
    const Vec3 c0 = glm::cross(r1, r2);
    const Real det = glm::dot(r0, c0);
    if (!std::isfinite(det) || std::abs(det) < 1e-300)
        return 0.0;
    const Vec3 update = (c0 * residual.x + glm::cross(r2, r0) * residual.y + glm::cross(r0, r1) * residual.z) / det;
    w -= update;
    return glm::length(update);
}

} // namespace

Vec3 eulerAngularAcceleration(const Vec3& bodyOmega, const Vec3& inertia) {
    return -glm::cross(bodyOmega, inertia * bodyOmega) / inertia;
}

Vec3 gyroscopicExplicit(const Vec3& bodyOmega, const Vec3& inertia, Real dt) {
    return bodyOmega + dt * eulerAngularAcceleration(bodyOmega, inertia);
}

Vec3 gyroscopicImplicit(const Vec3& bodyOmega, const Vec3& inertia, Real dt) {
    Vec3 w = bodyOmega;
    backwardEulerNewtonStep(bodyOmega, w, inertia, dt);
    return w;
}

Vec3 gyroscopicMidpoint(const Vec3& bodyOmega, const Vec3& inertia, Real dt) {
    // Newton's next update is about g |update|^2 / |w| with g = h |w| (largest / smallest moment): the curvature of
    // f over its slope. Once that is below 1e-15 |w|, a tenth of the tolerance, the iteration stops without taking
    // it. (Before, it always ran one more iteration to see a change below 1e-14: over boxes1000's first 120 frames,
    // 720,000 calls made 1.58 M Newton steps, 295,000 of them ran three; measured updates fell as 7.5e-5, 5.7e-13,
    // 3.8e-17 of |w| at h |w| = 1.5e-3.)
    const Real h = 0.5 * dt;
    const Real anisotropy = std::max({inertia.x, inertia.y, inertia.z}) / std::min({inertia.x, inertia.y, inertia.z});
    Vec3 mid = bodyOmega;
    for (int k = 0; k < kMidpointMaxIterations; ++k) {
        const Real change = backwardEulerNewtonStep(bodyOmega, mid, inertia, h);
        const Real size = glm::length(mid);
        if (!(change > 1e-14 * size))
            break;
        const Real relative = change / size;
        if (h * size * anisotropy * relative * relative <= 1e-15)
            break;
    }
    return 2.0 * mid - bodyOmega;
}

void rotationRk4(Quat& orientation, Vec3& bodyOmega, const Vec3& inertia, Real damping, Real dt) {
    auto omegaRate = [&](const Vec3& w) { return eulerAngularAcceleration(w, inertia) - damping * w; };
    const Quat q0 = orientation;
    const Vec3 w0 = bodyOmega;
    const Quat k1q = halfRate(q0, w0);
    const Vec3 k1w = omegaRate(w0);
    const Quat q1 = q0 + (0.5 * dt) * k1q;
    const Vec3 w1 = w0 + (0.5 * dt) * k1w;
    const Quat k2q = halfRate(q1, w1);
    const Vec3 k2w = omegaRate(w1);
    const Quat q2 = q0 + (0.5 * dt) * k2q;
    const Vec3 w2 = w0 + (0.5 * dt) * k2w;
    const Quat k3q = halfRate(q2, w2);
    const Vec3 k3w = omegaRate(w2);
    const Quat q3 = q0 + dt * k3q;
    const Vec3 w3 = w0 + dt * k3w;
    const Quat k4q = halfRate(q3, w3);
    const Vec3 k4w = omegaRate(w3);
    orientation = glm::normalize(q0 + (dt / 6.0) * (k1q + 2.0 * k2q + 2.0 * k3q + k4q));
    bodyOmega = w0 + (dt / 6.0) * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
}

Quat rotationFromVector(const Vec3& theta) {
    // Below 0.02 rad (7 rad/s at 360 substeps a second: nearly every body in contact) cos(a/2) and sin(a/2)/a by
    // their series to a^6, from a^2 alone: no square root, sine or cosine. The first term left out is below
    // a^8 / 10^7 < 3e-21, far under a double's rounding of 1, so the result is the same to the last bit or two.
    const Real angleSquared = glm::dot(theta, theta);
    if (angleSquared < 4e-4) {
        const Real a2 = angleSquared;
        const Real cosHalf = 1.0 - a2 * (1.0 / 8.0 - a2 * (1.0 / 384.0 - a2 * (1.0 / 46080.0)));
        const Real sinOverAngle = 0.5 - a2 * (1.0 / 48.0 - a2 * (1.0 / 3840.0 - a2 * (1.0 / 645120.0)));
        return Quat(cosHalf, sinOverAngle * theta.x, sinOverAngle * theta.y, sinOverAngle * theta.z);
    }
    const Real angle = std::sqrt(angleSquared);
    const Real half = 0.5 * angle;
    const Real sinOverAngle = std::sin(half) / angle;
    return Quat(std::cos(half), sinOverAngle * theta.x, sinOverAngle * theta.y, sinOverAngle * theta.z);
}

bool clampSpeeds(Vec3& linearVelocity, Vec3& angularVelocity, Real dt, const SpeedLimits& limits,
                 ClampCounters& counters) {
    bool clamped = false;
    const Real speed = glm::length(linearVelocity);
    if (!std::isfinite(speed)) {
        // A non-finite velocity can only come from non-finite input upstream; stopping the body keeps NaN contained.
        linearVelocity = Vec3(0.0);
        ++counters.linear;
        clamped = true;
    } else if (speed > limits.maxLinearSpeed) {
        linearVelocity *= limits.maxLinearSpeed / speed;
        ++counters.linear;
        clamped = true;
    }
    const Real maxAngularSpeed = limits.maxRotationPerSubstep / dt;
    const Real spin = glm::length(angularVelocity);
    if (!std::isfinite(spin)) {
        angularVelocity = Vec3(0.0);
        ++counters.angular;
        clamped = true;
    } else if (spin > maxAngularSpeed) {
        angularVelocity *= maxAngularSpeed / spin;
        ++counters.angular;
        clamped = true;
    }
    return clamped;
}

} // namespace rl
