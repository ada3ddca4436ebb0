// The slow part of issue 4's acceptance check (label `slow`): the original project's 642-cube ramps scene
// (resources/scenes/ramps.obj, made with Blender's OBJ exporter) baked for 20 s at default settings with
// `rigidlab-cli bake`, checked from the CSV (no NaN, no cube under the floor, at rest in the last second), re-baked
// and baked on 2 threads with identical hashes. Prints the wall time of each bake.
//
// Why 20 s: on the middle ramp (27.5 degrees) the 0.2 m cubes slide on each other (mu 0.5, below tan 27.5 = 0.52)
// until they reach its foot, some held behind others for seconds first, so whether the last one has arrived by 10 s
// is chance. Of 37 starts (the scene, and 36 with every cube moved by up to 0.1 mm), 17 were at rest in the last
// second of 10 s and all 37 in that of 20 s (2026-12-07, 9f3a1ec; with the wedge normal of Collide.cpp 14 and 37).
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
        const QString seconds = QStringLiteral("20");
        const Bake a = bake(scene, {}, true, seconds);
        const qint64 msA = timer.restart();
        QVERIFY2(a.run.exitCode == 0, a.run.err.constData());
        QVERIFY2(a.csv.ok, qPrintable(a.csv.error));
        QCOMPARE(a.csv.bodies, 646);
        QCOMPARE(a.csv.frames, 1201);
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

        const Bake b = bake(scene, {}, false, seconds);
        const qint64 msB = timer.restart();
        const Bake c = bake(scene, {"--threads", "2"}, false, seconds);
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
