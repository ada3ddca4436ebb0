// Tests of io/BakeFile: our .bake round trip, the original project's flavour both ways, the original reader's view
// of our files, and an Error with file and line for every kind of broken file.
#include "core/bake/BakeFixture.h"
#include "io/AtomicFile.h"
#include "io/BakeFile.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>
#include <sstream>

using namespace rl;

Q_DECLARE_METATYPE(std::string)

namespace {

std::string toText(const Bake& bake, bool legacy = false) {
    std::ostringstream out;
    if (legacy)
        writeLegacyBake(bake, out);
    else
        writeBake(bake, out);
    return out.str();
}

// The original project's reader: skip up to the '!' line if there is one, skip '#' lines, read `id x y z` and
// ignore further columns, group the positions by id in line order.
std::map<int, std::vector<Vec3>> readTheOriginalWay(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line == "!") {
            lines.clear();
            continue;
        }
        lines.push_back(line);
    }
    std::map<int, std::vector<Vec3>> byId;
    for (const std::string& l : lines) {
        if (l.empty() || l[0] == '#')
            continue;
        std::istringstream fields(l);
        int id = -1;
        Vec3 p;
        fields >> id >> p.x >> p.y >> p.z;
        if (fields)
            byId[id].push_back(p);
    }
    return byId;
}

double relativeError(double a, double b) {
    return std::abs(a - b) / std::max(1.0, std::abs(b));
}

} // namespace

class TestBakeFile : public QObject {
    Q_OBJECT

private slots:
    void roundTripIsExact() {
        const Bake bake = test::makeFixtureBake(61, 60.0);
        const std::string text = toText(bake);
        QVERIFY(text.rfind("# rigidlab-bake 2 fps=60 frames=61 bodies=3 columns=id,x,y,z,qw,qx,qy,qz\n", 0) == 0);
        std::string objAndEnd(test::fixtureObjText());
        objAndEnd += "!\n";
        QVERIFY(text.find(objAndEnd) != std::string::npos);

        BakeFileInfo info;
        Result<Bake> back = readBake(text, "fixture.bake", &info);
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
        QCOMPARE(info.version, 2);
        QCOMPARE(info.columns, 7);
        QVERIFY(info.order == BakeLineOrder::FrameMajor);
        QCOMPARE(back->fps(), 60.0);
        QCOMPARE(back->frameCount(), size_t(61));
        QCOMPARE(back->bodyCount(), size_t(3));
        QCOMPARE(back->sceneObjText(), std::string(test::fixtureObjText()));
        QVERIFY(!back->hasVelocities());
        for (size_t b = 0; b < 3; ++b) {
            QCOMPARE(back->body(b).name, bake.body(b).name);
            QCOMPARE(back->body(b).anchor, bake.body(b).anchor);
        }
        // Bit-exact: the file holds the float vertex mean and the float rotation.
        for (size_t f = 0; f < bake.frameCount(); ++f)
            for (size_t b = 0; b < 3; ++b) {
                QVERIFY(back->position(f, b) == glm::vec3(bake.vertexMean(f, b)));
                QVERIFY(back->rotation(f, b) == bake.rotation(f, b));
            }
        // Written again, the text is identical.
        QCOMPARE(toText(*back), text);
    }

    // The frame where the simulation started travels as start= in the header; 0 is left out.
    void simulationStartRoundTrips() {
        Bake bake = test::makeFixtureBake(61, 60.0);
        bake.setSimulationStart(20);
        const std::string text = toText(bake);
        QVERIFY(text.rfind("# rigidlab-bake 2 fps=60 frames=61 bodies=3 columns=id,x,y,z,qw,qx,qy,qz start=20\n", 0) ==
                0);
        Result<Bake> back = readBake(text, "fixture.bake");
        QVERIFY(back.ok());
        QCOMPARE(back->simulationStart(), size_t(20));
        QCOMPARE(toText(*back), text);
    }

    void fileRoundTripIsAtomic() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("run.bake").toStdString();
        const Bake bake = test::makeFixtureBake(5, 30.0);
        QVERIFY(writeBakeFile(bake, path).ok());
        Result<Bake> back = readBakeFile(path);
        QVERIFY(back.ok());
        QCOMPARE(back->frameCount(), size_t(5));
        QCOMPARE(back->fps(), 30.0);
        Result<Bake> missing = readBakeFile(dir.filePath("missing.bake").toStdString());
        QVERIFY(!missing.ok());
        QVERIFY(missing.error().toString().find("missing.bake") != std::string::npos);
    }

    // What the original project's reader gets from our file: frame 0 of every body is the OBJ vertex mean.
    void originalReaderLoadsOurFile() {
        const Bake bake = test::makeFixtureBake(21, 60.0);
        const std::map<int, std::vector<Vec3>> byId = readTheOriginalWay(toText(bake));
        const std::vector<Vec3> means = test::objVertexMeans(test::fixtureObjText());
        QCOMPARE(byId.size(), size_t(3));
        for (const auto& [id, positions] : byId) {
            QCOMPARE(positions.size(), size_t(21));
            // Float precision of a position of a few metres.
            QVERIFY2(glm::length(positions[0] - means[size_t(id)]) < 1e-6, qPrintable(QString::number(id)));
        }
        // And frame 20 is where the fixture put the vertex mean.
        QVERIFY(glm::length(byId.at(1)[20] - bake.vertexMean(20, 1)) < 1e-6);
    }

    void legacyFlavourRoundTrip() {
        const Bake bake = test::makeFixtureBake(41, kLegacyBakeFps);
        const std::string text = toText(bake, true);
        QVERIFY(text.find("# rigidlab-bake") == std::string::npos);
        QVERIFY(text.find("!\r\n") != std::string::npos);
        const std::string data = text.substr(text.find("!\r\n") + 3);
        QVERIFY(data.find('\n') == data.find("\r\n") + 1); // CRLF line ends
        QVERIFY(data.rfind("0 ", 0) == 0);

        BakeFileInfo info;
        Result<Bake> back = readBake(text, "legacy.bake", &info);
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
        QCOMPARE(info.version, 0);
        QCOMPARE(info.columns, 3);
        QVERIFY(info.order == BakeLineOrder::ObjectMajor);
        QCOMPARE(back->fps(), kLegacyBakeFps);
        QCOMPARE(back->frameCount(), size_t(41));
        QCOMPARE(back->body(1).name, std::string("Cube"));
        QVERIFY(back->body(0).anchor);
        // %g keeps six significant digits.
        double worst = 0.0;
        for (size_t f = 0; f < 41; ++f)
            for (size_t b = 0; b < 3; ++b) {
                const Vec3 expected = bake.vertexMean(f, b);
                const Vec3 got(back->position(f, b));
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, relativeError(got[c], expected[c]));
                QVERIFY(back->rotation(f, b) == glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
            }
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
    }

    // A file in the original flavour made by tests/data/formats/make_legacy_bake.py from a closed-form fall.
    void readsOriginalProjectFile() {
        BakeFileInfo info;
        Result<Bake> bake = readBakeFile(RL_TEST_DATA_DIR "/formats/legacy_fall.bake", &info);
        QVERIFY2(bake.ok(), bake.ok() ? "" : bake.error().toString().c_str());
        QCOMPARE(info.version, 0);
        QVERIFY(info.order == BakeLineOrder::ObjectMajor);
        QCOMPARE(bake->fps(), 200.0);
        QCOMPARE(bake->bodyCount(), size_t(2));
        QCOMPARE(bake->frameCount(), size_t(41));
        QVERIFY(bake->body(0).anchor);
        QVERIFY(!bake->body(1).anchor);
        QVERIFY(bake->sceneObjText().find("o Cube.002") != std::string::npos);
        for (size_t f = 0; f < bake->frameCount(); ++f) {
            const double t = bake->frameTime(f);
            QVERIFY(relativeError(bake->position(f, 1).y, 2.25 - 0.5 * 9.81 * t * t) < 1e-5);
            QCOMPARE(bake->position(f, 0).y, 0.0f);
        }
    }

    // Lines of several frames interleaved in another order still land in the right frames.
    void headerlessFrameMajorAndEightColumns() {
        const std::string text = "0 1 0 0 1 0 0 0\n1 2 0 0 1 0 0 0\n0 1 1 0 0 1 0 0\n1 2 1 0 0 0 1 0\n";
        BakeFileInfo info;
        Result<Bake> bake = readBake(text, "mixed.bake", &info);
        QVERIFY(bake.ok());
        QVERIFY(info.order == BakeLineOrder::FrameMajor);
        QCOMPARE(info.columns, 7);
        QCOMPARE(bake->frameCount(), size_t(2));
        QCOMPARE(bake->position(1, 1), glm::vec3(2, 1, 0));
        QVERIFY(bake->rotation(1, 1) == glm::quat(0, 0, 1, 0));
    }

    // The OBJ part only supplies names: a broken one costs the names, not the frames.
    void brokenObjPartKeepsFrames() {
        const std::string text = "o Lost\nf 1 2 3\n!\n0 1 2 3\n0 1 2 4\n";
        Result<Bake> bake = readBake(text, "noobj.bake");
        QVERIFY(bake.ok());
        QCOMPARE(bake->frameCount(), size_t(2));
        QCOMPARE(bake->body(0).name, std::string());
        QCOMPARE(bake->sceneObjText(), std::string("o Lost\nf 1 2 3\n"));
        QCOMPARE(bake->position(1, 0).z, 4.0f);
    }

    void badFiles_data() {
        QTest::addColumn<std::string>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        const std::string header = "# rigidlab-bake 2 fps=60 frames=2 bodies=2 columns=id,x,y,z,qw,qx,qy,qz\n!\n";
        QTest::newRow("empty file") << std::string() << 0 << "empty file";
        QTest::newRow("blank file") << std::string(" \r\n\n") << 0 << "empty file";
        QTest::newRow("bad id") << std::string("0 1 2 3\r\nx 1 2 3\r\n") << 2 << "bad id 'x'";
        QTest::newRow("negative id") << std::string("-1 1 2 3\n") << 1 << "bad id '-1'";
        QTest::newRow("id gap") << std::string("0 1 2 3\n2 1 2 3\n") << 2 << "without gaps";
        QTest::newRow("short line") << std::string("0 1 2 3\n1 1 2\n") << 2 << "short line";
        QTest::newRow("non-numeric") << std::string("0 1 abc 3\n") << 1 << "'abc' in column 3";
        QTest::newRow("nan") << std::string("0 nan 0 0\n") << 1 << "not a finite number";
        QTest::newRow("inconsistent frames")
            << std::string("0 0 0 0\n1 0 0 0\n0 0 0 0\n1 0 0 0\n1 0 0 0\n") << 5 << "body 1 has 3 frames, body 0 has 2";
        QTest::newRow("obj part only") << std::string("o Cube\nv 0 0 0\n!\n") << 3 << "no frames";
        QTest::newRow("obj without bang") << std::string("o Cube\nv 0 0 0\n") << 1 << "short line";
        QTest::newRow("newer version") << std::string("# rigidlab-bake 3 fps=60 frames=1 bodies=1\n!\n0 0 0 0\n") << 1
                                       << "newer";
        QTest::newRow("bad fps") << std::string("# rigidlab-bake 2 fps=-1 frames=1 bodies=1\n!\n") << 1 << "bad fps";
        QTest::newRow("bad start") << std::string("# rigidlab-bake 2 fps=60 frames=1 bodies=1 start=x\n!\n") << 1
                                   << "bad start 'x'";
        QTest::newRow("header lacks counts") << std::string("# rigidlab-bake 2 fps=60\n!\n") << 1 << "frames=";
        QTest::newRow("id beyond header") << header + "0 0 0 0 1 0 0 0\n2 0 0 0 1 0 0 0\n" << 4 << "bad id '2'";
        QTest::newRow("header short line") << header + "0 0 0 0 1 0 0\n" << 3 << "short line";
        QTest::newRow("truncated after header") << header << 2 << "truncated";
        QTest::newRow("missing frame") << header + "0 0 0 0 1 0 0 0\n1 0 0 0 1 0 0 0\n0 0 0 0 1 0 0 0\n"
                                       << 5 << "truncated";
        QTest::newRow("no bodies") << std::string("# rigidlab-bake 2 fps=60 frames=2000000000 bodies=0\n!\n") << 1
                                   << "at least one of each";
        QTest::newRow("huge header counts")
            << std::string("# rigidlab-bake 2 fps=60 frames=2000000000 bodies=2000000000\n!\n0 0 0 0 1 0 0 0\n") << 3
            << "truncated";
    }

    void badFiles() {
        QFETCH(std::string, text);
        QFETCH(int, line);
        QFETCH(QString, message);
        Result<Bake> bake = readBake(text, "broken.bake");
        QVERIFY(!bake.ok());
        const std::string s = bake.error().toString();
        QVERIFY2(s.rfind("broken.bake", 0) == 0, s.c_str());
        QVERIFY2(s.find(message.toStdString()) != std::string::npos, s.c_str());
        QCOMPARE(bake.error().line, line);
    }

    // Cutting our file anywhere in its frame lines gives an Error, never a shorter bake.
    void truncatedAnywhereIsAnError() {
        const std::string text = toText(test::makeFixtureBake(10, 60.0));
        const size_t dataStart = text.find("\n!\n") + 3;
        int errors = 0;
        for (size_t cut = dataStart + 1; cut < text.size() - 1; cut += 7) {
            Result<Bake> bake = readBake(std::string_view(text).substr(0, cut), "cut.bake");
            // A cut inside the last number still parses as a line; the missing final line end catches it.
            QVERIFY2(!bake.ok(), qPrintable(QString::number(cut)));
            QVERIFY(bake.error().line > 0);
            ++errors;
        }
        QVERIFY(errors > 100);
    }

    // Frames formatted on several threads are the same bytes as on one (eight blocks of 27 frames), and read back.
    void threadsWriteTheSameBytes_data() {
        QTest::addColumn<int>("threads");
        for (int threads : {2, 3, 8})
            QTest::addRow("%d threads", threads) << threads;
    }
    void threadsWriteTheSameBytes() {
        QFETCH(int, threads);
        const Bake bake = test::makeMovingBake(300, 200);
        std::ostringstream one, many;
        writeBake(bake, one, 1);
        writeBake(bake, many, threads);
        QVERIFY(one.str().size() > 1000);
        QVERIFY(many.str() == one.str());
        QTemporaryDir dir;
        const std::string path = dir.filePath("threads.bake").toStdString();
        QVERIFY(writeBakeFile(bake, path, threads).ok());
        Result<Bake> back = readBakeFile(path);
        QVERIFY(back.ok());
        QCOMPARE(back->frameCount(), size_t(200));
        for (size_t f : {size_t(0), size_t(26), size_t(27), size_t(199)})
            for (size_t b : {size_t(0), size_t(1), size_t(299)}) {
                const glm::vec3 mean(bake.vertexMean(f, b));
                QCOMPARE(glm::vec3(back->vertexMean(f, b)), mean);
                QCOMPARE(back->rotation(f, b), bake.rotation(f, b));
            }
    }

    // 100 frames of 2,000 bodies through the streaming writer and back, well within a test's time budget.
    void largeBakeStreams() {
        const size_t bodies = 2000, frames = 100;
        Bake bake(std::vector<BakeBodyInfo>(bodies), 60.0);
        bake.reserveFrames(frames);
        for (size_t f = 0; f < frames; ++f) {
            bake.addFrame();
            for (size_t b = 0; b < bodies; ++b) {
                BakeBodyState s;
                s.position = glm::vec3(float(b) * 0.1f, 10.0f - 0.01f * float(f), 0.0f);
                bake.setState(f, b, s);
            }
        }
        QTemporaryDir dir;
        const std::string path = dir.filePath("large.bake").toStdString();
        QElapsedTimer timer;
        timer.start();
        QVERIFY(writeBakeFile(bake, path).ok());
        Result<Bake> back = readBakeFile(path);
        const qint64 ms = timer.elapsed();
        QVERIFY(back.ok());
        QCOMPARE(back->frameCount(), frames);
        QVERIFY(back->position(frames - 1, bodies - 1) == bake.position(frames - 1, bodies - 1));
        qInfo("200,000 lines written and read back in %lld ms", ms);
        QVERIFY(ms < 5000);
    }
};

QTEST_APPLESS_MAIN(TestBakeFile)
#include "tst_bakefile.moc"
