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
                    const auto [begin, end] = ThreadTeam::share(b.levelBegin(level), b.levelEnd(level), member, 2);
                    range(begin, end);
                    team.barrier();
                }
            };
            for (int substep = 0; substep < 4; ++substep) {
                if (member == 0)
                    b.beginSubstep();
                team.barrier();
                sweep([&](size_t begin, size_t end) { b.warmStartRange(two, begin, end); });
                sweep([&](size_t begin, size_t end) { b.solveRange(two, true, begin, end); });
                sweep([&](size_t begin, size_t end) { b.solveRange(two, false, begin, end); });
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
