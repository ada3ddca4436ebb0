// Bad input through importScene: every broken file gives an Error that names the file (and the line, where there
// is one) and says what is wrong; nothing crashes, throws or returns a half-built scene.
#include "io/SceneImport.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace rl;

class TestBadInputImport : public QObject {
    Q_OBJECT

private slots:
    void badFiles_data();
    void badFiles();
    void overlongLine();
    void directory();
    void goodFilesStillImport_data();
    void goodFilesStillImport();
};

void TestBadInputImport::badFiles_data() {
    QTest::addColumn<QString>("file"); // relative to tests/data/import
    QTest::addColumn<int>("line");     // 0: the problem has no line
    QTest::addColumn<QString>("message");

    // Our OBJ reader.
    QTest::newRow("missing obj") << "obj/missing.obj" << 0 << "file not found";
    QTest::newRow("empty obj") << "obj/empty.obj" << 0 << "file is empty";
    QTest::newRow("binary obj") << "obj/binary.obj" << 0 << "binary file (NUL byte at offset 5)";
    QTest::newRow("truncated obj") << "obj/truncated.obj" << 8 << "face has 2 vertices; it needs at least 3";
    QTest::newRow("index out of range") << "obj/index_out_of_range.obj" << 7 << "face index 17 out of range (1..4)";
    QTest::newRow("index zero") << "obj/index_zero.obj" << 6 << "face index 0 is invalid";
    QTest::newRow("nan vertex") << "obj/nan_vertex.obj" << 3 << "vertex coordinate 'nan' is not a finite number";
    QTest::newRow("inf vertex") << "obj/inf_vertex.obj" << 4 << "vertex coordinate '-inf' is not a finite number";
    QTest::newRow("garbled number") << "obj/garbled_number.obj" << 4 << "bad number '1.0.5' in vertex";
    QTest::newRow("degenerate face") << "obj/degenerate_face.obj" << 5 << "face has 2 vertices";
    QTest::newRow("no faces") << "obj/no_faces.obj" << 0 << "no faces";

    // assimp formats.
    QTest::newRow("missing glb") << "bad/missing.glb" << 0 << "file not found";
    QTest::newRow("empty stl") << "bad/empty.stl" << 0 << "file is empty";
    QTest::newRow("garbage glb") << "bad/garbage.glb" << 0 << "assimp: ";
    QTest::newRow("garbage fbx") << "bad/garbage.fbx" << 0 << "assimp: ";
    QTest::newRow("truncated glb") << "bad/truncated.glb" << 0 << "assimp: ";
    QTest::newRow("truncated stl") << "bad/truncated.stl" << 0 << "assimp: ";
    QTest::newRow("nan ply") << "bad/nan_vertex.ply" << 0 << "vertex is not a finite number";
    QTest::newRow("ply index out of range") << "bad/index_out_of_range.ply" << 0 << "assimp: Validation failed";
    QTest::newRow("gltf without meshes") << "bad/no_meshes.gltf" << 0 << "the file has no meshes";
    QTest::newRow("ply points only") << "bad/points_only.ply" << 0 << "assimp: ";

    // Dispatch.
    QTest::newRow("unknown extension") << "bad/not_a_scene.xyz" << 0 << "unsupported file format '.xyz'";
    QTest::newRow("no extension") << "bad/no_extension" << 0 << "file has no extension";
}

void TestBadInputImport::badFiles() {
    QFETCH(QString, file);
    QFETCH(int, line);
    QFETCH(QString, message);

    const std::string path = (QStringLiteral(RL_TEST_DATA_DIR "/import/") + file).toStdString();
    Result<Scene> scene = importScene(path);
    QVERIFY(!scene.ok());
    const Error& error = scene.error();
    QCOMPARE(QString::fromStdString(error.file), QString::fromStdString(path));
    QCOMPARE(error.line, line);
    QVERIFY2(!error.message.empty(), "an error must say what is wrong");
    QVERIFY2(QString::fromStdString(error.message).startsWith(message), error.toString().c_str());
    // The one-line form a user sees starts with the file (and line).
    const std::string prefix = line > 0 ? path + ":" + std::to_string(line) + ": " : path + ": ";
    QVERIFY2(error.toString().rfind(prefix, 0) == 0, error.toString().c_str());
    qInfo("%s", error.toString().c_str());
}

void TestBadInputImport::overlongLine() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("long.obj");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n# ");
    f.write(QByteArray(int(kObjMaxLineLength), '#'));
    f.write("\nf 1 2 3\n");
    f.close();
    Result<Scene> scene = importScene(path.toStdString());
    QVERIFY(!scene.ok());
    QCOMPARE(scene.error().line, 4);
    QVERIFY2(QString::fromStdString(scene.error().message).startsWith("line is longer than"),
             scene.error().toString().c_str());
}

void TestBadInputImport::directory() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const char* name : {"folder.obj", "folder.glb"}) {
        QVERIFY(QDir(dir.path()).mkdir(name));
        Result<Scene> scene = importScene(dir.filePath(name).toStdString());
        QVERIFY(!scene.ok());
        QVERIFY2(QString::fromStdString(scene.error().message).contains("directory"), scene.error().toString().c_str());
    }
}

void TestBadInputImport::goodFilesStillImport_data() {
    // The same readers accept the well-formed neighbours of the bad files (so the errors above are not blanket).
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("bodies");
    QTest::newRow("obj") << "obj/negative_indices.obj" << 2;
    QTest::newRow("glb") << "blender/scene.glb" << 4;
    QTest::newRow("stl") << "blender/Cube.stl" << 1;
    QTest::newRow("ply") << "blender/Anchor.ply" << 1;
}

void TestBadInputImport::goodFilesStillImport() {
    QFETCH(QString, file);
    QFETCH(int, bodies);
    const std::string path = (QStringLiteral(RL_TEST_DATA_DIR "/import/") + file).toStdString();
    Result<Scene> scene = importScene(path);
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
    QCOMPARE(int(scene->bodies.size()), bodies);
}

QTEST_APPLESS_MAIN(TestBadInputImport)
#include "tst_badinput_import.moc"
