// Contact cache: impulses follow feature ids from frame to frame, fall back to the nearest point, start cold for
// new contacts and turned normals, and stale pairs are dropped.
#include "CollisionTestShapes.h"
#include "collision/Collide.h"
#include "collision/ContactCache.h"

#include <QtTest>

using namespace rl;
using namespace rl::test;

namespace {

Manifold restingCube(const Vec3& offset, Real yaw) {
    const Shape base = mustShape(makeBox(Vec3(2.0, 0.5, 2.0)));
    const Shape cube = mustShape(makeBox(Vec3(0.5)));
    Manifold m;
    m.bodyA = 3;
    m.bodyB = 7;
    collide(base, Transform{}, cube, Transform::fromQuat(Vec3(0.0, 0.999, 0.0) + offset, axisAngle(Vec3(0, 1, 0), yaw)),
            0.01, m);
    return m;
}

} // namespace

class TestContactCache : public QObject {
    Q_OBJECT
private slots:
    // A resting cube over several frames: each corner keeps the impulse the "solver" gave it, and the manifold its
    // friction and twist impulses.
    void impulsesFollowCorners() {
        ContactCache cache;
        for (int frame = 0; frame < 5; ++frame) {
            cache.beginFrame();
            Manifold& m = cache.update(restingCube(Vec3(0.0005 * frame, 0.0, 0.0), 0.001 * frame));
            QCOMPARE(m.pointCount, 4);
            for (int i = 0; i < m.pointCount; ++i) {
                // The impulse encodes the corner (in the cube's frame), so a mix-up cannot go unnoticed.
                const Real expected = 10.0 + 3.0 * (m.points[i].localB.x > 0) + 5.0 * (m.points[i].localB.z > 0);
                if (frame > 0)
                    QCOMPARE(m.points[i].normalImpulse, expected);
                else
                    QCOMPARE(m.points[i].normalImpulse, 0.0);
                m.points[i].normalImpulse = expected;
            }
            if (frame > 0) {
                QCOMPARE(m.frictionImpulse, Vec3(-1.0 * frame, 0.0, 0.5));
                QCOMPARE(m.twistImpulse, 0.25 * frame);
            } else {
                QCOMPARE(m.frictionImpulse, Vec3(0.0));
                QCOMPARE(m.twistImpulse, 0.0);
            }
            m.frictionImpulse = Vec3(-1.0 * (frame + 1), 0.0, 0.5);
            m.twistImpulse = 0.25 * (frame + 1);
            cache.endFrame();
            QCOMPARE(cache.size(), size_t(1));
        }
    }

    void warmStartRules_data() {
        QTest::addColumn<uint32_t>("newId");
        QTest::addColumn<Vec3>("moveA");
        QTest::addColumn<Vec3>("normal");
        QTest::addColumn<Real>("expected");
        const Vec3 up(0, 1, 0);
        QTest::newRow("same id, moved far") << 1u << Vec3(0.5, 0, 0) << up << 2.0;
        QTest::newRow("new id, 5 mm away") << 99u << Vec3(0.005, 0, 0) << up << 2.0;
        QTest::newRow("new id, 5 cm away") << 99u << Vec3(0.05, 0, 0) << up << 0.0;
        QTest::newRow("same id, normal turned 45 deg") << 1u << Vec3(0.0) << glm::normalize(Vec3(1, 1, 0)) << 0.0;
        QTest::newRow("same id, normal turned 20 deg")
            << 1u << Vec3(0.0) << Vec3(std::sin(0.349), std::cos(0.349), 0.0) << 2.0;
    }

    void warmStartRules() {
        QFETCH(uint32_t, newId);
        QFETCH(Vec3, moveA);
        QFETCH(Vec3, normal);
        QFETCH(Real, expected);
        Manifold old;
        old.pointCount = 2;
        old.points[0].featureId = 1;
        old.points[0].localA = Vec3(0.0);
        old.points[0].normalImpulse = 2.0;
        old.points[1].featureId = 2;
        old.points[1].localA = Vec3(0.0, 0.0, 1.0);
        old.points[1].normalImpulse = 4.0;
        old.frictionImpulse = Vec3(0.5, 0.0, -0.25);
        old.twistImpulse = 0.125;
        Manifold now;
        now.normal = normal;
        now.pointCount = 1;
        now.points[0].featureId = newId;
        now.points[0].localA = moveA;
        now.points[0].normalImpulse = 123.0; // must be overwritten either way
        now.frictionImpulse = Vec3(7.0);
        now.twistImpulse = 7.0;
        const int matched = warmStart(old, now);
        QCOMPARE(now.points[0].normalImpulse, expected);
        QCOMPARE(matched, expected > 0.0 ? 1 : 0);
        // The manifold's friction goes with any matched point, and only then.
        QCOMPARE(now.frictionImpulse, matched > 0 ? old.frictionImpulse : Vec3(0.0));
        QCOMPARE(now.twistImpulse, matched > 0 ? old.twistImpulse : 0.0);
    }

    // A pair missing for a frame is dropped; when it comes back it starts cold.
    void stalePairsDropped() {
        ContactCache cache;
        cache.beginFrame();
        Manifold& m = cache.update(restingCube(Vec3(0.0), 0.0));
        m.points[0].normalImpulse = 5.0;
        cache.endFrame();
        QVERIFY(cache.find(3, 7) != nullptr);
        QVERIFY(cache.find(7, 3) == nullptr);
        cache.beginFrame();
        cache.endFrame();
        QCOMPARE(cache.size(), size_t(0));
        cache.beginFrame();
        const Manifold& again = cache.update(restingCube(Vec3(0.0), 0.0));
        for (int i = 0; i < again.pointCount; ++i)
            QCOMPARE(again.points[i].normalImpulse, 0.0);
        cache.endFrame();
    }
};

QTEST_APPLESS_MAIN(TestContactCache)
#include "tst_contactcache.moc"
