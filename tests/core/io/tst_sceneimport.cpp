// Tests of importScene (bodies, anchors, material presets, source text) and of sceneToObjText (primitives, hulls,
// meshes, placement, and reading its output back with our OBJ reader).
#include "io/ObjReader.h"
#include "io/SceneImport.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <string>

using namespace rl;

namespace {

std::string importFixture(const char* relative) {
    return std::string(RL_TEST_DATA_DIR "/import/") + relative;
}

Real signedVolume(const std::vector<Vec3>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles) {
    Real sixV = 0.0;
    for (const auto& t : triangles)
        sixV += glm::dot(vertices[t[0]], glm::cross(vertices[t[1]], vertices[t[2]]));
    return sixV / 6.0;
}

// Writes the scene as OBJ and reads it back with our reader.
Result<ObjFile> roundTrip(const Scene& scene) {
    Result<std::string> text = sceneToObjText(scene);
    if (!text)
        return text.error();
    return readObj(*text, "written.obj");
}

BodyDef body(const std::string& name, ShapeType type) {
    BodyDef b;
    b.name = name;
    b.shape.type = type;
    return b;
}

} // namespace

class TestSceneImport : public QObject {
    Q_OBJECT

private slots:
    void formats_data();
    void formats();
    void objKeepsSourceText();
    void extensionIsCaseInsensitive();
    void rlsceneGoesToSceneJson();
    void roundTripSampleScenes_data();
    void roundTripSampleScenes();
    void primitives_data();
    void primitives();
    void sphereOutline();
    void meshFromObjReference();
    void writerErrors_data();
    void writerErrors();
    void namesStayOnOneLine();
};

void TestSceneImport::formats_data() {
    QTest::addColumn<QString>("file");
    for (const char* f : {"scene.obj", "scene.glb", "scene.gltf", "scene.fbx", "scene_zup.fbx"})
        QTest::newRow(f) << QString(f);
}

void TestSceneImport::formats() {
    QFETCH(QString, file);
    const std::string path = importFixture("blender/") + file.toStdString();
    Result<Scene> scene = importScene(path);
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
    QCOMPARE(scene->sourcePath, path);
    QCOMPARE(int(scene->bodies.size()), 4);
    const char* names[] = {"Cube", "Box.001", "Prism", "Anchor"};
    // usemtl "wood" matches the Wood preset case-insensitively and is stored in the preset's spelling;
    // "MyPaint" is no preset, so Default.
    const char* materials[] = {"Steel", "Wood", "Default", "Concrete"};
    const int vertexCounts[] = {8, 8, 16, 4};
    for (int i = 0; i < 4; ++i) {
        const BodyDef& b = scene->bodies[i];
        QCOMPARE(QString::fromStdString(b.name), QString(names[i]));
        QCOMPARE(QString::fromStdString(b.material), QString(materials[i]));
        QCOMPARE(b.anchor, i == 3);
        QCOMPARE(b.shape.type, ShapeType::Mesh);
        QCOMPARE(int(b.shape.points.size()), vertexCounts[i]);
        QVERIFY(!b.shape.triangles.empty());
        QCOMPARE(b.position, Vec3(0.0));
        QCOMPARE(b.orientation, identityQuat());
    }
}

void TestSceneImport::objKeepsSourceText() {
    const std::string path = importFixture("obj/crlf_continuation.obj");
    Result<Scene> scene = importScene(path);
    QVERIFY(scene.ok());
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    QVERIFY(!bytes.empty());
    QVERIFY(scene->sourceObjText == bytes); // CRLF and backslashes included

    Result<Scene> glb = importScene(importFixture("blender/scene.glb"));
    QVERIFY(glb.ok());
    QVERIFY(glb->sourceObjText.empty()); // only a scene read from one OBJ file has source OBJ text
}

void TestSceneImport::extensionIsCaseInsensitive() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString copy = dir.filePath("NGON.OBJ");
    QVERIFY(QFile::copy(QString::fromStdString(importFixture("obj/ngon.obj")), copy));
    Result<Scene> scene = importScene(copy.toStdString());
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
    QVERIFY(!scene->sourceObjText.empty()); // read by our OBJ reader, not assimp
    QCOMPARE(QString::fromStdString(scene->bodies.at(0).material), QStringLiteral("Wood"));
}

void TestSceneImport::rlsceneGoesToSceneJson() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("a.RLSCENE");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({ "format": "rigidlab-scene", "version": 1,
  "bodies": [ { "name": "Floor", "anchor": true, "shape": { "box": [20, 0.5, 20] }, "position": [0, -0.5, 0] },
              { "name": "Ball", "shape": { "sphere": 0.5 }, "position": [2, 3, 0] } ] }
)");
    f.close();
    Result<Scene> scene = importScene(path.toStdString());
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
    QCOMPARE(int(scene->bodies.size()), 2);
    QCOMPARE(scene->bodies[0].shape.type, ShapeType::Box);
    QVERIFY(scene->bodies[0].anchor);
    QVERIFY(scene->sourceObjText.empty());
    QVERIFY(!scene->sourcePath.empty());

    // Its errors come back through importScene unchanged, naming the file.
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("{ \"format\": \"rigidlab-scene\", \"version\": 1, \"bodies\": [ { \"nmae\": \"X\" } ] }\n");
    f.close();
    Result<Scene> bad = importScene(path.toStdString());
    QVERIFY(!bad.ok());
    QCOMPARE(bad.error().file, path.toStdString());
    qInfo("%s", bad.error().toString().c_str());

    // A scene that is not from one OBJ file is written as OBJ from its shapes.
    Result<ObjFile> back = roundTrip(*scene);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    QCOMPARE(int(back->objects.size()), 2);
    QVERIFY(glm::length(back->objects[0].vertexMean - Vec3(0.0, -0.5, 0.0)) < 1e-12);
    QVERIFY(glm::length(back->objects[1].vertexMean - Vec3(2.0, 3.0, 0.0)) < 1e-12);
}

void TestSceneImport::roundTripSampleScenes_data() {
    QTest::addColumn<QString>("path");
    for (const char* s : {"stack", "mixed", "pyramid"})
        QTest::newRow(s) << QStringLiteral(RL_SOURCE_DIR "/resources/scenes/%1.obj").arg(s);
    QTest::newRow("fbx z-up") << QString::fromStdString(importFixture("blender/scene_zup.fbx"));
}

void TestSceneImport::roundTripSampleScenes() {
    // Writing a scene as OBJ and reading it back gives the same bodies, bit for bit (shortest round-trip numbers).
    QFETCH(QString, path);
    Result<Scene> scene = importScene(path.toStdString());
    QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
    Result<ObjFile> back = roundTrip(*scene);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    QCOMPARE(back->objects.size(), scene->bodies.size());
    for (size_t i = 0; i < scene->bodies.size(); ++i) {
        const BodyDef& b = scene->bodies[i];
        const ObjObject& o = back->objects[i];
        QCOMPARE(o.name, b.name);
        QCOMPARE(o.material, b.material);
        QVERIFY(o.vertices == b.shape.points);
        QVERIFY(o.triangles == b.shape.triangles);
    }
}

void TestSceneImport::primitives_data() {
    QTest::addColumn<int>("shape");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<double>("volume"); // expected enclosed volume of what is written

    QTest::newRow("box") << int(ShapeType::Box) << 8 << 12 << 8.0 * 0.5 * 1.0 * 1.5;
    // Tetrahedron (volume 1/6) with an interior point that is not a hull vertex.
    QTest::newRow("hull") << int(ShapeType::Hull) << 4 << 4 << 1.0 / 6.0;
    QTest::newRow("mesh") << int(ShapeType::Mesh) << 4 << 4 << 1.0 / 6.0;
}

void TestSceneImport::primitives() {
    QFETCH(int, shape);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    QFETCH(double, volume);

    Scene scene;
    BodyDef b = body("Thing", ShapeType(shape));
    b.shape.halfExtents = Vec3(0.5, 1.0, 1.5);
    const std::vector<Vec3> tetra = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (b.shape.type == ShapeType::Hull) {
        b.shape.points = tetra;
        b.shape.points.push_back({0.1, 0.1, 0.1});
    } else if (b.shape.type == ShapeType::Mesh) {
        b.shape.points = tetra;
        b.shape.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    }
    b.material = "Rubber";
    b.position = Vec3(3.0, -2.0, 0.5);
    b.orientation = glm::angleAxis(0.7, glm::normalize(Vec3(1.0, 2.0, -0.5)));
    scene.bodies.push_back(b);

    // Unplaced, to know where each vertex started.
    Scene unplaced = scene;
    unplaced.bodies[0].position = Vec3(0.0);
    unplaced.bodies[0].orientation = identityQuat();

    Result<ObjFile> placed = roundTrip(scene);
    Result<ObjFile> local = roundTrip(unplaced);
    QVERIFY2(placed.ok(), placed.ok() ? "" : placed.error().toString().c_str());
    QVERIFY(local.ok());
    const ObjObject& p = placed->objects.at(0);
    const ObjObject& l = local->objects.at(0);
    QCOMPARE(QString::fromStdString(p.name), QStringLiteral("Thing"));
    QCOMPARE(QString::fromStdString(p.material), QStringLiteral("Rubber"));
    QCOMPARE(int(p.vertices.size()), vertices);
    QCOMPARE(int(p.triangles.size()), triangles);
    // Outward winding and the right size, before and after placing (a rotation keeps volume).
    QVERIFY2(std::abs(signedVolume(l.vertices, l.triangles) - volume) < 1e-12,
             qPrintable(QString::number(signedVolume(l.vertices, l.triangles))));
    QVERIFY(std::abs(signedVolume(p.vertices, p.triangles) - volume) < 1e-9);
    // Each vertex is placed by position + orientation * local.
    for (size_t i = 0; i < p.vertices.size(); ++i) {
        const Vec3 expected = b.position + b.orientation * l.vertices[i];
        QVERIFY(glm::length(p.vertices[i] - expected) < 1e-12);
    }
    if (b.shape.type == ShapeType::Box)
        QVERIFY(glm::length(p.vertexMean - b.position) < 1e-12); // a box's vertex mean is its centre
}

void TestSceneImport::sphereOutline() {
    Scene scene;
    BodyDef b = body("Ball", ShapeType::Sphere);
    b.shape.radius = 0.5;
    b.position = Vec3(1.0, 2.0, 3.0);
    scene.bodies.push_back(b);
    Result<ObjFile> back = roundTrip(scene);
    QVERIFY(back.ok());
    const ObjObject& o = back->objects.at(0);
    QCOMPARE(int(o.vertices.size()), 162);
    QCOMPARE(int(o.triangles.size()), 320);
    for (const Vec3& v : o.vertices)
        QVERIFY(std::abs(glm::length(v - b.position) - 0.5) < 1e-12);
    QVERIFY(glm::length(o.vertexMean - b.position) < 1e-12);
    std::vector<Vec3> centred;
    for (const Vec3& v : o.vertices)
        centred.push_back(v - b.position);
    const Real ratio = signedVolume(centred, o.triangles) / (4.0 / 3.0 * kPi * 0.125);
    qInfo("icosphere volume / sphere volume = %.4f", ratio);
    QVERIFY(ratio > 0.95 && ratio < 1.0);
}

void TestSceneImport::meshFromObjReference() {
    // A .rlscene body {"obj": "ngon.obj", "object": "Hexagon"} whose mesh has not been loaded yet.
    Scene scene;
    scene.sourcePath = importFixture("obj/parts.rlscene");
    BodyDef b = body("Part", ShapeType::Mesh);
    b.shape.objFile = "ngon.obj";
    b.shape.objObject = "Hexagon";
    b.position = Vec3(0.0, 10.0, 0.0);
    scene.bodies.push_back(b);
    Result<ObjFile> back = roundTrip(scene);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    QCOMPARE(int(back->objects.at(0).vertices.size()), 12);
    QVERIFY(glm::length(back->objects.at(0).vertexMean - Vec3(0.0, 10.5, 0.0)) < 1e-12);

    scene.bodies[0].shape.objObject = "Nope";
    Result<std::string> missing = sceneToObjText(scene);
    QVERIFY(!missing.ok());
    QCOMPARE(QString::fromStdString(missing.error().object), QStringLiteral("Part"));
}

void TestSceneImport::writerErrors_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("message");
    QTest::newRow("collinear hull") << 0 << "hull needs at least 3 points";
    QTest::newRow("nan hull point") << 1 << "hull point is not finite";
    QTest::newRow("mesh index out of range") << 2 << "mesh triangle index 7 out of range (0..3)";
    QTest::newRow("empty mesh") << 3 << "mesh has no vertices";
    QTest::newRow("nan position") << 4 << "position or orientation is not a finite placement";
    QTest::newRow("zero quaternion") << 5 << "position or orientation is not a finite placement";
}

void TestSceneImport::writerErrors() {
    QFETCH(int, kind);
    QFETCH(QString, message);
    Scene scene;
    scene.bodies.push_back(body("Fine", ShapeType::Box));
    BodyDef b = body("Broken", ShapeType::Hull);
    switch (kind) {
    case 0:
        b.shape.points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
        break;
    case 1:
        b.shape.points = {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}, {0, 0, 1}};
        break;
    case 2:
        b.shape.type = ShapeType::Mesh;
        b.shape.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        b.shape.triangles = {{0, 1, 7}};
        break;
    case 3:
        b.shape.type = ShapeType::Mesh;
        break;
    case 4:
        b.shape.type = ShapeType::Box;
        b.position = Vec3(0.0, std::nan(""), 0.0);
        break;
    case 5:
        b.shape.type = ShapeType::Box;
        b.orientation = Quat(0.0, 0.0, 0.0, 0.0);
        break;
    }
    scene.bodies.push_back(b);
    Result<std::string> text = sceneToObjText(scene);
    QVERIFY(!text.ok());
    QCOMPARE(QString::fromStdString(text.error().object), QStringLiteral("Broken"));
    QVERIFY2(QString::fromStdString(text.error().message).startsWith(message), text.error().toString().c_str());
}

void TestSceneImport::namesStayOnOneLine() {
    Scene scene;
    scene.bodies.push_back(body("Two\nLines", ShapeType::Box));
    scene.bodies.push_back(body("", ShapeType::Box));
    scene.bodies[1].material = "";
    Result<ObjFile> back = roundTrip(scene);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    QCOMPARE(int(back->objects.size()), 2);
    QCOMPARE(QString::fromStdString(back->objects[0].name), QStringLiteral("Two_Lines"));
    QCOMPARE(QString::fromStdString(back->objects[1].name), QStringLiteral("Body1"));
    QCOMPARE(QString::fromStdString(back->objects[1].material), QStringLiteral("Default"));
}

QTEST_APPLESS_MAIN(TestSceneImport)
#include "tst_sceneimport.moc"
