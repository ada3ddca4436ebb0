// The re-bake diff: identical bakes compare equal; a body perturbed from frame k on diverges at frame k with the
// right per-body deltas; tolerances, NaN, frame-count and body-count mismatches; the diff of a real run against the
// same run written to a .bake file and read back.
#include "analysis/BakeDiff.h"
#include "io/BakeFile.h"
#include "io/BakeLoad.h"
#include "io/SceneImport.h"
#include "world/Baker.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace rl;

namespace {

// Three bodies moving on simple paths, 20 frames at 60 fps.
Bake makeBake(size_t frames = 20) {
    std::vector<BakeBodyInfo> bodies(3);
    bodies[0].name = "Floor";
    bodies[0].anchor = true;
    bodies[1].name = "Cube";
    bodies[2].name = "Ball";
    Bake bake(bodies, 60.0);
    for (size_t f = 0; f < frames; ++f) {
        bake.addFrame();
        const float t = static_cast<float>(f) / 60.0f;
        bake.setState(f, 1, {{0.0f, 1.0f - 4.9f * t * t, 0.0f}, glm::angleAxis(t, glm::vec3(0, 1, 0)), {}, {}});
        bake.setState(f, 2, {{2.0f * t, 0.5f, 1.0f}, glm::quat(1, 0, 0, 0), {}, {}});
    }
    return bake;
}

} // namespace

class TestBakeDiff : public QObject {
    Q_OBJECT

private slots:
    void identicalBakesAreEqual();
    void perturbedBodyDiverges_data();
    void perturbedBodyDiverges();
    void rotationDelta_data();
    void rotationDelta();
    void nanCountsAsDivergence();
    void frameCountMismatch();
    void incompatibleBakes();
    void csvAndText();
    void bakeFileRoundTripIsEqual();
};

void TestBakeDiff::identicalBakesAreEqual() {
    const Bake a = makeBake(), b = makeBake();
    const BakeDiffResult r = diffBakes(a, b);
    QVERIFY(r.comparable());
    QVERIFY(r.equal());
    QVERIFY(!r.firstDivergingFrame);
    QCOMPARE(r.framesCompared, size_t(20));
    QCOMPARE(r.bodies.size(), size_t(3));
    for (const BakeBodyDiff& d : r.bodies) {
        QCOMPARE(d.maxPositionDelta, 0.0);
        QCOMPARE(d.maxRotationDegrees, 0.0);
        QVERIFY(!d.firstDivergingFrame);
    }
    QCOMPARE(r.bodies[2].name, std::string("Ball"));
}

void TestBakeDiff::perturbedBodyDiverges_data() {
    QTest::addColumn<int>("body");
    QTest::addColumn<int>("frame");
    QTest::addColumn<double>("offset"); // m along x, growing by this much per frame from `frame` on
    QTest::newRow("cube from frame 7") << 1 << 7 << 1e-3;
    QTest::newRow("ball from frame 0") << 2 << 0 << 0.25;
    QTest::newRow("ball in the last frame") << 2 << 19 << 0.01;
    QTest::newRow("anchor from frame 3") << 0 << 3 << 2e-5;
}

void TestBakeDiff::perturbedBodyDiverges() {
    QFETCH(int, body);
    QFETCH(int, frame);
    QFETCH(double, offset);
    const Bake a = makeBake();
    Bake b = makeBake();
    for (size_t f = static_cast<size_t>(frame); f < b.frameCount(); ++f) {
        BakeBodyState s = b.state(f, static_cast<size_t>(body));
        s.position.x += static_cast<float>(offset * static_cast<double>(f - static_cast<size_t>(frame) + 1));
        b.setState(f, static_cast<size_t>(body), s);
    }
    const BakeDiffResult r = diffBakes(a, b);
    QVERIFY(!r.equal());
    QCOMPARE(r.firstDivergingFrame, std::optional<size_t>(static_cast<size_t>(frame)));
    QCOMPARE(r.firstDivergingBody, std::optional<size_t>(static_cast<size_t>(body)));
    const BakeBodyDiff& d = r.bodies[static_cast<size_t>(body)];
    QCOMPARE(d.firstDivergingFrame, std::optional<size_t>(static_cast<size_t>(frame)));
    // The offset grows to its largest in the last frame.
    const double expected = offset * static_cast<double>(20 - frame);
    QVERIFY2(std::abs(d.maxPositionDelta - expected) < 1e-6 * std::max(1.0, expected),
             qPrintable(QString("max delta %1, expected %2").arg(d.maxPositionDelta).arg(expected)));
    QCOMPARE(d.maxPositionFrame, size_t(19));
    QCOMPARE(d.maxRotationDegrees, 0.0);
    for (size_t other = 0; other < 3; ++other)
        if (other != static_cast<size_t>(body)) {
            QVERIFY(!r.bodies[other].firstDivergingFrame);
            QCOMPARE(r.bodies[other].maxPositionDelta, 0.0);
        }
    // Raising the tolerance above the largest delta makes them equal again.
    BakeDiffOptions loose;
    loose.positionTolerance = expected * 1.01;
    QVERIFY(diffBakes(a, b, loose).equal());
}

void TestBakeDiff::rotationDelta_data() {
    QTest::addColumn<double>("degrees");
    QTest::newRow("tiny") << 0.01;
    QTest::newRow("30") << 30.0;
    QTest::newRow("179") << 179.0;
}

void TestBakeDiff::rotationDelta() {
    QFETCH(double, degrees);
    const Bake a = makeBake();
    Bake b = makeBake();
    const size_t k = 11;
    BakeBodyState s = b.state(k, 2);
    s.rotation =
        glm::angleAxis(static_cast<float>(glm::radians(degrees)), glm::normalize(glm::vec3(1, 2, 3))) * s.rotation;
    b.setState(k, 2, s);
    const BakeDiffResult r = diffBakes(a, b);
    QCOMPARE(r.firstDivergingFrame, std::optional<size_t>(k));
    QCOMPARE(r.bodies[2].maxRotationFrame, k);
    QVERIFY2(std::abs(r.bodies[2].maxRotationDegrees - degrees) < 1e-3 * std::max(1.0, degrees),
             qPrintable(QString::number(r.bodies[2].maxRotationDegrees)));
    QCOMPARE(r.bodies[2].maxPositionDelta, 0.0);
    // q and -q are the same rotation.
    QCOMPARE(rotationDeltaDegrees(s.rotation, -s.rotation), 0.0);
}

void TestBakeDiff::nanCountsAsDivergence() {
    const Bake a = makeBake();
    Bake b = makeBake();
    BakeBodyState s = b.state(5, 1);
    s.position.y = std::nanf("");
    b.setState(5, 1, s);
    const BakeDiffResult r = diffBakes(a, b);
    QCOMPARE(r.firstDivergingFrame, std::optional<size_t>(5));
    QVERIFY(std::isinf(r.bodies[1].maxPositionDelta));
    QCOMPARE(r.bodies[1].maxPositionFrame, size_t(5));
}

void TestBakeDiff::frameCountMismatch() {
    const Bake a = makeBake(20), b = makeBake(12);
    const BakeDiffResult r = diffBakes(a, b);
    QVERIFY(r.comparable());
    QCOMPARE(r.framesCompared, size_t(12));
    QVERIFY(!r.firstDivergingFrame); // the frames both have agree
    QVERIFY(!r.equal());
    QVERIFY(QString::fromStdString(formatBakeDiff(r, {})).contains("frame counts differ: 20 and 12"));
}

void TestBakeDiff::incompatibleBakes() {
    const Bake a = makeBake();
    Bake fewer({BakeBodyInfo{}}, 60.0);
    fewer.addFrame();
    QVERIFY(!diffBakes(a, fewer).comparable());
    QVERIFY(!diffBakes(a, fewer).equal());
    Bake slower(a.bodies(), 30.0);
    slower.addFrame();
    const BakeDiffResult r = diffBakes(a, slower);
    QVERIFY(!r.comparable());
    QVERIFY(QString::fromStdString(r.incompatibility).contains("frame rates"));
}

void TestBakeDiff::csvAndText() {
    const Bake a = makeBake();
    Bake b = makeBake();
    BakeBodyState s = b.state(4, 1);
    s.position.z += 0.5f;
    b.setState(4, 1, s);
    const BakeDiffResult r = diffBakes(a, b);
    const QStringList lines = QString::fromStdString(bakeDiffCsv(r)).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines[0], QString("body,name,first_diverging_frame,max_position_delta,max_position_frame,"
                               "max_rotation_deg,max_rotation_frame"));
    QCOMPARE(lines[1], QString("0,Floor,,0,0,0,0"));
    QCOMPARE(lines[2], QString("1,Cube,4,0.5,4,0,0"));
    const QString text = QString::fromStdString(formatBakeDiff(r, {}));
    QVERIFY2(text.startsWith("first diverging frame 4 (body 1 'Cube')"), qPrintable(text));
    QVERIFY(!text.contains("Ball")); // only bodies that differ are listed
}

void TestBakeDiff::bakeFileRoundTripIsEqual() {
    // A real run, and the same run written to a .bake file and loaded back (vertex means re-based onto centres of
    // mass, floats): equal at the default tolerances.
    Result<Scene> scene = importScene(RL_SOURCE_DIR "/resources/scenes/mixed.obj");
    QVERIFY(scene);
    Result<World> world = World::create(*scene);
    QVERIFY(world);
    Bake bake = startBake(*world);
    bake.setSceneObjText(scene->sourceObjText);
    BakeRequest request;
    request.frames = 90;
    bakeRun(*world, bake, request);
    QTemporaryDir dir;
    const std::string path = dir.filePath("run.bake").toStdString();
    QVERIFY(writeBakeFile(bake, path));
    Result<LoadedBake> loaded = loadBake(path);
    QVERIFY(loaded);
    const BakeDiffResult r = diffBakes(bake, loaded->bake);
    Real maxPos = 0.0, maxRot = 0.0;
    for (const BakeBodyDiff& d : r.bodies) {
        maxPos = std::max(maxPos, d.maxPositionDelta);
        maxRot = std::max(maxRot, d.maxRotationDegrees);
    }
    qInfo("in-memory bake vs its .bake file: largest position delta %.3g m, rotation %.3g deg", maxPos, maxRot);
    QVERIFY2(r.equal(), formatBakeDiff(r, {}).c_str());
    // A re-bake with other settings is not.
    WorldOptions other;
    other.substeps = 4;
    Result<World> world4 = World::create(*scene, other);
    Bake bake4 = startBake(*world4);
    bakeRun(*world4, bake4, request);
    const BakeDiffResult r4 = diffBakes(bake, bake4);
    QVERIFY(r4.firstDivergingFrame);
    QVERIFY(*r4.firstDivergingFrame >= 1);
}

QTEST_APPLESS_MAIN(TestBakeDiff)
#include "tst_bakediff.moc"
