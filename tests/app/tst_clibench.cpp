// Tests of `rigidlab-cli bench` as a user runs it: the one-line-per-scene output with its fields, and the exit
// codes for unknown scene names, bad frame counts and bad scene files.
#include "app/CliRunner.h"

#include <QTemporaryDir>
#include <QTest>

namespace {

using rl::test::runCli;
using Run = rl::test::CliRun;

// key=value pairs of one output line.
QHash<QString, QString> fields(const QString& line) {
    QHash<QString, QString> out;
    for (const QString& token : line.split(' ', Qt::SkipEmptyParts)) {
        const qsizetype eq = token.indexOf('=');
        if (eq > 0)
            out.insert(token.left(eq), token.mid(eq + 1));
    }
    return out;
}

} // namespace

class TestCliBench : public QObject {
    Q_OBJECT
private slots:
    void namedSceneLine() {
        const Run r = runCli({"bench", "stack20", "--frames", "10", "--quiet"});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = QString::fromUtf8(r.out).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1);
        const QHash<QString, QString> f = fields(lines.front());
        QCOMPARE(f.value("scene"), QStringLiteral("stack20"));
        QCOMPARE(f.value("bodies"), QStringLiteral("21")); // floor + 20 cubes
        QCOMPARE(f.value("frames"), QStringLiteral("10"));
        for (const char* key : {"median_ms", "p95_ms", "mean_ms", "broad_ms", "narrow_ms", "solve_ms", "other_ms"}) {
            bool ok = false;
            const double v = f.value(key).toDouble(&ok);
            QVERIFY2(ok && v >= 0.0, key);
        }
        QVERIFY(f.value("p95_ms").toDouble() >= f.value("median_ms").toDouble());
        for (const char* key : {"awake", "contacts"}) {
            bool ok = false;
            const int v = f.value(key).toInt(&ok);
            QVERIFY2(ok && v >= 0, key);
        }
        // The cubes of the stack rest on each other and on the floor.
        QVERIFY(f.value("contacts").toInt() > 0);
    }

    void progressGoesToStderr() {
        const Run r = runCli({"bench", "stack20", "--frames", "5"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.err.contains("stack20"));
        QVERIFY(r.out.startsWith("scene=stack20 "));
    }

    void sceneFile() {
        const Run r = runCli({"bench", RL_SOURCE_DIR "/resources/scenes/stack.obj", "--frames", "3", "--quiet"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("bodies=11 frames=3 "));
    }

    void usageErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("unknown name") << QStringList{"bench", "stack21", "--frames", "10"};
        QTest::newRow("frames zero") << QStringList{"bench", "stack20", "--frames", "0"};
        QTest::newRow("frames negative") << QStringList{"bench", "stack20", "--frames", "-5"};
        QTest::newRow("frames not a number") << QStringList{"bench", "stack20", "--frames", "ten"};
        QTest::newRow("threads zero") << QStringList{"bench", "stack20", "--threads", "0"};
        QTest::newRow("unknown option") << QStringList{"bench", "--bogus"};
        QTest::newRow("scaling with scenes") << QStringList{"bench", "--scaling", "stack20"};
    }
    void usageErrors() {
        QFETCH(QStringList, args);
        const Run r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY(!r.err.isEmpty());
    }

    void unknownNameListsTheNames() {
        const Run r = runCli({"bench", "stack21"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("stack21"));
        QVERIFY(r.err.contains("stack20"));
        QVERIFY(r.err.contains("scale16k"));
    }

    void badSceneFileFails() {
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.obj");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("o Cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
        f.close();
        const Run missing = runCli({"bench", dir.filePath("missing.obj"), "--frames", "2"});
        QCOMPARE(missing.exitCode, 1);
        QVERIFY(missing.err.contains("missing.obj"));
        const Run broken = runCli({"bench", path, "--frames", "2"});
        QCOMPARE(broken.exitCode, 1);
        QVERIFY(broken.err.contains("broken.obj"));
    }

    void help() {
        const Run r = runCli({"bench", "--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--frames"));
        QVERIFY(r.out.contains("--scaling"));
    }
};

QTEST_GUILESS_MAIN(TestCliBench)
#include "tst_clibench.moc"
