// The slow part of issue 4's acceptance check (label `slow`): the original project's 642-cube ramps scene
// (resources/scenes/ramps.obj, made with Blender's OBJ exporter) baked for 10 s at default settings with
// `rigidlab-cli bake`, checked from the CSV (no NaN, no cube under the floor, at rest in the last second), re-baked
// and baked on 2 threads with identical hashes. Prints the wall time of each bake.
#include "data/acceptance/AcceptanceCsv.h"

#include <QElapsedTimer>
#include <QTest>

using namespace rl::test::acceptance;

class TestAcceptanceSlow : public QObject {
    Q_OBJECT
private slots:
    void ramps() {
        const QString scene = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/ramps.obj");
        QElapsedTimer timer;
        timer.start();
        const Bake a = bake(scene);
        const qint64 msA = timer.restart();
        QVERIFY2(a.run.exitCode == 0, a.run.err.constData());
        QVERIFY2(a.csv.ok, qPrintable(a.csv.error));
        QCOMPARE(a.csv.bodies, 646);
        QCOMPARE(a.csv.frames, 601);
        QVERIFY2(a.csv.allFinite(), "NaN or inf in the CSV");
        int frame = 0;
        QString body;
        const double low = lowestVertexY(a.csv, scene, &frame, &body);
        const double speed = a.csv.maxSpeedLastSecond();
        qInfo("ramps.obj: bake %.1f s wall; lowest vertex y %.2f mm ('%s', frame %d; floor at 0), max speed in the "
              "last second %.4f cm/s, largest displacement %.2f m",
              msA / 1000.0, 1e3 * low, qPrintable(body), frame, 1e2 * speed, a.csv.maxDisplacement());
        QVERIFY(low > -0.01);
        QVERIFY(speed < 0.01);

        const Bake b = bake(scene, {}, false);
        const qint64 msB = timer.restart();
        const Bake c = bake(scene, {"--threads", "2"}, false);
        const qint64 msC = timer.restart();
        qInfo("ramps.obj: re-bake %.1f s, --threads 2 %.1f s; csv sha256 %s / %s / %s", msB / 1000.0, msC / 1000.0,
              a.csvHash.left(16).constData(), b.csvHash.left(16).constData(), c.csvHash.left(16).constData());
        QCOMPARE(b.csvHash, a.csvHash);
        QCOMPARE(b.bakeHash, a.bakeHash);
        QCOMPARE(c.csvHash, a.csvHash);
        QCOMPARE(c.bakeHash, a.bakeHash);
    }
};

QTEST_GUILESS_MAIN(TestAcceptanceSlow)
#include "tst_acceptance_slow.moc"
