// Tests of BroadPhase: the incrementally updated pair set must equal the brute-force overlap set of the fat boxes
// on random scenes with moves, removals and anchors, and its order must not depend on the tree layout.
#include "collision/BroadPhase.h"

#include <QTest>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <vector>

using namespace rl;

namespace {

using PairSet = std::set<std::pair<uint32_t, uint32_t>>;

struct Body {
    uint32_t id = 0;
    bool isStatic = false;
    Aabb box;
    Vec3 velocity{0.0};
    ProxyKey key;
    bool alive = true;
};

// A random scene: boxes of 0.2-2 m in a cube sized so that each box has a few neighbours, a fifth of them anchors.
// Body ids are shuffled so that id order and proxy order differ.
struct RandomScene {
    std::mt19937 rng;
    Real worldSize;
    std::vector<Body> bodies;

    RandomScene(uint32_t seed, int count) : rng(seed) {
        worldSize = std::cbrt(static_cast<Real>(count)) * 2.5;
        std::vector<uint32_t> ids(count);
        std::iota(ids.begin(), ids.end(), 0u);
        std::shuffle(ids.begin(), ids.end(), rng);
        for (int i = 0; i < count; ++i) {
            Body b;
            b.id = ids[i];
            b.isStatic = uniform(0, 1) < 0.2;
            b.box = randomBox();
            bodies.push_back(b);
        }
    }
    Real uniform(Real lo, Real hi) { return std::uniform_real_distribution<Real>(lo, hi)(rng); }
    Aabb randomBox() {
        const Vec3 c(uniform(0, worldSize), uniform(0, worldSize), uniform(0, worldSize));
        return Aabb::fromCenterHalfExtents(c, Vec3(uniform(0.1, 1.0), uniform(0.1, 1.0), uniform(0.1, 1.0)));
    }
};

PairSet bruteForce(const BroadPhase& bp, const std::vector<Body>& bodies) {
    PairSet pairs;
    for (size_t i = 0; i < bodies.size(); ++i) {
        if (!bodies[i].alive)
            continue;
        const Aabb& a = bp.fatAabb(bodies[i].key);
        for (size_t j = i + 1; j < bodies.size(); ++j) {
            if (!bodies[j].alive || (bodies[i].isStatic && bodies[j].isStatic))
                continue;
            if (a.overlaps(bp.fatAabb(bodies[j].key)))
                pairs.insert(std::minmax(bodies[i].id, bodies[j].id));
        }
    }
    return pairs;
}

PairSet toSet(std::span<const BroadPhasePair> pairs) {
    PairSet s;
    for (const BroadPhasePair& p : pairs)
        s.insert({p.idA, p.idB});
    return s;
}

ProxyKind kindOf(const Body& b) {
    return b.isStatic ? ProxyKind::Static : ProxyKind::Dynamic;
}

// Runs a deterministic sequence of moves on the scene and returns the concatenated pair lists of every step,
// so two runs can be compared element by element.
std::vector<BroadPhasePair> runSequence(RandomScene scene, bool reverseInsertion, int steps,
                                        const BroadPhase::ParallelFor& parallelFor = {}) {
    BroadPhase bp;
    std::vector<size_t> order(scene.bodies.size());
    std::iota(order.begin(), order.end(), size_t(0));
    if (reverseInsertion)
        std::reverse(order.begin(), order.end());
    for (size_t i : order) {
        Body& b = scene.bodies[i];
        b.key = bp.createProxy(b.box, b.id, kindOf(b)).value();
    }
    std::vector<BroadPhasePair> all;
    std::mt19937 rng(99);
    std::uniform_real_distribution<Real> u(-0.2, 0.2);
    for (int s = 0; s < steps; ++s) {
        bp.updatePairs(parallelFor);
        all.insert(all.end(), bp.pairs().begin(), bp.pairs().end());
        all.insert(all.end(), bp.addedPairs().begin(), bp.addedPairs().end());
        all.insert(all.end(), bp.removedPairs().begin(), bp.removedPairs().end());
        for (Body& b : scene.bodies) {
            if (b.isStatic)
                continue;
            const Vec3 d(u(rng), u(rng), u(rng));
            b.box = Aabb{b.box.min + d, b.box.max + d};
            bp.moveProxy(b.key, b.box, d);
        }
    }
    return all;
}

} // namespace

class TestBroadPhase : public QObject {
    Q_OBJECT

private slots:
    void matchesBruteForce_data();
    void matchesBruteForce();
    void orderIsIndependentOfTreeLayout();
    void splitQueriesGiveTheSamePairs();
    void anchorsNeverPairWithAnchors();
    void destroyRemovesPairs();
    void rejectsBadBoxes();
    void queryAndRayCastCoverBothTrees();
};

void TestBroadPhase::matchesBruteForce_data() {
    QTest::addColumn<uint32_t>("seed");
    QTest::addColumn<int>("count");
    QTest::newRow("seed 1, 200") << 1u << 200;
    QTest::newRow("seed 2, 200") << 2u << 200;
    QTest::newRow("seed 3, 700") << 3u << 700;
    QTest::newRow("seed 4, 2000") << 4u << 2000;
    QTest::newRow("seed 5, 2000") << 5u << 2000;
}

// Each step moves dynamic bodies (small random walks, some long jumps), destroys and re-creates a few bodies and
// moves one anchor; after updatePairs, pairs() must equal brute force exactly, be sorted and free of duplicates,
// and added/removed must be exactly the difference to the previous step.
void TestBroadPhase::matchesBruteForce() {
    QFETCH(uint32_t, seed);
    QFETCH(int, count);
    RandomScene scene(seed, count);
    BroadPhase bp;
    for (Body& b : scene.bodies) {
        auto key = bp.createProxy(b.box, b.id, kindOf(b));
        QVERIFY(key.ok());
        b.key = *key;
    }
    PairSet previous;
    int totalAdded = 0;
    int totalRemoved = 0;
    for (int step = 0; step < 12; ++step) {
        PairSet destroyedPairs;
        if (step > 0) {
            for (Body& b : scene.bodies) {
                if (b.isStatic || !b.alive)
                    continue;
                const Real r = scene.uniform(0, 1);
                Vec3 d(0.0);
                if (r < 0.05) // teleport: leaves its fat box for sure
                    d = Vec3(scene.uniform(-5, 5), scene.uniform(-5, 5), scene.uniform(-5, 5));
                else if (r < 0.7)
                    d = Vec3(scene.uniform(-0.15, 0.15), scene.uniform(-0.15, 0.15), scene.uniform(-0.15, 0.15));
                b.box = Aabb{b.box.min + d, b.box.max + d};
                QVERIFY(bp.moveProxy(b.key, b.box, d).ok());
            }
            // Destroy a few bodies; their pairs vanish at once and are not reported as removed.
            for (int k = 0; k < count / 50; ++k) {
                Body& b = scene.bodies[static_cast<size_t>(scene.uniform(0, count - 1e-9))];
                if (!b.alive)
                    continue;
                for (const auto& p : previous) {
                    if (p.first == b.id || p.second == b.id)
                        destroyedPairs.insert(p);
                }
                bp.destroyProxy(b.key);
                b.alive = false;
            }
            // Bring some back elsewhere, reusing freed proxy ids.
            for (Body& b : scene.bodies) {
                if (!b.alive && scene.uniform(0, 1) < 0.5) {
                    b.box = scene.randomBox();
                    b.key = bp.createProxy(b.box, b.id, kindOf(b)).value();
                    b.alive = true;
                }
            }
            // The editor may move an anchor.
            for (Body& b : scene.bodies) {
                if (b.isStatic && b.alive) {
                    const Vec3 d(1.0, 0.0, 0.0);
                    b.box = Aabb{b.box.min + d, b.box.max + d};
                    QVERIFY(bp.moveProxy(b.key, b.box, Vec3(0.0)).ok());
                    break;
                }
            }
        }
        bp.updatePairs();
        std::string problem;
        QVERIFY2(bp.tree(ProxyKind::Dynamic).validate(&problem), problem.c_str());
        QVERIFY2(bp.tree(ProxyKind::Static).validate(&problem), problem.c_str());

        const PairSet expected = bruteForce(bp, scene.bodies);
        const std::span<const BroadPhasePair> pairs = bp.pairs();
        QVERIFY(std::is_sorted(pairs.begin(), pairs.end()));
        QVERIFY(std::adjacent_find(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
                    return a.idA == b.idA && a.idB == b.idB;
                }) == pairs.end());
        for (const BroadPhasePair& p : pairs) {
            QVERIFY(p.idA < p.idB);
            QCOMPARE(bp.bodyId(p.proxyA), p.idA);
            QCOMPARE(bp.bodyId(p.proxyB), p.idB);
        }
        const PairSet got = toSet(pairs);
        QCOMPARE(got.size(), pairs.size());
        QCOMPARE(got.size(), expected.size());
        QVERIFY(got == expected);

        // added = now \ before; removed = before \ now, leaving out pairs of destroyed bodies.
        PairSet before;
        std::set_difference(previous.begin(), previous.end(), destroyedPairs.begin(), destroyedPairs.end(),
                            std::inserter(before, before.end()));
        PairSet expectedAdded, expectedRemoved;
        std::set_difference(got.begin(), got.end(), before.begin(), before.end(),
                            std::inserter(expectedAdded, expectedAdded.end()));
        std::set_difference(before.begin(), before.end(), got.begin(), got.end(),
                            std::inserter(expectedRemoved, expectedRemoved.end()));
        QVERIFY(std::is_sorted(bp.addedPairs().begin(), bp.addedPairs().end()));
        QVERIFY(std::is_sorted(bp.removedPairs().begin(), bp.removedPairs().end()));
        QVERIFY(toSet(bp.addedPairs()) == expectedAdded);
        QVERIFY(toSet(bp.removedPairs()) == expectedRemoved);
        QCOMPARE(bp.stats().addedPairs, static_cast<int32_t>(expectedAdded.size()));
        QCOMPARE(bp.stats().removedPairs, static_cast<int32_t>(expectedRemoved.size()));
        totalAdded += static_cast<int>(expectedAdded.size());
        totalRemoved += static_cast<int>(expectedRemoved.size());
        previous = got;
    }
    // The scene must actually exercise the incremental paths, or the comparison above proves little.
    QVERIFY2(previous.size() > static_cast<size_t>(count) / 4, qPrintable(QString::number(previous.size())));
    QVERIFY(totalRemoved > 0);
    QVERIFY(totalAdded > static_cast<int>(previous.size()));

    // A step in which nothing moves queries nothing and changes nothing.
    bp.updatePairs();
    QCOMPARE(bp.stats().movedProxies, 0);
    QVERIFY(bp.addedPairs().empty() && bp.removedPairs().empty());
    QVERIFY(toSet(bp.pairs()) == previous);
}

// The pair order is part of the determinism contract: the same bodies give the same list whatever order they were
// inserted in (and so whatever shape the trees took), and repeated runs give the same lists.
void TestBroadPhase::orderIsIndependentOfTreeLayout() {
    const RandomScene scene(7, 800);
    const std::vector<BroadPhasePair> forward = runSequence(scene, false, 6);
    const std::vector<BroadPhasePair> again = runSequence(scene, false, 6);
    const std::vector<BroadPhasePair> reversed = runSequence(scene, true, 6);
    QVERIFY(forward.size() > 800);
    QVERIFY(forward == again);
    QCOMPARE(reversed.size(), forward.size());
    for (size_t i = 0; i < forward.size(); ++i) {
        QCOMPARE(reversed[i].idA, forward[i].idA);
        QCOMPARE(reversed[i].idB, forward[i].idB);
    }
}

void TestBroadPhase::splitQueriesGiveTheSamePairs() {
    // The queries split in chunks, the ranges run in reverse order (as threads may finish in any order) and unevenly:
    // every step's pairs, added and removed lists must equal those of the unsplit queries.
    const RandomScene scene(11, 800);
    size_t calls = 0, largestCount = 0;
    const BroadPhase::ParallelFor reversed = [&](size_t count, const std::function<void(size_t, size_t)>& body) {
        ++calls;
        largestCount = std::max(largestCount, count);
        const size_t cut = count / 3;
        body(cut, count);
        body(0, cut);
    };
    const std::vector<BroadPhasePair> serial = runSequence(scene, false, 6);
    const std::vector<BroadPhasePair> split = runSequence(scene, false, 6, reversed);
    QVERIFY(calls > 0);
    QVERIFY(largestCount >= 8); // 640 dynamic proxies move each step: 10 chunks of 64
    QVERIFY(serial.size() > 800);
    QVERIFY(split == serial);
}

void TestBroadPhase::anchorsNeverPairWithAnchors() {
    BroadPhase bp;
    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    const ProxyKey s1 = bp.createProxy(box, 10, ProxyKind::Static).value();
    bp.createProxy(box, 11, ProxyKind::Static).value();
    bp.updatePairs();
    QVERIFY(bp.pairs().empty());
    const ProxyKey d = bp.createProxy(box, 3, ProxyKind::Dynamic).value();
    bp.updatePairs();
    QCOMPARE(bp.pairs().size(), size_t(2));
    QCOMPARE(bp.pairs()[0].idA, 3u);
    QCOMPARE(bp.pairs()[0].idB, 10u);
    QCOMPARE(bp.pairs()[1].idB, 11u);
    // Anchors get tight boxes, dynamic bodies fat ones.
    QCOMPARE(bp.fatAabb(s1), box);
    QVERIFY(bp.fatAabb(d).contains(box.fattened(0.05)));
}

void TestBroadPhase::destroyRemovesPairs() {
    BroadPhase bp;
    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    const ProxyKey a = bp.createProxy(box, 1, ProxyKind::Dynamic).value();
    bp.createProxy(box, 2, ProxyKind::Dynamic).value();
    bp.createProxy(box, 3, ProxyKind::Static).value();
    bp.updatePairs();
    QCOMPARE(bp.pairs().size(), size_t(3));
    bp.destroyProxy(a);
    QCOMPARE(bp.pairs().size(), size_t(1));
    QCOMPARE(bp.pairs()[0].idA, 2u);
    QCOMPARE(bp.pairs()[0].idB, 3u);
    // Re-created under the same id, it pairs again; the freed proxy id is reused.
    const ProxyKey again = bp.createProxy(box, 1, ProxyKind::Dynamic).value();
    QCOMPARE(again, a);
    bp.updatePairs();
    QCOMPARE(bp.pairs().size(), size_t(3));
    QCOMPARE(bp.addedPairs().size(), size_t(2));
    QVERIFY(bp.removedPairs().empty());
}

void TestBroadPhase::rejectsBadBoxes() {
    BroadPhase bp;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();
    auto bad = bp.createProxy(Aabb{{nan, 0, 0}, {1, 1, 1}}, 42, ProxyKind::Dynamic);
    QVERIFY(!bad.ok());
    QVERIFY(bad.error().message.find("not finite") != std::string::npos);
    QVERIFY(bad.error().object.find("42") != std::string::npos);
    QVERIFY(!bp.createProxy(Aabb{{0, 0, 0}, {inf, 1, 1}}, 1, ProxyKind::Static).ok());
    QVERIFY(!bp.createProxy(Aabb{{2, 0, 0}, {1, 1, 1}}, 1, ProxyKind::Dynamic).ok());
    QCOMPARE(bp.proxyCount(), 0);

    const Aabb box{{0, 0, 0}, {1, 1, 1}};
    const ProxyKey k = bp.createProxy(box, 5, ProxyKind::Dynamic).value();
    const Aabb fat = bp.fatAabb(k);
    QVERIFY(!bp.moveProxy(k, Aabb{{nan, nan, nan}, {nan, nan, nan}}, Vec3(0.0)).ok());
    QCOMPARE(bp.fatAabb(k), fat);
    // A non-finite displacement only loses the prediction; the box stays finite.
    QVERIFY(bp.moveProxy(k, Aabb{{3, 0, 0}, {4, 1, 1}}, Vec3(inf, 0, 0)).ok());
    QVERIFY(bp.fatAabb(k).isValid());
    QVERIFY(bp.fatAabb(k).contains(Aabb{{3, 0, 0}, {4, 1, 1}}));
}

void TestBroadPhase::queryAndRayCastCoverBothTrees() {
    BroadPhase bp;
    // A row along x: dynamic at x = 0, 4, 8, static at x = 2, 6.
    for (uint32_t i = 0; i < 5; ++i) {
        const Aabb box = Aabb::fromCenterHalfExtents(Vec3(2.0 * i, 0, 0), Vec3(0.5));
        bp.createProxy(box, i, i % 2 == 0 ? ProxyKind::Dynamic : ProxyKind::Static).value();
    }
    std::vector<uint32_t> found;
    bp.query(Aabb{{1, -1, -1}, {5, 1, 1}}, [&](ProxyKey k) {
        found.push_back(bp.bodyId(k));
        return true;
    });
    std::sort(found.begin(), found.end());
    QCOMPARE(found, (std::vector<uint32_t>{1, 2}));

    // Closest box from the left along +x is body 0; from x = 1.2, the static body 1 at x = 2 comes before the
    // dynamic body 2, so the clipping must carry over between the trees.
    for (const auto& [startX, expectedId] : {std::pair{-5.0, 0u}, std::pair{1.2, 1u}, std::pair{5.2, 3u}}) {
        uint32_t best = 99;
        Real bestT = std::numeric_limits<Real>::infinity();
        bp.rayCast(Vec3(startX, 0, 0), Vec3(1, 0, 0), 100.0, [&](ProxyKey k, Real maxT) {
            Real t;
            if (!rl::raySlab(bp.fatAabb(k), Vec3(startX, 0, 0), Vec3(1, 0, 0), maxT, t))
                return -1.0;
            if (t < bestT) {
                bestT = t;
                best = bp.bodyId(k);
            }
            return t;
        });
        QCOMPARE(best, expectedId);
    }
}

QTEST_APPLESS_MAIN(TestBroadPhase)
#include "tst_broadphase.moc"
