#include "dynamics/BodyState.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rl {

namespace {

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isFinite(const Mat3& m) {
    return isFinite(m[0]) && isFinite(m[1]) && isFinite(m[2]);
}

// Cyclic Jacobi on a symmetric 3x3 matrix. Kept local rather than borrowed from geometry/ so that creating bodies does
// not depend on the hull code; it is small, and for 3x3 it converges to machine precision in a handful of sweeps.
void symmetricEigen(const Mat3& tensor, Vec3& values, Mat3& axes) {
    Real a[3][3];
    Real v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            a[r][c] = 0.5 * (tensor[c][r] + tensor[r][c]);
    constexpr int kMaxSweeps = 32; // quadratic convergence: 3x3 needs about 5; the bound only guards against NaN
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
        const Real off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const Real diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-32 * diag))
            break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0)
                    continue;
                const Real theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const Real t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const Real c = 1.0 / std::sqrt(t * t + 1.0);
                const Real s = t * c;
                for (int k = 0; k < 3; ++k) { // A <- A J
                    const Real akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) { // A <- J^T A
                    const Real apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) { // V <- V J
                    const Real vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
        }
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
    for (int c = 0; c < 3; ++c) {
        values[c] = a[order[c]][order[c]];
        for (int r = 0; r < 3; ++r)
            axes[c][r] = v[r][order[c]];
    }
    if (glm::determinant(axes) < 0.0)
        axes[2] = -axes[2]; // a reflection cannot be an orientation
}

Error bodyError(const std::string& message) {
    return Error{"", 0, "", message};
}

} // namespace

void BodyState::clear() {
    *this = BodyState{};
}

void BodyState::reserve(uint32_t n) {
    position.reserve(n);
    orientation.reserve(n);
    linearVelocity.reserve(n);
    angularVelocity.reserve(n);
    invMass.reserve(n);
    invInertia.reserve(n);
    linearDamping.reserve(n);
    angularDamping.reserve(n);
    flags.reserve(n);
    smoothLinearVelocity.reserve(n);
    smoothDisplacement.reserve(n);
    smoothAngularVelocity.reserve(n);
    smoothRotation.reserve(n);
    info.reserve(n);
}

Result<uint32_t> BodyState::addBody(const BodyInit& init) {
    if (!isFinite(init.centerOfMass) || !isFinite(init.comInShape))
        return bodyError("position is not finite");
    if (!isFinite(init.linearVelocity) || !isFinite(init.angularVelocity))
        return bodyError("velocity is not finite");
    const Real qNorm = glm::length(init.orientation);
    if (!std::isfinite(qNorm) || qNorm < 1e-12)
        return bodyError("orientation is not a rotation (zero or non-finite quaternion)");
    if (!(init.linearDamping >= 0.0) || !(init.angularDamping >= 0.0) || !std::isfinite(init.linearDamping) ||
        !std::isfinite(init.angularDamping))
        return bodyError("damping must be a finite number >= 0");
    const Quat shapeToWorld = init.orientation / qNorm;

    BodyInfo bookkeeping;
    bookkeeping.comInShape = init.comInShape;
    Quat principalToWorld = shapeToWorld;
    Real inverseMass = 0.0;
    Vec3 inverseInertia{0.0};
    if (!init.isStatic) {
        if (!std::isfinite(init.mass) || !(init.mass > 0.0))
            return bodyError("mass must be a finite number > 0");
        if (!isFinite(init.inertia))
            return bodyError("inertia is not finite");
        Vec3 moments;
        Mat3 axes;
        symmetricEigen(init.inertia, moments, axes);
        const Real scale = std::max(std::abs(moments[2]), 1e-300);
        if (!(moments[0] > 1e-12 * scale))
            return bodyError("inertia is not positive definite");
        // Any real mass distribution satisfies I_max <= I_mid + I_min; equality is a flat body. Allow rounding only.
        if (moments[2] > (moments[0] + moments[1]) * (1.0 + 1e-9))
            return bodyError("inertia violates the triangle inequality (no mass distribution has it)");
        principalToWorld = glm::normalize(glm::quat_cast(axes));
        bookkeeping.mass = init.mass;
        bookkeeping.principalMoments = moments;
        inverseMass = 1.0 / init.mass;
        inverseInertia = Vec3(1.0 / moments[0], 1.0 / moments[1], 1.0 / moments[2]);
    }
    // shape -> world == (principal -> world) * (shape -> principal)
    bookkeeping.shapeFromPrincipal = glm::normalize(glm::conjugate(principalToWorld) * shapeToWorld);

    position.push_back(init.centerOfMass);
    orientation.push_back(principalToWorld);
    linearVelocity.push_back(init.isStatic ? Vec3(0.0) : init.linearVelocity);
    angularVelocity.push_back(init.isStatic ? Vec3(0.0) : init.angularVelocity);
    invMass.push_back(inverseMass);
    invInertia.push_back(inverseInertia);
    linearDamping.push_back(init.linearDamping);
    angularDamping.push_back(init.angularDamping);
    flags.push_back(init.isStatic ? uint8_t(kBodyStatic) : uint8_t(kBodyAwake));
    smoothLinearVelocity.push_back(Vec3(0.0));
    smoothDisplacement.push_back(Vec3(0.0));
    smoothAngularVelocity.push_back(Vec3(0.0));
    smoothRotation.push_back(identityQuat());
    info.push_back(bookkeeping);
    return size() - 1;
}

Mat3 BodyState::worldInverseInertia(uint32_t i) const {
    const Mat3 r = glm::mat3_cast(orientation[i]);
    Mat3 d(0.0);
    d[0][0] = invInertia[i].x;
    d[1][1] = invInertia[i].y;
    d[2][2] = invInertia[i].z;
    return r * d * glm::transpose(r);
}

Mat3 BodyState::worldInertia(uint32_t i) const {
    const Mat3 r = glm::mat3_cast(orientation[i]);
    Mat3 d(0.0);
    d[0][0] = info[i].principalMoments.x;
    d[1][1] = info[i].principalMoments.y;
    d[2][2] = info[i].principalMoments.z;
    return r * d * glm::transpose(r);
}

Real BodyState::rotationalEnergy(uint32_t i) const {
    const Vec3 wb = glm::conjugate(orientation[i]) * angularVelocity[i];
    return 0.5 * glm::dot(wb, info[i].principalMoments * wb);
}

Real BodyState::kineticEnergy(uint32_t i) const {
    return 0.5 * info[i].mass * glm::dot(linearVelocity[i], linearVelocity[i]) + rotationalEnergy(i);
}

Vec3 BodyState::angularMomentum(uint32_t i) const {
    const Vec3 wb = glm::conjugate(orientation[i]) * angularVelocity[i];
    return orientation[i] * (info[i].principalMoments * wb);
}

Vec3 BodyState::angularMomentumAbout(uint32_t i, const Vec3& point) const {
    return angularMomentum(i) + info[i].mass * glm::cross(position[i] - point, linearVelocity[i]);
}

Real BodyState::totalKineticEnergy() const {
    Real sum = 0.0;
    for (uint32_t i = 0; i < size(); ++i)
        sum += kineticEnergy(i);
    return sum;
}

Vec3 BodyState::totalAngularMomentum(const Vec3& point) const {
    Vec3 sum(0.0);
    for (uint32_t i = 0; i < size(); ++i)
        sum += angularMomentumAbout(i, point);
    return sum;
}

Quat BodyState::shapeOrientation(uint32_t i) const {
    return orientation[i] * info[i].shapeFromPrincipal;
}

Vec3 BodyState::shapeOrigin(uint32_t i) const {
    return position[i] - shapeOrientation(i) * info[i].comInShape;
}

} // namespace rl
