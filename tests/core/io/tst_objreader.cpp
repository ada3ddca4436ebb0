// Tests of our OBJ reader: statements, grouping into bodies, triangulation, vertex means, and every error it reports.
#include "io/ObjReader.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <string>

using namespace rl;

namespace {

QString dataPath(const char* relative) {
    return QStringLiteral(RL_TEST_DATA_DIR "/import/") + relative;
}

std::string fixture(const char* relative) {
    return dataPath(relative).toStdString();
}

QStringList namesOf(const ObjFile& file) {
    QStringList names;
    for (const ObjObject& o : file.objects)
        names << QString::fromStdString(o.name);
    return names;
}

QList<int> vertexCountsOf(const ObjFile& file) {
    QList<int> counts;
    for (const ObjObject& o : file.objects)
        counts << int(o.vertices.size());
    return counts;
}

QList<int> triangleCountsOf(const ObjFile& file) {
    QList<int> counts;
    for (const ObjObject& o : file.objects)
        counts << int(o.triangles.size());
    return counts;
}

QStringList materialsOf(const ObjFile& file) {
    QStringList names;
    for (const ObjObject& o : file.objects)
        names << QString::fromStdString(o.material);
    return names;
}

} // namespace

class TestObjReader : public QObject {
    Q_OBJECT

private slots:
    void statements_data();
    void statements();
    void fixtures_data();
    void fixtures();
    void verticesExactlyAsWritten();
    void localIndicesInFirstUseOrder();
    void fanTriangulation();
    void errors_data();
    void errors();
    void errorMessageFormat();
    void longLine();
    void missingFile();
    void blenderExport();
    void largeFileIsFast();
};

void TestObjReader::statements_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("names");
    QTest::addColumn<QList<int>>("vertexCounts");
    QTest::addColumn<QList<int>>("triangleCounts");
    QTest::addColumn<QStringList>("materials");

    const QByteArray tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
    QTest::newRow("no o or g: file stem") << tetra + "f 1 2 3\nf 1 3 4\n"
                                          << QStringList{"case"} << QList<int>{4} << QList<int>{2} << QStringList{""};
    QTest::newRow("quad") << tetra + "f 1 2 3 4\n"
                          << QStringList{"case"} << QList<int>{4} << QList<int>{2} << QStringList{""};
    QTest::newRow("corner forms") << tetra + "vt 0 0\nvn 0 0 1\nf 1/1 2/1/1 3//1\nf 1/1/1 3 4//1\n"
                                  << QStringList{"case"} << QList<int>{4} << QList<int>{2} << QStringList{""};
    QTest::newRow("o blocks") << "o A\n" + tetra + "f 1 2 3\no B.001\nf 2 3 4\nf 1 2 4\n"
                              << QStringList{"A", "B.001"} << QList<int>{3, 4} << QList<int>{1, 2}
                              << QStringList{"", ""};
    QTest::newRow("o wins over g") << "o A\ng x\n" + tetra + "f 1 2 3\ng y\nf 2 3 4\n"
                                   << QStringList{"A"} << QList<int>{4} << QList<int>{2} << QStringList{""};
    QTest::newRow("g groups merge by name")
        << tetra + "g a\nf 1 2 3\ng b\nf 2 3 4\ng a\nf 1 3 4\n"
        << QStringList{"a", "b"} << QList<int>{4, 3} << QList<int>{2, 1} << QStringList{"", ""};
    QTest::newRow("faces before first g")
        << tetra + "f 1 2 3\ng a\nf 2 3 4\n"
        << QStringList{"case", "a"} << QList<int>{3, 3} << QList<int>{1, 1} << QStringList{"", ""};
    QTest::newRow("faceless objects skipped")
        << "o Empty\n" + tetra + "o Full\nf 1 2 3\no Lines\nl 1 2\np 3\n"
        << QStringList{"Full"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("material at first face")
        << "mtllib x.mtl\no A\n" + tetra + "usemtl Steel\nf 1 2 3\nusemtl Wood\nf 1 2 4\no B\nf 2 3 4\n"
        << QStringList{"A", "B"} << QList<int>{4, 3} << QList<int>{2, 1} << QStringList{"Steel", "Wood"};
    QTest::newRow("names keep spaces and dots")
        << "o  Big Anchor.001 \n" + tetra + "f 1 2 3\n"
        << QStringList{"Big Anchor.001"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("crlf tabs comments") << QByteArray("# header\r\n\r\no\tT\r\nv\t0 0 0\r\nv 1\t0 0  # c\r\n"
                                                      "  v 0 1 0\r\n\tf 1 2 3 # tri\r\n")
                                        << QStringList{"T"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("continuation") << QByteArray("o C\nv 0 0 \\\n0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2 \\\n 3\n")
                                  << QStringList{"C"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("w and colours") << QByteArray("v 0 0 0 1\nv 1 0 0 0.2 0.3 0.4\nv 0 1 0 1 1 1 1\nf 1 2 3\n")
                                   << QStringList{"case"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("unknown statements") << tetra + "vp 0.5\ncstype bezier\nfoo bar\ns off\ns 1\nf 1 2 3\n"
                                        << QStringList{"case"} << QList<int>{3} << QList<int>{1} << QStringList{""};
    QTest::newRow("negative indices") << tetra + "f -4 -3 -2\nv 5 5 5\nf -1 -2 -3\n"
                                      << QStringList{"case"} << QList<int>{5} << QList<int>{2} << QStringList{""};
    QTest::newRow("no trailing newline") << tetra + "f 1 2 3" << QStringList{"case"} << QList<int>{3} << QList<int>{1}
                                         << QStringList{""};
}

void TestObjReader::statements() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, names);
    QFETCH(QList<int>, vertexCounts);
    QFETCH(QList<int>, triangleCounts);
    QFETCH(QStringList, materials);

    Result<ObjFile> file = readObj(std::string_view(text.constData(), size_t(text.size())), "dir/case.obj");
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().toString().c_str());
    QCOMPARE(namesOf(*file), names);
    QCOMPARE(vertexCountsOf(*file), vertexCounts);
    QCOMPARE(triangleCountsOf(*file), triangleCounts);
    QCOMPARE(materialsOf(*file), materials);
    for (const ObjObject& o : file->objects)
        for (const auto& t : o.triangles)
            for (uint32_t i : t)
                QVERIFY(i < o.vertices.size());
}

void TestObjReader::fixtures_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QStringList>("names");
    QTest::addColumn<QList<int>>("vertexCounts");
    QTest::addColumn<QList<int>>("triangleCounts");
    QTest::addColumn<QStringList>("materials");
    QTest::addColumn<QList<double>>("meanXyz"); // vertex mean of each object, flattened

    QTest::newRow("groups_only") << dataPath("obj/groups_only.obj") << QStringList{"Left", "Anchor.002"}
                                 << QList<int>{4, 4} << QList<int>{3, 3} << QStringList{"", "steel"}
                                 << QList<double>{0.25, 0.25, 0.25, 5.25, 0.25, 0.25};
    QTest::newRow("no_groups") << dataPath("obj/no_groups.obj") << QStringList{"no_groups"} << QList<int>{8}
                               << QList<int>{12} << QStringList{"Rubber"} << QList<double>{0, 0, 0};
    QTest::newRow("ngon") << dataPath("obj/ngon.obj") << QStringList{"Hexagon"} << QList<int>{12}
                          << QList<int>{4 + 4 + 6 * 2} << QStringList{"WOOD"} << QList<double>{0, 0.5, 0};
    QTest::newRow("negative_indices") << dataPath("obj/negative_indices.obj") << QStringList{"First", "Second"}
                                      << QList<int>{4, 4} << QList<int>{4, 4} << QStringList{"", ""}
                                      << QList<double>{0.5, 0.5, 0.5, 10.5, 0.5, 0.5};
    QTest::newRow("crlf_continuation") << dataPath("obj/crlf_continuation.obj") << QStringList{"Tetra"} << QList<int>{4}
                                       << QList<int>{4} << QStringList{"Ice"} << QList<double>{0.25, 0.25, 0.25};
}

void TestObjReader::fixtures() {
    QFETCH(QString, path);
    QFETCH(QStringList, names);
    QFETCH(QList<int>, vertexCounts);
    QFETCH(QList<int>, triangleCounts);
    QFETCH(QStringList, materials);
    QFETCH(QList<double>, meanXyz);

    std::string text;
    Result<ObjFile> file = readObjFile(path.toStdString(), &text);
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().toString().c_str());
    QCOMPARE(namesOf(*file), names);
    QCOMPARE(vertexCountsOf(*file), vertexCounts);
    QCOMPARE(triangleCountsOf(*file), triangleCounts);
    QCOMPARE(materialsOf(*file), materials);
    QCOMPARE(int(file->objects.size() * 3), int(meanXyz.size()));
    for (size_t i = 0; i < file->objects.size(); ++i)
        for (int k = 0; k < 3; ++k)
            QVERIFY(std::abs(file->objects[i].vertexMean[k] - meanXyz[int(i) * 3 + k]) < 1e-12);
    // The verbatim text is handed back byte for byte (it goes into .bake files).
    std::ifstream in(path.toStdString(), std::ios::binary);
    std::string expected((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    QVERIFY(text == expected);
}

void TestObjReader::verticesExactlyAsWritten() {
    // Parsing must round-trip the decimal text exactly: no float detour, no welding, no re-centring.
    const std::string text = "o P\nv 0.1 -2.5e-3 +7\nv 1e-300 123456789.123456789 -0\nv 0.1 -2.5e-3 7\nf 1 2 3\n";
    Result<ObjFile> file = readObj(text, "p.obj");
    QVERIFY(file.ok());
    const ObjObject& o = file->objects.at(0);
    QCOMPARE(int(o.vertices.size()), 3); // the repeated position is a distinct `v` and stays
    QCOMPARE(o.vertices[0].x, 0.1);
    QCOMPARE(o.vertices[0].y, -2.5e-3);
    QCOMPARE(o.vertices[0].z, 7.0);
    QCOMPARE(o.vertices[1].x, 1e-300);
    QCOMPARE(o.vertices[1].y, 123456789.123456789);
    QCOMPARE(o.vertexMean.x, (0.1 + 1e-300 + 0.1) / 3.0);
}

void TestObjReader::localIndicesInFirstUseOrder() {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\no A\nf 5 3 1\nf 1 3 4\n";
    Result<ObjFile> file = readObj(text, "a.obj");
    QVERIFY(file.ok());
    const ObjObject& o = file->objects.at(0);
    QCOMPARE(o.fileVertexIndices, (std::vector<uint32_t>{4, 2, 0, 3}));
    QCOMPARE(o.vertices[0].x, 4.0);
    QCOMPARE(o.vertices[3].x, 3.0);
    QCOMPARE(o.triangles.size(), size_t(2));
    QVERIFY((o.triangles[0] == std::array<uint32_t, 3>{0, 1, 2}));
    QVERIFY((o.triangles[1] == std::array<uint32_t, 3>{2, 1, 3}));
    QCOMPARE(o.vertexMean.x, (4.0 + 2.0 + 0.0 + 3.0) / 4.0); // vertex 2 (x = 1) is not used by A
    QCOMPARE(o.firstLine, 6);
}

void TestObjReader::fanTriangulation() {
    // A convex heptagon: the fan from the first corner covers its area exactly once.
    std::string text;
    const int n = 7;
    for (int i = 0; i < n; ++i)
        text +=
            "v " + std::to_string(std::cos(2 * kPi * i / n)) + " 0 " + std::to_string(std::sin(2 * kPi * i / n)) + "\n";
    text += "f 1 2 3 4 5 6 7\n";
    Result<ObjFile> file = readObj(text, "h.obj");
    QVERIFY(file.ok());
    const ObjObject& o = file->objects.at(0);
    QCOMPARE(int(o.triangles.size()), n - 2);
    Real area = 0.0;
    for (const auto& t : o.triangles) {
        QCOMPARE(t[0], 0u);
        area += 0.5 * glm::length(glm::cross(o.vertices[t[1]] - o.vertices[t[0]], o.vertices[t[2]] - o.vertices[t[0]]));
    }
    const Real expected = 0.5 * n * std::sin(2 * kPi / n); // regular polygon of unit circumradius
    QVERIFY2(std::abs(area - expected) < 1e-5, qPrintable(QString::number(area)));
}

void TestObjReader::errors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");

    const QByteArray tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    QTest::newRow("empty") << QByteArray() << 0 << "file is empty";
    QTest::newRow("whitespace only") << QByteArray(" \n\t\r\n\n") << 0 << "file is empty";
    QTest::newRow("NUL byte") << QByteArray("v 0 0 0\n\0\n", 10) << 0 << "binary file (NUL byte at offset 8)";
    QByteArray noise;
    for (int i = 0; i < 400; ++i)
        noise.append(char(1 + (i * 7) % 31)); // control bytes, no NUL
    QTest::newRow("mostly non-text") << noise << 0 << "binary file (";
    QByteArray latin;
    for (int i = 0; i < 400; ++i)
        latin.append(char(0xC0 + (i % 7) * 9 + 0x1)); // lone lead bytes: invalid UTF-8
    QTest::newRow("invalid utf-8") << latin << 0 << "binary file (";
    QTest::newRow("no faces") << tri + "l 1 2\n" << 0 << "no faces";
    QTest::newRow("comments only") << QByteArray("# nothing\n# here\n") << 0 << "no faces";
    QTest::newRow("garbled number") << QByteArray("v 0 0 0\nv 1 0x1 0\n") << 2 << "bad number '0x1' in vertex";
    QTest::newRow("truncated exponent") << QByteArray("v 0 0 1e") << 1 << "bad number '1e' in vertex";
    QTest::newRow("two coordinates") << QByteArray("v 0 0 0\nv 1 0\n") << 2 << "vertex has 2 coordinates";
    QTest::newRow("no coordinates") << QByteArray("v\n") << 1 << "vertex has 0 coordinates";
    QTest::newRow("nan") << QByteArray("v 0 NaN 0\n") << 1 << "vertex coordinate 'NaN' is not a finite number";
    QTest::newRow("inf") << QByteArray("v 0 0 -inf\n") << 1 << "vertex coordinate '-inf' is not a finite number";
    QTest::newRow("overflow") << QByteArray("v 1e999 0 0\n") << 1 << "vertex coordinate '1e999' is not a finite";
    QTest::newRow("out of range") << tri + "f 1 2 4\n" << 4 << "face index 4 out of range (1..3)";
    QTest::newRow("forward reference") << QByteArray("f 1 2 3\nv 0 0 0\n") << 1
                                       << "face index 1 out of range (no vertex defined yet)";
    QTest::newRow("zero") << tri + "f 0 1 2\n" << 4 << "face index 0 is invalid";
    QTest::newRow("negative out of range") << tri + "f -1 -2 -4\n" << 4 << "face index -4 out of range (1..3)";
    QTest::newRow("huge index") << tri + "f 1 2 99999999999999999999\n" << 4 << "face index '99999999999999999999'";
    QTest::newRow("two vertices") << tri + "f 1 2\n" << 4 << "face has 2 vertices; it needs at least 3";
    QTest::newRow("one vertex") << tri + "f 1\n" << 4 << "face has 1 vertex; it needs at least 3";
    QTest::newRow("bad corner") << tri + "f 1 2/x 3\n" << 4 << "bad face vertex '2/x'";
    QTest::newRow("too many slashes") << tri + "f 1 2/1/1/1 3\n" << 4 << "bad face vertex '2/1/1/1'";
    QTest::newRow("empty corner") << tri + "f 1 /1 3\n" << 4 << "bad face vertex '/1'";
    QTest::newRow("continued error line") << QByteArray("v 0 0 0\nv 1 \\\n0 \\\nzz\n") << 2 << "bad number 'zz'";
    QTest::newRow("line after continuation") << QByteArray("v 0 0 \\\n0\nv 1 0\n") << 3 << "vertex has 2";
}

void TestObjReader::errors() {
    QFETCH(QByteArray, text);
    QFETCH(int, line);
    QFETCH(QString, message);

    Result<ObjFile> file = readObj(std::string_view(text.constData(), size_t(text.size())), "bad.obj");
    QVERIFY(!file.ok());
    QCOMPARE(QString::fromStdString(file.error().file), QStringLiteral("bad.obj"));
    QCOMPARE(file.error().line, line);
    QVERIFY2(QString::fromStdString(file.error().message).startsWith(message), file.error().toString().c_str());
}

void TestObjReader::errorMessageFormat() {
    std::string text;
    for (int i = 0; i < 12; ++i)
        text += "v " + std::to_string(i) + " 0 0\n";
    for (int line = 13; line < 42; ++line)
        text += "# filler\n";
    text += "f 1 2 17\n";
    Result<ObjFile> file = readObj(text, "scene.obj");
    QVERIFY(!file.ok());
    QCOMPARE(QString::fromStdString(file.error().toString()),
             QStringLiteral("scene.obj:42: face index 17 out of range (1..12)"));
}

void TestObjReader::longLine() {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\no ";
    text += std::string(kObjMaxLineLength + 10, 'x');
    text += "\nf 1 2 3\n";
    Result<ObjFile> file = readObj(text, "long.obj");
    QVERIFY(!file.ok());
    QCOMPARE(file.error().line, 4);
    QVERIFY(QString::fromStdString(file.error().message).startsWith("line is longer than"));
    // The error message does not echo the long line.
    QVERIFY(file.error().toString().size() < 200);

    // The same limit holds for a line built from many short continued pieces.
    std::string continued = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3";
    for (size_t i = 0; i < kObjMaxLineLength / 4; ++i)
        continued += " 1 \\\n";
    continued += "2\n";
    file = readObj(continued, "long.obj");
    QVERIFY(!file.ok());
    QCOMPARE(file.error().line, 4);

    // Just under the limit is fine: an N-gon with thousands of corners is legal.
    std::string big = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    while (big.size() < kObjMaxLineLength)
        big += " 1 2 3";
    big += "\n";
    file = readObj(big, "big.obj");
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().toString().c_str());
}

void TestObjReader::missingFile() {
    const std::string path = fixture("obj/does_not_exist.obj");
    Result<ObjFile> file = readObjFile(path);
    QVERIFY(!file.ok());
    QCOMPARE(file.error().file, path);
    QCOMPARE(QString::fromStdString(file.error().message), QStringLiteral("file not found"));

    Result<ObjFile> dir = readObjFile(fixture("obj"));
    QVERIFY(!dir.ok());
    QVERIFY(QString::fromStdString(dir.error().message).contains("directory"));
}

void TestObjReader::blenderExport() {
    // Blender 3.4's OBJ exporter: o blocks, usemtl, s off, v/vt/vn corners, quads and octagon N-gons.
    Result<ObjFile> file = readObjFile(fixture("blender/scene.obj"));
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().toString().c_str());
    QCOMPARE(namesOf(*file), (QStringList{"Cube", "Box.001", "Prism", "Anchor"}));
    QCOMPARE(vertexCountsOf(*file), (QList<int>{8, 8, 16, 4}));
    QCOMPARE(triangleCountsOf(*file), (QList<int>{12, 12, 8 * 2 + 2 * 6, 2}));
    QCOMPARE(materialsOf(*file), (QStringList{"Steel", "wood", "MyPaint", "Concrete"}));
    // Blender's cube of size 2 at z = 1 (Z-up) is exported Y-up: its mean is (0, 1, 0).
    const Vec3 cubeMean = file->objects[0].vertexMean;
    QVERIFY(glm::length(cubeMean - Vec3(0.0, 1.0, 0.0)) < 1e-12);
}

void TestObjReader::largeFileIsFast() {
    // A 300 x 300 quad grid: 90,601 vertices and 180,000 triangles.
    const int n = 300;
    std::string text = "o Grid\n";
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            text += "v " + std::to_string(i * 0.01) + " 0 " + std::to_string(j * 0.01) + "\n";
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * (n + 1) + j + 1;
            text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 2) + " " +
                    std::to_string(a + n + 1) + "\n";
        }
    QElapsedTimer timer;
    timer.start();
    Result<ObjFile> file = readObj(text, "grid.obj");
    const qint64 ms = timer.elapsed();
    QVERIFY(file.ok());
    QCOMPARE(int(file->objects.at(0).vertices.size()), (n + 1) * (n + 1));
    QCOMPARE(int(file->objects.at(0).triangles.size()), 2 * n * n);
    qInfo("parsed %zu bytes in %lld ms", text.size(), ms);
    QVERIFY2(ms < 1500, qPrintable(QString::number(ms)));
}

QTEST_APPLESS_MAIN(TestObjReader)
#include "tst_objreader.moc"
