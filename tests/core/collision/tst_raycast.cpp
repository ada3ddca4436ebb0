// Tests of ray casts: single shapes (sphere, oriented box, hull, flat hull) against analytic answers, and the
// scene query over the broadphase (nearest body wins, filters, ties, agreement with brute force).
#include "collision/BroadPhase.h"
#include "collision/RayCast.h"
#include "geometry/ConvexHull.h"
#include "geometry/RayCast.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace rl;

Q_DECLARE_METATYPE(rl::Vec3)

namespace {

constexpr Real kTol = 1e-12;
const Real kSqrt2 = std::sqrt(2.0);
const Real kSqrt3 = std::sqrt(3.0);

bool near(const Vec3& a, const Vec3& b, Real tol = kTol) {
    return glm::length(a - b) <= tol;
}

QByteArray describe(const Vec3& v) {
    return QByteArray::number(v.x) + ' ' + QByteArray::number(v.y) + ' ' + QByteArray::number(v.z);
}

// Unit tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), built by hand so these tests do not depend on quickhull.
ConvexHull tetrahedron() {
    ConvexHull h;
    h.dimension = HullDimension::Solid;
    h.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    h.faces.push_back({{0, 2, 1}, {0, 0, -1}, 0.0});
    h.faces.push_back({{0, 1, 3}, {0, -1, 0}, 0.0});
    h.faces.push_back({{0, 3, 2}, {-1, 0, 0}, 0.0});
    h.faces.push_back({{1, 2, 3}, Vec3(1, 1, 1) / kSqrt3, 1.0 / kSqrt3});
    return h;
}

// The square [-1,1]^2 in the y = 0 plane, as the hull builder reports a flat point set: the polygon and its reverse.
ConvexHull flatSquare() {
    ConvexHull h;
    h.dimension = HullDimension::Flat;
    h.vertices = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}};
    h.faces.push_back({{0, 1, 2, 3}, {0, 1, 0}, 0.0});
    h.faces.push_back({{3, 2, 1, 0}, {0, -1, 0}, 0.0});
    return h;
}

} // namespace

class TestRayCast : public QObject {
    Q_OBJECT

private slots:
    void sphere_data();
    void sphere();
    void box_data();
    void box();
    void tetrahedronHull_data();
    void tetrahedronHull();
    void placedHull();
    void flatHull_data();
    void flatHull();
    void startInside();
    void badInput();
    void quickhullCubeMatchesBox();
    void sceneNearestWins();
    void sceneMatchesBruteForce();
};

void TestRayCast::sphere_data() {
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("direction");
    QTest::addColumn<Real>("maxDistance");
    QTest::addColumn<bool>("hit");
    QTest::addColumn<Real>("distance");
    // Sphere of radius 2 centred at (1, 2, 3).
    const Vec3 c(1, 2, 3);
    QTest::newRow("along +x") << c - Vec3(10, 0, 0) << Vec3(1, 0, 0) << 100.0 << true << 8.0;
    QTest::newRow("along -y") << c + Vec3(0, 7, 0) << Vec3(0, -1, 0) << 100.0 << true << 5.0;
    QTest::newRow("unnormalised direction") << c - Vec3(0, 0, 6) << Vec3(0, 0, 0.25) << 100.0 << true << 4.0;
    // Offset a from the axis: the hit is at 10 - sqrt(r^2 - a^2).
    QTest::newRow("off axis") << c + Vec3(-10, 1.2, 0) << Vec3(1, 0, 0) << 100.0 << true
                              << 10.0 - std::sqrt(4.0 - 1.44);
    QTest::newRow("just inside tangent") << c + Vec3(-10, 2.0 - 1e-9, 0) << Vec3(1, 0, 0) << 100.0 << true
                                         << 10.0 - std::sqrt(4.0 - (2.0 - 1e-9) * (2.0 - 1e-9));
    QTest::newRow("just outside tangent") << c + Vec3(-10, 2.0 + 1e-9, 0) << Vec3(1, 0, 0) << 100.0 << false << 0.0;
    QTest::newRow("pointing away") << c - Vec3(10, 0, 0) << Vec3(-1, 0, 0) << 100.0 << false << 0.0;
    QTest::newRow("too short") << c - Vec3(10, 0, 0) << Vec3(1, 0, 0) << 7.9 << false << 0.0;
    QTest::newRow("exactly long enough") << c - Vec3(10, 0, 0) << Vec3(1, 0, 0) << 8.0 << true << 8.0;
    QTest::newRow("infinite reach") << c - Vec3(1e6, 0, 0) << Vec3(1, 0, 0) << std::numeric_limits<Real>::infinity()
                                    << true << 1e6 - 2.0;
}

void TestRayCast::sphere() {
    QFETCH(Vec3, origin);
    QFETCH(Vec3, direction);
    QFETCH(Real, maxDistance);
    QFETCH(bool, hit);
    QFETCH(Real, distance);
    const Vec3 c(1, 2, 3);
    const Real r = 2.0;
    const auto h = raySphere({origin, direction}, maxDistance, c, r);
    QCOMPARE(h.has_value(), hit);
    if (!hit)
        return;
    QVERIFY2(std::abs(h->distance - distance) < 1e-9, QByteArray::number(h->distance, 'g', 17));
    const Vec3 d = glm::normalize(direction);
    QVERIFY(near(h->point, origin + distance * d, 1e-9));
    // On the surface, with the outward radial normal.
    QVERIFY(std::abs(glm::length(h->point - c) - r) < 1e-9);
    QVERIFY2(near(h->normal, (h->point - c) / r, 1e-9), describe(h->normal));
    QVERIFY(glm::dot(h->normal, d) <= 0.0);
}

void TestRayCast::box_data() {
    QTest::addColumn<Quat>("orientation");
    QTest::addColumn<Vec3>("halfExtents");
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("direction");
    QTest::addColumn<bool>("hit");
    QTest::addColumn<Real>("distance");
    QTest::addColumn<Vec3>("normal");
    // All boxes are centred at (0, 1, 0).
    const Quat id = identityQuat();
    const Vec3 h(1.0, 0.5, 2.0);
    QTest::newRow("+x face") << id << h << Vec3(5, 1, 0) << Vec3(-1, 0, 0) << true << 4.0 << Vec3(1, 0, 0);
    QTest::newRow("-x face") << id << h << Vec3(-5, 1.3, 1) << Vec3(1, 0, 0) << true << 4.0 << Vec3(-1, 0, 0);
    QTest::newRow("+y face") << id << h << Vec3(0.5, 4, -1.5) << Vec3(0, -1, 0) << true << 2.5 << Vec3(0, 1, 0);
    QTest::newRow("-z face") << id << h << Vec3(0, 1, -10) << Vec3(0, 0, 1) << true << 8.0 << Vec3(0, 0, -1);
    QTest::newRow("miss beside") << id << h << Vec3(-5, 1, 2.1) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("miss parallel above") << id << h << Vec3(-5, 1.6, 0) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("graze along top face")
        << id << h << Vec3(-5, 1.5, 0) << Vec3(1, 0, 0) << true << 4.0 << Vec3(-1, 0, 0);
    // A 3-4-5 diagonal onto the +x face: hits x = 1 at distance 5 * (4 / 4).
    QTest::newRow("diagonal") << id << h << Vec3(5, 1, -3) << Vec3(-4, 0, 3) << true << 5.0 << Vec3(1, 0, 0);
    // A cube rotated 45 degrees about y is the same shape either way round; its faces are x +- z = +-sqrt2.
    // From the -x side at z = 0.3 the ray enters the plane -x + z = sqrt2 at x = 0.3 - sqrt2.
    const Quat rotY45 = glm::angleAxis(kPi / 4.0, Vec3(0, 1, 0));
    QTest::newRow("rotated 45 about y") << rotY45 << Vec3(1.0) << Vec3(-5, 1, 0.3) << Vec3(1, 0, 0) << true
                                        << 5.0 + 0.3 - kSqrt2 << Vec3(-1, 0, 1) / kSqrt2;
    QTest::newRow("rotated 45, below") << rotY45 << Vec3(1.0) << Vec3(-5, 1, -0.3) << Vec3(1, 0, 0) << true
                                       << 5.0 + 0.3 - kSqrt2 << Vec3(-1, 0, -1) / kSqrt2;
    // A long box (2, 0.5, 0.5) turned 90 degrees about z lies along y.
    const Quat rotZ90 = glm::angleAxis(kPi / 2.0, Vec3(0, 0, 1));
    QTest::newRow("rotated 90 about z, end")
        << rotZ90 << Vec3(2, 0.5, 0.5) << Vec3(0, -5, 0) << Vec3(0, 1, 0) << true << 4.0 << Vec3(0, -1, 0);
    QTest::newRow("rotated 90 about z, side")
        << rotZ90 << Vec3(2, 0.5, 0.5) << Vec3(-5, 2.5, 0) << Vec3(1, 0, 0) << true << 4.5 << Vec3(-1, 0, 0);
    QTest::newRow("rotated 90 about z, miss")
        << rotZ90 << Vec3(2, 0.5, 0.5) << Vec3(-5, 3.1, 0) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
}

void TestRayCast::box() {
    QFETCH(Quat, orientation);
    QFETCH(Vec3, halfExtents);
    QFETCH(Vec3, origin);
    QFETCH(Vec3, direction);
    QFETCH(bool, hit);
    QFETCH(Real, distance);
    QFETCH(Vec3, normal);
    const Vec3 center(0, 1, 0);
    const auto h = rayBox({origin, direction}, 100.0, center, orientation, halfExtents);
    QCOMPARE(h.has_value(), hit);
    if (!hit)
        return;
    QVERIFY2(std::abs(h->distance - distance) < 1e-9, QByteArray::number(h->distance, 'g', 17));
    QVERIFY(near(h->point, origin + distance * glm::normalize(direction), 1e-9));
    QVERIFY2(near(h->normal, normal, 1e-9), describe(h->normal));
    // The hit point lies on the box surface: inside the box, and on the face whose normal was reported.
    const Vec3 local = glm::conjugate(orientation) * (h->point - center);
    const Vec3 localNormal = glm::conjugate(orientation) * h->normal;
    for (int i = 0; i < 3; ++i)
        QVERIFY(std::abs(local[i]) <= halfExtents[i] + 1e-9);
    QVERIFY(std::abs(glm::dot(local, localNormal) - glm::dot(glm::abs(localNormal), halfExtents)) < 1e-9);
}

void TestRayCast::tetrahedronHull_data() {
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("direction");
    QTest::addColumn<bool>("hit");
    QTest::addColumn<Real>("distance");
    QTest::addColumn<Vec3>("normal");
    QTest::newRow("x = 0 face") << Vec3(-1, 0.2, 0.2) << Vec3(1, 0, 0) << true << 1.0 << Vec3(-1, 0, 0);
    QTest::newRow("y = 0 face") << Vec3(0.1, -2, 0.3) << Vec3(0, 1, 0) << true << 2.0 << Vec3(0, -1, 0);
    QTest::newRow("z = 0 face") << Vec3(0.3, 0.3, -0.5) << Vec3(0, 0, 1) << true << 0.5 << Vec3(0, 0, -1);
    // From (1,1,1) towards the origin: enters the slanted face at its centroid (1/3,1/3,1/3).
    QTest::newRow("slanted face") << Vec3(1, 1, 1) << Vec3(-1, -1, -1) << true << 2.0 / kSqrt3 * 1.0
                                  << Vec3(1, 1, 1) / kSqrt3;
    QTest::newRow("slanted face from +x")
        << Vec3(2, 0.1, 0.1) << Vec3(-1, 0, 0) << true << 2.0 - 0.8 << Vec3(1, 1, 1) / kSqrt3;
    // At x = 0 the point (0, 0.8, 0.8) is outside the triangle (y + z > 1).
    QTest::newRow("miss past slanted face") << Vec3(-1, 0.8, 0.8) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("miss behind") << Vec3(-1, 0.2, 0.2) << Vec3(-1, 0, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("miss parallel") << Vec3(-1, -0.1, 0.2) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
}

void TestRayCast::tetrahedronHull() {
    QFETCH(Vec3, origin);
    QFETCH(Vec3, direction);
    QFETCH(bool, hit);
    QFETCH(Real, distance);
    QFETCH(Vec3, normal);
    const ConvexHull hull = tetrahedron();
    const auto h = rayHull({origin, direction}, 100.0, hull, Vec3(0.0), identityQuat());
    QCOMPARE(h.has_value(), hit);
    if (!hit)
        return;
    QVERIFY2(std::abs(h->distance - distance) < 1e-9, QByteArray::number(h->distance, 'g', 17));
    QVERIFY(near(h->point, origin + distance * glm::normalize(direction), 1e-9));
    QVERIFY2(near(h->normal, normal, 1e-9), describe(h->normal));
}

// The same tetrahedron placed at (10, -2, 3) and turned 90 degrees about z: the answer is the local one mapped by
// the placement.
void TestRayCast::placedHull() {
    const ConvexHull hull = tetrahedron();
    const Vec3 p(10, -2, 3);
    const Quat q = glm::angleAxis(kPi / 2.0, Vec3(0, 0, 1));
    const Vec3 localOrigin(-1, 0.2, 0.2);
    const Ray ray{p + q * localOrigin, q * Vec3(1, 0, 0)};
    const auto h = rayHull(ray, 100.0, hull, p, q);
    QVERIFY(h.has_value());
    QVERIFY(std::abs(h->distance - 1.0) < 1e-9);
    QVERIFY(near(h->point, p + q * Vec3(0, 0.2, 0.2), 1e-9));
    QVERIFY(near(h->normal, q * Vec3(-1, 0, 0), 1e-9));
    // (-1,0,0) turned 90 degrees about z is (0,-1,0): check against the hand value too, not only glm's rotation.
    QVERIFY(near(h->normal, Vec3(0, -1, 0), 1e-9));
}

void TestRayCast::flatHull_data() {
    QTest::addColumn<Vec3>("origin");
    QTest::addColumn<Vec3>("direction");
    QTest::addColumn<bool>("hit");
    QTest::addColumn<Real>("distance");
    QTest::addColumn<Vec3>("normal");
    QTest::newRow("from above") << Vec3(0.5, 3, -0.5) << Vec3(0, -1, 0) << true << 3.0 << Vec3(0, 1, 0);
    QTest::newRow("from below") << Vec3(0.5, -2, 0.5) << Vec3(0, 1, 0) << true << 2.0 << Vec3(0, -1, 0);
    QTest::newRow("slanted") << Vec3(-3, 4, 0) << Vec3(3, -4, 0) << true << 5.0 << Vec3(0, 1, 0);
    QTest::newRow("through a corner") << Vec3(1, 1, 1) << Vec3(0, -1, 0) << true << 1.0 << Vec3(0, 1, 0);
    QTest::newRow("outside the square") << Vec3(1.1, 1, 0) << Vec3(0, -1, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("edge-on") << Vec3(-5, 0, 0) << Vec3(1, 0, 0) << false << 0.0 << Vec3(0.0);
    QTest::newRow("pointing away") << Vec3(0, 1, 0) << Vec3(0, 1, 0) << false << 0.0 << Vec3(0.0);
}

void TestRayCast::flatHull() {
    QFETCH(Vec3, origin);
    QFETCH(Vec3, direction);
    QFETCH(bool, hit);
    QFETCH(Real, distance);
    QFETCH(Vec3, normal);
    const auto h = rayHull({origin, direction}, 100.0, flatSquare(), Vec3(0.0), identityQuat());
    QCOMPARE(h.has_value(), hit);
    if (!hit)
        return;
    QVERIFY(std::abs(h->distance - distance) < 1e-9);
    QVERIFY(near(h->normal, normal));
    QVERIFY(std::abs(h->point.y) < 1e-12);
}

void TestRayCast::startInside() {
    const Vec3 origin(0.1, 0.2, 0.15);
    const Vec3 dir(0, 0, 1);
    const ConvexHull tet = tetrahedron();
    const auto s = raySphere({origin, dir}, 10.0, Vec3(0.0), 1.0);
    const auto b = rayBox({origin, dir}, 10.0, Vec3(0.0), identityQuat(), Vec3(1.0));
    const auto t = rayHull({origin, dir}, 10.0, tet, Vec3(0.0), identityQuat());
    for (const auto& h : {s, b, t}) {
        QVERIFY(h.has_value());
        QCOMPARE(h->distance, 0.0);
        QCOMPARE(h->point, origin);
        QCOMPARE(h->normal, -dir);
    }
    QVERIFY(!raySphere({origin, dir}, 10.0, Vec3(0.0), 1.0, RayStartInside::Ignore));
    QVERIFY(!rayBox({origin, dir}, 10.0, Vec3(0.0), identityQuat(), Vec3(1.0), RayStartInside::Ignore));
    QVERIFY(!rayHull({origin, dir}, 10.0, tet, Vec3(0.0), identityQuat(), RayStartInside::Ignore));
}

void TestRayCast::badInput() {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();
    const Vec3 o(-5, 0, 0);
    const Vec3 x(1, 0, 0);
    QVERIFY(!raySphere({o, Vec3(0.0)}, 10.0, Vec3(0.0), 1.0));
    QVERIFY(!raySphere({o, Vec3(nan, 0, 0)}, 10.0, Vec3(0.0), 1.0));
    QVERIFY(!raySphere({Vec3(inf, 0, 0), x}, 10.0, Vec3(0.0), 1.0));
    QVERIFY(!raySphere({o, x}, nan, Vec3(0.0), 1.0));
    QVERIFY(!raySphere({o, x}, -1.0, Vec3(0.0), 1.0));
    QVERIFY(!raySphere({o, x}, 10.0, Vec3(0.0), -1.0));
    QVERIFY(!raySphere({o, x}, 10.0, Vec3(0.0), nan));
    QVERIFY(!rayBox({o, x}, 10.0, Vec3(0.0), Quat(0, 0, 0, 0), Vec3(1.0)));
    QVERIFY(!rayBox({o, x}, 10.0, Vec3(0.0), identityQuat(), Vec3(nan)));
    // A non-unit quaternion is normalised rather than allowed to scale the box.
    const auto scaled = rayBox({o, x}, 10.0, Vec3(0.0), Quat(2, 0, 0, 0), Vec3(1.0));
    QVERIFY(scaled && std::abs(scaled->distance - 4.0) < 1e-12);
    ConvexHull empty;
    QVERIFY(!rayHull({o, x}, 10.0, empty, Vec3(0.0), identityQuat()));
    ConvexHull line;
    line.dimension = HullDimension::Line;
    line.vertices = {{-1, 0, 0}, {1, 0, 0}};
    QVERIFY(!rayHull({o, x}, 10.0, line, Vec3(0.0), identityQuat()));
    QVERIFY(!rayHull({o, x}, 10.0, tetrahedron(), Vec3(nan), identityQuat()));
}

// A cube built by the project's quickhull must answer exactly like the analytic box on random rays.
void TestRayCast::quickhullCubeMatchesBox() {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back({i & 1 ? 1.5 : -1.5, i & 2 ? 0.5 : -0.5, i & 4 ? 1.0 : -1.0});
    const ConvexHull hull = computeConvexHull(corners);
    QVERIFY(hull.isSolid());
    const Vec3 p(1, 2, 3);
    const Quat q = glm::normalize(Quat(0.9, 0.2, -0.3, 0.1));
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 origin = p + 4.0 * Vec3(u(rng), u(rng), u(rng));
        const Vec3 target = p + 1.5 * Vec3(u(rng), u(rng), u(rng));
        const Ray ray{origin, target - origin};
        const auto a = rayBox(ray, 20.0, p, q, Vec3(1.5, 0.5, 1.0));
        const auto b = rayHull(ray, 20.0, hull, p, q);
        QCOMPARE(a.has_value(), b.has_value());
        if (!a)
            continue;
        ++hits;
        QVERIFY(std::abs(a->distance - b->distance) < 1e-9);
        if (a->distance > 0.0)
            QVERIFY2(near(a->normal, b->normal, 1e-9), describe(a->normal) + " vs " + describe(b->normal));
    }
    QVERIFY(hits > 100);
}

namespace {

struct SceneBody {
    bool sphere = true;
    Vec3 center{0.0};
    Real radius = 0.5;
    Quat orientation = identityQuat();
    Vec3 halfExtents{0.5};
    bool anchor = false;

    Aabb bounds() const {
        if (sphere)
            return Aabb::fromCenterHalfExtents(center, Vec3(radius));
        // The box's world extent along each axis is sum |R_ij| h_j.
        const Mat3 r = glm::mat3_cast(orientation);
        Vec3 e(0.0);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                e[i] += std::abs(r[j][i]) * halfExtents[j];
        return Aabb::fromCenterHalfExtents(center, e);
    }
    std::optional<ShapeRayHit> cast(const Ray& ray, Real maxDistance) const {
        if (sphere)
            return raySphere(ray, maxDistance, center, radius);
        return rayBox(ray, maxDistance, center, orientation, halfExtents);
    }
};

struct TestScene {
    std::vector<SceneBody> bodies;
    BroadPhase bp;
    void build() {
        for (uint32_t i = 0; i < bodies.size(); ++i)
            bp.createProxy(bodies[i].bounds(), i, bodies[i].anchor ? ProxyKind::Static : ProxyKind::Dynamic).value();
        bp.updatePairs();
    }
    ShapeRayTest test() const {
        return [this](uint32_t id, const Ray& ray, Real maxDistance) { return bodies[id].cast(ray, maxDistance); };
    }
};

} // namespace

void TestRayCast::sceneNearestWins() {
    // A row along x: spheres at x = 0, 3, 9 and an anchor box at x = 6. Ids are not in x order on purpose.
    TestScene scene;
    scene.bodies = {{true, {3, 0, 0}}, {true, {9, 0, 0}}, {false, {6, 0, 0}}, {true, {0, 0, 0}}};
    scene.bodies[2].anchor = true;
    scene.build();

    RayHit h = castRay(scene.bp, {{-10, 0, 0}, {1, 0, 0}}, 100.0, scene.test());
    QVERIFY(h.hit);
    QCOMPARE(h.bodyId, 3u);
    QVERIFY(std::abs(h.distance - 9.5) < 1e-12);
    QVERIFY(near(h.point, Vec3(-0.5, 0, 0)));
    QVERIFY(near(h.normal, Vec3(-1, 0, 0)));

    h = castRay(scene.bp, {{20, 0, 0}, {-2, 0, 0}}, 100.0, scene.test());
    QCOMPARE(h.bodyId, 1u);
    QVERIFY(std::abs(h.distance - 10.5) < 1e-12);

    // From between the bodies, the anchor box is nearest (static tree) although dynamic bodies lie behind it.
    h = castRay(scene.bp, {{4.5, 0, 0}, {1, 0, 0}}, 100.0, scene.test());
    QCOMPARE(h.bodyId, 2u);
    QVERIFY(std::abs(h.distance - 1.0) < 1e-12);
    QVERIFY(near(h.normal, Vec3(-1, 0, 0)));

    // A ray that passes beside every body, one that is too short, and an unusable one.
    QVERIFY(!castRay(scene.bp, {{-10, 0.6, 0.6}, {1, 0, 0}}, 100.0, scene.test()).hit);
    QVERIFY(!castRay(scene.bp, {{-10, 0, 0}, {1, 0, 0}}, 9.4, scene.test()).hit);
    QVERIFY(!castRay(scene.bp, {{-10, 0, 0}, {0, 0, 0}}, 100.0, scene.test()).hit);

    // Filtering: a test that skips body 3 (as picking may skip anchors or hidden bodies) lets the next one win.
    const ShapeRayTest inner = scene.test();
    h = castRay(scene.bp, {{-10, 0, 0}, {1, 0, 0}}, 100.0,
                [&](uint32_t id, const Ray& r, Real m) { return id == 3 ? std::nullopt : inner(id, r, m); });
    QCOMPARE(h.bodyId, 0u);
    QVERIFY(std::abs(h.distance - 12.5) < 1e-12);

    // Two bodies at the same place: the smaller id wins the tie, whatever the tree order.
    TestScene twins;
    twins.bodies = {{true, {0, 0, 0}}, {true, {5, 0, 0}}, {true, {5, 0, 0}}, {true, {5, 0, 0}}};
    twins.build();
    h = castRay(twins.bp, {{10, 0, 0}, {-1, 0, 0}}, 100.0, twins.test());
    QCOMPARE(h.bodyId, 1u);
    // Starting inside the twins: distance 0, and still the smaller id.
    h = castRay(twins.bp, {{5, 0, 0}, {-1, 0, 0}}, 100.0, twins.test());
    QCOMPARE(h.bodyId, 1u);
    QCOMPARE(h.distance, 0.0);
}

// Random spheres and rotated boxes: the tree-accelerated query must give the brute-force closest hit.
void TestRayCast::sceneMatchesBruteForce() {
    std::mt19937 rng(17);
    std::uniform_real_distribution<Real> u(0.0, 1.0);
    TestScene scene;
    for (int i = 0; i < 600; ++i) {
        SceneBody b;
        b.sphere = u(rng) < 0.5;
        b.center = Vec3(u(rng), u(rng), u(rng)) * 30.0;
        b.radius = 0.2 + u(rng);
        b.halfExtents = Vec3(0.2 + u(rng), 0.2 + u(rng), 0.2 + u(rng));
        b.orientation = glm::normalize(Quat(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        b.anchor = u(rng) < 0.2;
        scene.bodies.push_back(b);
    }
    scene.build();
    int hits = 0;
    for (int r = 0; r < 300; ++r) {
        const Vec3 origin = Vec3(u(rng), u(rng), u(rng)) * 30.0;
        const Vec3 dir = Vec3(u(rng), u(rng), u(rng)) - 0.5;
        const Ray ray{origin, dir};
        Real best = std::numeric_limits<Real>::infinity();
        uint32_t bestId = 0;
        for (uint32_t i = 0; i < scene.bodies.size(); ++i) {
            const auto h = scene.bodies[i].cast(ray, 50.0);
            if (h && h->distance < best) {
                best = h->distance;
                bestId = i;
            }
        }
        const RayHit h = castRay(scene.bp, ray, 50.0, scene.test());
        QCOMPARE(h.hit, std::isfinite(best));
        if (!h.hit)
            continue;
        ++hits;
        QCOMPARE(h.bodyId, bestId);
        QVERIFY(std::abs(h.distance - best) < 1e-12);
        QVERIFY(std::abs(glm::length(h.normal) - 1.0) < 1e-12);
    }
    QVERIFY(hits > 50);
}

QTEST_APPLESS_MAIN(TestRayCast)
#include "tst_raycast.moc"
