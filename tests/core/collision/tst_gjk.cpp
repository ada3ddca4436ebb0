// GJK distance, closest points and overlap against analytic answers, plus its iteration bound.
#include "CollisionTestShapes.h"
#include "collision/Gjk.h"

#include <QtTest>

#include <glm/gtx/quaternion.hpp>

using namespace rl;
using namespace rl::test;

Q_DECLARE_METATYPE(rl::Shape)

namespace {

struct DistanceCase {
    const char* name;
    Shape a;
    Transform xa;
    Shape b;
    Transform xb;
    Real distance;
    Vec3 pointA;
    Vec3 pointB;
};

std::vector<DistanceCase> distanceCases() {
    const Shape unitBox = mustShape(makeBox(Vec3(0.5)));
    const Shape ball = mustShape(makeSphere(0.25));
    const Shape km = mustShape(makeBox(Vec3(500.0)));
    const Shape mm = mustShape(makeBox(Vec3(0.0005)));
    const Transform origin;
    const Real s2 = std::sqrt(2.0);
    return {
        {"sphere-sphere",
         ball,
         origin,
         mustShape(makeSphere(0.5)),
         {Vec3(1.2, 1.6, 0.0), Mat3(1.0)},
         2.0 - 0.75,
         Vec3(0.15, 0.2, 0.0),
         Vec3(0.9, 1.2, 0.0)},
        {"sphere-box face",
         unitBox,
         origin,
         ball,
         {Vec3(0.1, 1.0, -0.2), Mat3(1.0)},
         0.25,
         Vec3(0.1, 0.5, -0.2),
         Vec3(0.1, 0.75, -0.2)},
        {"sphere-box edge",
         unitBox,
         origin,
         ball,
         {Vec3(1.0, 1.0, 0.3), Mat3(1.0)},
         s2 * 0.5 - 0.25,
         Vec3(0.5, 0.5, 0.3),
         Vec3(1.0 - 0.25 / s2, 1.0 - 0.25 / s2, 0.3)},
        {"sphere-box corner",
         unitBox,
         origin,
         ball,
         {Vec3(1.5, 1.5, 1.5), Mat3(1.0)},
         std::sqrt(3.0) - 0.25,
         Vec3(0.5),
         Vec3(1.5 - 0.25 / std::sqrt(3.0))},
        {"box-box faces",
         unitBox,
         origin,
         unitBox,
         {Vec3(0.2, 1.3, 0.1), Mat3(1.0)},
         0.3,
         Vec3(0.0, 0.5, 0.0),
         Vec3(0.0, 0.8, 0.0)},
        {"box-box edges", unitBox, Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), kPi / 4)), unitBox,
         Transform::fromQuat(Vec3(0.0, 2.0, 0.0), axisAngle(Vec3(1, 0, 0), kPi / 4)), 2.0 - s2, Vec3(0.0, s2 / 2, 0.0),
         Vec3(0.0, 2.0 - s2 / 2, 0.0)},
        {"box-box touching",
         unitBox,
         origin,
         unitBox,
         {Vec3(0.3, 1.0, -0.2), Mat3(1.0)},
         0.0,
         Vec3(0.0, 0.5, 0.0),
         Vec3(0.0, 0.5, 0.0)},
        {"1 mm above 1 km",
         km,
         origin,
         mm,
         {Vec3(3.0, 500.0015, -7.0), Mat3(1.0)},
         0.001,
         Vec3(3.0, 500.0, -7.0),
         Vec3(3.0, 500.001, -7.0)},
    };
}

} // namespace

class TestGjk : public QObject {
    Q_OBJECT
private slots:
    void distance_data() {
        QTest::addColumn<int>("index");
        const auto cases = distanceCases();
        for (int i = 0; i < int(cases.size()); ++i)
            QTest::newRow(cases[i].name) << i;
    }

    void distance() {
        QFETCH(int, index);
        const DistanceCase c = distanceCases()[size_t(index)];
        const GjkResult r = gjkDistance(c.a, c.xa, c.b, c.xb);
        QVERIFY2(std::abs(r.distance - c.distance) < 1e-9, qPrintable(QString::number(r.distance, 'g', 17)));
        QCOMPARE(r.status == GjkStatus::MaxIterations, false);
        QVERIFY(r.iterations <= GjkOptions{}.maxIterations);
        if (c.distance > 0.0) {
            // Face and edge contacts have many closest pairs; all lie on the planes the analytic pair lies on,
            // and the pair's difference is the distance vector.
            QVERIFY(std::abs(glm::length(r.pointB - r.pointA) - c.distance) < 1e-9);
            const Vec3 n = glm::normalize(c.pointB - c.pointA);
            QVERIFY(angleDegrees(r.normal, n) < 0.1);
            QVERIFY(std::abs(glm::dot(r.pointA - c.pointA, n)) < 1e-9);
            QVERIFY(std::abs(glm::dot(r.pointB - c.pointB, n)) < 1e-9);
        } else {
            QVERIFY(gjkOverlap(c.a, c.xa, c.b, c.xb));
        }
    }

    // Spheres and boxes: the unique closest points where they are unique.
    void closestPointsUnique() {
        for (const DistanceCase& c : distanceCases()) {
            const std::string name = c.name;
            if (name.rfind("sphere", 0) != 0 && name != "box-box edges")
                continue;
            const GjkResult r = gjkDistance(c.a, c.xa, c.b, c.xb);
            QVERIFY2(glm::length(r.pointA - c.pointA) < 1e-3, c.name);
            QVERIFY2(glm::length(r.pointB - c.pointB) < 1e-3, c.name);
        }
    }

    void overlap_data() {
        QTest::addColumn<Real>("gap");
        QTest::addColumn<bool>("overlapping");
        QTest::newRow("apart 1 cm") << 0.01 << false;
        QTest::newRow("apart 1 um") << 1e-6 << false;
        QTest::newRow("touching") << 0.0 << true;
        QTest::newRow("overlap 1 um") << -1e-6 << true;
        QTest::newRow("overlap half") << -0.5 << true;
    }

    void overlap() {
        QFETCH(Real, gap);
        QFETCH(bool, overlapping);
        const Shape box = mustShape(makeBox(Vec3(0.5)));
        const Shape hull = mustShape(makeHull(uvSphereHull(0.5, 9, 16)));
        // The hull's lowest point is its pole, so the gap is exact along y.
        const Transform xb{Vec3(0.1, 1.0 + gap, 0.05), Mat3(1.0)};
        QCOMPARE(gjkOverlap(box, Transform{}, hull, xb), overlapping);
        const GjkResult r = gjkDistance(box, Transform{}, hull, xb);
        QVERIFY(std::abs(r.distance - std::max(gap, 0.0)) < 1e-12);
    }

    // A 2,000-vertex hull in random orientations above a box: the exact distance is the lowest vertex's height.
    void bigHull() {
        const ConvexHull h = uvSphereHull(1.0, 37, 54);
        QCOMPARE(h.vertices.size(), size_t(2000));
        const Shape hull = mustShape(makeHull(h));
        const Shape floor = mustShape(makeBox(Vec3(5.0, 0.5, 5.0)));
        std::mt19937_64 rng(7);
        int maxIterations = 0;
        for (int i = 0; i < 200; ++i) {
            const Transform xh = Transform::fromQuat(Vec3(0.3, 1.7, -0.2), randomRotation(rng));
            Real lowest = 1e9;
            for (const Vec3& v : h.vertices)
                lowest = std::min(lowest, xh.apply(v).y);
            const GjkResult r = gjkDistance(floor, Transform{}, hull, xh);
            QVERIFY(std::abs(r.distance - (lowest - 0.5)) < 1e-9);
            maxIterations = std::max(maxIterations, r.iterations);
        }
        qInfo("most GJK iterations over 200 orientations: %d", maxIterations);
        QVERIFY2(maxIterations < 32, qPrintable(QString::number(maxIterations)));
    }

    // With the iteration bound at 1 the answer is an upper bound, finite, and flagged.
    void iterationBound() {
        const Shape a = mustShape(makeHull(uvSphereHull(1.0, 20, 30)));
        const Shape b = mustShape(makeBox(Vec3(0.3, 0.2, 0.7)));
        GjkOptions options;
        options.maxIterations = 1;
        const Transform xb = Transform::fromQuat(Vec3(1.5, 1.1, 0.4), axisAngle(Vec3(1, 2, 3), 0.7));
        const GjkResult r = gjkDistance(a, Transform{}, b, xb, options);
        QCOMPARE(r.status, GjkStatus::MaxIterations);
        QVERIFY(std::isfinite(r.distance));
        const GjkResult exact = gjkDistance(a, Transform{}, b, xb);
        QVERIFY(r.distance >= exact.distance - 1e-12);
        QVERIFY(exact.distance > 0.0);
    }

    // World bounds from the support function are the tight box of the rotated shape.
    void worldBounds() {
        const Shape box = mustShape(makeBox(Vec3(0.5, 0.2, 0.3)));
        const Shape ball = mustShape(makeSphere(0.4));
        std::mt19937_64 rng(2);
        for (int i = 0; i < 100; ++i) {
            const Transform xf = Transform::fromQuat(Vec3(1.0, -2.0, 3.0), randomRotation(rng));
            Aabb expected{Vec3(1e9), Vec3(-1e9)};
            for (const Vec3& v : box.polyhedron->vertices) {
                expected.min = glm::min(expected.min, xf.apply(v));
                expected.max = glm::max(expected.max, xf.apply(v));
            }
            const Aabb got = box.worldBounds(xf);
            QVERIFY(glm::length(got.min - expected.min) < 1e-12 && glm::length(got.max - expected.max) < 1e-12);
            const Aabb sphere = ball.worldBounds(xf);
            QVERIFY(glm::length(sphere.min - (xf.position - Vec3(0.4))) < 1e-12);
            QVERIFY(glm::length(sphere.max - (xf.position + Vec3(0.4))) < 1e-12);
        }
        QCOMPARE(box.minExtent(), 0.4);
        QVERIFY(std::abs(box.boundingRadius() - std::sqrt(0.25 + 0.04 + 0.09)) < 1e-15);
    }

    // A shape's reach along a direction (Shape::reachAlong(), the collisions after the step bound an overlap with it)
    // is the largest dot(direction, x) over its points, to within rounding and never below it; boxes take it from
    // their centre and axes, not a support query.
    void reachAlong_data() {
        QTest::addColumn<Shape>("shape");
        QTest::addColumn<bool>("box"); // the polyhedron is recognised as a box (the closed form is taken)
        std::mt19937_64 rng(5);
        QTest::newRow("box") << mustShape(makeBox(Vec3(0.5, 0.2, 0.3))) << true;
        // A box hull off its origin and turned in its own coordinates, as an exported cube is.
        ConvexHull turned = boxHull(Vec3(0.4, 0.1, 0.25));
        const Mat3 r = glm::mat3_cast(axisAngle(Vec3(1.0, 2.0, -1.0), 0.6));
        for (Vec3& v : turned.vertices)
            v = r * v + Vec3(0.3, -1.2, 2.0);
        for (HullFace& f : turned.faces) {
            f.normal = r * f.normal;
            f.offset += glm::dot(f.normal, Vec3(0.3, -1.2, 2.0));
        }
        QTest::newRow("turned box hull off its origin") << mustShape(makeHull(turned)) << true;
        QTest::newRow("sphere") << mustShape(makeSphere(0.4)) << false;
        QTest::newRow("random hull") << randomPolyhedron(rng) << false;
        QTest::newRow("uv sphere hull") << mustShape(makeHull(uvSphereHull(0.5, 8, 16))) << false;
    }
    void reachAlong() {
        QFETCH(Shape, shape);
        QFETCH(bool, box);
        QCOMPARE(shape.polyhedron && shape.polyhedron->isBox, box);
        std::mt19937_64 rng(11);
        std::normal_distribution<Real> n(0.0, 1.0);
        for (int i = 0; i < 200; ++i) {
            const Transform xf = Transform::fromQuat(Vec3(n(rng), n(rng), n(rng)) * 10.0, randomRotation(rng));
            const Vec3 direction = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
            Real expected = -1e300;
            if (shape.polyhedron)
                for (const Vec3& v : shape.polyhedron->vertices)
                    expected = std::max(expected, glm::dot(direction, xf.apply(v)));
            else
                expected = glm::dot(direction, xf.position) + shape.radius;
            const Real reach = shape.reachAlong(xf, direction);
            QVERIFY2(
                reach >= expected - 1e-14 && reach <= expected + 1e-12,
                qPrintable(QString("pose %1: %2 against %3").arg(i).arg(reach, 0, 'g', 17).arg(expected, 0, 'g', 17)));
        }
    }

    void badShapesAreErrors() {
        QVERIFY(!makeSphere(-1.0).ok());
        QVERIFY(!makeSphere(std::nan("")).ok());
        QVERIFY(!makeBox(Vec3(1.0, 0.0, 1.0)).ok());
        ConvexHull line;
        line.dimension = HullDimension::Line;
        line.vertices = {Vec3(0.0), Vec3(1.0)};
        QVERIFY(!makeHull(line).ok());
        ConvexHull open = boxHull(Vec3(1.0));
        open.faces.pop_back();
        const Result<Shape> r = makeHull(open);
        QVERIFY(!r.ok());
        QVERIFY(r.error().message.find("closed") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestGjk)
#include "tst_gjk.moc"
