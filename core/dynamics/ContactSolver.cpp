#include "dynamics/ContactSolver.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace rl {

void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
    // Pick the axis least aligned with n so the cross product is well conditioned.
    if (std::abs(n.x) >= 0.57735)
        t1 = glm::normalize(Vec3(n.y, -n.x, 0.0));
    else
        t1 = glm::normalize(Vec3(0.0, n.z, -n.y));
    t2 = glm::cross(n, t1);
}

namespace {

// Sorts the constraints stably by their batch key: the order std::stable_sort gives with key[l] < key[r], without
// the heap buffer it takes on every call (once per level: some 210 calls a step of boxes1000, 2026-12-04). Short
// runs by insertion, longer ones by counting into a buffer of the thread's.
void sortByKey(std::span<uint32_t> order, const std::vector<uint8_t>& key) {
    constexpr size_t kInsertionBelow = 24;
    if (order.size() < kInsertionBelow) {
        stableSortSmall(order.data(), order.data() + order.size(),
                        [&](uint32_t l, uint32_t r) { return key[l] < key[r]; });
        return;
    }
    std::array<uint32_t, 257> start{};
    for (const uint32_t i : order)
        ++start[static_cast<size_t>(key[i]) + 1];
    for (size_t k = 1; k < start.size(); ++k)
        start[k] += start[k - 1];
    thread_local std::vector<uint32_t> sorted;
    sorted.resize(order.size());
    for (const uint32_t i : order)
        sorted[start[key[i]]++] = i;
    std::copy(sorted.begin(), sorted.end(), order.begin());
}

// Restitution sweeps over one manifold's bouncing points: at most this many, fewer once the largest impulse change
// of a sweep is below the tolerance times the manifold's total impulse.
constexpr int kRestitutionPasses = 32;
constexpr Real kRestitutionTolerance = 1e-4;
constexpr Real kCenterFalloff = ContactSolver::kCenterFalloff;
constexpr Real kPatchRadius = ContactSolver::kPatchRadius;

Vec3 relativeVelocity(const SolverBody& a, const SolverBody& b, const Vec3& rA, const Vec3& rB) {
    return (b.v + glm::cross(b.w, rB)) - (a.v + glm::cross(a.w, rA));
}

// x rounded to the nearest float: what the batches store (BatchPoint). The empty asm keeps the float in a register:
// GCC 12 at -O3 vectorised two neighbouring static_cast<float> of doubles into one pair of multiplies and dropped
// the rounding of both (the tangent block's masses came out unrounded while the batches held them rounded).
inline Real roundedToFloat(Real x) {
    float f = static_cast<float>(x);
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    asm("" : "+x"(f));
#else
    volatile float kept = f;
    f = kept;
#endif
    return f;
}

inline Vec3 roundedToFloat(const Vec3& v) {
    return Vec3(roundedToFloat(v.x), roundedToFloat(v.y), roundedToFloat(v.z));
}

// r x d and I^-1 (r x d) of one side of a row, computed as ContactSolverWide.cpp's batches compute them.
inline Vec3 angularOf(const Vec3& r, const Vec3& d) {
    return glm::cross(r, d);
}

// A side's inverse mass and inertia as one constraint sees them: times its scale (see ContactConstraint), in the
// order the batches use, so a scale of 1 gives the body's own numbers.
struct Inverse {
    Real mass;
    Mat3 inertia;
};
inline Inverse inverseOf(const SolverBody& body, Real scale) {
    return {body.invMass * scale, body.invInertia * scale};
}
inline Vec3 inertiaOf(const Inverse& inverse, const Vec3& r, const Vec3& d) {
    return inverse.inertia * glm::cross(r, d);
}
// A normal row's velocity change per unit impulse at anchors rA and rB (the inverse of its effective mass).
inline Real normalK(const Inverse& ia, const Inverse& ib, const Vec3& rA, const Vec3& rB, const Vec3& n) {
    const Vec3 angularA = angularOf(rA, n), angularB = angularOf(rB, n);
    return ia.mass + ib.mass + glm::dot(angularA, ia.inertia * angularA) + glm::dot(angularB, ib.inertia * angularB);
}

// Relative velocity of the anchors along row d of point p: dot(d, vB - vA) + wB . (rB x d) - wA . (rA x d).
inline Real rowVelocity(const SolverBody& a, const SolverBody& b, const ContactConstraint::Point& p, const Vec3& d) {
    return glm::dot(d, b.v - a.v) + glm::dot(b.w, angularOf(p.rB, d)) - glm::dot(a.w, angularOf(p.rA, d));
}

// Applies the impulse j along row d of point p (to B, and its opposite to A).
inline void applyRow(SolverBody& a, SolverBody& b, const Inverse& ia, const Inverse& ib,
                     const ContactConstraint::Point& p, const Vec3& d, Real j) {
    a.v -= (ia.mass * j) * d;
    a.w -= j * inertiaOf(ia, p.rA, d);
    b.v += (ib.mass * j) * d;
    b.w += j * inertiaOf(ib, p.rB, d);
}

// rowVelocity() and applyRow() without the side that is the static entry 0 (see solveConstraint()).
template <bool kStaticA, bool kStaticB>
inline Real rowVelocityT(const SolverBody& a, const SolverBody& b, const ContactConstraint::Point& p, const Vec3& d) {
    if constexpr (kStaticA)
        return glm::dot(d, b.v) + glm::dot(b.w, angularOf(p.rB, d));
    else if constexpr (kStaticB)
        return glm::dot(d, -a.v) - glm::dot(a.w, angularOf(p.rA, d));
    else
        return rowVelocity(a, b, p, d);
}

template <bool kStaticA, bool kStaticB>
inline void applyRowT(SolverBody& a, SolverBody& b, const Inverse& ia, const Inverse& ib,
                      const ContactConstraint::Point& p, const Vec3& d, Real j) {
    if constexpr (!kStaticA) {
        a.v -= (ia.mass * j) * d;
        a.w -= j * inertiaOf(ia, p.rA, d);
    }
    if constexpr (!kStaticB) {
        b.v += (ib.mass * j) * d;
        b.w += j * inertiaOf(ib, p.rB, d);
    }
}

// One manifold's constraint, for one step (see prepare()). ContactSolver::setUpBatch() (ContactSolverWide.cpp) does
// the same for a batch's W constraints at once: a change here goes there too
// (tst_contactsolver's vectorSetUpGivesTheScalarNumbers compares the two).
void setUpConstraint(ContactConstraint& c, const Manifold& m, uint32_t indexA, uint32_t indexB, Real friction,
                     Real restitution, ContactSolver::Hold held, std::span<const SolverBody> bodies,
                     std::span<const Vec3> centers, Real h, const ContactSolverSettings& settings) {
    c.bodyA = indexA;
    c.bodyB = indexB;
    c.scaleA = held.side == ContactSolver::kHoldA ? held.scale : 1.0;
    c.scaleB = held.side == ContactSolver::kHoldB ? held.scale : 1.0;
    // The directions, anchors, friction centres and friction coefficient are rounded to float, as the batches store
    // them (see BatchPoint), so that both kinds of sweep compute with the same numbers.
    c.normal = roundedToFloat(m.normal);
    tangentBasis(c.normal, c.tangent[0], c.tangent[1]);
    c.tangent[0] = roundedToFloat(c.tangent[0]);
    c.tangent[1] = roundedToFloat(c.tangent[1]);
    // (A double past a float's range has no float to round to: C++ leaves that conversion undefined, x86 gives
    // infinity. 1e30 holds any contact as firmly as a larger coefficient would.)
    c.friction = roundedToFloat(std::min(friction, Real(1e30)));
    c.restitution = restitution;
    c.pointCount = m.pointCount;
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    // Gravity acts on the bodies that can move (not on anchors and sleepers, entries with no inverse mass).
    const Vec3 gA = a.invMass > 0.0 ? settings.gravity : Vec3(0.0);
    const Vec3 gB = b.invMass > 0.0 ? settings.gravity : Vec3(0.0);
    c.approachAcceleration = glm::dot(c.normal, gB - gA);
    // Both anchors sit at the world midpoint of the witness points, in world axes at the step start. Every point's
    // rB is its rA plus one offset, the vector between the centres, so the batches store one anchor a point and the
    // offset once (BatchPoint). A side that does not move (entry 0: zero velocities, no motion) takes the other
    // side's anchor, as good as any point there (the separation's anchor term, n . (rB - rA), then vanishes), and
    // better conditioned than a world position far from the origin. (A float sum of floats is the double sum rounded
    // once to float, so the batched sweeps get the same rB by adding in floats.)
    const bool stillA = c.bodyA == 0, stillB = c.bodyB == 0;
    c.anchorOffset = stillA || stillB ? Vec3(0.0) : roundedToFloat(centers[c.bodyA] - centers[c.bodyB]);
    const Vec3& anchorBase = stillA ? centers[c.bodyB] : centers[c.bodyA];
    bool impact = false;
    // A blow (ContactSolverSettings::blowPasses): a point closing faster than blowSpeed from near enough to meet
    // within the step.
    const bool blows = settings.blowPasses > 0 || settings.blowShockPasses > 0;
    const Real reach = settings.step > 0.0 ? settings.step : h;
    c.blow = false;
    for (int k = 0; k < m.pointCount; ++k) {
        const ContactPoint& mp = m.points[k];
        ContactConstraint::Point& p = c.points[k];
        p.rA = roundedToFloat(mp.position - anchorBase);
        p.rB = roundedToFloat(p.rA + c.anchorOffset);
        // The separation and the masses are rounded to float, as the batches store them (see BatchPoint).
        p.baseSeparation = roundedToFloat(mp.separation - glm::dot(p.rB - p.rA, c.normal));
        const Real perImpulse = normalK(ia, ib, p.rA, p.rB, c.normal);
        p.normalMass = perImpulse > 0.0 ? roundedToFloat(1.0 / perImpulse) : 0.0;
        p.normalImpulse = settings.warmStarting ? mp.normalImpulse : 0.0;
        p.maxNormalImpulse = 0.0;
        p.relativeVelocity = glm::dot(c.normal, relativeVelocity(a, b, p.rA, p.rB));
        impact = impact || p.relativeVelocity < -settings.restitutionThreshold;
        c.blow = c.blow ||
                 (blows && p.relativeVelocity < -settings.blowSpeed && mp.separation < -p.relativeVelocity * reach);
    }

    // The friction centre: the anchors' mean, with speculative points (still apart) weighted down the farther apart
    // they are, so that the centre moves smoothly as points come and go.
    Vec3 centerA(0.0), centerB(0.0);
    Real weights = 0.0;
    for (int k = 0; k < m.pointCount; ++k) {
        const Real gap = 1.0 + std::max(m.points[k].separation, 0.0) / kCenterFalloff;
        const Real w = 1.0 / (gap * gap);
        centerA += w * c.points[k].rA;
        centerB += w * c.points[k].rB;
        weights += w;
    }
    if (weights > 0.0) {
        centerA /= weights;
        centerB /= weights;
    }
    centerA = roundedToFloat(centerA);
    centerB = roundedToFloat(centerB);
    c.centerA = centerA;
    c.centerB = centerB;
    for (int k = 0; k < m.pointCount; ++k)
        c.points[k].leverArm = std::max(roundedToFloat(glm::length(c.points[k].rA - centerA)), kPatchRadius);
    // The tangent block K (2x2, symmetric) at the centre, inverted; the masses are rounded to float as the batches
    // store them.
    const Vec3 aA0 = angularOf(centerA, c.tangent[0]), aA1 = angularOf(centerA, c.tangent[1]);
    const Vec3 aB0 = angularOf(centerB, c.tangent[0]), aB1 = angularOf(centerB, c.tangent[1]);
    const Vec3 iA1 = ia.inertia * aA1, iB1 = ib.inertia * aB1;
    const Real k00 = ia.mass + ib.mass + glm::dot(aA0, ia.inertia * aA0) + glm::dot(aB0, ib.inertia * aB0);
    const Real k11 = ia.mass + ib.mass + glm::dot(aA1, iA1) + glm::dot(aB1, iB1);
    const Real k01 = glm::dot(aA0, iA1) + glm::dot(aB0, iB1);
    const Real det = k00 * k11 - k01 * k01;
    const Real inverseDet = det > 0.0 ? 1.0 / det : 0.0;
    c.frictionMass[0] = roundedToFloat(k11 * inverseDet);
    c.frictionMass[1] = roundedToFloat(-k01 * inverseDet);
    c.frictionMass[2] = roundedToFloat(k00 * inverseDet);
    const Real twist = glm::dot(c.normal, ia.inertia * c.normal) + glm::dot(c.normal, ib.inertia * c.normal);
    c.twistMass = twist > 0.0 ? roundedToFloat(1.0 / twist) : 0.0;
    // The manifold keeps its friction impulse in world axes: the tangents follow the normal, which may have turned.
    // Without friction nothing is carried, so that the sweeps, which then skip the friction rows, hold none.
    const bool warmFriction = settings.warmStarting && settings.friction && c.friction > 0.0;
    c.frictionImpulse[0] = warmFriction ? glm::dot(m.frictionImpulse, c.tangent[0]) : 0.0;
    c.frictionImpulse[1] = warmFriction ? glm::dot(m.frictionImpulse, c.tangent[1]) : 0.0;
    c.twistImpulse = warmFriction ? m.twistImpulse : 0.0;

    // An impact is solved deepest point first: a speculative point that is still apart must not push before the
    // point that touches first has taken the blow. A UV sphere landing on its pole, solved in manifold order,
    // let a ring vertex 1.9 mm up push first and bounced off spinning at 5.8 rad/s. Resting contacts keep the
    // manifold's order: reordering them by sub-millimetre differences from step to step kept a pile of 1,000
    // boxes creeping.
    for (int k = 0; k < 4; ++k)
        c.order[k] = static_cast<uint8_t>(k);
    // A face (three or four points) struck against something that does not move (an anchor, a sleeper, or a side
    // held still) may be solved as a block (solveConstraint()). Between two free bodies the blow stays with the
    // sweeps, which share it out over the other contacts of both: solved whole in one sweep, the cubes of ramps.obj
    // that landed on one another drove the lower one up to 13.6 mm into the floor in its first 10 s (its lowest
    // corner over 48 starts with every cube moved by up to 0.1 mm: 4.1-9.3 mm before, 4.4-8.7 mm over the first 12
    // now). Edges and corners keep the sweeps: only faces landing flat were seen to spin.
    const bool against = stillA || stillB || c.scaleA == 0.0 || c.scaleB == 0.0;
    c.impact = impact && against && m.pointCount > 2;
    if (impact)
        stableSortSmall(c.order, c.order + m.pointCount,
                        [&](uint8_t l, uint8_t r) { return m.points[l].separation < m.points[r].separation; });

    // Restitution bounces off the normal speed at the instant of impact. A point still apart at the step start
    // (separation s > 0, normal speed v on the flight the integrator follows, relative acceleration a along the
    // normal from gravity) meets at the speed energy gives, v_c^2 = v^2 - 2 a s, whichever substep it lands in; a
    // point already touching struck at or before the step start, at v. (Until 2026-11-26 the speed was taken at
    // the end of the substep where the point first pushed, up to a substep's a h too fast, so the third apex of an
    // e = 0.5 drop depended on where in the step the ball landed: -2.1 % at 8 substeps, +3.3 % at 6.)
    // (Only the restitution pass reads these speeds: a pair that cannot bounce skips the square roots.)
    for (int k = 0; k < (restitution > 0.0 && settings.restitution ? m.pointCount : 0); ++k) {
        ContactConstraint::Point& p = c.points[k];
        const Real accel = c.approachAcceleration, s = m.points[k].separation;
        const Real v = p.relativeVelocity + settings.flightOffset * accel * h;
        if (!(s > 0.0) || (v >= 0.0 && accel >= 0.0)) {
            p.relativeVelocity = v; // touching already, or never approaching in free flight
            continue;
        }
        p.relativeVelocity = -std::sqrt(std::max(v * v - 2.0 * accel * s, 0.0));
    }
}

// The kinetic energy of a body of inverse mass invMass and inverse inertia invInertia (world axes) moving at v and
// turning at w.
Real kineticEnergy(Real invMass, const Mat3& invInertia, const Vec3& v, const Vec3& w) {
    if (!(invMass > 0.0))
        return 0.0;
    Real e = 0.5 * glm::dot(v, v) / invMass;
    if (w != Vec3(0.0) && glm::determinant(invInertia) > 0.0)
        e += 0.5 * glm::dot(w, glm::inverse(invInertia) * w);
    return e;
}

// The root of x in a union-find forest of parents, halving the path on the way.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

// Each moving body's constraints, for constraints constraintAt(0) .. constraintAt(count - 1) between bodies
// bodiesOf(i) (entry 0, the still side, lists none): body x's are list[first[x]] .. list[first[x + 1] - 1], in the
// order given. fill is scratch.
template <class ConstraintAt, class BodiesOf>
void listByBody(size_t bodyCount, size_t count, ConstraintAt&& constraintAt, BodiesOf&& bodiesOf,
                std::vector<uint32_t>& first, std::vector<uint32_t>& list, std::vector<uint32_t>& fill) {
    first.assign(bodyCount + 1, 0);
    for (size_t k = 0; k < count; ++k)
        for (const uint32_t body : bodiesOf(constraintAt(k)))
            if (body != 0)
                ++first[body + 1];
    for (size_t x = 1; x <= bodyCount; ++x)
        first[x] += first[x - 1];
    list.resize(first[bodyCount]);
    fill.assign(first.begin(), first.end() - 1);
    for (size_t k = 0; k < count; ++k) {
        const uint32_t i = constraintAt(k);
        for (const uint32_t body : bodiesOf(i))
            if (body != 0)
                list[fill[body]++] = i;
    }
}

} // namespace

void shareOut(const ContactSolver::ParallelFor& parallelFor, size_t count,
              const std::function<void(size_t, size_t)>& body) {
    if (parallelFor)
        parallelFor(count, body);
    else
        body(0, count);
}

namespace {

// Solves A x = b for the m x m system in A (row r: A[r][0..m-1], b in A[r][m]) by elimination with the largest pivot
// first; false where a pivot is below `tiny` (the system is singular).
bool eliminate(Real (&A)[4][5], int m, Real tiny, Real (&x)[4]) {
    for (int c = 0; c < m; ++c) {
        int best = c;
        for (int r = c + 1; r < m; ++r)
            if (std::abs(A[r][c]) > std::abs(A[best][c]))
                best = r;
        if (!(std::abs(A[best][c]) > tiny))
            return false;
        if (best != c)
            for (int k = 0; k <= m; ++k)
                std::swap(A[c][k], A[best][k]);
        for (int r = c + 1; r < m; ++r) {
            const Real f = A[r][c] / A[c][c];
            for (int k = c; k <= m; ++k)
                A[r][k] -= f * A[c][k];
        }
    }
    for (int r = m - 1; r >= 0; --r) {
        Real sum = A[r][m];
        for (int k = r + 1; k < m; ++k)
            sum -= A[r][k] * x[k];
        x[r] = sum / A[r][r];
    }
    return true;
}

} // namespace

bool solveImpactRows(ImpactRows& rows) {
    // A linear complementarity problem of at most four rows, solved exactly by trying its active sets, the largest
    // first (Box2D v2's block solver does this for two rows): the rows in the set reach their targets, the others
    // take no impulse and end no slower than theirs.
    const int n = rows.count;
    if (n < 1 || n > 4)
        return false;
    Real K[4][4];
    Real largest = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            K[i][j] = (rows.massA + rows.massB) + glm::dot(rows.angularA[i], rows.inertiaA[j]) +
                      glm::dot(rows.angularB[i], rows.inertiaB[j]);
            largest = std::max(largest, std::abs(K[i][j]));
        }
    if (!(largest > 0.0) || !std::isfinite(largest))
        return false;
    const Real tiny = 1e-9 * largest;
    // w = K (lambda - accumulated) + velocity - target + softness lambda: each row's velocity above where it stops.
    Real w0[4], scale = 0.0, pushed = 0.0;
    for (int i = 0; i < n; ++i) {
        Real sum = 0.0;
        for (int j = 0; j < n; ++j)
            sum += K[i][j] * rows.impulse[j];
        w0[i] = rows.velocity[i] - rows.target[i] - sum;
        scale = std::max(scale, std::abs(rows.velocity[i] - rows.target[i]));
        pushed += rows.impulse[i];
    }
    for (int i = 0; i < n; ++i)
        K[i][i] += rows.softness[i];         // a soft row gives: (K + softness) lambda, after w0 took the rigid K
    const Real slack = 1e-9 * scale + 1e-12; // m/s: a row this much below its target counts as on it
    // The sets to try: the guess first (the rows the sweep left pushing), then the largest sets first.
    unsigned order[16];
    int sets = 0;
    const unsigned all = (1u << n) - 1u, guess = rows.guess & all;
    order[sets++] = guess;
    for (int size = n; size >= 0; --size)
        for (unsigned set = 0; set <= all; ++set)
            if (std::popcount(set) == size && set != guess)
                order[sets++] = set;
    for (int attempt = 0; attempt < sets; ++attempt) {
        const unsigned set = order[attempt];
        const int size = std::popcount(set);
        int index[4], m = 0;
        for (int i = 0; i < n; ++i)
            if (set & (1u << i))
                index[m++] = i;
        // K_SS lambda_S = -w0_S.
        Real A[4][5], x[4];
        for (int r = 0; r < m; ++r) {
            for (int c = 0; c < m; ++c)
                A[r][c] = K[index[r]][index[c]];
            A[r][m] = -w0[index[r]];
        }
        if (!eliminate(A, m, tiny, x))
            continue;
        Real lambda[4] = {0.0, 0.0, 0.0, 0.0};
        for (int r = 0; r < m; ++r)
            lambda[index[r]] = x[r];
        Real total = 0.0;
        for (int i = 0; i < n; ++i)
            total += std::abs(lambda[i]);
        bool fits = std::isfinite(total);
        for (int i = 0; i < n && fits; ++i) {
            if (set & (1u << i)) {
                fits = lambda[i] >= -1e-9 * (total + pushed);
            } else {
                Real w = w0[i];
                for (int j = 0; j < n; ++j)
                    w += K[i][j] * lambda[j];
                fits = w >= -slack;
            }
        }
        if (!fits)
            continue;
        for (int i = 0; i < n; ++i)
            lambda[i] = std::max(lambda[i], 0.0);
        // A flat face's four points (or three in a line) make a singular block: a body has three ways to move
        // along a plane's normal, not four. A set one row smaller answers it, e.g. two opposite corners of a
        // square, and any impulses z with K z = 0 can be added without changing a velocity. Where the row
        // left out is on its target too (within nearTarget of the speed to take off), the answer keeps the one
        // nearest to sharing alike (the least sum of squares, every impulse at least zero): the next substep
        // starts warm from these impulses, and two corners of a square holding the whole weight set the cube
        // turning about its diagonal as the sweeps shared them out again.
        int out = 0;
        while (out < n && (set & (1u << out)))
            ++out;
        Real outAbove = out < n ? w0[out] : 0.0;
        for (int j = 0; j < n && out < n; ++j)
            outAbove += K[out][j] * lambda[j];
        constexpr Real nearTarget = 1e-3;
        if (size == n - 1 && n > 1 && outAbove <= nearTarget * scale + slack) {
            for (int r = 0; r < m; ++r) {
                for (int c = 0; c < m; ++c)
                    A[r][c] = K[index[r]][index[c]];
                A[r][m] = -K[index[r]][out];
            }
            Real z[4] = {0.0, 0.0, 0.0, 0.0}, y[4];
            bool nullVector = eliminate(A, m, tiny, y);
            if (nullVector) {
                for (int r = 0; r < m; ++r)
                    z[index[r]] = y[r];
                z[out] = 1.0;
                // K z = 0 on the set's rows by construction; on the row left out only if the block is singular.
                Real residual = K[out][out], size1 = 1.0;
                for (int r = 0; r < m; ++r) {
                    residual += K[out][index[r]] * y[r];
                    size1 += std::abs(y[r]);
                }
                nullVector = std::abs(residual) <= 1e-9 * largest * size1;
            }
            if (nullVector) {
                Real lz = 0.0, zz = 0.0, lo = -std::numeric_limits<Real>::infinity(),
                     hi = std::numeric_limits<Real>::infinity();
                for (int i = 0; i < n; ++i) {
                    lz += lambda[i] * z[i];
                    zz += z[i] * z[i];
                    if (z[i] > 0.0)
                        lo = std::max(lo, -lambda[i] / z[i]);
                    else if (z[i] < 0.0)
                        hi = std::min(hi, -lambda[i] / z[i]);
                }
                const Real alpha = lo <= hi ? std::clamp(-lz / zz, lo, hi) : 0.0;
                if (std::isfinite(alpha))
                    for (int i = 0; i < n; ++i)
                        lambda[i] = std::max(lambda[i] + alpha * z[i], 0.0);
            }
        }
        for (int i = 0; i < n; ++i)
            rows.impulse[i] = lambda[i];
        return true;
    }
    return false;
}

Softness softness(Real omega, Real zeta, Real h) {
    // Soft constraint as an implicit-Euler damped spring (Catto, "Solver2D", 2024): with a1 = 2 zeta + h omega,
    // the bias rate is omega / a1, and the mass and impulse scales blend the rigid answer with the spring's.
    const Real a1 = 2.0 * zeta + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void ContactSolver::prepare(std::span<Manifold* const> manifolds, std::span<const uint32_t> solverIndexA,
                            std::span<const uint32_t> solverIndexB, std::span<const Real> friction,
                            std::span<const Real> restitution, std::span<const SolverBody> bodies,
                            std::span<const Vec3> centers, Real h, const ContactSolverSettings& settings,
                            std::span<const uint8_t> bodyPart, const ParallelFor& parallelFor,
                            std::span<const Hold> held, const PackParts& packParts) {
    m_settings = settings;
    m_inverseH = h > 0.0 ? 1.0 / h : 0.0;
    m_h = h;
    m_soft = softness(2.0 * kPi * settings.contactHertz, settings.dampingRatio, h);

    m_count = manifolds.size();
    // The constraints are set up straight into the batches (buildBatches()); the whole records are kept as well only
    // where something reads them after prepare(). Written in manifold order by a pass of their own, 620 bytes each,
    // and read back level by level, they cost that pass alone 1.8-1.9 ms of the 4.9 ms a step of large_pyramid's
    // prepare_contacts on one thread (its first 120 frames, 2026-11-27). The restitution pass reads only the records
    // of the constraints that may bounce (mayBounce()), so only those are kept for it (see m_constraints).
    m_kept = m_keepConstraints;
    m_bounceOnly = !m_kept && settings.restitution;
    m_constraints.resize(m_kept || m_bounceOnly ? m_count : 0);
    m_bouncing.assign(m_bounceOnly ? m_count : 0, 0);
    batchKeys(manifolds, parallelFor);
    scheduleLevels(bodies.size(), bodyPart, solverIndexA, solverIndexB, packParts, parallelFor);
    const SetUpInputs inputs{manifolds, solverIndexA, solverIndexB, friction, restitution, bodies, centers, held};
    m_struck.assign(settings.blowPasses > 0 || settings.blowShockPasses > 0 ? m_count : 0, 0);
    buildBatches(inputs, parallelFor);
    findBlows(inputs, parallelFor);
    if (m_bounceOnly || (m_kept && settings.restitution)) {
        m_startVelocity.resize(bodies.size());
        m_startInverseInertia.resize(bodies.size());
        for (size_t i = 0; i < bodies.size(); ++i) {
            m_startVelocity[i] = {bodies[i].v, bodies[i].w};
            m_startInverseInertia[i] = bodies[i].invInertia;
        }
    }
    m_sweepRows = {};
    for (size_t i = 0; i < m_count; ++i)
        if (settings.friction && friction[i] > 0.0)
            m_sweepRows.frictionRows += 3u; // the tangent block (two rows) and the twist
    for (uint8_t key : m_batchKey)
        m_sweepRows.normalRows += 4u - key % 8u; // the point count (see buildBatches())
    m_sweepRows.sweptBatches = batchCount();
}

void ContactSolver::scheduleLevels(size_t bodyCount, std::span<const uint8_t> bodyPart, std::span<const uint32_t> bodyA,
                                   std::span<const uint32_t> bodyB, const PackParts& packParts,
                                   const ParallelFor& parallelFor) {
    // Level schedule of the sequential order: a constraint's level is one more than the highest level among the
    // earlier constraints (in manifold order) that share one of its moving bodies. Solving level by level then
    // performs, for every body, the same updates in the same order as solving the constraints one after the other,
    // so the result is bit-identical to the sequential sweep; and the constraints of one level share no moving
    // body, so they can be solved in any order or at once on several threads. (A greedy colouring, as Box2D v3
    // uses, reorders constraints that share a body: in a tower it solves every other contact first, which here let
    // the 20-cube tower's top drift 5.6 mm instead of 0.7 mm and the 210-cube pyramid's 9.5 mm instead of 0.24 mm.)
    // Entry 0 (anchors and sleepers) does not count: it is never written.
    //
    // With parts, the sequential order is segment by segment (see prepare()), and each segment's levels follow the
    // previous segment's, so that a segment is a contiguous run of levels and of batches.
    m_segment.resize(m_count);
    Schedule schedule; // for packParts
    for (size_t i = 0; i < m_count; ++i) {
        const uint32_t a = bodyA[i], b = bodyB[i];
        if (bodyPart.empty())
            m_segment[i] = 0;
        else if (a == 0 || b == 0)
            m_segment[i] = bodyPart[a == 0 ? b : a];
        else
            m_segment[i] = bodyPart[a] == bodyPart[b] ? bodyPart[a] : kBoundarySegment;
        ++schedule.constraints[m_segment[i]];
    }
    // One pass over the constraints numbers each one's level within its segment; the segments' levels are then
    // placed one after the other. The parts share no moving body, so one array of next levels serves both; the
    // boundary's constraints count from its own start, since every level of the parts comes before it. (With a pass
    // per segment, scheduleLevels() took 97-98 us a step of the 5,050-cube pyramid's set-up, with one 69-72 us:
    // medians of its first 45 frames on one thread, three interleaved runs, 2026-11-27.)
    //
    // The boundary is levelled by colour instead: each of its constraints, in manifold order, takes the lowest level
    // that no earlier boundary constraint of either of its bodies holds, so a body may meet its boundary constraints
    // in another order than manifold order (the sequential sweeps follow the levels there, see solveSequential()).
    // A cut through a brick wall or a pile crosses it along a seam where each constraint shares a body with the
    // next one: in manifold order that was a chain of single-constraint levels (the 5,050-cube pyramid's cut: 96 a
    // step, swept by one thread in every sweep while the other waited at the barrier), and by colour it is three
    // levels, 19 batches. Its step on two threads took 12.4, 15.9 and 15.2 ms against 13.1, 16.3 and 15.4 in
    // manifold order, on one thread 22.5, 27.1 and 24.8 against 22.4, 26.6 and 24.7 (medians of its first 45 frames,
    // each frame's least of three runs, all four by turns, three rounds on a busy host; 2026-12-01). Its top drifted
    // 5.3 mm in 10 s instead of 6.0 and pyramid20's 0.29 mm instead of 0.41 (tst_large_pyramid, tst_stacking).
    // A body with all 64 colours taken (more than 64 constraints across the cut) goes on in levels after them, one
    // more than its last.
    thread_local std::vector<uint32_t> nextLevel, nextBoundaryLevel, levelOf;
    thread_local std::vector<uint64_t> boundaryColours;
    nextLevel.assign(bodyCount, 0);
    if (!bodyPart.empty()) {
        nextBoundaryLevel.assign(bodyCount, 0);
        boundaryColours.assign(bodyCount, 0);
    }
    levelOf.resize(m_count);
    uint32_t segmentLevels[kParts + 1] = {};
    for (size_t i = 0; i < m_count; ++i) {
        const uint32_t a = bodyA[i], b = bodyB[i];
        uint32_t level;
        if (m_segment[i] == kBoundarySegment) {
            constexpr uint32_t kColours = 64;
            const uint64_t taken = (a != 0 ? boundaryColours[a] : 0) | (b != 0 ? boundaryColours[b] : 0);
            if (taken != ~uint64_t{0}) {
                level = static_cast<uint32_t>(std::countr_one(taken));
                for (const uint32_t body : {a, b})
                    if (body != 0)
                        boundaryColours[body] |= uint64_t{1} << level;
            } else {
                level = std::max({kColours, a != 0 ? nextBoundaryLevel[a] : 0u, b != 0 ? nextBoundaryLevel[b] : 0u});
                for (const uint32_t body : {a, b})
                    if (body != 0)
                        nextBoundaryLevel[body] = level + 1;
            }
        } else {
            level = std::max(a != 0 ? nextLevel[a] : 0u, b != 0 ? nextLevel[b] : 0u);
            if (a != 0)
                nextLevel[a] = level + 1;
            if (b != 0)
                nextLevel[b] = level + 1;
        }
        levelOf[i] = level;
        uint32_t& count = segmentLevels[m_segment[i]];
        count = std::max(count, level + 1);
    }
    const size_t segments = bodyPart.empty() ? 1 : kParts + 1;
    if (packParts) {
        std::copy(segmentLevels, segmentLevels + kParts + 1, schedule.levels.begin());
        if (packParts(schedule) && s_packLevels) {
            // The parts share no moving body, so each is packed alone, on a thread of the team if there is one.
            const size_t parts = bodyPart.empty() ? 1 : kParts;
            // (levelOf is this thread's: a lambda names a thread_local of the thread it runs on, so it takes a
            // reference.)
            std::array<uint32_t, kParts> batches{};
            std::vector<uint32_t>& packed = levelOf;
            shareOut(parallelFor, parts, [&](size_t first, size_t last) {
                for (size_t part = first; part < last; ++part)
                    packPartLevels(part, bodyCount, static_cast<size_t>(laneWidthHere()), bodyA, bodyB, packed,
                                   batches[part]);
            });
            std::copy(batches.begin(), batches.begin() + static_cast<std::ptrdiff_t>(parts), segmentLevels);
        }
    }
    uint32_t levels = 0;
    for (size_t segment = 0; segment < segments; ++segment) {
        m_segmentLevelStart[segment] = levels;
        levels += segmentLevels[segment];
    }
    for (size_t i = 0; i < m_count; ++i)
        levelOf[i] += m_segmentLevelStart[m_segment[i]];
    for (size_t segment = segments; segment < kParts + 2; ++segment)
        m_segmentLevelStart[segment] = levels;
    m_levelStart.assign(static_cast<size_t>(levels) + 1, 0);
    for (uint32_t level : levelOf)
        ++m_levelStart[static_cast<size_t>(level) + 1];
    for (uint32_t k = 0; k < levels; ++k)
        m_levelStart[k + 1] += m_levelStart[k];
    thread_local std::vector<uint32_t> fill;
    fill.assign(m_levelStart.begin(), m_levelStart.end() - 1);
    m_solveOrder.resize(m_count);
    for (size_t i = 0; i < m_count; ++i)
        m_solveOrder[fill[levelOf[i]]++] = static_cast<uint32_t>(i);
}

void ContactSolver::packPartLevels(size_t part, size_t bodyCount, size_t width, std::span<const uint32_t> bodyA,
                                   std::span<const uint32_t> bodyB, std::vector<uint32_t>& levelOf,
                                   uint32_t& batches) const {
    // A part swept by one thread needs its levels only to fill batches: the constraints of a batch must share no
    // moving body, and each must come after the earlier constraints (in manifold order) of its bodies, so that every
    // body still gets the same updates in the same order. Level by level, every level's last batch is part empty:
    // over ramps.obj's first 120 frames on one thread 11,127 batches held 81,481 constraints, where 10,186 of eight
    // lanes would do. So the constraints are listed into batches instead, each batch taking up to `width` of those
    // whose earlier constraints are all in earlier batches, those with the longest chain of later constraints after
    // them first (Hu's rule for unit tasks; among equal chains the one made ready last, the first ready ones in
    // manifold order).
    //
    // A batch sweeps as many point slots as its constraint with the most points, so it is led by the ready
    // constraint with the longest chain, and filled with ready ones of as many points as that one, then with fewer;
    // never with more. (Filled by chain alone, boxes1000's first 120 frames took 19,877 batches instead of 22,040,
    // but 76,557 point slots instead of 63,906, and their sweeps took longer.)
    //
    // Everything here is numbered by the constraint's place in the part (members).
    constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    constexpr int kPointCounts = 5; // 0 to 4 points
    thread_local std::vector<uint32_t> members, last, next, waiting, chain, readyNext, batch;
    thread_local std::array<std::vector<uint32_t>, kPointCounts> readyHead;
    thread_local std::array<std::vector<uint64_t>, kPointCounts> nonEmpty;
    members.clear();
    for (size_t i = 0; i < m_count; ++i)
        if (m_segment[i] == part)
            members.push_back(static_cast<uint32_t>(i));
    const size_t n = members.size();
    // The point count from the key (buildBatches()), read beside the constraint rather than from its manifold.
    const auto points = [&](uint32_t k) { return 4 - m_batchKey[members[k]] % 8; };
    // next[2 k + s]: the constraint after k on its body A (s = 0) or B (s = 1); waiting[k]: how many of the
    // constraints before k on its bodies are not in a batch yet (one if both bodies' are the same one).
    last.assign(bodyCount, kNone);
    next.assign(2 * n, kNone);
    waiting.assign(n, 0);
    chain.assign(n, 1);
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t i = members[k];
        uint32_t before[2] = {kNone, kNone};
        for (int side = 0; side < 2; ++side) {
            const uint32_t body = side == 0 ? bodyA[i] : bodyB[i];
            if (body == 0)
                continue;
            const uint32_t p = last[body];
            if (p != kNone) {
                next[2 * p + (bodyA[members[p]] == body ? 0 : 1)] = k;
                before[side] = p;
            }
            last[body] = k;
        }
        waiting[k] = (before[0] != kNone ? 1u : 0u) + (before[1] != kNone && before[1] != before[0] ? 1u : 0u);
    }
    // chain[k]: the constraints in the longest run of later constraints that starts at k, k included.
    uint32_t longest = 0;
    for (size_t k = n; k-- > 0;) {
        for (int side = 0; side < 2; ++side)
            if (const uint32_t after = next[2 * k + side]; after != kNone)
                chain[k] = std::max(chain[k], chain[after] + 1);
        longest = std::max(longest, chain[k]);
    }
    // The constraints ready for a batch: one list per point count and chain length, and per point count a bit per
    // chain length whose list holds any, so that a batch finds the longest chains ready without looking at the
    // empty lists in between.
    readyNext.assign(n, kNone);
    const size_t lengths = static_cast<size_t>(longest) + 1, words = (lengths + 63) / 64;
    for (int p = 0; p < kPointCounts; ++p) {
        readyHead[p].assign(lengths, kNone);
        nonEmpty[p].assign(words, 0);
    }
    std::array<uint32_t, kPointCounts> top{}; // per point count: no list above it holds a constraint
    std::array<size_t, kPointCounts> ready{}; // per point count: the constraints in its lists
    const auto makeReady = [&](uint32_t k) {
        const uint32_t p = points(k), length = chain[k];
        top[p] = std::max(top[p], length);
        ++ready[p];
        uint32_t& head = readyHead[p][length];
        if (head == kNone)
            nonEmpty[p][length / 64] |= uint64_t{1} << (length % 64);
        readyNext[k] = head;
        head = k;
    };
    // The longest chain below `below` ready among the constraints of p points; 0 if none (chains are 1 or more long).
    const auto longestReady = [&](uint32_t p, uint32_t below) -> uint32_t {
        if (ready[p] == 0 || below <= 1)
            return 0;
        const uint32_t from = std::min(below - 1, top[p]);
        size_t w = from / 64;
        uint64_t bits = nonEmpty[p][w] & (~uint64_t{0} >> (63 - from % 64));
        for (;;) {
            if (bits != 0)
                return static_cast<uint32_t>(w * 64 + 63 - static_cast<size_t>(std::countl_zero(bits)));
            if (w == 0)
                return 0;
            bits = nonEmpty[p][--w];
        }
    };
    // Last in first out: made ready in reverse, ties come out in manifold order.
    for (size_t k = n; k-- > 0;)
        if (waiting[k] == 0)
            makeReady(static_cast<uint32_t>(k));
    // Takes ready constraints of p points into the batch, longest chains first, until it is full.
    const auto take = [&](uint32_t p) {
        for (uint32_t length = top[p]; length > 0 && batch.size() < width; length = longestReady(p, length)) {
            uint32_t& head = readyHead[p][length];
            while (head != kNone && batch.size() < width) {
                batch.push_back(head);
                head = readyNext[head];
                --ready[p];
            }
            if (head == kNone)
                nonEmpty[p][length / 64] &= ~(uint64_t{1} << (length % 64));
        }
    };
    uint32_t count = 0;
    for (size_t left = n; left > 0; left -= batch.size(), ++count) {
        batch.clear();
        // The batch is led by the point count of the longest chain ready (the most points among ties).
        uint32_t lead = kPointCounts - 1, leadLength = 0;
        for (uint32_t p = kPointCounts; p-- > 0;) {
            top[p] = longestReady(p, top[p] + 1);
            if (top[p] > leadLength) {
                lead = p;
                leadLength = top[p];
            }
        }
        for (uint32_t p = lead + 1; p-- > 0 && batch.size() < width;)
            take(p);
        // The constraints after this batch's become ready for the next one, not for this one.
        for (const uint32_t k : batch) {
            levelOf[members[k]] = count;
            const uint32_t afterA = next[2 * k], afterB = next[2 * k + 1];
            if (afterA != kNone && --waiting[afterA] == 0)
                makeReady(afterA);
            if (afterB != kNone && afterB != afterA && --waiting[afterB] == 0)
                makeReady(afterB);
        }
    }
    batches = count;
}

void ContactSolver::batchKeys(std::span<Manifold* const> manifolds, const ParallelFor& parallelFor) {
    // A constraint's key groups it with others of the same point count, and pushing ones apart from those that did
    // not push in the last step: the lanes of a batch then have work of the same size, and a point slot in which no
    // lane pushes skips its warm start, as the scalar sweep skips such points (buildBatches(), packPartLevels()).
    // The keys are worked out once per constraint, not in every comparison of a sort.
    // (The manifold's impulses are the constraint's if warm starting is on, else zero: setUpConstraint().)
    m_batchKey.resize(m_count);
    shareOut(parallelFor, m_count, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const Manifold& m = *manifolds[i];
            bool pushing = false;
            for (int k = 0; k < m.pointCount; ++k)
                pushing = pushing || (m_settings.warmStarting && m.points[k].normalImpulse != 0.0);
            m_batchKey[i] = static_cast<uint8_t>((pushing ? 0 : 8) + (4 - m.pointCount));
        }
    });
}

int ContactSolver::laneWidthHere() {
    // Eight lanes of doubles need AVX-512 (x86-64-v4); elsewhere 512-bit vectors split into halves ran 2.2x slower
    // than four lanes in one AVX2 register (a microbenchmark of the row update, 2026-11-26).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
    static const bool wide = __builtin_cpu_supports("x86-64-v4");
#else
    static const bool wide = false;
#endif
    return wide && s_widestLanes >= 8 ? 8 : 4;
}

std::string ContactSolver::sweepsDescription() {
    const int lanes = laneWidthHere();
    std::string isa = "portable";
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
    // As the sweeps' target_clones choose: the x86-64-v3 clone where the CPU has it, else the baseline one.
    isa = lanes == 8 ? "AVX-512" : __builtin_cpu_supports("x86-64-v3") ? "AVX2" : "SSE2";
#endif
    return std::to_string(lanes) + " lanes of doubles (" + isa + ")";
}

int ContactSolver::s_widestLanes = 8;
bool ContactSolver::s_wideSetUp = true;
bool ContactSolver::s_packLevels = true;
bool ContactSolver::s_keepSeparations = true;

void ContactSolver::buildBatches(const SetUpInputs& inputs, const ParallelFor& parallelFor) {
    m_batchesAhead = false;
    m_separationsKept = false;
    m_width = laneWidthHere();
    if (m_width == 8)
        buildBatches(m_store8, inputs, parallelFor);
    else
        buildBatches(m_store4, inputs, parallelFor);
}

template <int W>
void ContactSolver::buildBatches(BatchStore<W>& store, const SetUpInputs& inputs, const ParallelFor& parallelFor) {
    // Each part below writes only its own constraints, levels or batches, so a team can share it out (parallelFor)
    // with the same results; the layout of the batches in between is a short serial pass over one byte per
    // constraint. Built in one serial pass, the batches took 3.0 ms a step of the 5.9 ms that large_pyramid's
    // prepare_contacts took over its first 120 frames on one thread, and were the largest serial part of its step on
    // two; shared out, prepare_contacts on two threads went from 6.6-6.8 to 4.9-5.2 ms a step over frames 60-120
    // (2026-11-27, two interleaved runs each, the same frames).
    //
    // The fill sets each constraint up (setUpConstraint()) as it puts it in its lane. A pass that first wrote every
    // record in manifold order, 620 bytes each, then read them back level by level, cost a write and a scattered read
    // of some 10 MB a step in large_pyramid. Setting up in the fill, with the next batch's manifolds and bodies
    // fetched ahead, prepare_contacts over frames 60-120 took 4.2-4.3 ms a step on one thread and 3.0-3.1 on two,
    // against 4.8 and 3.7-3.8 before (2026-11-27, two interleaved runs; without the fetching ahead, 5.1-5.2 and
    // 3.3-3.4).
    std::vector<Batch<W>>& batches = store.batches;
    std::vector<BatchPoint<W>>& points = store.points;
    const size_t levels = levelCount();
    auto set = [](auto* lanes, const Vec3& v, int lane) {
        for (int axis = 0; axis < 3; ++axis)
            lanes[axis].v[lane] = static_cast<std::remove_reference_t<decltype(lanes[axis].v[0])>>(v[axis]);
    };
    // Within a level the order is free (its constraints share no moving body), so constraints are grouped there by
    // their key (batchKeys()).
    const std::vector<uint8_t>& key = m_batchKey;
    shareOut(parallelFor, levels, [&](size_t begin, size_t end) {
        for (size_t level = begin; level < end; ++level)
            sortByKey(std::span<uint32_t>(m_solveOrder).subspan(levelBegin(level), levelEnd(level) - levelBegin(level)),
                      key);
    });
    // The layout: each batch's first constraint in m_solveOrder, its lanes and its points. A batch has as many point
    // slots as its constraint with the most points; the key holds each constraint's point count (4 - key % 8).
    m_batchLevelStart.assign(levels + 1, 0);
    std::vector<BatchLayout>& layout = m_batchLayout;
    layout.clear();
    uint32_t pointTotal = 0;
    for (size_t level = 0; level < levels; ++level) {
        m_batchLevelStart[level] = static_cast<uint32_t>(layout.size());
        for (size_t first = levelBegin(level); first < levelEnd(level); first += W) {
            const size_t lanes = std::min<size_t>(W, levelEnd(level) - first);
            uint32_t pointCount = 0;
            for (size_t l = 0; l < lanes; ++l)
                pointCount = std::max<uint32_t>(pointCount, 4u - key[m_solveOrder[first + l]] % 8u);
            layout.push_back({static_cast<uint32_t>(first), static_cast<uint32_t>(lanes), pointTotal, pointCount});
            pointTotal += pointCount;
        }
    }
    m_batchLevelStart[levels] = static_cast<uint32_t>(layout.size());
    // Every batch and point is written whole below (an empty lane or point slot zeroed), so the arrays are only
    // sized here.
    static_assert(std::is_trivially_copyable_v<Batch<W>> && std::is_trivially_copyable_v<BatchPoint<W>>);
    batches.resize(layout.size());
    store.scales.resize(layout.size());
    points.resize(pointTotal);
    const bool maxImpulse = m_settings.restitution;
    store.maxImpulse.resize(maxImpulse ? pointTotal : 0);
    store.separation.resize(pointTotal); // written by the first sweep (Motion::Moved)
    m_laneOf.resize(m_count);
    m_order.resize(m_count);
    // W constraints at a time, in vectors (setUpBatch()). Set up one by one, large_pyramid's prepare_contacts took
    // 4.13-4.49 ms a step on one thread and 2.32-2.46 on two; in vectors 3.25-3.41 and 1.83-1.85 (frames 5-45, each
    // frame's least of three runs, two interleaved runs of each build, 2026-11-28). With the records written from
    // the vectors too (restitution on), ramps' took 0.164-0.169 ms against 0.190 (one thread, 300 frames, likewise).
    // The frames are the same.
    const bool wideSetUp = s_wideSetUp;
    // The scalar set-up of batch b (where setUpBatch() is not used), constraint by constraint. Lanes past at.lanes stay
    // empty: no constraint, bodies 0, zero masses and impulses.
    const auto fill = [&](size_t b) {
        const BatchLayout& at = layout[b];
        Batch<W>& batch = batches[b];
        std::memset(static_cast<void*>(&batch), 0, sizeof(Batch<W>));
        BatchScales<W>& scales = store.scales[b];
        std::memset(static_cast<void*>(&scales), 0, sizeof(BatchScales<W>));
        batch.firstPoint = at.firstPoint;
        batch.pointCount = at.pointCount;
        batch.isotropic = isotropicBatch<W>(inputs, at);
        for (uint32_t k = 0; k < at.pointCount; ++k)
            std::memset(static_cast<void*>(&points[at.firstPoint + k]), 0, sizeof(BatchPoint<W>));
        if (maxImpulse && at.pointCount > 0)
            std::memset(static_cast<void*>(&store.maxImpulse[at.firstPoint]), 0, at.pointCount * sizeof(Lanes<W>));
        for (uint32_t l = 0; l < at.lanes; ++l) {
            const int lane = static_cast<int>(l);
            const uint32_t index = m_solveOrder[at.first + l];
            ContactConstraint c;
            setUpConstraint(c, *inputs.manifolds[index], inputs.indexA[index], inputs.indexB[index],
                            inputs.friction[index], inputs.restitution[index],
                            inputs.held.empty() ? Hold{} : inputs.held[index], inputs.bodies, inputs.centers, m_h,
                            m_settings);
            if (m_kept) {
                m_constraints[index] = c;
            } else if (m_bounceOnly && mayBounce(c)) {
                m_constraints[index] = c;
                m_bouncing[index] = 1;
            }
            std::copy(c.order, c.order + 4, m_order[index].begin());
            if (!m_struck.empty())
                m_struck[index] = c.blow ? 1 : 0;
            batch.bodyA[l] = c.bodyA;
            batch.bodyB[l] = c.bodyB;
            m_laneOf[index] = static_cast<uint32_t>(b * W + l);
            set(batch.normal, c.normal, lane);
            set(batch.tangent[0], c.tangent[0], lane);
            set(batch.tangent[1], c.tangent[1], lane);
            batch.friction.v[l] = c.friction;
            scales.a.v[l] = c.scaleA;
            scales.b.v[l] = c.scaleB;
            batch.holds = batch.holds || c.scaleA != 1.0 || c.scaleB != 1.0;
            batch.impacts = static_cast<uint8_t>(batch.impacts | (c.impact ? 1u << l : 0u));
            set(batch.anchorOffset, c.anchorOffset, lane);
            set(batch.centerA, c.centerA, lane);
            set(batch.centerB, c.centerB, lane);
            for (int m = 0; m < 3; ++m)
                batch.frictionMass[m].v[l] = static_cast<float>(c.frictionMass[m]);
            batch.twistMass.v[l] = static_cast<float>(c.twistMass);
            batch.frictionImpulse[0].v[l] = c.frictionImpulse[0];
            batch.frictionImpulse[1].v[l] = c.frictionImpulse[1];
            batch.twistImpulse.v[l] = c.twistImpulse;
            for (int k = 0; k < c.pointCount; ++k) {
                const ContactConstraint::Point& p = c.points[c.order[k]];
                BatchPoint<W>& q = points[at.firstPoint + static_cast<uint32_t>(k)];
                set(q.rA, p.rA, lane);
                q.baseSeparation.v[l] = static_cast<float>(p.baseSeparation);
                q.mass.v[l] = static_cast<float>(p.normalMass);
                q.leverArm.v[l] = static_cast<float>(p.leverArm);
                q.impulse.v[l] = p.normalImpulse;
                if (maxImpulse)
                    store.maxImpulse[at.firstPoint + static_cast<uint32_t>(k)].v[l] = p.maxNormalImpulse;
            }
        }
    };
    shareOut(parallelFor, layout.size(), [&](size_t begin, size_t end) {
        for (size_t b = begin; b < end; ++b) {
            // The next batch's manifolds and bodies are read in level order, scattered in memory: fetch them ahead.
            if (b + 1 < end) {
                const BatchLayout& next = layout[b + 1];
                for (uint32_t l = 0; l < next.lanes; ++l) {
                    const uint32_t index = m_solveOrder[next.first + l];
                    const char* m = reinterpret_cast<const char*>(inputs.manifolds[index]);
                    for (size_t line = 0; line < sizeof(Manifold); line += 64)
                        __builtin_prefetch(m + line);
                    for (const uint32_t body : {inputs.indexA[index], inputs.indexB[index]}) {
                        const char* record = reinterpret_cast<const char*>(&inputs.bodies[body]);
                        for (size_t line = 0; line < sizeof(SolverBody); line += 64)
                            __builtin_prefetch(record + line);
                    }
                }
            }
            if (!wideSetUp || !(W == 8 ? setUpBatch8(inputs, b) : setUpBatch4(inputs, b)))
                fill(b);
        }
    });
}

void ContactSolver::findBlows(const SetUpInputs& inputs, const ParallelFor& parallelFor) {
    m_blows.clear();
    m_shocks.clear();
    m_blowIndex.clear();
    if (std::find(m_struck.begin(), m_struck.end(), uint8_t(1)) == m_struck.end())
        return; // no blow (or none looked for)
    const size_t bodyCount = inputs.bodies.size();
    // A manifold that bounces is left to the substeps and the restitution pass.
    const auto bounces = [&](size_t i) { return m_settings.restitution && inputs.restitution[i] > 0.0; };
    listByBody(
        bodyCount, m_count, [](size_t k) { return static_cast<uint32_t>(k); },
        [&](uint32_t i) {
            return std::array<uint32_t, 2>{inputs.indexA[i], inputs.indexB[i]};
        },
        m_blowFirst, m_blowList, m_blowLevel);
    const auto constraintsOf = [&](uint32_t x) { return m_blowFirst[x + 1] - m_blowFirst[x]; };
    // The struck constraints that hand a blow on (two moving bodies, or a moving body with another constraint) and
    // their moving bodies, level 0 of the walk down.
    constexpr uint32_t kNone = 0xffffffffu;
    m_blowTaken.assign(m_count, 0);
    m_blowLevel.assign(bodyCount, kNone);
    std::vector<uint32_t>& queue = m_blowQueue;
    queue.clear();
    for (size_t i = 0; i < m_count; ++i) {
        if (m_struck[i] == 0 || bounces(i))
            continue;
        const uint32_t a = inputs.indexA[i], b = inputs.indexB[i];
        if (!((a != 0 && b != 0) || (a != 0 && constraintsOf(a) > 1) || (b != 0 && constraintsOf(b) > 1)))
            continue;
        m_blowTaken[i] = 1;
        for (const uint32_t x : {a, b})
            if (x != 0 && m_blowLevel[x] == kNone) {
                m_blowLevel[x] = 0;
                queue.push_back(x);
            }
    }
    if (queue.empty())
        return;
    // Down from each struck body through the constraints that bear it up (the normal within 45 degrees of
    // vertical, the other body below), to the ground or kBlowDepth bodies down.
    const Real g2 = glm::dot(m_settings.gravity, m_settings.gravity);
    const Vec3 up = g2 > 0.0 ? -m_settings.gravity / std::sqrt(g2) : Vec3(0.0);
    const Real steep = std::sqrt(0.5);
    // How far the normal of constraint i rises from body `lower` to the other one (the normal points from A to B).
    const auto rise = [&](size_t i, uint32_t lower) {
        const Real along = glm::dot(inputs.manifolds[i]->normal, up);
        return lower == inputs.indexA[i] ? along : -along;
    };
    // Whether constraint i can bear its upper body up in this step: a struck one, or one whose nearest point is at
    // most kBlowSupportGap apart. (A fast body's speculative manifold with a body farther down, which it would meet
    // only through the nearer one, gave it the height of the nearer one, and so no hold: a box coming down at 20 m/s
    // onto a stack of two had a manifold with the lower box of the stack too.)
    const auto bears = [&](size_t i) {
        if (m_struck[i] != 0)
            return true;
        const Manifold& m = *inputs.manifolds[i];
        for (int k = 0; k < m.pointCount; ++k)
            if (m.points[k].separation <= kBlowSupportGap)
                return true;
        return false;
    };
    for (size_t q = 0; q < queue.size(); ++q) {
        const uint32_t x = queue[q];
        if (m_blowLevel[x] >= static_cast<uint32_t>(kBlowDepth))
            continue;
        for (uint32_t k = m_blowFirst[x]; k < m_blowFirst[x + 1]; ++k) {
            const uint32_t i = m_blowList[k];
            const uint32_t y = inputs.indexA[i] == x ? inputs.indexB[i] : inputs.indexA[i];
            if (bounces(i) || !(rise(i, y) >= steep) || !bears(i))
                continue;
            m_blowTaken[i] = 1;
            if (y != 0 && m_blowLevel[y] == kNone) {
                m_blowLevel[y] = m_blowLevel[x] + 1;
                queue.push_back(y);
            }
        }
    }
    const Hold none{};
    const auto setUp = [&](ContactConstraint& c, size_t i, const Hold& hold) {
        setUpConstraint(c, *inputs.manifolds[i], inputs.indexA[i], inputs.indexB[i], inputs.friction[i],
                        inputs.restitution[i], hold, inputs.bodies, inputs.centers, m_h, m_settings);
        // Every manifold's normal rows are solved as a block where a sweep leaves one far off its target
        // (solveConstraint()). Point by point, a box struck flat took the blow at its first point and turned, and the
        // turn came out of the substeps as a rise: a box coming down at 20 m/s onto a stack of two sent the stack
        // up at 0.175 m/s, against 0.001 solved as blocks.
        c.impact = c.pointCount > 1;
    };
    // Each record is set up alone, so a team shares them out with the same results. (Set up by one thread,
    // boxes1000's blows and shocks took some 0.03 ms a step of serial work on two threads, frames 45-120.)
    for (size_t i = 0; i < m_count; ++i)
        if (m_blowTaken[i] != 0)
            m_blowIndex.push_back(static_cast<uint32_t>(i));
    m_blows.resize(m_blowIndex.size());
    const ParallelFor alone;
    const ParallelFor& shared = m_blowIndex.size() >= kMinSharedBlows ? parallelFor : alone; // a job pays for many
    shareOut(shared, m_blowIndex.size(), [&](size_t first, size_t last) {
        for (size_t k = first; k < last; ++k) {
            const uint32_t i = m_blowIndex[k];
            setUp(m_blows[k], i, inputs.held.empty() ? none : inputs.held[i]);
        }
    });
    if (m_settings.blowShockPasses <= 0)
        return;
    // Heights above the ground over those constraints: 0 for the still side, one more for each body borne up.
    std::vector<uint32_t>& height = m_blowHeight;
    height.assign(bodyCount, kNone);
    height[0] = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (const uint32_t i : m_blowIndex) {
            const uint32_t a = inputs.indexA[i], b = inputs.indexB[i];
            for (const auto& [lower, upper] : {std::pair{a, b}, std::pair{b, a}})
                if (height[lower] != kNone && height[lower] + 1 < height[upper] && rise(i, lower) >= steep &&
                    bears(i)) {
                    height[upper] = height[lower] + 1;
                    changed = true;
                }
        }
    }
    // From the ground up (the lower height of each constraint's bodies, then manifold order), each constraint
    // between two moving bodies at different heights holding its lower body still where it bears the other up.
    std::vector<std::pair<uint32_t, uint32_t>>& order = m_blowOrder; // (height, position in m_blowIndex)
    order.clear();
    for (size_t k = 0; k < m_blowIndex.size(); ++k) {
        const uint32_t i = m_blowIndex[k];
        order.emplace_back(std::min(height[inputs.indexA[i]], height[inputs.indexB[i]]), static_cast<uint32_t>(k));
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    m_shocks.resize(order.size());
    shareOut(shared, order.size(), [&](size_t first, size_t last) {
        for (size_t n = first; n < last; ++n) {
            const auto [level, k] = order[n];
            const uint32_t i = m_blowIndex[k];
            const uint32_t a = inputs.indexA[i], b = inputs.indexB[i];
            Hold hold{};
            if (a != 0 && b != 0 && level != kNone && height[a] != height[b]) {
                const uint32_t lower = height[a] < height[b] ? a : b;
                if (rise(i, lower) >= kBlowHoldRise)
                    hold = Hold{lower == a ? kHoldA : kHoldB, 0.0};
            }
            if (hold.side != 0)
                setUp(m_shocks[n], i, hold);
            else
                m_shocks[n] = m_blows[k]; // as set up above
        }
    });
}

bool ContactSolver::mayBounce(const ContactConstraint& c) const {
    if (c.restitution == 0.0)
        return false;
    if (c.bodyA != 0 && c.bodyB != 0)
        return true;
    for (int k = 0; k < c.pointCount; ++k)
        if (!(c.points[k].relativeVelocity > -m_settings.restitutionThreshold))
            return true;
    return false;
}

void ContactSolver::syncFromBatches() const {
    if (!m_batchesAhead || !(m_kept || m_bounceOnly))
        return;
    m_batchesAhead = false;
    if (m_width == 8)
        syncFromBatches(m_store8);
    else
        syncFromBatches(m_store4);
}

template <int W>
void ContactSolver::syncFromBatches(const BatchStore<W>& store) const {
    for (size_t n = 0; n < store.batches.size(); ++n) {
        const Batch<W>& batch = store.batches[n];
        const BatchLayout& at = m_batchLayout[n];
        for (uint32_t lane = 0; lane < at.lanes; ++lane) {
            const int l = static_cast<int>(lane);
            const uint32_t i = m_solveOrder[at.first + lane];
            if (!hasRecord(i))
                continue;
            ContactConstraint& c = m_constraints[i];
            c.frictionImpulse[0] = batch.frictionImpulse[0].v[l];
            c.frictionImpulse[1] = batch.frictionImpulse[1].v[l];
            c.twistImpulse = batch.twistImpulse.v[l];
            for (int k = 0; k < c.pointCount; ++k) {
                const uint32_t point = batch.firstPoint + static_cast<uint32_t>(k);
                ContactConstraint::Point& p = c.points[c.order[k]];
                p.normalImpulse = store.points[point].impulse.v[l];
                p.maxNormalImpulse = store.maxImpulse.empty() ? 0.0 : store.maxImpulse[point].v[l];
            }
        }
    }
}

void ContactSolver::warmStart(std::span<SolverBody> bodies) {
    beginSubstep();
    if (m_settings.warmStarting)
        warmStartBatchRange(bodies, 0, batchCount());
}

template <class Visit>
void ContactSolver::forEachInSequence(Visit&& visit) const {
    // The parts in manifold order, then the boundary level by level (its levels are colours, see scheduleLevels()).
    for (size_t segment = 0; segment < kBoundarySegment; ++segment)
        for (size_t i = 0; i < m_constraints.size(); ++i)
            if (m_segment[i] == segment)
                visit(i);
    for (size_t k = levelBegin(m_segmentLevelStart[kBoundarySegment]); k < m_solveOrder.size(); ++k)
        visit(m_solveOrder[k]);
}

void ContactSolver::warmStartSequential(std::span<SolverBody> bodies) {
    if (!m_settings.warmStarting)
        return;
    forEachInSequence([&](size_t i) { warmStartOne(bodies, m_constraints[i]); });
}

namespace {

// The friction rows of one manifold (see ContactConstraint): impulses j0, j1 along the tangents at the friction
// centre, and jt about the normal. Both sides are read (the static entry 0 has zero velocities), only moving ones
// written, in the order of the batches' lanes (ContactSolverWide.cpp).
template <bool kStaticA, bool kStaticB>
void applyFriction(SolverBody& a, SolverBody& b, const Inverse& ia, const Inverse& ib, const ContactConstraint& c,
                   Real j0, Real j1) {
    const Vec3 P = j0 * c.tangent[0] + j1 * c.tangent[1];
    if constexpr (!kStaticA) {
        a.v = a.v - ia.mass * P;
        a.w = a.w - ia.inertia * glm::cross(c.centerA, P);
    }
    if constexpr (!kStaticB) {
        b.v = b.v + ib.mass * P;
        b.w = b.w + ib.inertia * glm::cross(c.centerB, P);
    }
}

template <bool kStaticA, bool kStaticB>
void applyTwist(SolverBody& a, SolverBody& b, const Inverse& ia, const Inverse& ib, const ContactConstraint& c,
                Real jt) {
    const Vec3 T = jt * c.normal;
    if constexpr (!kStaticA)
        a.w = a.w - ia.inertia * T;
    if constexpr (!kStaticB)
        b.w = b.w + ib.inertia * T;
}

template <bool kStaticA, bool kStaticB>
void warmStartConstraint(const ContactConstraint& c, SolverBody& a, SolverBody& b) {
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    for (int k = 0; k < c.pointCount; ++k) {
        const ContactConstraint::Point& p = c.points[c.order[k]]; // the batches' order
        if (p.normalImpulse == 0.0)
            continue; // a speculative point that never pushed: nothing to apply
        applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.normal, p.normalImpulse);
    }
    applyTwist<kStaticA, kStaticB>(a, b, ia, ib, c, c.twistImpulse);
    applyFriction<kStaticA, kStaticB>(a, b, ia, ib, c, c.frictionImpulse[0], c.frictionImpulse[1]);
}

} // namespace

void ContactSolver::warmStartOne(std::span<SolverBody> bodies, const ContactConstraint& c) {
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    // The static entry 0 is never written: with several threads on one level it is shared.
    if (c.bodyA == 0)
        warmStartConstraint<true, false>(c, a, b);
    else if (c.bodyB == 0)
        warmStartConstraint<false, true>(c, a, b);
    else
        warmStartConstraint<false, false>(c, a, b);
}

namespace {

// One constraint's normal and friction rows. kStaticA / kStaticB: that side is the solver's entry 0 (anchors and
// sleepers), which never moves: its velocity, position change and rotation change are zero and identity, so the
// terms that read it and the writes to it are left out. The results are the same as the general path's.
template <bool kStaticA, bool kStaticB>
void solveConstraint(ContactConstraint& c, SolverBody& a, SolverBody& b, bool useBias, Real inverseH,
                     const Softness& soft, const ContactSolverSettings& settings) {
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    // Current separation of point p from the motion since the step began; anchors follow each body's rotation.
    const auto separation = [&](const ContactConstraint::Point& p) {
        Vec3 d;
        if constexpr (kStaticA)
            d = b.dp + (b.dR * p.rB - p.rA);
        else if constexpr (kStaticB)
            d = -a.dp + (p.rB - a.dR * p.rA);
        else
            d = (b.dp - a.dp) + (b.dR * p.rB - a.dR * p.rA);
        return glm::dot(c.normal, d) + p.baseSeparation;
    };
    // One sweep of the normal rows, each row taking what it needs after the rows before it. `off` (if given) gets
    // the most any row was off its target when its turn came: short of it, or past it while holding an impulse.
    const auto normalRows = [&](Real* off) {
        for (int j = 0; j < c.pointCount; ++j) {
            ContactConstraint::Point& p = c.points[c.order[j]];
            const Real s = separation(p);
            Real velocityBias = 0.0, massScale = 1.0, impulseScale = 0.0;
            if (s > 0.0) {
                // Speculative: allow the gap to close exactly within this substep.
                velocityBias = s * inverseH;
            } else if (useBias) {
                velocityBias = std::max(soft.biasRate * s, -settings.maxPushoutSpeed);
                massScale = soft.massScale;
                impulseScale = soft.impulseScale;
            }
            const Real vn = rowVelocityT<kStaticA, kStaticB>(a, b, p, c.normal);
            if (off && p.normalMass > 0.0) {
                const Real short_ = -(vn + velocityBias);
                *off = std::max(*off, p.normalImpulse > 0.0 ? std::abs(short_) : short_);
            }
            Real impulse = -p.normalMass * massScale * (vn + velocityBias) - impulseScale * p.normalImpulse;
            const Real newImpulse = std::max(p.normalImpulse + impulse, 0.0);
            impulse = newImpulse - p.normalImpulse;
            p.normalImpulse = newImpulse;
            if (settings.restitution)
                p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
            applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.normal, impulse);
        }
    };
    // A struck manifold's rows are solved as a block (solveImpactRows()) in a sweep that takes some of the blow.
    // Swept one point after the other, a flat face landing on four points let the first point take the whole blow
    // and spin the body: a 0.5 m box dropped flat from 2 m onto a 0.25 m pedestal at 18 substeps took 375/0/0/0 N s
    // and toppled off. So did a sweep that gave back the blow the next substep's warm start had applied again: a
    // cube landing flat at 6.2 m/s went up at 1.5 m/s after that warm start, and the rows, giving their impulses back
    // one after the other, turned it at up to 2.3 rad/s within the step (its third bounce then landed on a corner and
    // spun at 12 rad/s). A soft row (touching, with the bias on) takes its place in the block as the sweeps would
    // leave it if repeated: short of its target by impulseScale / (massScale * normalMass) times its impulse. Where
    // the block has no answer, the sweep stands.
    if (!c.impact) {
        normalRows(nullptr);
    } else {
        // The state before the sweep, for the block.
        const Vec3 startVA = a.v, startWA = a.w, startVB = b.v, startWB = b.w;
        Real startImpulse[4], startLargest[4];
        for (int k = 0; k < c.pointCount; ++k) {
            startImpulse[k] = c.points[k].normalImpulse;
            startLargest[k] = c.points[k].maxNormalImpulse;
        }
        Real off = 0.0;
        normalRows(&off);
        // Only a sweep that takes some of the blow or gives it back (a row more than impactShortfall off its target
        // when its turn came) does more; the others sweep once as every other manifold does.
        if (off > settings.impactShortfall) {
            SolverBody startA = a, startB = b;
            startA.v = startVA;
            startA.w = startWA;
            startB.v = startVB;
            startB.w = startWB;
            ImpactRows rows;
            int slot[4];
            for (int j = 0; j < c.pointCount; ++j) {
                const int k = c.order[j];
                const ContactConstraint::Point& p = c.points[k];
                if (!(p.normalMass > 0.0))
                    continue; // as the batches' empty point slots
                setImpactTarget(rows, rows.count, separation(p), useBias, inverseH, soft, settings.maxPushoutSpeed,
                                p.normalMass);
                rows.angularA[rows.count] = kStaticA ? Vec3(0.0) : angularOf(p.rA, c.normal);
                rows.inertiaA[rows.count] = kStaticA ? Vec3(0.0) : inertiaOf(ia, p.rA, c.normal);
                rows.angularB[rows.count] = kStaticB ? Vec3(0.0) : angularOf(p.rB, c.normal);
                rows.inertiaB[rows.count] = kStaticB ? Vec3(0.0) : inertiaOf(ib, p.rB, c.normal);
                rows.velocity[rows.count] = rowVelocityT<kStaticA, kStaticB>(startA, startB, p, c.normal);
                rows.impulse[rows.count] = startImpulse[k];
                if (p.normalImpulse > 0.0) // pushing after the sweep: likely pushing in the answer
                    rows.guess |= 1u << rows.count;
                slot[rows.count++] = k;
            }
            rows.massA = kStaticA ? 0.0 : ia.mass;
            rows.massB = kStaticB ? 0.0 : ib.mass;
            if (rows.count > 1 && solveImpactRows(rows)) {
                // The block's impulses, applied to the state before the sweep.
                a.v = startVA;
                a.w = startWA;
                b.v = startVB;
                b.w = startWB;
                for (int k = 0; k < c.pointCount; ++k) {
                    c.points[k].normalImpulse = startImpulse[k];
                    c.points[k].maxNormalImpulse = startLargest[k];
                }
                for (int r = 0; r < rows.count; ++r) {
                    ContactConstraint::Point& p = c.points[slot[r]];
                    const Real impulse = rows.impulse[r] - p.normalImpulse;
                    p.normalImpulse = rows.impulse[r];
                    if (settings.restitution)
                        p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
                    applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.normal, impulse);
                }
            }
        }
    }

    if (!settings.friction || c.friction <= 0.0)
        return;
    Real total = 0.0, twistLimit = 0.0;
    for (int k = 0; k < c.pointCount; ++k) {
        const ContactConstraint::Point& p = c.points[c.order[k]];
        total = total + p.normalImpulse;
        twistLimit = twistLimit + p.leverArm * p.normalImpulse;
    }
    // Nothing pushes and nothing was held: every clamp below would give zero.
    if (total == 0.0 && c.twistImpulse == 0.0 && c.frictionImpulse[0] == 0.0 && c.frictionImpulse[1] == 0.0)
        return;
    // Twist about the normal.
    {
        const Real spin = glm::dot(c.normal, b.w - a.w);
        const Real limit = c.friction * twistLimit;
        const Real newImpulse = std::clamp(c.twistImpulse - c.twistMass * spin, -limit, limit);
        const Real impulse = newImpulse - c.twistImpulse;
        c.twistImpulse = newImpulse;
        applyTwist<kStaticA, kStaticB>(a, b, ia, ib, c, impulse);
    }
    // Sliding at the friction centre: both tangents at once, clamped to the friction disc.
    const Vec3 vr = (b.v + glm::cross(b.w, c.centerB)) - (a.v + glm::cross(a.w, c.centerA));
    const Real v0 = glm::dot(vr, c.tangent[0]), v1 = glm::dot(vr, c.tangent[1]);
    Real n0 = c.frictionImpulse[0] - (c.frictionMass[0] * v0 + c.frictionMass[1] * v1);
    Real n1 = c.frictionImpulse[1] - (c.frictionMass[1] * v0 + c.frictionMass[2] * v1);
    const Real limit = c.friction * total;
    const Real length2 = n0 * n0 + n1 * n1;
    if (length2 > limit * limit) {
        const Real scale = limit / std::sqrt(length2);
        n0 = n0 * scale;
        n1 = n1 * scale;
    }
    const Real j0 = n0 - c.frictionImpulse[0], j1 = n1 - c.frictionImpulse[1];
    c.frictionImpulse[0] = n0;
    c.frictionImpulse[1] = n1;
    applyFriction<kStaticA, kStaticB>(a, b, ia, ib, c, j0, j1);
}

} // namespace

void ContactSolver::solve(std::span<SolverBody> bodies, bool useBias, Motion motion) {
    solveBatchRange(bodies, useBias, 0, batchCount(), m_separationsKept ? motion : Motion::Moved);
    m_separationsKept = true;
    countSweep();
}

void ContactSolver::solveSequential(std::span<SolverBody> bodies, bool useBias) {
    forEachInSequence([&](size_t i) { solveOne(bodies, m_constraints[i], useBias, m_inverseH); });
    countSweep();
}

void ContactSolver::solveOne(std::span<SolverBody> bodies, ContactConstraint& c, bool useBias, Real inverseH) const {
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    if (c.bodyA == 0)
        solveConstraint<true, false>(c, a, b, useBias, inverseH, m_soft, m_settings);
    else if (c.bodyB == 0)
        solveConstraint<false, true>(c, a, b, useBias, inverseH, m_soft, m_settings);
    else
        solveConstraint<false, false>(c, a, b, useBias, inverseH, m_soft, m_settings);
}

void ContactSolver::absorbBlows(std::span<SolverBody> bodies, const ParallelFor& parallelFor) {
    m_blowBodies.clear();
    if (m_blows.empty())
        return;
    // Rigid rows (no bias, no softness), each speculative one closing its gap within the whole step.
    const Real inverseStep = m_settings.step > 0.0 ? 1.0 / m_settings.step : m_inverseH;
    // From zero impulses: the records were set up with the last step's, for warm starting.
    const auto cold = [](std::vector<ContactConstraint>& records) {
        for (ContactConstraint& c : records) {
            for (int k = 0; k < c.pointCount; ++k)
                c.points[k].normalImpulse = 0.0;
            c.frictionImpulse[0] = c.frictionImpulse[1] = c.twistImpulse = 0.0;
        }
    };
    cold(m_blows);
    cold(m_shocks);
    // The moving bodies of those constraints, each once.
    std::vector<uint32_t>& moved = m_blowBodies;
    for (const ContactConstraint& c : m_blows)
        for (const uint32_t x : {c.bodyA, c.bodyB})
            if (x != 0)
                moved.push_back(x);
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    // The blows fall apart into groups that share no moving body (each struck body and those bearing it up): a team
    // sweeps whole groups apart, each group's constraints in their order, so every body sees the same operations in
    // the same order as in one sweep of them all, and the velocities are the same. (Swept by one thread, the blows
    // of boxes1000's pile, some 60 constraints in 15 groups a step, took 0.06-0.07 ms a step of serial work on two
    // threads, frames 45-120.)
    const bool shared = parallelFor && m_blows.size() >= kMinSharedBlows;
    if (shared)
        shareBlows(bodies.size());
    const auto sweep = [&](std::vector<ContactConstraint>& records, const std::array<std::vector<uint32_t>, 2>& share,
                           int passes) {
        for (const ContactConstraint& c : records)
            m_counters.blowRows += static_cast<uint64_t>(passes) * static_cast<uint64_t>(c.pointCount);
        if (!shared) {
            for (int pass = 0; pass < passes; ++pass)
                for (ContactConstraint& c : records)
                    solveOne(bodies, c, false, inverseStep);
            return;
        }
        shareOut(parallelFor, share.size(), [&](size_t first, size_t last) {
            for (size_t m = first; m < last; ++m)
                for (int pass = 0; pass < passes; ++pass)
                    for (const uint32_t k : share[m])
                        solveOne(bodies, records[k], false, inverseStep);
        });
    };
    // Rigid passes from zero impulses take energy out. A held body that moves into the one it bears (or slides under
    // it) gives energy, as World::contactHold() found, and so may a speculative row: passes that leave these bodies
    // more kinetic energy than they had are undone (the regular ones once over 600 frames of the pile of 1,000 boxes
    // where this was traced, 2026-12-06). Each body's inertia is taken once for the four sums (as kineticEnergy()
    // takes it: the same numbers).
    m_blowInertia.resize(moved.size());
    for (size_t k = 0; k < moved.size(); ++k) {
        const SolverBody& b = bodies[moved[k]];
        m_blowInertia[k] = glm::determinant(b.invInertia) > 0.0 ? glm::inverse(b.invInertia) : Mat3(0.0);
    }
    const auto energy = [&] {
        Real e = 0.0;
        for (size_t k = 0; k < moved.size(); ++k) {
            const SolverBody& b = bodies[moved[k]];
            if (!(b.invMass > 0.0))
                continue;
            Real body = 0.5 * glm::dot(b.v, b.v) / b.invMass;
            if (b.w != Vec3(0.0) && glm::determinant(b.invInertia) > 0.0)
                body += 0.5 * glm::dot(b.w, m_blowInertia[k] * b.w);
            e += body;
        }
        return e;
    };
    std::vector<std::pair<Vec3, Vec3>>& saved = m_blowSaved;
    saved.resize(moved.size());
    const auto keep = [&] {
        for (size_t k = 0; k < moved.size(); ++k)
            saved[k] = {bodies[moved[k]].v, bodies[moved[k]].w};
    };
    const auto restore = [&] {
        for (size_t k = 0; k < moved.size(); ++k) {
            bodies[moved[k]].v = saved[k].first;
            bodies[moved[k]].w = saved[k].second;
        }
    };
    Real before = energy();
    keep();
    sweep(m_blows, m_blowShare, std::max(m_settings.blowPasses, 0));
    Real after = energy();
    if (after > before) {
        restore();
        return;
    }
    before = after;
    keep();
    sweep(m_shocks, m_shockShare, std::max(m_settings.blowShockPasses, 0));
    after = energy();
    if (after > before)
        restore();
    // The restitution pass works chains out from the velocities at the step start: these are the new ones.
    if (m_startVelocity.size() == bodies.size())
        for (const ContactConstraint& c : m_blows)
            for (const uint32_t x : {c.bodyA, c.bodyB})
                m_startVelocity[x] = {bodies[x].v, bodies[x].w};
}

void ContactSolver::shareBlows(size_t bodyCount) {
    // The groups: moving bodies joined by the blows' constraints (union by the lower root).
    std::vector<uint32_t>& root = m_blowRoot;
    root.resize(bodyCount);
    for (const uint32_t x : m_blowBodies)
        root[x] = x;
    const auto find = [&](uint32_t x) { return findRoot(root, x); };
    for (const ContactConstraint& c : m_blows)
        if (c.bodyA != 0 && c.bodyB != 0) {
            const uint32_t a = find(c.bodyA), b = find(c.bodyB);
            if (a != b)
                root[std::max(a, b)] = std::min(a, b);
        }
    const auto groupOf = [&](const ContactConstraint& c) { return find(c.bodyA != 0 ? c.bodyA : c.bodyB); };
    // Each group's constraints, then the groups to the members, largest first (then by root), each to the member
    // with fewer constraints so far.
    std::vector<uint32_t>& weight = m_blowWeight; // per root
    weight.resize(bodyCount);
    for (const uint32_t x : m_blowBodies)
        weight[x] = 0;
    for (const ContactConstraint& c : m_blows)
        ++weight[groupOf(c)];
    std::vector<std::pair<uint32_t, uint32_t>>& groups = m_blowGroups; // (constraints, root)
    groups.clear();
    for (const uint32_t x : m_blowBodies)
        if (find(x) == x)
            groups.emplace_back(weight[x], x);
    std::sort(groups.begin(), groups.end(), [](const auto& p, const auto& q) {
        return p.first != q.first ? p.first > q.first : p.second < q.second;
    });
    size_t load[2] = {0, 0};
    for (const auto& [constraints, x] : groups) {
        const size_t m = load[1] < load[0] ? 1 : 0;
        weight[x] = static_cast<uint32_t>(m); // now the member of the group
        load[m] += constraints;
    }
    for (size_t m = 0; m < 2; ++m) {
        m_blowShare[m].clear();
        m_shockShare[m].clear();
    }
    for (size_t k = 0; k < m_blows.size(); ++k)
        m_blowShare[weight[groupOf(m_blows[k])]].push_back(static_cast<uint32_t>(k));
    for (size_t k = 0; k < m_shocks.size(); ++k)
        m_shockShare[weight[groupOf(m_shocks[k])]].push_back(static_cast<uint32_t>(k));
}

void ContactSolver::countSweep() {
    m_counters.normalRows += m_sweepRows.normalRows;
    m_counters.frictionRows += m_sweepRows.frictionRows;
    m_counters.sweptBatches += m_sweepRows.sweptBatches;
}

namespace {

// The points of c that approached faster than the threshold and pushed back in the sweeps (bit k for point k).
uint8_t struckPoints(const ContactConstraint& c, Real threshold) {
    uint8_t points = 0;
    for (int k = 0; k < c.pointCount; ++k)
        if (!(c.points[k].relativeVelocity > -threshold) && c.points[k].maxNormalImpulse != 0.0)
            points = static_cast<uint8_t>(points | 1u << k);
    return points;
}

// Whether c holds a side still or makes it heavier (ContactConstraint::scaleA, scaleB).
bool holdsASide(const ContactConstraint& c) {
    return c.scaleA != 1.0 || c.scaleB != 1.0;
}

// A chain's collisions one after the other take at most this many blows on one record: with e < 1 each blow passes
// on less than it got and the threshold ends the chain; a row of e = 1 takes one blow a record.
constexpr uint16_t kChainBlowsPerRecord = 16;
constexpr uint32_t kNoRecord = 0xffffffffu;
// Sweeps of the launches of a chain's points, together (alternately forwards and backwards, so that a row's ends
// hear of each other in a sweep or two).
constexpr int kChainPasses = 64;

} // namespace

void ContactSolver::applyRestitution(std::span<SolverBody> bodies, const PoseInverseInertia& poseInverseInertia) {
    if (!m_settings.restitution)
        return;
    m_poseInverseInertia = poseInverseInertia ? &poseInverseInertia : nullptr;
    struct Forget { // the function is the caller's: not kept past this call
        const PoseInverseInertia*& pose;
        ~Forget() { pose = nullptr; }
    } forget{m_poseInverseInertia};
    syncFromBatches();
    // The constraints with records (restitution, and two moving bodies or a fast approach: mayBounce()) and the
    // struck ones among them. A constraint that holds a side (ContactConstraint::scaleA, scaleB) makes a light body
    // heavier or still for the sweeps' sake, which is no mass to work a chain's collisions out with: it bounces by the
    // rule for a manifold alone (with the bodies' own masses, bounceAlone()) and takes no part in chains. (In a chain,
    // a 0.128 kg box held under a falling 463 kg cube hit it from below as an immovable body and threw it up at 6.6
    // m/s, 2026-12-05.)
    thread_local std::vector<uint32_t> records, struck, chained, touches;
    records.clear();
    struck.clear();
    chained.clear();
    for (size_t i = 0; i < m_constraints.size(); ++i) {
        if (!hasRecord(i) || !mayBounce(m_constraints[i])) // the same records whether or not all are kept
            continue;
        const ContactConstraint& c = m_constraints[i];
        if (!holdsASide(c))
            records.push_back(static_cast<uint32_t>(i));
        if (struckPoints(c, m_settings.restitutionThreshold) != 0)
            struck.push_back(static_cast<uint32_t>(i));
    }
    if (struck.empty())
        return;
    // A struck manifold none of whose moving bodies has another record bounces alone; the rest are links of chains.
    touches.assign(bodies.size(), 0);
    for (const uint32_t i : records)
        for (const uint32_t body : {m_constraints[i].bodyA, m_constraints[i].bodyB})
            if (body != 0)
                ++touches[body];
    const bool chains = m_startVelocity.size() == bodies.size(); // the bodies given to prepare()
    for (const uint32_t i : struck) {
        const ContactConstraint& c = m_constraints[i];
        if (chains && !holdsASide(c) &&
            ((c.bodyA != 0 && touches[c.bodyA] > 1) || (c.bodyB != 0 && touches[c.bodyB] > 1)))
            chained.push_back(i);
        else
            bounceAlone(bodies, i);
    }
    if (!chained.empty())
        bounceChains(bodies, records, chained);
}

ContactSolver::Launch ContactSolver::launchOf(std::span<const SolverBody> bodies, uint32_t constraint, uint8_t points,
                                              const Real atSurface[4], bool sweepsFloor) const {
    const ContactConstraint& c = m_constraints[constraint];
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Real offset = m_settings.flightOffset * c.approachAcceleration * m_h;
    Launch l;
    l.constraint = constraint;
    l.points = points;
    Real apart[4] = {0.0, 0.0, 0.0, 0.0};
    bool touched = false; // a point that pushed is touching at the step end
    for (int k = 0; k < c.pointCount; ++k) {
        const ContactConstraint::Point& p = c.points[k];
        const Vec3 d = (b.dp - a.dp) + (b.dR * p.rB - a.dR * p.rA);
        apart[k] = glm::dot(c.normal, d) + p.baseSeparation;
        touched = touched || (p.maxNormalImpulse != 0.0 && !(apart[k] > 0.0));
        if ((points >> k & 1u) != 0)
            l.target[k] = atSurface[k] - offset;
    }
    // A manifold can push back with none of its points touching at the step end: the relax sweep's speculative
    // rows slow what would close the gap in the next substep. Its bounce is launched from where it is, each point
    // with the speed that a bounce off the surface has on its way back up to that separation (energy again, as
    // for the impact in prepare()). Launched at the surface's speed from a few millimetres up, a ball dropped
    // from 1 m reached a second apex 6.6 % above e^4 h0, and one from 1.25 m a third 15 % above e^6 h0
    // (2026-12-05). A point is never launched slower than the sweeps left it: a corner far from the surface then
    // gave back the impulse that kept it off, and ramps.obj's deepest contact in its first 2 s went from 49.6 to
    // 60.1 mm (36.5 mm now). Where a point that pushed touches, the manifold landed within the step and bounces
    // as before.
    for (int k = 0; k < c.pointCount && !touched; ++k) {
        if ((points >> k & 1u) == 0 || atSurface[k] < 0.0)
            continue;
        const Real speed =
            std::sqrt(std::max(atSurface[k] * atSurface[k] + 2.0 * c.approachAcceleration * apart[k], 0.0));
        l.target[k] = sweepsFloor ? std::max(speed - offset, rowVelocity(a, b, c.points[k], c.normal)) : speed - offset;
    }
    return l;
}

void ContactSolver::launch(std::span<SolverBody> bodies, std::span<const Launch> launches, int passes,
                           bool warmStartsNext) {
    // Per point, each row's restitution takes the point's own approach speed: the points of a body that lands
    // turning approach at different speeds, and leaving each at e times its own can take more energy out of the
    // sweeps than came in. A 79 kg cone landing on its rim at 52 rad/s with e = 0.9 left with 945 J more than it
    // brought (2026-12-05). So the launch is bounded by the energy the bodies could have had at impact.
    const bool bounded = m_settings.step > 0.0 && m_startVelocity.size() == bodies.size();
    thread_local std::vector<uint32_t> ids;
    thread_local std::vector<std::pair<Vec3, Vec3>> before;
    thread_local std::vector<std::array<Real, 4>> impulseBefore;
    Real bound = 0.0;
    if (bounded) {
        ids.clear();
        for (const Launch& l : launches)
            for (const uint32_t body : {m_constraints[l.constraint].bodyA, m_constraints[l.constraint].bodyB})
                if (body != 0)
                    ids.push_back(body);
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        before.resize(ids.size());
        for (size_t k = 0; k < ids.size(); ++k) {
            const SolverBody& b = bodies[ids[k]];
            before[k] = {b.v, b.w};
            const auto [v0, w0] = m_startVelocity[ids[k]];
            const Mat3& start = m_startInverseInertia[ids[k]];
            const Real work = b.invMass > 0.0 ? glm::dot(m_settings.gravity, b.dp) / b.invMass : 0.0;
            bound += kineticEnergy(b.invMass, start, v0, w0) + work;
        }
    }
    impulseBefore.resize(launches.size());
    for (size_t l = 0; l < launches.size(); ++l)
        for (size_t k = 0; k < 4; ++k)
            impulseBefore[l][k] = m_constraints[launches[l].constraint].points[k].normalImpulse;
    const auto restoreImpulses = [&] {
        for (size_t l = 0; l < launches.size(); ++l)
            for (size_t k = 0; k < 4; ++k)
                m_constraints[launches[l].constraint].points[k].normalImpulse = impulseBefore[l][k];
    };
    sweepLaunches(bodies, launches, passes);
    if (!bounded) {
        if (!warmStartsNext)
            restoreImpulses();
        return;
    }
    // Kinetic energy along the launch's change d from the velocities before it: E(s) = e0 + e1 s + e2 s^2.
    Real e0 = 0.0, e1 = 0.0, e2 = 0.0;
    for (size_t k = 0; k < ids.size(); ++k) {
        const SolverBody& b = bodies[ids[k]];
        const Mat3 inertia = m_poseInverseInertia ? (*m_poseInverseInertia)(ids[k]) : b.invInertia;
        const auto energy = [&](const Vec3& v, const Vec3& w) { return kineticEnergy(b.invMass, inertia, v, w); };
        const auto [v, w] = before[k];
        e0 += energy(v, w);
        e2 += energy(b.v - v, b.w - w);
        e1 += energy(b.v, b.w) - energy(v, w) - energy(b.v - v, b.w - w);
    }
    if (e0 + e1 + e2 <= bound) {
        if (!warmStartsNext)
            restoreImpulses();
        return;
    }
    Real s = 0.0;
    if (e0 < bound && e2 > 0.0)
        s = std::clamp((-e1 + std::sqrt(std::max(e1 * e1 - 4.0 * e2 * (e0 - bound), 0.0))) / (2.0 * e2), 0.0, 1.0);
    ++m_counters.boundedBounces;
    for (size_t k = 0; k < ids.size(); ++k) {
        SolverBody& b = bodies[ids[k]];
        const auto [v, w] = before[k];
        b.v = v + s * (b.v - v);
        b.w = w + s * (b.w - w);
    }
    if (!warmStartsNext) {
        restoreImpulses();
        return;
    }
    for (size_t l = 0; l < launches.size(); ++l)
        for (size_t k = 0; k < 4; ++k) {
            Real& impulse = m_constraints[launches[l].constraint].points[k].normalImpulse;
            impulse = impulseBefore[l][k] + s * (impulse - impulseBefore[l][k]);
        }
}

void ContactSolver::sweepLaunches(std::span<SolverBody> bodies, std::span<const Launch> launches, int passes) {
    for (int pass = 0; pass < passes; ++pass) {
        Real largest = 0.0, total = 0.0;
        for (size_t n = 0; n < launches.size(); ++n) {
            const Launch& l = launches[pass % 2 == 0 ? n : launches.size() - 1 - n];
            ContactConstraint& c = m_constraints[l.constraint];
            SolverBody& a = bodies[c.bodyA];
            SolverBody& b = bodies[c.bodyB];
            const Inverse ia = inverseOf(a, l.bodiesOwnMasses ? 1.0 : c.scaleA);
            const Inverse ib = inverseOf(b, l.bodiesOwnMasses ? 1.0 : c.scaleB);
            for (int k = 0; k < c.pointCount; ++k) {
                if ((l.points >> k & 1u) == 0)
                    continue;
                ContactConstraint::Point& p = c.points[k];
                const Real vn = rowVelocity(a, b, p, c.normal);
                // (The bodies' own masses: the effective mass unrounded, as setUpConstraint() works it out.)
                const Real perImpulse = l.bodiesOwnMasses ? normalK(ia, ib, p.rA, p.rB, c.normal) : 0.0;
                const Real mass = l.bodiesOwnMasses ? (perImpulse > 0.0 ? 1.0 / perImpulse : 0.0) : p.normalMass;
                Real impulse = -mass * (vn - l.target[k]);
                const Real newImpulse = std::max(p.normalImpulse + impulse, 0.0);
                impulse = newImpulse - p.normalImpulse;
                p.normalImpulse = newImpulse;
                p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
                applyRow(a, b, ia, ib, p, c.normal, impulse);
                ++m_counters.restitutionRows;
                largest = std::max(largest, std::abs(impulse));
                total += newImpulse;
            }
        }
        if (largest <= kRestitutionTolerance * total)
            break;
    }
}

void ContactSolver::bounceAlone(std::span<SolverBody> bodies, uint32_t constraint) {
    // The points of one manifold are coupled through the bodies' rotation: one pass, point after point, leaves the
    // first point's impulse lopsided and spins a box that landed flat (a 0.2 m cube dropped face down on its four
    // corners left at 15 rad/s). So the manifold's bouncing points are swept together until the impulses settle,
    // which for a symmetric landing gives the symmetric answer.
    const ContactConstraint& c = m_constraints[constraint];
    const uint8_t points = struckPoints(c, m_settings.restitutionThreshold);
    Real atSurface[4] = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < c.pointCount; ++k)
        atSurface[k] = -c.restitution * c.points[k].relativeVelocity;
    Launch l = launchOf(bodies, constraint, points, atSurface, true);
    // A held side (ContactConstraint::scaleA, scaleB) is still or heavier for the sweeps' sake: a stack's light body
    // under a heavy one stands for the ground. Bounced off as such, a heavy body took the held body's own motion as
    // the ground's: a 536 kg cylinder falling at 6.9 m/s onto a 3 kg cone spinning at 52 rad/s (its surface rising at
    // 2.8 m/s there) left at 8.9 m/s, and a random scene of bouncing shapes gained 31 % of its energy (2026-12-05).
    // A bounce is a collision, so it takes the bodies' own masses.
    l.bodiesOwnMasses = holdsASide(c);
    launch(bodies, std::span<const Launch>(&l, 1), std::popcount(points) == 1 ? 1 : kRestitutionPasses, true);
}

void ContactSolver::bounceChains(std::span<SolverBody> bodies, std::span<const uint32_t> records,
                                 std::span<const uint32_t> struck) {
    // A chain's collisions are played out one after the other on copies of the bodies at their velocities of the
    // step start (Guendelman, Bridson and Fedkiw 2003, "Nonconvex rigid bodies with stacking", do the same with the
    // positions too): a struck manifold takes its blow (its points leave at -e times their approach speed, swept
    // together as in bounceAlone()), the other records of its bodies are looked at again, and any of their points
    // that now approaches faster than the threshold takes its own blow, and so on. Points that did not push back in
    // the sweeps take none. Each point that took a blow is then launched at the normal speed the collisions left it
    // (a slow approach the threshold let through stays one, for the next step's sweeps), and those launches are swept
    // together from the sweeps' velocities. A ball rolled into a row of touching balls so leaves the ball at the far
    // end moving, the others still; by the rule for a manifold alone the row took the blow as one lump, and five
    // balls with e = 1 kept 48 % of the energy.
    //
    // The blows go through one queue, first in first out, seeded in constraint order: records that share no moving
    // body never meet, so each island's blows come in the same order whichever other islands share this solver (a
    // team's members solve different sets). The launches are swept chain by chain (the records that took blows,
    // joined through their moving bodies) for the same reason. Only the records a blow reaches are looked at: in a
    // bouncing pile of 1,000 boxes, finding every chain's whole extent first took the restitution stage from 4.5 to
    // 43 ms over 240 steps (2026-12-05).
    const size_t n = bodies.size();
    thread_local std::vector<uint32_t> first, adjacent, queue, hitOnce, rattled, owner, root;
    thread_local std::vector<uint8_t> seen, queued, modelled;
    thread_local std::vector<uint16_t> blowsTaken;
    thread_local std::vector<SolverBody> model;
    thread_local std::vector<std::array<Real, 4>> given, shift;
    thread_local std::vector<Launch> launches;
    // Each moving body's records.
    {
        thread_local std::vector<uint32_t> fill;
        listByBody(
            n, records.size(), [&](size_t k) { return records[k]; },
            [&](uint32_t i) {
                return std::array<uint32_t, 2>{m_constraints[i].bodyA, m_constraints[i].bodyB};
            },
            first, adjacent, fill);
    }
    model.resize(n);
    model[0] = bodies[0];
    modelled.assign(n, 0);
    const size_t count = m_constraints.size();
    given.resize(count);
    shift.resize(count);
    seen.assign(count, 0);
    queued.assign(count, 0);
    blowsTaken.assign(count, 0);
    // A record the blows reach: its bodies' copies at their velocities of the step start, and each point's approach
    // speed at impact (prepare()) less its normal speed at the step start, what gravity adds on the way to the
    // surface, kept through the blows.
    const auto reach = [&](uint32_t i) {
        if (seen[i] != 0)
            return;
        seen[i] = 1;
        const ContactConstraint& c = m_constraints[i];
        for (const uint32_t body : {c.bodyA, c.bodyB})
            if (body != 0 && modelled[body] == 0) {
                modelled[body] = 1;
                model[body] = bodies[body];
                model[body].v = m_startVelocity[body].first;
                model[body].w = m_startVelocity[body].second;
            }
        given[i] = {0.0, 0.0, 0.0, 0.0};
        // (From the velocities of the step start, not the copies': a blow may have reached them already.)
        const auto [vA, wA] = c.bodyA != 0 ? m_startVelocity[c.bodyA] : std::pair<Vec3, Vec3>{};
        const auto [vB, wB] = c.bodyB != 0 ? m_startVelocity[c.bodyB] : std::pair<Vec3, Vec3>{};
        for (int k = 0; k < c.pointCount; ++k) {
            const ContactConstraint::Point& p = c.points[k];
            const Real atStart = glm::dot(c.normal, vB - vA) + glm::dot(wB, angularOf(p.rB, c.normal)) -
                                 glm::dot(wA, angularOf(p.rA, c.normal));
            shift[i][static_cast<size_t>(k)] = p.relativeVelocity - atStart;
        }
    };
    queue.assign(struck.begin(), struck.end());
    for (const uint32_t i : struck) {
        reach(i);
        queued[i] = 1;
    }
    hitOnce.clear();
    rattled.clear();
    for (size_t head = 0; head < queue.size(); ++head) {
        const uint32_t i = queue[head];
        queued[i] = 0;
        const ContactConstraint& c = m_constraints[i];
        SolverBody& a = model[c.bodyA];
        SolverBody& b = model[c.bodyB];
        const std::array<Real, 4>& dv = shift[i];
        uint8_t hit = 0;
        Real target[4] = {0.0, 0.0, 0.0, 0.0};
        for (int k = 0; k < c.pointCount; ++k) {
            const ContactConstraint::Point& p = c.points[k];
            const Real vn = rowVelocity(a, b, p, c.normal) + dv[static_cast<size_t>(k)];
            if (p.maxNormalImpulse == 0.0 || vn > -m_settings.restitutionThreshold)
                continue;
            hit = static_cast<uint8_t>(hit | 1u << k);
            target[k] = -c.restitution * vn;
        }
        if (hit == 0)
            continue;
        if (blowsTaken[i] == kChainBlowsPerRecord) {
            rattled.push_back(i); // still struck after as many blows: see below
            continue;
        }
        if (blowsTaken[i]++ == 0)
            hitOnce.push_back(i);
        const Inverse ia = inverseOf(a, 1.0), ib = inverseOf(b, 1.0);
        Real taken[4] = {0.0, 0.0, 0.0, 0.0};
        const int passes = std::popcount(hit) == 1 ? 1 : kRestitutionPasses;
        for (int pass = 0; pass < passes; ++pass) {
            Real largest = 0.0, total = 0.0;
            for (int k = 0; k < c.pointCount; ++k) {
                if ((hit >> k & 1u) == 0)
                    continue;
                const ContactConstraint::Point& p = c.points[k];
                const Real vn = rowVelocity(a, b, p, c.normal) + dv[static_cast<size_t>(k)];
                const Real now = std::max(taken[k] - p.normalMass * (vn - target[k]), 0.0);
                const Real impulse = now - taken[k];
                taken[k] = now;
                applyRow(a, b, ia, ib, p, c.normal, impulse);
                ++m_counters.restitutionRows;
                largest = std::max(largest, std::abs(impulse));
                total += now;
            }
            if (largest <= kRestitutionTolerance * total)
                break;
        }
        for (int k = 0; k < c.pointCount; ++k)
            given[i][static_cast<size_t>(k)] += taken[k];
        for (const uint32_t body : {c.bodyA, c.bodyB})
            if (body != 0)
                for (uint32_t e = first[body]; e < first[body + 1]; ++e)
                    if (const uint32_t j = adjacent[e]; j != i && queued[j] == 0) {
                        reach(j);
                        queued[j] = 1;
                        queue.push_back(j);
                    }
    }
    // The chains: the records that took blows, joined through their moving bodies (union-find on the records, each
    // body remembering the first record that took a blow through it).
    std::sort(hitOnce.begin(), hitOnce.end());
    root.resize(count);
    for (const uint32_t i : hitOnce)
        root[i] = i;
    const auto find = [&](uint32_t i) { return findRoot(root, i); };
    owner.assign(n, kNoRecord);
    for (const uint32_t i : hitOnce)
        for (const uint32_t body : {m_constraints[i].bodyA, m_constraints[i].bodyB}) {
            if (body == 0)
                continue;
            if (owner[body] == kNoRecord) {
                owner[body] = i;
                continue;
            }
            const uint32_t x = find(i), y = find(owner[body]);
            root[std::max(x, y)] = std::min(x, y); // the chain's root is its first record
        }
    // A chain still struck after kChainBlowsPerRecord blows on one record (a light body rattling between two heavy
    // ones, whose end the blows would take long to reach) bounces by the rule for a manifold alone, struck record by
    // struck record.
    for (const uint32_t i : rattled)
        seen[find(i)] = 2;
    for (const uint32_t i : hitOnce)
        if (seen[find(i)] == 2 && struckPoints(m_constraints[i], m_settings.restitutionThreshold) != 0)
            bounceAlone(bodies, i);
    // The others are launched chain by chain, in the order of their first records (a chain's root), each chain's
    // records in constraint order: the records sorted by (root, record) are the chains one after the other.
    thread_local std::vector<std::pair<uint32_t, uint32_t>> byChain;
    byChain.clear();
    for (const uint32_t i : hitOnce)
        if (const uint32_t chainRoot = find(i); seen[chainRoot] != 2)
            byChain.emplace_back(chainRoot, i);
    std::sort(byChain.begin(), byChain.end());
    for (size_t k = 0; k < byChain.size();) {
        const uint32_t chainRoot = byChain[k].first;
        launches.clear();
        for (; k < byChain.size() && byChain[k].first == chainRoot; ++k) {
            const uint32_t i = byChain[k].second;
            const ContactConstraint& c = m_constraints[i];
            uint8_t points = 0;
            Real atSurface[4] = {0.0, 0.0, 0.0, 0.0};
            for (int p = 0; p < c.pointCount; ++p) {
                if (!(given[i][static_cast<size_t>(p)] > 0.0))
                    continue;
                points = static_cast<uint8_t>(points | 1u << p);
                atSurface[p] = rowVelocity(model[c.bodyA], model[c.bodyB], c.points[p], c.normal) +
                               shift[i][static_cast<size_t>(p)];
            }
            if (points != 0)
                launches.push_back(launchOf(bodies, i, points, atSurface, false));
        }
        // The launches' impulses are not kept for the next step's warm start, only the sweeps': a row of touching
        // balls stays touching, and warm started with the blow it passed on it pushed itself apart again (five balls
        // with e = 1 ended with 15 % more energy than the first ball brought).
        launch(bodies, launches, kChainPasses, false);
    }
}

void ContactSolver::storeImpulses(std::span<Manifold* const> manifolds, const ParallelFor& parallelFor) const {
    const size_t count = std::min(manifolds.size(), m_count);
    // The batches hold the impulses after any sweep, and also right after prepare() (as the constraints do). After
    // the restitution pass the records are ahead: all of them where kept, else those of the constraints that may
    // bounce, the others' being still in the batches.
    if (m_batchesAhead || !m_kept) {
        const bool bouncersFromRecords = !m_batchesAhead && m_bounceOnly;
        if (m_width == 8)
            storeFromBatches(m_store8, manifolds.first(count), parallelFor, bouncersFromRecords);
        else
            storeFromBatches(m_store4, manifolds.first(count), parallelFor, bouncersFromRecords);
        return;
    }
    shareOut(parallelFor, count, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i)
            storeRecord(m_constraints[i], *manifolds[i]);
    });
}

void ContactSolver::storeRecord(const ContactConstraint& c, Manifold& m) {
    for (int k = 0; k < c.pointCount; ++k)
        m.points[k].normalImpulse = c.points[k].normalImpulse;
    m.frictionImpulse = c.frictionImpulse[0] * c.tangent[0] + c.frictionImpulse[1] * c.tangent[1];
    m.twistImpulse = c.twistImpulse;
}

template <int W>
void ContactSolver::storeFromBatches(const BatchStore<W>& store, std::span<Manifold* const> manifolds,
                                     const ParallelFor& parallelFor, bool bouncersFromRecords) const {
    // The same numbers as syncFromBatches() and then the loop above, but straight from the batches, in manifold
    // order: the member that writes a manifold here is the one that reads it in the next step's prepare(), so its
    // cache lines need not cross to the other core. (Written by one thread after syncing, the manifolds were read
    // half by the other core, whose half of the set-up then took twice as long as the writer's half.)
    shareOut(parallelFor, manifolds.size(), [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            if (bouncersFromRecords && m_bouncing[i] != 0) {
                storeRecord(m_constraints[i], *manifolds[i]);
                continue;
            }
            const Batch<W>& batch = store.batches[m_laneOf[i] / W];
            const uint32_t lane = m_laneOf[i] % W;
            Manifold& m = *manifolds[i];
            for (int k = 0; k < m.pointCount; ++k)
                m.points[m_order[i][static_cast<size_t>(k)]].normalImpulse =
                    store.points[batch.firstPoint + static_cast<uint32_t>(k)].impulse.v[lane];
            const auto tangent = [&](int t) {
                return Vec3(batch.tangent[t][0].v[lane], batch.tangent[t][1].v[lane], batch.tangent[t][2].v[lane]);
            };
            m.frictionImpulse =
                batch.frictionImpulse[0].v[lane] * tangent(0) + batch.frictionImpulse[1].v[lane] * tangent(1);
            m.twistImpulse = batch.twistImpulse.v[lane];
        }
    });
}

size_t ContactSolver::isotropicBatchCount() const {
    const auto count = [](const auto& batches) {
        return static_cast<size_t>(
            std::count_if(batches.begin(), batches.end(), [](const auto& batch) { return batch.isotropic; }));
    };
    return m_width == 8 ? count(m_store8.batches) : count(m_store4.batches);
}

} // namespace rl
