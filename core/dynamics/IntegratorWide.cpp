// symplecticVelocitiesForSolver() and symplecticPositionsForSolver(): symplectic Euler's two phases in the world's
// substeps, with the solver's copies of what they change, several bodies at a time in the lanes of one vector. Every
// lane does what the scalar code does (symplecticVelocityPhase() and symplecticPositionPhase() in Integrator.cpp, the
// motion since the step began), operation for operation in glm's order, so the numbers are the same to the bit: this
// file is compiled without contracting a * b + c into fused multiply-adds (core/CMakeLists.txt). One lane at a time: a
// body with the gyroscopic term takes the scalar velocity phase, a rotation over the substep too large for the series
// of rotationFromVector() takes that function's sine and cosine, and an inverse inertia that is not isotropic takes
// BodyState::worldInverseInertia().
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
        solver.invInertia = state.worldInverseInertia(k);
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
        if (rotationEnabled) // (what worldInverseInertia() gives an isotropic body, without the call)
            s.invInertia = s.isotropic ? Mat3(state.invInertia[k].x) : state.worldInverseInertia(k);
    }
}

// symplecticVelocityPhase() (Integrator.cpp) in every lane whose body moves and turns without the gyroscopic term:
// v = (v + g dt) / (1 + c dt) and w = w / (1 + c_w dt), then the speed clamp where a lane may need it (one lane at a
// time, with clampSpeeds() itself). A moving body with the gyroscopic term takes the scalar phase. Then every listed
// body's velocities go to the solver.
template <int W>
RL_LANES_INLINE void velocitiesForSolverLanes(BodyState& state, const uint32_t* ids, Real dt, const Vec3& gravity,
                                              const Damping& damping, bool rotationEnabled,
                                              ClampCounters& clampCounters, std::span<SolverBody> solver) {
    using V = typename Lanes<W>::V;
    V vx, vy, vz, wx, wy, wz, linear, angular;
    bool lane[W];
    for (int l = 0; l < W; ++l) {
        const uint32_t k = ids[l];
        lane[l] = state.isMoving(k) && (!rotationEnabled || detail::isotropicMoments(state.info[k].principalMoments));
        setLane(vx, vy, vz, l, state.linearVelocity[k]);
        setLane(wx, wy, wz, l, state.angularVelocity[k]);
        linear[l] = damping.linear + state.linearDamping[k];
        angular[l] = damping.angular + state.angularDamping[k];
    }
    const Vec3 kick = gravity * dt;
    const V decay = 1.0 / (1.0 + linear * dt); // detail::implicitDecay()
    vx = (vx + kick.x) * decay;
    vy = (vy + kick.y) * decay;
    vz = (vz + kick.z) * decay;
    if (rotationEnabled) {
        const V turnDecay = 1.0 / (1.0 + angular * dt);
        wx = wx * turnDecay;
        wy = wy * turnDecay;
        wz = wz * turnDecay;
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
