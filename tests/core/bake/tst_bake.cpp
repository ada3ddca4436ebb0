// Tests of bake/Bake: frame storage and O(1) access, vertex means from the centre of mass, re-centring, diagnostics.
#include "bake/Bake.h"
#include "core/bake/BakeFixture.h"

#include <QTest>

#include <glm/gtc/quaternion.hpp>

using namespace rl;

namespace {
double distance(const Vec3& a, const Vec3& b) {
    return glm::length(a - b);
}
} // namespace

class TestBake : public QObject {
    Q_OBJECT

private slots:
    void storesAndSeeks() {
        Bake bake(std::vector<BakeBodyInfo>(4), 50.0);
        bake.reserveFrames(10);
        for (int f = 0; f < 10; ++f) {
            QCOMPARE(bake.addFrame(), size_t(f));
            for (int b = 0; b < 4; ++b) {
                BakeBodyState s;
                s.position = glm::vec3(f, b, f * b);
                s.rotation = glm::normalize(glm::quat(1.0f, 0.1f * f, 0.0f, 0.01f * b));
                s.linearVelocity = glm::vec3(-f, 0, b);
                s.angularVelocity = glm::vec3(0, f + b, 0);
                bake.setState(f, b, s);
            }
        }
        QCOMPARE(bake.frameCount(), size_t(10));
        QCOMPARE(bake.bodyCount(), size_t(4));
        QCOMPARE(bake.frameTime(5), 0.1);
        // Random access in any order returns exactly what was stored.
        for (int f : {9, 0, 4, 7}) {
            const std::span<const glm::vec3> frame = bake.positions(f);
            QCOMPARE(frame.size(), size_t(4));
            for (int b = 0; b < 4; ++b) {
                QVERIFY(frame[b] == glm::vec3(f, b, f * b));
                QVERIFY(bake.state(f, b).linearVelocity == glm::vec3(-f, 0, b));
                QVERIFY(bake.angularVelocity(f, b) == glm::vec3(0, f + b, 0));
                QVERIFY(bake.rotations(f)[b] == bake.rotation(f, b));
            }
        }
        // Positions, rotations and two velocities per body and frame: at least 52 bytes each.
        QVERIFY(bake.memoryBytes() >= size_t(10 * 4 * 52));
    }

    void newFrameStartsAtRest() {
        Bake bake(std::vector<BakeBodyInfo>(2), 60.0);
        bake.addFrame();
        const BakeBodyState s = bake.state(0, 1);
        QVERIFY(s.rotation == glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
        QVERIFY(s.position == glm::vec3(0.0f));
        QVERIFY(bake.hasVelocities());
    }

    void vertexMeanFollowsRotation_data() {
        QTest::addColumn<double>("angleDegrees");
        QTest::addColumn<double>("expectX");
        QTest::addColumn<double>("expectZ");
        // Offset (1, 0, 0) rotated about +y: 90 degrees takes +x to -z.
        QTest::newRow("0") << 0.0 << 1.0 << 0.0;
        QTest::newRow("90") << 90.0 << 0.0 << -1.0;
        QTest::newRow("180") << 180.0 << -1.0 << 0.0;
        QTest::newRow("270") << 270.0 << 0.0 << 1.0;
    }

    void vertexMeanFollowsRotation() {
        QFETCH(double, angleDegrees);
        QFETCH(double, expectX);
        QFETCH(double, expectZ);
        std::vector<BakeBodyInfo> infos(1);
        infos[0].vertexMeanOffset = Vec3(1.0, 0.0, 0.0);
        Bake bake(infos, 60.0);
        bake.addFrame();
        BakeBodyState s;
        s.position = glm::vec3(10.0f, 2.0f, 3.0f);
        s.rotation = glm::quat(glm::angleAxis(glm::radians(float(angleDegrees)), glm::vec3(0, 1, 0)));
        bake.setState(0, 0, s);
        QVERIFY(distance(bake.vertexMean(0, 0), Vec3(10.0 + expectX, 2.0, 3.0 + expectZ)) < 1e-6);
    }

    // Re-centring changes what is stored but not where the vertex means are.
    void rebaseKeepsVertexMeans() {
        Bake bake = test::makeFixtureBake(30, 60.0);
        std::vector<Vec3> before;
        for (size_t f = 0; f < bake.frameCount(); ++f)
            before.push_back(bake.vertexMean(f, 2));
        const glm::vec3 oldCom = bake.position(20, 2);
        bake.rebaseVertexMeanOffset(2, Vec3(0.5, -0.25, 0.125));
        QVERIFY(bake.position(20, 2) != oldCom);
        for (size_t f = 0; f < bake.frameCount(); ++f)
            QVERIFY2(distance(bake.vertexMean(f, 2), before[f]) < 1e-5, qPrintable(QString::number(f)));
    }

    void fixtureFrameZeroIsTheVertexMean() {
        const Bake bake = test::makeFixtureBake(2, 60.0);
        const std::vector<Vec3> means = test::objVertexMeans(bake.sceneObjText());
        QCOMPARE(means.size(), bake.bodyCount());
        for (size_t b = 0; b < bake.bodyCount(); ++b)
            QVERIFY(distance(bake.vertexMean(0, b), means[b]) < 1e-6);
    }

    void diagnostics() {
        Bake bake(std::vector<BakeBodyInfo>(1), 60.0);
        bake.addFrame();
        bake.addFrame();
        QVERIFY(!bake.hasDiagnostics());
        QVERIFY(bake.diagnosticTrack(BakeDiagnostic::KineticEnergy).empty());
        bake.enableDiagnostics();
        bake.addFrame();
        for (int d = 0; d < kBakeDiagnosticCount; ++d)
            QCOMPARE(bake.diagnosticTrack(static_cast<BakeDiagnostic>(d)).size(), size_t(3));
        bake.setDiagnostic(2, BakeDiagnostic::ContactCount, 12.0f);
        QCOMPARE(bake.diagnostic(2, BakeDiagnostic::ContactCount), 12.0f);
        QCOMPARE(bake.diagnostic(0, BakeDiagnostic::ContactCount), 0.0f);
        QCOMPARE(bakeDiagnosticName(BakeDiagnostic::AwakeBodies), std::string_view("awake_bodies"));
    }
};

QTEST_APPLESS_MAIN(TestBake)
#include "tst_bake.moc"
