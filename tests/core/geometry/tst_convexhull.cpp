// Tests of computeConvexHull: exact topology on shapes with known hulls, and geometric invariants on random clouds.
// Invariants: every input point behind every face, closed 2-manifold (Euler), planar convex CCW faces, unit normals.
#include "geometry/ConvexHull.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

using namespace rl;

Q_DECLARE_METATYPE(rl::Vec3)

namespace {

Real extentOf(const std::vector<Vec3>& pts) {
    Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
    for (const Vec3& p : pts) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::length(hi - lo);
}

// Tolerance for the checks: ten times the hull's default relative tolerance, plus the rounding of the coordinates.
Real checkTolerance(const std::vector<Vec3>& pts) {
    Real maxAbs = 0.0;
    for (const Vec3& p : pts) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            maxAbs = std::max({maxAbs, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    return 1e-9 * extentOf(pts) + 1e-13 * maxAbs;
}

struct HullReport {
    Real worstOutside = 0.0;     // largest signed distance of an input point in front of a face plane
    Real worstNonPlanar = 0.0;   // largest distance of a face vertex from its plane
    Real worstReflex = 0.0;      // largest distance of a face vertex to the outer side of one of its face's edges
    Real worstNormalError = 0.0; // | |n| - 1 |, and 1 - dot(n, Newell normal of the loop)
    int euler = 0;
    bool edgesPaired = true; // every directed edge has exactly one reverse twin
    bool indexMapOk = true;
    bool allVerticesUsed = true;
};

HullReport inspect(const ConvexHull& hull, const std::vector<Vec3>& input) {
    HullReport r;
    for (size_t i = 0; i < hull.vertices.size(); ++i) {
        if (i >= hull.inputIndex.size() || hull.inputIndex[i] >= input.size() ||
            input[hull.inputIndex[i]] != hull.vertices[i])
            r.indexMapOk = false;
    }
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    std::set<uint32_t> used;
    for (const HullFace& f : hull.faces) {
        const size_t n = f.vertices.size();
        r.worstNormalError = std::max(r.worstNormalError, std::abs(glm::length(f.normal) - 1.0));
        Vec3 newell(0.0);
        for (size_t i = 0; i < n; ++i) {
            const Vec3& p = hull.vertices[f.vertices[i]];
            const Vec3& q = hull.vertices[f.vertices[(i + 1) % n]];
            newell += glm::cross(p - hull.vertices[f.vertices[0]], q - hull.vertices[f.vertices[0]]);
            ++directed[{f.vertices[i], f.vertices[(i + 1) % n]}];
            used.insert(f.vertices[i]);
            r.worstNonPlanar = std::max(r.worstNonPlanar, std::abs(glm::dot(f.normal, p) - f.offset));
        }
        r.worstNormalError = std::max(r.worstNormalError, 1.0 - glm::dot(f.normal, glm::normalize(newell)));
        for (size_t i = 0; i < n; ++i) {
            const Vec3& a = hull.vertices[f.vertices[i]];
            const Vec3& b = hull.vertices[f.vertices[(i + 1) % n]];
            const Vec3 inward = glm::normalize(glm::cross(f.normal, b - a));
            for (uint32_t v : f.vertices)
                r.worstReflex = std::max(r.worstReflex, -glm::dot(inward, hull.vertices[v] - a));
        }
        for (const Vec3& p : input) {
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
                r.worstOutside = std::max(r.worstOutside, glm::dot(f.normal, p) - f.offset);
        }
    }
    for (const auto& [edge, count] : directed) {
        const auto twin = directed.find({edge.second, edge.first});
        if (count != 1 || twin == directed.end() || twin->second != 1)
            r.edgesPaired = false;
    }
    r.allVerticesUsed = used.size() == hull.vertices.size();
    r.euler = static_cast<int>(hull.vertices.size()) - static_cast<int>(directed.size() / 2) +
              static_cast<int>(hull.faces.size());
    return r;
}

void verifySolid(const ConvexHull& hull, const std::vector<Vec3>& input) {
    QCOMPARE(hull.dimension, HullDimension::Solid);
    const HullReport r = inspect(hull, input);
    // Faces merge within the hull's face tolerance (the rounding of the input, see HullOptions), so planarity and
    // containment hold to that; with exact input it equals the build tolerance.
    const Real tol = std::max(checkTolerance(input), 2.0 * hull.faceTolerance);
    QVERIFY(r.indexMapOk);
    QVERIFY(r.allVerticesUsed);
    QVERIFY(r.edgesPaired);
    QCOMPARE(r.euler, 2);
    QVERIFY2(r.worstOutside <= tol, qPrintable(QString("outside by %1, tol %2").arg(r.worstOutside).arg(tol)));
    QVERIFY2(r.worstNonPlanar <= tol, qPrintable(QString("non-planar by %1, tol %2").arg(r.worstNonPlanar).arg(tol)));
    QVERIFY2(r.worstReflex <= tol, qPrintable(QString("reflex by %1, tol %2").arg(r.worstReflex).arg(tol)));
    QVERIFY2(r.worstNormalError <= 1e-9, qPrintable(QString("normal error %1").arg(r.worstNormalError)));
}

std::vector<Vec3> cubeCorners(Real h = 1.0, Vec3 offset = Vec3(0.0)) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 8; ++i)
        pts.push_back(offset + h * Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    return pts;
}

std::vector<int> faceSizes(const ConvexHull& hull) {
    std::vector<int> sizes;
    for (const HullFace& f : hull.faces)
        sizes.push_back(static_cast<int>(f.vertices.size()));
    std::sort(sizes.begin(), sizes.end());
    return sizes;
}

std::vector<Vec3> uvSpherePoints(Real r, int segments, int rings) {
    std::vector<Vec3> pts{{0.0, r, 0.0}, {0.0, -r, 0.0}};
    for (int i = 1; i < rings; ++i) {
        const Real phi = kPi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const Real theta = 2.0 * kPi * j / segments;
            pts.push_back(r * Vec3(std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta)));
        }
    }
    return pts;
}

} // namespace

class TestConvexHull : public QObject {
    Q_OBJECT

private slots:
    void cube_data() {
        QTest::addColumn<Real>("halfExtent");
        QTest::addColumn<Vec3>("offset");
        QTest::newRow("unit") << 1.0 << Vec3(0.0);
        QTest::newRow("1 mm") << 0.5e-3 << Vec3(0.0);
        QTest::newRow("1 km") << 500.0 << Vec3(0.0);
        QTest::newRow("1 mm at 1 km") << 0.5e-3 << Vec3(1000.0, -700.0, 300.0);
        QTest::newRow("1 km at 1e6 m") << 500.0 << Vec3(1e6, 0.0, -1e6);
    }
    void cube() {
        QFETCH(Real, halfExtent);
        QFETCH(Vec3, offset);
        const std::vector<Vec3> pts = cubeCorners(halfExtent, offset);
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        QCOMPARE(hull.vertices.size(), size_t(8));
        QCOMPARE(faceSizes(hull), std::vector<int>(6, 4));
        // The tolerance follows the size (1e-10 of the diagonal) unless the coordinates' rounding is larger.
        const Real diagonal = 2.0 * std::sqrt(3.0) * halfExtent;
        const Real maxAbs = std::max({std::abs(offset.x), std::abs(offset.y), std::abs(offset.z)}) + halfExtent;
        QVERIFY(hull.tolerance >= 1e-10 * diagonal * (1.0 - 1e-12));
        QVERIFY(hull.tolerance <= std::max(1e-10 * diagonal, 1e-14 * maxAbs) * (1.0 + 1e-12));
        for (const HullFace& f : hull.faces) {
            const Real axisAligned = std::max({std::abs(f.normal.x), std::abs(f.normal.y), std::abs(f.normal.z)});
            QVERIFY(std::abs(axisAligned - 1.0) < 1e-12);
        }
    }

    void cubeWithExtraPoints_data() {
        QTest::addColumn<bool>("faceCentres");
        QTest::addColumn<bool>("edgeMidpoints");
        QTest::addColumn<bool>("interior");
        QTest::addColumn<bool>("duplicates");
        QTest::addColumn<bool>("nonFinite");
        QTest::newRow("face centres") << true << false << false << false << false;
        QTest::newRow("edge midpoints") << false << true << false << false << false;
        QTest::newRow("interior") << false << false << true << false << false;
        QTest::newRow("duplicates") << false << false << false << true << false;
        QTest::newRow("non-finite") << false << false << false << false << true;
        QTest::newRow("everything") << true << true << true << true << true;
    }
    void cubeWithExtraPoints() {
        QFETCH(bool, faceCentres);
        QFETCH(bool, edgeMidpoints);
        QFETCH(bool, interior);
        QFETCH(bool, duplicates);
        QFETCH(bool, nonFinite);
        std::vector<Vec3> pts;
        // Extra points first: the hull must not depend on the corners being listed before them.
        if (faceCentres) {
            for (int axis = 0; axis < 3; ++axis)
                for (Real s : {-1.0, 1.0}) {
                    Vec3 p(0.0);
                    p[axis] = s;
                    pts.push_back(p);
                }
        }
        if (edgeMidpoints) {
            for (int axis = 0; axis < 3; ++axis)
                for (Real s : {-1.0, 1.0})
                    for (Real t : {-1.0, 1.0}) {
                        Vec3 p(0.0);
                        p[(axis + 1) % 3] = s;
                        p[(axis + 2) % 3] = t;
                        pts.push_back(p);
                    }
        }
        if (interior) {
            std::mt19937 rng(7);
            std::uniform_real_distribution<Real> u(-0.99, 0.99);
            for (int i = 0; i < 200; ++i)
                pts.push_back({u(rng), u(rng), u(rng)});
        }
        if (nonFinite) {
            const Real inf = std::numeric_limits<Real>::infinity();
            const Real nan = std::numeric_limits<Real>::quiet_NaN();
            pts.push_back({inf, 0.0, 0.0});
            pts.push_back({0.0, nan, 0.0});
            pts.push_back({-inf, -inf, nan});
        }
        const std::vector<Vec3> corners = cubeCorners();
        pts.insert(pts.end(), corners.begin(), corners.end());
        if (duplicates) {
            pts.insert(pts.end(), corners.begin(), corners.end());
            pts.insert(pts.end(), corners.begin(), corners.begin() + 3);
        }
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        QCOMPARE(hull.vertices.size(), size_t(8));
        QCOMPARE(faceSizes(hull), std::vector<int>(6, 4));
        for (const Vec3& v : hull.vertices)
            QVERIFY(std::abs(v.x) == 1.0 && std::abs(v.y) == 1.0 && std::abs(v.z) == 1.0);
    }

    void tetrahedron() {
        const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}, {0.5, 0.5, 0}};
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        QCOMPARE(hull.vertices.size(), size_t(4));
        QCOMPARE(faceSizes(hull), std::vector<int>(4, 3));
        std::set<uint32_t> inputs(hull.inputIndex.begin(), hull.inputIndex.end());
        QCOMPARE(inputs, (std::set<uint32_t>{0, 1, 2, 3}));
    }

    void cylinder_data() {
        QTest::addColumn<int>("segments");
        QTest::addColumn<bool>("capCentres");
        QTest::newRow("32-gon") << 32 << false;
        QTest::newRow("32-gon with cap centres") << 32 << true;
        QTest::newRow("7-gon") << 7 << false;
        QTest::newRow("128-gon") << 128 << true;
    }
    void cylinder() {
        QFETCH(int, segments);
        QFETCH(bool, capCentres);
        std::vector<Vec3> pts;
        for (int i = 0; i < segments; ++i) {
            const Real a = 2.0 * kPi * i / segments;
            for (Real y : {-0.75, 0.75})
                pts.push_back({0.4 * std::cos(a), y, 0.4 * std::sin(a)});
        }
        if (capCentres) {
            pts.push_back({0.0, -0.75, 0.0});
            pts.push_back({0.0, 0.75, 0.0});
        }
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        QCOMPARE(hull.vertices.size(), size_t(2 * segments));
        std::vector<int> expected(segments, 4);
        expected.push_back(segments);
        expected.push_back(segments);
        std::sort(expected.begin(), expected.end());
        QCOMPARE(faceSizes(hull), expected);
    }

    // Blender writes six decimals, so the faces of a rotated box are planar only to about 1e-6 m (the Cube of
    // resources/scenes/mixed.obj: 7.8e-7). They must still come out as six quads; as twelve triangles a box landing
    // flat got a three-point manifold and sank a corner 3.7 cm into the floor.
    void roundedRotatedBoxHasSixQuads_data() {
        QTest::addColumn<Real>("half");
        QTest::addColumn<Vec3>("centre");
        QTest::newRow("mixed.obj's Cube, as exported") << -1.0 << Vec3(0.0);
        QTest::newRow("10 cm cube") << 0.05 << Vec3(0.3, 0.05, -1.2);
        QTest::newRow("1 m cube") << 0.5 << Vec3(2.0, 0.5, 0.0);
        QTest::newRow("10 m cube far out") << 5.0 << Vec3(120.0, 5.0, -80.0);
    }
    void roundedRotatedBoxHasSixQuads() {
        QFETCH(Real, half);
        QFETCH(Vec3, centre);
        std::vector<Vec3> pts;
        if (half < 0.0) {
            pts = {{1.269854, 0.050000, 0.437522},  {1.259130, 0.488992, 0.676626},  {0.887288, 0.378835, -0.183373},
                   {0.876564, 0.817827, 0.055730},  {2.323436, 0.344394, -0.055730}, {2.312712, 0.783386, 0.183373},
                   {1.940870, 0.673229, -0.676626}, {1.930146, 1.112221, -0.437522}};
        } else {
            const Quat q = glm::normalize(Quat(0.9, 0.2, -0.33, 0.17));
            for (int k = 0; k < 8; ++k) {
                const Vec3 corner(k & 1 ? half : -half, k & 2 ? half : -half, k & 4 ? half : -half);
                pts.push_back(glm::round((centre + q * corner) * 1e6) / 1e6); // as an exporter writes it
            }
        }
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        QCOMPARE(hull.faces.size(), size_t(6));
        for (const auto& face : hull.faces)
            QCOMPARE(face.vertices.size(), size_t(4));
    }

    void uvSphere_data() {
        QTest::addColumn<int>("segments");
        QTest::addColumn<int>("rings");
        QTest::newRow("16x8") << 16 << 8;
        QTest::newRow("32x16") << 32 << 16;
        QTest::newRow("64x48") << 64 << 48;
    }
    void uvSphere() {
        QFETCH(int, segments);
        QFETCH(int, rings);
        const std::vector<Vec3> pts = uvSpherePoints(2.0, segments, rings);
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        // Every point of a UV sphere is a corner; the bands are planar trapezoids and the pole fans are triangles.
        QCOMPARE(hull.vertices.size(), pts.size());
        QCOMPARE(hull.faces.size(), size_t(segments * rings));
        const std::vector<int> sizes = faceSizes(hull);
        QCOMPARE(std::count(sizes.begin(), sizes.end(), 3), 2 * segments);
        QCOMPARE(std::count(sizes.begin(), sizes.end(), 4), segments * (rings - 2));
    }

    void flat_data() {
        QTest::addColumn<QList<Vec3>>("points");
        QTest::addColumn<int>("corners");
        QTest::newRow("blender plane") << QList<Vec3>{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}} << 4;
        QTest::newRow("plane with centre and duplicate")
            << QList<Vec3>{{-1, 0, -1}, {1, 0, -1}, {0, 0, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, 1}, {0, 0, 1}} << 4;
        QList<Vec3> disc;
        const Vec3 u = glm::normalize(Vec3(1, 2, 3));
        const Vec3 v = glm::normalize(glm::cross(u, Vec3(0, 0, 1)));
        for (int i = 0; i < 24; ++i) {
            const Real a = 2.0 * kPi * i / 24;
            disc.push_back(Vec3(5, -3, 2) + 0.3 * std::cos(a) * u + 0.3 * std::sin(a) * v);
            disc.push_back(Vec3(5, -3, 2) + 0.1 * std::cos(a) * u + 0.1 * std::sin(a) * v);
        }
        QTest::newRow("tilted disc") << disc << 24;
        // Thinner than the flat threshold (64 tolerances, here 64 * 6e-11): a slab of slivers is not a useful solid.
        QList<Vec3> thinDisc = disc;
        const Vec3 normal = glm::normalize(glm::cross(u, v));
        for (qsizetype i = 0; i < thinDisc.size(); ++i)
            thinDisc[i] += (i % 3 == 0 ? 1e-9 : -1e-9) * normal;
        QTest::newRow("disc 2e-9 thick") << thinDisc << 24;
        QTest::newRow("triangle") << QList<Vec3>{{0, 0, 0}, {2, 0, 0}, {0, 0, 3}, {0.5, 0, 0.5}} << 3;
    }
    void flat() {
        QFETCH(QList<Vec3>, points);
        QFETCH(int, corners);
        const std::vector<Vec3> pts(points.begin(), points.end());
        const ConvexHull hull = computeConvexHull(pts);
        QCOMPARE(hull.dimension, HullDimension::Flat);
        QCOMPARE(hull.vertices.size(), size_t(corners));
        QCOMPARE(hull.faces.size(), size_t(2));
        const HullFace& a = hull.faces[0];
        const HullFace& b = hull.faces[1];
        QCOMPARE(a.vertices.size(), size_t(corners));
        QVERIFY(std::equal(a.vertices.begin(), a.vertices.end(), b.vertices.rbegin()));
        QVERIFY(std::abs(glm::length(a.normal) - 1.0) < 1e-12);
        QVERIFY(glm::dot(a.normal, b.normal) < -1.0 + 1e-12);
        const HullReport r = inspect(hull, pts);
        const Real tol = checkTolerance(pts);
        QVERIFY(r.indexMapOk);
        QVERIFY(r.edgesPaired);
        QVERIFY(r.worstOutside <= tol);
        // ConvexHull.h: a flat hull's faces lie within its thickness, at most 64 tolerances, of the points.
        QVERIFY(r.worstNonPlanar <= std::max(tol, 64.0 * hull.tolerance));
        QVERIFY(r.worstReflex <= tol);
        QVERIFY(r.worstNormalError <= 1e-9);
    }

    void collinear() {
        std::vector<Vec3> pts;
        const Vec3 dir = glm::normalize(Vec3(1, -2, 0.5));
        for (int i = 0; i < 20; ++i)
            pts.push_back(Vec3(3, 1, 2) + dir * ((i * 7) % 20 - 5.0)); // scrambled, ends at t = -5 and t = 14
        pts.push_back(pts[3]);
        const ConvexHull hull = computeConvexHull(pts);
        QCOMPARE(hull.dimension, HullDimension::Line);
        QCOMPARE(hull.vertices.size(), size_t(2));
        QVERIFY(hull.faces.empty());
        const Real length = glm::length(hull.vertices[0] - hull.vertices[1]);
        QVERIFY(std::abs(length - 19.0) < 1e-12);
        for (size_t i = 0; i < 2; ++i)
            QCOMPARE(pts[hull.inputIndex[i]], hull.vertices[i]);
    }

    void singlePoint_data() {
        QTest::addColumn<int>("copies");
        QTest::newRow("one") << 1;
        QTest::newRow("many copies") << 50;
    }
    void singlePoint() {
        QFETCH(int, copies);
        std::vector<Vec3> pts(copies, Vec3(1.5, -2.0, 1e3));
        pts.insert(pts.begin(), Vec3(std::numeric_limits<Real>::quiet_NaN()));
        const ConvexHull hull = computeConvexHull(pts);
        QCOMPARE(hull.dimension, HullDimension::Point);
        QCOMPARE(hull.vertices.size(), size_t(1));
        QCOMPARE(hull.vertices[0], Vec3(1.5, -2.0, 1e3));
        QCOMPARE(hull.inputIndex[0], 1u);
        QVERIFY(hull.faces.empty());
    }

    void empty() {
        const ConvexHull none = computeConvexHull({});
        QCOMPARE(none.dimension, HullDimension::Empty);
        QVERIFY(none.vertices.empty() && none.faces.empty() && none.inputIndex.empty());
        const std::vector<Vec3> bad{Vec3(std::numeric_limits<Real>::infinity()), Vec3(std::nan(""))};
        const ConvexHull onlyBad = computeConvexHull(bad);
        QCOMPARE(onlyBad.dimension, HullDimension::Empty);
    }

    void randomClouds_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("count");
        // 0 box, 1 ball, 2 sphere surface, 3 grid-snapped box (many exactly coplanar points), 4 the grid jittered by
        // 1e-10 (coplanar only within the tolerance), 5 a slab 1e-7 thick (nearly flat, so concave folds would add
        // up), 6 the rims of a 32-gon cylinder jittered by 1e-10.
        QTest::addColumn<int>("kind");
        QTest::addColumn<Real>("scale");
        QTest::addColumn<Vec3>("offset");
        const int counts[10] = {5, 12, 50, 100, 300, 600, 1000, 1500, 2000, 2000};
        const Real scales[10] = {1.0, 1e-3, 1e3, 1.0, 1.0, 1e-3, 1e3, 1.0, 1.0, 1.0};
        for (int seed = 0; seed < 10; ++seed) {
            for (int kind = 0; kind < 7; ++kind) {
                if (kind == 6 && counts[seed] < 50)
                    continue; // a few rim points may all lie on one rim: flat, not a solid
                const Vec3 offset = seed % 3 == 2 ? Vec3(1e3, 2e3, -5e2) * scales[seed] : Vec3(0.0);
                QTest::addRow("seed %d kind %d n %d", seed, kind, counts[seed])
                    << seed << counts[seed] << kind << scales[seed] << offset;
            }
        }
    }
    void randomClouds() {
        QFETCH(int, seed);
        QFETCH(int, count);
        QFETCH(int, kind);
        QFETCH(Real, scale);
        QFETCH(Vec3, offset);
        std::mt19937_64 rng(1000 + seed);
        std::uniform_real_distribution<Real> u(-1.0, 1.0);
        std::normal_distribution<Real> g(0.0, 1.0);
        std::vector<Vec3> pts;
        while (static_cast<int>(pts.size()) < count) {
            Vec3 p(u(rng), u(rng), u(rng));
            if (kind == 1 && glm::length(p) > 1.0)
                continue;
            if (kind == 2)
                p = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
            if (kind == 3 || kind == 4)
                p = glm::round(p * 4.0) / 4.0;
            if (kind == 5)
                p.y *= 1e-7;
            if (kind == 6) {
                const Real a = 2.0 * kPi * std::floor((u(rng) + 1.0) * 16.0) / 32.0;
                p = Vec3(std::cos(a), p.y > 0.0 ? 1.0 : -1.0, std::sin(a));
            }
            if (kind == 4 || kind == 6)
                p += 1e-10 * Vec3(u(rng), u(rng), u(rng));
            pts.push_back(offset + scale * p);
        }
        const ConvexHull hull = computeConvexHull(pts);
        verifySolid(hull, pts);
        if (kind == 2)
            QVERIFY(hull.vertices.size() >= size_t(count) * 9 / 10); // almost every surface point is a corner
    }
};

QTEST_APPLESS_MAIN(TestConvexHull)
#include "tst_convexhull.moc"
