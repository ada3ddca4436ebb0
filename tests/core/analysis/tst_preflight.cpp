// The pre-flight check: one scene per kind of finding (and a clean scene with none), each asserting exactly which
// findings come out, for which bodies, with the figures the check documents.
#include "analysis/Preflight.h"

#include <QTest>

#include <algorithm>

using namespace rl;

Q_DECLARE_METATYPE(rl::Scene)

namespace {

BodyDef box(const std::string& name, Vec3 halfExtents, Vec3 position, bool anchor = false) {
    BodyDef b;
    b.name = name;
    b.anchor = anchor;
    b.shape.type = ShapeType::Box;
    b.shape.halfExtents = halfExtents;
    b.position = position;
    return b;
}

// A 1 m cube with a pit pushed 0.3 m into the middle of its top face: a closed, concave mesh.
BodyDef dentedCube(const std::string& name, Vec3 position) {
    BodyDef b;
    b.name = name;
    b.position = position;
    b.shape.type = ShapeType::Mesh;
    b.shape.points = {{-0.5, -0.5, -0.5}, {0.5, -0.5, -0.5}, {0.5, -0.5, 0.5}, {-0.5, -0.5, 0.5}, {-0.5, 0.5, -0.5},
                      {0.5, 0.5, -0.5},   {0.5, 0.5, 0.5},   {-0.5, 0.5, 0.5}, {0.0, 0.2, 0.0}};
    b.shape.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 1}, {1, 5, 6}, {1, 6, 2}, {2, 6, 7},
                         {2, 7, 3}, {3, 7, 4}, {3, 4, 0}, {4, 8, 5}, {5, 8, 6}, {6, 8, 7}, {7, 8, 4}};
    return b;
}

Scene withFloor(std::vector<BodyDef> bodies) {
    Scene scene;
    scene.bodies.push_back(box("Floor", {10, 0.5, 10}, {0, -0.5, 0}, true));
    for (BodyDef& b : bodies)
        scene.bodies.push_back(std::move(b));
    return scene;
}

QString describe(const std::vector<PreflightFinding>& findings) {
    QStringList parts;
    for (const PreflightFinding& f : findings)
        parts << QString("%1@%2").arg(QString::fromUtf8(preflightKindName(f.kind).data())).arg(f.body);
    return parts.join(' ');
}

} // namespace

class TestPreflight : public QObject {
    Q_OBJECT

private slots:
    void findings_data();
    void findings();
    void tunnellingFigures();
    void massRatioNamesBothBodies();
    void ccdOffChangesTheFix();
    void invalidBodyIsReported();
};

void TestPreflight::findings_data() {
    QTest::addColumn<Scene>("scene");
    QTest::addColumn<QString>("expected"); // kind@body, in the order the check returns them

    // A unit cube resting on a floor, a heavier one on top (2:1), a sphere beside them: nothing to report.
    {
        BodyDef top = box("Top", {0.5, 0.5, 0.5}, {0, 1.5, 0});
        top.density = 2000.0;
        BodyDef ball;
        ball.name = "Ball";
        ball.shape.type = ShapeType::Sphere;
        ball.shape.radius = 0.25;
        ball.position = {3, 0.25, 0};
        QTest::newRow("clean") << withFloor({box("Cube", {0.5, 0.5, 0.5}, {0, 0.5, 0}), top, ball}) << "";
    }
    // A 1.5 cm pebble: below the 2 cm limit. (Resting on the floor, so it cannot tunnel.)
    QTest::newRow("tiny") << withFloor({box("Pebble", {0.0075, 0.0075, 0.0075}, {0, 0.0075, 0})}) << "tiny-body@1";
    // A 1 cm thick plate shot sideways at 5 m/s moves 8.3 cm per frame at 60 fps.
    {
        BodyDef plate = box("Plate", {0.5, 0.005, 0.5}, {0, 0.005, 0});
        plate.velocity = {5, 0, 0};
        QTest::newRow("tunnelling-velocity") << withFloor({plate}) << "tunnelling@1";
    }
    // A 4 cm cube dropped from 2 m reaches 6.3 m/s: 10 cm per frame.
    QTest::newRow("tunnelling-fall") << withFloor({box("Dice", {0.02, 0.02, 0.02}, {0, 2.02, 0})}) << "tunnelling@1";
    QTest::newRow("concave") << withFloor({dentedCube("Dented", {0, 0.5, 0})}) << "concave-dynamic@1";
    // A 1 kg cube under a 1,000 kg cube (README's hard case), resting on each other.
    {
        BodyDef light = box("Light", {0.5, 0.5, 0.5}, {0, 0.5, 0});
        light.mass = 1.0;
        BodyDef heavy = box("Heavy", {0.5, 0.5, 0.5}, {0, 1.5, 0});
        heavy.mass = 1000.0;
        QTest::newRow("mass-ratio") << withFloor({light, heavy}) << "mass-ratio@1";
        // The same pair 1 m apart does not touch: no finding.
        heavy.position = {0, 2.5, 0};
        heavy.mass = 1000.0;
        BodyDef apart = heavy;
        apart.position = {3, 0.5, 0};
        QTest::newRow("mass-ratio-apart") << withFloor({light, apart}) << "";
        // Exactly at the limit (100:1) is accepted.
        heavy.position = {0, 1.5, 0};
        heavy.mass = 100.0;
        QTest::newRow("mass-ratio-at-limit") << withFloor({light, heavy}) << "";
    }
    // Anchors are never flagged, whatever their size or shape.
    QTest::newRow("tiny-anchor") << withFloor({box("Anchor", {0.005, 0.005, 0.005}, {0, 3, 0}, true)}) << "";
    // Several kinds at once come out in body order, then kind order.
    {
        BodyDef plate = box("Plate", {0.5, 0.005, 0.5}, {0, 0.005, 0});
        plate.velocity = {5, 0, 0};
        QTest::newRow("several") << withFloor({dentedCube("Dented", {5, 0.5, 0}), plate,
                                               box("Grain", {0.005, 0.005, 0.005}, {8, 1, 0})})
                                 << "concave-dynamic@1 tunnelling@2 tiny-body@3 tunnelling@3";
    }
}

void TestPreflight::findings() {
    QFETCH(Scene, scene);
    QFETCH(QString, expected);
    const std::vector<PreflightFinding> findings = runPreflight(scene);
    QCOMPARE(describe(findings), expected);
    for (const PreflightFinding& f : findings) {
        QVERIFY(!f.message.empty());
        QVERIFY(!f.fix.empty());
        // Every message names its body.
        QVERIFY2(QString::fromStdString(f.message).contains(QString::fromStdString(scene.bodies[f.body].name)),
                 f.message.c_str());
    }
}

void TestPreflight::tunnellingFigures() {
    // Dropped from 2 m above the floor's top: v = sqrt(2 g h) = 6.264 m/s; 4 cm thick; 60 fps.
    const Scene scene = withFloor({box("Dice", {0.02, 0.02, 0.02}, {0, 2.02, 0})});
    const std::vector<PreflightFinding> findings = runPreflight(scene);
    QCOMPARE(findings.size(), size_t(1));
    const PreflightFinding& f = findings[0];
    QCOMPARE(f.kind, PreflightKind::Tunnelling);
    QVERIFY(std::abs(f.speed - std::sqrt(2.0 * 9.81 * 2.0)) < 1e-9);
    QVERIFY(std::abs(f.limit - 0.04) < 1e-12);
    QVERIFY(std::abs(f.value - f.speed / 60.0) < 1e-12);
    QCOMPARE(f.suggestedFps, std::ceil(f.speed / 0.04));
    // At the suggested frame rate the check is satisfied.
    Scene faster = scene;
    faster.world.fps = f.suggestedFps;
    QVERIFY(runPreflight(faster).empty());
    // Without gravity and at rest it cannot move at all.
    Scene still = scene;
    still.world.gravity = Vec3(0.0);
    QVERIFY(runPreflight(still).empty());
    // With no anchor below, free fall lasts the whole bake: g T = 98.1 m/s over 10 s.
    Scene noFloor;
    noFloor.bodies.push_back(box("Dice", {0.02, 0.02, 0.02}, {0, 2.02, 0}));
    PreflightOptions shortRun;
    shortRun.duration = 0.1; // 0.981 m/s: 1.6 cm per frame, below 4 cm
    QVERIFY(runPreflight(noFloor, shortRun).empty());
    const std::vector<PreflightFinding> longRun = runPreflight(noFloor);
    QCOMPARE(longRun.size(), size_t(1));
    QVERIFY(std::abs(longRun[0].speed - 98.1) < 1e-9);
}

void TestPreflight::massRatioNamesBothBodies() {
    BodyDef light = box("Light", {0.5, 0.5, 0.5}, {0, 0.5, 0});
    light.mass = 1.0;
    BodyDef heavy = box("Heavy", {0.5, 0.5, 0.5}, {0, 1.5, 0});
    heavy.mass = 1000.0;
    // The heavy body first in the scene: the finding is still listed at the lighter body.
    const std::vector<PreflightFinding> findings = runPreflight(withFloor({heavy, light}));
    QCOMPARE(findings.size(), size_t(1));
    QCOMPARE(findings[0].body, size_t(2));
    QCOMPARE(findings[0].other, std::optional<size_t>(1));
    QVERIFY(std::abs(findings[0].value - 1000.0) < 1e-9);
    QVERIFY(QString::fromStdString(findings[0].message).contains("Heavy"));
    // A stricter limit catches a 20:1 pair.
    heavy.mass = 20.0;
    PreflightOptions strict;
    strict.maxMassRatio = 10.0;
    QCOMPARE(runPreflight(withFloor({heavy, light}), strict).size(), size_t(1));
    QVERIFY(runPreflight(withFloor({heavy, light})).empty());
}

void TestPreflight::ccdOffChangesTheFix() {
    BodyDef plate = box("Plate", {0.5, 0.005, 0.5}, {0, 0.005, 0});
    plate.velocity = {5, 0, 0};
    Scene scene = withFloor({plate});
    const std::string autoFix = runPreflight(scene).at(0).fix;
    scene.world.effects.set(Effect::Ccd, EffectMode::Off);
    const std::string offFix = runPreflight(scene).at(0).fix;
    QVERIFY(autoFix != offFix);
    QVERIFY(QString::fromStdString(offFix).contains("switched off"));
}

void TestPreflight::invalidBodyIsReported() {
    BodyDef bad = box("Bad", {0.5, -1.0, 0.5}, {0, 2, 0});
    const std::vector<PreflightFinding> findings = runPreflight(withFloor({bad}));
    QCOMPARE(findings.size(), size_t(1));
    QCOMPARE(findings[0].kind, PreflightKind::InvalidBody);
    QVERIFY(QString::fromStdString(findings[0].message).contains("Bad"));
}

QTEST_APPLESS_MAIN(TestPreflight)
#include "tst_preflight.moc"
