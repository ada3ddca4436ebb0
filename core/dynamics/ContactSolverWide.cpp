// The contact solver's sweeps over batches of W constraints, W = 4 or 8 (ContactSolver::warmStartBatchRange() and
// solveBatchRange()).
//
// A batch holds W constraints of one level of the schedule, so its lanes share no moving body: the lanes are
// independent, and every body receives the same updates in the same order as in the sequential sweep. Each lane
// performs exactly the operations of the scalar rows in ContactSolver.cpp, in the same order, so the results are the
// same numbers. This file is built with -ffp-contract=off (core/CMakeLists.txt): no a * b + c becomes a fused
// multiply-add, so the x86-64-v4 function, the x86-64-v3 and baseline clones and the scalar reference compute the
// same bits, and a machine gives the same results whichever it runs.
#include "dynamics/ContactSolver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
// Four lanes: one AVX2 register of doubles where the CPU has it, two SSE2 registers elsewhere. Eight lanes run only
// where the CPU has AVX-512 (ContactSolver::buildBatches() chooses), in one register.
#define RL_WIDE4 __attribute__((target_clones("arch=x86-64-v3", "default")))
#define RL_WIDE8 __attribute__((target("arch=x86-64-v4")))
#else
#define RL_WIDE4
#define RL_WIDE8
#endif
#define RL_LANES_INLINE inline __attribute__((always_inline))
// The sanitizer build never runs eight lanes (ContactSolver::laneWidthHere() gives four there), so the eight-lane
// functions are left empty in it: without a target there, each of their 512-bit operations was lowered into four SSE2
// ones, and this file took 130 s to compile in that build (2026-12-07), most of CI's sanitizer build's longest job.
#if defined(__SANITIZE_ADDRESS__)
#define RL_EIGHT_LANES 0
#else
#define RL_EIGHT_LANES 1
#endif

namespace rl {

namespace {

// Vec<W>::V holds W doubles, one per lane. With GCC it is a vector type. Elsewhere (the clang build of the fuzzers)
// it is an array with per-lane loops: the same numbers, at scalar speed.
#if defined(__GNUC__) && !defined(__clang__)
typedef double V4 __attribute__((vector_size(32)));
typedef long M4 __attribute__((vector_size(32)));
typedef float F4 __attribute__((vector_size(16)));
typedef double V8 __attribute__((vector_size(64)));
typedef long M8 __attribute__((vector_size(64)));
typedef float F8 __attribute__((vector_size(32)));
template <int W>
struct Vec;
template <>
struct Vec<4> {
    using V = V4;
    using Mask = M4; // what a comparison of V gives
    using F = F4;    // W floats
};
template <>
struct Vec<8> {
    using V = V8;
    using Mask = M8;
    using F = F8;
};
template <class V, class Mask>
RL_LANES_INLINE V select(const Mask& m, const V& x, const V& y) { // m ? x : y, per lane
    return m ? x : y;
}
// W floats widened exactly, lane by lane. (GCC 12 lowers __builtin_convertvector from floats to doubles by halves:
// with four lanes, two two-lane conversions through the stack and an insert, where this loop becomes one
// vcvtps2pd; with eight, two four-lane ones where this is one.)
template <int W, class Floats>
RL_LANES_INLINE typename Vec<W>::V widenFloats(const Floats& f) {
    typename Vec<W>::V r;
#pragma GCC unroll 8
    for (int l = 0; l < W; ++l)
        r[l] = static_cast<Real>(f[l]);
    return r;
}
template <int W>
RL_LANES_INLINE typename Vec<W>::V widen(const ContactSolver::FloatLanes<W>& lanes) { // exactly
    return widenFloats<W>(lanes.v);
}
// x + y added in floats, then widened exactly.
template <int W>
RL_LANES_INLINE typename Vec<W>::V widenSum(const ContactSolver::FloatLanes<W>& x,
                                            const ContactSolver::FloatLanes<W>& y) {
    typename Vec<W>::F f, g;
    std::memcpy(&f, x.v, sizeof f);
    std::memcpy(&g, y.v, sizeof g);
    return widenFloats<W>(f + g);
}
#else
template <int W>
struct ArrayV {
    Real v[W];
    Real& operator[](int l) { return v[l]; }
    Real operator[](int l) const { return v[l]; }
};
template <int W>
struct ArrayMask {
    bool v[W];
};
template <int W>
struct Vec {
    using V = ArrayV<W>;
    using Mask = ArrayMask<W>;
};
template <class Out, int W, class F>
RL_LANES_INLINE Out perLane(F&& f) {
    Out r;
    for (int l = 0; l < W; ++l)
        r.v[l] = f(l);
    return r;
}
template <int W>
RL_LANES_INLINE ArrayV<W> operator+(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayV<W>, W>([&](int l) { return a.v[l] + b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> operator-(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayV<W>, W>([&](int l) { return a.v[l] - b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> operator*(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayV<W>, W>([&](int l) { return a.v[l] * b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> operator-(const ArrayV<W>& a) {
    return perLane<ArrayV<W>, W>([&](int l) { return -a.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> operator/(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayV<W>, W>([&](int l) { return a.v[l] / b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayMask<W> operator<(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayMask<W>, W>([&](int l) { return a.v[l] < b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayMask<W> operator>(const ArrayV<W>& a, const ArrayV<W>& b) {
    return perLane<ArrayMask<W>, W>([&](int l) { return a.v[l] > b.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> select(const ArrayMask<W>& m, const ArrayV<W>& x, const ArrayV<W>& y) {
    return perLane<ArrayV<W>, W>([&](int l) { return m.v[l] ? x.v[l] : y.v[l]; });
}
template <int W>
RL_LANES_INLINE ArrayV<W> widen(const ContactSolver::FloatLanes<W>& lanes) {
    return perLane<ArrayV<W>, W>([&](int l) { return static_cast<Real>(lanes.v[l]); });
}
template <int W>
RL_LANES_INLINE ArrayV<W> widenSum(const ContactSolver::FloatLanes<W>& x, const ContactSolver::FloatLanes<W>& y) {
    return perLane<ArrayV<W>, W>([&](int l) { return static_cast<Real>(x.v[l] + y.v[l]); });
}
#endif

template <int W>
using Lanes = ContactSolver::Lanes<W>;

template <int W>
RL_LANES_INLINE typename Vec<W>::V splat(Real x) {
    typename Vec<W>::V r;
    for (int l = 0; l < W; ++l)
        r[l] = x;
    return r;
}
template <int W>
RL_LANES_INLINE typename Vec<W>::V get(const Lanes<W>& lanes) {
    typename Vec<W>::V r;
    std::memcpy(&r, lanes.v, sizeof r);
    return r;
}
template <int W>
RL_LANES_INLINE typename Vec<W>::V get(const ContactSolver::FloatLanes<W>& lanes) {
    return widen<W>(lanes);
}
template <int W>
RL_LANES_INLINE void put(Lanes<W>& lanes, const typename Vec<W>::V& x) {
    std::memcpy(lanes.v, &x, sizeof x);
}
// Whether any lane is not zero.
template <int W>
RL_LANES_INLINE bool anyNonZero(const Lanes<W>& lanes) {
    bool any = false;
    for (int l = 0; l < W; ++l)
        any = any || lanes.v[l] != 0.0;
    return any;
}
template <int W, class V>
RL_LANES_INLINE bool anyNonZero(const V& x) {
    bool any = false;
    for (int l = 0; l < W; ++l)
        any = any || x[l] != 0.0;
    return any;
}
// std::sqrt per lane.
template <int W, class V>
RL_LANES_INLINE V sqrtOf(const V& x) {
    V r = x;
    for (int l = 0; l < W; ++l)
        r[l] = std::sqrt(x[l]);
    return r;
}
// std::max(a, b): a < b ? b : a, per lane.
template <class V>
RL_LANES_INLINE V maxOf(const V& a, const V& b) {
    return select(a < b, b, a);
}
// std::clamp(x, lo, hi): x < lo ? lo : (hi < x ? hi : x), per lane.
template <class V>
RL_LANES_INLINE V clampTo(const V& x, const V& lo, const V& hi) {
    return select(x < lo, lo, select(hi < x, hi, x));
}

// A vector of three lanes-wide components.
template <class V>
struct L3 {
    V x, y, z;
};
template <int W, class Stored>
RL_LANES_INLINE L3<typename Vec<W>::V> load(const Stored* c) {
    return {get<W>(c[0]), get<W>(c[1]), get<W>(c[2])};
}
// A point's anchor on B: its anchor on A plus the batch's offset, added in floats as prepare() adds them
// (ContactConstraint::anchorOffset).
template <int W, class BatchT, class PointT>
RL_LANES_INLINE L3<typename Vec<W>::V> anchorB(const BatchT& batch, const PointT& p) {
    return {widenSum<W>(p.rA[0], batch.anchorOffset[0]), widenSum<W>(p.rA[1], batch.anchorOffset[1]),
            widenSum<W>(p.rA[2], batch.anchorOffset[2])};
}
template <class V>
RL_LANES_INLINE L3<V> operator+(const L3<V>& a, const L3<V>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class V>
RL_LANES_INLINE L3<V> operator-(const L3<V>& a, const L3<V>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class V>
RL_LANES_INLINE L3<V> operator*(const V& s, const L3<V>& a) {
    return {s * a.x, s * a.y, s * a.z};
}
// glm::dot's order: (x x + y y) + z z.
template <class V>
RL_LANES_INLINE V dot(const L3<V>& a, const L3<V>& b) {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}
// glm::cross's order.
template <class V>
RL_LANES_INLINE L3<V> cross(const L3<V>& x, const L3<V>& y) {
    return {x.y * y.z - y.y * x.z, x.z * y.x - y.z * x.x, x.x * y.y - y.x * x.y};
}
// A column-major 3x3 matrix (glm's m[c][r]) times a vector, in glm's order: (m0 x + m1 y) + m2 z per row.
template <class V>
struct M3 {
    V m[3][3];
};
template <class V>
RL_LANES_INLINE L3<V> operator*(const M3<V>& a, const L3<V>& v) {
    return {(a.m[0][0] * v.x + a.m[1][0] * v.y) + a.m[2][0] * v.z,
            (a.m[0][1] * v.x + a.m[1][1] * v.y) + a.m[2][1] * v.z,
            (a.m[0][2] * v.x + a.m[1][2] * v.y) + a.m[2][2] * v.z};
}

// The velocities (and, for the solve, the motion since the step began) of one side of a batch, gathered from the
// lanes' bodies. Lanes whose body is the static entry 0 read its zeros and identity and are never written back.
template <class V>
struct Side {
    L3<V> v, w;
    V invMass;
    M3<V> invInertia; // only m[0][0] is read (and set) where isotropic
    L3<V> dp;
    M3<V> dR;
    bool isotropic = false; // every lane's body is SolverBody::isotropic: invInertia is m[0][0] times the identity
};

// The doubles of a SolverBody record: v 0-2, w 3-5, dp 6-8, dR 9-17, invMass 18, invInertia 19-27, unused 28-31.
static_assert(sizeof(SolverBody) == 32 * sizeof(Real) && offsetof(SolverBody, v) == 0 &&
              offsetof(SolverBody, w) == 3 * sizeof(Real) && offsetof(SolverBody, dp) == 6 * sizeof(Real) &&
              offsetof(SolverBody, dR) == 9 * sizeof(Real) && offsetof(SolverBody, invMass) == 18 * sizeof(Real) &&
              offsetof(SolverBody, invInertia) == 19 * sizeof(Real));

template <class V>
RL_LANES_INLINE void unpack(Side<V>& s, const V* d, bool motion) { // d[k]: double k of the record, per lane
    s.v = {d[0], d[1], d[2]};
    s.w = {d[3], d[4], d[5]};
    s.invMass = d[18];
    if (s.isotropic) { // d[20] .. d[27] hold the zeros and copies of d[19], and may not have been read
        s.invInertia = M3<V>{};
        s.invInertia.m[0][0] = d[19];
    } else {
        s.invInertia = {{{d[19], d[20], d[21]}, {d[22], d[23], d[24]}, {d[25], d[26], d[27]}}};
    }
    if (motion) {
        s.dp = {d[6], d[7], d[8]};
        s.dR = {{{d[9], d[10], d[11]}, {d[12], d[13], d[14]}, {d[15], d[16], d[17]}}};
    }
}

#if defined(__GNUC__) && !defined(__clang__)
// The records of a batch's bodies are moved in blocks of W doubles and transposed in registers: block k of the W
// bodies gives the lanes of doubles W k .. W k + W - 1. (Four loads and eight shuffles for sixteen values with four
// lanes, against sixteen scalar loads and twelve inserts.)
typedef long I4 __attribute__((vector_size(32)));
typedef long I8 __attribute__((vector_size(64)));
// rows[l] -> lanes: out[j][l] = rows[l][j]. Its own inverse.
RL_LANES_INLINE void transpose(const V4 rows[4], V4 out[4]) {
    const V4 t0 = __builtin_shuffle(rows[0], rows[1], I4{0, 4, 2, 6});
    const V4 t1 = __builtin_shuffle(rows[0], rows[1], I4{1, 5, 3, 7});
    const V4 t2 = __builtin_shuffle(rows[2], rows[3], I4{0, 4, 2, 6});
    const V4 t3 = __builtin_shuffle(rows[2], rows[3], I4{1, 5, 3, 7});
    out[0] = __builtin_shuffle(t0, t2, I4{0, 1, 4, 5});
    out[1] = __builtin_shuffle(t1, t3, I4{0, 1, 4, 5});
    out[2] = __builtin_shuffle(t0, t2, I4{2, 3, 6, 7});
    out[3] = __builtin_shuffle(t1, t3, I4{2, 3, 6, 7});
}
RL_LANES_INLINE void transpose(const V8 rows[8], V8 out[8]) {
    V8 a[8], b[8];
    for (int i = 0; i < 4; ++i) { // pairs of rows interleaved by element
        a[2 * i] = __builtin_shuffle(rows[2 * i], rows[2 * i + 1], I8{0, 8, 2, 10, 4, 12, 6, 14});
        a[2 * i + 1] = __builtin_shuffle(rows[2 * i], rows[2 * i + 1], I8{1, 9, 3, 11, 5, 13, 7, 15});
    }
    for (int i = 0; i < 2; ++i) // then by pairs of elements
        for (int j = 0; j < 2; ++j) {
            const V8& x = a[4 * i + j];
            const V8& y = a[4 * i + j + 2];
            b[4 * i + j] = __builtin_shuffle(x, y, I8{0, 1, 8, 9, 4, 5, 12, 13});
            b[4 * i + j + 2] = __builtin_shuffle(x, y, I8{2, 3, 10, 11, 6, 7, 14, 15});
        }
    for (int j = 0; j < 4; ++j) { // then by halves
        out[j] = __builtin_shuffle(b[j], b[j + 4], I8{0, 1, 2, 3, 8, 9, 10, 11});
        out[j + 4] = __builtin_shuffle(b[j], b[j + 4], I8{4, 5, 6, 7, 12, 13, 14, 15});
    }
}
// Doubles W block .. W block + W - 1 of the W bodies, one vector per double. (Written out: GCC's -O2 kept loops over
// the lanes and blocks as loops, which made the gather slower than the scalar one.)
template <int W>
RL_LANES_INLINE void loadBlock(const char* const record[W], int block, typename Vec<W>::V out[W]) {
    using V = typename Vec<W>::V;
    V rows[W];
#pragma GCC unroll 8
    for (int l = 0; l < W; ++l)
        std::memcpy(&rows[l], record[l] + block * sizeof(V), sizeof(V));
    transpose(rows, out);
}

template <int W, bool kMotion>
RL_LANES_INLINE void gather(Side<typename Vec<W>::V>& s, std::span<const SolverBody> bodies, const uint32_t index[W]) {
    using V = typename Vec<W>::V;
    const char* record[W];
#pragma GCC unroll 8
    for (int l = 0; l < W; ++l)
        record[l] = reinterpret_cast<const char*>(&bodies[index[l]]);
    V d[32];
    // The blocks holding v and w, then dp and dR (the solve only), then invMass and invInertia.
    if constexpr (W == 4) {
        loadBlock<4>(record, 0, d);
        loadBlock<4>(record, 1, d + 4);
        if constexpr (kMotion) {
            loadBlock<4>(record, 2, d + 8);
            loadBlock<4>(record, 3, d + 12);
        }
        loadBlock<4>(record, 4, d + 16);
        if (!s.isotropic) {
            loadBlock<4>(record, 5, d + 20);
            loadBlock<4>(record, 6, d + 24);
        }
    } else {
        loadBlock<8>(record, 0, d);
        if constexpr (kMotion)
            loadBlock<8>(record, 1, d + 8);
        loadBlock<8>(record, 2, d + 16);
        if (!s.isotropic)
            loadBlock<8>(record, 3, d + 24);
    }
    unpack(s, d, kMotion);
}

template <int W>
RL_LANES_INLINE void scatter(const Side<typename Vec<W>::V>& s, std::span<SolverBody> bodies, const uint32_t index[W]) {
    using V = typename Vec<W>::V;
    if constexpr (W == 4) {
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
    } else {
        const V rows[8] = {s.v.x, s.v.y, s.v.z, s.w.x, s.w.y, s.w.z, s.w.z, s.w.z};
        V out[8];
        transpose(rows, out); // out[l]: v and w of lane l (and two copies)
#pragma GCC unroll 8
        for (int l = 0; l < 8; ++l) {
            if (index[l] == 0)
                continue;
            std::memcpy(reinterpret_cast<char*>(&bodies[index[l]]), &out[l], 6 * sizeof(Real));
        }
    }
}
#else
template <int W, bool kMotion>
RL_LANES_INLINE void gather(Side<typename Vec<W>::V>& s, std::span<const SolverBody> bodies, const uint32_t index[W]) {
    using V = typename Vec<W>::V;
    V d[32];
    for (int l = 0; l < W; ++l) {
        Real record[32];
        std::memcpy(record, &bodies[index[l]], sizeof record);
        for (int k = 0; k < 32; ++k)
            d[k][l] = record[k];
    }
    unpack(s, d, kMotion);
}

template <int W>
RL_LANES_INLINE void scatter(const Side<typename Vec<W>::V>& s, std::span<SolverBody> bodies, const uint32_t index[W]) {
    for (int l = 0; l < W; ++l) {
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
template <class V>
RL_LANES_INLINE void scaleSide(Side<V>& s, const V& scale) {
    s.invMass = s.invMass * scale;
    if (s.isotropic) { // the zeros off the diagonal stay +0
        s.invInertia.m[0][0] = s.invInertia.m[0][0] * scale;
        return;
    }
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            s.invInertia.m[c][r] = s.invInertia.m[c][r] * scale;
}

// Both sides of a batch, gathered, with a held side's inverse mass and inertia scaled (see scaleSide()).
template <int W, bool kMotion, class BatchT, class ScalesT>
RL_LANES_INLINE void gatherSides(const BatchT& batch, const ScalesT& scales, std::span<const SolverBody> bodies,
                                 Side<typename Vec<W>::V>& a, Side<typename Vec<W>::V>& b) {
    a.isotropic = b.isotropic = batch.isotropic;
    gather<W, kMotion>(a, bodies, batch.bodyA);
    gather<W, kMotion>(b, bodies, batch.bodyB);
    if (batch.holds) {
        scaleSide(a, get<W>(scales.a));
        scaleSide(b, get<W>(scales.b));
    }
}

// d I x for the lanes' numbers d, bit for bit what the full product M x gives for M = d I with +0 off the diagonal
// (glm's order, operator* above): row r sums d x_r and two +0 times the other components. A sum of zeros is -0
// only where every term is -0, and a +0 times a component is -0 where the component's sign bit is set; so the row is
// d x_r where that is not zero, else -0 where x, y and z all have their sign bits set, else +0, which is d x_r plus
// that zero. (Only non-finite components, which the full product spreads to the other rows, would differ.)
#if defined(__GNUC__) && !defined(__clang__)
template <class V>
RL_LANES_INLINE L3<V> isotropicTimes(const V& d, const L3<V>& x) {
    using Mask = decltype(x.x < x.x);
    // (A cast between vector types of one size keeps the bits.)
    const Mask negative = (((Mask)x.x & (Mask)x.y) & (Mask)x.z) & std::numeric_limits<int64_t>::min();
    const V zero = (V)negative;
    return {d * x.x + zero, d * x.y + zero, d * x.z + zero};
}
#else
template <class V>
RL_LANES_INLINE L3<V> isotropicTimes(const V& d, const L3<V>& x) {
    L3<V> r;
    for (size_t l = 0; l < sizeof(V) / sizeof(Real); ++l) {
        const Real zero = std::signbit(x.x[l]) && std::signbit(x.y[l]) && std::signbit(x.z[l]) ? -0.0 : 0.0;
        r.x[l] = d[l] * x.x[l] + zero;
        r.y[l] = d[l] * x.y[l] + zero;
        r.z[l] = d[l] * x.z[l] + zero;
    }
    return r;
}
#endif
template <class V>
RL_LANES_INLINE L3<V> inverseInertiaTimes(const Side<V>& s, const L3<V>& x) {
    return s.isotropic ? isotropicTimes(s.invInertia.m[0][0], x) : s.invInertia * x;
}

// One row of one point along direction d: r x d for each body, and that times the body's inverse inertia, computed
// as the scalar sweeps compute them (angularOf(), inertiaOf() in ContactSolver.cpp).
template <class V>
struct Row {
    // The direction, the batch's normal, by address: copied into every row, its three lanes-wide components were
    // stored to the stack at every point (AVX2 has no registers to spare), 5.6 % of solveBatches4's instructions
    // over pyramid20's first 60 frames (callgrind, 132.1 million, now 124.8).
    const L3<V>* d;
    L3<V> angularA, angularB, inertiaA, inertiaB;
};
template <class V>
Row<V> makeRow(const Side<V>& a, const Side<V>& b, const L3<V>&& d, const L3<V>& rA, const L3<V>& rB) = delete;
template <class V>
RL_LANES_INLINE Row<V> makeRow(const Side<V>& a, const Side<V>& b, const L3<V>& d, const L3<V>& rA, const L3<V>& rB) {
    Row<V> row;
    row.d = &d;
    row.angularA = cross(rA, d);
    row.angularB = cross(rB, d);
    row.inertiaA = inverseInertiaTimes(a, row.angularA);
    row.inertiaB = inverseInertiaTimes(b, row.angularB);
    return row;
}

// Relative velocity along the row: dot(d, vB - vA) + wB . (rB x d) - wA . (rA x d), as rowVelocity().
template <class V>
RL_LANES_INLINE V rowVelocity(const Side<V>& a, const Side<V>& b, const Row<V>& row) {
    return (dot(*row.d, b.v - a.v) + dot(b.w, row.angularB)) - dot(a.w, row.angularA);
}

// The impulse j along the row, as applyRow(): B gains it, A loses it.
template <class V>
RL_LANES_INLINE void applyRow(Side<V>& a, Side<V>& b, const Row<V>& row, const V& j) {
    const V ja = a.invMass * j, jb = b.invMass * j;
    a.v = a.v - ja * *row.d;
    a.w = a.w - j * row.inertiaA;
    b.v = b.v + jb * *row.d;
    b.w = b.w + j * row.inertiaB;
}

// The friction rows of a batch's manifolds, as applyFriction() and applyTwist() in ContactSolver.cpp: impulses j0, j1
// along the tangents at the friction centres, jt about the normal.
template <class V>
RL_LANES_INLINE void applyFriction(Side<V>& a, Side<V>& b, const L3<V> tangent[2], const L3<V>& centerA,
                                   const L3<V>& centerB, const V& j0, const V& j1) {
    const L3<V> P = j0 * tangent[0] + j1 * tangent[1];
    a.v = a.v - a.invMass * P;
    a.w = a.w - inverseInertiaTimes(a, cross(centerA, P));
    b.v = b.v + b.invMass * P;
    b.w = b.w + inverseInertiaTimes(b, cross(centerB, P));
}
template <class V>
RL_LANES_INLINE void applyTwist(Side<V>& a, Side<V>& b, const L3<V>& normal, const V& jt) {
    const L3<V> T = jt * normal;
    a.w = a.w - inverseInertiaTimes(a, T);
    b.w = b.w + inverseInertiaTimes(b, T);
}

} // namespace

template <int W>
RL_LANES_INLINE void ContactSolver::warmStartBatches(BatchStore<W>& store, std::span<SolverBody> bodies, size_t begin,
                                                     size_t end) {
    using V = typename Vec<W>::V;
    for (size_t n = begin; n < end; ++n) {
        const Batch<W>& batch = store.batches[n];
        Side<V> a, b;
        gatherSides<W, false>(batch, store.scales[n], bodies, a, b);
        const L3<V> normal = load<W>(batch.normal);
        const L3<V> tangent[2] = {load<W>(batch.tangent[0]), load<W>(batch.tangent[1])};
        for (uint32_t k = 0; k < batch.pointCount; ++k) {
            const BatchPoint<W>& p = store.points[batch.firstPoint + k];
            if (!anyNonZero<W>(p.impulse))
                continue; // speculative points that never pushed, in every lane: nothing to apply
            const L3<V> rA = load<W>(p.rA), rB = anchorB<W>(batch, p);
            applyRow(a, b, makeRow(a, b, normal, rA, rB), get<W>(p.impulse));
        }
        applyTwist(a, b, normal, get<W>(batch.twistImpulse));
        applyFriction(a, b, tangent, load<W>(batch.centerA), load<W>(batch.centerB), get<W>(batch.frictionImpulse[0]),
                      get<W>(batch.frictionImpulse[1]));
        scatter<W>(a, bodies, batch.bodyA);
        scatter<W>(b, bodies, batch.bodyB);
    }
}

namespace {

// A struck batch's state before its sweep of the normal rows (see solveStruck()).
template <int W>
struct StruckStart {
    using V = typename Vec<W>::V;
    L3<V> va, wa, vb, wb;
    Lanes<W> impulse[4], largest[4];
    template <class StoreT, class BatchT>
    RL_LANES_INLINE void keep(const StoreT& store, const BatchT& batch, const Side<V>& a, const Side<V>& b) {
        va = a.v;
        wa = a.w;
        vb = b.v;
        wb = b.w;
        for (uint32_t k = 0; k < batch.pointCount; ++k) {
            impulse[k] = store.points[batch.firstPoint + k].impulse;
            if (!store.maxImpulse.empty())
                largest[k] = store.maxImpulse[batch.firstPoint + k];
        }
    }
};

// The lanes of a batch (bits of `blow`) whose struck manifolds' sweep took some of the blow or gave it back, as
// solveConstraint() in ContactSolver.cpp treats each: its rows solved again as a block (solveImpactRows()) from the
// state before the sweep; where the block has no answer, the sweep stands. Other lanes keep the sweep's numbers.
// (Out of line, with the first sweep repeated inside it for the struck batches, ramps.obj's solve stage over its
// first 120 frames took 118 ms against 105-107 inline, 2026-12-05.)
template <int W, bool kMaxImpulse, class BatchT, class StoreT>
RL_LANES_INLINE void solveStruck(StoreT& store, const BatchT& batch, Side<typename Vec<W>::V>& a,
                                 Side<typename Vec<W>::V>& b, const L3<typename Vec<W>::V>& normal, bool useBias,
                                 Real inverseH, const Softness& soft, const ContactSolverSettings& settings,
                                 const StruckStart<W>& start, uint32_t blow) {
    using V = typename Vec<W>::V;
    const V zero = splat<W>(0.0);
    const uint32_t first = batch.firstPoint, count = batch.pointCount;
    Side<V> startA = a, startB = b;
    startA.v = start.va;
    startA.w = start.wa;
    startB.v = start.vb;
    startB.w = start.wb;
    Row<V> rows[4];
    V startVelocity[4];
    for (uint32_t k = 0; k < count; ++k) {
        const auto& p = store.points[first + k];
        rows[k] = makeRow(startA, startB, normal, load<W>(p.rA), anchorB<W>(batch, p));
        startVelocity[k] = rowVelocity(startA, startB, rows[k]);
    }
    V delta[4], solvedImpulse[4], used[4], blockedLane = zero;
    for (uint32_t k = 0; k < count; ++k)
        delta[k] = solvedImpulse[k] = used[k] = zero;
    for (int l = 0; l < W; ++l) {
        if (!((blow >> l) & 1u))
            continue;
        const bool staticA = batch.bodyA[l] == 0, staticB = batch.bodyB[l] == 0;
        ImpactRows block;
        uint32_t slot[4];
        for (uint32_t k = 0; k < count; ++k) {
            const auto& p = store.points[first + k];
            if (!(static_cast<Real>(p.mass.v[l]) > 0.0))
                continue; // an empty point slot, or a point with no mass
            setImpactTarget(block, block.count, store.separation[first + k].v[l], useBias, inverseH, soft,
                            settings.maxPushoutSpeed, static_cast<Real>(p.mass.v[l]));
            const auto lane3 = [l](const L3<V>& x) { return Vec3(x.x[l], x.y[l], x.z[l]); };
            block.angularA[block.count] = staticA ? Vec3(0.0) : lane3(rows[k].angularA);
            block.inertiaA[block.count] = staticA ? Vec3(0.0) : lane3(rows[k].inertiaA);
            block.angularB[block.count] = staticB ? Vec3(0.0) : lane3(rows[k].angularB);
            block.inertiaB[block.count] = staticB ? Vec3(0.0) : lane3(rows[k].inertiaB);
            block.velocity[block.count] = startVelocity[k][l];
            block.impulse[block.count] = start.impulse[k].v[l];
            if (p.impulse.v[l] > 0.0) // pushing after the sweep (solveConstraint())
                block.guess |= 1u << block.count;
            slot[block.count++] = k;
        }
        block.massA = staticA ? 0.0 : startA.invMass[l];
        block.massB = staticB ? 0.0 : startB.invMass[l];
        if (block.count < 2 || !solveImpactRows(block))
            continue;
        blockedLane[l] = 1.0;
        for (int r = 0; r < block.count; ++r) {
            const uint32_t k = slot[r];
            solvedImpulse[k][l] = block.impulse[r];
            delta[k][l] = block.impulse[r] - start.impulse[k].v[l];
            used[k][l] = 1.0;
        }
    }
    if (!anyNonZero<W>(blockedLane))
        return;
    const auto blocked = blockedLane > zero;
    // The blocks' impulses applied to the state before the sweep, row by row as solveConstraint() applies them.
    Side<V> ta = startA, tb = startB;
    for (uint32_t k = 0; k < count; ++k) {
        const auto here = used[k] > zero;
        Side<V> na = ta, nb = tb;
        applyRow(na, nb, rows[k], delta[k]);
        ta.v = {select(here, na.v.x, ta.v.x), select(here, na.v.y, ta.v.y), select(here, na.v.z, ta.v.z)};
        ta.w = {select(here, na.w.x, ta.w.x), select(here, na.w.y, ta.w.y), select(here, na.w.z, ta.w.z)};
        tb.v = {select(here, nb.v.x, tb.v.x), select(here, nb.v.y, tb.v.y), select(here, nb.v.z, tb.v.z)};
        tb.w = {select(here, nb.w.x, tb.w.x), select(here, nb.w.y, tb.w.y), select(here, nb.w.z, tb.w.z)};
        auto& p = store.points[first + k];
        put<W>(p.impulse, select(blocked, select(here, solvedImpulse[k], get<W>(start.impulse[k])), get<W>(p.impulse)));
        if constexpr (kMaxImpulse) {
            Lanes<W>& largest = store.maxImpulse[first + k];
            const V before = get<W>(start.largest[k]);
            put<W>(largest, select(blocked, select(here, maxOf(before, delta[k]), before), get<W>(largest)));
        }
    }
    const auto take = [&](L3<V>& x, const L3<V>& y) {
        x = {select(blocked, y.x, x.x), select(blocked, y.y, x.y), select(blocked, y.z, x.z)};
    };
    take(a.v, ta.v);
    take(a.w, ta.w);
    take(b.v, tb.v);
    take(b.w, tb.w);
}

} // namespace

template <int W, bool kMaxImpulse, bool kKeptSeparation>
RL_LANES_INLINE void ContactSolver::solveBatches(BatchStore<W>& store, std::span<SolverBody> bodies, bool useBias,
                                                 size_t begin, size_t end) {
    using V = typename Vec<W>::V;
    const V inverseH = splat<W>(m_inverseH), zero = splat<W>(0.0);
    const V biasRate = splat<W>(m_soft.biasRate), maxPushout = splat<W>(-m_settings.maxPushoutSpeed);
    const V softMass = splat<W>(useBias ? m_soft.massScale : 1.0),
            softImpulse = splat<W>(useBias ? m_soft.impulseScale : 0.0);
    const V one = splat<W>(1.0);
    const bool friction = m_settings.friction;
    for (size_t n = begin; n < end; ++n) {
        Batch<W>& batch = store.batches[n];
        Side<V> a, b;
        gatherSides<W, !kKeptSeparation>(batch, store.scales[n], bodies, a, b);
        const L3<V> normal = load<W>(batch.normal);
        // A batch with struck manifolds (Batch::impacts) keeps the state before its sweep, and how far off its target
        // each lane's rows were, for solveStruck().
        const bool struck = batch.impacts != 0;
        StruckStart<W> start;
        V off = zero;
        if (struck)
            start.keep(store, batch, a, b);
        for (uint32_t k = 0; k < batch.pointCount; ++k) {
            BatchPoint<W>& p = store.points[batch.firstPoint + k];
            const L3<V> rA = load<W>(p.rA), rB = anchorB<W>(batch, p);
            // Current separation from the motion since the step began (anchors follow each body's rotation), or as
            // a sweep since the last motion took it (Motion::Unchanged).
            Lanes<W>& kept = store.separation[batch.firstPoint + k];
            V s;
            if constexpr (kKeptSeparation) {
                s = get<W>(kept);
            } else {
                const L3<V> d = (b.dp - a.dp) + (b.dR * rB - a.dR * rA);
                s = dot(normal, d) + get<W>(p.baseSeparation);
                put<W>(kept, s);
            }
            // Speculative points (s > 0) may close the gap within this substep; touching ones are soft while the
            // bias pushes them apart, and rigid in the relax pass.
            const auto speculative = s > zero;
            const V pushout = useBias ? maxOf(biasRate * s, maxPushout) : zero;
            const V velocityBias = select(speculative, s * inverseH, pushout);
            const V massScale = select(speculative, one, softMass);
            const V impulseScale = select(speculative, zero, softImpulse);
            const Row<V> row = makeRow(a, b, normal, rA, rB);
            const V vn = rowVelocity(a, b, row);
            const V accumulated = get<W>(p.impulse);
            if (struck) { // the most a row (with a mass: not an empty slot) was off its target when its turn came
                const V short_ = zero - (vn + velocityBias);
                const V away = select(accumulated > zero, maxOf(short_, zero - short_), short_);
                off = maxOf(off, select(widen<W>(p.mass) > zero, away, zero));
            }
            const V trial = (-get<W>(p.mass) * massScale) * (vn + velocityBias) - impulseScale * accumulated;
            const V total = maxOf(accumulated + trial, zero);
            const V impulse = total - accumulated;
            put<W>(p.impulse, total);
            if constexpr (kMaxImpulse) {
                Lanes<W>& largest = store.maxImpulse[batch.firstPoint + k];
                put<W>(largest, maxOf(get<W>(largest), impulse));
            }
            applyRow(a, b, row, impulse);
        }
        if (struck) {
            uint32_t blow = 0;
            for (int l = 0; l < W; ++l)
                if (((batch.impacts >> l) & 1u) && off[l] > m_settings.impactShortfall)
                    blow |= 1u << l;
            if (blow != 0)
                solveStruck<W, kMaxImpulse>(store, batch, a, b, normal, useBias, m_inverseH, m_soft, m_settings, start,
                                            blow);
        }
        if (friction) {
            // The manifolds' friction (solveConstraint() in ContactSolver.cpp): the twist, then the tangent block at
            // the friction centre, clamped to the disc.
            V total = zero, twistLimit = zero;
            for (uint32_t k = 0; k < batch.pointCount; ++k) {
                const BatchPoint<W>& p = store.points[batch.firstPoint + k];
                const V impulse = get<W>(p.impulse);
                total = total + impulse;
                twistLimit = twistLimit + get<W>(p.leverArm) * impulse;
            }
            const V twist = get<W>(batch.twistImpulse);
            const V f0 = get<W>(batch.frictionImpulse[0]), f1 = get<W>(batch.frictionImpulse[1]);
            // In no lane does anything push or hold: every clamp would give zero.
            if (anyNonZero<W>(total) || anyNonZero<W>(twist) || anyNonZero<W>(f0) || anyNonZero<W>(f1)) {
                const V coefficient = get<W>(batch.friction);
                const L3<V> tangent[2] = {load<W>(batch.tangent[0]), load<W>(batch.tangent[1])};
                const L3<V> centerA = load<W>(batch.centerA), centerB = load<W>(batch.centerB);
                {
                    const V spin = dot(normal, b.w - a.w);
                    const V limit = coefficient * twistLimit;
                    const V newImpulse = clampTo(twist - get<W>(batch.twistMass) * spin, -limit, limit);
                    put<W>(batch.twistImpulse, newImpulse);
                    applyTwist(a, b, normal, newImpulse - twist);
                }
                const L3<V> vr = (b.v + cross(b.w, centerB)) - (a.v + cross(a.w, centerA));
                const V v0 = dot(vr, tangent[0]), v1 = dot(vr, tangent[1]);
                const V m00 = get<W>(batch.frictionMass[0]), m01 = get<W>(batch.frictionMass[1]),
                        m11 = get<W>(batch.frictionMass[2]);
                V n0 = f0 - (m00 * v0 + m01 * v1);
                V n1 = f1 - (m01 * v0 + m11 * v1);
                const V limit = coefficient * total;
                const V length2 = n0 * n0 + n1 * n1;
                const auto outside = length2 > limit * limit;
                const V scale = limit / sqrtOf<W>(length2); // used only where outside: length2 > 0 there
                n0 = select(outside, n0 * scale, n0);
                n1 = select(outside, n1 * scale, n1);
                put<W>(batch.frictionImpulse[0], n0);
                put<W>(batch.frictionImpulse[1], n1);
                applyFriction(a, b, tangent, centerA, centerB, n0 - f0, n1 - f1);
            }
        }
        scatter<W>(a, bodies, batch.bodyA);
        scatter<W>(b, bodies, batch.bodyB);
    }
}

RL_WIDE4 void ContactSolver::warmStartBatches4(std::span<SolverBody> bodies, size_t begin, size_t end) {
    warmStartBatches(m_store4, bodies, begin, end);
}
RL_WIDE8 void ContactSolver::warmStartBatches8(std::span<SolverBody> bodies, size_t begin, size_t end) {
#if RL_EIGHT_LANES
    warmStartBatches(m_store8, bodies, begin, end);
#else
    (void)bodies, (void)begin, (void)end;
    std::abort(); // never chosen in this build
#endif
}
RL_WIDE4 void ContactSolver::solveBatches4(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end,
                                           Motion motion) {
    const bool kept = motion == Motion::Unchanged;
    if (m_settings.restitution)
        kept ? solveBatches<4, true, true>(m_store4, bodies, useBias, begin, end)
             : solveBatches<4, true, false>(m_store4, bodies, useBias, begin, end);
    else
        kept ? solveBatches<4, false, true>(m_store4, bodies, useBias, begin, end)
             : solveBatches<4, false, false>(m_store4, bodies, useBias, begin, end);
}
RL_WIDE8 void ContactSolver::solveBatches8(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end,
                                           Motion motion) {
#if RL_EIGHT_LANES
    const bool kept = motion == Motion::Unchanged;
    if (m_settings.restitution)
        kept ? solveBatches<8, true, true>(m_store8, bodies, useBias, begin, end)
             : solveBatches<8, true, false>(m_store8, bodies, useBias, begin, end);
    else
        kept ? solveBatches<8, false, true>(m_store8, bodies, useBias, begin, end)
             : solveBatches<8, false, false>(m_store8, bodies, useBias, begin, end);
#else
    (void)bodies, (void)useBias, (void)begin, (void)end, (void)motion;
    std::abort(); // never chosen in this build
#endif
}

#if defined(__GNUC__) && !defined(__clang__)
namespace {

// x rounded to the nearest float, per lane: what prepare()'s roundedToFloat() gives each lane.
template <int W>
RL_LANES_INLINE typename Vec<W>::V rounded(const typename Vec<W>::V& x) {
    return widenFloats<W>(__builtin_convertvector(x, typename Vec<W>::F));
}
template <int W>
RL_LANES_INLINE L3<typename Vec<W>::V> rounded(const L3<typename Vec<W>::V>& v) {
    return {rounded<W>(v.x), rounded<W>(v.y), rounded<W>(v.z)};
}
template <class V, class Mask>
RL_LANES_INLINE L3<V> select(const Mask& m, const L3<V>& x, const L3<V>& y) {
    return {select(m, x.x, y.x), select(m, x.y, y.y), select(m, x.z, y.z)};
}
// Stores x, whose lanes hold floats already, in float lanes.
template <int W>
RL_LANES_INLINE void putFloat(ContactSolver::FloatLanes<W>& lanes, const typename Vec<W>::V& x) {
    const typename Vec<W>::F f = __builtin_convertvector(x, typename Vec<W>::F);
    std::memcpy(lanes.v, &f, sizeof f);
}
template <int W>
RL_LANES_INLINE void putFloat(ContactSolver::FloatLanes<W>* lanes, const L3<typename Vec<W>::V>& v) {
    putFloat<W>(lanes[0], v.x);
    putFloat<W>(lanes[1], v.y);
    putFloat<W>(lanes[2], v.z);
}
// glm's matrix times a scalar: each element times it.
template <class V>
RL_LANES_INLINE M3<V> scaled(const M3<V>& a, const V& s) {
    M3<V> r;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            r.m[c][k] = a.m[c][k] * s;
    return r;
}

} // namespace
#endif

// setUpConstraint() (ContactSolver.cpp) for the W constraints of batch b at once: the same operations in the same
// order in every lane, so the same numbers; the whole records are written too where they are kept (m_kept). The
// lanes are read from the manifolds and bodies one by one; empty lanes and point slots beyond a lane's points compute
// on zeros and are stored as zeros, as the scalar fill leaves them.
template <int W>
RL_LANES_INLINE bool ContactSolver::setUpBatch(BatchStore<W>& store, const SetUpInputs& in, size_t b) {
#if defined(__GNUC__) && !defined(__clang__)
    using V = typename Vec<W>::V;
    using Mask = typename Vec<W>::Mask;
    const BatchLayout& at = m_batchLayout[b];
    Batch<W>& batch = store.batches[b];
    BatchScales<W>& scales = store.scales[b];
    std::memset(static_cast<void*>(&batch), 0, sizeof(Batch<W>));
    std::memset(static_cast<void*>(&scales), 0, sizeof(BatchScales<W>));
    batch.firstPoint = at.firstPoint;
    batch.pointCount = at.pointCount;

    static const Manifold kNone{};
    const Manifold* manifold[W];
    uint32_t index[W];
    V used, pointCount, stillA, stillB; // 1 or 0 per lane
    V scaleA, scaleB, frictionIn, restitution, invMassA, invMassB, twistImpulseIn;
    M3<V> inertiaA, inertiaB;
    L3<V> normalIn, centreA, centreB, vA, wA, vB, wB, frictionImpulseIn;
    L3<V> position[4];
    V separation[4], impulseIn[4];
    const auto setLane = [](L3<V>& lanes, int l, const Vec3& v) {
        lanes.x[l] = v.x;
        lanes.y[l] = v.y;
        lanes.z[l] = v.z;
    };
    // Where every body of the batch is isotropic, its inverse inertia is one number a lane, and the products below take
    // isotropicTimes(), which gives the full products' bits.
    const bool isotropic = batch.isotropic = isotropicBatch<W>(in, at);
    if (isotropic)
        inertiaA = inertiaB = M3<V>{};
    for (int l = 0; l < W; ++l) {
        const bool inUse = static_cast<uint32_t>(l) < at.lanes;
        const uint32_t i = inUse ? m_solveOrder[at.first + static_cast<uint32_t>(l)] : 0;
        const Manifold& m = inUse ? *in.manifolds[i] : kNone;
        const uint32_t a = inUse ? in.indexA[i] : 0, bb = inUse ? in.indexB[i] : 0;
        index[l] = i;
        manifold[l] = &m;
        batch.bodyA[l] = a;
        batch.bodyB[l] = bb;
        used[l] = inUse ? 1.0 : 0.0;
        pointCount[l] = inUse ? m.pointCount : 0;
        stillA[l] = a == 0 ? 1.0 : 0.0;
        stillB[l] = bb == 0 ? 1.0 : 0.0;
        const Hold held = inUse && !in.held.empty() ? in.held[i] : Hold{};
        scaleA[l] = held.side == kHoldA ? held.scale : 1.0;
        scaleB[l] = held.side == kHoldB ? held.scale : 1.0;
        // (A double past a float's range has no float to round to: see setUpConstraint().)
        frictionIn[l] = inUse ? std::min(in.friction[i], Real(1e30)) : 0.0;
        restitution[l] = inUse ? in.restitution[i] : 0.0;
        const SolverBody& bodyA = in.bodies[a];
        const SolverBody& bodyB = in.bodies[bb];
        invMassA[l] = bodyA.invMass;
        invMassB[l] = bodyB.invMass;
        if (isotropic) {
            inertiaA.m[0][0][l] = bodyA.invInertia[0][0];
            inertiaB.m[0][0][l] = bodyB.invInertia[0][0];
        } else {
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k) {
                    inertiaA.m[c][k][l] = bodyA.invInertia[c][k];
                    inertiaB.m[c][k][l] = bodyB.invInertia[c][k];
                }
        }
        setLane(vA, l, bodyA.v);
        setLane(wA, l, bodyA.w);
        setLane(vB, l, bodyB.v);
        setLane(wB, l, bodyB.w);
        setLane(centreA, l, in.centers[a]);
        setLane(centreB, l, in.centers[bb]);
        setLane(normalIn, l, m.normal);
        for (int k = 0; k < 4; ++k) {
            setLane(position[k], l, m.points[k].position);
            separation[k][l] = m.points[k].separation;
            impulseIn[k][l] = m.points[k].normalImpulse;
        }
        setLane(frictionImpulseIn, l, m.frictionImpulse);
        twistImpulseIn[l] = m.twistImpulse;
    }

    const V zero = splat<W>(0.0), one = splat<W>(1.0);
    const Mask inUse = used > zero;
    const L3<V> zero3{zero, zero, zero};
    const L3<V> normal = rounded<W>(normalIn);
    // tangentBasis(): the axis least aligned with the normal, normalised as glm does (times 1 / sqrt).
    const Mask alongX = select(normal.x < zero, -normal.x, normal.x) >= splat<W>(0.57735);
    const L3<V> u{select(alongX, normal.y, zero), select(alongX, -normal.x, normal.z), select(alongX, zero, -normal.y)};
    const L3<V> t0 = (one / sqrtOf<W>(dot(u, u))) * u;
    const L3<V> tangent[2] = {rounded<W>(t0), rounded<W>(cross(normal, t0))};
    const V friction = rounded<W>(frictionIn);
    const V massA = invMassA * scaleA, massB = invMassB * scaleB;
    const M3<V> inverseA = scaled(inertiaA, scaleA), inverseB = scaled(inertiaB, scaleB);
    const auto times = [isotropic](const M3<V>& m, const L3<V>& x) {
        return isotropic ? isotropicTimes(m.m[0][0], x) : m * x;
    };
    const Mask still = (stillA > zero) | (stillB > zero);
    const L3<V> anchorOffset = select(still, zero3, rounded<W>(centreA - centreB));
    const L3<V> anchorBase = select(stillA > zero, centreB, centreA);

    const bool warm = m_settings.warmStarting;
    const V approaching = splat<W>(-m_settings.restitutionThreshold);
    L3<V> rA[4], rB[4];
    V baseSeparation[4], mass[4], impulse[4], leverArm[4], relativeVelocity[4];
    Mask valid[4];
    Mask impact = zero < zero, blow = zero < zero;
    const bool blows = m_settings.blowPasses > 0 || m_settings.blowShockPasses > 0;
    const V blowSpeed = splat<W>(-m_settings.blowSpeed);
    const V reach = splat<W>(m_settings.step > 0.0 ? m_settings.step : m_h);
    for (uint32_t k = 0; k < at.pointCount; ++k) {
        valid[k] = splat<W>(static_cast<Real>(k)) < pointCount;
        rA[k] = rounded<W>(position[k] - anchorBase);
        rB[k] = rounded<W>(rA[k] + anchorOffset);
        baseSeparation[k] = rounded<W>(separation[k] - dot(rB[k] - rA[k], normal));
        const L3<V> angularA = cross(rA[k], normal), angularB = cross(rB[k], normal);
        const V normalK =
            ((massA + massB) + dot(angularA, times(inverseA, angularA))) + dot(angularB, times(inverseB, angularB));
        mass[k] = select(normalK > zero, rounded<W>(one / normalK), zero);
        impulse[k] = warm ? impulseIn[k] : zero;
        relativeVelocity[k] = dot(normal, (vB + cross(wB, rB[k])) - (vA + cross(wA, rA[k])));
        impact = impact | (valid[k] & (relativeVelocity[k] < approaching));
        if (blows) // as setUpConstraint()
            blow = blow | (valid[k] & (relativeVelocity[k] < blowSpeed) &
                           (separation[k] < (zero - relativeVelocity[k]) * reach));
    }

    // The friction centre, weighted as setUpConstraint() weighs it.
    L3<V> centerA = zero3, centerB = zero3;
    V weights = zero;
    const V falloff = splat<W>(kCenterFalloff);
    for (uint32_t k = 0; k < at.pointCount; ++k) {
        const V gap = one + maxOf(separation[k], zero) / falloff;
        const V w = one / (gap * gap);
        centerA = select(valid[k], centerA + w * rA[k], centerA);
        centerB = select(valid[k], centerB + w * rB[k], centerB);
        weights = select(valid[k], weights + w, weights);
    }
    const Mask weighed = weights > zero;
    centerA =
        rounded<W>(select(weighed, L3<V>{centerA.x / weights, centerA.y / weights, centerA.z / weights}, centerA));
    centerB =
        rounded<W>(select(weighed, L3<V>{centerB.x / weights, centerB.y / weights, centerB.z / weights}, centerB));
    const V patchRadius = splat<W>(ContactSolver::kPatchRadius);
    for (uint32_t k = 0; k < at.pointCount; ++k) {
        const L3<V> arm = rA[k] - centerA;
        leverArm[k] = maxOf(rounded<W>(sqrtOf<W>(dot(arm, arm))), patchRadius);
    }
    const L3<V> aA0 = cross(centerA, tangent[0]), aA1 = cross(centerA, tangent[1]);
    const L3<V> aB0 = cross(centerB, tangent[0]), aB1 = cross(centerB, tangent[1]);
    const L3<V> iA1 = times(inverseA, aA1), iB1 = times(inverseB, aB1);
    const V k00 = ((massA + massB) + dot(aA0, times(inverseA, aA0))) + dot(aB0, times(inverseB, aB0));
    const V k11 = ((massA + massB) + dot(aA1, iA1)) + dot(aB1, iB1);
    const V k01 = dot(aA0, iA1) + dot(aB0, iB1);
    const V det = k00 * k11 - k01 * k01;
    const V inverseDet = select(det > zero, one / det, zero);
    const V twist = dot(normal, times(inverseA, normal)) + dot(normal, times(inverseB, normal));
    const V twistMass = select(twist > zero, rounded<W>(one / twist), zero);
    const Mask warmFriction = warm && m_settings.friction ? friction > zero : zero < zero;

    // The normal speed at impact, for restitution only (setUpConstraint()): a point still apart meets at the speed
    // energy gives, one touching already at the speed it has.
    const L3<V> gravity{splat<W>(m_settings.gravity.x), splat<W>(m_settings.gravity.y), splat<W>(m_settings.gravity.z)};
    const V approachAcceleration =
        dot(normal, select(invMassB > zero, gravity, zero3) - select(invMassA > zero, gravity, zero3));
    if (m_settings.restitution) {
        const Mask bounces = restitution > zero;
        const V flight = splat<W>(m_settings.flightOffset), h = splat<W>(m_h), two = splat<W>(2.0);
        for (uint32_t k = 0; k < at.pointCount; ++k) {
            const V& s = separation[k];
            const V v = relativeVelocity[k] + (flight * approachAcceleration) * h;
            const Mask apart = s > zero;
            const Mask flying = (v >= zero) & (approachAcceleration >= zero);
            const V atImpact = -sqrtOf<W>(maxOf(v * v - (two * approachAcceleration) * s, zero));
            relativeVelocity[k] = select(bounces & valid[k], select(apart & ~flying, atImpact, v), relativeVelocity[k]);
        }
    }

    // The batch, with empty lanes zero.
    const auto keep = [&](const V& x) { return select(inUse, x, zero); };
    const auto keep3 = [&](const L3<V>& x) { return select(inUse, x, zero3); };
    putFloat<W>(batch.normal, keep3(normal));
    putFloat<W>(batch.tangent[0], keep3(tangent[0]));
    putFloat<W>(batch.tangent[1], keep3(tangent[1]));
    putFloat<W>(batch.friction, keep(friction));
    put<W>(scales.a, keep(scaleA));
    put<W>(scales.b, keep(scaleB));
    for (uint32_t l = 0; l < at.lanes; ++l) {
        batch.holds = batch.holds || scaleA[l] != 1.0 || scaleB[l] != 1.0;
        const bool against = stillA[l] > 0.0 || stillB[l] > 0.0 || scaleA[l] == 0.0 || scaleB[l] == 0.0;
        const bool struck = impact[l] != 0 && against && manifold[l]->pointCount > 2; // as setUpConstraint()
        batch.impacts = static_cast<uint8_t>(batch.impacts | (struck ? 1u << l : 0u));
    }
    putFloat<W>(batch.anchorOffset, keep3(anchorOffset));
    putFloat<W>(batch.centerA, keep3(centerA));
    putFloat<W>(batch.centerB, keep3(centerB));
    putFloat<W>(batch.frictionMass[0], keep(rounded<W>(k11 * inverseDet)));
    putFloat<W>(batch.frictionMass[1], keep(rounded<W>(-k01 * inverseDet)));
    putFloat<W>(batch.frictionMass[2], keep(rounded<W>(k00 * inverseDet)));
    putFloat<W>(batch.twistMass, keep(twistMass));
    put<W>(batch.frictionImpulse[0], select(warmFriction, dot(frictionImpulseIn, tangent[0]), zero));
    put<W>(batch.frictionImpulse[1], select(warmFriction, dot(frictionImpulseIn, tangent[1]), zero));
    put<W>(batch.twistImpulse, select(warmFriction, twistImpulseIn, zero));
    // The points in manifold order; an impact is solved deepest point first (setUpConstraint()), so its lane's
    // points are then put in that order.
    for (uint32_t k = 0; k < at.pointCount; ++k) {
        BatchPoint<W>& q = store.points[at.firstPoint + k];
        const Mask here = valid[k];
        putFloat<W>(q.rA, select(here, rA[k], zero3));
        putFloat<W>(q.baseSeparation, select(here, baseSeparation[k], zero));
        putFloat<W>(q.mass, select(here, mass[k], zero));
        putFloat<W>(q.leverArm, select(here, leverArm[k], zero));
        put<W>(q.impulse, select(here, impulse[k], zero));
    }
    // Lane l's whole record, for the sequential sweeps and the restitution pass (when kept).
    const auto laneOf = [](const L3<V>& v, uint32_t l) { return Vec3(v.x[l], v.y[l], v.z[l]); };
    const auto record = [&](uint32_t l) {
        const Manifold& m = *manifold[l];
        ContactConstraint c;
        c.bodyA = batch.bodyA[l];
        c.bodyB = batch.bodyB[l];
        c.scaleA = scaleA[l];
        c.scaleB = scaleB[l];
        c.normal = laneOf(normal, l);
        c.tangent[0] = laneOf(tangent[0], l);
        c.tangent[1] = laneOf(tangent[1], l);
        c.friction = friction[l];
        c.restitution = restitution[l];
        c.pointCount = m.pointCount;
        c.approachAcceleration = approachAcceleration[l];
        c.impact = (batch.impacts >> l) & 1u;
        c.blow = blow[l] != 0;
        c.anchorOffset = laneOf(anchorOffset, l);
        for (int k = 0; k < m.pointCount; ++k) {
            ContactConstraint::Point& p = c.points[k];
            p.rA = laneOf(rA[k], l);
            p.rB = laneOf(rB[k], l);
            p.baseSeparation = baseSeparation[k][l];
            p.normalMass = mass[k][l];
            p.normalImpulse = impulse[k][l];
            p.maxNormalImpulse = 0.0;
            p.relativeVelocity = relativeVelocity[k][l];
            p.leverArm = leverArm[k][l];
        }
        std::copy(m_order[index[l]].begin(), m_order[index[l]].end(), c.order);
        c.centerA = laneOf(centerA, l);
        c.centerB = laneOf(centerB, l);
        c.frictionMass[0] = batch.frictionMass[0].v[l];
        c.frictionMass[1] = batch.frictionMass[1].v[l];
        c.frictionMass[2] = batch.frictionMass[2].v[l];
        c.frictionImpulse[0] = batch.frictionImpulse[0].v[l];
        c.frictionImpulse[1] = batch.frictionImpulse[1].v[l];
        c.twistMass = twistMass[l];
        c.twistImpulse = batch.twistImpulse.v[l];
        return c;
    };
    if (!store.maxImpulse.empty() && at.pointCount > 0)
        std::memset(static_cast<void*>(&store.maxImpulse[at.firstPoint]), 0, at.pointCount * sizeof(Lanes<W>));
    for (uint32_t l = 0; l < at.lanes; ++l) {
        const uint32_t i = index[l];
        const Manifold& m = *manifold[l];
        std::array<uint8_t, 4>& order = m_order[i];
        for (int k = 0; k < 4; ++k)
            order[static_cast<size_t>(k)] = static_cast<uint8_t>(k);
        m_laneOf[i] = static_cast<uint32_t>(b * W + l);
        if (blows)
            m_struck[i] = blow[l] != 0 ? 1 : 0;
        if (impact[l] != 0)
            stableSortSmall(order.data(), order.data() + m.pointCount,
                            [&](uint8_t x, uint8_t y) { return m.points[x].separation < m.points[y].separation; });
        if (m_kept) {
            m_constraints[i] = record(l);
        } else if (m_bounceOnly && restitution[l] != 0.0) {
            // mayBounce(), on the lane's values: most constraints against still bodies have no point approaching
            // fast enough.
            bool keep = batch.bodyA[l] != 0 && batch.bodyB[l] != 0;
            for (int k = 0; k < m.pointCount; ++k)
                keep = keep || !(relativeVelocity[k][l] > -m_settings.restitutionThreshold);
            if (keep) {
                m_constraints[i] = record(l);
                m_bouncing[i] = 1;
            }
        }
        if (impact[l] == 0)
            continue;
        for (int k = 0; k < m.pointCount; ++k) {
            const uint8_t from = order[static_cast<size_t>(k)];
            BatchPoint<W>& q = store.points[at.firstPoint + static_cast<uint32_t>(k)];
            q.rA[0].v[l] = static_cast<float>(rA[from].x[l]);
            q.rA[1].v[l] = static_cast<float>(rA[from].y[l]);
            q.rA[2].v[l] = static_cast<float>(rA[from].z[l]);
            q.baseSeparation.v[l] = static_cast<float>(baseSeparation[from][l]);
            q.mass.v[l] = static_cast<float>(mass[from][l]);
            q.leverArm.v[l] = static_cast<float>(leverArm[from][l]);
            q.impulse.v[l] = impulse[from][l];
        }
    }
    return true;
#else
    (void)store;
    (void)in;
    (void)b;
    return false;
#endif
}

RL_WIDE4 bool ContactSolver::setUpBatch4(const SetUpInputs& inputs, size_t b) {
    return setUpBatch(m_store4, inputs, b);
}
RL_WIDE8 bool ContactSolver::setUpBatch8(const SetUpInputs& inputs, size_t b) {
#if RL_EIGHT_LANES
    return setUpBatch(m_store8, inputs, b);
#else
    (void)inputs, (void)b;
    std::abort(); // never chosen in this build
#endif
}

void ContactSolver::warmStartBatchRange(std::span<SolverBody> bodies, size_t begin, size_t end) {
    if (!m_settings.warmStarting)
        return;
    if (m_width == 8)
        warmStartBatches8(bodies, begin, end);
    else
        warmStartBatches4(bodies, begin, end);
}

void ContactSolver::solveBatchRange(std::span<SolverBody> bodies, bool useBias, size_t begin, size_t end,
                                    Motion motion) {
    if (!s_keepSeparations)
        motion = Motion::Moved;
    if (m_width == 8)
        solveBatches8(bodies, useBias, begin, end, motion);
    else
        solveBatches4(bodies, useBias, begin, end, motion);
}

} // namespace rl
