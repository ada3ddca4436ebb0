// Tests of Aabb and DynamicTree: structure invariants under random inserts, moves and removals, and queries and
// ray casts that must agree exactly with brute force over the fat boxes.
#include "collision/Aabb.h"
#include "collision/DynamicTree.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

using namespace rl;

Q_DECLARE_METATYPE(rl::Vec3)

namespace {

struct RandomBoxes {
    std::mt19937 rng;
    Real worldSize;
    explicit RandomBoxes(uint32_t seed, Real size) : rng(seed), worldSize(size) {}

    Real uniform(Real lo, Real hi) { return std::uniform_real_distribution<Real>(lo, hi)(rng); }
    Vec3 point() { return {uniform(0, worldSize), uniform(0, worldSize), uniform(0, worldSize)}; }
    Aabb box() {
        return Aabb::fromCenterHalfExtents(point(), Vec3(uniform(0.1, 1.0), uniform(0.1, 1.0), uniform(0.1, 1.0)));
    }
};

std::vector<int32_t> sorted(std::vector<int32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

class TestDynamicTree : public QObject {
    Q_OBJECT

private slots:
    void aabbBasics();
    void raySlab_data();
    void raySlab();
    void randomOperations_data();
    void randomOperations();
    void testedThenReinsertedMatchesMoveProxy_data();
    void testedThenReinsertedMatchesMoveProxy();
    void jitterDoesNotReinsert();
    void fastBodyStretchesFatBox();
    void treeQuality_data();
    void treeQuality();
    void rayCastClosest();
    void emptyTree();
};

void TestDynamicTree::aabbBasics() {
    const Aabb a{{0, 0, 0}, {1, 2, 3}};
    const Aabb b{{0.5, 1, 1}, {4, 4, 4}};
    QCOMPARE(a.surfaceArea(), 2.0 * (1 * 2 + 2 * 3 + 3 * 1));
    QVERIFY(a.overlaps(b));
    QVERIFY(!a.contains(b));
    const Aabb u = unionOf(a, b);
    QVERIFY(u.contains(a) && u.contains(b));
    QCOMPARE(u.min, Vec3(0, 0, 0));
    QCOMPARE(u.max, Vec3(4, 4, 4));
    // Touching boxes overlap: resting contact must not flicker in and out of the pair set.
    QVERIFY(a.overlaps(Aabb{{1, 0, 0}, {2, 1, 1}}));
    QVERIFY(!a.overlaps(Aabb{{1.0001, 0, 0}, {2, 1, 1}}));
    const Aabb f = a.fattened(0.5);
    QCOMPARE(f.min, Vec3(-0.5));
    QCOMPARE(f.max, Vec3(1.5, 2.5, 3.5));
    const Aabb e = a.extendedBy({-1, 0, 2});
    QCOMPARE(e.min, Vec3(-1, 0, 0));
    QCOMPARE(e.max, Vec3(1, 2, 5));
    QVERIFY(a.isValid());
    QVERIFY(!Aabb({{1, 0, 0}, {0, 1, 1}}).isValid());
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    QVERIFY(!Aabb({{nan, 0, 0}, {1, 1, 1}}).isValid());
    QVERIFY(!Aabb({{0, 0, 0}, {std::numeric_limits<Real>::infinity(), 1, 1}}).isValid());
}

void TestDynamicTree::raySlab_data() {
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("direction");
    QTest::addColumn<Real>("tMax");
    QTest::addColumn<bool>("hit");
    QTest::addColumn<Real>("enter");
    // Unit cube [0,1]^3.
    QTest::newRow("front face") << Vec3(-2, 0.5, 0.5) << Vec3(1, 0, 0) << 10.0 << true << 2.0;
    QTest::newRow("too short") << Vec3(-2, 0.5, 0.5) << Vec3(1, 0, 0) << 1.9 << false << 0.0;
    QTest::newRow("pointing away") << Vec3(-2, 0.5, 0.5) << Vec3(-1, 0, 0) << 10.0 << false << 0.0;
    QTest::newRow("inside") << Vec3(0.5, 0.5, 0.5) << Vec3(0, 1, 0) << 10.0 << true << 0.0;
    QTest::newRow("parallel outside") << Vec3(-1, 2, 0.5) << Vec3(1, 0, 0) << 10.0 << false << 0.0;
    // The origin lies exactly on the y = 0 slab plane with a zero y direction: 0 * inf would be NaN.
    QTest::newRow("parallel on face plane") << Vec3(-1, 0, 0.5) << Vec3(1, 0, 0) << 10.0 << true << 1.0;
    QTest::newRow("diagonal") << Vec3(-1, -1, -1) << Vec3(1, 1, 1) << 10.0 << true << 1.0;
    QTest::newRow("scaled direction") << Vec3(-3, 0.5, 0.5) << Vec3(4, 0, 0) << 1.0 << true << 0.75;
}

void TestDynamicTree::raySlab() {
    QFETCH(Vec3, origin);
    QFETCH(Vec3, direction);
    QFETCH(Real, tMax);
    QFETCH(bool, hit);
    QFETCH(Real, enter);
    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    Real t = -1.0;
    QCOMPARE(rl::raySlab(box, origin, direction, tMax, t), hit);
    if (hit)
        QVERIFY(std::abs(t - enter) < 1e-12);
}

void TestDynamicTree::randomOperations_data() {
    QTest::addColumn<uint32_t>("seed");
    QTest::addColumn<int>("count");
    QTest::newRow("seed 1, 100") << 1u << 100;
    QTest::newRow("seed 2, 500") << 2u << 500;
    QTest::newRow("seed 3, 2000") << 3u << 2000;
    QTest::newRow("seed 4, 2000") << 4u << 2000;
}

// Inserts, moves, destroys and re-creates proxies at random; after every round the tree must be valid, every fat
// box must contain its tight box, and queries must return exactly the brute-force overlap set.
void TestDynamicTree::randomOperations() {
    QFETCH(uint32_t, seed);
    QFETCH(int, count);
    const Real worldSize = std::cbrt(static_cast<Real>(count)) * 3.0;
    RandomBoxes gen(seed, worldSize);
    DynamicTree tree;
    std::vector<int32_t> proxies;
    std::vector<Aabb> tight;
    for (int i = 0; i < count; ++i) {
        tight.push_back(gen.box());
        proxies.push_back(tree.createProxy(tight.back(), static_cast<uint32_t>(i)));
    }
    std::string problem;
    QVERIFY2(tree.validate(&problem), problem.c_str());
    QCOMPARE(tree.proxyCount(), count);

    for (int round = 0; round < 8; ++round) {
        for (int i = 0; i < count; ++i) {
            const Vec3 step(gen.uniform(-0.3, 0.3), gen.uniform(-0.3, 0.3), gen.uniform(-0.3, 0.3));
            tight[i] = Aabb{tight[i].min + step, tight[i].max + step};
            tree.moveProxy(proxies[i], tight[i], step);
        }
        // Destroy and re-create a tenth, so freed node ids get reused.
        for (int k = 0; k < count / 10; ++k) {
            const int i = static_cast<int>(gen.uniform(0, count - 1e-9));
            tree.destroyProxy(proxies[i]);
            tight[i] = gen.box();
            proxies[i] = tree.createProxy(tight[i], static_cast<uint32_t>(i));
        }
        QVERIFY2(tree.validate(&problem), problem.c_str());
        QCOMPARE(tree.proxyCount(), count);
        for (int i = 0; i < count; ++i) {
            QVERIFY(tree.fatAabb(proxies[i]).contains(tight[i]));
            QCOMPARE(tree.userId(proxies[i]), static_cast<uint32_t>(i));
        }
        for (int q = 0; q < 20; ++q) {
            const Aabb query = Aabb::fromCenterHalfExtents(gen.point(), Vec3(gen.uniform(0.5, 4.0)));
            std::vector<int32_t> found;
            tree.query(query, [&](int32_t p) {
                found.push_back(p);
                return true;
            });
            std::vector<int32_t> expected;
            for (int i = 0; i < count; ++i) {
                if (tree.fatAabb(proxies[i]).overlaps(query))
                    expected.push_back(proxies[i]);
            }
            QCOMPARE(sorted(found), sorted(expected));
        }
    }
    for (int i = 0; i < count; ++i)
        tree.destroyProxy(proxies[i]);
    QVERIFY2(tree.validate(&problem), problem.c_str());
    QCOMPARE(tree.proxyCount(), 0);
    QCOMPARE(tree.nodeCount(), 0);
}

void TestDynamicTree::testedThenReinsertedMatchesMoveProxy_data() {
    QTest::addColumn<uint32_t>("seed");
    QTest::addColumn<int>("count");
    QTest::newRow("seed 5, 300") << 5u << 300;
    QTest::newRow("seed 6, 2000") << 6u << 2000;
}

// The world tests every proxy first (fatBoxIfMoved(), on several threads) and reinserts afterwards: that must build
// the same tree as moveProxy() one proxy after the other, and the test alone must change nothing.
void TestDynamicTree::testedThenReinsertedMatchesMoveProxy() {
    QFETCH(uint32_t, seed);
    QFETCH(int, count);
    RandomBoxes gen(seed, std::cbrt(static_cast<Real>(count)) * 3.0);
    DynamicTree one, split;
    std::vector<int32_t> proxies;
    std::vector<Aabb> tight;
    for (int i = 0; i < count; ++i) {
        tight.push_back(gen.box());
        proxies.push_back(one.createProxy(tight.back(), static_cast<uint32_t>(i)));
        QCOMPARE(split.createProxy(tight.back(), static_cast<uint32_t>(i)), proxies.back());
    }
    int reinsertedTotal = 0;
    for (int round = 0; round < 6; ++round) {
        std::vector<Vec3> steps(static_cast<size_t>(count));
        for (int i = 0; i < count; ++i) {
            steps[i] = Vec3(gen.uniform(-0.3, 0.3), gen.uniform(-0.3, 0.3), gen.uniform(-0.3, 0.3));
            tight[i] = Aabb{tight[i].min + steps[i], tight[i].max + steps[i]};
        }
        std::vector<bool> moved(static_cast<size_t>(count));
        for (int i = 0; i < count; ++i)
            moved[i] = one.moveProxy(proxies[i], tight[i], steps[i]);
        std::vector<std::optional<Aabb>> fat(static_cast<size_t>(count));
        for (int i = 0; i < count; ++i) {
            const Aabb before = split.fatAabb(proxies[i]);
            fat[i] = split.fatBoxIfMoved(proxies[i], tight[i], steps[i]);
            QCOMPARE(split.fatAabb(proxies[i]), before);
            QCOMPARE(fat[i].has_value(), bool(moved[i]));
        }
        for (int i = 0; i < count; ++i)
            if (fat[i]) {
                split.reinsertProxy(proxies[i], *fat[i]);
                ++reinsertedTotal;
            }
        std::string problem;
        QVERIFY2(split.validate(&problem), problem.c_str());
        QCOMPARE(split.nodeCount(), one.nodeCount());
        for (int i = 0; i < count; ++i)
            QCOMPARE(split.fatAabb(proxies[i]), one.fatAabb(proxies[i]));
        const Aabb query = Aabb::fromCenterHalfExtents(gen.point(), Vec3(3.0));
        std::vector<int32_t> foundOne, foundSplit;
        one.query(query, [&](int32_t p) {
            foundOne.push_back(p);
            return true;
        });
        split.query(query, [&](int32_t p) {
            foundSplit.push_back(p);
            return true;
        });
        QCOMPARE(foundSplit, foundOne); // the same tree, so the same order
    }
    QVERIFY(reinsertedTotal > count); // the rounds moved proxies out of their fat boxes
}

void TestDynamicTree::jitterDoesNotReinsert() {
    DynamicTreeSettings settings;
    settings.margin = 0.1;
    DynamicTree tree(settings);
    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    const int32_t p = tree.createProxy(box, 7);
    const Aabb fat = tree.fatAabb(p);
    QCOMPARE(fat, box.fattened(0.1));
    int reinserted = 0;
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> jitter(-0.09, 0.09);
    for (int i = 0; i < 100; ++i) {
        const Vec3 d(jitter(rng), jitter(rng), jitter(rng));
        reinserted += tree.moveProxy(p, Aabb{box.min + d, box.max + d}, Vec3(0.0)) ? 1 : 0;
    }
    QCOMPARE(reinserted, 0);
    QCOMPARE(tree.fatAabb(p), fat);
    // Leaving the fat box forces a reinsertion with a box that holds the new position.
    const Aabb moved{box.min + Vec3(0.2, 0, 0), box.max + Vec3(0.2, 0, 0)};
    QVERIFY(tree.moveProxy(p, moved, Vec3(0.0)));
    QVERIFY(tree.fatAabb(p).contains(moved));
}

void TestDynamicTree::fastBodyStretchesFatBox() {
    DynamicTreeSettings settings;
    settings.margin = 0.1;
    settings.displacementMultiplier = 2.0;
    DynamicTree tree(settings);
    Aabb box{{0, 0, 0}, {1, 1, 1}};
    const int32_t p = tree.createProxy(box, 0);
    const Vec3 step(0.5, 0, 0); // per update
    int reinserted = 0;
    const int steps = 100;
    for (int i = 0; i < steps; ++i) {
        box = Aabb{box.min + step, box.max + step};
        reinserted += tree.moveProxy(p, box, step) ? 1 : 0;
        QVERIFY(tree.fatAabb(p).contains(box));
    }
    // The box is stretched 2 steps ahead, so a steady body is reinserted about every other step, not every step.
    QVERIFY2(reinserted <= steps * 6 / 10, qPrintable(QString::number(reinserted)));
    // The stretch is on the side of motion only.
    QVERIFY(tree.fatAabb(p).max.x - box.max.x > 0.5);
    QVERIFY(box.min.x - tree.fatAabb(p).min.x <= 0.1 + 1e-12);

    // Stopping shrinks a box that has become far larger than needed.
    QVERIFY(tree.moveProxy(p, box, Vec3(0.0)));
    QCOMPARE(tree.fatAabb(p), box.fattened(0.1));
}

void TestDynamicTree::treeQuality_data() {
    QTest::addColumn<QString>("layout");
    QTest::addColumn<int>("count");
    QTest::newRow("random 4096") << "random" << 4096;
    QTest::newRow("sorted row 4096") << "row" << 4096;
    QTest::newRow("sorted grid 4096") << "grid" << 4096;
}

// Inserting boxes in sorted order is the classic way to degenerate an incremental tree into a list. Rotations
// must keep it logarithmic. The bound 2 log2(n) leaves room over the ideal log2(n) while ruling out lists.
void TestDynamicTree::treeQuality() {
    QFETCH(QString, layout);
    QFETCH(int, count);
    DynamicTree tree;
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(0.0, 1.0);
    const int side = static_cast<int>(std::round(std::cbrt(count)));
    for (int i = 0; i < count; ++i) {
        Vec3 c;
        if (layout == "random")
            c = Vec3(u(rng), u(rng), u(rng)) * 50.0;
        else if (layout == "row")
            c = Vec3(2.0 * i, 0, 0);
        else
            c = Vec3(2.0 * (i % side), 2.0 * ((i / side) % side), 2.0 * (i / (side * side)));
        tree.createProxy(Aabb::fromCenterHalfExtents(c, Vec3(0.5)), static_cast<uint32_t>(i));
    }
    std::string problem;
    QVERIFY2(tree.validate(&problem), problem.c_str());
    const Real bound = 2.0 * std::log2(static_cast<Real>(count));
    QVERIFY2(tree.height() <= bound,
             qPrintable(
                 QStringLiteral("height %1 > %2, area ratio %3").arg(tree.height()).arg(bound).arg(tree.areaRatio())));
}

void TestDynamicTree::rayCastClosest() {
    // Brute force: the closest fat box entry along random rays must be the first hit the clipping cast keeps.
    RandomBoxes gen(21, 30.0);
    DynamicTree tree;
    std::vector<int32_t> proxies;
    for (int i = 0; i < 1000; ++i)
        proxies.push_back(tree.createProxy(gen.box(), static_cast<uint32_t>(i)));
    int hits = 0;
    for (int r = 0; r < 200; ++r) {
        const Vec3 origin = gen.point();
        Vec3 dir(gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1));
        dir = glm::normalize(dir);
        const Real maxT = 40.0;
        Real bestT = std::numeric_limits<Real>::infinity();
        int32_t best = -1;
        for (int32_t p : proxies) {
            Real t;
            if (rl::raySlab(tree.fatAabb(p), origin, dir, maxT, t) && t < bestT) {
                bestT = t;
                best = p;
            }
        }
        Real castT = std::numeric_limits<Real>::infinity();
        int32_t castBest = -1;
        int visited = 0;
        tree.rayCast(origin, dir, maxT, [&](int32_t p, Real currentMax) {
            ++visited;
            Real t;
            if (!rl::raySlab(tree.fatAabb(p), origin, dir, currentMax, t))
                return -1.0;
            if (t < castT) {
                castT = t;
                castBest = p;
            }
            return t;
        });
        QCOMPARE(castBest, best);
        if (best >= 0) {
            ++hits;
            QCOMPARE(castT, bestT);
            // Clipping and near-first order mean only a handful of leaves are tested, not all thousand.
            QVERIFY2(visited < 100, qPrintable(QString::number(visited)));
        }
    }
    QVERIFY(hits > 20);

    // Returning 0 stops at the first leaf reached.
    int calls = 0;
    tree.rayCast(Vec3(-10, 15, 15), Vec3(1, 0, 0), 100.0, [&](int32_t, Real) {
        ++calls;
        return 0.0;
    });
    QVERIFY(calls <= 1);
}

void TestDynamicTree::emptyTree() {
    DynamicTree tree;
    QVERIFY(tree.validate());
    QCOMPARE(tree.height(), 0);
    int calls = 0;
    tree.query(Aabb{{-1e9, -1e9, -1e9}, {1e9, 1e9, 1e9}}, [&](int32_t) { return ++calls > 0; });
    tree.rayCast(Vec3(0), Vec3(1, 0, 0), 1e9, [&](int32_t, Real) { return Real(++calls); });
    QCOMPARE(calls, 0);
    const int32_t p = tree.createProxy(Aabb{{0, 0, 0}, {1, 1, 1}}, 3);
    QVERIFY(tree.validate());
    QCOMPARE(tree.height(), 0);
    tree.destroyProxy(p);
    QVERIFY(tree.validate());
    QVERIFY(!tree.isProxy(p));
}

QTEST_APPLESS_MAIN(TestDynamicTree)
#include "tst_dynamictree.moc"
