// Tests of io/AtomicFile: a write either replaces the target completely or leaves it as it was, with no leftovers.
#include "io/AtomicFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>
#include <sstream>

using namespace rl;

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

QStringList entries(const QTemporaryDir& dir) {
    return QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot);
}

} // namespace

class TestAtomicFile : public QObject {
    Q_OBJECT

private slots:
    void writesNewFile() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("out.txt").toStdString();
        Status s = writeFileAtomically(path, std::string_view("hello\nworld\n"));
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().toString().c_str());
        QCOMPARE(slurp(path), std::string("hello\nworld\n"));
        QCOMPARE(entries(dir), QStringList{"out.txt"});
    }

    void replacesExistingFile() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("out.txt").toStdString();
        QVERIFY(writeFileAtomically(path, std::string_view("old content that is longer")).ok());
        QVERIFY(writeFileAtomically(path, std::string_view("new")).ok());
        QCOMPARE(slurp(path), std::string("new"));
        QCOMPARE(entries(dir), QStringList{"out.txt"});
    }

    // A writer that gives up half way (a cancelled bake, a validation error) must leave the old file untouched.
    void failingWriterKeepsOldFile() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("scene.bake").toStdString();
        const std::string old = "the previous export\n";
        QVERIFY(writeFileAtomically(path, std::string_view(old)).ok());

        bool wroteSomething = false;
        Status s = writeFileAtomically(path, [&](std::ostream& out) -> Status {
            // More than the stream buffer, so part of it has really reached the temporary file.
            const std::string chunk(1000, 'x');
            for (int i = 0; i < 300; ++i)
                out << chunk << '\n';
            wroteSomething = out.good();
            return Error{{}, 0, {}, "cancelled half way"};
        });
        QVERIFY(wroteSomething);
        QVERIFY(!s.ok());
        QCOMPARE(s.error().file, path);
        QVERIFY(s.error().message.find("cancelled") != std::string::npos);
        QCOMPARE(slurp(path), old);
        QCOMPARE(entries(dir), QStringList{"scene.bake"});
    }

    // Saving through a symbolic link updates the file it points to; the link stays a link.
    void writesThroughSymbolicLink() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("real"));
        const std::string real = dir.filePath("real/data.txt").toStdString();
        const std::string link = dir.filePath("link.txt").toStdString();
        QVERIFY(writeFileAtomically(real, std::string_view("before")).ok());
        QVERIFY(QFile::link(QString::fromStdString(real), QString::fromStdString(link)));
        QVERIFY(writeFileAtomically(link, std::string_view("after")).ok());
        QVERIFY(QFileInfo(QString::fromStdString(link)).isSymLink());
        QCOMPARE(slurp(real), std::string("after"));
        QCOMPARE(entries(dir), QStringList{"link.txt"});
        QCOMPARE(QDir(dir.filePath("real")).entryList(QDir::Files | QDir::Hidden), QStringList{"data.txt"});
    }

    void destroyedWriterLeavesNothing() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("never.txt").toStdString();
        {
            AtomicFileWriter writer(path);
            QVERIFY(writer.open().ok());
            writer.stream() << "partial";
            QCOMPARE(entries(dir).size(), 1); // the temporary file exists while writing
        }
        QVERIFY(entries(dir).isEmpty());
    }

    void unwritableTargetIsAnError_data() {
        QTest::addColumn<QString>("relative");
        QTest::addColumn<QString>("expectInMessage");
        QTest::newRow("missing directory") << "no/such/dir/out.txt"
                                           << "no/such/dir";
        QTest::newRow("parent is a file") << "plain.txt/out.txt"
                                          << "not a directory";
        QTest::newRow("directory as target") << "sub/"
                                             << "not a file name";
    }

    void unwritableTargetIsAnError() {
        QFETCH(QString, relative);
        QFETCH(QString, expectInMessage);
        QTemporaryDir dir;
        QVERIFY(writeFileAtomically(dir.filePath("plain.txt").toStdString(), std::string_view("x")).ok());
        QVERIFY(QDir(dir.path()).mkdir("sub"));
        const std::string path = dir.filePath(relative).toStdString();
        Status s = writeFileAtomically(path, std::string_view("data"));
        QVERIFY(!s.ok());
        QCOMPARE(s.error().file, path);
        const std::string text = s.error().toString();
        QVERIFY2(text.find(expectInMessage.toStdString()) != std::string::npos, text.c_str());
        QVERIFY(text.find(path) != std::string::npos);
    }

    // Streams well past the buffer size; the content must arrive complete and in order.
    void streamsLargeOutput() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("big.txt").toStdString();
        constexpr int kLines = 200000;
        Status s = writeFileAtomically(path, [](std::ostream& out) -> Status {
            for (int i = 0; i < kLines; ++i)
                out << i << '\n';
            return Ok{};
        });
        QVERIFY(s.ok());
        std::ifstream in(path);
        int expected = 0, value = 0;
        while (in >> value) {
            QCOMPARE(value, expected);
            ++expected;
        }
        QCOMPARE(expected, kLines);
    }
};

QTEST_APPLESS_MAIN(TestAtomicFile)
#include "tst_atomicfile.moc"
