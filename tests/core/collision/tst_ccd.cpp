// Continuous collision: a 0.1 m cube at 300 m/s never passes a 5 cm wall (20 start offsets), a thin plank spinning
// at 50 rad/s is stopped before it first touches (checked against dense sampling), and the CCD criterion.
#include "CollisionTestShapes.h"
#include "collision/Ccd.h"
#include "collision/Gjk.h"

#include <QtTest>

using namespace rl;
using namespace rl::test;

namespace {

constexpr Real kDt = 1.0 / 60.0;

// First sampled fraction of the step at which the shapes overlap, or 2 when they never do.
Real firstOverlapSampled(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, int samples) {
    for (int i = 0; i <= samples; ++i) {
        const Real f = Real(i) / samples;
        if (gjkOverlap(a, ma.at(f * kDt), b, mb.at(f * kDt)))
            return f;
    }
    return 2.0;
}

} // namespace

class TestCcd : public QObject {
    Q_OBJECT
private slots:
    void bulletCube_data() {
        QTest::addColumn<Real>("gap");
        QTest::addColumn<Real>("tilt");
        for (int k = 0; k < 20; ++k) {
            // Gaps from 1 cm to 4.7 m: all inside one 5 m step; every other offset also tilts the cube.
            const Real gap = 0.01 + k * (4.69 / 19.0);
            QTest::newRow(qPrintable(QString("offset %1").arg(k))) << gap << (k % 2 ? 0.3 * k / 19.0 : 0.0);
        }
    }

    void bulletCube() {
        QFETCH(Real, gap);
        QFETCH(Real, tilt);
        const Shape cube = mustShape(makeBox(Vec3(0.05)));
        const Shape wall = mustShape(makeBox(Vec3(0.025, 2.0, 2.0)));
        Motion mc;
        mc.start = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0.3, 1.0, 0.2), tilt));
        // Place the cube so that its leading point is `gap` in front of the wall's face at x = -0.025.
        const Real lead = mc.start.apply(cube.support(mc.start.rotateInverse(Vec3(1, 0, 0)))).x;
        mc.start.position = Vec3(-0.025 - gap - lead, 0.1, -0.05);
        mc.linearVelocity = Vec3(300.0, 0.0, 0.0);
        const Motion mw{Transform{}, Vec3(0.0), Vec3(0.0)};
        QVERIFY(needsCcd(cube, mc.linearVelocity, mc.angularVelocity, kDt));
        // Without CCD the step would end past the wall.
        QVERIFY(mc.at(kDt).position.x > 0.025 + 0.1);

        const ToiOptions options;
        const ToiResult r = timeOfImpact(cube, mc, wall, mw, kDt, options);
        QCOMPARE(r.status, ToiStatus::Hit);
        QVERIFY(r.iterations <= 3);
        const Transform atHit = mc.at(r.fraction * kDt);
        const GjkResult g = gjkDistance(cube, atHit, wall, Transform{});
        QVERIFY(g.distance >= options.targetSeparation - options.tolerance);
        QVERIFY(g.distance <= options.targetSeparation + options.tolerance);
        QVERIFY(atHit.position.x < -0.025);
        // Pure translation along the wall normal: the travel is the gap less the target separation.
        QVERIFY(std::abs(r.fraction * kDt * 300.0 - (gap - options.targetSeparation)) <= options.tolerance);
        QVERIFY(angleDegrees(r.normal, Vec3(1, 0, 0)) < 0.1);
    }

    void spinningPlank_data() {
        QTest::addColumn<Real>("startAngle");
        QTest::addColumn<Vec3>("velocity");
        for (int k = 0; k < 8; ++k) {
            const Real angle = kPi / 2 - 0.1 - 0.09 * k;
            QTest::newRow(qPrintable(QString("spin only, start %1 rad").arg(angle, 0, 'f', 2))) << angle << Vec3(0.0);
            QTest::newRow(qPrintable(QString("spin and 20 m/s, start %1 rad").arg(angle, 0, 'f', 2)))
                << angle << Vec3(0.0, 20.0, 0.0);
        }
    }

    // A 2 m plank, 2 cm thick, spinning about z at 50 rad/s (0.83 rad per step, tip at 50 m/s) meets a thin post
    // standing at 1.63 rad from the plank's x axis; the start angles leave 0.16 to 0.79 rad to go.
    void spinningPlank() {
        QFETCH(Real, startAngle);
        QFETCH(Vec3, velocity);
        const Shape plank = mustShape(makeBox(Vec3(1.0, 0.01, 0.05)));
        const Shape post = mustShape(makeBox(Vec3(0.01, 0.01, 0.5)));
        Motion mp;
        mp.start = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), startAngle));
        mp.linearVelocity = velocity;
        mp.angularVelocity = Vec3(0.0, 0.0, 50.0);
        const Motion mpost{Transform{Vec3(-0.05, 0.8, 0.0), Mat3(1.0)}, Vec3(0.0), Vec3(0.0)};
        QVERIFY(needsCcd(plank, mp.linearVelocity, mp.angularVelocity, kDt));

        const ToiOptions options;
        const ToiResult r = timeOfImpact(plank, mp, post, mpost, kDt, options);
        const Real sampled = firstOverlapSampled(plank, mp, post, mpost, 20000);
        QVERIFY2(sampled <= 1.0, "the setup must collide within the step");
        QCOMPARE(r.status, ToiStatus::Hit);
        qInfo("toi %.5f, first sampled overlap %.5f, %d iterations", r.fraction, sampled, r.iterations);
        QVERIFY2(r.fraction <= sampled, qPrintable(QString("%1 > %2").arg(r.fraction).arg(sampled)));
        // The tip closes at about 50 m/s: 1 mm of target separation is ~0.0012 of the step.
        QVERIFY2(sampled - r.fraction < 0.005, qPrintable(QString("%1 vs %2").arg(r.fraction).arg(sampled)));
        const GjkResult g = gjkDistance(plank, mp.at(r.fraction * kDt), post, mpost.start);
        QVERIFY(g.distance >= options.targetSeparation - options.tolerance);
        QVERIFY(g.distance <= options.targetSeparation + options.tolerance);
        QVERIFY2(r.iterations < 32, qPrintable(QString::number(r.iterations)));
    }

    // Out of iterations: the fraction returned is still a time at which the shapes are apart.
    void notConvergedIsSafe() {
        const Shape plank = mustShape(makeBox(Vec3(1.0, 0.01, 0.05)));
        const Shape post = mustShape(makeBox(Vec3(0.01, 0.01, 0.5)));
        Motion mp;
        mp.start = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), 1.0));
        mp.angularVelocity = Vec3(0.0, 0.0, 50.0);
        const Motion mpost{Transform{Vec3(-0.05, 0.8, 0.0), Mat3(1.0)}, Vec3(0.0), Vec3(0.0)};
        ToiOptions options;
        options.maxIterations = 2;
        const ToiResult r = timeOfImpact(plank, mp, post, mpost, kDt, options);
        QCOMPARE(r.status, ToiStatus::NotConverged);
        QVERIFY(r.fraction > 0.0 && r.fraction < 1.0);
        QVERIFY(!gjkOverlap(plank, mp.at(r.fraction * kDt), post, mpost.start));
    }

    void missesAndOverlap() {
        const Shape cube = mustShape(makeBox(Vec3(0.05)));
        const Shape wall = mustShape(makeBox(Vec3(0.025, 2.0, 2.0)));
        const Motion mw{Transform{}, Vec3(0.0), Vec3(0.0)};
        Motion away{Transform{Vec3(-1.0, 0.0, 0.0), Mat3(1.0)}, Vec3(-300.0, 0.0, 0.0), Vec3(0.0)};
        QCOMPARE(timeOfImpact(cube, away, wall, mw, kDt).status, ToiStatus::Miss);
        Motion slow{Transform{Vec3(-1.0, 0.0, 0.0), Mat3(1.0)}, Vec3(3.0, 0.0, 0.0), Vec3(0.0)};
        const ToiResult s = timeOfImpact(cube, slow, wall, mw, kDt);
        QCOMPARE(s.status, ToiStatus::Miss);
        QCOMPARE(s.fraction, 1.0);
        Motion inside{Transform{Vec3(0.0), Mat3(1.0)}, Vec3(300.0, 0.0, 0.0), Vec3(0.0)};
        const ToiResult o = timeOfImpact(cube, inside, wall, mw, kDt);
        QCOMPARE(o.status, ToiStatus::Overlapping);
        QCOMPARE(o.fraction, 0.0);
        QCOMPARE(timeOfImpact(cube, slow, wall, mw, std::nan("")).status, ToiStatus::Miss);
    }

    void criterion_data() {
        QTest::addColumn<Real>("speed");
        QTest::addColumn<Real>("spin");
        QTest::addColumn<bool>("expected");
        // 0.1 m cube, 60 Hz: the threshold travel is 2.5 cm per step, 1.5 m/s.
        QTest::newRow("resting") << 0.0 << 0.0 << false;
        QTest::newRow("1 m/s") << 1.0 << 0.0 << false;
        QTest::newRow("2 m/s") << 2.0 << 0.0 << true;
        QTest::newRow("300 m/s") << 300.0 << 0.0 << true;
        QTest::newRow("10 rad/s") << 0.0 << 10.0 << false;
        QTest::newRow("50 rad/s") << 0.0 << 50.0 << true;
    }

    void criterion() {
        QFETCH(Real, speed);
        QFETCH(Real, spin);
        QFETCH(bool, expected);
        const Shape cube = mustShape(makeBox(Vec3(0.05)));
        QCOMPARE(needsCcd(cube, Vec3(speed, 0.0, 0.0), Vec3(0.0, spin, 0.0), kDt), expected);
    }
};

QTEST_APPLESS_MAIN(TestCcd)
#include "tst_ccd.moc"
