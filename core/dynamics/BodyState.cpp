#include "dynamics/BodyState.h"

#include "geometry/MassProperties.h"

#include <glm/gtc/quaternion.hpp>

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

Error bodyError(const std::string& message) {
    return Error{"", 0, "", message};
}

} // namespace

void BodyState::clear() {
    const SpeedLimits keep = limits;
    *this = BodyState{};
    limits = keep;
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

namespace {

template <class T>
void gatherInto(std::vector<T>& to, const std::vector<T>& from, std::span<const uint32_t> ids, size_t first,
                size_t last) {
    for (size_t k = first; k < last; ++k)
        to[k] = from[ids[k]];
}

template <class T>
void scatterFrom(const std::vector<T>& from, std::vector<T>& to, std::span<const uint32_t> ids, size_t first,
                 size_t last) {
    for (size_t k = first; k < last; ++k)
        to[ids[k]] = from[k];
}

} // namespace

void BodyState::gather(const BodyState& from, std::span<const uint32_t> ids) {
    sizeFor(from, ids.size());
    gatherRange(from, ids, 0, ids.size());
}

void BodyState::sizeFor(const BodyState& from, size_t count) {
    position.resize(count);
    orientation.resize(count);
    linearVelocity.resize(count);
    angularVelocity.resize(count);
    invMass.resize(count);
    invInertia.resize(count);
    linearDamping.resize(count);
    angularDamping.resize(count);
    flags.resize(count);
    info.resize(count);
    smoothLinearVelocity.resize(count);
    smoothDisplacement.resize(count);
    smoothAngularVelocity.resize(count);
    smoothRotation.resize(count);
    limits = from.limits;
}

void BodyState::gatherRange(const BodyState& from, std::span<const uint32_t> ids, size_t first, size_t last) {
    gatherInto(position, from.position, ids, first, last);
    gatherInto(orientation, from.orientation, ids, first, last);
    gatherInto(linearVelocity, from.linearVelocity, ids, first, last);
    gatherInto(angularVelocity, from.angularVelocity, ids, first, last);
    gatherInto(invMass, from.invMass, ids, first, last);
    gatherInto(invInertia, from.invInertia, ids, first, last);
    gatherInto(linearDamping, from.linearDamping, ids, first, last);
    gatherInto(angularDamping, from.angularDamping, ids, first, last);
    gatherInto(flags, from.flags, ids, first, last);
    gatherInto(info, from.info, ids, first, last);
}

void BodyState::scatterMotion(BodyState& to, std::span<const uint32_t> ids) const {
    scatterMotionRange(to, ids, 0, ids.size());
}

void BodyState::scatterMotionRange(BodyState& to, std::span<const uint32_t> ids, size_t first, size_t last) const {
    scatterFrom(position, to.position, ids, first, last);
    scatterFrom(orientation, to.orientation, ids, first, last);
    scatterFrom(linearVelocity, to.linearVelocity, ids, first, last);
    scatterFrom(angularVelocity, to.angularVelocity, ids, first, last);
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
        principalAxes(init.inertia, moments, axes);
        if (glm::determinant(axes) < 0.0)
            axes[2] = -axes[2]; // a reflection cannot be folded into an orientation
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
    flags.push_back(static_cast<uint8_t>((init.isStatic ? kBodyStatic : kBodyAwake) | (init.round ? kBodyRound : 0)));
    smoothLinearVelocity.push_back(Vec3(0.0));
    smoothDisplacement.push_back(Vec3(0.0));
    smoothAngularVelocity.push_back(Vec3(0.0));
    smoothRotation.push_back(identityQuat());
    info.push_back(bookkeeping);
    return size() - 1;
}

Result<BodyInit> bodyInitFromHull(const ConvexHull& hull, Real density, const Vec3& shapePosition,
                                  const Quat& shapeOrientation) {
    if (!std::isfinite(density) || !(density > 0.0))
        return bodyError("density must be a finite number > 0");
    if (!hull.isSolid())
        return bodyError("a dynamic body needs a hull with volume");
    const MassProperties properties = hullMassProperties(hull);
    if (!(properties.volume > 0.0) || !std::isfinite(properties.volume))
        return bodyError("the hull has no volume");
    const Real qNorm = glm::length(shapeOrientation);
    if (!std::isfinite(qNorm) || qNorm < 1e-12 || !isFinite(shapePosition))
        return bodyError("placement is not finite");
    const Quat q = shapeOrientation / qNorm;
    BodyInit init;
    init.orientation = q;
    init.comInShape = properties.centroid;
    init.centerOfMass = shapePosition + q * properties.centroid;
    init.mass = density * properties.volume;
    init.inertia = rotateInertia(density * properties.inertia, glm::mat3_cast(q));
    return init;
}

bool BodyState::solverInertiaDrifted(uint32_t i, const Quat& stepStart) const {
    // The turn since the step start in the principal frame, q0* q, and twice its vector part t (2 sin(angle / 2)
    // times the axis). [T, D] (T = t x) has the entries t_k (d_i - d_j) for each pair i, j of axes and k the third:
    // |[T, D]|^2 = 2 sum t_k^2 (d_i - d_j)^2, which bounds |R D R^T - D|^2 (BodyState.h).
    const Quat turn = glm::conjugate(stepStart) * orientation[i];
    const Vec3 t = 2.0 * Vec3(turn.x, turn.y, turn.z);
    const Vec3 d = invInertia[i];
    const Real yz = d.y - d.z, xz = d.x - d.z, xy = d.x - d.y;
    const Real drift2 = 2.0 * (t.x * t.x * yz * yz + t.y * t.y * xz * xz + t.z * t.z * xy * xy);
    const Real least = std::min({d.x, d.y, d.z});
    return drift2 > kSolverInertiaDrift * kSolverInertiaDrift * least * least;
}

Mat3 BodyState::leastInverseInertia(uint32_t i) const {
    const Vec3 d = invInertia[i];
    return Mat3(std::min({d.x, d.y, d.z}));
}

Mat3 BodyState::solverInverseInertia(uint32_t i, const Quat& stepStart) const {
    return solverInertiaDrifted(i, stepStart) ? leastInverseInertia(i) : worldInverseInertia(i);
}

bool BodyState::hasIsotropicInverseInertia(uint32_t i) const {
    const Vec3 d = invInertia[i];
    return std::abs(d.y - d.x) <= 1e-12 * d.x && std::abs(d.z - d.x) <= 1e-12 * d.x;
}

Quat withoutTwist(const Quat& turn, const Vec3& axis) {
    // turn = swing * twist, twist about the axis.
    const Vec3 along = glm::dot(Vec3(turn.x, turn.y, turn.z), axis) * axis;
    const Real length = std::sqrt(turn.w * turn.w + glm::dot(along, along));
    if (!(length > 1e-12)) // half a turn about an axis across it: no twist
        return turn;
    const Quat twist(turn.w / length, along.x / length, along.y / length, along.z / length);
    return turn * glm::conjugate(twist);
}

Quat BodyState::anchorTurnQuat(uint32_t i, const Quat& turn, const Quat& startOrientation) const {
    if (!isRound(i))
        return turn;
    const Vec3& rollAxis = info[i].rollAxis;
    if (rollAxis == Vec3(0.0))
        return identityQuat();
    return withoutTwist(turn, startOrientation * rollAxis); // the axis as it was at the step's start
}

Mat3 BodyState::anchorTurn(uint32_t i, const Quat& startOrientation) const {
    if (isRound(i) && info[i].rollAxis == Vec3(0.0))
        return Mat3(1.0);
    const Quat turn = glm::normalize(orientation[i] * glm::conjugate(startOrientation));
    return glm::mat3_cast(anchorTurnQuat(i, turn, startOrientation));
}

Mat3 BodyState::worldInverseInertia(uint32_t i) const {
    const Vec3 d = invInertia[i];
    // Three moments equal to 1e-12 (a cube, a sphere; the integrator treats such a body as isotropic too): R D R^T is
    // then d times the identity, to within that spread, in any pose. Cubes are most of the bodies of a stacking
    // scene, and the solver takes this for every body on every substep: the matrix products took 34 ns a body, a
    // quarter of ramps.obj's integrate_positions (2026-11-28, Intel Xeon at 2.5 GHz).
    if (hasIsotropicInverseInertia(i))
        return Mat3(d.x);
    // R D R^T, each of its six distinct entries once, so that it is symmetric to the bit: sum over k of
    // R_ik d_k R_jk, with R_ik = r[k][i] (glm's matrices are column by column).
    const Mat3 r = glm::mat3_cast(orientation[i]);
    Mat3 m(0.0);
    for (int col = 0; col < 3; ++col)
        for (int row = col; row < 3; ++row) {
            m[col][row] = r[0][row] * d.x * r[0][col] + r[1][row] * d.y * r[1][col] + r[2][row] * d.z * r[2][col];
            m[row][col] = m[col][row];
        }
    return m;
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
