// Tests of the mass-property integrals against closed forms: boxes, a general tetrahedron (Tonon 2004), rotated and
// far-translated boxes, refined spheres, the parallel-axis shift, rotation of tensors and Jacobi principal axes.
#include "geometry/ConvexHull.h"
#include "geometry/MassProperties.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace rl;

Q_DECLARE_METATYPE(rl::Vec3)

namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

constexpr Real kRelTol = 1e-9;

Real maxAbs(const Mat3& m) {
    Real r = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            r = std::max(r, std::abs(m[c][k]));
    return r;
}

Real maxAbsDiff(const Mat3& a, const Mat3& b) {
    return maxAbs(a - b);
}

// Winds every triangle of a convex mesh outward, judged from a point inside it.
void orientOutward(const std::vector<Vec3>& v, Triangles& tris, const Vec3& inside) {
    for (auto& t : tris) {
        const Vec3 n = glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
        if (glm::dot(n, v[t[0]] - inside) < 0.0)
            std::swap(t[1], t[2]);
    }
}

// Axis-aligned box of half extents h centred on c, as 12 outward triangles.
void boxMesh(const Vec3& h, const Vec3& c, std::vector<Vec3>& v, Triangles& tris) {
    v.clear();
    tris.clear();
    for (int i = 0; i < 8; ++i)
        v.push_back(c + h * Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    // Each face is the four corners sharing one coordinate bit; split along a diagonal.
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            std::vector<uint32_t> q;
            for (uint32_t i = 0; i < 8; ++i)
                if (((i >> axis) & 1) == uint32_t(side))
                    q.push_back(i);
            // q is ordered by index, so q[0] and q[3] are opposite corners of the face.
            tris.push_back({q[0], q[1], q[3]});
            tris.push_back({q[0], q[3], q[2]});
        }
    }
    orientOutward(v, tris, c);
}

Mat3 boxInertia(const Vec3& h) {
    const Real m = 8.0 * h.x * h.y * h.z;
    return Mat3(Vec3(m / 3.0 * (h.y * h.y + h.z * h.z), 0, 0), Vec3(0, m / 3.0 * (h.x * h.x + h.z * h.z), 0),
                Vec3(0, 0, m / 3.0 * (h.x * h.x + h.y * h.y)));
}

// Icosphere of radius r with the given number of midpoint subdivisions, vertices projected onto the sphere.
void icosphere(Real r, int subdivisions, std::vector<Vec3>& v, Triangles& tris) {
    const Real phi = (1.0 + std::sqrt(5.0)) / 2.0;
    v.clear();
    tris.clear();
    for (Real a : {-1.0, 1.0})
        for (Real b : {-phi, phi}) {
            v.push_back({0, a, b});
            v.push_back({a, b, 0});
            v.push_back({b, 0, a});
        }
    // The icosahedron's faces are the triples of mutually adjacent vertices (edge length 2).
    for (uint32_t i = 0; i < 12; ++i)
        for (uint32_t j = i + 1; j < 12; ++j)
            for (uint32_t k = j + 1; k < 12; ++k) {
                auto adjacent = [&](uint32_t a, uint32_t b) { return std::abs(glm::length(v[a] - v[b]) - 2.0) < 1e-9; };
                if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k))
                    tris.push_back({i, j, k});
            }
    for (Vec3& p : v)
        p = r * glm::normalize(p);
    orientOutward(v, tris, Vec3(0.0));
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end())
                return it->second;
            v.push_back(r * glm::normalize(v[a] + v[b]));
            return mid[key] = static_cast<uint32_t>(v.size() - 1);
        };
        Triangles next;
        for (const auto& t : tris) {
            const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({t[1], bc, ab});
            next.push_back({t[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        tris = std::move(next);
    }
}

Mat3 rotationOf(const Vec3& axis, Real angle) {
    return glm::mat3_cast(glm::angleAxis(angle, glm::normalize(axis)));
}

} // namespace

class TestMassProperties : public QObject {
    Q_OBJECT

private slots:
    void box_data() {
        QTest::addColumn<Vec3>("halfExtents");
        QTest::addColumn<Vec3>("centre");
        QTest::newRow("unit box") << Vec3(0.5) << Vec3(0.0);
        QTest::newRow("1x2x3 box") << Vec3(0.5, 1.0, 1.5) << Vec3(0.0);
        QTest::newRow("1x2x3 box off centre") << Vec3(0.5, 1.0, 1.5) << Vec3(0.25, -3.0, 7.0);
        QTest::newRow("1x2x3 box 1 km away") << Vec3(0.5, 1.0, 1.5) << Vec3(1e3, -2e3, 5e2);
        QTest::newRow("1x2x3 box 1000 km away") << Vec3(0.5, 1.0, 1.5) << Vec3(1e6, 3e6, -2e6);
        QTest::newRow("1 mm box 1 km away") << Vec3(0.5e-3, 1e-3, 1.5e-3) << Vec3(1e3, -1e3, 0.0);
    }
    void box() {
        QFETCH(Vec3, halfExtents);
        QFETCH(Vec3, centre);
        std::vector<Vec3> v;
        Triangles tris;
        boxMesh(halfExtents, centre, v, tris);
        const MassProperties mp = polyhedronMassProperties(v, tris);
        const Real volume = 8.0 * halfExtents.x * halfExtents.y * halfExtents.z;
        const Real area =
            8.0 * (halfExtents.x * halfExtents.y + halfExtents.y * halfExtents.z + halfExtents.x * halfExtents.z);
        const Mat3 expected = boxInertia(halfExtents);
        QVERIFY(std::abs(mp.volume - volume) <= kRelTol * volume);
        QVERIFY(std::abs(mp.area - area) <= kRelTol * area);
        const Real size = glm::length(halfExtents);
        QVERIFY2(glm::length(mp.centroid - centre) <= kRelTol * size,
                 qPrintable(QString("centroid error %1").arg(glm::length(mp.centroid - centre))));
        QVERIFY2(
            maxAbsDiff(mp.inertia, expected) <= kRelTol * maxAbs(expected),
            qPrintable(QString("inertia error %1 of %2").arg(maxAbsDiff(mp.inertia, expected)).arg(maxAbs(expected))));
    }

    void tetrahedron_data() {
        QTest::addColumn<Vec3>("p1");
        QTest::addColumn<Vec3>("p2");
        QTest::addColumn<Vec3>("p3");
        QTest::addColumn<Vec3>("p4");
        QTest::newRow("corner") << Vec3(0, 0, 0) << Vec3(1, 0, 0) << Vec3(0, 1, 0) << Vec3(0, 0, 1);
        QTest::newRow("general") << Vec3(8.33220, -11.86875, 0.93355) << Vec3(0.75523, 5.00000, 16.37072)
                                 << Vec3(52.61236, 5.00000, -5.38580) << Vec3(2.00000, 5.00000, 3.00000);
        QTest::newRow("sliver") << Vec3(0, 0, 0) << Vec3(3, 0.1, 0) << Vec3(0.2, 2, 0.1) << Vec3(1, 1, 0.05);
    }
    void tetrahedron() {
        QFETCH(Vec3, p1);
        QFETCH(Vec3, p2);
        QFETCH(Vec3, p3);
        QFETCH(Vec3, p4);
        const std::vector<Vec3> v{p1, p2, p3, p4};
        Triangles tris{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
        const Vec3 centroid = (p1 + p2 + p3 + p4) / 4.0;
        orientOutward(v, tris, centroid);
        const MassProperties mp = polyhedronMassProperties(v, tris);

        const Real jacobian = std::abs(glm::dot(p2 - p1, glm::cross(p3 - p1, p4 - p1)));
        const Real volume = jacobian / 6.0;
        // Tonon (2004), J. Math. Stat. 1(1): the moments about the centroid as sums over vertex pairs i <= j of the
        // centroid-relative coordinates, e.g. a = |J|/60 * sum(y_i y_j + z_i z_j), a' = |J|/120 * sum(y_i z_j + ...).
        std::array<Vec3, 4> q{p1 - centroid, p2 - centroid, p3 - centroid, p4 - centroid};
        auto square = [&](int k) {
            Real s = 0.0;
            for (int i = 0; i < 4; ++i)
                for (int j = i; j < 4; ++j)
                    s += q[i][k] * q[j][k];
            return s;
        };
        auto product = [&](int k, int l) {
            Real s = 0.0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    s += (i == j ? 2.0 : 1.0) * q[i][k] * q[j][l];
            return s;
        };
        const Real a = jacobian / 60.0 * (square(1) + square(2));
        const Real b = jacobian / 60.0 * (square(0) + square(2));
        const Real c = jacobian / 60.0 * (square(0) + square(1));
        const Real aPrime = jacobian / 120.0 * product(1, 2);
        const Real bPrime = jacobian / 120.0 * product(0, 2);
        const Real cPrime = jacobian / 120.0 * product(0, 1);
        const Mat3 expected(Vec3(a, -cPrime, -bPrime), Vec3(-cPrime, b, -aPrime), Vec3(-bPrime, -aPrime, c));

        QVERIFY(std::abs(mp.volume - volume) <= kRelTol * volume);
        QVERIFY(glm::length(mp.centroid - centroid) <= kRelTol * glm::length(q[0]));
        QVERIFY2(
            maxAbsDiff(mp.inertia, expected) <= kRelTol * maxAbs(expected),
            qPrintable(QString("inertia error %1 of %2").arg(maxAbsDiff(mp.inertia, expected)).arg(maxAbs(expected))));
        // The same solid through the hull path.
        const MassProperties viaHull = hullMassProperties(computeConvexHull(v));
        QVERIFY(std::abs(viaHull.volume - volume) <= kRelTol * volume);
        QVERIFY(maxAbsDiff(viaHull.inertia, expected) <= kRelTol * maxAbs(expected));
    }

    void rotatedScaledBox_data() {
        QTest::addColumn<Vec3>("halfExtents");
        QTest::addColumn<Vec3>("axis");
        QTest::addColumn<Real>("angle");
        QTest::addColumn<Vec3>("centre");
        QTest::newRow("small tilt") << Vec3(0.5, 1.0, 1.5) << Vec3(0, 0, 1) << 0.1 << Vec3(0.0);
        QTest::newRow("oblique") << Vec3(0.2, 3.0, 0.7) << Vec3(1, 2, 3) << 1.0 << Vec3(4, 5, -6);
        QTest::newRow("oblique far") << Vec3(2.0, 0.1, 1.0) << Vec3(-1, 0.3, 0.2) << 2.5 << Vec3(-3e4, 1e4, 2e4);
    }
    void rotatedScaledBox() {
        QFETCH(Vec3, halfExtents);
        QFETCH(Vec3, axis);
        QFETCH(Real, angle);
        QFETCH(Vec3, centre);
        const Mat3 r = rotationOf(axis, angle);
        std::vector<Vec3> v;
        Triangles tris;
        boxMesh(halfExtents, Vec3(0.0), v, tris);
        for (Vec3& p : v)
            p = centre + r * p;
        const MassProperties mp = polyhedronMassProperties(v, tris);
        const Mat3 expected = r * boxInertia(halfExtents) * glm::transpose(r);
        QVERIFY(std::abs(mp.volume - 8.0 * halfExtents.x * halfExtents.y * halfExtents.z) <= kRelTol * mp.volume);
        QVERIFY(glm::length(mp.centroid - centre) <= kRelTol * glm::length(halfExtents));
        QVERIFY2(
            maxAbsDiff(mp.inertia, expected) <= kRelTol * maxAbs(expected),
            qPrintable(QString("inertia error %1 of %2").arg(maxAbsDiff(mp.inertia, expected)).arg(maxAbs(expected))));
        QVERIFY(maxAbsDiff(rotateInertia(boxInertia(halfExtents), r), expected) <= 1e-12 * maxAbs(expected));

        // Principal axes recover the box's moments, and its axes up to sign and order.
        Vec3 moments;
        Mat3 axes;
        principalAxes(mp.inertia, moments, axes);
        const Mat3 local = boxInertia(halfExtents);
        std::array<Real, 3> sorted{local[0][0], local[1][1], local[2][2]};
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < 3; ++i)
            QVERIFY(std::abs(moments[i] - sorted[i]) <= kRelTol * sorted[2]);
        QVERIFY(std::abs(glm::determinant(axes) - 1.0) < 1e-12);
        for (int i = 0; i < 3; ++i) {
            Real best = 0.0;
            for (int k = 0; k < 3; ++k)
                best = std::max(best, std::abs(glm::dot(axes[i], r[k])));
            QVERIFY(std::abs(best - 1.0) < 1e-9);
        }
        const Mat3 rebuilt =
            axes * Mat3(Vec3(moments.x, 0, 0), Vec3(0, moments.y, 0), Vec3(0, 0, moments.z)) * glm::transpose(axes);
        QVERIFY(maxAbsDiff(rebuilt, mp.inertia) <= kRelTol * maxAbs(expected));
    }

    void principalAxesDegenerate_data() {
        QTest::addColumn<Vec3>("diagonal");
        QTest::newRow("isotropic") << Vec3(2.0, 2.0, 2.0);
        QTest::newRow("two equal") << Vec3(1.0, 3.0, 3.0);
        QTest::newRow("zero") << Vec3(0.0);
        QTest::newRow("distinct") << Vec3(5.0, 1.0, 3.0);
    }
    void principalAxesDegenerate() {
        QFETCH(Vec3, diagonal);
        const Mat3 r = rotationOf(Vec3(0.3, -1.0, 0.4), 0.8);
        const Mat3 tensor =
            r * Mat3(Vec3(diagonal.x, 0, 0), Vec3(0, diagonal.y, 0), Vec3(0, 0, diagonal.z)) * glm::transpose(r);
        Vec3 moments;
        Mat3 axes;
        principalAxes(tensor, moments, axes);
        std::array<Real, 3> sorted{diagonal.x, diagonal.y, diagonal.z};
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < 3; ++i)
            QVERIFY(std::abs(moments[i] - sorted[i]) <= 1e-12 * (1.0 + sorted[2]));
        QVERIFY(maxAbsDiff(glm::transpose(axes) * axes, Mat3(1.0)) < 1e-12);
        QVERIFY(std::abs(glm::determinant(axes) - 1.0) < 1e-12);
    }

    void shiftToCorner() {
        // A 1x2x3 box about its corner: I_xx = m (B^2 + C^2) / 3 and I_xy = -m A B / 4 for edge lengths A, B, C.
        const Vec3 h(0.5, 1.0, 1.5);
        const Vec3 e = 2.0 * h;
        const Real m = e.x * e.y * e.z;
        const Mat3 corner = shiftInertia(boxInertia(h), m, h);
        const Mat3 expected(Vec3(m * (e.y * e.y + e.z * e.z) / 3.0, -m * e.x * e.y / 4.0, -m * e.x * e.z / 4.0),
                            Vec3(-m * e.x * e.y / 4.0, m * (e.x * e.x + e.z * e.z) / 3.0, -m * e.y * e.z / 4.0),
                            Vec3(-m * e.x * e.z / 4.0, -m * e.y * e.z / 4.0, m * (e.x * e.x + e.y * e.y) / 3.0));
        QVERIFY(maxAbsDiff(corner, expected) <= kRelTol * maxAbs(expected));
        // And back again.
        QVERIFY(maxAbsDiff(shiftInertia(corner, m, Vec3(0.0)), corner) == 0.0);
    }

    void sphereConvergence() {
        const Real r = 1.3;
        const Real volume = 4.0 / 3.0 * kPi * r * r * r;
        const Real moment = 0.4 * volume * r * r;
        Real lastVolumeError = std::numeric_limits<Real>::max();
        Real lastInertiaError = std::numeric_limits<Real>::max();
        for (int level = 0; level <= 5; ++level) {
            std::vector<Vec3> v;
            Triangles tris;
            icosphere(r, level, v, tris);
            const MassProperties mp = polyhedronMassProperties(v, tris);
            const Real volumeError = std::abs(mp.volume - volume) / volume;
            Real inertiaError = 0.0;
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k)
                    inertiaError =
                        std::max(inertiaError, std::abs(mp.inertia[c][k] - (c == k ? moment : 0.0)) / moment);
            qDebug("level %d triangles %zu volume error %.3e inertia error %.3e", level, tris.size(), volumeError,
                   inertiaError);
            QVERIFY(volumeError < lastVolumeError);
            QVERIFY(inertiaError < lastInertiaError);
            QVERIFY(mp.volume < volume); // an inscribed polyhedron is smaller than its sphere
            QVERIFY(glm::length(mp.centroid) < 1e-12 * r);
            lastVolumeError = volumeError;
            lastInertiaError = inertiaError;
        }
        // Midpoint subdivision quarters the edge length squared, so the error falls about fourfold per level.
        QVERIFY(lastVolumeError < 1e-3);
        QVERIFY(lastInertiaError < 2e-3);
    }

    void hullOfBox() {
        std::vector<Vec3> v;
        Triangles tris;
        const Vec3 h(0.5, 1.0, 1.5);
        boxMesh(h, Vec3(2, 3, 4), v, tris);
        const MassProperties mp = hullMassProperties(computeConvexHull(v));
        QVERIFY(std::abs(mp.volume - 6.0) <= kRelTol * 6.0);
        QVERIFY(std::abs(mp.area - 22.0) <= kRelTol * 22.0);
        QVERIFY(glm::length(mp.centroid - Vec3(2, 3, 4)) <= kRelTol);
        QVERIFY(maxAbsDiff(mp.inertia, boxInertia(h)) <= kRelTol * maxAbs(boxInertia(h)));
    }

    void flatHull_data() {
        QTest::addColumn<QList<Vec3>>("points");
        QTest::addColumn<Real>("area");
        QTest::addColumn<Vec3>("centroid");
        QTest::newRow("blender plane") << QList<Vec3>{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}} << 4.0
                                       << Vec3(0.0);
        QTest::newRow("triangle") << QList<Vec3>{{0, 2, 0}, {3, 2, 0}, {0, 2, 3}} << 4.5 << Vec3(1, 2, 1);
        QTest::newRow("tilted rectangle far") << QList<Vec3>{{1e3, 0, 0}, {1e3 + 2, 2, 0}, {1e3 + 2, 2, 5}, {1e3, 0, 5}}
                                              << 5.0 * std::sqrt(8.0) << Vec3(1e3 + 1, 1, 2.5);
    }
    void flatHull() {
        QFETCH(QList<Vec3>, points);
        QFETCH(Real, area);
        QFETCH(Vec3, centroid);
        const ConvexHull hull = computeConvexHull(std::vector<Vec3>(points.begin(), points.end()));
        QCOMPARE(hull.dimension, HullDimension::Flat);
        const MassProperties mp = hullMassProperties(hull);
        QCOMPARE(mp.volume, 0.0);
        QVERIFY(std::abs(mp.area - area) <= kRelTol * area);
        QVERIFY(glm::length(mp.centroid - centroid) <= kRelTol * glm::length(centroid) + 1e-12);
        QCOMPARE(maxAbs(mp.inertia), 0.0);
    }

    void badInput() {
        std::vector<Vec3> v;
        Triangles tris;
        boxMesh(Vec3(1.0), Vec3(0.0), v, tris);
        // Inward winding: same magnitudes.
        Triangles inward = tris;
        for (auto& t : inward)
            std::swap(t[1], t[2]);
        const MassProperties out = polyhedronMassProperties(v, tris);
        const MassProperties in = polyhedronMassProperties(v, inward);
        QVERIFY(std::abs(in.volume - out.volume) <= kRelTol * out.volume);
        QVERIFY(maxAbsDiff(in.inertia, out.inertia) <= kRelTol * maxAbs(out.inertia));
        // Out-of-range indices are skipped, not read.
        Triangles broken = tris;
        broken.push_back({0, 1, 99});
        const MassProperties skipped = polyhedronMassProperties(v, broken);
        QVERIFY(std::abs(skipped.volume - out.volume) <= kRelTol * out.volume);
        // No triangles, or an open single triangle: no volume, finite numbers.
        const MassProperties none = polyhedronMassProperties(v, {});
        QCOMPARE(none.volume, 0.0);
        const Triangles one{tris[0]};
        const MassProperties open = polyhedronMassProperties(v, one);
        QVERIFY(std::isfinite(open.volume) && std::isfinite(open.centroid.x) && std::isfinite(maxAbs(open.inertia)));
        // A non-finite vertex: its triangles are skipped, nothing non-finite comes out.
        std::vector<Vec3> withNan = v;
        withNan.push_back(Vec3(std::nan(""), 0.0, 0.0));
        Triangles nanTris = tris;
        nanTris.push_back({0, 1, static_cast<uint32_t>(withNan.size() - 1)});
        const MassProperties nanProps = polyhedronMassProperties(withNan, nanTris);
        QVERIFY(std::abs(nanProps.volume - out.volume) <= kRelTol * out.volume);
        QVERIFY(std::isfinite(nanProps.area) && std::isfinite(maxAbs(nanProps.inertia)));
        Vec3 moments(7.0);
        Mat3 axes(0.0);
        principalAxes(Mat3(std::nan("")), moments, axes);
        QCOMPARE(moments, Vec3(0.0));
        QCOMPARE(axes, Mat3(1.0));
        // Beyond about 1e100 m the integrals overflow: reported as empty at a finite point, never as inf or NaN.
        std::vector<Vec3> huge;
        Triangles hugeTris;
        boxMesh(Vec3(1e120), Vec3(3e120, 0.0, 0.0), huge, hugeTris);
        for (const MassProperties& mp :
             {polyhedronMassProperties(huge, hugeTris), hullMassProperties(computeConvexHull(huge))}) {
            QCOMPARE(mp.volume, 0.0);
            QVERIFY(std::isfinite(mp.area) && std::isfinite(glm::length(mp.centroid)) && maxAbs(mp.inertia) == 0.0);
        }
        const MassProperties empty = hullMassProperties(ConvexHull{});
        QCOMPARE(empty.volume, 0.0);
        QCOMPARE(empty.area, 0.0);
    }
};

QTEST_APPLESS_MAIN(TestMassProperties)
#include "tst_massproperties.moc"
