// EPA penetration depth, normal and witness points against analytic answers (Jolt's EPA tests are the model:
// normals within 0.1 degree, points within 1e-3 m), against an exact SAT on random hulls, and its SAT fallback.
#include "CollisionTestShapes.h"
#include "collision/Epa.h"
#include "collision/Penetration.h"
#include "collision/Sat.h"

#include <QtTest>

#include <glm/gtx/quaternion.hpp>

using namespace rl;
using namespace rl::test;

namespace {

struct DepthCase {
    const char* name;
    Shape a;
    Transform xa;
    Shape b;
    Transform xb;
    Real depth;
    Vec3 normal;
    bool uniquePoints; // false for face contacts, where only the planes of the witnesses are known
    Vec3 pointA;
    Vec3 pointB;
};

Transform at(const Vec3& p) {
    return {p, Mat3(1.0)};
}

std::vector<DepthCase> depthCases() {
    const Shape unit = mustShape(makeBox(Vec3(0.5)));
    const Real s2 = std::sqrt(2.0), s3 = std::sqrt(3.0);
    const Shape plate = mustShape(makeBox(Vec3(1.0, 0.5, 1.0)));
    const Shape ball = mustShape(makeSphere(0.3));
    const Shape floor = mustShape(makeHull(
        flatPolygonHull({Vec3(-5, 0, -5), Vec3(5, 0, -5), Vec3(5, 0, 5), Vec3(-5, 0, 5)}, Vec3(0.0, 1.0, 0.0))));
    const Quat cornerDown = glm::rotation(glm::normalize(Vec3(-1.0)), Vec3(0.0, -1.0, 0.0));
    const Shape km = mustShape(makeBox(Vec3(500.0)));
    const Shape mm = mustShape(makeBox(Vec3(0.0005)));
    const Vec3 n1(0.6, 0.8, 0.0), ne = glm::normalize(Vec3(1, 1, 0));
    return {
        {"sphere-sphere", mustShape(makeSphere(0.5)), at(Vec3(0.0)), ball, at(Vec3(0.3, 0.4, 0.0)), 0.3, n1, true,
         0.5 * n1, Vec3(0.3, 0.4, 0.0) - 0.3 * n1},
        {"box-sphere face", mustShape(makeBox(Vec3(1.0, 0.5, 2.0))), at(Vec3(0.0)), ball, at(Vec3(0.2, 0.7, -0.5)), 0.1,
         Vec3(0, 1, 0), true, Vec3(0.2, 0.5, -0.5), Vec3(0.2, 0.4, -0.5)},
        {"box-sphere centre inside", mustShape(makeBox(Vec3(1.0, 0.5, 2.0))), at(Vec3(0.0)), ball,
         at(Vec3(0.9, 0.0, 0.0)), 0.4, Vec3(1, 0, 0), true, Vec3(1.0, 0.0, 0.0), Vec3(0.6, 0.0, 0.0)},
        {"box-sphere edge", unit, at(Vec3(0.0)), mustShape(makeSphere(0.5)), at(Vec3(0.8, 0.8, 0.1)), 0.5 - 0.3 * s2,
         ne, true, Vec3(0.5, 0.5, 0.1), Vec3(0.8, 0.8, 0.1) - 0.5 * ne},
        {"box-box face on face", plate, at(Vec3(0.0)), unit, at(Vec3(0.3, 0.9, -0.2)), 0.1, Vec3(0, 1, 0), false,
         Vec3(0.0, 0.5, 0.0), Vec3(0.0, 0.4, 0.0)},
        {"box-box edge on edge", unit, Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), kPi / 4)), unit,
         Transform::fromQuat(Vec3(0.0, 1.3, 0.0), axisAngle(Vec3(1, 0, 0), kPi / 4)), s2 - 1.3, Vec3(0, 1, 0), true,
         Vec3(0.0, s2 / 2, 0.0), Vec3(0.0, 1.3 - s2 / 2, 0.0)},
        {"box-box vertex on face", plate, at(Vec3(0.0)), unit,
         Transform::fromQuat(Vec3(0.1, 0.5 + 0.5 * s3 - 0.05, 0.2), cornerDown), 0.05, Vec3(0, 1, 0), true,
         Vec3(0.1, 0.5, 0.2), Vec3(0.1, 0.45, 0.2)},
        {"touching faces", unit, at(Vec3(0.0)), unit, at(Vec3(0.2, 1.0, 0.1)), 0.0, Vec3(0, 1, 0), false,
         Vec3(0.0, 0.5, 0.0), Vec3(0.0, 0.5, 0.0)},
        {"coincident boxes", mustShape(makeBox(Vec3(0.5, 0.3, 0.7))), at(Vec3(1.0, 2.0, 3.0)),
         mustShape(makeBox(Vec3(0.5, 0.3, 0.7))), at(Vec3(1.0, 2.0, 3.0)), 0.6, Vec3(0, 1, 0), false,
         Vec3(0.0, 2.3, 0.0), Vec3(0.0, 1.7, 0.0)},
        {"box inside box", mustShape(makeBox(Vec3(2.0))), at(Vec3(0.0)), mustShape(makeBox(Vec3(0.25))),
         at(Vec3(0.5, 0.0, 0.3)), 1.75, Vec3(1, 0, 0), false, Vec3(2.0, 0.0, 0.0), Vec3(0.25, 0.0, 0.0)},
        {"2 mm slab", mustShape(makeBox(Vec3(1.0, 0.001, 1.0))), at(Vec3(0.0)), mustShape(makeBox(Vec3(0.1))),
         at(Vec3(0.2, 0.101 - 0.0005, 0.0)), 0.0005, Vec3(0, 1, 0), false, Vec3(0.0, 0.001, 0.0),
         Vec3(0.0, 0.0005, 0.0)},
        {"1 mm into 1 km", km, at(Vec3(0.0)), mm, at(Vec3(3.0, 500.0005 - 0.0002, -7.0)), 0.0002, Vec3(0, 1, 0), false,
         Vec3(0.0, 500.0, 0.0), Vec3(0.0, 499.9998, 0.0)},
        {"1 km under 1 mm", mm, at(Vec3(3.0, 500.0005 - 0.0002, -7.0)), km, at(Vec3(0.0)), 0.0002, Vec3(0, -1, 0),
         false, Vec3(0.0, 499.9998, 0.0), Vec3(0.0, 500.0, 0.0)},
        {"flat anchor under cube", floor, at(Vec3(0.0)), unit, at(Vec3(0.7, 0.49, -1.0)), 0.01, Vec3(0, 1, 0), false,
         Vec3(0.0, 0.0, 0.0), Vec3(0.0, -0.01, 0.0)},
    };
}

} // namespace

class TestEpa : public QObject {
    Q_OBJECT
private slots:
    void analytic_data() {
        QTest::addColumn<int>("index");
        const auto cases = depthCases();
        for (int i = 0; i < int(cases.size()); ++i)
            QTest::newRow(cases[i].name) << i;
    }

    void analytic() {
        QFETCH(int, index);
        DepthCase c = depthCases()[size_t(index)];
        const PenetrationResult r = signedDistance(c.a, c.xa, c.b, c.xb);
        if (c.name == std::string("coincident boxes") && r.normal.y < 0.0) {
            // Both directions along y are exact answers here.
            c.normal = -c.normal;
            std::swap(c.pointA, c.pointB);
        }
        QVERIFY2(r.method != PenetrationMethod::SatFallback, "EPA should converge on the analytic cases");
        QVERIFY2(std::abs(-r.separation - c.depth) < 1e-9, qPrintable(QString::number(-r.separation, 'g', 17)));
        if (c.name != std::string("coincident boxes"))
            QVERIFY2(angleDegrees(r.normal, c.normal) < 0.1,
                     qPrintable(QString::number(angleDegrees(r.normal, c.normal))));
        else // every face normal is a valid answer; it must be the smallest extent's axis, y
            QVERIFY(std::abs(r.normal.y) > std::cos(0.1 * kPi / 180.0));
        QVERIFY(glm::length((r.pointA - r.pointB) - (-r.separation) * r.normal) < 1e-9);
        if (c.uniquePoints) {
            QVERIFY2(glm::length(r.pointA - c.pointA) < 1e-3,
                     qPrintable(QString("%1 %2 %3").arg(r.pointA.x).arg(r.pointA.y).arg(r.pointA.z)));
            QVERIFY(glm::length(r.pointB - c.pointB) < 1e-3);
        } else {
            QVERIFY(std::abs(glm::dot(r.pointA - c.pointA, c.normal)) < 1e-3);
            QVERIFY(std::abs(glm::dot(r.pointB - c.pointB, c.normal)) < 1e-3);
        }
        // Polyhedral pairs: the exact SAT agrees.
        if (c.a.isPolyhedral() && c.b.isPolyhedral()) {
            const SatResult sat = satPolyhedra(c.a, c.xa, c.b, c.xb);
            QVERIFY(std::abs(sat.separation - r.separation) < 1e-9);
        }
    }

    // 10,000 random overlapping hull pairs: EPA's depth against the exact SAT over faces and edge pairs.
    void randomHullsAgainstSat() {
        std::mt19937_64 rng(20261122);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        int compared = 0, fallbacks = 0, apart = 0;
        Real worst = 0.0, worstAxis = 0.0, worstWitness = 0.0;
        for (int i = 0; i < 10000; ++i) {
            const Shape a = randomPolyhedron(rng);
            const Shape b = randomPolyhedron(rng);
            const Transform xa = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 0.2, randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 0.6, randomRotation(rng));
            const SatResult sat = satPolyhedra(a, xa, b, xb);
            const PenetrationResult r = signedDistance(a, xa, b, xb);
            if (sat.separation > 0.0) {
                ++apart; // GJK's exact distance is at least the best axis's separation
                QVERIFY(r.separation >= sat.separation - 1e-9);
                continue;
            }
            ++compared;
            fallbacks += r.method == PenetrationMethod::SatFallback;
            worst = std::max(worst, std::abs(r.separation - sat.separation));
            // The reported normal must realise the reported depth.
            worstAxis = std::max(worstAxis, std::abs(separationAlong(a, xa, b, xb, r.normal) - r.separation));
            // The witnesses lie on the normal's line: pointA - pointB == depth * normal.
            worstWitness = std::max(worstWitness, glm::length((r.pointB - r.pointA) - r.separation * r.normal));
        }
        qInfo("compared %d overlapping pairs (%d apart), worst depth difference %.3g m, worst normal %.3g m, "
              "worst witness %.3g m, %d SAT fallbacks",
              compared, apart, worst, worstAxis, worstWitness, fallbacks);
        QVERIFY(compared > 5000);
        QVERIFY(worst < 1e-4);
        QVERIFY(worstAxis < 1e-4);
        QVERIFY(worstWitness < 1e-9);
        QVERIFY(fallbacks < compared / 100);
    }

    // The 2,000-vertex hull into a box, in random orientations: EPA against the SAT.
    void bigHull() {
        const Shape hull = mustShape(makeHull(uvSphereHull(1.0, 37, 54)));
        const Shape box = mustShape(makeBox(Vec3(0.7, 0.4, 0.9)));
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        for (int i = 0; i < 50; ++i) {
            const Transform xa = Transform::fromQuat(Vec3(0.0), randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 1.2, randomRotation(rng));
            const SatResult sat = satPolyhedra(hull, xa, box, xb);
            const PenetrationResult r = signedDistance(hull, xa, box, xb);
            if (sat.separation > 0.0)
                continue;
            QCOMPARE(r.method, PenetrationMethod::Epa);
            QVERIFY(std::abs(r.separation - sat.separation) < 1e-6);
        }
    }

    // Two 2,000-vertex hulls almost coincident: every direction is nearly as deep, EPA runs out of faces, and the
    // pair is too big for the quadratic SAT fallback. The answer is EPA's lower bound; check it against the SAT.
    void bigPairKeepsEpaBound() {
        const Shape big = mustShape(makeHull(uvSphereHull(0.5, 37, 54)));
        const Transform xa = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(1, 2, 3), 0.3));
        const Transform xb = Transform::fromQuat(Vec3(0.01, 0.03, -0.02), axisAngle(Vec3(-2, 1, 0), 1.1));
        QVERIFY(!satAffordable(big, big));
        const PenetrationResult r = signedDistance(big, xa, big, xb);
        QCOMPARE(r.method, PenetrationMethod::Epa);
        QCOMPARE(r.epaStatus, EpaStatus::BudgetExceeded);
        const SatResult sat = satPolyhedra(big, xa, big, xb);
        qInfo("EPA lower bound %.6f m, exact %.6f m, depth along EPA's normal %.6f m", -r.separation, -sat.separation,
              -separationAlong(big, xa, big, xb, r.normal));
        QVERIFY(-r.separation <= -sat.separation + 1e-9);
        QVERIFY(-r.separation >= 0.99 * -sat.separation);
        // Pushing along EPA's normal separates the pair with at most 1% more travel than the exact depth.
        QVERIFY(std::abs(separationAlong(big, xa, big, xb, r.normal) - sat.separation) < 0.01 * -sat.separation);
    }

    // EPA with a face budget too small to converge: the result must come from the SAT and still be exact.
    void fallbackOnBudget() {
        const Shape a = mustShape(makeHull(uvSphereHull(1.0, 12, 20)));
        const Shape b = mustShape(makeBox(Vec3(0.5, 0.2, 0.4)));
        const Transform xb = Transform::fromQuat(Vec3(0.3, 1.0, 0.1), axisAngle(Vec3(1, 1, 0), 0.4));
        PenetrationOptions options;
        options.epa.maxFaces = 6;
        const PenetrationResult r = signedDistance(a, Transform{}, b, xb, options);
        QCOMPARE(r.method, PenetrationMethod::SatFallback);
        QCOMPARE(r.epaStatus, EpaStatus::BudgetExceeded);
        const PenetrationResult full = signedDistance(a, Transform{}, b, xb);
        QCOMPARE(full.method, PenetrationMethod::Epa);
        QVERIFY(full.separation < 0.0);
        QVERIFY(std::abs(r.separation - full.separation) < 1e-9);
        QVERIFY(angleDegrees(r.normal, full.normal) < 0.1);
        QVERIFY(std::abs(separationAlong(a, Transform{}, b, xb, r.normal) - r.separation) < 1e-9);
    }

    // Two coplanar flat anchors overlap in a zero-volume set: EPA cannot build a polytope and the SAT answers.
    void fallbackOnFlatPair() {
        const Shape quad = mustShape(
            makeHull(flatPolygonHull({Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1)}, Vec3(0, 1, 0))));
        const PenetrationResult r = signedDistance(quad, Transform{}, quad, at(Vec3(0.5, 0.0, 0.2)));
        QCOMPARE(r.method, PenetrationMethod::SatFallback);
        QCOMPARE(r.epaStatus, EpaStatus::Degenerate);
        QVERIFY(std::isfinite(r.separation) && std::isfinite(r.normal.x + r.normal.y + r.normal.z));
        QVERIFY(std::abs(glm::length(r.normal) - 1.0) < 1e-12);
        QVERIFY(r.separation <= 0.0);
    }

    // Spheres with coincident centres have no preferred direction; the answer is defined and finite.
    void coincidentSpheres() {
        const Shape s = mustShape(makeSphere(0.5));
        const PenetrationResult r = signedDistance(s, at(Vec3(1.0)), s, at(Vec3(1.0)));
        QCOMPARE(r.method, PenetrationMethod::Analytic);
        QCOMPARE(r.separation, -1.0);
        QVERIFY(std::abs(glm::length(r.normal) - 1.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestEpa)
#include "tst_epa.moc"
