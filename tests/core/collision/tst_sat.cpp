// The SAT on polyhedra: Gauss-map pruning loses no axis (checked against every face and edge pair measured with
// the support functions, in both orientations), its early out is conservative, and flat polygons only offer their
// facing side.
#include "CollisionTestShapes.h"
#include "collision/Collide.h"
#include "collision/Sat.h"
#include "geometry/ConvexHull.h"

#include <QtTest>

using namespace rl;
using namespace rl::test;

namespace {

// Brute force: every face normal and every edge-pair cross product, each measured by support functions.
// With `facing` set (A flat), only axes leaning to that side count, as the side rule says.
Real bruteForceSeparation(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                          const Vec3& facing = Vec3(0.0)) {
    Real best = -std::numeric_limits<Real>::infinity();
    auto measure = [&](Vec3 axis) {
        const Real len = glm::length(axis);
        if (!(len > 1e-9))
            return;
        axis /= len;
        for (const Vec3& u : {axis, -axis}) {
            if (glm::dot(u, facing) >= -1e-12) // in-plane axes are allowed; rounding must not drop them
                best = std::max(best, separationAlong(a, xa, b, xb, u));
        }
    };
    for (const PolyFace& f : a.polyhedron->faces)
        measure(xa.rotate(f.normal));
    for (const PolyFace& f : b.polyhedron->faces)
        measure(xb.rotate(f.normal));
    for (const PolyEdge& ea : a.polyhedron->edges) {
        const Vec3 da = xa.rotate(a.polyhedron->vertices[ea.v1] - a.polyhedron->vertices[ea.v0]);
        for (const PolyEdge& eb : b.polyhedron->edges)
            measure(glm::cross(da, xb.rotate(b.polyhedron->vertices[eb.v1] - b.polyhedron->vertices[eb.v0])));
        // A flat A behaves as its polygon extruded away from the facing side: that prism's side faces and side
        // edges (along the facing normal) add in-plane axes.
        if (glm::dot(facing, facing) > 0.0)
            measure(glm::cross(da, facing));
    }
    if (glm::dot(facing, facing) > 0.0) {
        for (const PolyEdge& eb : b.polyhedron->edges)
            measure(glm::cross(facing, xb.rotate(b.polyhedron->vertices[eb.v1] - b.polyhedron->vertices[eb.v0])));
    }
    return best;
}

} // namespace

class TestSat : public QObject {
    Q_OBJECT
private slots:
    void pruningLosesNoAxis() {
        std::mt19937_64 rng(99);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        Real worst = 0.0;
        int edgeWins = 0;
        for (int i = 0; i < 3000; ++i) {
            const Shape a = randomPolyhedron(rng);
            const Shape b = randomPolyhedron(rng);
            const Transform xa = Transform::fromQuat(Vec3(0.0), randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)), randomRotation(rng));
            const SatResult sat = satPolyhedra(a, xa, b, xb);
            const Real brute = bruteForceSeparation(a, xa, b, xb);
            // Apart, both are lower bounds of the distance (the closest pair may be two vertices, whose direction
            // is no candidate axis), but they must agree that the pair is apart. Overlapping, both are exact.
            QCOMPARE(sat.separation > 0.0, brute > 0.0);
            if (brute <= 0.0)
                worst = std::max(worst, std::abs(sat.separation - brute));
            else
                QVERIFY(sat.separation <= brute + 1e-12);
            edgeWins += sat.feature == SatFeature::EdgePair;
            // The reported normal realises the reported separation.
            QVERIFY(std::abs(separationAlong(a, xa, b, xb, sat.normal) - sat.separation) < 1e-9);
        }
        qInfo("worst difference to brute force %.3g m; %d of 3000 pairs decided by an edge pair", worst, edgeWins);
        QVERIFY(worst < 1e-9);
        QVERIFY(edgeWins > 100); // the edge query is really exercised
    }

    // Boxes are recognised: made as boxes, as hulls of exact corners, and as hulls of a turned cube whose corners were
    // written with six decimals (as Blender's OBJ exporter does); a slanted parallelepiped and a wedge are not boxes.
    void boxesAreRecognised_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("box");
        QTest::newRow("makeBox") << 0 << true;
        QTest::newRow("hull of the corners") << 1 << true;
        QTest::newRow("turned cube, six decimals") << 2 << true;
        QTest::newRow("slanted parallelepiped") << 3 << false;
        QTest::newRow("wedge") << 4 << false;
        // Far from the origin: the faces' offsets multiply the normals' rounding by the distance (detectBox()).
        QTest::newRow("turned cube 7 m out, six decimals") << 5 << true;
        QTest::newRow("Blender's turned box 7 m out (boxes1000.obj's Box.004)") << 6 << true;
    }
    void boxesAreRecognised() {
        QFETCH(int, kind);
        QFETCH(bool, box);
        const Vec3 h(0.3, 0.1, 0.2);
        std::vector<Vec3> corners;
        for (int i = 0; i < 8; ++i)
            corners.emplace_back(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
        const Mat3 turn = glm::mat3_cast(axisAngle(glm::normalize(Vec3(1.0, 2.0, 3.0)), 0.7));
        for (Vec3& c : corners) {
            if (kind == 2)
                c = glm::round((turn * c + Vec3(1.5, 0.25, -2.0)) * 1e6) * 1e-6;
            if (kind == 5)
                c = glm::round((turn * c + Vec3(-2.5, 1.0, 7.3)) * 1e6) * 1e-6;
            if (kind == 3)
                c.x += 0.5 * c.y; // a parallelepiped whose faces do not meet at right angles
        }
        if (kind == 4)
            corners.resize(6); // a wedge: the four corners at z = -h.z and two at z = +h.z
        // Its corners as Blender 3.4 wrote them (tests/data/acceptance/boxes1000.obj): sides 0.39036, 0.45424 and
        // 0.70806 m, square to 2.6e-6 rad.
        if (kind == 6)
            corners = {{-2.506817, 0.605075, 7.470549}, {-2.825663, 0.823691, 7.416446},
                       {-2.248507, 0.828295, 6.850225}, {-2.567353, 1.046911, 6.796122},
                       {-2.303796, 0.953088, 7.680320}, {-2.622643, 1.171705, 7.626216},
                       {-2.045486, 1.176309, 7.059996}, {-2.364332, 1.394925, 7.005892}};
        Shape s = kind == 0 ? mustShape(makeBox(h)) : mustShape(makeHull(computeConvexHull(corners)));
        QCOMPARE(s.polyhedron->isBox, box);
        if (!box)
            return;
        const ConvexPolyhedron::BoxFeatures& f = s.polyhedron->box;
        Real halves[3] = {f.half[0], f.half[1], f.half[2]};
        std::sort(halves, halves + 3);
        const Vec3 expected = kind == 6 ? Vec3(0.195181, 0.227120, 0.354031) : Vec3(0.1, 0.2, 0.3);
        QVERIFY(std::abs(halves[0] - expected.x) < 1e-5 && std::abs(halves[1] - expected.y) < 1e-5 &&
                std::abs(halves[2] - expected.z) < 1e-5);
        QVERIFY(glm::dot(glm::cross(f.axis[0], f.axis[1]), f.axis[2]) > 1.0 - 1e-12);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(glm::dot(s.polyhedron->faces[f.face[i][0]].normal, f.axis[i]) > 1.0 - 1e-6);
            QVERIFY(glm::dot(s.polyhedron->faces[f.face[i][1]].normal, f.axis[i]) < -1.0 + 1e-6);
            for (int bits = 0; bits < 4; ++bits) {
                const PolyEdge& e = s.polyhedron->edges[f.edge[i][bits]];
                const Vec3 middle = 0.5 * (s.polyhedron->vertices[e.v0] + s.polyhedron->vertices[e.v1]) - f.center;
                QCOMPARE(glm::dot(middle, f.axis[(i + 1) % 3]) < 0.0, (bits & 1) != 0);
                QCOMPARE(glm::dot(middle, f.axis[(i + 2) % 3]) < 0.0, (bits & 2) != 0);
            }
        }
        // A box's world bounds come from its axes and reaches (Shape::worldBounds()): they hold every vertex, and
        // are the vertices' own box to within the fit of a six-decimal corner.
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<Real> u(-3.0, 3.0);
        Real widest = 0.0;
        for (int i = 0; i < 200; ++i) {
            const Transform xf = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)), randomRotation(rng));
            Aabb vertexBox{Vec3(1e9), Vec3(-1e9)};
            for (const Vec3& v : s.polyhedron->vertices) {
                vertexBox.min = glm::min(vertexBox.min, xf.apply(v));
                vertexBox.max = glm::max(vertexBox.max, xf.apply(v));
            }
            const Aabb got = s.worldBounds(xf);
            for (int axis = 0; axis < 3; ++axis) {
                QVERIFY(got.min[axis] <= vertexBox.min[axis] && got.max[axis] >= vertexBox.max[axis]);
                widest = std::max({widest, vertexBox.min[axis] - got.min[axis], got.max[axis] - vertexBox.max[axis]});
            }
        }
        // (Six decimals 7 m out: the features fit the corners to 2e-5 of the size along each axis, detectBox().)
        const Real slack = kind == 2 ? 1e-5 : kind >= 5 ? 2e-5 : 1e-12;
        QVERIFY2(widest < slack, qPrintable(QString::number(widest)));
    }

    // Two boxes measured by projection give the general query's answer: the same kind of feature, the same face or
    // edges, the same normal and separation (to rounding), the same early outs; over box pairs apart, touching
    // and deeply overlapping, boxes of six-decimal corners included.
    void boxesByProjectionAsTheGeneralQuery() {
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<Real> u(-1.0, 1.0), size(0.05, 0.6);
        int kinds[3] = {0, 0, 0}, earlyOuts = 0;
        Real worst = 0.0;
        for (int n = 0; n < 4000; ++n) {
            auto makeOne = [&](bool rounded) {
                const Vec3 h(size(rng), size(rng), size(rng));
                if (!rounded)
                    return mustShape(makeBox(h));
                std::vector<Vec3> corners;
                const Mat3 turn = glm::mat3_cast(randomRotation(rng));
                for (int i = 0; i < 8; ++i)
                    corners.push_back(
                        glm::round(turn * Vec3(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z) * 1e6) *
                        1e-6);
                return mustShape(makeHull(computeConvexHull(corners)));
            };
            const Shape a = makeOne(n % 2 == 1), b = makeOne(n % 3 == 1);
            QVERIFY(a.polyhedron->isBox && b.polyhedron->isBox);
            const Transform xa = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)), randomRotation(rng));
            const Transform xb =
                Transform::fromQuat(xa.position + 0.8 * Vec3(u(rng), u(rng), u(rng)), randomRotation(rng));
            SatOptions options;
            options.faceBias = 0.005;
            options.faceRelative = 0.98;
            options.edgeRelative = 0.9;
            options.earlyOut = n % 4 == 0 ? 0.02 : std::numeric_limits<Real>::infinity();
            SatOptions general = options;
            general.useBoxes = false;
            const SatResult box = satPolyhedra(a, xa, b, xb, options);
            const SatResult ref = satPolyhedra(a, xa, b, xb, general);
            if (ref.separation > options.earlyOut) {
                // Either answer only says "apart by more than the early out".
                QVERIFY(box.separation > options.earlyOut);
                ++earlyOuts;
                continue;
            }
            QCOMPARE(int(box.feature), int(ref.feature));
            ++kinds[int(ref.feature)];
            if (ref.feature == SatFeature::EdgePair) {
                QCOMPARE(box.edgeA, ref.edgeA);
                QCOMPARE(box.edgeB, ref.edgeB);
                QVERIFY(glm::length(box.pointA - ref.pointA) < 1e-9 && glm::length(box.pointB - ref.pointB) < 1e-9);
            } else {
                QCOMPARE(box.face, ref.face);
            }
            // Exact boxes agree to rounding; six-decimal ones to the fit of their box.
            const bool exact = n % 2 == 0 && n % 3 != 1;
            QVERIFY(glm::length(box.normal - ref.normal) < (exact ? 1e-12 : 1e-4));
            QVERIFY(std::abs(box.separation - ref.separation) < (exact ? 1e-12 : 2e-5));
            worst = std::max(worst, std::abs(box.separation - ref.separation));
        }
        qInfo("face A %d, face B %d, edge pairs %d, early outs %d; worst separation difference %.3g m", kinds[0],
              kinds[1], kinds[2], earlyOuts, worst);
        QVERIFY(kinds[0] > 100 && kinds[1] > 100 && kinds[2] > 100 && earlyOuts > 100);
    }

    // Flat polygons against hulls: the pruned query with the side rule equals the brute force over the axes
    // that lean to the polygon's facing side.
    void flatPolygonsAgainstBruteForce() {
        std::mt19937_64 rng(123);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        Real worst = 0.0;
        int overlapping = 0;
        for (int i = 0; i < 2000; ++i) {
            std::vector<Vec3> polygon;
            const int sides = 3 + int(rng() % 6);
            for (int k = 0; k < sides; ++k)
                polygon.push_back({std::cos(2 * kPi * k / sides), 0.0, std::sin(2 * kPi * k / sides)});
            const Shape flat = mustShape(makeHull(flatPolygonHull(polygon, Vec3(0, 1, 0))));
            const Shape b = randomPolyhedron(rng);
            const Transform xa = Transform::fromQuat(Vec3(0.0), randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 1.2, randomRotation(rng));
            const Vec3 n = xa.rotate(Vec3(0, 1, 0));
            const Vec3 facing = glm::dot(n, xb.apply(b.centre()) - xa.position) >= 0.0 ? n : -n;
            const SatResult sat = satPolyhedra(flat, xa, b, xb);
            const Real brute = bruteForceSeparation(flat, xa, b, xb, facing);
            if ((sat.separation > 0.0) != (brute > 0.0))
                qWarning("pair %d: sat %.17g (feature %d) brute %.17g", i, sat.separation, int(sat.feature), brute);
            QCOMPARE(sat.separation > 0.0, brute > 0.0);
            QVERIFY(glm::dot(sat.normal, facing) >= -1e-12);
            // The flat shape as B gives the same answer.
            const SatResult reversed = satPolyhedra(b, xb, flat, xa);
            QVERIFY(std::abs(reversed.separation - sat.separation) < 1e-9);
            QVERIFY(glm::dot(reversed.normal, facing) <= 1e-12);
            if (brute <= 0.0) {
                ++overlapping;
                worst = std::max(worst, std::abs(sat.separation - brute));
            }
        }
        qInfo("%d overlapping flat-hull pairs, worst difference %.3g m", overlapping, worst);
        QVERIFY(overlapping > 500);
        QVERIFY(worst < 1e-9);
    }

    // A 48-sided disc exported by Blender (rotated, then written with six decimals) lying on a 10 m floor: its bottom
    // face is planar only to the rounding. The SAT with the world's options must keep the face pair and report
    // the supports' separation along its normal. An edge of the disc's bottom against the floor's rim, 5 m away,
    // once passed the Gauss-map test at a tilt of ~1e-4 rad and, measured on the edges alone, looked 0.3 mm better
    // than the face: a one-point contact at the floor's rim (the sample scene's Torus, which never fell asleep).
    void nearlyPlanarFaceOnALargeFloorKeepsTheFace() {
        std::vector<Vec3> points;
        const Quat tilt = axisAngle(glm::normalize(Vec3(1.0, 0.2, 0.0)), 0.2618); // 15 degrees, as the Torus
        for (int k = 0; k < 48; ++k) {
            const Real angle = 2.0 * kPi * k / 48;
            for (Real y : {-0.1, 0.1}) {
                const Vec3 v = glm::mat3_cast(tilt) * Vec3(0.6 * std::cos(angle), y, 0.6 * std::sin(angle));
                points.push_back(glm::round(v * 1e6) / 1e6);
            }
        }
        const Shape disc = mustShape(makeHull(computeConvexHull(points)));
        const Shape floor = mustShape(makeHull(
            flatPolygonHull({{-5.0, 0.0, 5.0}, {5.0, 0.0, 5.0}, {5.0, 0.0, -5.0}, {-5.0, 0.0, -5.0}}, Vec3(0, 1, 0))));
        const CollideOptions world; // the world's face preferences
        SatOptions options;
        options.faceBias = world.faceBias;
        options.faceRelative = world.faceRelative;
        options.edgeRelative = world.edgeRelative;
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        int edgePairs = 0;
        Real worst = 0.0;
        for (int i = 0; i < 2000; ++i) {
            // Untilt the disc so its bottom lies flat, turn it about the vertical, put it anywhere on the floor
            // with its bottom a fraction of a millimetre above or below the floor.
            const Quat yaw = axisAngle(Vec3(0, 1, 0), kPi * u(rng));
            const Quat rotation = yaw * glm::inverse(tilt);
            const Mat3 r = glm::mat3_cast(rotation);
            Real bottom = std::numeric_limits<Real>::infinity();
            for (const Vec3& v : disc.polyhedron->vertices)
                bottom = std::min(bottom, (r * v).y);
            const Vec3 position(4.0 * u(rng), -bottom + 2e-4 * u(rng), 4.0 * u(rng));
            const Transform xDisc = Transform::fromQuat(position, rotation);
            for (bool discFirst : {true, false}) {
                const SatResult sat = discFirst ? satPolyhedra(disc, xDisc, floor, Transform{}, options)
                                                : satPolyhedra(floor, Transform{}, disc, xDisc, options);
                edgePairs += sat.feature == SatFeature::EdgePair;
                const Real along = discFirst ? separationAlong(disc, xDisc, floor, Transform{}, sat.normal)
                                             : separationAlong(floor, Transform{}, disc, xDisc, sat.normal);
                worst = std::max(worst, std::abs(along - sat.separation));
            }
        }
        qInfo("%d of 4000 queries decided by an edge pair; worst gap to the supports %.3g m", edgePairs, worst);
        QCOMPARE(edgePairs, 0); // 2,706 without the support check (measured), up to 0.69 m off the supports
        // A merged face's plane fits its vertices within the hull's merge tolerance (2e-6 m), not exactly.
        QVERIFY(worst < 2e-6);
    }

    // With an early out the SAT stops at the first separating axis, which still proves separation.
    void earlyOut() {
        const Shape box = mustShape(makeBox(Vec3(0.5)));
        SatOptions options;
        options.earlyOut = 0.01;
        const Transform xb{Vec3(0.0, 1.5, 0.0), Mat3(1.0)};
        const SatResult r = satPolyhedra(box, Transform{}, box, xb, options);
        QVERIFY(r.separation > 0.01);
        QVERIFY(r.separation <= 0.5 + 1e-12);
    }

    // A flat polygon pushes a box out along its facing normal even when the box is more than halfway through.
    void flatSideRule_data() {
        QTest::addColumn<Real>("centreY");
        QTest::addColumn<Real>("expectedNormalY");
        QTest::newRow("above, shallow") << 0.45 << 1.0;
        QTest::newRow("above, deep") << 0.05 << 1.0;
        QTest::newRow("below, deep") << -0.05 << -1.0;
    }

    void flatSideRule() {
        QFETCH(Real, centreY);
        QFETCH(Real, expectedNormalY);
        const Shape floor = mustShape(
            makeHull(flatPolygonHull({Vec3(-3, 0, -3), Vec3(3, 0, -3), Vec3(3, 0, 3), Vec3(-3, 0, 3)}, Vec3(0, 1, 0))));
        const Shape box = mustShape(makeBox(Vec3(0.5)));
        const SatResult r = satPolyhedra(floor, Transform{}, box, Transform{Vec3(0.2, centreY, 0.1), Mat3(1.0)});
        QCOMPARE(r.feature, SatFeature::FaceA);
        QVERIFY(angleDegrees(r.normal, Vec3(0.0, expectedNormalY, 0.0)) < 0.1);
        QVERIFY(std::abs(r.separation - (std::abs(centreY) - 0.5)) < 1e-12);
    }

    void segmentClosestPoints() {
        Vec3 p, q;
        closestPointsSegments(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1, -1), Vec3(0.3, 1, 1), p, q);
        QVERIFY(glm::length(p - Vec3(0.3, 0, 0)) < 1e-12);
        QVERIFY(glm::length(q - Vec3(0.3, 1, 0)) < 1e-12);
        closestPointsSegments(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), p, q); // collinear
        QVERIFY(glm::length(p - Vec3(1, 0, 0)) < 1e-12);
        QVERIFY(glm::length(q - Vec3(2, 0, 0)) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestSat)
#include "tst_sat.moc"
