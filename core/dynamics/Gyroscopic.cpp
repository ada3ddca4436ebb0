#include "dynamics/Gyroscopic.h"

#include <cmath>

namespace rl {

namespace {

Mat3 skew(const Vec3& v) {
    // glm is column-major: m[c][r]. skew(v) * x == cross(v, x).
    return Mat3(Vec3(0.0, v.z, -v.y), Vec3(-v.z, 0.0, v.x), Vec3(v.y, -v.x, 0.0));
}

Mat3 diagonal(const Vec3& d) {
    Mat3 m(0.0);
    m[0][0] = d.x;
    m[1][1] = d.y;
    m[2][2] = d.z;
    return m;
}

Quat halfRate(const Quat& q, const Vec3& bodyOmega) {
    return 0.5 * (q * Quat(0.0, bodyOmega.x, bodyOmega.y, bodyOmega.z));
}

// One Newton iteration on f(w) = I (w - w0) + h w x (I w) = 0 from the current guess w; returns |update|.
// J = I + h (skew(w) I - skew(I w)) is I plus a term of order h |w| I, so it is far from singular for any step the
// clamp allows; a singular or non-finite J (only from non-finite input) leaves w as it is.
Real backwardEulerNewtonStep(const Vec3& w0, Vec3& w, const Vec3& inertia, Real h) {
    const Vec3 momentum = inertia * w;
    const Vec3 residual = inertia * (w - w0) + h * glm::cross(w, momentum);
    const Mat3 jacobian = diagonal(inertia) + h * (skew(w) * diagonal(inertia) - skew(momentum));
    const Real det = glm::determinant(jacobian);
    if (!std::isfinite(det) || std::abs(det) < 1e-300)
        return 0.0;
    const Vec3 update = glm::inverse(jacobian) * residual;
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
    Vec3 mid = bodyOmega;
    for (int k = 0; k < kMidpointMaxIterations; ++k) {
        const Real change = backwardEulerNewtonStep(bodyOmega, mid, inertia, 0.5 * dt);
        if (!(change > 1e-14 * glm::length(mid)))
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
