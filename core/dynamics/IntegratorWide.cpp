// symplecticVelocitiesForSolver() and symplecticPositionsForSolver(): symplectic Euler's two phases in the world's
// substeps, with the solver's copies of what they change, several bodies at a time in the lanes of one vector. Every
// lane does what the scalar code does (symplecticVelocityPhase() and symplecticPositionPhase() in Integrator.cpp, the
// motion since the step began), operation for operation in glm's order, so the numbers are the same to the bit: this
// file is compiled without contracting a * b + c into fused multiply-adds (core/CMakeLists.txt). The gyroscopic term's
// Newton iterations run in the lanes too, each lane stopping where the scalar loop stops. One lane at a time: a body
// that does not move takes the scalar velocity phase (which leaves it as it is), a rotation over the substep too large
// for the series of rotationFromVector() takes that function's sine and cosine, and a round body takes
// BodyState::anchorTurn().
#include "dynamics/Gyroscopic.h"
#include "dynamics/Integrator.h"

#include <glm/gtc/quaternion.hpp>

namespace rl {

namespace {

// The scalar reference: the four steps of World::solveSubsteps() for one body.
void positionsForSolverOne(BodyState& state, uint32_t k, Real dt, bool rotationEnabled, const Vec3& startPosition,
                           const Quat& startOrientation, SolverBody& solver) {
    state.linearVelocity[k] = solver.v;
    if (rotationEnabled)
        state.angularVelocity[k] = solver.w;
    if (state.isMoving(k)) {
        state.position[k] = state.position[k] + state.linearVelocity[k] * dt;
        if (rotationEnabled) {
            Quat& q = state.orientation[k];
            q = glm::normalize(rotationFromVector(state.angularVelocity[k] * dt) * q);
        }
    }
    solver.dp = state.position[k] - startPosition;
    solver.dR = state.anchorTurn(k, startOrientation);
    if (rotationEnabled)
        solver.invInertia = state.solverInverseInertia(k, startOrientation);
}

// The velocity phase of one body (the list overload of integrateVelocities()), then its velocities to the solver.
void velocitiesForSolverOne(BodyState& state, uint32_t k, Real dt, const Vec3& gravity, const Damping& damping,
                            bool rotationEnabled, ClampCounters& clampCounters, SolverBody& solver) {
    integrateVelocities(state, std::span<const uint32_t>(&k, 1), dt, gravity, damping, Integrator::SymplecticEuler,
                        rotationEnabled, clampCounters);
    solver.v = state.linearVelocity[k];
    solver.w = rotationEnabled ? state.angularVelocity[k] : Vec3(0.0);
}

#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define RL_INTEGRATOR_LANES 1
#define RL_LANES_INLINE inline __attribute__((always_inline))
// As in ContactSolverWide.cpp: the lanes' functions are built for AVX-512 and AVX2 (chosen where they are called),
// except under AddressSanitizer, where they stay with the baseline instructions.
#if !defined(__SANITIZE_ADDRESS__)
#define RL_INTEGRATOR_WIDE8 __attribute__((target("arch=x86-64-v4")))
#define RL_INTEGRATOR_WIDE4 __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RL_INTEGRATOR_WIDE8
#define RL_INTEGRATOR_WIDE4
#endif

template <int W>
struct Lanes;
template <>
struct Lanes<4> {
    typedef double V __attribute__((vector_size(32)));
};
template <>
struct Lanes<8> {
    typedef double V __attribute__((vector_size(64)));
};

// Lane l of the three vectors x, y, z gets v's components.
template <class V>
RL_LANES_INLINE void setLane(V& x, V& y, V& z, int l, const Vec3& v) {
    x[l] = v.x;
    y[l] = v.y;
    z[l] = v.z;
}

// A quaternion with W lanes per component.
template <class V>
struct QuatL {
    V w, x, y, z;
};

// glm's quaternion product p q (qua::operator*=), per lane.
template <class V>
RL_LANES_INLINE QuatL<V> multiply(const QuatL<V>& p, const QuatL<V>& q) {
    return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z, p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
            p.w * q.y + p.y * q.w + p.z * q.x - p.x * q.z, p.w * q.z + p.z * q.w + p.x * q.y - p.y * q.x};
}

// glm::normalize of a quaternion: length from glm's dot, (w w + x x) + (y y + z z), and the identity where the length
// is <= 0 (not where it is NaN: glm divides by it there).
template <int W, class V>
RL_LANES_INLINE QuatL<V> normalized(const QuatL<V>& q) {
    const V squared = (q.w * q.w + q.x * q.x) + (q.y * q.y + q.z * q.z);
    V length;
    for (int l = 0; l < W; ++l)
        length[l] = std::sqrt(squared[l]);
    const V one = V{} + 1.0, zero = V{};
    const auto identity = length <= zero;
    const V oneOverLength = one / (identity ? one : length);
    return {identity ? one : q.w * oneOverLength, identity ? zero : q.x * oneOverLength,
            identity ? zero : q.y * oneOverLength, identity ? zero : q.z * oneOverLength};
}

template <int W>
RL_LANES_INLINE void positionsForSolverLanes(BodyState& state, const uint32_t* ids, Real dt, bool rotationEnabled,
                                             std::span<const Vec3> startPosition,
                                             std::span<const Quat> startOrientation, std::span<SolverBody> solver) {
    using V = typename Lanes<W>::V;
    V vx, vy, vz, wx, wy, wz, px, py, pz, moving;
    QuatL<V> q, q0;
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        const SolverBody& s = solver[k + 1];
        setLane(vx, vy, vz, l, s.v);
        setLane(wx, wy, wz, l, rotationEnabled ? s.w : state.angularVelocity[k]);
        setLane(px, py, pz, l, state.position[k]);
        const Quat& o = state.orientation[k];
        q.w[l] = o.w;
        q.x[l] = o.x;
        q.y[l] = o.y;
        q.z[l] = o.z;
        const Quat& o0 = startOrientation[k];
        q0.w[l] = o0.w;
        q0.x[l] = -o0.x; // glm::conjugate
        q0.y[l] = -o0.y;
        q0.z[l] = -o0.z;
        moving[l] = state.isMoving(k) ? 1.0 : 0.0;
    }
    const V zero = V{};
    const auto move = moving > zero;
    // x += v dt.
    px = move ? px + vx * dt : px;
    py = move ? py + vy * dt : py;
    pz = move ? pz + vz * dt : pz;
    if (rotationEnabled) {
        // q = normalize(rotationFromVector(w dt) q), the series of rotationFromVector() in every lane.
        const V tx = wx * dt, ty = wy * dt, tz = wz * dt;
        const V a2 = (tx * tx + ty * ty) + tz * tz;
        const V cosHalf = 1.0 - a2 * (1.0 / 8.0 - a2 * (1.0 / 384.0 - a2 * (1.0 / 46080.0)));
        const V sinOverAngle = 0.5 - a2 * (1.0 / 48.0 - a2 * (1.0 / 3840.0 - a2 * (1.0 / 645120.0)));
        QuatL<V> turn{cosHalf, sinOverAngle * tx, sinOverAngle * ty, sinOverAngle * tz};
        for (int l = 0; l < W; ++l)
            if (!(a2[l] < 4e-4)) { // the sine and cosine (and a non-finite w) one lane at a time
                const Quat r = rotationFromVector(Vec3(tx[l], ty[l], tz[l]));
                turn.w[l] = r.w;
                turn.x[l] = r.x;
                turn.y[l] = r.y;
                turn.z[l] = r.z;
            }
        const QuatL<V> turned = normalized<W>(multiply(turn, q));
        q = {move ? turned.w : q.w, move ? turned.x : q.x, move ? turned.y : q.y, move ? turned.z : q.z};
    }
    // The motion since the step began: dp, and dR = mat3_cast(normalize(q conjugate(q0))).
    const QuatL<V> r = normalized<W>(multiply(q, q0));
    const V xx = r.x * r.x, yy = r.y * r.y, zz = r.z * r.z;
    const V xz = r.x * r.z, xy = r.x * r.y, yz = r.y * r.z;
    const V wxp = r.w * r.x, wyp = r.w * r.y, wzp = r.w * r.z;
    const V one = zero + 1.0, two = zero + 2.0;
    const V m00 = one - two * (yy + zz), m01 = two * (xy + wzp), m02 = two * (xz - wyp);
    const V m10 = two * (xy - wzp), m11 = one - two * (xx + zz), m12 = two * (yz + wxp);
    const V m20 = two * (xz + wyp), m21 = two * (yz - wxp), m22 = one - two * (xx + yy);
    // The world inverse inertia R D R^T at the pose just reached, in the lanes whose three moments differ:
    // BodyState::worldInverseInertia(), entry for entry in its order, with R = mat3_cast(q). (One lane at a time,
    // it was 2 % of the step of boxes1000's random boxes, 2026-12-06.)
    bool full[W];
    bool anyFull = false;
    V dx, dy, dz;
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        setLane(dx, dy, dz, l, state.invInertia[k]);
        full[l] = rotationEnabled && !solver[k + 1].isotropic && !state.hasIsotropicInverseInertia(k);
        anyFull = anyFull || full[l];
    }
    V i00 = zero, i01 = zero, i02 = zero, i11 = zero, i12 = zero, i22 = zero;
    if (anyFull) {
        const V qxx = q.x * q.x, qyy = q.y * q.y, qzz = q.z * q.z;
        const V qxz = q.x * q.z, qxy = q.x * q.y, qyz = q.y * q.z;
        const V qwx = q.w * q.x, qwy = q.w * q.y, qwz = q.w * q.z;
        const V a[3][3] = {{one - two * (qyy + qzz), two * (qxy + qwz), two * (qxz - qwy)},
                           {two * (qxy - qwz), one - two * (qxx + qzz), two * (qyz + qwx)},
                           {two * (qxz + qwy), two * (qyz - qwx), one - two * (qxx + qyy)}};
        const auto entry = [&](int col, int row) {
            return a[0][row] * dx * a[0][col] + a[1][row] * dy * a[1][col] + a[2][row] * dz * a[2][col];
        };
        i00 = entry(0, 0);
        i01 = entry(0, 1);
        i02 = entry(0, 2);
        i11 = entry(1, 1);
        i12 = entry(1, 2);
        i22 = entry(2, 2);
    }
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        SolverBody& s = solver[k + 1];
        state.linearVelocity[k] = s.v;
        if (rotationEnabled) {
            state.angularVelocity[k] = s.w;
            state.orientation[k] = Quat(q.w[l], q.x[l], q.y[l], q.z[l]);
        }
        state.position[k] = Vec3(px[l], py[l], pz[l]);
        s.dp = state.position[k] - startPosition[k];
        s.dR = state.isRound(k) ? state.anchorTurn(k, startOrientation[k])
                                : Mat3(m00[l], m01[l], m02[l], m10[l], m11[l], m12[l], m20[l], m21[l], m22[l]);
        if (full[l] && state.solverInertiaDrifted(k, startOrientation[k]))
            s.invInertia = state.leastInverseInertia(k); // (see kSolverInertiaDrift)
        else if (full[l])
            s.invInertia = Mat3(i00[l], i01[l], i02[l], i01[l], i11[l], i12[l], i02[l], i12[l], i22[l]);
        else if (rotationEnabled) // (what worldInverseInertia() gives an isotropic body, without the call)
            s.invInertia = s.isotropic ? Mat3(state.invInertia[k].x) : state.worldInverseInertia(k);
    }
}

// A vector with W lanes per component.
template <class V>
struct Vec3L {
    V x, y, z;
};

// glm::cross(a, b), per lane.
template <class V>
RL_LANES_INLINE Vec3L<V> cross(const Vec3L<V>& a, const Vec3L<V>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

// glm's q * v (qua::operator*(qua, vec3)): v + ((u x v) w + u x (u x v)) 2 with u = (q.x, q.y, q.z), per lane.
template <class V>
RL_LANES_INLINE Vec3L<V> rotate(const QuatL<V>& q, const Vec3L<V>& v) {
    const Vec3L<V> u{q.x, q.y, q.z};
    const Vec3L<V> uv = cross(u, v);
    const Vec3L<V> uuv = cross(u, uv);
    return {v.x + (uv.x * q.w + uuv.x) * 2.0, v.y + (uv.y * q.w + uuv.y) * 2.0, v.z + (uv.z * q.w + uuv.z) * 2.0};
}

// glm::length(v), per lane: the square root of glm's dot, (x x + y y) + z z.
template <int W, class V>
RL_LANES_INLINE V length(const Vec3L<V>& v) {
    const V squared = (v.x * v.x + v.y * v.y) + v.z * v.z;
    V root;
    for (int l = 0; l < W; ++l)
        root[l] = std::sqrt(squared[l]);
    return root;
}

// gyroscopicMidpoint() (Gyroscopic.cpp) in the lanes where `active` is set, operation for operation: Newton's
// iterations on the implicit midpoint, each lane stopping after the iteration where the scalar loop stops (a lane
// that has stopped keeps its value while the others go on), then 2 wm - w0. Other lanes' results are not used.
template <int W, class V, class Mask>
RL_LANES_INLINE Vec3L<V> gyroscopicMidpointLanes(const Vec3L<V>& w0, const Vec3L<V>& inertia, Real dt, Mask active) {
    const Real h = 0.5 * dt;
    const V largest = inertia.x > inertia.y ? inertia.x : inertia.y,
            smallest = inertia.x < inertia.y ? inertia.x : inertia.y;
    const V anisotropy = (largest > inertia.z ? largest : inertia.z) / (smallest < inertia.z ? smallest : inertia.z);
    const V zero = V{};
    Vec3L<V> mid = w0;
    for (int k = 0; k < kMidpointMaxIterations; ++k) {
        bool any = false;
        for (int l = 0; l < W; ++l)
            any = any || active[l];
        if (!any)
            break;
        // backwardEulerNewtonStep(w0, mid, inertia, h).
        const Vec3L<V> momentum{inertia.x * mid.x, inertia.y * mid.y, inertia.z * mid.z};
        const Vec3L<V> turn = cross(mid, momentum);
        const Vec3L<V> residual{inertia.x * (mid.x - w0.x) + h * turn.x, inertia.y * (mid.y - w0.y) + h * turn.y,
                                inertia.z * (mid.z - w0.z) + h * turn.z};
        const Vec3L<V> hw{h * mid.x, h * mid.y, h * mid.z};
        const Vec3L<V> r0{inertia.x, hw.z * (inertia.z - inertia.y), hw.y * (inertia.z - inertia.y)};
        const Vec3L<V> r1{hw.z * (inertia.x - inertia.z), inertia.y, hw.x * (inertia.x - inertia.z)};
        const Vec3L<V> r2{hw.y * (inertia.y - inertia.x), hw.x * (inertia.y - inertia.x), inertia.z};
        const Vec3L<V> c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
        const V det = (r0.x * c0.x + r0.y * c0.y) + r0.z * c0.z;
        Mask solvable = active;
        for (int l = 0; l < W; ++l)
            solvable[l] = active[l] && std::isfinite(det[l]) && !(std::abs(det[l]) < 1e-300) ? -1 : 0;
        const Vec3L<V> update{((c0.x * residual.x + c1.x * residual.y) + c2.x * residual.z) / det,
                              ((c0.y * residual.x + c1.y * residual.y) + c2.y * residual.z) / det,
                              ((c0.z * residual.x + c1.z * residual.y) + c2.z * residual.z) / det};
        mid = {solvable ? mid.x - update.x : mid.x, solvable ? mid.y - update.y : mid.y,
               solvable ? mid.z - update.z : mid.z};
        // The scalar loop's two tests on the update's size (zero where the step was not solvable).
        const V change = solvable ? length<W>(update) : zero;
        const V size = length<W>(mid);
        const V relative = change / size;
        const auto goesOn = (change > 1e-14 * size) & ~(h * size * anisotropy * relative * relative <= 1e-15);
        active = active & goesOn;
    }
    return {2.0 * mid.x - w0.x, 2.0 * mid.y - w0.y, 2.0 * mid.z - w0.z};
}

// symplecticVelocityPhase() (Integrator.cpp) in every lane whose body moves: v = (v + g dt) / (1 + c dt), then
// w = w / (1 + c_w dt) for a body with three equal moments, or the gyroscopic step in its own frame,
// w = q (gyroscopicMidpoint(q* w) / (1 + c_w dt)); then the speed clamp where a lane may need it (one lane at a
// time, with clampSpeeds() itself). Then every listed body's velocities go to the solver. (Before 2026-12-06 a body
// with the gyroscopic term took the scalar phase: boxes1000's random boxes spent 13 % of the step there.)
template <int W>
RL_LANES_INLINE void velocitiesForSolverLanes(BodyState& state, const uint32_t* ids, Real dt, const Vec3& gravity,
                                              const Damping& damping, bool rotationEnabled,
                                              ClampCounters& clampCounters, std::span<SolverBody> solver) {
    using V = typename Lanes<W>::V;
    V vx, vy, vz, wx, wy, wz, linear, angular;
    Vec3L<V> inertia;
    QuatL<V> q;
    bool lane[W];
    bool anyGyroscopic = false;
    const V zero = V{};
    auto gyroscopic = zero > zero; // the lanes with the gyroscopic term
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        lane[l] = state.isMoving(k);
        const Vec3& moments = state.info[k].principalMoments;
        gyroscopic[l] = lane[l] && rotationEnabled && !detail::isotropicMoments(moments) ? -1 : 0;
        anyGyroscopic = anyGyroscopic || gyroscopic[l];
        setLane(vx, vy, vz, l, state.linearVelocity[k]);
        setLane(wx, wy, wz, l, state.angularVelocity[k]);
        linear[l] = damping.linear + state.linearDamping[k];
        angular[l] = damping.angular + state.angularDamping[k];
    }
    if (anyGyroscopic) // (a scene of cubes and balls has none)
        for (int l = 0; l < W; ++l) {
            const uint32_t k = ids[l];
            setLane(inertia.x, inertia.y, inertia.z, l, state.info[k].principalMoments);
            const Quat& o = state.orientation[k];
            q.w[l] = o.w;
            q.x[l] = o.x;
            q.y[l] = o.y;
            q.z[l] = o.z;
        }
    const Vec3 kick = gravity * dt;
    const V decay = 1.0 / (1.0 + linear * dt); // detail::implicitDecay()
    vx = (vx + kick.x) * decay;
    vy = (vy + kick.y) * decay;
    vz = (vz + kick.z) * decay;
    if (rotationEnabled) {
        const V turnDecay = 1.0 / (1.0 + angular * dt);
        Vec3L<V> turned{wx * turnDecay, wy * turnDecay, wz * turnDecay};
        if (anyGyroscopic) {
            // The body frame's w by the conjugate of q, the midpoint step there, the decay, and back.
            const QuatL<V> inverse{q.w, -q.x, -q.y, -q.z};
            const Vec3L<V> bodyW = rotate(inverse, Vec3L<V>{wx, wy, wz});
            const Vec3L<V> stepped = gyroscopicMidpointLanes<W>(bodyW, inertia, dt, gyroscopic);
            const Vec3L<V> world =
                rotate(q, Vec3L<V>{stepped.x * turnDecay, stepped.y * turnDecay, stepped.z * turnDecay});
            turned = {gyroscopic ? world.x : turned.x, gyroscopic ? world.y : turned.y,
                      gyroscopic ? world.z : turned.z};
        }
        wx = turned.x;
        wy = turned.y;
        wz = turned.z;
    }
    // glm::length()'s squares; the clamp compares the square roots, as clampSpeeds() does.
    const V speed2 = (vx * vx + vy * vy) + vz * vz, spin2 = (wx * wx + wy * wy) + wz * wz;
    const Real maxAngularSpeed = state.limits.maxRotationPerSubstep / dt;
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        SolverBody& s = solver[k + 1];
        if (lane[l]) {
            Vec3 v(vx[l], vy[l], vz[l]);
            Vec3 w = rotationEnabled ? Vec3(wx[l], wy[l], wz[l]) : Vec3(0.0);
            const Real speed = std::sqrt(speed2[l]), spin = rotationEnabled ? std::sqrt(spin2[l]) : 0.0;
            if (!(speed <= state.limits.maxLinearSpeed) || !(spin <= maxAngularSpeed))
                clampSpeeds(v, w, dt, state.limits, clampCounters);
            state.linearVelocity[k] = v;
            if (rotationEnabled)
                state.angularVelocity[k] = w;
            s.v = v;
            s.w = w;
        } else {
            velocitiesForSolverOne(state, k, dt, gravity, damping, rotationEnabled, clampCounters, s);
        }
    }
}

RL_INTEGRATOR_WIDE8 void velocitiesForSolver8(BodyState& state, const uint32_t* ids, Real dt, const Vec3& gravity,
                                              const Damping& damping, bool rotationEnabled,
                                              ClampCounters& clampCounters, std::span<SolverBody> solver) {
    velocitiesForSolverLanes<8>(state, ids, dt, gravity, damping, rotationEnabled, clampCounters, solver);
}
RL_INTEGRATOR_WIDE4 void velocitiesForSolver4(BodyState& state, const uint32_t* ids, Real dt, const Vec3& gravity,
                                              const Damping& damping, bool rotationEnabled,
                                              ClampCounters& clampCounters, std::span<SolverBody> solver) {
    velocitiesForSolverLanes<4>(state, ids, dt, gravity, damping, rotationEnabled, clampCounters, solver);
}

RL_INTEGRATOR_WIDE8 void positionsForSolver8(BodyState& state, const uint32_t* ids, Real dt, bool rotationEnabled,
                                             std::span<const Vec3> startPosition,
                                             std::span<const Quat> startOrientation, std::span<SolverBody> solver) {
    positionsForSolverLanes<8>(state, ids, dt, rotationEnabled, startPosition, startOrientation, solver);
}
RL_INTEGRATOR_WIDE4 void positionsForSolver4(BodyState& state, const uint32_t* ids, Real dt, bool rotationEnabled,
                                             std::span<const Vec3> startPosition,
                                             std::span<const Quat> startOrientation, std::span<SolverBody> solver) {
    positionsForSolverLanes<4>(state, ids, dt, rotationEnabled, startPosition, startOrientation, solver);
}
#endif

} // namespace

namespace {

// Calls one(n) for the positions n of a list of `count` bodies, where the CPU has the vectors lanes8(n) or lanes4(n)
// for runs of eight or four of them first (`lanes` as in Integrator.h).
template <class Eight, class Four, class One>
void overLanes(size_t count, int lanes, [[maybe_unused]] Eight&& lanes8, [[maybe_unused]] Four&& lanes4, One&& one) {
    size_t n = 0;
#ifdef RL_INTEGRATOR_LANES
    static const bool wide = __builtin_cpu_supports("x86-64-v4");
    const size_t width = lanes == 1 ? 1 : wide && lanes != 4 ? 8 : 4;
    for (; width > 1 && n + width <= count; n += width)
        width == 8 ? lanes8(n) : lanes4(n);
#else
    (void)lanes;
#endif
    for (; n < count; ++n)
        one(n);
}

#ifndef RL_INTEGRATOR_LANES
// Without GCC's vector types there are no lanes, and overLanes() takes the bodies one at a time.
constexpr auto velocitiesForSolver8 = [](auto&&...) {};
constexpr auto velocitiesForSolver4 = velocitiesForSolver8;
constexpr auto positionsForSolver8 = velocitiesForSolver8;
constexpr auto positionsForSolver4 = velocitiesForSolver8;
#endif

} // namespace

void symplecticVelocitiesForSolver(BodyState& state, std::span<const uint32_t> bodies, Real dt, const Vec3& gravity,
                                   const Damping& damping, bool rotationEnabled, ClampCounters& clampCounters,
                                   std::span<SolverBody> solver, int lanes) {
    if (!(dt > 0.0) || !std::isfinite(dt)) { // a step of no time (or a broken one) changes no velocity
        for (const uint32_t k : bodies) {
            solver[k + 1].v = state.linearVelocity[k];
            solver[k + 1].w = rotationEnabled ? state.angularVelocity[k] : Vec3(0.0);
        }
        return;
    }
    overLanes(
        bodies.size(), lanes,
        [&](size_t n) {
            velocitiesForSolver8(state, &bodies[n], dt, gravity, damping, rotationEnabled, clampCounters, solver);
        },
        [&](size_t n) {
            velocitiesForSolver4(state, &bodies[n], dt, gravity, damping, rotationEnabled, clampCounters, solver);
        },
        [&](size_t n) {
            velocitiesForSolverOne(state, bodies[n], dt, gravity, damping, rotationEnabled, clampCounters,
                                   solver[bodies[n] + 1]);
        });
}

void symplecticPositionsForSolver(BodyState& state, std::span<const uint32_t> bodies, Real dt, bool rotationEnabled,
                                  std::span<const Vec3> startPosition, std::span<const Quat> startOrientation,
                                  std::span<SolverBody> solver, int lanes) {
    overLanes(
        bodies.size(), lanes,
        [&](size_t n) {
            positionsForSolver8(state, &bodies[n], dt, rotationEnabled, startPosition, startOrientation, solver);
        },
        [&](size_t n) {
            positionsForSolver4(state, &bodies[n], dt, rotationEnabled, startPosition, startOrientation, solver);
        },
        [&](size_t n) {
            const uint32_t k = bodies[n];
            positionsForSolverOne(state, k, dt, rotationEnabled, startPosition[k], startOrientation[k], solver[k + 1]);
        });
}

} // namespace rl
