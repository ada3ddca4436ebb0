// Tests of the assimp import path: Blender's glTF, GLB, FBX (Y-up and Z-up), PLY and STL exports of one scene must
// give the bodies of Blender's OBJ export of it, and assimp's OBJ reader must agree with ours on the sample scenes.
#include "io/AssimpImporter.h"
#include "io/ObjReader.h"
#include "scene/BodyDef.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <string>

using namespace rl;

namespace {

std::string blenderFixture(const QString& name) {
    return (QStringLiteral(RL_TEST_DATA_DIR "/import/blender/") + name).toStdString();
}

// Signed volume of a closed triangle mesh by the divergence theorem: positive when the triangles face outward.
Real signedVolume(const ObjObject& o) {
    Real sixV = 0.0;
    for (const auto& t : o.triangles)
        sixV += glm::dot(o.vertices[t[0]], glm::cross(o.vertices[t[1]], o.vertices[t[2]]));
    return sixV / 6.0;
}

const ObjObject* findObject(const ObjFile& file, const std::string& name) {
    for (const ObjObject& o : file.objects)
        if (o.name == name)
            return &o;
    return nullptr;
}

// Blender's OBJ export of the fixture scene is the reference every other format is compared with.
const ObjFile& reference() {
    static const ObjFile file = *readObjFile(blenderFixture("scene.obj"));
    return file;
}

} // namespace

class TestAssimpImport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void sceneFormats_data();
    void sceneFormats();
    void colladaUnit();
    void perObjectFormats_data();
    void perObjectFormats();
    void assimpObjMatchesOurReader_data();
    void assimpObjMatchesOurReader();
    void extensions_data();
    void extensions();
};

void TestAssimpImport::initTestCase() {
    Result<ObjFile> file = readObjFile(blenderFixture("scene.obj"));
    QVERIFY2(file.ok(), file.ok() ? "" : file.error().toString().c_str());
    QCOMPARE(int(file->objects.size()), 4);
}

void TestAssimpImport::sceneFormats_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("objOrder"); // the file lists the objects in the order of Blender's OBJ export
    QTest::newRow("glb") << "scene.glb" << true;
    QTest::newRow("gltf") << "scene.gltf" << true;
    QTest::newRow("fbx") << "scene.fbx" << true;
    QTest::newRow("fbx z-up") << "scene_zup.fbx" << true;
    QTest::newRow("dae z-up") << "scene.dae" << false; // Blender's COLLADA writer lists them in reverse
    QTest::newRow("obj via assimp") << "scene.obj" << true;
}

void TestAssimpImport::sceneFormats() {
    QFETCH(QString, file);
    QFETCH(bool, objOrder);
    Result<ObjFile> imported = importWithAssimp(blenderFixture(file));
    QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error().toString().c_str());
    const ObjFile& ref = reference();

    // These formats keep object names; bodies come in the file's own order.
    QCOMPARE(int(imported->objects.size()), int(ref.objects.size()));
    for (size_t i = 0; i < ref.objects.size(); ++i) {
        const ObjObject& expected = ref.objects[i];
        const ObjObject* found = objOrder ? &imported->objects[i] : findObject(*imported, expected.name);
        QVERIFY2(found, expected.name.c_str());
        const ObjObject& got = *found;
        QCOMPARE(QString::fromStdString(got.name), QString::fromStdString(expected.name));
        QCOMPARE(QString::fromStdString(got.material), QString::fromStdString(expected.material));
        QCOMPARE(int(got.vertices.size()), int(expected.vertices.size()));
        // N-gon caps are triangulated; every format ends with the same number of triangles.
        QCOMPARE(int(got.triangles.size()), int(expected.triangles.size()));
        const Real meanError = glm::length(got.vertexMean - expected.vertexMean);
        QVERIFY2(meanError < 1e-5,
                 qPrintable(QStringLiteral("%1: mean off by %2").arg(got.name.c_str()).arg(meanError)));
        // Every reference vertex is found in the import (same world placement, unit and axes), within the
        // rounding of Blender's six-decimal OBJ text and of float storage.
        for (const Vec3& v : expected.vertices) {
            Real nearest = 1e30;
            for (const Vec3& w : got.vertices)
                nearest = std::min(nearest, glm::length(v - w));
            QVERIFY2(nearest < 1e-5,
                     qPrintable(QStringLiteral("%1: vertex off by %2").arg(got.name.c_str()).arg(nearest)));
        }
        // Closed bodies keep outward winding; their volume matches the reference's.
        if (expected.name != "Anchor") {
            const Real v = signedVolume(got);
            QVERIFY2(v > 0 && std::abs(v - signedVolume(expected)) < 1e-4, qPrintable(QString::number(v)));
        }
    }
}

void TestAssimpImport::colladaUnit() {
    // The same COLLADA file declared in centimetres: every vertex, and so every mean, is 0.01 of the metre file's.
    QFile in(QString::fromStdString(blenderFixture("scene.dae")));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    QVERIFY(text.contains("meter=\"1\""));
    text.replace("meter=\"1\"", "meter=\"0.01\"");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile out(dir.filePath("scene_cm.dae"));
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    Result<ObjFile> metres = importWithAssimp(blenderFixture("scene.dae"));
    Result<ObjFile> centimetres = importWithAssimp(out.fileName().toStdString());
    QVERIFY(metres.ok() && centimetres.ok());
    QCOMPARE(centimetres->objects.size(), metres->objects.size());
    for (size_t i = 0; i < metres->objects.size(); ++i)
        QVERIFY(glm::length(centimetres->objects[i].vertexMean - 0.01 * metres->objects[i].vertexMean) < 1e-7);
}

void TestAssimpImport::perObjectFormats_data() {
    QTest::addColumn<QString>("extension");
    QTest::addColumn<QString>("object");
    for (const char* ext : {"ply", "stl"})
        for (const char* name : {"Cube", "Box.001", "Prism", "Anchor"})
            QTest::addRow("%s %s", ext, name) << QString(ext) << QString(name);
}

void TestAssimpImport::perObjectFormats() {
    // PLY and STL hold one unnamed mesh: Blender wrote one file per object, and the body takes the file's name.
    QFETCH(QString, extension);
    QFETCH(QString, object);
    Result<ObjFile> imported = importWithAssimp(blenderFixture(object + "." + extension));
    QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error().toString().c_str());
    QCOMPARE(int(imported->objects.size()), 1);
    const ObjObject& got = imported->objects[0];
    const ObjObject* expected = findObject(reference(), object.toStdString());
    QVERIFY(expected);
    QCOMPARE(QString::fromStdString(got.name), object);
    QCOMPARE(isAnchorName(got.name), object == "Anchor");
    QCOMPARE(int(got.vertices.size()), int(expected->vertices.size()));
    QCOMPARE(int(got.triangles.size()), int(expected->triangles.size()));
    const Real meanError = glm::length(got.vertexMean - expected->vertexMean);
    QVERIFY2(meanError < 1e-5, qPrintable(QString::number(meanError)));
    if (object != "Anchor")
        QVERIFY2(std::abs(signedVolume(got) - signedVolume(*expected)) < 1e-4,
                 qPrintable(QString::number(signedVolume(got))));
}

void TestAssimpImport::assimpObjMatchesOurReader_data() {
    QTest::addColumn<QString>("path");
    for (const char* scene : {"stack", "pyramid", "mixed", "ramps"})
        QTest::newRow(scene) << QStringLiteral(RL_SOURCE_DIR "/resources/scenes/%1.obj").arg(scene);
    QTest::newRow("ngon") << QStringLiteral(RL_TEST_DATA_DIR "/import/obj/ngon.obj");
    QTest::newRow("negative indices") << QStringLiteral(RL_TEST_DATA_DIR "/import/obj/negative_indices.obj");
}

void TestAssimpImport::assimpObjMatchesOurReader() {
    QFETCH(QString, path);
    Result<ObjFile> ours = readObjFile(path.toStdString());
    QVERIFY2(ours.ok(), ours.ok() ? "" : ours.error().toString().c_str());
    Result<ObjFile> theirs = importWithAssimp(path.toStdString());
    QVERIFY2(theirs.ok(), theirs.ok() ? "" : theirs.error().toString().c_str());
    QCOMPARE(int(theirs->objects.size()), int(ours->objects.size()));
    Real worst = 0.0;
    for (size_t i = 0; i < ours->objects.size(); ++i) {
        const ObjObject& a = ours->objects[i];
        const ObjObject& b = theirs->objects[i];
        QCOMPARE(QString::fromStdString(b.name), QString::fromStdString(a.name));
        QCOMPARE(int(b.vertices.size()), int(a.vertices.size()));
        QCOMPARE(int(b.triangles.size()), int(a.triangles.size()));
        QCOMPARE(isAnchorName(b.name), isAnchorName(a.name));
        worst = std::max(worst, glm::length(b.vertexMean - a.vertexMean));
    }
    qInfo("%zu bodies, largest vertex-mean difference %.3g m", ours->objects.size(), worst);
    QVERIFY(worst < 1e-5);
}

void TestAssimpImport::extensions_data() {
    QTest::addColumn<QString>("extension");
    QTest::addColumn<bool>("readable");
    for (const char* ext : {"glb", ".gltf", "FBX", "ply", "stl", "dae", "3ds", "obj"})
        QTest::newRow(ext) << QString(ext) << true;
    for (const char* ext : {"", "rlscene", "bake", "txt"})
        QTest::newRow(*ext ? ext : "empty") << QString(ext) << false;
}

void TestAssimpImport::extensions() {
    QFETCH(QString, extension);
    QFETCH(bool, readable);
    QCOMPARE(assimpReadsExtension(extension.toStdString()), readable);
}

QTEST_APPLESS_MAIN(TestAssimpImport)
#include "tst_assimpimport.moc"
