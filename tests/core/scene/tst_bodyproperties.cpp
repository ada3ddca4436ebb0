// Derived body properties: mass, centre of mass and inertia in world axes, vertex means, and the errors and warnings
// that name the body.
#include "scene/BodyProperties.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace rl;

namespace {

BodyDef boxBody(const Vec3& half, const Vec3& position, const Quat& orientation) {
    BodyDef b;
    b.name = "Box";
    b.shape.type = ShapeType::Box;
    b.shape.halfExtents = half;
    b.position = position;
    b.orientation = orientation;
    return b;
}

BodyDef meshBody(const std::string& name, std::vector<Vec3> vertices, std::vector<std::array<uint32_t, 3>> tris) {
    BodyDef b;
    b.name = name;
    b.shape.type = ShapeType::Mesh;
    b.shape.points = std::move(vertices);
    b.shape.triangles = std::move(tris);
    return b;
}

// A torus as a closed triangle mesh: the classic concave shape.
BodyDef torusBody(Real major, Real minor, int segments, int sides) {
    std::vector<Vec3> v;
    std::vector<std::array<uint32_t, 3>> t;
    for (int i = 0; i < segments; ++i) {
        const Real u = 2.0 * kPi * i / segments;
        for (int j = 0; j < sides; ++j) {
            const Real w = 2.0 * kPi * j / sides;
            const Real r = major + minor * std::cos(w);
            v.emplace_back(r * std::cos(u), minor * std::sin(w), r * std::sin(u));
        }
    }
    auto id = [&](int i, int j) { return static_cast<uint32_t>((i % segments) * sides + (j % sides)); };
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < sides; ++j) {
            t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return meshBody("Torus", std::move(v), std::move(t));
}

bool near(Real a, Real b, Real rel) {
    return std::abs(a - b) <= rel * std::max(1.0, std::abs(b));
}

} // namespace

class TestBodyProperties : public QObject {
    Q_OBJECT
private slots:
    void rotatedBox_data() {
        QTest::addColumn<double>("hx");
        QTest::addColumn<double>("hy");
        QTest::addColumn<double>("hz");
        QTest::addColumn<double>("angle");
        QTest::newRow("unit cube") << 0.5 << 0.5 << 0.5 << 0.0;
        QTest::newRow("1x2x3 rotated 30deg") << 0.5 << 1.0 << 1.5 << 30.0;
        QTest::newRow("plank rotated 73deg") << 2.0 << 0.05 << 0.2 << 73.0;
    }
    void rotatedBox() {
        QFETCH(double, hx);
        QFETCH(double, hy);
        QFETCH(double, hz);
        QFETCH(double, angle);
        const Vec3 axis = glm::normalize(Vec3(1.0, 2.0, -0.5));
        const Quat q = glm::angleAxis(glm::radians(angle), axis);
        const Vec3 pos(3.0, -2.0, 100.0);
        Scene scene;
        BodyDef body = boxBody(Vec3(hx, hy, hz), pos, q);
        body.material = "Steel";
        Result<BodyProperties> p = computeBodyProperties(scene, body);
        QVERIFY(p.ok());
        const Real volume = 8.0 * hx * hy * hz;
        const Real mass = 7850.0 * volume;
        QVERIFY(near(p->volume, volume, 1e-12));
        QVERIFY(near(p->mass, mass, 1e-12));
        QVERIFY(glm::length(p->com - pos) < 1e-9);
        QVERIFY(glm::length(p->vertexMean - pos) < 1e-9);
        // Closed form in body axes, rotated into world axes.
        const Mat3 local(mass / 3.0 * (hy * hy + hz * hz), 0.0, 0.0, 0.0, mass / 3.0 * (hx * hx + hz * hz), 0.0, 0.0,
                         0.0, mass / 3.0 * (hx * hx + hy * hy));
        const Mat3 r = glm::mat3_cast(q);
        const Mat3 expected = r * local * glm::transpose(r);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                QVERIFY2(std::abs(p->inertia[c][k] - expected[c][k]) <= 1e-9 * mass * (hx * hx + hy * hy + hz * hz),
                         qPrintable(QString("I[%1][%2] = %3, expected %4")
                                        .arg(c)
                                        .arg(k)
                                        .arg(p->inertia[c][k])
                                        .arg(expected[c][k])));
        QCOMPARE(p->hullVertexCount, 8);
    }

    void sphere() {
        Scene scene;
        BodyDef b;
        b.name = "Ball";
        b.shape.type = ShapeType::Sphere;
        b.shape.radius = 0.25;
        b.position = Vec3(1, 2, 3);
        b.material = "rubber"; // case-insensitive preset
        Result<BodyProperties> p = computeBodyProperties(scene, b);
        QVERIFY(p.ok());
        const Real volume = 4.0 / 3.0 * kPi * 0.25 * 0.25 * 0.25;
        QVERIFY(near(p->volume, volume, 1e-14));
        QVERIFY(near(p->mass, 1100.0 * volume, 1e-14));
        QVERIFY(near(p->inertia[1][1], 0.4 * 1100.0 * volume * 0.0625, 1e-12));
        QVERIFY(glm::length(p->com - b.position) < 1e-15);
    }

    void massOverrideKeepsShapeOfInertia() {
        Scene scene;
        BodyDef b = boxBody(Vec3(0.5), Vec3(0.0), Quat(1, 0, 0, 0));
        b.mass = 2.0;
        Result<BodyProperties> p = computeBodyProperties(scene, b);
        QVERIFY(p.ok());
        QVERIFY(near(p->mass, 2.0, 1e-15));
        QVERIFY(near(p->density, 2.0, 1e-12));
        QVERIFY(near(p->inertia[0][0], 2.0 / 6.0, 1e-12));
    }

    void flatPlaneIsAValidAnchor() {
        Scene scene;
        BodyDef b =
            meshBody("Anchor", {{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10}}, {{0, 2, 1}, {0, 3, 2}});
        b.anchor = true;
        Result<BodyProperties> p = computeBodyProperties(scene, b);
        QVERIFY(p.ok());
        QVERIFY(p->flat);
        QCOMPARE(p->volume, 0.0);
        QVERIFY(glm::length(p->com) < 1e-12);
        QVERIFY(p->warnings.empty());
    }

    void errorsNameTheBody_data() {
        QTest::addColumn<int>("kind");
        QTest::newRow("flat dynamic body") << 0;
        QTest::newRow("collinear points") << 1;
        QTest::newRow("negative density") << 2;
        QTest::newRow("zero mass") << 3;
        QTest::newRow("nan position") << 4;
        QTest::newRow("zero box") << 5;
        QTest::newRow("zero quaternion") << 6;
    }
    void errorsNameTheBody() {
        QFETCH(int, kind);
        Scene scene;
        BodyDef b = boxBody(Vec3(0.5), Vec3(0.0), Quat(1, 0, 0, 0));
        switch (kind) {
        case 0:
            b = meshBody("Sheet", {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 2, 1}, {0, 3, 2}});
            break;
        case 1:
            b = meshBody("Stick", {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {});
            b.shape.type = ShapeType::Hull;
            break;
        case 2:
            b.density = -5.0;
            break;
        case 3:
            b.mass = 0.0;
            break;
        case 4:
            b.position.y = std::nan("");
            break;
        case 5:
            b.shape.halfExtents = Vec3(0.5, 0.0, 0.5);
            break;
        case 6:
            b.orientation = Quat(0, 0, 0, 0);
            break;
        }
        Result<BodyProperties> p = computeBodyProperties(scene, b);
        QVERIFY(!p.ok());
        QCOMPARE(QString::fromStdString(p.error().object), QString::fromStdString(b.name));
        QVERIFY(!p.error().message.empty());
    }

    void torusIsConcaveWithWarning() {
        Scene scene;
        Result<BodyProperties> p = computeBodyProperties(scene, torusBody(1.0, 0.25, 32, 16));
        QVERIFY(p.ok());
        QVERIFY(p->concave);
        QCOMPARE(p->warnings.size(), size_t(1));
        QVERIFY(QString::fromStdString(p->warnings[0]).contains("concave"));
    }

    // Blender's legacy OBJ exporter writes an object renamed "Anchor" whose mesh kept its name as "Anchor_Plane",
    // which the anchor rule makes dynamic: a box so named gets a warning that says what to do, a flat one an error
    // that says it. Names the rule makes anchors, or that only start like one, get neither.
    void legacyExporterAnchorNames_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("anchor");
        QTest::addColumn<bool>("hint");
        QTest::newRow("Anchor_Cube") << "Anchor_Cube" << false << true;
        QTest::newRow("Anchor.001_Cube.003") << "Anchor.001_Cube.003" << false << true;
        QTest::newRow("Anchor_ (no mesh name)") << "Anchor_" << false << false;
        QTest::newRow("Anchorage_Cube") << "Anchorage_Cube" << false << false;
        QTest::newRow("Cube_Anchor") << "Cube_Anchor" << false << false;
        QTest::newRow("Anchor_Cube, made an anchor") << "Anchor_Cube" << true << false;
    }
    void legacyExporterAnchorNames() {
        QFETCH(QString, name);
        QFETCH(bool, anchor);
        QFETCH(bool, hint);
        Scene scene;
        BodyDef box = boxBody(Vec3(0.5), Vec3(0.0), Quat(1, 0, 0, 0));
        box.name = name.toStdString();
        box.anchor = anchor;
        Result<BodyProperties> p = computeBodyProperties(scene, box);
        QVERIFY(p.ok());
        const bool warned = std::any_of(p->warnings.begin(), p->warnings.end(), [](const std::string& w) {
            return w.find("legacy OBJ exporter") != std::string::npos;
        });
        QCOMPARE(warned, hint);

        BodyDef plane =
            meshBody(name.toStdString(), {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, {{0, 1, 2}, {0, 2, 3}});
        plane.anchor = anchor;
        Result<BodyProperties> flat = computeBodyProperties(scene, plane);
        QCOMPARE(flat.ok(), anchor);
        if (!flat.ok())
            QCOMPARE(QString::fromStdString(flat.error().message).contains("legacy OBJ exporter"), hint);
    }
};

QTEST_APPLESS_MAIN(TestBodyProperties)
#include "tst_bodyproperties.moc"
