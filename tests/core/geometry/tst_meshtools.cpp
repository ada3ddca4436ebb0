// Tests of the mesh utilities: primitive meshes (closed, outward, exact polyhedral volume), hull triangulation,
// welding, closedness, and the concavity test on convex and concave shapes.
#include "geometry/ConvexHull.h"
#include "geometry/MassProperties.h"
#include "geometry/MeshTools.h"

#include <QTest>

#include <cmath>
#include <map>

using namespace rl;

Q_DECLARE_METATYPE(rl::TriangleMesh)

namespace {

// Signed volume straight from the definition, independent of the library.
Real signedVolume(const TriangleMesh& m) {
    Real s = 0.0;
    for (const auto& t : m.triangles)
        s += glm::dot(m.vertices[t[0]], glm::cross(m.vertices[t[1]], m.vertices[t[2]]));
    return s / 6.0;
}

// Every directed edge used once and its reverse used once, by index (the generators share vertices).
bool edgesPaired(const TriangleMesh& m) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : m.triangles)
        for (int e = 0; e < 3; ++e)
            ++directed[{t[e], t[(e + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        const auto twin = directed.find({edge.second, edge.first});
        if (count != 1 || twin == directed.end() || twin->second != 1)
            return false;
    }
    return !m.triangles.empty();
}

// Flips every triangle when the (consistently wound) mesh is inside out.
TriangleMesh outward(TriangleMesh m) {
    if (signedVolume(m) < 0.0)
        for (auto& t : m.triangles)
            std::swap(t[1], t[2]);
    return m;
}

// Area of a regular n-gon of circumradius r.
Real ngonArea(int n, Real r) {
    return 0.5 * n * r * r * std::sin(2.0 * kPi / n);
}

// The UV sphere's exact polyhedral volume: pyramids at the poles and frusta of similar n-gons between rings.
Real uvSphereVolume(Real r, int segments, int rings) {
    Real v = 0.0;
    for (int i = 0; i < rings; ++i) {
        const Real phi0 = kPi * i / rings, phi1 = kPi * (i + 1) / rings;
        const Real a0 = ngonArea(segments, r * std::sin(phi0)), a1 = ngonArea(segments, r * std::sin(phi1));
        const Real h = r * (std::cos(phi0) - std::cos(phi1));
        v += h / 3.0 * (a0 + a1 + std::sqrt(a0 * a1));
    }
    return v;
}

TriangleMesh torus(Real major, Real minor, int around, int tube) {
    TriangleMesh m;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const Real u = 2.0 * kPi * i / around, v = 2.0 * kPi * j / tube;
            m.vertices.push_back({(major + minor * std::cos(v)) * std::cos(u), minor * std::sin(v),
                                  (major + minor * std::cos(v)) * std::sin(u)});
        }
    auto id = [&](int i, int j) { return static_cast<uint32_t>((i % around) * tube + (j % tube)); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return outward(m);
}

// An L-shaped prism: the L (3 unit squares) in XY, extruded along Z by 1. Volume 3.
TriangleMesh lPrism() {
    const std::vector<glm::dvec2> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    TriangleMesh m;
    for (Real z : {0.0, 1.0})
        for (const auto& p : l)
            m.vertices.push_back({p.x, p.y, z});
    const uint32_t n = static_cast<uint32_t>(l.size());
    // The L is star-shaped from (0, 0), so fans from vertex 0 triangulate both caps.
    for (uint32_t i = 1; i + 1 < n; ++i) {
        m.triangles.push_back({0, i + 1, i});
        m.triangles.push_back({n, n + i, n + i + 1});
    }
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t k = (i + 1) % n;
        m.triangles.push_back({i, k, n + k});
        m.triangles.push_back({i, n + k, n + i});
    }
    return outward(m);
}

// A triangular prism with the top twisted by 30 degrees; each side quad is split along one of its two diagonals.
// One choice is the convex hull, the other is Schönhardt's polyhedron: every vertex on the hull, reflex edges.
TriangleMesh twistedPrism(bool otherDiagonal) {
    TriangleMesh m;
    for (int i = 0; i < 3; ++i) {
        const Real a = 2.0 * kPi * i / 3.0;
        m.vertices.push_back({std::cos(a), 0.0, std::sin(a)});
    }
    for (int i = 0; i < 3; ++i) {
        const Real a = 2.0 * kPi * i / 3.0 + kPi / 6.0;
        m.vertices.push_back({std::cos(a), 1.0, std::sin(a)});
    }
    m.triangles.push_back({0, 2, 1});
    m.triangles.push_back({3, 4, 5});
    for (uint32_t i = 0; i < 3; ++i) {
        const uint32_t b0 = i, b1 = (i + 1) % 3, t0 = 3 + i, t1 = 3 + (i + 1) % 3;
        if (otherDiagonal) {
            m.triangles.push_back({b0, b1, t1});
            m.triangles.push_back({b0, t1, t0});
        } else {
            m.triangles.push_back({b0, b1, t0});
            m.triangles.push_back({b1, t1, t0});
        }
    }
    return outward(m);
}

TriangleMesh roundedTo(TriangleMesh m, Real step) {
    for (Vec3& v : m.vertices)
        v = glm::round(v / step) * step;
    return m;
}

} // namespace

class TestMeshTools : public QObject {
    Q_OBJECT

private slots:
    void primitives_data() {
        QTest::addColumn<TriangleMesh>("mesh");
        QTest::addColumn<Real>("polyhedralVolume"); // exact volume of the polyhedron the generator should make
        QTest::addColumn<Real>("smoothVolume");     // volume of the smooth solid it approximates
        QTest::addColumn<Real>("smoothTolerance");  // relative, from the discretisation: about (2 pi / n)^2 / 6
        QTest::addColumn<int>("vertexCount");
        QTest::addColumn<int>("triangleCount");
        QTest::newRow("box") << makeBoxMesh(Vec3(0.5, 1.0, 1.5)) << 6.0 << 6.0 << 0.0 << 8 << 12;
        QTest::newRow("uv sphere 32x16") << makeUvSphereMesh(1.3, 32, 16) << uvSphereVolume(1.3, 32, 16)
                                         << 4.0 / 3.0 * kPi * std::pow(1.3, 3) << 0.02 << 32 * 15 + 2 << 2 * 32 * 15;
        QTest::newRow("uv sphere 3x2") << makeUvSphereMesh(1.0, 3, 2) << uvSphereVolume(1.0, 3, 2) << 4.0 / 3.0 * kPi
                                       << 0.9 << 5 << 6;
        QTest::newRow("cylinder 32") << makeCylinderMesh(0.4, 0.75, 32) << ngonArea(32, 0.4) * 1.5 << kPi * 0.16 * 1.5
                                     << 0.01 << 64 << 124;
        QTest::newRow("cone 32") << makeConeMesh(0.5, 1.0, 32) << ngonArea(32, 0.5) * 2.0 / 3.0
                                 << kPi * 0.25 * 2.0 / 3.0 << 0.01 << 33 << 62;
        QTest::newRow("segments clamped to 3")
            << makeCylinderMesh(1.0, 1.0, 1) << ngonArea(3, 1.0) * 2.0 << ngonArea(3, 1.0) * 2.0 << 0.0 << 6 << 8;
    }
    void primitives() {
        QFETCH(TriangleMesh, mesh);
        QFETCH(Real, polyhedralVolume);
        QFETCH(Real, smoothVolume);
        QFETCH(Real, smoothTolerance);
        QFETCH(int, vertexCount);
        QFETCH(int, triangleCount);
        QCOMPARE(int(mesh.vertices.size()), vertexCount);
        QCOMPARE(int(mesh.triangles.size()), triangleCount);
        QVERIFY(edgesPaired(mesh));
        QVERIFY(isClosedMesh(mesh.vertices, mesh.triangles));
        // Outward: positive signed volume, and every triangle faces away from the origin (the shapes are convex).
        QVERIFY(signedVolume(mesh) > 0.0);
        for (const auto& t : mesh.triangles) {
            const Vec3& a = mesh.vertices[t[0]];
            const Vec3 n = glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
            QVERIFY(glm::dot(n, a) > 0.0);
        }
        const Real volume = closedMeshVolume(mesh.vertices, mesh.triangles);
        QVERIFY2(
            std::abs(volume - polyhedralVolume) <= 1e-12 * polyhedralVolume,
            qPrintable(QString("volume %1 expected %2").arg(volume, 0, 'g', 17).arg(polyhedralVolume, 0, 'g', 17)));
        QVERIFY(std::abs(volume - smoothVolume) <= smoothTolerance * smoothVolume + 1e-12);

        // A convex primitive is its own hull: same volume, and not concave.
        const ConvexHull hull = computeConvexHull(mesh.vertices);
        QCOMPARE(hull.dimension, HullDimension::Solid);
        QVERIFY(std::abs(hullMassProperties(hull).volume - volume) <= 1e-12 * volume);
        QVERIFY(!isConcave(mesh.vertices, mesh.triangles, hull));
        const TriangleMesh fromHull = hullMesh(hull);
        QVERIFY(edgesPaired(fromHull));
        QVERIFY(std::abs(signedVolume(fromHull) - volume) <= 1e-12 * volume);
    }

    void badSizes_data() {
        QTest::addColumn<TriangleMesh>("mesh");
        const Real nan = std::numeric_limits<Real>::quiet_NaN();
        QTest::newRow("box zero") << makeBoxMesh(Vec3(1.0, 0.0, 1.0));
        QTest::newRow("box nan") << makeBoxMesh(Vec3(nan));
        QTest::newRow("sphere negative") << makeUvSphereMesh(-1.0, 8, 4);
        QTest::newRow("cylinder infinite") << makeCylinderMesh(1.0, std::numeric_limits<Real>::infinity(), 8);
        QTest::newRow("cone nan") << makeConeMesh(nan, 1.0, 8);
    }
    void badSizes() {
        QFETCH(TriangleMesh, mesh);
        QVERIFY(mesh.vertices.empty());
        QVERIFY(mesh.triangles.empty());
    }

    void resolutionClamped() {
        // A typo like 100000 segments is clamped to 1024 (MeshTools.h), not allocated.
        QCOMPARE(makeCylinderMesh(1.0, 1.0, 100000).vertices.size(), size_t(2 * 1024));
        QCOMPARE(makeUvSphereMesh(1.0, 1 << 30, 1 << 30).vertices.size(), size_t(1024 * 1023 + 2));
        QCOMPARE(makeUvSphereMesh(1.0, -5, 0).vertices.size(), size_t(3 * 1 + 2));
    }

    void concavity_data() {
        QTest::addColumn<TriangleMesh>("mesh");
        QTest::addColumn<bool>("concave");
        QTest::newRow("box") << makeBoxMesh(Vec3(1.0, 2.0, 3.0)) << false;
        QTest::newRow("uv sphere") << makeUvSphereMesh(1.0, 24, 12) << false;
        QTest::newRow("uv sphere, OBJ-rounded 1e-6") << roundedTo(makeUvSphereMesh(1.0, 64, 32), 1e-6) << false;
        QTest::newRow("cylinder 32") << makeCylinderMesh(0.5, 1.0, 32) << false;
        QTest::newRow("cone") << makeConeMesh(0.5, 1.0, 16) << false;
        QTest::newRow("torus") << torus(1.0, 0.3, 24, 12) << true;
        QTest::newRow("L prism") << lPrism() << true;
        QTest::newRow("twisted prism, hull diagonals") << twistedPrism(false) << false;
        QTest::newRow("twisted prism, Schoenhardt diagonals") << twistedPrism(true) << true;
        TriangleMesh lSheet;
        lSheet.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}, {1, 0, 2}, {0, 0, 2}};
        lSheet.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}};
        QTest::newRow("L sheet") << lSheet << true;
        TriangleMesh plane;
        plane.vertices = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
        plane.triangles = {{0, 2, 1}, {0, 3, 2}};
        QTest::newRow("blender plane") << plane << false;
        TriangleMesh halfPlane = plane;
        halfPlane.triangles.pop_back();
        QTest::newRow("plane missing a triangle") << halfPlane << true;
    }
    void concavity() {
        QFETCH(TriangleMesh, mesh);
        QFETCH(bool, concave);
        const ConvexHull hull = computeConvexHull(mesh.vertices);
        QCOMPARE(isConcave(mesh.vertices, mesh.triangles, hull), concave);
    }

    void schoenhardtHasAllVerticesOnHull() {
        // The Schönhardt case must be caught by volume, not by depth: check that its premise holds.
        const TriangleMesh m = twistedPrism(true);
        const ConvexHull hull = computeConvexHull(m.vertices);
        QCOMPARE(hull.vertices.size(), size_t(6));
        QVERIFY(closedMeshVolume(m.vertices, m.triangles) < 0.99 * hullMassProperties(hull).volume);
        QVERIFY(isClosedMesh(m.vertices, m.triangles));
    }

    void weldAndClosed() {
        const TriangleMesh box = makeBoxMesh(Vec3(1.0));
        // Unwelded, as an importer that copies a vertex per face corner would produce it.
        TriangleMesh soup;
        for (const auto& t : box.triangles) {
            const uint32_t base = static_cast<uint32_t>(soup.vertices.size());
            for (uint32_t v : t)
                soup.vertices.push_back(box.vertices[v]);
            soup.triangles.push_back({base, base + 1, base + 2});
        }
        QVERIFY(!edgesPaired(soup));
        QVERIFY(isClosedMesh(soup.vertices, soup.triangles));
        const TriangleMesh welded = weldVertices(soup.vertices, soup.triangles);
        QCOMPARE(welded.vertices.size(), size_t(8));
        QCOMPARE(welded.triangles.size(), size_t(12));
        QVERIFY(edgesPaired(welded));
        QVERIFY(std::abs(closedMeshVolume(soup.vertices, soup.triangles) - 8.0) < 1e-12);

        TriangleMesh open = box;
        open.triangles.pop_back();
        QVERIFY(!isClosedMesh(open.vertices, open.triangles));
        TriangleMesh flipped = box;
        std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
        QVERIFY(!isClosedMesh(flipped.vertices, flipped.triangles));
        TriangleMesh badIndex = box;
        badIndex.triangles.push_back({0, 1, 1000});
        QVERIFY(!isClosedMesh(badIndex.vertices, badIndex.triangles));
        QVERIFY(std::abs(closedMeshVolume(badIndex.vertices, badIndex.triangles) - 8.0) < 1e-12);
        QVERIFY(!isClosedMesh({}, {}));
        QCOMPARE(closedMeshVolume({}, {}), 0.0);

        // Inside-out winding: same volume.
        TriangleMesh inverted = box;
        for (auto& t : inverted.triangles)
            std::swap(t[1], t[2]);
        QVERIFY(std::abs(closedMeshVolume(inverted.vertices, inverted.triangles) - 8.0) < 1e-12);
    }

    void hullMeshFlatAndDegenerate() {
        const std::vector<Vec3> hexagon{{1, 0, 0},  {0.5, 0, 0.8},   {-0.5, 0, 0.8},
                                        {-1, 0, 0}, {-0.5, 0, -0.8}, {0.5, 0, -0.8}};
        const TriangleMesh sheet = hullMesh(computeConvexHull(hexagon));
        QCOMPARE(sheet.triangles.size(), size_t(2 * (6 - 2)));
        QVERIFY(edgesPaired(sheet)); // two-sided: each edge once on each side
        QVERIFY(std::abs(signedVolume(sheet)) < 1e-15);
        const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
        QVERIFY(hullMesh(computeConvexHull(line)).triangles.empty());
        QVERIFY(hullMesh(ConvexHull{}).vertices.empty());
    }
};

QTEST_APPLESS_MAIN(TestMeshTools)
#include "tst_meshtools.moc"
