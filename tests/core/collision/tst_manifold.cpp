// Contact manifolds: resting boxes give their four corners, flat anchors push back to the side a body is on,
// feature ids persist under small motion, speculative points appear within the margin, and both polyhedron
// methods (SAT and GJK/EPA) agree with the exact depth.
#include "CollisionTestShapes.h"
#include "collision/Collide.h"
#include "collision/Gjk.h"
#include "collision/Penetration.h"
#include "collision/Sat.h"
#include "geometry/ConvexHull.h"

#include <QtTest>

#include <set>

using namespace rl;
using namespace rl::test;

Q_DECLARE_METATYPE(rl::PolyhedronMethod)

namespace {

Transform at(const Vec3& p) {
    return {p, Mat3(1.0)};
}

// Every manifold point must be finite, on the normal's line through its witnesses, and its two witnesses must
// lie on (or within tolerance of) the two shapes' surfaces.
bool manifoldIsConsistent(const Manifold& m, const Transform& xa, const Transform& xb) {
    if (std::abs(glm::length(m.normal) - 1.0) > 1e-9)
        return false;
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& c = m.points[i];
        const Vec3 pa = xa.apply(c.localA), pb = xb.apply(c.localB);
        if (!std::isfinite(c.separation + pa.x + pa.y + pa.z + pb.x + pb.y + pb.z))
            return false;
        if (std::abs(glm::dot(pb - pa, m.normal) - c.separation) > 1e-9)
            return false;
        if (glm::length((pb - pa) - c.separation * m.normal) > 1e-9)
            return false;
    }
    return true;
}

// Area of the convex hull of four coplanar points (normal y): the largest of the three diagonal pairings.
Real quadAreaY(const Vec3 p[4]) {
    Real best = 0.0;
    const int orders[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 3, 2}};
    for (const auto& o : orders)
        best = std::max(best, 0.5 * std::abs(glm::cross(p[o[2]] - p[o[0]], p[o[3]] - p[o[1]]).y));
    return best;
}

// A disc of 32 sides, 0.4 m in radius and 0.1 m thick, about its centre (a hull, not a box).
Shape discShape() {
    std::vector<Vec3> points;
    for (int k = 0; k < 32; ++k) {
        const Real phi = 2.0 * kPi * k / 32.0;
        for (const Real y : {-0.05, 0.05})
            points.push_back(Vec3(0.4 * std::cos(phi), y, 0.4 * std::sin(phi)));
    }
    return mustShape(makeHull(computeConvexHull(points)));
}

} // namespace

class TestManifold : public QObject {
    Q_OBJECT
private slots:
    void boxRestingOnBox_data() {
        QTest::addColumn<PolyhedronMethod>("method");
        QTest::addColumn<Real>("yaw");
        QTest::addColumn<Vec3>("baseHalf");
        QTest::newRow("sat aligned") << PolyhedronMethod::Sat << 0.0 << Vec3(2.0, 0.5, 2.0);
        QTest::newRow("sat yawed 30") << PolyhedronMethod::Sat << kPi / 6 << Vec3(2.0, 0.5, 2.0);
        QTest::newRow("sat equal boxes") << PolyhedronMethod::Sat << 0.0 << Vec3(0.5);
        QTest::newRow("epa aligned") << PolyhedronMethod::GjkEpa << 0.0 << Vec3(2.0, 0.5, 2.0);
        QTest::newRow("epa yawed 30") << PolyhedronMethod::GjkEpa << kPi / 6 << Vec3(2.0, 0.5, 2.0);
        QTest::newRow("epa equal boxes") << PolyhedronMethod::GjkEpa << 0.0 << Vec3(0.5);
    }

    // A box resting flat on a box: four points, at the four bottom corners, each 1 mm deep.
    void boxRestingOnBox() {
        QFETCH(PolyhedronMethod, method);
        QFETCH(Real, yaw);
        QFETCH(Vec3, baseHalf);
        const Shape base = mustShape(makeBox(baseHalf));
        const Shape cube = mustShape(makeBox(Vec3(0.5)));
        const Real depth = 0.001;
        const Transform xc =
            Transform::fromQuat(Vec3(0.0, baseHalf.y + 0.5 - depth, 0.0), axisAngle(Vec3(0, 1, 0), yaw));
        Manifold m;
        CollideOptions options;
        options.method = method;
        QVERIFY(collide(base, Transform{}, cube, xc, 0.01, m, options));
        QCOMPARE(m.pointCount, 4);
        QVERIFY(angleDegrees(m.normal, Vec3(0, 1, 0)) < 0.1);
        QVERIFY(manifoldIsConsistent(m, Transform{}, xc));
        // Each corner of the cube's bottom face is matched by exactly one point.
        int matched = 0;
        for (int sx = -1; sx <= 1; sx += 2) {
            for (int sz = -1; sz <= 1; sz += 2) {
                const Vec3 corner = xc.apply(Vec3(0.5 * sx, -0.5, 0.5 * sz));
                for (int i = 0; i < m.pointCount; ++i) {
                    const Vec3 onCube = xc.apply(m.points[i].localB);
                    if (glm::length(onCube - corner) < 1e-9) {
                        ++matched;
                        QVERIFY(std::abs(m.points[i].separation + depth) < 1e-9);
                    }
                }
            }
        }
        QCOMPARE(matched, 4);
    }

    // Flat two-sided anchors: a cube on either side gets four points and a normal that pushes it back to its side.
    void flatAnchor_data() {
        QTest::addColumn<Real>("side");
        QTest::addColumn<Real>("penetration");
        QTest::newRow("above, 1 mm") << 1.0 << 0.001;
        QTest::newRow("below, 1 mm") << -1.0 << 0.001;
        QTest::newRow("above, 40 cm") << 1.0 << 0.4;
        QTest::newRow("below, 40 cm") << -1.0 << 0.4;
        QTest::newRow("above, speculative 3 mm") << 1.0 << -0.003;
    }

    void flatAnchor() {
        QFETCH(Real, side);
        QFETCH(Real, penetration);
        const Shape floor = mustShape(
            makeHull(flatPolygonHull({Vec3(-5, 0, -5), Vec3(5, 0, -5), Vec3(5, 0, 5), Vec3(-5, 0, 5)}, Vec3(0, 1, 0))));
        const Shape cube = mustShape(makeBox(Vec3(0.5)));
        const Transform xc = at(Vec3(0.3, side * (0.5 - penetration), -1.2));
        for (int order = 0; order < 2; ++order) {
            Manifold m;
            const bool hit = order == 0 ? collide(floor, Transform{}, cube, xc, 0.01, m)
                                        : collide(cube, xc, floor, Transform{}, 0.01, m);
            QVERIFY(hit);
            QCOMPARE(m.pointCount, 4);
            const Vec3 push = order == 0 ? m.normal : -m.normal; // from the floor to the cube
            QVERIFY(angleDegrees(push, Vec3(0.0, side, 0.0)) < 0.1);
            for (int i = 0; i < m.pointCount; ++i)
                QVERIFY(std::abs(m.points[i].separation + penetration) < 1e-9);
            QVERIFY(order == 0 ? manifoldIsConsistent(m, Transform{}, xc) : manifoldIsConsistent(m, xc, Transform{}));
        }
    }

    // Feature ids identify the same corners after a small motion; they are distinct within a manifold.
    void featureIdsPersist() {
        const Shape base = mustShape(makeBox(Vec3(2.0, 0.5, 2.0)));
        const Shape cube = mustShape(makeBox(Vec3(0.5)));
        std::vector<std::pair<uint32_t, Vec3>> first;
        for (int step = 0; step < 10; ++step) {
            const Transform xc = Transform::fromQuat(Vec3(0.001 * step, 0.999 - 0.0001 * step, 0.0005 * step),
                                                     axisAngle(Vec3(0, 1, 0), 0.002 * step));
            Manifold m;
            QVERIFY(collide(base, Transform{}, cube, xc, 0.01, m));
            QCOMPARE(m.pointCount, 4);
            std::set<uint32_t> ids;
            for (int i = 0; i < m.pointCount; ++i)
                ids.insert(m.points[i].featureId);
            QCOMPARE(int(ids.size()), 4);
            for (int i = 0; i < m.pointCount; ++i) {
                if (step == 0) {
                    first.push_back({m.points[i].featureId, m.points[i].localB});
                    continue;
                }
                // The same id must name the same corner of the cube.
                bool found = false;
                for (const auto& [id, local] : first)
                    found = found || (id == m.points[i].featureId && glm::length(local - m.points[i].localB) < 1e-9);
                QVERIFY(found);
            }
        }
    }

    void speculative_data() {
        QTest::addColumn<Real>("gap");
        QTest::addColumn<Real>("margin");
        QTest::addColumn<int>("points");
        QTest::newRow("5 mm gap, 1 cm margin") << 0.005 << 0.01 << 4;
        QTest::newRow("5 mm gap, 1 mm margin") << 0.005 << 0.001 << 0;
        QTest::newRow("touching, no margin") << 0.0 << 0.0 << 4;
    }

    void speculative() {
        QFETCH(Real, gap);
        QFETCH(Real, margin);
        QFETCH(int, points);
        const Shape base = mustShape(makeBox(Vec3(2.0, 0.5, 2.0)));
        const Shape cube = mustShape(makeBox(Vec3(0.5)));
        const Transform xc = Transform::fromQuat(Vec3(0.1, 1.0 + gap, 0.0), axisAngle(Vec3(0, 1, 0), 0.3));
        for (PolyhedronMethod method : {PolyhedronMethod::Sat, PolyhedronMethod::GjkEpa}) {
            Manifold m;
            CollideOptions options;
            options.method = method;
            QCOMPARE(collide(base, Transform{}, cube, xc, margin, m, options), points > 0);
            QCOMPARE(m.pointCount, points);
            for (int i = 0; i < m.pointCount; ++i)
                QVERIFY(std::abs(m.points[i].separation - gap) < 1e-9);
        }
    }

    // Spheres: one point, analytic depth, normal and position, in both orders.
    void spheres_data() {
        QTest::addColumn<int>("kind"); // 0 sphere, 1 box, 2 hull
        QTest::addColumn<Vec3>("centre");
        QTest::addColumn<Real>("separation");
        QTest::addColumn<Vec3>("normal");
        QTest::newRow("sphere-sphere") << 0 << Vec3(0.3, 0.4, 0.0) << -0.3 << Vec3(0.6, 0.8, 0.0);
        QTest::newRow("sphere-box face") << 1 << Vec3(0.2, 0.7, 0.1) << -0.1 << Vec3(0, 1, 0);
        QTest::newRow("sphere-box inside") << 1 << Vec3(0.4, 0.1, 0.0) << -0.4 << Vec3(1, 0, 0);
        QTest::newRow("sphere-box speculative") << 1 << Vec3(0.2, 0.805, 0.1) << 0.005 << Vec3(0, 1, 0);
        QTest::newRow("sphere-hull face") << 2 << Vec3(0.0, -0.75, 0.1) << -0.05 << Vec3(0, -1, 0);
    }

    void spheres() {
        QFETCH(int, kind);
        QFETCH(Vec3, centre);
        QFETCH(Real, separation);
        QFETCH(Vec3, normal);
        const Shape ball = mustShape(makeSphere(0.3));
        std::vector<Vec3> hexagon;
        for (int i = 0; i < 6; ++i)
            hexagon.push_back({0.8 * std::cos(i * kPi / 3), 0.0, 0.8 * std::sin(i * kPi / 3)});
        const Shape other = kind == 0   ? mustShape(makeSphere(0.5))
                            : kind == 1 ? mustShape(makeBox(Vec3(0.5)))
                                        : mustShape(makeHull(prismHull(hexagon, 0.5)));
        const Transform xs = at(centre);
        Manifold m;
        QVERIFY(collide(other, Transform{}, ball, xs, 0.01, m));
        QCOMPARE(m.pointCount, 1);
        QVERIFY(std::abs(m.points[0].separation - separation) < 1e-9);
        QVERIFY(angleDegrees(m.normal, normal) < 0.1);
        QVERIFY(manifoldIsConsistent(m, Transform{}, xs));
        QVERIFY(glm::length(xs.apply(m.points[0].localB) - (centre - 0.3 * normal)) < 1e-3);
        Manifold r;
        QVERIFY(collide(ball, xs, other, Transform{}, 0.01, r));
        QCOMPARE(r.pointCount, 1);
        QVERIFY(angleDegrees(r.normal, -normal) < 0.1);
        QVERIFY(std::abs(r.points[0].separation - separation) < 1e-9);
        QVERIFY(manifoldIsConsistent(r, xs, Transform{}));
    }

    // Crossed edges give one point at the analytic closest pair.
    void edgeOnEdge() {
        const Shape unit = mustShape(makeBox(Vec3(0.5)));
        const Real s2 = std::sqrt(2.0);
        const Transform xa = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), kPi / 4));
        const Transform xb = Transform::fromQuat(Vec3(0.0, 1.3, 0.0), axisAngle(Vec3(1, 0, 0), kPi / 4));
        Manifold m;
        QVERIFY(collide(unit, xa, unit, xb, 0.01, m));
        QCOMPARE(m.pointCount, 1);
        QVERIFY(angleDegrees(m.normal, Vec3(0, 1, 0)) < 0.1);
        QVERIFY(std::abs(m.points[0].separation - (1.3 - s2)) < 1e-9);
        QVERIFY(glm::length(m.points[0].position - Vec3(0.0, 0.5 * (s2 / 2 + 1.3 - s2 / 2), 0.0)) < 1e-3);
        QVERIFY(manifoldIsConsistent(m, xa, xb));
    }

    // Random hull pairs: the deepest manifold point matches the exact depth with both methods, and the points are
    // consistent with the normal.
    void randomHulls_data() {
        QTest::addColumn<PolyhedronMethod>("method");
        QTest::newRow("sat") << PolyhedronMethod::Sat;
        QTest::newRow("gjk-epa") << PolyhedronMethod::GjkEpa;
    }

    void randomHulls() {
        QFETCH(PolyhedronMethod, method);
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        CollideOptions options;
        options.method = method;
        options.faceBias = 0.0; // the exact deepest axis: no preference for faces
        options.faceRelative = 1.0;
        options.edgeRelative = 1.0;
        int touching = 0;
        Real worst = 0.0;
        for (int i = 0; i < 2000; ++i) {
            const Shape a = randomPolyhedron(rng);
            const Shape b = randomPolyhedron(rng);
            const Transform xa = Transform::fromQuat(Vec3(0.0), randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 0.8, randomRotation(rng));
            Manifold m;
            const bool hit = collide(a, xa, b, xb, 0.0, m, options);
            const SatResult sat = satPolyhedra(a, xa, b, xb);
            QCOMPARE(hit, sat.separation <= 0.0);
            if (!hit)
                continue;
            ++touching;
            QVERIFY(m.pointCount >= 1 && m.pointCount <= 4);
            if (!manifoldIsConsistent(m, xa, xb)) {
                for (int k = 0; k < m.pointCount; ++k) {
                    const Vec3 d = xb.apply(m.points[k].localB) - xa.apply(m.points[k].localA);
                    qWarning("pair %d point %d/%d sep %.17g along %.17g lateral %.3g", i, k, m.pointCount,
                             m.points[k].separation, glm::dot(d, m.normal),
                             glm::length(d - m.points[k].separation * m.normal));
                }
            }
            QVERIFY(manifoldIsConsistent(m, xa, xb));
            Real deepest = 0.0;
            for (int k = 0; k < m.pointCount; ++k)
                deepest = std::min(deepest, m.points[k].separation);
            worst = std::max(worst, std::abs(deepest - sat.separation));
        }
        qInfo("%d touching pairs, worst deepest-point error %.3g m", touching, worst);
        QVERIFY(touching > 500);
        QVERIFY(worst < 1e-6);
    }

    // Two cubes apart edge against edge, the edges crossed at 10 degrees and 1 cm apart (speculative margin 5 cm):
    // the manifold keeps the edge axis as its normal but gets the points of the faces that face each other along it,
    // each at least the edges' distance apart along the normal, so none pushes before the bodies touch.
    void speculativeEdgeContactHasFacePoints() {
        const Shape cube = mustShape(makeBox(Vec3(0.1)));
        const Real corner = 0.1 * std::sqrt(2.0); // a 45-degree cube reaches this far from its centre
        const Transform xa = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), kPi / 4));
        const Quat turn = axisAngle(Vec3(0, 1, 0), 10.0 * kPi / 180.0); // B's bottom edge 10 degrees off A's top edge
        const Transform xb =
            Transform::fromQuat(Vec3(0.0, 2.0 * corner + 0.01, 0.0), turn * axisAngle(Vec3(0, 0, 1), kPi / 4));
        const SatResult sat = satPolyhedra(cube, xa, cube, xb);
        QVERIFY(sat.feature == SatFeature::EdgePair);
        QVERIFY(std::abs(sat.separation - 0.01) < 1e-9);
        Manifold m;
        QVERIFY(collide(cube, xa, cube, xb, 0.05, m));
        QVERIFY(std::abs(glm::dot(m.normal, sat.normal) - 1.0) < 1e-9);
        QVERIFY(m.pointCount >= 3);
        Real closest = 1.0;
        for (int k = 0; k < m.pointCount; ++k) {
            const ContactPoint& p = m.points[k];
            QVERIFY(p.separation >= 0.01 - 1e-9);
            QVERIFY(p.separation <= 0.05);
            closest = std::min(closest, p.separation);
            // The witnesses lie on the two surfaces along the normal.
            const Vec3 pa = xa.apply(p.localA), pb = xb.apply(p.localB);
            QVERIFY(glm::length(glm::cross(pb - pa, m.normal)) < 1e-9);
        }
        QVERIFY(closest < 0.01 + 1e-6); // the edges' crossing is among the points
    }

    // The same cubes with B's edge 1 cm into A's: one point at the edges' witnesses, unless the speculative distance
    // is at least CollideOptions::clipOverlappingEdgesFrom (a pair closing or turning fast); then the faces that
    // face each other along the edge axis are clipped, and no point is deeper than the edges' overlap.
    void overlappingEdgeContactHasFacePointsWhenFast_data() {
        QTest::addColumn<PolyhedronMethod>("method");
        QTest::addColumn<Real>("spec");
        QTest::addColumn<int>("fewestPoints");
        QTest::newRow("sat, at rest") << PolyhedronMethod::Sat << 0.03 << 1;
        QTest::newRow("sat, fast") << PolyhedronMethod::Sat << 0.05 << 3;
        QTest::newRow("gjk-epa, at rest") << PolyhedronMethod::GjkEpa << 0.03 << 1;
        QTest::newRow("gjk-epa, fast") << PolyhedronMethod::GjkEpa << 0.05 << 3;
    }
    void overlappingEdgeContactHasFacePointsWhenFast() {
        QFETCH(PolyhedronMethod, method);
        QFETCH(Real, spec);
        QFETCH(int, fewestPoints);
        const Shape cube = mustShape(makeBox(Vec3(0.1)));
        const Real corner = 0.1 * std::sqrt(2.0);
        const Transform xa = Transform::fromQuat(Vec3(0.0), axisAngle(Vec3(0, 0, 1), kPi / 4));
        const Quat turn = axisAngle(Vec3(0, 1, 0), 10.0 * kPi / 180.0);
        const Transform xb =
            Transform::fromQuat(Vec3(0.0, 2.0 * corner - 0.01, 0.0), turn * axisAngle(Vec3(0, 0, 1), kPi / 4));
        const SatResult sat = satPolyhedra(cube, xa, cube, xb);
        QVERIFY(sat.feature == SatFeature::EdgePair);
        QVERIFY(std::abs(sat.separation + 0.01) < 1e-9);
        CollideOptions options;
        options.method = method;
        options.clipOverlappingEdgesFrom = 0.04;
        Manifold m;
        QVERIFY(collide(cube, xa, cube, xb, spec, m, options));
        QVERIFY(std::abs(glm::dot(m.normal, sat.normal) - 1.0) < 1e-6);
        QVERIFY(m.pointCount >= fewestPoints);
        if (fewestPoints == 1)
            QCOMPARE(m.pointCount, 1);
        Real deepest = 1.0;
        for (int k = 0; k < m.pointCount; ++k) {
            const ContactPoint& p = m.points[k];
            QVERIFY(p.separation >= -0.01 - 1e-6);
            QVERIFY(p.separation <= spec);
            deepest = std::min(deepest, p.separation);
            const Vec3 pa = xa.apply(p.localA), pb = xb.apply(p.localB);
            QVERIFY(glm::length(glm::cross(pb - pa, m.normal)) < 1e-6);
        }
        QVERIFY(deepest < -0.01 + 1e-6); // the edges' overlap is among the points
        // By default (CollideOptions{}), never clipped.
        Manifold single;
        CollideOptions defaults;
        defaults.method = method;
        QVERIFY(collide(cube, xa, cube, xb, spec, single, defaults));
        QCOMPARE(single.pointCount, 1);
    }

    // A speculative edge contact must engage at the shapes' true distance: its nearest point may not be farther
    // apart than GJK says the shapes are. The faces that face each other along the axis need not hold the closest
    // edges; before the edges' witnesses joined such manifolds, 71 of 3,000 random pairs engaged late, by up to
    // 15.6 cm (measured). Now 1 does, by 2.65 mm.
    void speculativeEdgeContactsEngageAtTheTrueDistance() {
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        const CollideOptions world;
        SatOptions options;
        options.faceBias = world.faceBias;
        options.faceRelative = world.faceRelative;
        options.edgeRelative = world.edgeRelative;
        int cases = 0, late = 0;
        Real worst = 0.0;
        for (int i = 0; i < 200000 && cases < 3000; ++i) {
            const Shape a = randomPolyhedron(rng), b = randomPolyhedron(rng);
            const Transform xa = Transform::fromQuat(Vec3(0.0), randomRotation(rng));
            const Transform xb = Transform::fromQuat(Vec3(u(rng), u(rng), u(rng)) * 1.5, randomRotation(rng));
            const SatResult sat = satPolyhedra(a, xa, b, xb, options);
            if (sat.feature != SatFeature::EdgePair || !(sat.separation > 0.0) || sat.separation > 0.1)
                continue;
            ++cases;
            Manifold m;
            QVERIFY(collide(a, xa, b, xb, 0.2, m));
            Real nearest = std::numeric_limits<Real>::infinity();
            for (int k = 0; k < m.pointCount; ++k)
                nearest = std::min(nearest, m.points[k].separation);
            const Real gap = nearest - gjkDistance(a, xa, b, xb).distance;
            worst = std::max(worst, gap);
            late += gap > 1e-6 ? 1 : 0;
        }
        qInfo("%d separated edge-pair contacts; %d engage later than the true distance, by at most %.3g m", cases, late,
              worst);
        QCOMPARE(cases, 3000);
        QVERIFY(late <= 1);
        QVERIFY(worst < 0.003);
    }

    // A touching point is not dropped for points that are still apart: two touching corners 2 cm apart and six
    // speculative points 3-16 mm away keep both touching corners (the old reduction kept the deepest and three
    // wide speculative ones, and the cube rocked between the two corners).
    void reductionKeepsTouchingPoints() {
        const std::vector<Vec3> pts = {{0.0, 0.0, 0.0}, {0.02, 0.0, 0.0}, {-0.1, 0.0, -0.1}, {0.1, 0.0, -0.1},
                                       {0.1, 0.0, 0.1}, {-0.1, 0.0, 0.1}, {0.0, 0.0, 0.12},  {0.12, 0.0, 0.0}};
        const std::vector<Real> seps = {-5e-5, -2e-5, 0.016, 0.012, 0.003, 0.009, 0.014, 0.006};
        int chosen[4];
        const int k = reduceContactPoints(pts.data(), seps.data(), int(pts.size()), Vec3(0, 1, 0), chosen);
        QCOMPARE(k, 4);
        QCOMPARE(chosen[0], 0);
        QVERIFY(std::find(chosen, chosen + 4, 1) != chosen + 4);
        // The free slots go to the apart points that span the most area with the touching pair (0.011 m^2 at best).
        const Vec3 four[4] = {pts[size_t(chosen[0])], pts[size_t(chosen[1])], pts[size_t(chosen[2])],
                              pts[size_t(chosen[3])]};
        QVERIFY(quadAreaY(four) > 0.01);
    }

    // The reduction keeps the deepest point and nearly the largest area the candidates allow.
    void reductionKeepsArea() {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        Real worstRatio = 1.0;
        for (int trial = 0; trial < 500; ++trial) {
            const int n = 5 + int(rng() % 8);
            std::vector<Vec3> pts(static_cast<size_t>(n));
            std::vector<Real> seps(static_cast<size_t>(n));
            for (int i = 0; i < n; ++i) {
                pts[size_t(i)] = Vec3(u(rng), 0.0, u(rng));
                seps[size_t(i)] = -0.01 * (1.0 + u(rng));
            }
            int chosen[4];
            const int k = reduceContactPoints(pts.data(), seps.data(), n, Vec3(0, 1, 0), chosen);
            QVERIFY(k >= 3);
            if (k == 3)
                chosen[3] = chosen[2]; // every other point lies inside the triangle: it is the hull
            const int deepest = int(std::min_element(seps.begin(), seps.end()) - seps.begin());
            QVERIFY(std::find(chosen, chosen + 4, deepest) != chosen + 4);
            auto quadArea = [&](const int q[4]) {
                const Vec3 four[4] = {pts[size_t(q[0])], pts[size_t(q[1])], pts[size_t(q[2])], pts[size_t(q[3])]};
                return quadAreaY(four);
            };
            Real optimum = 0.0;
            for (int a = 0; a < n; ++a)
                for (int b = a + 1; b < n; ++b)
                    for (int c = b + 1; c < n; ++c)
                        for (int d = c + 1; d < n; ++d) {
                            const int q[4] = {a, b, c, d};
                            if (std::find(q, q + 4, deepest) != q + 4)
                                optimum = std::max(optimum, quadArea(q));
                        }
            worstRatio = std::min(worstRatio, quadArea(chosen) / optimum);
        }
        qInfo("worst area ratio to the best quadrilateral through the deepest point: %.3f", worstRatio);
        QVERIFY(worstRatio > 0.85);
    }

    // A 1,000-gon face (a 2,000-vertex prism) lying on a box: still four points, all at the right depth.
    void bigFaceOnBox() {
        std::vector<Vec3> polygon;
        for (int i = 0; i < 1000; ++i)
            polygon.push_back({std::cos(2 * kPi * i / 1000), 0.0, std::sin(2 * kPi * i / 1000)});
        const Shape disc = mustShape(makeHull(prismHull(polygon, 0.1)));
        QCOMPARE(disc.polyhedron->vertices.size(), size_t(2000));
        const Shape base = mustShape(makeBox(Vec3(3.0, 0.5, 3.0)));
        const Transform xd = at(Vec3(0.2, 0.598, 0.0));
        Manifold m;
        QVERIFY(collide(base, Transform{}, disc, xd, 0.01, m));
        QCOMPARE(m.pointCount, 4);
        QVERIFY(manifoldIsConsistent(m, Transform{}, xd));
        for (int i = 0; i < 4; ++i)
            QVERIFY(std::abs(m.points[i].separation + 0.002) < 1e-9);
        // The four kept rim points span most of the disc: the inscribed square has area 2.
        const Vec3 four[4] = {m.points[0].position, m.points[1].position, m.points[2].position, m.points[3].position};
        QVERIFY(quadAreaY(four) > 1.9);
    }

    // EPA out of budget inside collide(): the SAT answers, with the same manifold the SAT method gives.
    void epaBudgetFallsBackToSat() {
        std::vector<Vec3> polygon;
        for (int i = 0; i < 16; ++i)
            polygon.push_back({0.5 * std::cos(2 * kPi * i / 16), 0.0, 0.5 * std::sin(2 * kPi * i / 16)});
        const Shape prism = mustShape(makeHull(prismHull(polygon, 0.4)));
        const Transform xb = Transform::fromQuat(Vec3(0.2, 0.7, 0.1), axisAngle(Vec3(1, 0, 1), 0.3));
        CollideOptions starved;
        starved.method = PolyhedronMethod::GjkEpa;
        starved.epa.maxFaces = 4;
        CollideOptions sat;
        sat.method = PolyhedronMethod::Sat;
        // This budget really makes EPA give up on this pair.
        const GjkResult g = gjkDistance(prism, Transform{}, prism, xb);
        QCOMPARE(epaPenetration(prism, Transform{}, prism, xb, g, starved.epa).status, EpaStatus::BudgetExceeded);
        Manifold m, reference;
        QVERIFY(collide(prism, Transform{}, prism, xb, 0.01, m, starved));
        QVERIFY(collide(prism, Transform{}, prism, xb, 0.01, reference, sat));
        QCOMPARE(m.pointCount, reference.pointCount);
        QVERIFY(angleDegrees(m.normal, reference.normal) < 1e-9);
        for (int i = 0; i < m.pointCount; ++i)
            QCOMPARE(m.points[i].separation, reference.points[i].separation);
    }

    // A 1 mm cube on a 1 km box and a 10 cm cube on a 2 mm slab: four points at the right depth.
    void extremeScales_data() {
        QTest::addColumn<Vec3>("baseHalf");
        QTest::addColumn<Real>("cubeHalf");
        QTest::addColumn<Real>("depth");
        QTest::newRow("1 mm on 1 km") << Vec3(500.0) << 0.0005 << 0.0001;
        QTest::newRow("10 cm on 2 mm slab") << Vec3(1.0, 0.001, 1.0) << 0.05 << 0.0005;
    }

    void extremeScales() {
        QFETCH(Vec3, baseHalf);
        QFETCH(Real, cubeHalf);
        QFETCH(Real, depth);
        const Shape base = mustShape(makeBox(baseHalf));
        const Shape cube = mustShape(makeBox(Vec3(cubeHalf)));
        const Transform xc =
            Transform::fromQuat(Vec3(0.3, baseHalf.y + cubeHalf - depth, -0.2), axisAngle(Vec3(0, 1, 0), 0.4));
        for (PolyhedronMethod method : {PolyhedronMethod::Sat, PolyhedronMethod::GjkEpa}) {
            CollideOptions options;
            options.method = method;
            Manifold m;
            QVERIFY(collide(base, Transform{}, cube, xc, 0.0, m, options));
            QCOMPARE(m.pointCount, 4);
            QVERIFY(angleDegrees(m.normal, Vec3(0, 1, 0)) < 0.1);
            for (int i = 0; i < 4; ++i)
                QVERIFY(std::abs(m.points[i].separation + depth) < 1e-9);
        }
    }

    // Degenerate overlaps: two identical coincident boxes, and a box fully inside another. The deepest point
    // matches the exact depth and the normal is the analytic one.
    void containedAndCoincident_data() {
        QTest::addColumn<Vec3>("outerHalf");
        QTest::addColumn<Vec3>("innerHalf");
        QTest::addColumn<Vec3>("innerCentre");
        QTest::addColumn<Real>("depth");
        QTest::addColumn<Vec3>("normal");
        QTest::newRow("coincident") << Vec3(0.5, 0.3, 0.7) << Vec3(0.5, 0.3, 0.7) << Vec3(0.0) << 0.6 << Vec3(0, 1, 0);
        QTest::newRow("contained") << Vec3(2.0) << Vec3(0.25) << Vec3(0.5, 0.0, 0.3) << 1.75 << Vec3(1, 0, 0);
    }

    void containedAndCoincident() {
        QFETCH(Vec3, outerHalf);
        QFETCH(Vec3, innerHalf);
        QFETCH(Vec3, innerCentre);
        QFETCH(Real, depth);
        QFETCH(Vec3, normal);
        const Shape outer = mustShape(makeBox(outerHalf));
        const Shape inner = mustShape(makeBox(innerHalf));
        const Transform xi = at(innerCentre);
        for (PolyhedronMethod method : {PolyhedronMethod::Sat, PolyhedronMethod::GjkEpa}) {
            CollideOptions options;
            options.method = method;
            Manifold m;
            QVERIFY(collide(outer, Transform{}, inner, xi, 0.01, m, options));
            QVERIFY(m.pointCount >= 1);
            QVERIFY(manifoldIsConsistent(m, Transform{}, xi));
            // Either sign is exact for the coincident pair; the axis is not negotiable.
            QVERIFY(std::abs(glm::dot(m.normal, normal)) > std::cos(0.1 * kPi / 180.0));
            Real deepest = 0.0;
            for (int i = 0; i < m.pointCount; ++i)
                deepest = std::min(deepest, m.points[i].separation);
            QVERIFY(std::abs(deepest + depth) < 1e-9);
        }
    }

    // Two 2 mm cards leaning on each other meet rim to rim: their inner faces separate them equally well, so the
    // contact's normal is the bisector, level, whichever card is A, touching, a hair apart or a hair into each other
    // (turnWedgeNormal() in Collide.cpp; before, the SAT's tie-break gave A's face normal, tilted by the lean). A
    // card's top edge 5 mm down the other's face keeps that face's normal.
    void wedgeContactsTakeTheBisector_data() {
        QTest::addColumn<Real>("tilt");    // each card's lean from the vertical, degrees
        QTest::addColumn<Real>("overlap"); // how far the top edges reach past each other, m (< 0: apart)
        QTest::addColumn<Real>("down");    // the left card moved this far down the right card's face, m
        QTest::addColumn<bool>("swap");    // the right card is A
        for (const Real tilt : {10.0, 25.0, 40.0})
            for (const Real overlap : {-1e-4, 0.0, 5e-5})
                for (const bool swap : {false, true})
                    QTest::addRow("%.0f degrees, overlap %g m%s", tilt, overlap, swap ? ", swapped" : "")
                        << tilt << overlap << 0.0 << swap;
        for (const Real tilt : {10.0, 25.0, 40.0})
            for (const bool swap : {false, true})
                QTest::addRow("%.0f degrees, edge 5 mm down the face%s", tilt, swap ? ", swapped" : "")
                    << tilt << 1e-5 << 0.005 << swap;
    }
    void wedgeContactsTakeTheBisector() {
        QFETCH(Real, tilt);
        QFETCH(Real, overlap);
        QFETCH(Real, down);
        QFETCH(bool, swap);
        const Real th = tilt * kPi / 180.0, half = 0.2, thick = 0.001;
        const Shape card = mustShape(makeBox(Vec3(thick, half, 0.15)));
        // Centres placed so that the inner top edges meet at x = 0 (each reaching `overlap` / 2 past it).
        const Real dx = half * std::sin(th) + thick * std::cos(th) - 0.5 * overlap;
        const Real y = half * std::cos(th) + thick * std::sin(th);
        const Vec3 downRightFace(std::sin(th), -std::cos(th), 0.0); // down the right card's inner face
        const Vec3 rightNormal(-std::cos(th), -std::sin(th), 0.0);  // the right card's inner face, outward
        const Transform left =
            Transform::fromQuat(Vec3(-dx, y, 0.0) + down * downRightFace, axisAngle(Vec3(0, 0, 1), -th));
        const Transform right = Transform::fromQuat(Vec3(dx, y, 0.0), axisAngle(Vec3(0, 0, 1), th));
        Manifold m;
        QVERIFY(swap ? collide(card, right, card, left, 0.01, m) : collide(card, left, card, right, 0.01, m));
        QVERIFY(m.pointCount >= 1);
        QVERIFY(swap ? manifoldIsConsistent(m, right, left) : manifoldIsConsistent(m, left, right));
        const Vec3 leftToRight = down > 0.0 ? -rightNormal : Vec3(1, 0, 0);
        const Vec3 expected = swap ? -leftToRight : leftToRight;
        qInfo("normal (%.6f, %.6f, %.6f), %d points, separation %.3g mm", m.normal.x, m.normal.y, m.normal.z,
              m.pointCount, 1e3 * m.points[0].separation);
        QVERIFY(angleDegrees(m.normal, expected) < 1e-6);
    }

    // Hulls from computeConvexHull (coplanar faces merged into polygons) behave like the hand-built ones: a box
    // from its eight corners plus interior points, and a Blender plane (four coplanar points) as a flat anchor.
    void computedHulls() {
        std::vector<Vec3> points;
        std::mt19937_64 rng(8);
        std::uniform_real_distribution<Real> u(-0.5, 0.5);
        for (int i = 0; i < 8; ++i)
            points.push_back({(i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5});
        for (int i = 0; i < 40; ++i)
            points.push_back({u(rng), u(rng), u(rng)});
        const Result<Shape> cube = makeHull(computeConvexHull(points));
        QVERIFY(cube.ok());
        QCOMPARE(cube->polyhedron->faces.size(), size_t(6));
        const Result<Shape> plane = makeHull(
            computeConvexHull(std::vector<Vec3>{Vec3(-3, 0, -3), Vec3(3, 0, -3), Vec3(3, 0, 3), Vec3(-3, 0, 3)}));
        QVERIFY(plane.ok());
        QVERIFY(plane->isFlat());
        const Shape base = mustShape(makeBox(Vec3(2.0, 0.5, 2.0)));
        for (const Shape* floor : {&base, &plane.value()}) {
            const Real top = floor->isFlat() ? 0.0 : 0.5;
            const Transform xc = Transform::fromQuat(Vec3(0.2, top + 0.499, -0.1), axisAngle(Vec3(0, 1, 0), 0.7));
            Manifold m;
            QVERIFY(collide(*floor, Transform{}, *cube, xc, 0.01, m));
            QCOMPARE(m.pointCount, 4);
            QVERIFY(angleDegrees(m.normal, Vec3(0, 1, 0)) < 0.1);
            for (int i = 0; i < 4; ++i)
                QVERIFY(std::abs(m.points[i].separation + 0.001) < 1e-9);
        }
    }

    // addTurnedSupports(): a disc of 32 sides tilted above a floor, to be turned so that its far rim comes down.
    // The manifold at the start holds the near rim; with the turn it also holds the corner that comes lowest,
    // measured against the floor's surface straight along the normal.
    void turnedSupportsHoldTheCornerATurnBringsDown_data() {
        QTest::addColumn<bool>("flatFloor");
        QTest::addColumn<Real>("turn");
        QTest::newRow("box floor, 0.6 rad") << false << 0.6;
        QTest::newRow("box floor, 0.45 rad") << false << 0.45;
        QTest::newRow("flat floor, 0.6 rad") << true << 0.6;
    }
    void turnedSupportsHoldTheCornerATurnBringsDown() {
        QFETCH(bool, flatFloor);
        QFETCH(Real, turn);
        const Shape box = mustShape(makeBox(Vec3(2.0, 0.5, 2.0)));
        const Shape plane = mustShape(makeHull(
            computeConvexHull(std::vector<Vec3>{Vec3(-3, 0, -3), Vec3(3, 0, -3), Vec3(3, 0, 3), Vec3(-3, 0, 3)})));
        const Shape& floor = flatFloor ? plane : box;
        const Real top = flatFloor ? 0.0 : 0.5;
        const Shape disc = discShape();
        const Transform xd = Transform::fromQuat(Vec3(0.0, top + 0.2, 0.0), axisAngle(Vec3(1, 0, 0), 0.3));
        Manifold m;
        QVERIFY(collide(floor, Transform{}, disc, xd, 0.5, m));
        const Manifold before = m;
        const Quat q = axisAngle(Vec3(1, 0, 0), -turn);
        addTurnedSupports(floor, Transform{}, Quat(1, 0, 0, 0), disc, xd, q, m);
        QVERIFY(manifoldIsConsistent(m, Transform{}, xd));
        QVERIFY(m.pointCount <= 4);
        // The corner lowest once turned about the disc's centre, and where it is now.
        const ConvexPolyhedron& p = *disc.polyhedron;
        size_t lowest = 0;
        for (size_t k = 1; k < p.vertices.size(); ++k)
            if ((q * xd.rotate(p.vertices[k])).y < (q * xd.rotate(p.vertices[lowest])).y)
                lowest = k;
        const Vec3 corner = xd.apply(p.vertices[lowest]);
        bool held = false;
        for (int k = 0; k < m.pointCount; ++k)
            if (glm::length(xd.apply(m.points[k].localB) - corner) < 1e-9) {
                held = true;
                QVERIFY(std::abs(m.points[k].separation - (corner.y - top)) < 1e-9);
            }
        QVERIFY(held);
        // The nearest point at the start stays.
        int deepest = 0;
        for (int k = 1; k < before.pointCount; ++k)
            if (before.points[k].separation < before.points[deepest].separation)
                deepest = k;
        bool kept = false;
        for (int k = 0; k < m.pointCount; ++k)
            kept = kept || glm::length(m.points[k].position - before.points[deepest].position) < 1e-12;
        QVERIFY(kept);
    }

    // Without a turn, with a turn that brings no corner nearer (about the normal, the disc lying flat), or with the
    // corner that comes down over nothing (the floor a post under the near rim), the manifold is left as it was;
    // over a wide floor the same turn adds the corner.
    void turnedSupportsAddOnlyACornerThatComesDownOnSomething_data() {
        QTest::addColumn<Real>("tilt");
        QTest::addColumn<Vec3>("axis");
        QTest::addColumn<Real>("turn");
        QTest::addColumn<bool>("post");
        QTest::addColumn<bool>("added");
        QTest::newRow("tilted, no turn") << 0.3 << Vec3(1, 0, 0) << 0.0 << false << false;
        QTest::newRow("flat, turned about the normal") << 0.0 << Vec3(0, 1, 0) << 0.6 << false << false;
        QTest::newRow("tilted, turned over a post") << 0.3 << Vec3(1, 0, 0) << -0.6 << true << false;
        QTest::newRow("tilted, turned over a floor") << 0.3 << Vec3(1, 0, 0) << -0.6 << false << true;
    }
    void turnedSupportsAddOnlyACornerThatComesDownOnSomething() {
        QFETCH(Real, tilt);
        QFETCH(Vec3, axis);
        QFETCH(Real, turn);
        QFETCH(bool, post);
        QFETCH(bool, added);
        const Shape disc = discShape();
        // About 2 cm over the floor; tilted about +x, its +z side is the lower, and under it a post 10 cm wide, or a
        // wide floor.
        const Transform xd =
            Transform::fromQuat(Vec3(0.0, 0.57 + 0.4 * std::sin(tilt), 0.0), axisAngle(Vec3(1, 0, 0), tilt));
        const Shape floor = mustShape(makeBox(post ? Vec3(0.05, 0.5, 0.05) : Vec3(2.0, 0.5, 2.0)));
        const Transform xf{post ? Vec3(0.0, 0.0, 0.37) : Vec3(0.0), Mat3(1.0)};
        Manifold m;
        QVERIFY(collide(floor, xf, disc, xd, 0.05, m)); // the near rim only
        const Manifold before = m;
        addTurnedSupports(floor, xf, Quat(1, 0, 0, 0), disc, xd, axisAngle(axis, turn), m);
        bool same = m.pointCount == before.pointCount;
        for (int k = 0; k < m.pointCount && same; ++k)
            same = m.points[k].position == before.points[k].position &&
                   m.points[k].separation == before.points[k].separation;
        QCOMPARE(!same, added);
        QVERIFY(manifoldIsConsistent(m, xf, xd));
    }

    // distanceAlong(): from outside a shape along a direction to its surface; none when the ray misses it or starts
    // inside it. A flat polygon is hit within its outline only.
    void distanceAlongAShape_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<Vec3>("origin");
        QTest::addColumn<Vec3>("direction");
        QTest::addColumn<Real>("distance"); // negative: none
        QTest::newRow("box, from above") << "box" << Vec3(0.3, 0.8, -0.2) << Vec3(0, -1, 0) << 0.3;
        QTest::newRow("box, slanting in through a side")
            << "box" << Vec3(-1.0, 0.2, 0.0) << glm::normalize(Vec3(1, -0.1, 0)) << 0.5 * std::sqrt(1.01);
        QTest::newRow("box, beside it") << "box" << Vec3(0.6, 0.8, 0.0) << Vec3(0, -1, 0) << -1.0;
        QTest::newRow("box, from inside") << "box" << Vec3(0.1, 0.1, 0.1) << Vec3(0, -1, 0) << -1.0;
        QTest::newRow("box, pointing away") << "box" << Vec3(0.0, 0.8, 0.0) << Vec3(0, 1, 0) << -1.0;
        QTest::newRow("plane, from above") << "plane" << Vec3(1.0, 0.4, 1.0) << Vec3(0, -1, 0) << 0.4;
        QTest::newRow("plane, from below") << "plane" << Vec3(1.0, -0.4, 1.0) << Vec3(0, 1, 0) << 0.4;
        QTest::newRow("plane, beyond its outline") << "plane" << Vec3(3.5, 0.4, 0.0) << Vec3(0, -1, 0) << -1.0;
        QTest::newRow("sphere, from above") << "sphere" << Vec3(0.0, 2.0, 0.0) << Vec3(0, -1, 0) << 1.5;
        QTest::newRow("sphere, beside it") << "sphere" << Vec3(0.6, 2.0, 0.0) << Vec3(0, -1, 0) << -1.0;
    }
    void distanceAlongAShape() {
        QFETCH(QString, shape);
        QFETCH(Vec3, origin);
        QFETCH(Vec3, direction);
        QFETCH(Real, distance);
        const Shape s = shape == "box"     ? mustShape(makeBox(Vec3(0.5)))
                        : shape == "plane" ? mustShape(makeHull(computeConvexHull(std::vector<Vec3>{
                                                 Vec3(-3, 0, -3), Vec3(3, 0, -3), Vec3(3, 0, 3), Vec3(-3, 0, 3)})))
                                           : mustShape(makeSphere(0.5));
        const std::optional<Real> t = distanceAlong(s, Transform{}, origin, direction);
        QCOMPARE(t.has_value(), distance >= 0.0);
        if (t)
            QVERIFY(std::abs(*t - distance) < 1e-12);
    }

    void nonFiniteInputGivesNoContact() {
        const Shape cube = mustShape(makeBox(Vec3(0.5)));
        Manifold m;
        m.pointCount = 3;
        QVERIFY(!collide(cube, Transform{}, cube, at(Vec3(std::nan(""), 0.0, 0.0)), 0.01, m));
        QCOMPARE(m.pointCount, 0);
        Transform bad;
        bad.rotation[1][1] = std::numeric_limits<Real>::infinity();
        QVERIFY(!collide(cube, bad, cube, Transform{}, 0.01, m));
    }
};

QTEST_APPLESS_MAIN(TestManifold)
#include "tst_manifold.moc"
