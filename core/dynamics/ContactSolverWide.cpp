// The contact solver's sweeps, four constraints at a time (ContactSolver::warmStartBatchRange() and
// solveBatchRange()).
//
// A batch holds four constraints of one level of the schedule, so its lanes share no moving body: the lanes are
// independent, and every body receives the same updates in the same order as in the sequential sweep. Each lane
// performs exactly the operations of the scalar rows in ContactSolver.cpp, in the same order, so the results are the
// same numbers. This file is built with -ffp-contract=off (core/CMakeLists.txt): no a * b + c becomes a fused
// multiply-add, so the x86-64-v3 clone, the baseline clone and the scalar reference compute the same bits, and a
// machine gives the same results whichever clone it picks.
#include "dynamics/ContactSolver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define RL_WIDE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RL_WIDE_CLONES
#endif
#define RL_LANES_INLINE inline __attribute__((always_inline))

namespace rl {

namespace {

// V holds four doubles, one per lane. With GCC it is a vector type: two SSE2 instructions per operation in the
// baseline clone, one AVX instruction in the x86-64-v3 clone. Elsewhere (the clang build of the fuzzers) it is an
// array with per-lane loops: the same numbers, at scalar speed.
#if defined(__GNUC__) && !defined(__clang__)
using V = double __attribute__((vector_size(32)));
using Mask = long __attribute__((vector_size(32)));               // what a comparison of V gives
RL_LANES_INLINE V select(const Mask& m, const V& x, const V& y) { // m ? x : y, per lane
    return m ? x : y;
}
#else
struct V {
    Real v[4];
    Real& operator[](int l) { return v[l]; }
    Real operator[](int l) const { return v[l]; }
};
struct Mask {
    bool v[4];
};
template <class Out, class F>
RL_LANES_INLINE Out perLane(F&& f) {
    Out r;
    for (int l = 0; l < 4; ++l)
        r.v[l] = f(l);
    return r;
}
RL_LANES_INLINE V operator+(const V& a, const V& b) {
    return perLane<V>([&](int l) { return a.v[l] + b.v[l]; });
}
RL_LANES_INLINE V operator-(const V& a, const V& b) {
    return perLane<V>([&](int l) { return a.v[l] - b.v[l]; });
}
RL_LANES_INLINE V operator*(const V& a, const V& b) {
    return perLane<V>([&](int l) { return a.v[l] * b.v[l]; });
}
RL_LANES_INLINE V operator-(const V& a) {
    return perLane<V>([&](int l) { return -a.v[l]; });
}
RL_LANES_INLINE V operator/(const V& a, const V& b) {
    return perLane<V>([&](int l) { return a.v[l] / b.v[l]; });
}
RL_LANES_INLINE Mask operator<(const V& a, const V& b) {
    return perLane<Mask>([&](int l) { return a.v[l] < b.v[l]; });
}
RL_LANES_INLINE Mask operator>(const V& a, const V& b) {
    return perLane<Mask>([&](int l) { return a.v[l] > b.v[l]; });
}
RL_LANES_INLINE Mask operator==(const V& a, const V& b) {
    return perLane<Mask>([&](int l) { return a.v[l] == b.v[l]; });
}
RL_LANES_INLINE Mask operator&&(const Mask& a, const Mask& b) {
    return perLane<Mask>([&](int l) { return a.v[l] && b.v[l]; });
}
RL_LANES_INLINE V select(const Mask& m, const V& x, const V& y) {
    return perLane<V>([&](int l) { return m.v[l] ? x.v[l] : y.v[l]; });
}
#endif

using Lanes = ContactSolver::Lanes;
static_assert(sizeof(V) == sizeof(Lanes));

RL_LANES_INLINE V splat(Real x) {
    return V{x, x, x, x};
}
RL_LANES_INLINE V get(const Lanes& lanes) {
    V r;
    std::memcpy(&r, lanes.v, sizeof r);
    return r;
}
RL_LANES_INLINE void put(Lanes& lanes, const V& x) {
    std::memcpy(lanes.v, &x, sizeof x);
}
// Four floats widened to four doubles (exactly).
#if defined(__GNUC__) && !defined(__clang__)
using VF = float __attribute__((vector_size(16)));
RL_LANES_INLINE V get(const ContactSolver::FloatLanes& lanes) {
    VF f;
    std::memcpy(&f, lanes.v, sizeof f);
    return __builtin_convertvector(f, V);
}
#else
RL_LANES_INLINE V get(const ContactSolver::FloatLanes& lanes) {
    return V{lanes.v[0], lanes.v[1], lanes.v[2], lanes.v[3]};
}
#endif
// Whether any lane is not zero.
RL_LANES_INLINE bool anyNonZero(const Lanes& lanes) {
    bool any = false;
    for (int l = 0; l < 4; ++l)
        any = any || lanes.v[l] != 0.0;
    return any;
}
RL_LANES_INLINE bool anyNonZero(const V& x) {
    bool any = false;
    for (int l = 0; l < 4; ++l)
        any = any || x[l] != 0.0;
    return any;
}
// std::sqrt per lane.
RL_LANES_INLINE V sqrtOf(const V& x) {
    V r = x;
    for (int l = 0; l < 4; ++l)
        r[l] = std::sqrt(x[l]);
    return r;
}
// std::max(a, b): a < b ? b : a, per lane.
RL_LANES_INLINE V maxOf(const V& a, const V& b) {
    return select(a < b, b, a);
}
// std::clamp(x, lo, hi): x < lo ? lo : (hi < x ? hi : x), per lane.
RL_LANES_INLINE V clampTo(const V& x, const V& lo, const V& hi) {
    return select(x < lo, lo, select(hi < x, hi, x));
}

// A vector of three lanes-wide components.
struct L3 {
    V x, y, z;
};
template <class Stored>
RL_LANES_INLINE L3 load(const Stored* c) {
    return {get(c[0]), get(c[1]), get(c[2])};
}
RL_LANES_INLINE L3 operator+(const L3& a, const L3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
RL_LANES_INLINE L3 operator-(const L3& a, const L3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
RL_LANES_INLINE L3 operator*(const V& s, const L3& a) {
    return {s * a.x, s * a.y, s * a.z};
}
// glm::dot's order: (x x + y y) + z z.
RL_LANES_INLINE V dot(const L3& a, const L3& b) {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}
// glm::cross's order.
RL_LANES_INLINE L3 cross(const L3& x, const L3& y) {
    return {x.y * y.z - y.y * x.z, x.z * y.x - y.z * x.x, x.x * y.y - y.x * x.y};
}
// A column-major 3x3 matrix (glm's m[c][r]) times a vector, in glm's order: (m0 x + m1 y) + m2 z per row.
struct M3 {
    V m[3][3];
};
RL_LANES_INLINE L3 operator*(const M3& a, const L3& v) {
    return {(a.m[0][0] * v.x + a.m[1][0] * v.y) + a.m[2][0] * v.z,
            (a.m[0][1] * v.x + a.m[1][1] * v.y) + a.m[2][1] * v.z,
            (a.m[0][2] * v.x + a.m[1][2] * v.y) + a.m[2][2] * v.z};
}

// The velocities (and, for the solve, the motion since the step began) of one side of a batch, gathered from the
// lanes' bodies. Lanes whose body is the static entry 0 read its zeros and identity and are never written back.
struct Side {
    L3 v, w;
    V invMass;
    M3 invInertia;
    L3 dp;
    M3 dR;
};

#if defined(__GNUC__) && !defined(__clang__)
// A SolverBody is 28 doubles with no padding, so four bodies' records can be moved in blocks of four doubles and
// transposed in registers: block k of the four bodies gives the lanes of doubles 4k .. 4k + 3. That is four loads
// and eight shuffles for sixteen values, against sixteen scalar loads and twelve inserts.
static_assert(sizeof(SolverBody) == 28 * sizeof(Real) && offsetof(SolverBody, v) == 0 &&
              offsetof(SolverBody, w) == 3 * sizeof(Real) && offsetof(SolverBody, dp) == 6 * sizeof(Real) &&
              offsetof(SolverBody, dR) == 9 * sizeof(Real) && offsetof(SolverBody, invMass) == 18 * sizeof(Real) &&
              offsetof(SolverBody, invInertia) == 19 * sizeof(Real));
using Index = long __attribute__((vector_size(32)));
// rows[l] -> lanes: out[j][l] = rows[l][j]. Its own inverse.
RL_LANES_INLINE void transpose(const V rows[4], V out[4]) {
    const V t0 = __builtin_shuffle(rows[0], rows[1], Index{0, 4, 2, 6});
    const V t1 = __builtin_shuffle(rows[0], rows[1], Index{1, 5, 3, 7});
    const V t2 = __builtin_shuffle(rows[2], rows[3], Index{0, 4, 2, 6});
    const V t3 = __builtin_shuffle(rows[2], rows[3], Index{1, 5, 3, 7});
    out[0] = __builtin_shuffle(t0, t2, Index{0, 1, 4, 5});
    out[1] = __builtin_shuffle(t1, t3, Index{0, 1, 4, 5});
    out[2] = __builtin_shuffle(t0, t2, Index{2, 3, 6, 7});
    out[3] = __builtin_shuffle(t1, t3, Index{2, 3, 6, 7});
}
// Doubles 4 block .. 4 block + 3 of the four bodies, one V per double. (Written out: GCC's -O2 kept loops over the
// lanes and blocks as loops, which made the gather slower than the scalar one.)
RL_LANES_INLINE void loadBlock(const char* const record[4], int block, V out[4]) {
    V rows[4];
    std::memcpy(&rows[0], record[0] + block * sizeof(V), sizeof(V));
    std::memcpy(&rows[1], record[1] + block * sizeof(V), sizeof(V));
    std::memcpy(&rows[2], record[2] + block * sizeof(V), sizeof(V));
    std::memcpy(&rows[3], record[3] + block * sizeof(V), sizeof(V));
    transpose(rows, out);
}

template <bool kMotion>
RL_LANES_INLINE void gather(Side& s, std::span<const SolverBody> bodies, const uint32_t index[4]) {
    const char* const record[4] = {
        reinterpret_cast<const char*>(&bodies[index[0]]), reinterpret_cast<const char*>(&bodies[index[1]]),
        reinterpret_cast<const char*>(&bodies[index[2]]), reinterpret_cast<const char*>(&bodies[index[3]])};
    V d[28]; // d[k]: double k of the record, per lane
    loadBlock(record, 0, d);
    loadBlock(record, 1, d + 4);
    if constexpr (kMotion) {
        loadBlock(record, 2, d + 8);
        loadBlock(record, 3, d + 12);
    }
    loadBlock(record, 4, d + 16);
    loadBlock(record, 5, d + 20);
    loadBlock(record, 6, d + 24);
    s.v = {d[0], d[1], d[2]};
    s.w = {d[3], d[4], d[5]};
    s.invMass = d[18];
    s.invInertia = {{{d[19], d[20], d[21]}, {d[22], d[23], d[24]}, {d[25], d[26], d[27]}}};
    if constexpr (kMotion) {
        s.dp = {d[6], d[7], d[8]};
        s.dR = {{{d[9], d[10], d[11]}, {d[12], d[13], d[14]}, {d[15], d[16], d[17]}}};
    }
}

RL_LANES_INLINE void scatter(const Side& s, std::span<SolverBody> bodies, const uint32_t index[4]) {
    const V first[4] = {s.v.x, s.v.y, s.v.z, s.w.x}, rest[4] = {s.w.y, s.w.z, s.w.y, s.w.z};
    V head[4], tail[4];
    transpose(first, head); // head[l]: v and w.x of lane l
    transpose(rest, tail);  // tail[l]: w.y, w.z of lane l (and two copies)
#pragma GCC unroll 4
    for (int l = 0; l < 4; ++l) {
        if (index[l] == 0)
            continue; // the static entry (and empty lanes): shared by every thread, never written
        char* record = reinterpret_cast<char*>(&bodies[index[l]]);
        std::memcpy(record, &head[l], sizeof(V));
        std::memcpy(record + sizeof(V), &tail[l], 2 * sizeof(Real));
    }
}
#else
template <bool kMotion>
RL_LANES_INLINE void gather(Side& s, std::span<const SolverBody> bodies, const uint32_t index[4]) {
    const SolverBody* b[4] = {&bodies[index[0]], &bodies[index[1]], &bodies[index[2]], &bodies[index[3]]};
    const auto lanes = [&](auto&& field) { return V{field(*b[0]), field(*b[1]), field(*b[2]), field(*b[3])}; };
    const auto vector = [&](Vec3 SolverBody::*member) {
        return L3{lanes([&](const SolverBody& x) { return (x.*member).x; }),
                  lanes([&](const SolverBody& x) { return (x.*member).y; }),
                  lanes([&](const SolverBody& x) { return (x.*member).z; })};
    };
    const auto matrix = [&](Mat3 SolverBody::*member, M3& out) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                out.m[c][r] = lanes([&](const SolverBody& x) { return (x.*member)[c][r]; });
    };
    s.v = vector(&SolverBody::v);
    s.w = vector(&SolverBody::w);
    s.invMass = lanes([](const SolverBody& x) { return x.invMass; });
    matrix(&SolverBody::invInertia, s.invInertia);
    if constexpr (kMotion) {
        s.dp = vector(&SolverBody::dp);
        matrix(&SolverBody::dR, s.dR);
    }
}

RL_LANES_INLINE void scatter(const Side& s, std::span<SolverBody> bodies, const uint32_t index[4]) {
    for (int l = 0; l < 4; ++l) {
        if (index[l] == 0)
            continue; // the static entry (and empty lanes): shared by every thread, never written
        SolverBody& b = bodies[index[l]];
        b.v = Vec3(s.v.x[l], s.v.y[l], s.v.z[l]);
        b.w = Vec3(s.w.x[l], s.w.y[l], s.w.z[l]);
    }
}

#endif

// The constraints' scales on each side's inverse mass and inertia, as inverseOf() in ContactSolver.cpp: a held side
// (scale 0) is read but not moved.
RL_LANES_INLINE void scaleSide(Side& s, const V& scale) {
    s.invMass = s.invMass * scale;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            s.invInertia.m[c][r] = s.invInertia.m[c][r] * scale;
}
RL_LANES_INLINE void hold(Side& a, Side& b, const Lanes& scaleA, const Lanes& scaleB) {
    scaleSide(a, get(scaleA));
    scaleSide(b, get(scaleB));
}

// One row of one point along direction d: r x d for each body, and that times the body's inverse inertia, computed
// as the scalar sweeps compute them (angularOf(), inertiaOf() in ContactSolver.cpp).
struct Row {
    L3 d, angularA, angularB, inertiaA, inertiaB;
};
RL_LANES_INLINE Row makeRow(const Side& a, const Side& b, const L3& d, const L3& rA, const L3& rB) {
    Row row;
    row.d = d;
    row.angularA = cross(rA, d);
    row.angularB = cross(rB, d);
    row.inertiaA = a.invInertia * row.angularA;
    row.inertiaB = b.invInertia * row.angularB;
    return row;
}

// Relative velocity along the row: dot(d, vB - vA) + wB . (rB x d) - wA . (rA x d), as rowVelocity().
RL_LANES_INLINE V rowVelocity(const Side& a, const Side& b, const Row& row) {
    return (dot(row.d, b.v - a.v) + dot(b.w, row.angularB)) - dot(a.w, row.angularA);
}

// The impulse j along the row, as applyRow(): B gains it, A loses it.
RL_LANES_INLINE void applyRow(Side& a, Side& b, const Row& row, const V& j) {
    const V ja = a.invMass * j, jb = b.invMass * j;
    a.v = a.v - ja * row.d;
    a.w = a.w - j * row.inertiaA;
    b.v = b.v + jb * row.d;
    b.w = b.w + j * row.inertiaB;
}

// The friction rows of a batch's manifolds, as applyFriction() and applyTwist() in ContactSolver.cpp: impulses j0, j1
// along the tangents at the friction centres, jt about the normal.
RL_LANES_INLINE void applyFriction(Side& a, Side& b, const L3 tangent[2], const L3& centerA, const L3& centerB,
                                   const V& j0, const V& j1) {
    const L3 P = j0 * tangent[0] + j1 * tangent[1];
    a.v = a.v - a.invMass * P;
    a.w = a.w - a.invInertia * cross(centerA, P);
    b.v = b.v + b.invMass * P;
    b.w = b.w + b.invInertia * cross(centerB, P);
}
RL_LANES_INLINE void applyTwist(Side& a, Side& b, const L3& normal, const V& jt) {
    const L3 T = jt * normal;
    a.w = a.w - a.invInertia * T;
    b.w = b.w + b.invInertia * T;
}

} // namespace

RL_WIDE_CLONES void ContactSolver::warmStartBatchRange(std::span<SolverBody> bodies, size_t begin, size_t end) {
    if (!m_settings.warmStarting)
        return;
    for (size_t n = begin; n < end; ++n) {
        const Batch& batch = m_batches[n];
        Side a, b;
        gather<false>(a, bodies, batch.bodyA);
        gather<false>(b, bodies, batch.bodyB);
        if (batch.holds)
            hold(a, b, batch.scaleA, batch.scaleB);
        const L3 normal = load(batch.normal);
        const L3 tangent[2] = {load(batch.tangent[0]), load(batch.tangent[1])};
        for (uint32_t k = 0; k < batch.pointCount; ++k) {
            const BatchPoint& p = m_batchPoints[batch.firstPoint + k];
            if (!anyNonZero(p.impulse))
                continue; // speculative points that never pushed, in every lane: nothing to apply
            const L3 rA = load(p.rA), rB = load(p.rB);
            applyRow(a, b, makeRow(a, b, normal, rA, rB), get(p.impulse));
        }
        applyTwist(a, b, normal, get(batch.twistImpulse));
        applyFriction(a, b, tangent, load(batch.centerA), load(batch.centerB), get(batch.frictionImpulse[0]),
                      get(batch.frictionImpulse[1]));
        scatter(a, bodies, batch.bodyA);
        scatter(b, bodies, batch.bodyB);
    }
}

RL_WIDE_CLONES void ContactSolver::solveBatchRange(std::span<SolverBody> bodies, bool useBias, size_t begin,
                                                   size_t end) {
    const V inverseH = splat(m_inverseH), zero = splat(0.0);
    const V biasRate = splat(m_soft.biasRate), maxPushout = splat(-m_settings.maxPushoutSpeed);
    const V softMass = splat(useBias ? m_soft.massScale : 1.0),
            softImpulse = splat(useBias ? m_soft.impulseScale : 0.0);
    const V one = splat(1.0);
    const bool friction = m_settings.friction;
    for (size_t n = begin; n < end; ++n) {
        Batch& batch = m_batches[n];
        Side a, b;
        gather<true>(a, bodies, batch.bodyA);
        gather<true>(b, bodies, batch.bodyB);
        if (batch.holds)
            hold(a, b, batch.scaleA, batch.scaleB);
        const L3 normal = load(batch.normal);
        for (uint32_t k = 0; k < batch.pointCount; ++k) {
            BatchPoint& p = m_batchPoints[batch.firstPoint + k];
            // Current separation from the motion since the step began; anchors follow each body's rotation.
            const L3 rA = load(p.rA), rB = load(p.rB);
            const L3 d = (b.dp - a.dp) + (b.dR * rB - a.dR * rA);
            const V s = dot(normal, d) + get(p.baseSeparation);
            // Speculative points (s > 0) may close the gap within this substep; touching ones are soft while the
            // bias pushes them apart, and rigid in the relax pass.
            const auto speculative = s > zero;
            const V pushout = useBias ? maxOf(biasRate * s, maxPushout) : zero;
            const V velocityBias = select(speculative, s * inverseH, pushout);
            const V massScale = select(speculative, one, softMass);
            const V impulseScale = select(speculative, zero, softImpulse);
            const Row row = makeRow(a, b, normal, rA, rB);
            const V vn = rowVelocity(a, b, row);
            const V accumulated = get(p.impulse);
            const V trial = (-get(p.mass) * massScale) * (vn + velocityBias) - impulseScale * accumulated;
            const V total = maxOf(accumulated + trial, zero);
            const V impulse = total - accumulated;
            put(p.impulse, total);
            put(p.maxNormalImpulse, maxOf(get(p.maxNormalImpulse), impulse));
            applyRow(a, b, row, impulse);
        }
        if (friction) {
            // The manifolds' friction (solveConstraint() in ContactSolver.cpp): the twist, then the tangent block at
            // the friction centre, clamped to the disc.
            V total = zero, twistLimit = zero;
            for (uint32_t k = 0; k < batch.pointCount; ++k) {
                const BatchPoint& p = m_batchPoints[batch.firstPoint + k];
                const V impulse = get(p.impulse);
                total = total + impulse;
                twistLimit = twistLimit + get(p.leverArm) * impulse;
            }
            const V twist = get(batch.twistImpulse);
            const V f0 = get(batch.frictionImpulse[0]), f1 = get(batch.frictionImpulse[1]);
            // In no lane does anything push or hold: every clamp would give zero.
            if (anyNonZero(total) || anyNonZero(twist) || anyNonZero(f0) || anyNonZero(f1)) {
                const V coefficient = get(batch.friction);
                const L3 tangent[2] = {load(batch.tangent[0]), load(batch.tangent[1])};
                const L3 centerA = load(batch.centerA), centerB = load(batch.centerB);
                {
                    const V spin = dot(normal, b.w - a.w);
                    const V limit = coefficient * twistLimit;
                    const V newImpulse = clampTo(twist - get(batch.twistMass) * spin, -limit, limit);
                    put(batch.twistImpulse, newImpulse);
                    applyTwist(a, b, normal, newImpulse - twist);
                }
                const L3 vr = (b.v + cross(b.w, centerB)) - (a.v + cross(a.w, centerA));
                const V v0 = dot(vr, tangent[0]), v1 = dot(vr, tangent[1]);
                const V m00 = get(batch.frictionMass[0]), m01 = get(batch.frictionMass[1]),
                        m11 = get(batch.frictionMass[2]);
                V n0 = f0 - (m00 * v0 + m01 * v1);
                V n1 = f1 - (m01 * v0 + m11 * v1);
                const V limit = coefficient * total;
                const V length2 = n0 * n0 + n1 * n1;
                const auto outside = length2 > limit * limit;
                const V scale = limit / sqrtOf(length2); // used only where outside: length2 > 0 there
                n0 = select(outside, n0 * scale, n0);
                n1 = select(outside, n1 * scale, n1);
                put(batch.frictionImpulse[0], n0);
                put(batch.frictionImpulse[1], n1);
                applyFriction(a, b, tangent, centerA, centerB, n0 - f0, n1 - f1);
            }
        }
        scatter(a, bodies, batch.bodyA);
        scatter(b, bodies, batch.bodyB);
    }
}

} // namespace rl
