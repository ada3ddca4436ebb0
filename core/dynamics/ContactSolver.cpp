#include "dynamics/ContactSolver.h"

#include <algorithm>
#include <cmath>
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

// Restitution sweeps over one manifold's bouncing points: at most this many, fewer once the largest impulse change
// of a sweep is below the tolerance times the manifold's total impulse.
constexpr int kRestitutionPasses = 32;
constexpr Real kRestitutionTolerance = 1e-4;

Vec3 relativeVelocity(const SolverBody& a, const SolverBody& b, const Vec3& rA, const Vec3& rB) {
    return (b.v + glm::cross(b.w, rB)) - (a.v + glm::cross(a.w, rA));
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

// One manifold's constraint, for one step (see prepare()).
void setUpConstraint(ContactConstraint& c, const Manifold& m, uint32_t indexA, uint32_t indexB, Real friction,
                     Real restitution, uint8_t held, std::span<const SolverBody> bodies, std::span<const Vec3> centers,
                     const ContactSolverSettings& settings) {
    c.bodyA = indexA;
    c.bodyB = indexB;
    c.scaleA = held == ContactSolver::kHoldA ? 0.0 : 1.0;
    c.scaleB = held == ContactSolver::kHoldB ? 0.0 : 1.0;
    c.normal = m.normal;
    tangentBasis(m.normal, c.tangent[0], c.tangent[1]);
    c.friction = friction;
    c.restitution = restitution;
    c.pointCount = m.pointCount;
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    // Gravity acts on the bodies that can move (not on anchors and sleepers, entries with no inverse mass).
    const Vec3 gA = a.invMass > 0.0 ? settings.gravity : Vec3(0.0);
    const Vec3 gB = b.invMass > 0.0 ? settings.gravity : Vec3(0.0);
    c.approachAcceleration = glm::dot(c.normal, gB - gA);
    bool impact = false;
    for (int k = 0; k < m.pointCount; ++k) {
        const ContactPoint& mp = m.points[k];
        ContactConstraint::Point& p = c.points[k];
        // Both anchors sit at the world midpoint of the witness points, in world axes at the step start.
        p.rA = mp.position - centers[c.bodyA];
        p.rB = mp.position - centers[c.bodyB];
        // The separation and the masses are rounded to float, as the batches store them (see BatchPoint).
        p.baseSeparation = static_cast<float>(mp.separation - glm::dot(p.rB - p.rA, c.normal));
        const Vec3* directions[3] = {&c.normal, &c.tangent[0], &c.tangent[1]};
        Real masses[3];
        for (int row = 0; row < 3; ++row) {
            const Vec3 angularA = angularOf(p.rA, *directions[row]), angularB = angularOf(p.rB, *directions[row]);
            const Vec3 inertiaA = ia.inertia * angularA, inertiaB = ib.inertia * angularB;
            const Real k = ia.mass + ib.mass + glm::dot(angularA, inertiaA) + glm::dot(angularB, inertiaB);
            masses[row] = k > 0.0 ? static_cast<float>(1.0 / k) : 0.0;
        }
        p.normalMass = masses[0];
        p.tangentMass[0] = masses[1];
        p.tangentMass[1] = masses[2];
        p.normalImpulse = settings.warmStarting ? mp.normalImpulse : 0.0;

        p.tangentImpulse[0] = settings.warmStarting ? mp.tangentImpulse[0] : 0.0;
        p.tangentImpulse[1] = settings.warmStarting ? mp.tangentImpulse[1] : 0.0;
        p.maxNormalImpulse = 0.0;
        p.relativeVelocity = glm::dot(c.normal, relativeVelocity(a, b, p.rA, p.rB));
        impact = impact || p.relativeVelocity < -settings.restitutionThreshold;
    }
    // An impact is solved deepest point first: a speculative point that is still apart must not push before the
    // point that touches first has taken the blow. A UV sphere landing on its pole, solved in manifold order,
    // let a ring vertex 1.9 mm up push first and bounced off spinning at 5.8 rad/s. Resting contacts keep the
    // manifold's order: reordering them by sub-millimetre differences from step to step kept a pile of 1,000
    // boxes creeping.
    for (int k = 0; k < 4; ++k)
        c.order[k] = static_cast<uint8_t>(k);
    if (impact)
        std::stable_sort(c.order, c.order + m.pointCount,
                         [&](uint8_t l, uint8_t r) { return m.points[l].separation < m.points[r].separation; });
}

} // namespace

Softness softness(Real omega, Real zeta, Real h) {
    // Soft constraint as an implicit-Euler damped spring (Catto, "Solver2D", 2024): with a1 = 2 zeta + h omega,
    // the bias rate is omega / a1, and the mass and impulse scales blend the rigid answer with the spring's.
    const Real a1 = 2.0 * zeta + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void ContactSolver::prepare(std::span<const Manifold> manifolds, std::span<const uint32_t> solverIndexA,
                            std::span<const uint32_t> solverIndexB, std::span<const Real> friction,
                            std::span<const Real> restitution, std::span<const SolverBody> bodies,
                            std::span<const Vec3> centers, Real h, const ContactSolverSettings& settings,
                            std::span<const uint8_t> bodyPart, const ParallelFor& parallelFor,
                            std::span<const uint8_t> heldSide) {
    m_settings = settings;
    m_inverseH = h > 0.0 ? 1.0 / h : 0.0;
    m_h = h;
    m_elapsed = 0.0;
    m_soft = softness(2.0 * kPi * settings.contactHertz, settings.dampingRatio, h);

    m_constraints.resize(manifolds.size());
    const auto setUp = [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i)
            setUpConstraint(m_constraints[i], manifolds[i], solverIndexA[i], solverIndexB[i], friction[i],
                            restitution[i], heldSide.empty() ? uint8_t(0) : heldSide[i], bodies, centers, settings);
    };
    if (parallelFor)
        parallelFor(manifolds.size(), setUp);
    else
        setUp(0, manifolds.size());
    scheduleLevels(bodies.size(), bodyPart);
    buildBatches();
    m_sweepRows = {};
    for (const ContactConstraint& c : m_constraints) {
        m_sweepRows.normalRows += static_cast<uint64_t>(c.pointCount);
        if (settings.friction && c.friction > 0.0)
            m_sweepRows.frictionRows += 2u * static_cast<uint64_t>(c.pointCount);
    }
}

void ContactSolver::scheduleLevels(size_t bodyCount, std::span<const uint8_t> bodyPart) {
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
    m_segment.resize(m_constraints.size());
    for (size_t i = 0; i < m_constraints.size(); ++i) {
        const ContactConstraint& c = m_constraints[i];
        if (bodyPart.empty())
            m_segment[i] = 0;
        else if (c.bodyA == 0 || c.bodyB == 0)
            m_segment[i] = bodyPart[c.bodyA == 0 ? c.bodyB : c.bodyA];
        else
            m_segment[i] = bodyPart[c.bodyA] == bodyPart[c.bodyB] ? bodyPart[c.bodyA] : kBoundarySegment;
    }
    thread_local std::vector<uint32_t> nextLevel, levelOf;
    nextLevel.assign(bodyCount, 0);
    levelOf.resize(m_constraints.size());
    uint32_t levels = 0;
    const size_t segments = bodyPart.empty() ? 1 : kParts + 1;
    for (size_t segment = 0; segment < segments; ++segment) {
        m_segmentLevelStart[segment] = levels;
        const uint32_t first = levels;
        for (size_t i = 0; i < m_constraints.size(); ++i) {
            if (m_segment[i] != segment)
                continue;
            const ContactConstraint& c = m_constraints[i];
            const uint32_t level =
                std::max({first, c.bodyA != 0 ? nextLevel[c.bodyA] : 0u, c.bodyB != 0 ? nextLevel[c.bodyB] : 0u});
            if (c.bodyA != 0)
                nextLevel[c.bodyA] = level + 1;
            if (c.bodyB != 0)
                nextLevel[c.bodyB] = level + 1;
            levelOf[i] = level;
            levels = std::max(levels, level + 1);
        }
    }
    for (size_t segment = segments; segment < kParts + 2; ++segment)
        m_segmentLevelStart[segment] = levels;
    m_levelStart.assign(static_cast<size_t>(levels) + 1, 0);
    for (uint32_t level : levelOf)
        ++m_levelStart[static_cast<size_t>(level) + 1];
    for (uint32_t k = 0; k < levels; ++k)
        m_levelStart[k + 1] += m_levelStart[k];
    thread_local std::vector<uint32_t> fill;
    fill.assign(m_levelStart.begin(), m_levelStart.end() - 1);
    m_solveOrder.resize(m_constraints.size());
    for (size_t i = 0; i < m_constraints.size(); ++i)
        m_solveOrder[fill[levelOf[i]]++] = static_cast<uint32_t>(i);
}

void ContactSolver::buildBatches() {
    m_batches.clear();
    m_batchPoints.clear();
    m_batchesAhead = false;
    const size_t levels = levelCount();
    m_batchLevelStart.assign(levels + 1, 0);
    auto set = [](auto* lanes, const Vec3& v, int lane) {
        for (int axis = 0; axis < 3; ++axis)
            lanes[axis].v[lane] = static_cast<std::remove_reference_t<decltype(lanes[axis].v[0])>>(v[axis]);
    };
    // Within a level the order is free (its constraints share no moving body), so constraints are grouped there by
    // their point count, and pushing ones apart from those that did not push in the last step: the lanes of a batch
    // then have work of the same size, and a point slot in which no lane pushes skips its friction rows and warm
    // start, as the scalar sweep skips such points.
    // The keys are worked out once per constraint, not in every comparison of the sort.
    thread_local std::vector<uint8_t> key;
    key.resize(m_constraints.size());
    for (size_t i = 0; i < m_constraints.size(); ++i) {
        const ContactConstraint& c = m_constraints[i];
        bool pushing = false;
        for (int k = 0; k < c.pointCount; ++k)
            pushing = pushing || c.points[k].normalImpulse != 0.0;
        key[i] = static_cast<uint8_t>((pushing ? 0 : 8) + (4 - c.pointCount));
    }
    for (size_t level = 0; level < levels; ++level)
        std::stable_sort(m_solveOrder.begin() + levelBegin(level), m_solveOrder.begin() + levelEnd(level),
                         [&](uint32_t l, uint32_t r) { return key[l] < key[r]; });
    for (size_t level = 0; level < levels; ++level) {
        m_batchLevelStart[level] = static_cast<uint32_t>(m_batches.size());
        for (size_t first = levelBegin(level); first < levelEnd(level); first += 4) {
            const size_t lanes = std::min<size_t>(4, levelEnd(level) - first);
            Batch& batch = m_batches.emplace_back();
            batch.firstPoint = static_cast<uint32_t>(m_batchPoints.size());
            for (size_t l = 0; l < lanes; ++l)
                batch.pointCount = std::max<uint32_t>(
                    batch.pointCount, static_cast<uint32_t>(m_constraints[m_solveOrder[first + l]].pointCount));
            m_batchPoints.resize(m_batchPoints.size() + batch.pointCount);
            for (size_t l = 0; l < lanes; ++l) {
                const int lane = static_cast<int>(l);
                const uint32_t index = m_solveOrder[first + l];
                const ContactConstraint& c = m_constraints[index];
                batch.bodyA[l] = c.bodyA;
                batch.bodyB[l] = c.bodyB;
                batch.constraint[l] = index;
                set(batch.normal, c.normal, lane);
                set(batch.tangent[0], c.tangent[0], lane);
                set(batch.tangent[1], c.tangent[1], lane);
                batch.friction.v[l] = c.friction;
                batch.approachAcceleration.v[l] = c.approachAcceleration;
                batch.scaleA.v[l] = c.scaleA;
                batch.scaleB.v[l] = c.scaleB;
                batch.holds = batch.holds || c.scaleA != 1.0 || c.scaleB != 1.0;
                for (int k = 0; k < c.pointCount; ++k) {
                    const ContactConstraint::Point& p = c.points[c.order[k]];
                    BatchPoint& q = m_batchPoints[batch.firstPoint + static_cast<uint32_t>(k)];
                    set(q.rA, p.rA, lane);
                    set(q.rB, p.rB, lane);
                    q.baseSeparation.v[l] = static_cast<float>(p.baseSeparation);
                    q.mass[0].v[l] = static_cast<float>(p.normalMass);
                    q.mass[1].v[l] = static_cast<float>(p.tangentMass[0]);
                    q.mass[2].v[l] = static_cast<float>(p.tangentMass[1]);
                    q.impulse[0].v[l] = p.normalImpulse;
                    q.impulse[1].v[l] = p.tangentImpulse[0];
                    q.impulse[2].v[l] = p.tangentImpulse[1];
                    q.maxNormalImpulse.v[l] = p.maxNormalImpulse;
                    q.relativeVelocity.v[l] = p.relativeVelocity;
                }
            }
        }
    }
    m_batchLevelStart[levels] = static_cast<uint32_t>(m_batches.size());
}

void ContactSolver::syncFromBatches() const {
    if (!m_batchesAhead)
        return;
    m_batchesAhead = false;
    for (const Batch& batch : m_batches)
        for (int l = 0; l < 4; ++l) {
            if (batch.constraint[l] == kNoConstraint)
                continue;
            ContactConstraint& c = m_constraints[batch.constraint[l]];
            for (int k = 0; k < c.pointCount; ++k) {
                const BatchPoint& q = m_batchPoints[batch.firstPoint + static_cast<uint32_t>(k)];
                ContactConstraint::Point& p = c.points[c.order[k]];
                p.normalImpulse = q.impulse[0].v[l];
                p.tangentImpulse[0] = q.impulse[1].v[l];
                p.tangentImpulse[1] = q.impulse[2].v[l];
                p.maxNormalImpulse = q.maxNormalImpulse.v[l];
                p.relativeVelocity = q.relativeVelocity.v[l];
            }
        }
}

void ContactSolver::warmStart(std::span<SolverBody> bodies) {
    beginSubstep();
    if (m_settings.warmStarting)
        warmStartBatchRange(bodies, 0, m_batches.size());
}

void ContactSolver::warmStartSequential(std::span<SolverBody> bodies) {
    m_elapsed += m_h;
    if (!m_settings.warmStarting)
        return;
    for (size_t segment = 0; segment <= kBoundarySegment; ++segment)
        for (size_t i = 0; i < m_constraints.size(); ++i)
            if (m_segment[i] == segment)
                warmStartOne(bodies, m_constraints[i]);
}

namespace {

template <bool kStaticA, bool kStaticB>
void warmStartConstraint(const ContactConstraint& c, SolverBody& a, SolverBody& b) {
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    for (int k = 0; k < c.pointCount; ++k) {
        const ContactConstraint::Point& p = c.points[c.order[k]]; // the batches' order
        if (p.normalImpulse == 0.0 && p.tangentImpulse[0] == 0.0 && p.tangentImpulse[1] == 0.0)
            continue; // a speculative point that never pushed: nothing to apply
        applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.normal, p.normalImpulse);
        applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.tangent[0], p.tangentImpulse[0]);
        applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.tangent[1], p.tangentImpulse[1]);
    }
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
void solveConstraint(ContactConstraint& c, SolverBody& a, SolverBody& b, bool useBias, Real inverseH, Real elapsed,
                     const Softness& soft, const ContactSolverSettings& settings) {
    const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
    for (int j = 0; j < c.pointCount; ++j) {
        ContactConstraint::Point& p = c.points[c.order[j]];
        // Current separation from the motion since the step began; anchors follow each body's rotation.
        Vec3 d;
        if constexpr (kStaticA)
            d = b.dp + (b.dR * p.rB - p.rA);
        else if constexpr (kStaticB)
            d = -a.dp + (p.rB - a.dR * p.rA);
        else
            d = (b.dp - a.dp) + (b.dR * p.rB - a.dR * p.rA);
        const Real s = glm::dot(c.normal, d) + p.baseSeparation;

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
        Real impulse = -p.normalMass * massScale * (vn + velocityBias) - impulseScale * p.normalImpulse;
        const Real newImpulse = std::max(p.normalImpulse + impulse, 0.0);
        impulse = newImpulse - p.normalImpulse;
        p.normalImpulse = newImpulse;
        // Restitution bounces off the speed at the moment of impact, which for a speculative contact comes
        // substeps after prepare() looked: gravity has added to it since. The solver's own vn is no measure of it:
        // the impulses of the manifold's other points, already applied in this sweep, tilt it (a cube landing
        // flat recorded 9.8 m/s at one corner and 12.6 m/s at another, and bounced off spinning).
        if (impulse > 0.0 && p.maxNormalImpulse == 0.0)
            p.relativeVelocity += c.approachAcceleration * elapsed;
        p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
        applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.normal, impulse);
    }

    if (!settings.friction || c.friction <= 0.0)
        return;
    for (int k = 0; k < c.pointCount; ++k) {
        ContactConstraint::Point& p = c.points[c.order[k]]; // the normal rows' order, as the batches
        // No normal impulse and no friction impulse (a speculative point): the clamp would give zero.
        if (p.normalImpulse == 0.0 && p.tangentImpulse[0] == 0.0 && p.tangentImpulse[1] == 0.0)
            continue;
        const Real maxFriction = c.friction * p.normalImpulse;
        for (int t = 0; t < 2; ++t) {
            const Real vt = rowVelocityT<kStaticA, kStaticB>(a, b, p, c.tangent[t]);
            Real impulse = -p.tangentMass[t] * vt;
            const Real newImpulse = std::clamp(p.tangentImpulse[t] + impulse, -maxFriction, maxFriction);
            impulse = newImpulse - p.tangentImpulse[t];
            p.tangentImpulse[t] = newImpulse;
            applyRowT<kStaticA, kStaticB>(a, b, ia, ib, p, c.tangent[t], impulse);
        }
    }
}

} // namespace

void ContactSolver::solve(std::span<SolverBody> bodies, bool useBias) {
    solveBatchRange(bodies, useBias, 0, m_batches.size());
    countSweep();
}

void ContactSolver::solveSequential(std::span<SolverBody> bodies, bool useBias) {
    for (size_t segment = 0; segment <= kBoundarySegment; ++segment)
        for (size_t i = 0; i < m_constraints.size(); ++i)
            if (m_segment[i] == segment)
                solveOne(bodies, m_constraints[i], useBias);
    countSweep();
}

void ContactSolver::solveOne(std::span<SolverBody> bodies, ContactConstraint& c, bool useBias) {
    SolverBody& a = bodies[c.bodyA];
    SolverBody& b = bodies[c.bodyB];
    if (c.bodyA == 0)
        solveConstraint<true, false>(c, a, b, useBias, m_inverseH, m_elapsed, m_soft, m_settings);
    else if (c.bodyB == 0)
        solveConstraint<false, true>(c, a, b, useBias, m_inverseH, m_elapsed, m_soft, m_settings);
    else
        solveConstraint<false, false>(c, a, b, useBias, m_inverseH, m_elapsed, m_soft, m_settings);
}

void ContactSolver::countSweep() {
    m_counters.normalRows += m_sweepRows.normalRows;
    m_counters.frictionRows += m_sweepRows.frictionRows;
}

void ContactSolver::applyRestitution(std::span<SolverBody> bodies) {
    if (!m_settings.restitution)
        return;
    syncFromBatches();
    const Real h = m_h;
    for (ContactConstraint& c : m_constraints) {
        if (c.restitution == 0.0)
            continue;
        SolverBody& a = bodies[c.bodyA];
        SolverBody& b = bodies[c.bodyB];
        const Inverse ia = inverseOf(a, c.scaleA), ib = inverseOf(b, c.scaleB);
        // The points of one manifold are coupled through the bodies' rotation: one pass, point after point, leaves
        // the first point's impulse lopsided and spins a box that landed flat (a 0.2 m cube dropped face down on
        // its four corners left at 15 rad/s). So the manifold's bouncing points are iterated together until the
        // impulses settle, which for a symmetric landing gives the symmetric answer.
        bool bouncing[4] = {false, false, false, false};
        Real target[4] = {0.0, 0.0, 0.0, 0.0};
        int count = 0;
        for (int k = 0; k < c.pointCount; ++k) {
            const ContactConstraint::Point& p = c.points[k];
            // Only points that approached fast and actually pushed back bounce.
            if (p.relativeVelocity > -m_settings.restitutionThreshold || p.maxNormalImpulse == 0.0)
                continue;
            bouncing[k] = true;
            target[k] = -c.restitution * p.relativeVelocity - (1.0 + c.restitution) * 0.5 * h * c.approachAcceleration;
            ++count;
        }
        const int passes = count == 1 ? 1 : kRestitutionPasses;
        for (int pass = 0; count > 0 && pass < passes; ++pass) {
            Real largest = 0.0, total = 0.0;
            for (int k = 0; k < c.pointCount; ++k) {
                if (!bouncing[k])
                    continue;
                ContactConstraint::Point& p = c.points[k];
                const Real vn = rowVelocity(a, b, p, c.normal);
                Real impulse = -p.normalMass * (vn - target[k]);
                const Real newImpulse = std::max(p.normalImpulse + impulse, 0.0);
                impulse = newImpulse - p.normalImpulse;
                p.normalImpulse = newImpulse;
                p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
                applyRow(a, b, ia, ib, p, c.normal, impulse);
                ++m_counters.restitutionRows;
                largest = std::max(largest, std::abs(impulse));
                total += newImpulse;
            }
            if (largest <= kRestitutionTolerance * total)
                break;
        }
    }
}

void ContactSolver::storeImpulses(std::span<Manifold> manifolds) const {
    syncFromBatches();
    for (size_t i = 0; i < manifolds.size() && i < m_constraints.size(); ++i) {
        const ContactConstraint& c = m_constraints[i];
        for (int k = 0; k < c.pointCount; ++k) {
            manifolds[i].points[k].normalImpulse = c.points[k].normalImpulse;
            manifolds[i].points[k].tangentImpulse[0] = c.points[k].tangentImpulse[0];
            manifolds[i].points[k].tangentImpulse[1] = c.points[k].tangentImpulse[1];
        }
    }
}

} // namespace rl
