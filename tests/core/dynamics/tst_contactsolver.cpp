// The contact solver's level schedule: constraints of one level share no moving body, and constraints that share one
// keep their manifold order, so that solving level by level, on one thread or on several, does what the sequential
// sweep does; with parts, the same holds for the order part 0, part 1, boundary. Solving on a team of two gives
// bit-identical velocities.
#include "dynamics/ContactSolver.h"
#include "world/ThreadTeam.h"

#include <QScopeGuard>
#include <QTest>

#include <algorithm>
#include <bit>
#include <cstring>
#include <random>

using namespace rl;

namespace {

struct Problem {
    std::vector<Manifold> manifolds;
    std::vector<uint32_t> indexA, indexB;
    std::vector<Real> friction, restitution;
    std::vector<SolverBody> bodies;
    std::vector<Vec3> centers;
    std::vector<ContactSolver::Hold> held; // empty, or one per manifold
};

// Of every four constraints between two moving bodies, the second holds its A side still, the third its B side, and
// the fourth makes its A side four times heavier.
void holdSome(Problem& p) {
    p.held.assign(p.manifolds.size(), ContactSolver::Hold{});
    for (size_t k = 0; k < p.manifolds.size(); ++k) {
        if (p.indexA[k] == 0 || p.indexB[k] == 0)
            continue;
        if (k % 4 == 1)
            p.held[k] = {ContactSolver::kHoldA, 0.0};
        else if (k % 4 == 2)
            p.held[k] = {ContactSolver::kHoldB, 0.0};
        else if (k % 4 == 3)
            p.held[k] = {ContactSolver::kHoldA, 0.25};
    }
}

// Body 1 (1 kg, at rest) under body 2 (1,000 kg, falling onto it at 3 m/s), touching on a square of four points; the
// light body is side A (holdA) or B of the manifold and is held with `scale` (ContactSolver::Hold).
Problem heavyOnLight(bool holdA, Real scale) {
    Problem p;
    p.bodies.assign(3, SolverBody{});
    p.centers = {Vec3(0.0), Vec3(0.0, 0.5, 0.0), Vec3(0.0, 1.5, 0.0)};
    for (size_t i = 1; i < 3; ++i) {
        p.bodies[i].invMass = i == 1 ? 1.0 : 1e-3; // 1 kg under 1,000 kg
        p.bodies[i].invInertia = Mat3(6.0 * p.bodies[i].invMass);
    }
    p.bodies[2].v = Vec3(0.0, -3.0, 0.0);
    Manifold m;
    m.bodyA = holdA ? 1 : 2;
    m.bodyB = holdA ? 2 : 1;
    m.normal = Vec3(0.0, holdA ? 1.0 : -1.0, 0.0); // from A to B
    m.pointCount = 4;
    for (int k = 0; k < 4; ++k) {
        m.points[k].position = Vec3(k % 2 ? 0.5 : -0.5, 1.0, k / 2 ? 0.5 : -0.5);
        m.points[k].separation = 0.0;
    }
    p.manifolds = {m};
    p.indexA = {m.bodyA};
    p.indexB = {m.bodyB};
    p.friction = {0.6};
    p.restitution = {0.0};
    p.held = {{holdA ? ContactSolver::kHoldA : ContactSolver::kHoldB, scale}};
    return p;
}

// `count` one-point contacts between random bodies 1..bodyCount, some against the static entry 0; or a chain
// 0-1, 1-2, 2-3, ... (a tower) when chain is set.
Problem makeProblem(int bodyCount, int count, bool chain, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, bodyCount);
    std::uniform_real_distribution<Real> u(-0.5, 0.5);
    Problem p;
    p.bodies.assign(static_cast<size_t>(bodyCount) + 1, SolverBody{});
    p.centers.assign(static_cast<size_t>(bodyCount) + 1, Vec3(0.0));
    for (int i = 1; i <= bodyCount; ++i) {
        SolverBody& b = p.bodies[static_cast<size_t>(i)];
        b.invMass = 1.0 / (1.0 + 0.1 * i);
        // A box's inverse inertia, turned, so that both sweeps multiply by a full matrix in the same order.
        const Mat3 turn = glm::mat3_cast(glm::angleAxis(0.3 * i, glm::normalize(Vec3(1.0, 2.0, 3.0))));
        const Mat3 principal(Vec3(6.0, 0.0, 0.0), Vec3(0.0, 4.0, 0.0), Vec3(0.0, 0.0, 9.0));
        b.invInertia = b.invMass * (turn * principal * glm::transpose(turn));
        b.v = Vec3(u(rng), u(rng) - 1.0, u(rng));
        b.w = Vec3(u(rng), u(rng), u(rng));
        p.centers[static_cast<size_t>(i)] = Vec3(u(rng), static_cast<Real>(i), u(rng));
    }
    for (int k = 0; k < count; ++k) {
        uint32_t a = chain ? static_cast<uint32_t>(k) : static_cast<uint32_t>(pick(rng));
        uint32_t b = chain ? static_cast<uint32_t>(k + 1) : static_cast<uint32_t>(pick(rng));
        if (a == b)
            b = (b + 1) % static_cast<uint32_t>(bodyCount + 1);
        if (a > b)
            std::swap(a, b);
        Manifold m;
        m.bodyA = a;
        m.bodyB = b;
        m.normal = glm::normalize(Vec3(u(rng), 1.0, u(rng)));
        m.pointCount = 1 + k % 4;
        for (int i = 0; i < m.pointCount; ++i) {
            m.points[i].position = 0.5 * (p.centers[a] + p.centers[b]) + Vec3(u(rng), 0.0, u(rng));
            m.points[i].separation = 0.01 * u(rng);
            m.points[i].normalImpulse = k % 3 == 0 ? 0.5 : 0.0;
        }
        if (k % 3 == 0) { // warm started: friction and twist carried from a last step
            m.frictionImpulse = Vec3(0.2 * u(rng), 0.0, 0.2 * u(rng));
            m.twistImpulse = 0.05 * u(rng);
        }
        p.manifolds.push_back(m);
        p.indexA.push_back(a);
        p.indexB.push_back(b);
        p.friction.push_back(0.6);
        p.restitution.push_back(0.0);
    }
    return p;
}

void prepare(ContactSolver& solver, const Problem& p, std::span<const uint8_t> parts = {}, bool restitution = true,
             const ContactSolver::ParallelFor& parallelFor = {}, const Vec3& gravity = Vec3(0.0),
             const ContactSolver::PackParts& packParts = {}) {
    ContactSolverSettings settings;
    settings.contactHertz = 120.0;
    settings.restitution = restitution;
    settings.gravity = gravity;
    // prepare() reads the manifolds and keeps nothing of them (only storeImpulses(), not called here, writes).
    std::vector<Manifold*> manifolds;
    for (const Manifold& m : p.manifolds)
        manifolds.push_back(const_cast<Manifold*>(&m));
    solver.prepare(manifolds, p.indexA, p.indexB, p.friction, p.restitution, p.bodies, p.centers, 1.0 / 480.0, settings,
                   parts, parallelFor, p.held, packParts);
}

// The addresses of the manifolds, for storeImpulses().
std::vector<Manifold*> pointers(std::vector<Manifold>& manifolds) {
    std::vector<Manifold*> out;
    for (Manifold& m : manifolds)
        out.push_back(&m);
    return out;
}

// A stack of `stack` unit cubes of 1 kg resting on the static entry 0 (body 1 at the bottom), and one more coming
// down at `speed` onto its top, every manifold a face of four touching points; restitution e everywhere.
Problem struckStack(int stack, Real speed, Real e) {
    Problem p;
    const size_t n = static_cast<size_t>(stack) + 1;
    p.bodies.assign(n + 1, SolverBody{});
    p.centers.assign(n + 1, Vec3(0.0));
    for (size_t i = 1; i <= n; ++i) {
        p.bodies[i].invMass = 1.0;
        p.bodies[i].invInertia = Mat3(6.0);
        p.centers[i] = Vec3(0.0, static_cast<Real>(i) - 0.5, 0.0);
    }
    p.bodies[n].v = Vec3(0.0, -speed, 0.0);
    for (size_t i = 0; i < n; ++i) {
        Manifold m;
        m.bodyA = static_cast<uint32_t>(i);
        m.bodyB = static_cast<uint32_t>(i + 1);
        m.normal = Vec3(0.0, 1.0, 0.0);
        m.pointCount = 4;
        for (int k = 0; k < 4; ++k)
            m.points[k].position = Vec3(k % 2 ? 0.5 : -0.5, static_cast<Real>(i), k / 2 ? 0.5 : -0.5);
        p.manifolds.push_back(m);
        p.indexA.push_back(m.bodyA);
        p.indexB.push_back(m.bodyB);
        p.friction.push_back(0.5);
        p.restitution.push_back(e);
    }
    return p;
}

// Stacks of 1 .. count cubes side by side on one ground (3 m apart), each struck from above at 4 + stack m/s, with
// their manifolds taken level by level across the stacks: the stacks' blows alternate in manifold order.
Problem struckStacks(int count) {
    Problem all;
    all.bodies.assign(1, SolverBody{});
    all.centers.assign(1, Vec3(0.0));
    std::vector<std::pair<int, size_t>> order; // (level in its stack, position in `all`) of each manifold
    for (int stack = 1; stack <= count; ++stack) {
        const Problem p = struckStack(stack, 4.0 + stack, 0.0);
        const uint32_t offset = static_cast<uint32_t>(all.bodies.size() - 1);
        const Vec3 shift(3.0 * stack, 0.0, 0.0);
        for (size_t i = 1; i < p.bodies.size(); ++i) {
            all.bodies.push_back(p.bodies[i]);
            all.centers.push_back(p.centers[i] + shift);
        }
        for (size_t k = 0; k < p.manifolds.size(); ++k) {
            Manifold m = p.manifolds[k];
            for (uint32_t* body : {&m.bodyA, &m.bodyB})
                if (*body != 0)
                    *body += offset;
            for (int n = 0; n < m.pointCount; ++n)
                m.points[n].position += shift;
            order.emplace_back(static_cast<int>(k), all.manifolds.size());
            all.manifolds.push_back(m);
        }
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    Problem p;
    p.bodies = all.bodies;
    p.centers = all.centers;
    for (const auto& [level, k] : order) {
        p.manifolds.push_back(all.manifolds[k]);
        p.indexA.push_back(all.manifolds[k].bodyA);
        p.indexB.push_back(all.manifolds[k].bodyB);
        p.friction.push_back(0.5);
        p.restitution.push_back(0.0);
    }
    return p;
}

// p's bodies after a warm start and one solve sweep, and a relax sweep if `relax`.
std::vector<SolverBody> oneSubstep(const Problem& p, bool relax) {
    ContactSolver solver;
    prepare(solver, p);
    std::vector<SolverBody> bodies = p.bodies;
    solver.warmStart(bodies);
    solver.solve(bodies, true);
    if (relax)
        solver.solve(bodies, false);
    return bodies;
}

// Part 0 or 1 for each body: bodies 1..n/2 in part 0, the rest in part 1 (a cut through the middle of the ids).
std::vector<uint8_t> halves(size_t bodyCount) {
    std::vector<uint8_t> part(bodyCount + 1, 0);
    for (size_t i = 1; i <= bodyCount; ++i)
        part[i] = i <= bodyCount / 2 ? 0 : 1;
    return part;
}

// makeProblem()'s problem, sides held if `holds`, with its bodies moved and turned since the step began (dp, dR).
Problem movedProblem(int bodies, int constraints, bool chain, bool holds, unsigned seed) {
    Problem p = makeProblem(bodies, constraints, chain, seed);
    if (holds)
        holdSome(p);
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-0.01, 0.01);
    for (size_t i = 1; i < p.bodies.size(); ++i) {
        p.bodies[i].dp = Vec3(u(rng), u(rng), u(rng));
        p.bodies[i].dR = glm::mat3_cast(glm::angleAxis(10.0 * u(rng), glm::normalize(Vec3(u(rng), 0.01, u(rng)))));
    }
    return p;
}

// A row of batchesGiveTheSequentialNumbers_data(): its problem (movedProblem()) and the bodies' parts if it has
// them. Sets the lanes the row asks for.
struct Row {
    Problem problem;
    std::vector<uint8_t> part;
    bool parts = false, chain = false;
    int constraints = 0;
    std::span<const uint8_t> partSpan() const {
        return parts ? std::span<const uint8_t>(part) : std::span<const uint8_t>();
    }
};
Row fetchRow(unsigned seed) {
    QFETCH(int, bodies);
    QFETCH(int, constraints);
    QFETCH(bool, chain);
    QFETCH(bool, parts);
    QFETCH(bool, holds);
    QFETCH(int, lanes);
    ContactSolver::setWidestLanes(lanes);
    return {movedProblem(bodies, constraints, chain, holds, seed), halves(static_cast<size_t>(std::max(bodies, 1))),
            parts, chain, constraints};
}

// The segment a constraint belongs to: the part of its moving bodies, or the boundary.
size_t segmentOf(const Problem& p, const std::vector<uint8_t>& part, size_t c) {
    const uint32_t a = p.indexA[c], b = p.indexB[c];
    if (a == 0 || b == 0)
        return part[a == 0 ? b : a];
    return part[a] == part[b] ? part[a] : ContactSolver::kBoundarySegment;
}

bool sameBits(const Vec3& a, const Vec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The solver's accumulated impulses written to a copy of the manifolds (storeImpulses()).
void storeInto(const ContactSolver& solver, std::vector<Manifold>& manifolds) {
    solver.storeImpulses(pointers(manifolds));
}

// Whether two copies of the manifolds carry the same impulses, bit for bit (zero signs too).
bool sameImpulses(const std::vector<Manifold>& a, const std::vector<Manifold>& b) {
    const auto same = [](Real x, Real y) { return std::bit_cast<uint64_t>(x) == std::bit_cast<uint64_t>(y); };
    for (size_t i = 0; i < a.size(); ++i) {
        if (!sameBits(a[i].frictionImpulse, b[i].frictionImpulse) || !same(a[i].twistImpulse, b[i].twistImpulse))
            return false;
        for (int k = 0; k < a[i].pointCount; ++k)
            if (!same(a[i].points[k].normalImpulse, b[i].points[k].normalImpulse))
                return false;
    }
    return a.size() == b.size();
}

} // namespace

class TestContactSolver : public QObject {
    Q_OBJECT
private slots:
    // stableSortSmall() (a manifold's points deepest first, the levels' short runs) gives std::stable_sort's order:
    // random runs of 0 to 40 values with many ties, each value carrying its place so that a tie out of order shows.
    void stableSortSmallMatchesStableSort_data() {
        QTest::addColumn<int>("length");
        for (int length : {0, 1, 2, 3, 4, 7, 23, 24, 40})
            QTest::addRow("%d values", length) << length;
    }
    void stableSortSmallMatchesStableSort() {
        QFETCH(int, length);
        std::mt19937 random(static_cast<unsigned>(length) * 7919u + 1u);
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<std::pair<int, int>> values(static_cast<size_t>(length));
            for (int i = 0; i < length; ++i)
                values[static_cast<size_t>(i)] = {static_cast<int>(random() % 4), i};
            const auto less = [](const std::pair<int, int>& a, const std::pair<int, int>& b) {
                return a.first < b.first;
            };
            std::vector<std::pair<int, int>> expected = values;
            std::stable_sort(expected.begin(), expected.end(), less);
            stableSortSmall(values.data(), values.data() + values.size(), less);
            QVERIFY(values == expected);
        }
    }

    // solveImpactRows() solves a struck manifold's rows as a linear complementarity problem: every impulse at least
    // zero, every row at least at its target, and a row above its target takes no impulse. Random bodies and points
    // (and some flat faces, whose four points give a singular block), with random targets and accumulated impulses.
    void impactRowsAreComplementary_data() {
        QTest::addColumn<int>("rows");
        QTest::addColumn<bool>("flat");
        QTest::addColumn<bool>("staticA");
        for (int rows : {2, 3, 4}) {
            QTest::addRow("%d random rows", rows) << rows << false << false;
            QTest::addRow("%d random rows against a static side", rows) << rows << false << true;
        }
        QTest::newRow("flat square against a static side") << 4 << true << true;
        QTest::newRow("flat square between two bodies") << 4 << true << false;
    }
    void impactRowsAreComplementary() {
        QFETCH(int, rows);
        QFETCH(bool, flat);
        QFETCH(bool, staticA);
        std::mt19937 random(static_cast<unsigned>(rows * 31 + (flat ? 7 : 0) + (staticA ? 3 : 0)));
        std::uniform_real_distribution<Real> unit(-1.0, 1.0), positive(0.1, 2.0);
        const Vec3 normal(0.0, 1.0, 0.0);
        int solved = 0, trials = 400, withSlack = 0;
        Real worst = 0.0;
        for (int trial = 0; trial < trials; ++trial) {
            ImpactRows block;
            block.count = rows;
            const Real massA = staticA ? 0.0 : 1.0 / positive(random), massB = 1.0 / positive(random);
            const Mat3 inertiaA = staticA ? Mat3(0.0) : Mat3(6.0 * massA / positive(random));
            const Mat3 inertiaB = Mat3(6.0 * massB / positive(random));
            block.massA = massA;
            block.massB = massB;
            const Real halfWidth = 0.05 + 0.5 * (unit(random) + 1.0);
            const Real target = -std::abs(unit(random));
            for (int i = 0; i < rows; ++i) {
                const Vec3 corner(i == 0 || i == 3 ? halfWidth : -halfWidth, -0.5, i < 2 ? halfWidth : -halfWidth);
                const Vec3 rB = flat ? corner : Vec3(unit(random), -0.5, unit(random));
                const Vec3 rA = rB + Vec3(0.0, 1.0, 0.0);
                block.angularA[i] = glm::cross(rA, normal);
                block.inertiaA[i] = inertiaA * block.angularA[i];
                block.angularB[i] = glm::cross(rB, normal);
                block.inertiaB[i] = inertiaB * block.angularB[i];
                block.velocity[i] = flat ? -6.0 : -6.0 * std::abs(unit(random));
                block.target[i] = flat ? target : -std::abs(unit(random));
                block.impulse[i] = trial % 2 ? std::abs(unit(random)) : 0.0;
            }
            const ImpactRows before = block;
            if (!solveImpactRows(block))
                continue;
            ++solved;
            Real scale = 0.0;
            for (int i = 0; i < rows; ++i)
                scale = std::max(scale, std::abs(before.velocity[i] - before.target[i]));
            for (int i = 0; i < rows; ++i) {
                Real velocity = before.velocity[i];
                for (int j = 0; j < rows; ++j) {
                    const Real k = (massA + massB) + glm::dot(before.angularA[i], before.inertiaA[j]) +
                                   glm::dot(before.angularB[i], before.inertiaB[j]);
                    velocity += k * (block.impulse[j] - before.impulse[j]);
                }
                const Real above = velocity - before.target[i];
                QVERIFY(block.impulse[i] >= 0.0);
                QVERIFY2(above >= -1e-6 * scale, qPrintable(QString::number(above)));
                if (block.impulse[i] > 0.0)
                    worst = std::max(worst, std::abs(above) / scale);
                else if (above > 1e-6 * scale)
                    ++withSlack;
            }
        }
        qInfo("%d of %d blocks solved, %d rows left above their targets, worst active row off its target by %.3g of "
              "the speed to remove",
              solved, trials, withSlack, worst);
        QCOMPARE(solved, trials); // a problem of this kind always has an answer, and the block finds it
        QVERIFY(worst < 1e-6);
        if (!flat)
            QVERIFY(withSlack > 0); // some rows were above their targets and took nothing
    }

    // A flat face landing squarely on four points stops without turning: the block (singular, as four points on a
    // plane are) is answered by a set of three rows, and its impulses are then shared alike between the four
    // corners (two opposite corners holding it all set the cube turning in the next substep's warm start).
    void aFlatLandingDoesNotTurn() {
        ImpactRows block;
        block.count = 4;
        const Real massB = 1e-3;                 // 1,000 kg
        const Mat3 inertiaB(6.0 * massB / 0.25); // a 0.5 m cube
        block.massB = massB;
        for (int i = 0; i < 4; ++i) {
            const Vec3 rB(i == 0 || i == 3 ? 0.125 : -0.125, -0.25, i < 2 ? 0.125 : -0.125);
            block.angularB[i] = glm::cross(rB, Vec3(0.0, 1.0, 0.0));
            block.inertiaB[i] = inertiaB * block.angularB[i];
            block.velocity[i] = -6.2;
            block.target[i] = -0.97;
        }
        QVERIFY(solveImpactRows(block));
        Vec3 spin(0.0);
        Real total = 0.0;
        for (int i = 0; i < 4; ++i) {
            spin += block.impulse[i] * block.inertiaB[i];
            total += block.impulse[i];
        }
        qInfo("impulses %.4g %.4g %.4g %.4g N s, spin %.3g rad/s", block.impulse[0], block.impulse[1], block.impulse[2],
              block.impulse[3], glm::length(spin));
        QVERIFY(glm::length(spin) < 1e-9);
        QVERIFY(std::abs(total * massB - (6.2 - 0.97)) < 1e-9);
        for (int i = 0; i < 4; ++i) // shared alike, not two opposite corners holding it all
            QVERIFY(std::abs(block.impulse[i] - 0.25 * total) < 1e-6 * total);
    }

    void levelsKeepTheSequentialOrder_data() {
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("constraints");
        QTest::addColumn<bool>("chain");
        QTest::addColumn<bool>("parts");
        QTest::newRow("tower of 40") << 40 << 40 << true << false;
        QTest::newRow("200 random contacts among 60 bodies") << 60 << 200 << false << false;
        QTest::newRow("2000 random contacts among 1000 bodies") << 1000 << 2000 << false << false;
        QTest::newRow("tower of 40 in two parts") << 40 << 40 << true << true;
        QTest::newRow("2000 random contacts among 1000 bodies in two parts") << 1000 << 2000 << false << true;
        // Every other body of a chain in part 1: each constraint but the first crosses the cut and shares a body
        // with the next one, as along the seam of a cut through a wall of bricks.
        QTest::newRow("a seam of 40 contacts across the cut") << 41 << 40 << true << true;
        // One body in part 0 touching 70 of part 1: more constraints on one body than there are colours.
        QTest::newRow("70 contacts across the cut on one body") << 71 << 70 << true << true;
    }
    // With parts, the sequential order is part 0's constraints, part 1's, each in manifold order, then the
    // boundary's by colour, and each segment is a run of whole levels.
    void levelsKeepTheSequentialOrder() {
        QFETCH(int, bodies);
        QFETCH(int, constraints);
        QFETCH(bool, chain);
        QFETCH(bool, parts);
        const QByteArray row = QTest::currentDataTag();
        const bool seam = row.startsWith("a seam"), star = row.startsWith("70 contacts");
        Problem p = makeProblem(bodies, constraints, chain, 7);
        std::vector<uint8_t> part = halves(static_cast<size_t>(bodies));
        if (seam)
            for (size_t i = 1; i < part.size(); ++i)
                part[i] = static_cast<uint8_t>(i % 2);
        if (star) {
            std::fill(part.begin() + 1, part.end(), uint8_t(1));
            part[1] = 0;
            for (int k = 0; k < constraints; ++k) {
                p.indexA[static_cast<size_t>(k)] = 1;
                p.indexB[static_cast<size_t>(k)] = static_cast<uint32_t>(k + 2);
            }
        }
        ContactSolver solver;
        prepare(solver, p, parts ? std::span<const uint8_t>(part) : std::span<const uint8_t>());
        const auto segment = [&](int c) { return parts ? segmentOf(p, part, static_cast<size_t>(c)) : size_t(0); };
        const auto order = solver.solveOrder();
        QCOMPARE(order.size(), size_t(constraints));
        std::vector<int> levelOf(static_cast<size_t>(constraints), -1);
        for (size_t level = 0; level < solver.levelCount(); ++level) {
            std::vector<bool> seen(static_cast<size_t>(bodies) + 1, false);
            for (size_t n = solver.levelBegin(level); n < solver.levelEnd(level); ++n) {
                const uint32_t c = order[n];
                QCOMPARE(levelOf[c], -1); // each constraint once
                levelOf[c] = static_cast<int>(level);
                for (uint32_t body : {p.indexA[c], p.indexB[c]}) {
                    if (body == 0)
                        continue; // the static entry is shared freely
                    QVERIFY2(!seen[body], "two constraints of one level share a moving body");
                    seen[body] = true;
                }
            }
        }
        // Constraints that share a moving body are solved in segment order, then within a part in manifold order.
        // In the boundary each constraint, in manifold order, takes the lowest of its levels (colours) that no earlier
        // one sharing a body holds; past 64 colours, one level more than the last such constraint's.
        constexpr size_t kBoundary = ContactSolver::kBoundarySegment;
        const int boundaryStart = static_cast<int>(solver.segmentLevelBegin(kBoundary));
        for (int j = 0; j < constraints; ++j) {
            std::vector<int> takenBefore; // the boundary levels of the earlier constraints that share a body with j
            for (int i = 0; i < j; ++i) {
                const bool share = (p.indexA[i] != 0 && (p.indexA[i] == p.indexA[j] || p.indexA[i] == p.indexB[j])) ||
                                   (p.indexB[i] != 0 && (p.indexB[i] == p.indexA[j] || p.indexB[i] == p.indexB[j]));
                if (!share)
                    continue;
                if (segment(i) != segment(j))
                    QCOMPARE(levelOf[i] < levelOf[j], segment(i) < segment(j));
                else if (segment(j) != kBoundary)
                    QVERIFY(levelOf[i] < levelOf[j]);
                else
                    takenBefore.push_back(levelOf[i] - boundaryStart);
            }
            if (segment(j) != kBoundary)
                continue;
            int expected = 0;
            while (expected < 64 && std::find(takenBefore.begin(), takenBefore.end(), expected) != takenBefore.end())
                ++expected;
            if (expected == 64)
                for (int level : takenBefore)
                    expected = std::max(expected, level + 1);
            QCOMPARE(levelOf[j] - boundaryStart, expected);
        }
        // Each segment is a run of whole levels, in order.
        size_t counts[ContactSolver::kBoundarySegment + 1] = {};
        for (int c = 0; c < constraints; ++c) {
            const size_t s = segment(c);
            ++counts[s];
            QVERIFY(static_cast<size_t>(levelOf[c]) >= solver.segmentLevelBegin(s));
            QVERIFY(static_cast<size_t>(levelOf[c]) < solver.segmentLevelBegin(s + 1));
        }
        QCOMPARE(solver.segmentLevelBegin(0), size_t(0));
        QCOMPARE(solver.segmentLevelBegin(ContactSolver::kBoundarySegment + 1), solver.levelCount());
        if (parts && !seam && !star)
            QVERIFY(counts[0] > 0 && counts[1] > 0 && counts[ContactSolver::kBoundarySegment] > 0);
        if (chain && !parts)
            QCOMPARE(solver.levelCount(), size_t(constraints)); // a tower has no two independent contacts
        const size_t boundaryLevels = solver.levelCount() - solver.segmentLevelBegin(kBoundary);
        if (seam)
            QCOMPARE(boundaryLevels, size_t(2)); // 39 levels in manifold order
        if (star)
            QCOMPARE(boundaryLevels, size_t(constraints)); // one body: one constraint a level
        qInfo("%d constraints in %zu levels; segments %zu, %zu and %zu", constraints, solver.levelCount(), counts[0],
              counts[1], counts[2]);
    }

    // The batched sweeps (four constraints of a level side by side) give the numbers of the scalar sweep in manifold
    // order: velocities, impulses and impact records, through warm starts, soft and relax sweeps, with bodies that
    // have moved and turned since the step began.
    // Rows run with batches of four lanes and with the widest the CPU offers (eight where it has AVX-512, else four
    // again; the row's output says which ran).
    void batchesGiveTheSequentialNumbers_data() {
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("constraints");
        QTest::addColumn<bool>("chain");
        QTest::addColumn<bool>("parts");
        QTest::addColumn<bool>("holds");
        QTest::addColumn<int>("lanes");
        for (int lanes : {4, 8}) {
            QTest::addRow("tower of 40, %d lanes", lanes) << 40 << 40 << true << false << false << lanes;
            QTest::addRow("203 random contacts among 60 bodies, %d lanes", lanes)
                << 60 << 203 << false << false << false << lanes;
            QTest::addRow("3001 random contacts among 1000 bodies, %d lanes", lanes)
                << 1000 << 3001 << false << false << false << lanes;
            QTest::addRow("3001 random contacts among 1000 bodies in two parts, %d lanes", lanes)
                << 1000 << 3001 << false << true << false << lanes;
            QTest::addRow("tower of 40, holding sides, %d lanes", lanes) << 40 << 40 << true << false << true << lanes;
            QTest::addRow("203 random contacts among 60 bodies, holding sides, %d lanes", lanes)
                << 60 << 203 << false << false << true << lanes;
        }
    }
    void batchesGiveTheSequentialNumbers() {
        const Row row = fetchRow(5);
        const Problem& p = row.problem;
        const std::span<const uint8_t> partSpan = row.partSpan();
        const int constraints = row.constraints;
        std::vector<SolverBody> sequential = p.bodies, batched = p.bodies;
        ContactSolver a, b;
        a.keepConstraints(true); // the sequential sweeps work on the records
        b.keepConstraints(true); // to compare them below
        prepare(a, p, partSpan);
        prepare(b, p, partSpan);
        int impacts = 0;
        for (const ContactConstraint& c : a.constraints())
            impacts += c.order[0] != 0 || c.order[1] != 1 ? 1 : 0;
        for (int substep = 0; substep < 4; ++substep) {
            a.warmStartSequential(sequential);
            b.warmStart(batched);
            for (int it = 0; it < 2; ++it) {
                a.solveSequential(sequential, true);
                b.solve(batched, true);
            }
            a.solveSequential(sequential, false);
            b.solve(batched, false);
        }
        for (size_t i = 0; i < sequential.size(); ++i) {
            QCOMPARE(batched[i].v, sequential[i].v);
            QCOMPARE(batched[i].w, sequential[i].w);
        }
        QVERIFY(batched[0].v == Vec3(0.0) && batched[0].w == Vec3(0.0)); // the static entry is never written
        int pushing = 0, rubbing = 0;
        for (size_t i = 0; i < a.constraints().size(); ++i) {
            const ContactConstraint& ca = a.constraints()[i];
            const ContactConstraint& cb = b.constraints()[i];
            QCOMPARE(cb.frictionImpulse[0], ca.frictionImpulse[0]);
            QCOMPARE(cb.frictionImpulse[1], ca.frictionImpulse[1]);
            QCOMPARE(cb.twistImpulse, ca.twistImpulse);
            rubbing += ca.frictionImpulse[0] != 0.0 && ca.twistImpulse != 0.0 ? 1 : 0;
            for (int k = 0; k < ca.pointCount; ++k) {
                QCOMPARE(cb.points[k].normalImpulse, ca.points[k].normalImpulse);
                QCOMPARE(cb.points[k].maxNormalImpulse, ca.points[k].maxNormalImpulse);
                QCOMPARE(cb.points[k].relativeVelocity, ca.points[k].relativeVelocity);
                pushing += ca.points[k].normalImpulse > 0.0 ? 1 : 0;
            }
        }
        // The batches store one anchor a point: rB is rA plus the constraint's offset, added in floats; beside the
        // static entry (which does not move) the two anchors are one.
        int besideStatic = 0;
        for (const ContactConstraint& c : a.constraints())
            for (int k = 0; k < c.pointCount; ++k) {
                const ContactConstraint::Point& q = c.points[k];
                const Vec3 sum(static_cast<float>(q.rA.x) + static_cast<float>(c.anchorOffset.x),
                               static_cast<float>(q.rA.y) + static_cast<float>(c.anchorOffset.y),
                               static_cast<float>(q.rA.z) + static_cast<float>(c.anchorOffset.z));
                QCOMPARE(q.rB, sum);
                if (c.bodyA == 0 || c.bodyB == 0) {
                    QCOMPARE(q.rB, q.rA);
                    ++besideStatic;
                }
            }
        QVERIFY(besideStatic > 0);
        qInfo("%d constraints, %d solved deepest point first, %d points pushing, %d with friction and twist; batches "
              "of %d lanes",
              constraints, impacts, pushing, rubbing, b.laneWidth());
        ContactSolver::setWidestLanes(8);
        QVERIFY(pushing > 0);
        QVERIFY(rubbing > 0);
    }

    // Packed into batches (packParts says each part is swept by one thread), the levels of the parts give every body
    // the same updates in the same order, so the sweeps give the numbers of the unpacked levels, bit for bit, with
    // fewer batches. Each packed level is one batch: no two of its constraints share a moving body, and each body's
    // constraints within a part come in manifold order. The boundary keeps its levels by colour. With packParts
    // saying no, nothing is packed.
    void packedLevelsGiveTheSameNumbers_data() { batchesGiveTheSequentialNumbers_data(); }
    void packedLevelsGiveTheSameNumbers() {
        const Row row = fetchRow(5);
        const Problem& p = row.problem;
        const std::span<const uint8_t> partSpan = row.partSpan();
        ContactSolver::Schedule asked;
        int asks = 0;
        const auto pack = [&](bool answer) -> ContactSolver::PackParts {
            return [&, answer](const ContactSolver::Schedule& schedule) {
                asked = schedule;
                ++asks;
                return answer;
            };
        };
        ContactSolver levels, packed, declined;
        prepare(levels, p, partSpan);
        prepare(packed, p, partSpan, true, {}, Vec3(0.0), pack(true));
        QCOMPARE(asks, 1);
        // The schedule it was asked about is that of the sequential order, before packing.
        size_t constraints = 0;
        for (size_t segment = 0; segment <= ContactSolver::kParts; ++segment) {
            constraints += asked.constraints[segment];
            QCOMPARE(asked.levels[segment], levels.segmentLevelBegin(segment + 1) - levels.segmentLevelBegin(segment));
        }
        QCOMPARE(constraints, p.manifolds.size());
        prepare(declined, p, partSpan, true, {}, Vec3(0.0), pack(false));
        QCOMPARE(asks, 2);
        QCOMPARE(declined.levelCount(), levels.levelCount());

        const auto batches = [](const ContactSolver& solver, size_t segment) {
            const auto [begin, end] = solver.segmentBatches(segment);
            return end - begin;
        };
        const size_t parts = row.parts ? ContactSolver::kParts : 1;
        const size_t width = static_cast<size_t>(packed.laneWidth());
        size_t before = 0, after = 0;
        for (size_t segment = 0; segment < parts; ++segment) {
            before += batches(levels, segment);
            after += batches(packed, segment);
            QCOMPARE(batches(packed, segment),
                     packed.segmentLevelBegin(segment + 1) - packed.segmentLevelBegin(segment));
        }
        QVERIFY(after <= before);
        // No fewer than the constraints need, nor than the longest chain of one body's constraints.
        size_t partConstraints = 0;
        std::vector<size_t> perBody(p.bodies.size(), 0);
        for (size_t segment = 0; segment < parts; ++segment)
            for (size_t k = packed.levelBegin(packed.segmentLevelBegin(segment));
                 k < packed.levelEnd(packed.segmentLevelBegin(segment + 1) - 1); ++k) {
                ++partConstraints;
                const uint32_t i = packed.solveOrder()[k];
                for (const uint32_t body : {p.indexA[i], p.indexB[i]})
                    if (body != 0)
                        ++perBody[body];
            }
        QVERIFY(after >= (partConstraints + width - 1) / width);
        QVERIFY(after >= *std::max_element(perBody.begin(), perBody.end()));
        // Random contacts leave part-filled batches at the end of their levels: 203 among 60 bodies take 52 batches
        // packed against 60 in levels of four lanes, 28 against 38 of eight; 3001 among 1000 bodies have wider
        // levels and gain less (751 against 759, 376 against 384).
        const QString counts = QString("%1 batches against %2").arg(after).arg(before);
        if (!row.chain)
            QVERIFY2(after < before, qPrintable(counts));
        if (!row.chain && row.constraints < 1000)
            QVERIFY2(100 * after <= 90 * before, qPrintable(counts));
        // Boundary unchanged.
        QCOMPARE(batches(packed, ContactSolver::kBoundarySegment), batches(levels, ContactSolver::kBoundarySegment));

        // One batch a level, no body twice in it, and each body's constraints of a part in manifold order.
        std::vector<uint32_t> lastOf(p.bodies.size(), 0), levelOfLast(p.bodies.size(), 0);
        std::vector<bool> seen(p.bodies.size(), false);
        for (size_t level = 0; level < packed.segmentLevelBegin(parts); ++level) {
            QVERIFY(packed.levelEnd(level) - packed.levelBegin(level) <= width);
            QCOMPARE(packed.batchLevelEnd(level) - packed.batchLevelBegin(level), size_t(1));
            std::vector<uint32_t> bodies;
            for (size_t k = packed.levelBegin(level); k < packed.levelEnd(level); ++k) {
                const uint32_t i = packed.solveOrder()[k];
                for (const uint32_t body : {p.indexA[i], p.indexB[i]}) {
                    if (body == 0)
                        continue;
                    QVERIFY(std::find(bodies.begin(), bodies.end(), body) == bodies.end());
                    bodies.push_back(body);
                    if (seen[body]) {
                        QVERIFY(i > lastOf[body]);
                        QVERIFY(level > levelOfLast[body]);
                    }
                    seen[body] = true;
                    lastOf[body] = i;
                    levelOfLast[body] = static_cast<uint32_t>(level);
                }
            }
        }

        // Four substeps of a warm start, two soft sweeps and a relax sweep.
        const auto substeps = [](ContactSolver& solver, std::vector<SolverBody>& bodies) {
            for (int substep = 0; substep < 4; ++substep) {
                solver.warmStart(bodies);
                for (int sweep = 0; sweep < 3; ++sweep)
                    solver.solve(bodies, sweep < 2);
            }
        };
        std::vector<SolverBody> byLevels = p.bodies, byBatches = p.bodies;
        substeps(levels, byLevels);
        substeps(packed, byBatches);
        for (size_t i = 0; i < byLevels.size(); ++i) {
            QCOMPARE(byBatches[i].v, byLevels[i].v);
            QCOMPARE(byBatches[i].w, byLevels[i].w);
        }
        std::vector<Manifold> fromLevels = p.manifolds, fromBatches = p.manifolds;
        storeInto(levels, fromLevels);
        storeInto(packed, fromBatches);
        // The same values (== and QCOMPARE on vectors take -0 for +0): a zero impulse may differ in its sign, as it
        // already did between batches of four and of eight lanes in levels (the random rows here, 2026-12-02).
        for (size_t i = 0; i < p.manifolds.size(); ++i) {
            QVERIFY(fromBatches[i].frictionImpulse == fromLevels[i].frictionImpulse);
            QVERIFY(fromBatches[i].twistImpulse == fromLevels[i].twistImpulse);
            for (int k = 0; k < p.manifolds[i].pointCount; ++k)
                QVERIFY(fromBatches[i].points[k].normalImpulse == fromLevels[i].points[k].normalImpulse);
        }
        qInfo("parts' batches: %zu in levels, %zu packed (%zu constraints in %zu lanes)", before, after,
              partConstraints, width);
        ContactSolver::setWidestLanes(8);
    }

    // The benchmark's report of the sweeps names the lanes a solver prepared on this CPU uses, and the instruction set
    // that gives them (eight lanes only with AVX-512); with the lanes held to four, it says four.
    void sweepsDescriptionNamesTheLanesInUse() {
        const Problem p = makeProblem(20, 40, false, 5);
        const auto restore = qScopeGuard([] { ContactSolver::setWidestLanes(8); });
        for (const int widest : {8, 4}) {
            ContactSolver::setWidestLanes(widest);
            ContactSolver solver;
            prepare(solver, p);
            const QString description = QString::fromStdString(ContactSolver::sweepsDescription());
            QVERIFY2(description.startsWith(QString("%1 lanes of doubles (").arg(solver.laneWidth())),
                     qPrintable(description));
            QCOMPARE(description.contains("(AVX-512)"), solver.laneWidth() == 8);
            QVERIFY(widest == 8 || solver.laneWidth() == 4);
        }
    }

    // storeImpulses() writes the same impulses to the manifolds whether the solver kept its constraint records or
    // set the constraints up straight into the batches (restitution off), and however its parallelFor cuts up the
    // manifolds: the reference is the sequential sweep, stored from the records.
    void storedImpulsesAreTheSequentialOnes_data() {
        QTest::addColumn<int>("lanes");
        QTest::addColumn<bool>("kept");
        QTest::addColumn<bool>("shared");
        for (int lanes : {4, 8})
            for (bool kept : {false, true})
                for (bool shared : {false, true})
                    QTest::addRow("%d lanes, records %s, %s", lanes, kept ? "kept" : "not kept",
                                  shared ? "shared out in three" : "one range")
                        << lanes << kept << shared;
    }
    void storedImpulsesAreTheSequentialOnes() {
        QFETCH(int, lanes);
        QFETCH(bool, kept);
        QFETCH(bool, shared);
        ContactSolver::setWidestLanes(lanes);
        Problem p = makeProblem(60, 203, false, 11);
        holdSome(p);
        // Three ranges, last first: each manifold must be written alone.
        const ContactSolver::ParallelFor inThree = [](size_t count, const std::function<void(size_t, size_t)>& body) {
            for (int part = 2; part >= 0; --part)
                body(count * static_cast<size_t>(part) / 3, count * static_cast<size_t>(part + 1) / 3);
        };

        ContactSolver reference;
        reference.keepConstraints(true);
        prepare(reference, p, {}, false);
        std::vector<SolverBody> sequential = p.bodies;
        ContactSolver solver;
        solver.keepConstraints(kept);
        prepare(solver, p, {}, false, shared ? inThree : ContactSolver::ParallelFor());
        QCOMPARE(solver.constraints().size(), kept ? p.manifolds.size() : size_t(0));
        std::vector<SolverBody> batched = p.bodies;
        for (int substep = 0; substep < 2; ++substep) {
            reference.warmStartSequential(sequential);
            reference.solveSequential(sequential, true);
            reference.solveSequential(sequential, false);
            solver.warmStart(batched);
            solver.solve(batched, true);
            solver.solve(batched, false);
        }
        std::vector<Manifold> expected = p.manifolds, stored = p.manifolds;
        reference.storeImpulses(pointers(expected));
        solver.storeImpulses(pointers(stored), shared ? inThree : ContactSolver::ParallelFor());
        int changed = 0;
        for (size_t i = 0; i < p.manifolds.size(); ++i) {
            QCOMPARE(stored[i].frictionImpulse, expected[i].frictionImpulse);
            QCOMPARE(stored[i].twistImpulse, expected[i].twistImpulse);
            for (int k = 0; k < p.manifolds[i].pointCount; ++k) {
                QCOMPARE(stored[i].points[k].normalImpulse, expected[i].points[k].normalImpulse);
                changed += stored[i].points[k].normalImpulse != p.manifolds[i].points[k].normalImpulse ? 1 : 0;
            }
        }
        ContactSolver::setWidestLanes(8);
        QVERIFY(changed > 100); // the sweeps changed most points' impulses (203 manifolds, 507 points)
    }

    // The batches are set up eight (or four) constraints at a time in vectors; that set-up gives the numbers of
    // setUpConstraint(), one constraint at a time, to the bit: the same records where they are kept (restitution on,
    // with half the contacts bouncing under gravity), and the same velocities and stored impulses through warm
    // starts, soft and relax sweeps and the restitution pass, with impacts (points reordered deepest first), held
    // sides and parts.
    void vectorSetUpGivesTheScalarNumbers_data() { batchesGiveTheSequentialNumbers_data(); }
    void vectorSetUpGivesTheScalarNumbers() {
        // To the bit: QCOMPARE compares doubles within a tolerance.
        const auto bits = [](const auto& x) {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Vec3>)
                return std::array<uint64_t, 3>{std::bit_cast<uint64_t>(x.x), std::bit_cast<uint64_t>(x.y),
                                               std::bit_cast<uint64_t>(x.z)};
            else
                return std::bit_cast<uint64_t>(x);
        };
        Row row = fetchRow(7);
        Problem& p = row.problem;
        for (size_t i = 0; i < p.restitution.size(); ++i)
            p.restitution[i] = i % 2 == 0 ? 0.5 : 0.0;
        const std::span<const uint8_t> partSpan = row.partSpan();
        const Vec3 gravity(0.0, -9.81, 0.0);
        for (const bool restitution : {false, true}) {
            std::vector<SolverBody> result[2];
            std::vector<Manifold> stored[2];
            std::vector<ContactConstraint> records[2];
            for (int wide = 0; wide < 2; ++wide) {
                ContactSolver::setWideSetUp(wide == 1);
                ContactSolver solver;
                // Every record kept, to compare them all (without, only those that may bounce are kept: see
                // restitutionReadsOnlyTheBouncers()).
                solver.keepConstraints(restitution);
                prepare(solver, p, partSpan, restitution, {}, gravity);
                ContactSolver::setWideSetUp(true);
                QCOMPARE(solver.constraints().size(), restitution ? p.manifolds.size() : size_t(0));
                records[wide] = solver.constraints();
                result[wide] = p.bodies;
                for (int substep = 0; substep < 3; ++substep) {
                    solver.warmStart(result[wide]);
                    solver.solve(result[wide], true);
                    solver.solve(result[wide], false);
                }
                if (restitution)
                    solver.applyRestitution(result[wide]);
                stored[wide] = p.manifolds;
                storeInto(solver, stored[wide]);
            }
            int impacts = 0, bouncing = 0;
            for (size_t i = 0; i < records[0].size(); ++i) {
                const ContactConstraint& x = records[1][i];
                const ContactConstraint& y = records[0][i];
                QCOMPARE(x.bodyA, y.bodyA);
                QCOMPARE(x.bodyB, y.bodyB);
                QCOMPARE(bits(x.anchorOffset), bits(y.anchorOffset));
                QCOMPARE(bits(x.normal), bits(y.normal));
                QCOMPARE(bits(x.tangent[0]), bits(y.tangent[0]));
                QCOMPARE(bits(x.tangent[1]), bits(y.tangent[1]));
                QCOMPARE(bits(x.friction), bits(y.friction));
                QCOMPARE(bits(x.restitution), bits(y.restitution));
                QCOMPARE(bits(x.approachAcceleration), bits(y.approachAcceleration));
                QCOMPARE(x.pointCount, y.pointCount);
                for (int k = 0; k < 4; ++k) {
                    QCOMPARE(x.order[k], y.order[k]);
                    const ContactConstraint::Point &q = x.points[k], &r = y.points[k];
                    QCOMPARE(bits(q.rA), bits(r.rA));
                    QCOMPARE(bits(q.rB), bits(r.rB));
                    QCOMPARE(bits(q.baseSeparation), bits(r.baseSeparation));
                    QCOMPARE(bits(q.normalMass), bits(r.normalMass));
                    QCOMPARE(bits(q.normalImpulse), bits(r.normalImpulse));
                    QCOMPARE(bits(q.maxNormalImpulse), bits(r.maxNormalImpulse));
                    QCOMPARE(bits(q.relativeVelocity), bits(r.relativeVelocity));
                    QCOMPARE(bits(q.leverArm), bits(r.leverArm));
                }
                QCOMPARE(bits(x.centerA), bits(y.centerA));
                QCOMPARE(bits(x.centerB), bits(y.centerB));
                for (int k = 0; k < 3; ++k)
                    QCOMPARE(bits(x.frictionMass[k]), bits(y.frictionMass[k]));
                QCOMPARE(bits(x.frictionImpulse[0]), bits(y.frictionImpulse[0]));
                QCOMPARE(bits(x.frictionImpulse[1]), bits(y.frictionImpulse[1]));
                QCOMPARE(bits(x.twistMass), bits(y.twistMass));
                QCOMPARE(bits(x.twistImpulse), bits(y.twistImpulse));
                QCOMPARE(bits(x.scaleA), bits(y.scaleA));
                QCOMPARE(bits(x.scaleB), bits(y.scaleB));
                impacts += y.order[0] != 0 || y.order[1] != 1 || y.order[2] != 2 ? 1 : 0;
                bouncing += y.restitution > 0.0 && y.points[0].relativeVelocity < 0.0 ? 1 : 0;
            }
            int moved = 0;
            for (size_t i = 0; i < p.bodies.size(); ++i) {
                QCOMPARE(bits(result[1][i].v), bits(result[0][i].v));
                QCOMPARE(bits(result[1][i].w), bits(result[0][i].w));
                moved += result[0][i].v != p.bodies[i].v ? 1 : 0;
            }
            int pushing = 0;
            for (size_t i = 0; i < p.manifolds.size(); ++i) {
                QCOMPARE(bits(stored[1][i].frictionImpulse), bits(stored[0][i].frictionImpulse));
                QCOMPARE(bits(stored[1][i].twistImpulse), bits(stored[0][i].twistImpulse));
                for (int k = 0; k < p.manifolds[i].pointCount; ++k) {
                    QCOMPARE(bits(stored[1][i].points[k].normalImpulse), bits(stored[0][i].points[k].normalImpulse));
                    pushing += stored[0][i].points[k].normalImpulse > 0.0 ? 1 : 0;
                }
            }
            qInfo("restitution %s: %d constraints, %d solved deepest point first, %d bouncing, %d bodies moved, %d "
                  "points pushing",
                  restitution ? "on" : "off", row.constraints, impacts, bouncing, moved, pushing);
            QVERIFY(moved > 0 && pushing > 0);
            if (restitution && !row.chain)
                QVERIFY(impacts > 0 && bouncing > 0);
        }
        ContactSolver::setWidestLanes(8);
    }

    // With restitution on and the records not kept whole, prepare() keeps only those of the constraints that may
    // bounce, and the restitution pass reads only those: the velocities after it and the stored impulses are those
    // of the solver that keeps every record, to the bit, set up in vectors or one by one.
    void restitutionReadsOnlyTheBouncers_data() { batchesGiveTheSequentialNumbers_data(); }
    void restitutionReadsOnlyTheBouncers() {
        Row row = fetchRow(7);
        Problem& p = row.problem;
        for (size_t i = 0; i < p.restitution.size(); ++i)
            p.restitution[i] = i % 2 == 0 ? 0.5 : 0.0;
        const Vec3 gravity(0.0, -9.81, 0.0);
        for (const bool wideSetUp : {false, true}) {
            std::vector<SolverBody> result[2];
            std::vector<Manifold> stored[2];
            uint64_t rows[2] = {};
            size_t records[2] = {};
            for (int kept = 0; kept < 2; ++kept) {
                ContactSolver::setWideSetUp(wideSetUp);
                ContactSolver solver;
                solver.keepConstraints(kept == 1);
                prepare(solver, p, row.partSpan(), true, {}, gravity);
                ContactSolver::setWideSetUp(true);
                records[kept] = kept == 1 ? solver.constraints().size() : solver.bounceRecords();
                result[kept] = p.bodies;
                for (int substep = 0; substep < 3; ++substep) {
                    solver.warmStart(result[kept]);
                    solver.solve(result[kept], true);
                    solver.solve(result[kept], false);
                }
                solver.applyRestitution(result[kept]);
                rows[kept] = solver.counters().restitutionRows;
                stored[kept] = p.manifolds;
                storeInto(solver, stored[kept]);
            }
            for (size_t i = 0; i < p.bodies.size(); ++i)
                QVERIFY(sameBits(result[0][i].v, result[1][i].v) && sameBits(result[0][i].w, result[1][i].w));
            QVERIFY(sameImpulses(stored[0], stored[1]));
            QCOMPARE(rows[0], rows[1]);
            qInfo("%s set-up: %zu of %zu records kept, %llu restitution rows", wideSetUp ? "vector" : "scalar",
                  records[0], records[1], static_cast<unsigned long long>(rows[0]));
            QCOMPARE(records[1], p.manifolds.size());
            QVERIFY(records[0] < records[1]);
            if (!row.chain)
                QVERIFY(records[0] > 0 && rows[0] > 0);
        }
        ContactSolver::setWidestLanes(8);
    }

    // A constraint that holds one side reads that body's velocity but never moves it (to the bit), so the other body
    // is stopped by it as by an anchor: body 1 (held, at rest) under body 2 (falling onto it at 3 m/s).
    void aHeldSideIsReadButNotMoved_data() {
        QTest::addColumn<bool>("holdA");
        QTest::newRow("held as A") << true;
        QTest::newRow("held as B") << false;
    }
    void aHeldSideIsReadButNotMoved() {
        QFETCH(bool, holdA);
        Problem p = heavyOnLight(holdA, 0.0);
        std::vector<SolverBody> bodies = oneSubstep(p, true);
        QVERIFY(sameBits(bodies[1].v, p.bodies[1].v) && sameBits(bodies[1].w, p.bodies[1].w));
        qInfo("held: heavy body %.4f m/s", bodies[2].v.y);
        QVERIFY(std::abs(bodies[2].v.y) < 0.05); // stopped from 3 m/s in one substep, as by an anchor
        // Unheld, the light body takes most of the blow and the heavy one is barely slowed.
        p.held.clear();
        bodies = oneSubstep(p, true);
        qInfo("unheld: light body %.4f m/s, heavy %.4f m/s", bodies[1].v.y, bodies[2].v.y);
        QVERIFY(bodies[2].v.y < -2.9);
    }

    // A side held with a scale between 0 and 1 moves as if its inverse mass and inertia were that much smaller, in
    // this constraint only: 1 kg under 1,000 kg, scaled by 0.01, takes ten times the heavy body's change of speed
    // instead of a thousand times (World's wedge contacts, WorldTuning::holdMassRatio).
    void aPartlyHeldSideIsHeavier_data() { aHeldSideIsReadButNotMoved_data(); }
    void aPartlyHeldSideIsHeavier() {
        QFETCH(bool, holdA);
        const Problem p = heavyOnLight(holdA, 0.01);
        const std::vector<SolverBody> bodies = oneSubstep(p, false);
        const Real light = bodies[1].v.y - p.bodies[1].v.y, heavy = bodies[2].v.y - p.bodies[2].v.y;
        qInfo("partly held: light body %.4f m/s, heavy body %.4f m/s (ratio %.6f)", light, heavy, light / heavy);
        QVERIFY(light < -0.1 && heavy > 0.0);
        QVERIFY(std::abs(light / heavy + 10.0) < 1e-6);
    }

    // Bodies marked isotropic (SolverBody::isotropic: d times the identity) are swept with d alone where a batch has
    // only such bodies; the velocities and impulses are those of the same bodies unmarked, which every batch sweeps
    // with the full matrix, to the bit, and equal to the sequential sweep's. Half the contacts (a tower's all) are
    // axis-aligned and frictionless, and some velocity components start as zeros of either sign.
    void isotropicBodiesGiveTheFullProductsNumbers_data() { batchesGiveTheSequentialNumbers_data(); }
    void isotropicBodiesGiveTheFullProductsNumbers() {
        Row row = fetchRow(9);
        Problem& p = row.problem;
        // In a tower every contact, elsewhere every other one, is axis-aligned and frictionless: its normal rows
        // leave w.y at a zero of either sign.
        for (size_t k = 0; k < p.manifolds.size(); k += row.chain ? 1 : 2) {
            Manifold& m = p.manifolds[k];
            m.normal = Vec3(0.0, k % 4 == 0 ? 1.0 : -1.0, 0.0);
            m.frictionImpulse = Vec3(0.0);
            m.twistImpulse = 0.0;
            p.friction[k] = 0.0;
            for (int i = 0; i < m.pointCount; ++i) // on the centres' own axes: r has zero components
                m.points[i].position = Vec3(p.centers[m.bodyA].x, 0.5 * (p.centers[m.bodyA].y + p.centers[m.bodyB].y),
                                            i % 2 == 0 ? p.centers[m.bodyA].z : -0.25);
        }
        p.bodies[0].isotropic = true; // zero inverse mass and inertia
        size_t marked = 0;
        for (size_t i = 1; i < p.bodies.size(); ++i) {
            SolverBody& b = p.bodies[i];
            if (i % 7 == 0)
                continue; // a turned box's inverse inertia: the batches with it take the full products
            b.invInertia = Mat3(6.0 * b.invMass);
            b.w = Vec3(i % 3 == 0 ? -0.0 : b.w.x, i % 2 == 0 ? -0.0 : 0.0, i % 4 == 1 ? -0.0 : b.w.z);
            if (i % 5 == 0)
                b.v.x = -0.0;
            b.isotropic = true;
            ++marked;
        }
        Problem unmarked = p;
        for (SolverBody& b : unmarked.bodies)
            b.isotropic = false;
        std::vector<SolverBody> result[3] = {p.bodies, unmarked.bodies, p.bodies};
        std::vector<Manifold> stored[2] = {p.manifolds, p.manifolds};
        size_t isotropicBatches[2] = {};
        for (int run = 0; run < 2; ++run) {
            ContactSolver solver;
            prepare(solver, run == 0 ? p : unmarked, row.partSpan(), false);
            isotropicBatches[run] = solver.isotropicBatchCount();
            for (int substep = 0; substep < 3; ++substep) {
                solver.warmStart(result[run]);
                solver.solve(result[run], true);
                solver.solve(result[run], true);
                solver.solve(result[run], false);
            }
            storeInto(solver, stored[run]);
        }
        ContactSolver sequential;
        sequential.keepConstraints(true);
        prepare(sequential, p, row.partSpan(), false);
        for (int substep = 0; substep < 3; ++substep) {
            sequential.warmStartSequential(result[2]);
            sequential.solveSequential(result[2], true);
            sequential.solveSequential(result[2], true);
            sequential.solveSequential(result[2], false);
        }
        int signedZeros = 0;
        for (size_t i = 0; i < p.bodies.size(); ++i) {
            QVERIFY(sameBits(result[0][i].v, result[1][i].v) && sameBits(result[0][i].w, result[1][i].w));
            // (The sequential sweep's rows beside the static entry drop its zero terms: equal, but not always
            // with the same zero signs, as in batchesGiveTheSequentialNumbers().)
            QVERIFY(result[0][i].v == result[2][i].v && result[0][i].w == result[2][i].w);
            for (int c = 0; c < 3; ++c)
                signedZeros += result[0][i].w[c] == 0.0 && std::signbit(result[0][i].w[c]) ? 1 : 0;
        }
        QVERIFY(sameImpulses(stored[0], stored[1]));
        qInfo("%zu of %zu bodies marked; %zu isotropic batches; %d angular velocity components -0 after the sweeps",
              marked, p.bodies.size() - 1, isotropicBatches[0], signedZeros);
        ContactSolver::setWidestLanes(8);
        QCOMPARE(isotropicBatches[1], size_t(0));
        QVERIFY(isotropicBatches[0] > 0);
    }

    // Where d x_r is a zero, the full product's row is +0 unless x, y and z all have their sign bits set: a box on the
    // ground (n = +y, no friction rows) with every point at x > 0, z < 0 from its centre has r x n = (0.5, -0, ...) at
    // each, whose y row is +0, so its w.y, -0 at the start, ends +0; d x_y alone would keep it -0.
    void anIsotropicBodyKeepsTheFullProductsZeroSigns_data() {
        QTest::addColumn<int>("lanes");
        QTest::newRow("4 lanes") << 4;
        QTest::newRow("8 lanes") << 8;
    }
    void anIsotropicBodyKeepsTheFullProductsZeroSigns() {
        QFETCH(int, lanes);
        ContactSolver::setWidestLanes(lanes);
        Problem p;
        p.bodies.assign(2, SolverBody{});
        p.centers = {Vec3(0.0), Vec3(0.0, 0.5, 0.0)};
        p.bodies[1].invMass = 1.0;
        p.bodies[1].invInertia = Mat3(6.0);
        p.bodies[1].v = Vec3(0.0, -1.0, 0.0);
        p.bodies[1].w = Vec3(-0.0, -0.0, -0.0);
        Manifold m;
        m.bodyA = 0;
        m.bodyB = 1;
        m.normal = Vec3(0.0, 1.0, 0.0);
        m.pointCount = 4;
        for (int k = 0; k < 4; ++k)
            m.points[k].position = Vec3(0.125 * (k + 1), 0.0, -0.125 * (k + 1));
        p.manifolds = {m};
        p.indexA = {0};
        p.indexB = {1};
        p.friction = {0.0};
        p.restitution = {0.0};
        std::vector<SolverBody> result[2];
        for (int marked = 0; marked < 2; ++marked) {
            Problem q = p;
            q.bodies[0].isotropic = q.bodies[1].isotropic = marked == 1;
            ContactSolverSettings settings;
            settings.restitution = false;
            settings.friction = false; // the friction rows would add zeros of their own to w.y
            std::vector<Manifold*> manifolds = {&q.manifolds[0]};
            ContactSolver solver;
            solver.prepare(manifolds, q.indexA, q.indexB, q.friction, q.restitution, q.bodies, q.centers, 1.0 / 480.0,
                           settings);
            QCOMPARE(solver.isotropicBatchCount(), size_t(marked));
            result[marked] = q.bodies;
            // (No warm start: its twist and friction rows, applied even at zero impulse, would add +0 to w.y.)
            solver.solve(result[marked], true);
            solver.solve(result[marked], false);
        }
        ContactSolver::setWidestLanes(8);
        QVERIFY(result[1][1].v.y > -1.0); // the contact pushed
        QVERIFY(result[1][1].w.y == 0.0 && !std::signbit(result[1][1].w.y));
        QVERIFY(sameBits(result[0][1].v, result[1][1].v) && sameBits(result[0][1].w, result[1][1].w));
    }

    // A sweep after Motion::Unchanged reads each point's separation as the last sweep after Moved took it, and gives
    // the numbers of a sweep that takes it again: three substeps in the world's order (the solve sweeps, then a move of
    // every body, then the relax sweep), once with every sweep Moved and once saying Unchanged wherever nothing moved
    // since the last sweep, and also in the first sweep after prepare(), which solve() takes as Moved. A third run
    // that says Unchanged after a move (the separations a move old) comes out different, so the moves matter here.
    void keptSeparationsGiveTheTakenNumbers_data() { batchesGiveTheSequentialNumbers_data(); }
    void keptSeparationsGiveTheTakenNumbers() {
        using Motion = ContactSolver::Motion;
        const Row row = fetchRow(13);
        const Problem& p = row.problem;
        std::vector<SolverBody> result[3] = {p.bodies, p.bodies, p.bodies};
        std::vector<Manifold> stored[3] = {p.manifolds, p.manifolds, p.manifolds};
        for (int run = 0; run < 3; ++run) {
            std::vector<SolverBody>& bodies = result[run];
            ContactSolver solver;
            prepare(solver, p, row.partSpan());
            const auto motion = [run](bool movedSince) {
                if (run == 0)
                    return Motion::Moved;
                return movedSince && run == 1 ? Motion::Moved : Motion::Unchanged;
            };
            bool movedSince = false; // run 1 says Unchanged even in the first sweep: solve() takes it as Moved
            for (int substep = 0; substep < 3; ++substep) {
                solver.warmStart(bodies);
                for (int it = 0; it < 2; ++it) {
                    solver.solve(bodies, true, motion(movedSince));
                    movedSince = false;
                }
                for (size_t i = 1; i < bodies.size(); ++i) { // a position phase: every body moves on and turns
                    bodies[i].dp += 0.002 * bodies[i].v;
                    bodies[i].dR =
                        glm::mat3_cast(glm::angleAxis(0.01 * (substep + 1.0), Vec3(0.0, 1.0, 0.0))) * bodies[i].dR;
                }
                movedSince = true;
                solver.solve(bodies, false, motion(movedSince));
                movedSince = false;
            }
            storeInto(solver, stored[run]);
        }
        ContactSolver::setWidestLanes(8);
        bool staleDiffers = false;
        for (size_t i = 0; i < p.bodies.size(); ++i) {
            QVERIFY(sameBits(result[0][i].v, result[1][i].v) && sameBits(result[0][i].w, result[1][i].w));
            staleDiffers = staleDiffers || result[0][i].v != result[2][i].v || result[0][i].w != result[2][i].w;
        }
        QVERIFY(sameImpulses(stored[0], stored[1]));
        QVERIFY(staleDiffers);
    }

    void aTeamOfTwoSolvesBitIdentically_data() {
        QTest::addColumn<bool>("parts");
        QTest::addColumn<int>("lanes");
        for (int lanes : {4, 8}) {
            QTest::addRow("level by level, %d lanes", lanes) << false << lanes;
            QTest::addRow("a part each, then the boundary, %d lanes", lanes) << true << lanes;
        }
    }
    // Two threads split every level between barriers, or (with parts) each sweeps a part with no barrier between
    // levels, then one sweeps the boundary. Either gives the bits of one thread sweeping the levels in order.
    void aTeamOfTwoSolvesBitIdentically() {
        QFETCH(bool, parts);
        QFETCH(int, lanes);
        ContactSolver::setWidestLanes(lanes);
        const Problem p = makeProblem(1000, 3000, false, 11);
        const std::vector<uint8_t> part = halves(1000);
        const std::span<const uint8_t> partSpan = parts ? std::span<const uint8_t>(part) : std::span<const uint8_t>();
        std::vector<SolverBody> one = p.bodies, two = p.bodies;
        ContactSolver a, b;
        a.keepConstraints(true); // the sequential sweeps work on the records
        b.keepConstraints(true); // to compare them below
        prepare(a, p, partSpan);
        prepare(b, p, partSpan);
        for (int substep = 0; substep < 4; ++substep) {
            a.warmStart(one);
            a.solve(one, true);
            a.solve(one, false);
        }
        ThreadTeam team(2);
        team.run([&](int member) {
            const auto sweep = [&](auto&& range) {
                if (parts) {
                    const auto [begin, end] = b.segmentBatches(static_cast<size_t>(member));
                    range(begin, end);
                    team.barrier();
                    if (member == 0) {
                        const auto [first, last] = b.segmentBatches(ContactSolver::kBoundarySegment);
                        range(first, last);
                    }
                    team.barrier();
                    return;
                }
                for (size_t level = 0; level < b.levelCount(); ++level) {
                    const auto [begin, end] =
                        ThreadTeam::share(b.batchLevelBegin(level), b.batchLevelEnd(level), member, 2);
                    range(begin, end);
                    team.barrier();
                }
            };
            for (int substep = 0; substep < 4; ++substep) {
                if (member == 0)
                    b.beginSubstep();
                team.barrier();
                sweep([&](size_t begin, size_t end) { b.warmStartBatchRange(two, begin, end); });
                sweep([&](size_t begin, size_t end) { b.solveBatchRange(two, true, begin, end); });
                sweep([&](size_t begin, size_t end) { b.solveBatchRange(two, false, begin, end); });
            }
        });
        for (size_t i = 0; i < one.size(); ++i) {
            QVERIFY(sameBits(one[i].v, two[i].v));
            QVERIFY(sameBits(one[i].w, two[i].w));
        }
        QVERIFY(one[0].v == Vec3(0.0) && two[0].w == Vec3(0.0)); // the static entry is never written
        qInfo("batches of %d lanes", b.laneWidth());
        ContactSolver::setWidestLanes(8);
    }

    // A blow is taken out of the velocities before the substeps (ContactSolver::absorbBlows()): a cube coming down
    // onto a stack resting on the ground stops, and the stack with it, whatever the stack's height, from velocities
    // alone (the manifolds all touching); every manifold down to the ground takes part. A blow below blowSpeed, one
    // between bouncing bodies, or with no passes set, is left to the sweeps.
    void absorbBlowsStopsAStruckStack_data() {
        QTest::addColumn<int>("stack");
        QTest::addColumn<Real>("speed");
        QTest::addColumn<Real>("e");
        QTest::addColumn<int>("passes");
        QTest::addColumn<bool>("absorbed");
        QTest::addColumn<Real>("bound"); // on the fastest body's speed and spin after (m/s, rad/s)
        QTest::newRow("onto 1 at 10 m/s") << 1 << 10.0 << 0.0 << 4 << true << 1e-9;
        QTest::newRow("onto 2 at 10 m/s") << 2 << 10.0 << 0.0 << 4 << true << 1e-9;
        QTest::newRow("onto 4 at 20 m/s") << 4 << 20.0 << 0.0 << 4 << true << 1e-9;
        // Eight high, the passes leave the upper cubes sliding and turning a little (7.3 cm/s measured, 2026-12-06).
        QTest::newRow("onto 8 at 5 m/s") << 8 << 5.0 << 0.0 << 4 << true << 0.1;
        QTest::newRow("slower than blowSpeed") << 2 << 0.9 << 0.0 << 4 << false << 0.0;
        QTest::newRow("bouncing") << 2 << 10.0 << 0.5 << 4 << false << 0.0;
        QTest::newRow("no passes") << 2 << 10.0 << 0.0 << 0 << false << 0.0;
    }
    void absorbBlowsStopsAStruckStack() {
        QFETCH(int, stack);
        QFETCH(Real, speed);
        QFETCH(Real, e);
        QFETCH(int, passes);
        QFETCH(bool, absorbed);
        QFETCH(Real, bound);
        const Problem p = struckStack(stack, speed, e);
        ContactSolverSettings settings;
        settings.contactHertz = 15.0;
        settings.gravity = Vec3(0.0, -9.81, 0.0);
        settings.step = 1.0 / 60.0;
        settings.blowPasses = passes;
        settings.blowShockPasses = passes > 0 ? 2 : 0;
        std::vector<Manifold*> manifolds;
        for (const Manifold& m : p.manifolds)
            manifolds.push_back(const_cast<Manifold*>(&m));
        ContactSolver solver;
        solver.prepare(manifolds, p.indexA, p.indexB, p.friction, p.restitution, p.bodies, p.centers, 1.0 / 360.0,
                       settings);
        QCOMPARE(solver.hasBlows(), absorbed);
        std::vector<SolverBody> bodies = p.bodies;
        solver.absorbBlows(bodies);
        const size_t top = bodies.size() - 1;
        if (!absorbed) {
            QVERIFY(sameBits(bodies[top].v, p.bodies[top].v)); // untouched
            QCOMPARE(solver.counters().blowRows, uint64_t(0));
            return;
        }
        std::vector<uint32_t> expected(static_cast<size_t>(stack) + 1);
        for (size_t i = 0; i < expected.size(); ++i)
            expected[i] = static_cast<uint32_t>(i);
        QCOMPARE(solver.blowConstraints(), expected);
        Real fastest = 0.0;
        for (size_t i = 1; i < bodies.size(); ++i)
            fastest = std::max(fastest, glm::length(bodies[i].v) + glm::length(bodies[i].w));
        qInfo("struck at %.0f m/s: fastest body after %.2e m/s, %llu rows", speed, fastest,
              static_cast<unsigned long long>(solver.counters().blowRows));
        QVERIFY(fastest < bound);
    }

    // The blows fall apart into groups that share no moving body, which a team sweeps apart (two members, each its
    // groups in their order): the velocities are those of one sweep of all of them, to the bit, whichever group a
    // member takes first and however many blows (few are swept by one thread: kMinSharedBlows).
    void absorbBlowsInGroupsGivesTheSameVelocities_data() {
        QTest::addColumn<int>("stacks");
        QTest::newRow("2 stacks, 5 blows") << 2;
        QTest::newRow("6 stacks, 27 blows") << 6;
        QTest::newRow("9 stacks, 54 blows") << 9;
    }
    void absorbBlowsInGroupsGivesTheSameVelocities() {
        QFETCH(int, stacks);
        const Problem p = struckStacks(stacks);
        ContactSolverSettings settings;
        settings.contactHertz = 15.0;
        settings.gravity = Vec3(0.0, -9.81, 0.0);
        settings.step = 1.0 / 60.0;
        settings.blowPasses = 4;
        settings.blowShockPasses = 2;
        std::vector<Manifold*> manifolds;
        for (const Manifold& m : p.manifolds)
            manifolds.push_back(const_cast<Manifold*>(&m));
        const auto run = [&](const ContactSolver::ParallelFor& parallelFor, std::vector<SolverBody>& bodies) {
            ContactSolver solver;
            solver.prepare(manifolds, p.indexA, p.indexB, p.friction, p.restitution, p.bodies, p.centers, 1.0 / 360.0,
                           settings, {}, parallelFor);
            bodies = p.bodies;
            solver.absorbBlows(bodies, parallelFor);
            return std::make_pair(solver.blowConstraints().size(), solver.counters().blowRows);
        };
        std::vector<SolverBody> alone, backwards, team;
        const auto [blows, rows] = run({}, alone);
        QCOMPARE(blows, static_cast<size_t>(stacks * (stacks + 3) / 2)); // every manifold of every stack
        // One thread taking the second member's share first, then a team of two.
        const ContactSolver::ParallelFor reversed = [](size_t count, const std::function<void(size_t, size_t)>& body) {
            for (int member = 1; member >= 0; --member) {
                const auto [begin, end] = ThreadTeam::share(0, count, member, 2);
                body(begin, end);
            }
        };
        ThreadTeam threads(2);
        const ContactSolver::ParallelFor together = [&](size_t count, const std::function<void(size_t, size_t)>& body) {
            threads.run([&](int member) {
                const auto [begin, end] = ThreadTeam::share(0, count, member, 2);
                body(begin, end);
            });
        };
        QCOMPARE(run(reversed, backwards), std::make_pair(blows, rows));
        QCOMPARE(run(together, team), std::make_pair(blows, rows));
        Real fastest = 0.0;
        for (size_t i = 0; i < alone.size(); ++i) {
            for (const std::vector<SolverBody>* other : {&backwards, &team}) {
                QVERIFY(sameBits(alone[i].v, (*other)[i].v));
                QVERIFY(sameBits(alone[i].w, (*other)[i].w));
            }
            fastest = std::max(fastest, glm::length(alone[i].v));
        }
        QVERIFY(fastest < 0.1); // the blows were absorbed: every stack stopped
    }
};

QTEST_APPLESS_MAIN(TestContactSolver)
#include "tst_contactsolver.moc"
