// The contact solver's level schedule: constraints of one level share no moving body, and constraints that share one
// keep their manifold order, so that solving level by level, on one thread or on several, does what the sequential
// sweep does. Solving on a team of two gives bit-identical velocities.
#include "dynamics/ContactSolver.h"
#include "world/ThreadTeam.h"

#include <QTest>

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
};

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
        b.invInertia = Mat3(6.0 * b.invMass);
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
        p.manifolds.push_back(m);
        p.indexA.push_back(a);
        p.indexB.push_back(b);
        p.friction.push_back(0.6);
        p.restitution.push_back(0.0);
    }
    return p;
}

void prepare(ContactSolver& solver, const Problem& p) {
    ContactSolverSettings settings;
    settings.contactHertz = 120.0;
    solver.prepare(p.manifolds, p.indexA, p.indexB, p.friction, p.restitution, p.bodies, p.centers, 1.0 / 480.0,
                   settings);
}

bool sameBits(const Vec3& a, const Vec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

class TestContactSolver : public QObject {
    Q_OBJECT
private slots:
    void levelsKeepTheSequentialOrder_data() {
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("constraints");
        QTest::addColumn<bool>("chain");
        QTest::newRow("tower of 40") << 40 << 40 << true;
        QTest::newRow("200 random contacts among 60 bodies") << 60 << 200 << false;
        QTest::newRow("2000 random contacts among 1000 bodies") << 1000 << 2000 << false;
    }
    void levelsKeepTheSequentialOrder() {
        QFETCH(int, bodies);
        QFETCH(int, constraints);
        QFETCH(bool, chain);
        const Problem p = makeProblem(bodies, constraints, chain, 7);
        ContactSolver solver;
        prepare(solver, p);
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
        // Constraints that share a moving body are solved in manifold order.
        for (int i = 0; i < constraints; ++i)
            for (int j = i + 1; j < constraints; ++j) {
                const bool share = (p.indexA[i] != 0 && (p.indexA[i] == p.indexA[j] || p.indexA[i] == p.indexB[j])) ||
                                   (p.indexB[i] != 0 && (p.indexB[i] == p.indexA[j] || p.indexB[i] == p.indexB[j]));
                if (share)
                    QVERIFY(levelOf[i] < levelOf[j]);
            }
        if (chain)
            QCOMPARE(solver.levelCount(), size_t(constraints)); // a tower has no two independent contacts
        qInfo("%d constraints in %zu levels", constraints, solver.levelCount());
    }

    // The batched sweeps (four constraints of a level side by side) give the numbers of the scalar sweep in manifold
    // order: velocities, impulses and impact records, through warm starts, soft and relax sweeps, with bodies that
    // have moved and turned since the step began.
    void batchesGiveTheSequentialNumbers_data() {
        QTest::addColumn<int>("bodies");
        QTest::addColumn<int>("constraints");
        QTest::addColumn<bool>("chain");
        QTest::newRow("tower of 40") << 40 << 40 << true;
        QTest::newRow("203 random contacts among 60 bodies") << 60 << 203 << false;
        QTest::newRow("3001 random contacts among 1000 bodies") << 1000 << 3001 << false;
    }
    void batchesGiveTheSequentialNumbers() {
        QFETCH(int, bodies);
        QFETCH(int, constraints);
        QFETCH(bool, chain);
        Problem p = makeProblem(bodies, constraints, chain, 5);
        std::mt19937 rng(3);
        std::uniform_real_distribution<Real> u(-0.01, 0.01);
        for (size_t i = 1; i < p.bodies.size(); ++i) {
            p.bodies[i].dp = Vec3(u(rng), u(rng), u(rng));
            p.bodies[i].dR = glm::mat3_cast(glm::angleAxis(10.0 * u(rng), glm::normalize(Vec3(u(rng), 0.01, u(rng)))));
        }
        std::vector<SolverBody> sequential = p.bodies, batched = p.bodies;
        ContactSolver a, b;
        prepare(a, p);
        prepare(b, p);
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
        int pushing = 0;
        for (size_t i = 0; i < a.constraints().size(); ++i) {
            const ContactConstraint& ca = a.constraints()[i];
            const ContactConstraint& cb = b.constraints()[i];
            for (int k = 0; k < ca.pointCount; ++k) {
                QCOMPARE(cb.points[k].normalImpulse, ca.points[k].normalImpulse);
                QCOMPARE(cb.points[k].tangentImpulse[0], ca.points[k].tangentImpulse[0]);
                QCOMPARE(cb.points[k].tangentImpulse[1], ca.points[k].tangentImpulse[1]);
                QCOMPARE(cb.points[k].maxNormalImpulse, ca.points[k].maxNormalImpulse);
                QCOMPARE(cb.points[k].relativeVelocity, ca.points[k].relativeVelocity);
                pushing += ca.points[k].normalImpulse > 0.0 ? 1 : 0;
            }
        }
        qInfo("%d constraints, %d solved deepest point first, %d points pushing", constraints, impacts, pushing);
        QVERIFY(pushing > 0);
    }

    void aTeamOfTwoSolvesBitIdentically() {
        const Problem p = makeProblem(1000, 3000, false, 11);
        std::vector<SolverBody> one = p.bodies, two = p.bodies;
        ContactSolver a, b;
        prepare(a, p);
        prepare(b, p);
        for (int substep = 0; substep < 4; ++substep) {
            a.warmStart(one);
            a.solve(one, true);
            a.solve(one, false);
        }
        ThreadTeam team(2);
        team.run([&](int member) {
            const auto sweep = [&](auto&& range) {
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
    }
};

QTEST_APPLESS_MAIN(TestContactSolver)
#include "tst_contactsolver.moc"
