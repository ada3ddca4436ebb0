// rigidlab-cli diff as a user runs it: a bake against itself (exit 0), against a re-bake with other settings (exit
// 1, the first diverging frame and the per-body table), tolerances, --csv, and bad usage or input.
#include "app/CliRunner.h"

#include <QTemporaryDir>
#include <QTest>

namespace {

using rl::test::runCli;
using Run = rl::test::CliRun;

const QString kStack = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj");

} // namespace

class TestCliDiff : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_base, m_same, m_other, m_short;

    QString path(const char* name) const { return m_dir.filePath(QLatin1String(name)); }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_base = path("base.bake");
        m_same = path("same.bake");
        m_other = path("substeps4.bake");
        m_short = path("short.bake");
        // A dropped cube makes the stack's motion depend on the substeps from the first frames on.
        const QStringList common{"--seconds", "1", "--quiet"};
        QCOMPARE(runCli(QStringList{"bake", kStack, "-o", m_base} + common).exitCode, 0);
        QCOMPARE(runCli(QStringList{"bake", kStack, "-o", m_same} + common).exitCode, 0);
        QCOMPARE(runCli(QStringList{"bake", kStack, "-o", m_other, "--substeps", "1"} + common).exitCode, 0);
        QCOMPARE(runCli(QStringList{"bake", kStack, "-o", m_short, "--frames", "30", "--quiet"}).exitCode, 0);
    }

    void equalBakes() {
        const Run r = runCli({"diff", m_base, m_same});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith("equal within tolerance 1e-05 m, 0.001 deg over 61 frames"), r.out.constData());
    }

    void differentSettings() {
        const Run r = runCli({"diff", m_base, m_other});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.startsWith("first diverging frame "), r.out.constData());
        QVERIFY(r.out.contains("max_pos_m"));
        QVERIFY(r.out.contains("Cube"));
        QVERIFY(r.err.isEmpty());
    }

    void csvOutput() {
        const Run r = runCli({"diff", m_base, m_other, "--csv"});
        QCOMPARE(r.exitCode, 1);
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 12); // header + 11 bodies
        QCOMPARE(lines[0], QByteArray("body,name,first_diverging_frame,max_position_delta,max_position_frame,"
                                      "max_rotation_deg,max_rotation_frame"));
        QVERIFY(lines[1].startsWith("0,Anchor,,0,0,0,0")); // the floor never moves
        // Same bakes in CSV: every body within tolerance.
        const Run same = runCli({"diff", m_base, m_same, "--csv"});
        QCOMPARE(same.exitCode, 0);
        for (const QByteArray& line : same.out.trimmed().split('\n').mid(1))
            QCOMPARE(line.split(',').at(2), QByteArray());
    }

    void toleranceDecides() {
        // A tolerance far above any difference (100 m, 360 degrees) makes the re-bake equal.
        const Run r = runCli({"diff", m_base, m_other, "--tolerance", "100", "--angle-tolerance", "360"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith("equal within tolerance 100 m, 360 deg"));
    }

    void frameCountsDiffer() {
        const Run r = runCli({"diff", m_base, m_short});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains("frame counts differ: 61 and 31"), r.out.constData());
    }

    void badUsageAndInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("help") << QStringList{"diff", "--help"} << 0 << "";
        QTest::newRow("one file") << QStringList{"diff", "a.bake"} << 2 << "expected two .bake files";
        QTest::newRow("bad tolerance") << QStringList{"diff", "a.bake", "b.bake", "--tolerance", "-1"} << 2
                                       << "--tolerance";
        QTest::newRow("unknown option") << QStringList{"diff", "a.bake", "b.bake", "--bogus"} << 2 << "bogus";
        QTest::newRow("missing file") << QStringList{"diff", "/nonexistent/a.bake", "b.bake"} << 1
                                      << "/nonexistent/a.bake";
    }
    void badUsageAndInput() {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        const Run r = runCli(args);
        QCOMPARE(r.exitCode, exitCode);
        if (!message.isEmpty()) {
            QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
            QVERIFY(r.out.isEmpty());
        }
    }

    void incompatibleBakes() {
        // Another scene with other bodies.
        const QString mixed = path("mixed.bake");
        QCOMPARE(runCli({"bake", RL_SOURCE_DIR "/resources/scenes/mixed.obj", "-o", mixed, "--frames", "5", "--quiet"})
                     .exitCode,
                 0);
        const Run r = runCli({"diff", m_base, mixed});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("different bodies: 11 and 9"), r.err.constData());
    }

    void listedInUsage() {
        const Run r = runCli({"--help"});
        QVERIFY(r.out.contains("diff"));
    }
};

QTEST_GUILESS_MAIN(TestCliDiff)
#include "tst_clidiff.moc"
