// Tests of rigidlab-cli as a user runs it: exit codes, messages that name the file, and the info/export output.
#include "app/CliRunner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

using rl::test::runCli;
using Run = rl::test::CliRun;

QString scenePath(const char* name) {
    return QStringLiteral(RL_SOURCE_DIR "/resources/scenes/") + name;
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void usage_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("no arguments") << QStringList{} << 2;
        QTest::newRow("help") << QStringList{"--help"} << 0;
        QTest::newRow("unknown command") << QStringList{"frobnicate"} << 2;
        QTest::newRow("info help") << QStringList{"info", "--help"} << 0;
        QTest::newRow("info without scene") << QStringList{"info"} << 2;
        QTest::newRow("info unknown option") << QStringList{"info", "--bogus", "x.obj"} << 2;
        QTest::newRow("export help") << QStringList{"export", "--help"} << 0;
        QTest::newRow("export without input") << QStringList{"export"} << 2;
        QTest::newRow("export with --threads 0")
            << QStringList{"export", RL_TEST_DATA_DIR "/formats/legacy_fall.bake", "--csv", "x.csv", "--threads", "0"}
            << 2;
    }
    void usage() {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        const Run r = runCli(args);
        QCOMPARE(r.exitCode, exitCode);
        if (exitCode == 2)
            QVERIFY(!r.err.isEmpty());
    }

    void badInputNamesTheFile_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("fileName");
        QTest::newRow("empty") << QByteArray() << "empty.obj";
        QTest::newRow("binary") << QByteArray("\x00\x01\x02\xff\xfe garbage \x00", 16) << "binary.obj";
        QTest::newRow("face index out of range")
            << QByteArray("o Cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") << "range.obj";
        QTest::newRow("nan vertex") << QByteArray("o Cube\nv 0 0 nan\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n")
                                    << "nan.obj";
        QTest::newRow("flat dynamic body")
            << QByteArray("o Sheet\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n") << "flat.obj";
    }
    void badInputNamesTheFile() {
        QFETCH(QByteArray, content);
        QFETCH(QString, fileName);
        QTemporaryDir dir;
        const QString path = dir.filePath(fileName);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        const Run r = runCli({"info", path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(fileName.toUtf8()), r.err.constData());
    }

    void deviceFileIsRefused() {
        // A scene path that names a device must fail at once, not read forever.
        QTemporaryDir dir;
        const QString link = dir.filePath("zero.obj");
        QVERIFY(QFile::link("/dev/zero", link));
        const Run r = runCli({"info", link});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("regular file"), r.err.constData());
    }

    void missingFile() {
        const Run r = runCli({"info", "/nonexistent/scene.obj"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("/nonexistent/scene.obj"));
    }

    void infoJsonOnStack() {
        const Run r = runCli({"info", scenePath("stack.obj"), "--json"});
        QCOMPARE(r.exitCode, 0);
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(r.out, &error);
        QCOMPARE(error.error, QJsonParseError::NoError);
        const QJsonArray bodies = doc.object().value("bodies").toArray();
        QCOMPARE(bodies.size(), 11);
        int anchors = 0;
        for (const QJsonValue& v : bodies) {
            const QJsonObject b = v.toObject();
            if (b.value("anchor").toBool()) {
                ++anchors;
                QCOMPARE(b.value("volume").toDouble(), 0.0);
                continue;
            }
            // Unit Wood cubes: 1 m^3, 700 kg, inertia m/6 on the diagonal.
            QVERIFY(qAbs(b.value("volume").toDouble() - 1.0) < 1e-9);
            QVERIFY(qAbs(b.value("mass").toDouble() - 700.0) < 1e-6);
            QCOMPARE(b.value("material").toString(), QString("Wood"));
            const QJsonArray inertia = b.value("inertia").toArray();
            QCOMPARE(inertia.size(), 3);
            QVERIFY(qAbs(inertia[0].toArray()[0].toDouble() - 700.0 / 6.0) < 1e-6);
            QVERIFY(qAbs(inertia[0].toArray()[1].toDouble()) < 1e-6);
            QCOMPARE(b.value("hull_vertices").toInt(), 8);
        }
        QCOMPARE(anchors, 1);
    }

    void exportLegacyBakeToCsvAndBack() {
        QTemporaryDir dir;
        const QString legacy = QStringLiteral(RL_TEST_DATA_DIR "/formats/legacy_fall.bake");
        const QString csv1 = dir.filePath("a.csv"), bake = dir.filePath("b.bake"), csv2 = dir.filePath("b.csv");
        Run r = runCli({"export", legacy, "--csv", csv1, "--bake", bake});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        r = runCli({"export", bake, "--csv", csv2});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile a(csv1), b(csv2);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QByteArray textA = a.readAll();
        QCOMPARE(textA, b.readAll()); // rewriting as a current .bake loses nothing the CSV shows
        const QList<QByteArray> lines = textA.split('\n');
        QCOMPARE(lines[0], QByteArray("frame,time,body,name,anchor,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz"));
        // Frame 0 of the cube: its centre of mass, (0.25, 2.25, 0.25); the anchor flag comes from the OBJ part.
        QVERIFY2(lines[2].startsWith("0,0,1,Cube.002,0,0.25,2.25,0.25,1,0,0,0"), lines[2].constData());
        QVERIFY2(lines[1].startsWith("0,0,0,Anchor,1,"), lines[1].constData());
    }

    // export --threads formats on several threads and writes the same bytes as one thread: 31 frames of ramps.obj's
    // 646 bodies are three blocks of frames.
    void exportOnThreadsWritesTheSameFiles() {
        QTemporaryDir dir;
        const QString legacy = dir.filePath("ramps.bake");
        const Run baked =
            runCli({"bake", RL_SOURCE_DIR "/resources/scenes/ramps.obj", "--frames", "30", "-o", legacy, "--quiet"});
        QVERIFY2(baked.exitCode == 0, baked.err.constData());
        QByteArray csv[2], bake[2];
        for (int k = 0; k < 2; ++k) {
            const QString c = dir.filePath(QString("%1.csv").arg(k)), b = dir.filePath(QString("%1.bake").arg(k));
            const Run r = runCli({"export", legacy, "--csv", c, "--bake", b, "--threads", k == 0 ? "1" : "3"});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            QFile fc(c), fb(b);
            QVERIFY(fc.open(QIODevice::ReadOnly) && fb.open(QIODevice::ReadOnly));
            csv[k] = fc.readAll();
            bake[k] = fb.readAll();
        }
        QCOMPARE(csv[0].count('\n'), 31 * 646 + 1);
        QVERIFY(csv[1] == csv[0]);
        QVERIFY(bake[1] == bake[0]);
    }

    void exportSubsetOfBodiesAndFrames() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("s.csv");
        const Run r = runCli({"export", QStringLiteral(RL_TEST_DATA_DIR "/formats/legacy_fall.bake"), "--csv", csv,
                              "--bodies", "Cube.002", "--frames", "1:2"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 3); // header + frames 1 and 2 of one body
        QVERIFY(lines[1].startsWith("1,"));
        QVERIFY(lines[2].startsWith("2,"));
    }

    void exportBadInput_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("bad id") << QByteArray("0 0 0 0\nx 1 1 1\n") << 1;
        QTest::newRow("short line") << QByteArray("0 0 0 0\n0 1 1\n") << 1;
        QTest::newRow("empty") << QByteArray() << 1;
    }
    void exportBadInput() {
        QFETCH(QByteArray, content);
        QFETCH(int, exitCode);
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.bake");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        const Run r = runCli({"export", path, "--csv", dir.filePath("out.csv")});
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains("broken.bake"), r.err.constData());
        QVERIFY(!QFile::exists(dir.filePath("out.csv"))); // nothing half-written
    }

    void bakeWritesBakeCsvAndProfile() {
        QTemporaryDir dir;
        const QString bake = dir.filePath("stack.bake"), csv = dir.filePath("stack.csv");
        const Run r = runCli(
            {"bake", scenePath("stack.obj"), "-o", bake, "--csv", csv, "--frames", "30", "--profile", "--quiet"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        // --profile: one line per stage, the active effects, and counters.
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        int stages = 0, counters = 0, effects = 0;
        for (const QByteArray& line : lines) {
            stages += line.startsWith("stage=") && line.contains(" ms=") && line.contains(" calls=") ? 1 : 0;
            counters += line.startsWith("counter=") && line.contains(" value=") ? 1 : 0;
            effects += line.startsWith("effects=") ? 1 : 0;
        }
        QCOMPARE(stages, 17); // rl::kStageCount
        QVERIFY(r.out.contains("stage=separate ms="));
        QVERIFY(r.out.contains("stage=prepare_contacts ms=") && r.out.contains("stage=store_impulses ms="));
        QCOMPARE(effects, 1);
        QVERIFY(counters >= 10);
        QVERIFY(r.out.contains("effects=gravity,rotation,friction,restitution,sleeping"));

        // The .bake: header, the source OBJ verbatim, '!', then 31 frames x 11 bodies; frame 0 = vertex means.
        QFile f(bake);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.startsWith("# rigidlab-bake 2 fps=60 frames=31 bodies=11 columns=id,x,y,z,qw,qx,qy,qz\n"));
        QFile source(scenePath("stack.obj"));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QVERIFY(text.contains(source.readAll()));
        const QByteArray data = text.mid(text.indexOf("\n!\n") + 3);
        const QList<QByteArray> rows = data.trimmed().split('\n');
        QCOMPARE(rows.size(), 31 * 11);
        const QList<QByteArray> top = rows[10].split(' '); // frame 0, body 10: the top cube, spanning y 9..10
        QCOMPARE(top[0], QByteArray("10"));
        QCOMPARE(top[2].toDouble(), 9.5);
        QCOMPARE(top[4], QByteArray("1"));

        QFile c(csv);
        QVERIFY(c.open(QIODevice::ReadOnly));
        QCOMPARE(c.readAll().trimmed().split('\n').size(), 1 + 31 * 11);

        // Without --quiet, the closing line says how long the bake and the files took; with no files, only the bake.
        Run loud = runCli({"bake", scenePath("stack.obj"), "-o", bake, "--frames", "30", "--threads", "2"});
        QVERIFY2(loud.exitCode == 0, loud.err.constData());
        QVERIFY2(
            QRegularExpression("baked 30 frames of 11 bodies in [0-9.]+ s \\([0-9.]+ ms/step\\), wrote the files in "
                               "[0-9.]+ s\n$")
                .match(QString::fromUtf8(loud.err))
                .hasMatch(),
            loud.err.constData());
        loud = runCli({"bake", scenePath("stack.obj"), "--frames", "30"});
        QVERIFY2(loud.exitCode == 0, loud.err.constData());
        QVERIFY2(loud.err.contains("ms/step)\n") && !loud.err.contains("wrote"), loud.err.constData());
    }

    void bakeBadOptions_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("both seconds and frames") << QStringList{"--seconds", "1", "--frames", "2"};
        QTest::newRow("bad integrator") << QStringList{"--integrator", "leapfrog"};
        QTest::newRow("bad effect") << QStringList{"--effects", "auto,-magic"};
        QTest::newRow("negative substeps") << QStringList{"--substeps", "-2"};
    }
    void bakeBadOptions() {
        QFETCH(QStringList, args);
        const Run r = runCli(QStringList{"bake", scenePath("stack.obj")} + args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(!r.err.isEmpty());
    }

    void accuracyPrintsTableAndWritesFiles() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("acc.csv"), svg = dir.filePath("acc.svg");
        const Run r = runCli({"accuracy", "--csv", csv, "--plot", svg});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(r.out.contains("fitted order"));
        // The original project's experiment: sin(t) over [0, 2 pi] with 10, 20 and 40 steps for every integrator.
        for (const char* integrator : {"explicit-euler", "symplectic-euler", "verlet", "rk4"})
            for (const char* steps : {" 10 ", " 20 ", " 40 "}) {
                bool found = false;
                for (const QByteArray& line : r.out.split('\n'))
                    found =
                        found || (line.startsWith("oscillator") && line.contains(integrator) && line.contains(steps));
                QVERIFY2(found, integrator);
            }
        QFile c(csv), p(svg);
        QVERIFY(c.open(QIODevice::ReadOnly) && p.open(QIODevice::ReadOnly));
        QVERIFY(c.readAll().count('\n') > 100);
        QVERIFY(p.readAll().contains("<svg"));
    }

    void infoTextMentionsWarnings() {
        const Run r = runCli({"info", scenePath("mixed.obj")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("concave"), r.out.constData());
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
