// Tests of io/SceneJson: the DESIGN.md §6 example, exact round trips of random scenes, OBJ-backed and mesh bodies,
// and an error that names the file, line, body and key for every kind of bad input.
#include "io/AtomicFile.h"
#include "io/SceneJson.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

using namespace rl;

Q_DECLARE_METATYPE(std::string)

namespace {

const std::string kExample = RL_TEST_DATA_DIR "/formats/design_example.rlscene";

// Values spread over many magnitudes with full 53-bit mantissas, so that any rounding in the text would show.
class RandomScene {
public:
    explicit RandomScene(uint64_t seed) : m_rng(seed) {}

    double any() { return std::ldexp(unit() * 2.0 - 1.0, exponent()); }
    double positive() { return std::ldexp(0.5 + unit(), exponent()); }
    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(m_rng); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_rng); }
    bool coin() { return integer(0, 1) == 1; }
    Vec3 vec() { return Vec3(any(), any(), any()); }

    Scene make() {
        Scene s;
        s.sourcePath = "random.rlscene";
        s.world.gravity = vec();
        s.world.fps = positive();
        s.world.substeps = integer(1, 64);
        s.world.iterations = integer(1, 50);
        s.world.integrator = static_cast<Integrator>(integer(0, 3));
        for (int e = 0; e < kEffectCount; ++e)
            s.world.effects.modes[e] = static_cast<EffectMode>(integer(0, 2));
        s.world.linearDamping = positive();
        s.world.angularDamping = positive();
        s.world.frictionCombine = static_cast<CombineRule>(integer(0, 4));
        s.world.restitutionCombine = static_cast<CombineRule>(integer(0, 4));
        const int materials = integer(0, 3);
        for (int m = 0; m < materials; ++m)
            s.materials.push_back(MaterialDef{"Mat" + std::to_string(m), positive(), positive(), unit()});
        const int bodies = integer(1, 12);
        for (int i = 0; i < bodies; ++i)
            s.bodies.push_back(body(i, s));
        return s;
    }

private:
    int exponent() { return integer(-30, 30); }

    BodyDef body(int i, const Scene& s) {
        BodyDef b;
        b.name = "Body \"" + std::to_string(i) + "\"\t\xC3\xA9";
        b.anchor = coin();
        if (!s.materials.empty() && coin())
            b.material = s.materials[size_t(integer(0, int(s.materials.size()) - 1))].name;
        else if (coin())
            b.material = "Rubber";
        if (coin())
            b.density = positive();
        if (coin())
            b.mass = positive();
        if (coin())
            b.friction = positive();
        if (coin())
            b.restitution = unit();
        b.position = vec();
        b.orientation = glm::normalize(Quat(any(), any(), any(), any()));
        if (coin())
            b.velocity = vec();
        if (coin())
            b.angularVelocity = vec();
        switch (integer(0, 3)) {
        case 0:
            b.shape.type = ShapeType::Box;
            b.shape.halfExtents = Vec3(positive(), positive(), positive());
            break;
        case 1:
            b.shape.type = ShapeType::Sphere;
            b.shape.radius = positive();
            break;
        case 2:
            b.shape.type = ShapeType::Hull;
            for (int p = integer(3, 20); p > 0; --p)
                b.shape.points.push_back(vec());
            break;
        default:
            b.shape.type = ShapeType::Mesh;
            for (int p = integer(3, 20); p > 0; --p)
                b.shape.points.push_back(vec());
            for (int t = integer(1, 20); t > 0; --t) {
                const auto n = static_cast<int>(b.shape.points.size()) - 1;
                b.shape.triangles.push_back(
                    {uint32_t(integer(0, n)), uint32_t(integer(0, n)), uint32_t(integer(0, n))});
            }
        }
        return b;
    }

    std::mt19937_64 m_rng;
};

// A scene whose bodies are the given JSON lines, one per line from line 3 on.
std::string withBodies(const std::vector<std::string>& bodies) {
    std::string text = "{\"format\": \"rigidlab-scene\", \"version\": 1,\n\"bodies\": [\n";
    for (size_t i = 0; i < bodies.size(); ++i)
        text += bodies[i] + (i + 1 < bodies.size() ? ",\n" : "\n");
    return text + "]}\n";
}

// A scene whose world section is on line 2.
std::string withWorld(const std::string& world) {
    return "{\"format\": \"rigidlab-scene\", \"version\": 1,\n\"world\": " + world + "\n}\n";
}

const std::string kBox = "\"shape\": {\"box\": [1, 1, 1]}";

} // namespace

class TestSceneJson : public QObject {
    Q_OBJECT

private slots:
    void readsDesignExample() {
        Result<Scene> scene = readSceneFile(kExample);
        QVERIFY2(scene.ok(), scene.ok() ? "" : scene.error().toString().c_str());
        const Scene& s = *scene;
        QCOMPARE(s.sourcePath, kExample);
        QCOMPARE(s.world.fps, 60.0);
        QCOMPARE(s.world.substeps, 4);
        QVERIFY(s.world.gravity == Vec3(0, -9.81, 0));
        QVERIFY(s.world.integrator == Integrator::SymplecticEuler);
        QCOMPARE(s.materials.size(), size_t(1));
        QVERIFY(s.materials[0] == (MaterialDef{"Bouncy", 500, 0.2, 0.9}));
        QCOMPARE(s.bodies.size(), size_t(5));

        QVERIFY(s.bodies[0].anchor);
        QVERIFY(s.bodies[0].shape.halfExtents == Vec3(20, 0.5, 20));
        QVERIFY(s.bodies[0].position == Vec3(0, -0.5, 0));
        QCOMPARE(s.bodies[1].material, std::string("Steel"));
        QVERIFY(s.bodies[1].velocity == Vec3(300, 0, 0));
        QVERIFY(!s.bodies[1].anchor);
        QVERIFY(s.bodies[2].shape.type == ShapeType::Sphere);
        QCOMPARE(s.bodies[2].shape.radius, 0.5);
        QCOMPARE(s.bodies[2].friction.value_or(-1), 0.3);
        QVERIFY(!s.bodies[2].density);
        QVERIFY(s.bodies[3].shape.type == ShapeType::Hull);
        QCOMPARE(s.bodies[3].shape.points.size(), size_t(4));

        // The OBJ object is loaded from parts.obj next to the scene.
        const ShapeDef& part = s.bodies[4].shape;
        QVERIFY(part.type == ShapeType::Mesh);
        QCOMPARE(part.objFile, std::string("parts.obj"));
        QCOMPARE(part.objObject, std::string("Cube.001"));
        QCOMPARE(part.points.size(), size_t(8));
        QCOMPARE(part.triangles.size(), size_t(12));
        Vec3 mean(0.0);
        for (const Vec3& p : part.points)
            mean += p / 8.0;
        QVERIFY(glm::length(mean - Vec3(0, 0.5, 0)) < 1e-12);
    }

    void exampleRoundTrips() {
        Result<Scene> scene = readSceneFile(kExample);
        QVERIFY(scene.ok());
        const std::string text = writeSceneJson(*scene);
        QVERIFY(text.find("\"obj\": \"parts.obj\"") != std::string::npos); // a reference, not the vertices
        Result<Scene> back = readSceneJson(text, kExample);
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
        QVERIFY(*back == *scene);
    }

    void randomScenesRoundTripExactly() {
        int bodies = 0;
        for (uint64_t seed = 1; seed <= 200; ++seed) {
            const Scene scene = RandomScene(seed).make();
            const std::string text = writeSceneJson(scene);
            Result<Scene> back = readSceneJson(text, scene.sourcePath);
            QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
            QVERIFY2(*back == scene, qPrintable(QString("seed %1").arg(seed)));
            QCOMPARE(writeSceneJson(*back), text);
            bodies += int(scene.bodies.size());
        }
        QVERIFY(bodies > 1000);
    }

    // A mesh from an OBJ import (no file named) is written out in full so that nothing is lost.
    void importedMeshIsWrittenInFull() {
        Scene scene;
        BodyDef b;
        b.name = "Imported";
        b.shape.type = ShapeType::Mesh;
        b.shape.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        b.shape.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        scene.bodies.push_back(b);
        const std::string text = writeSceneJson(scene);
        QVERIFY(text.find("\"mesh\": {") != std::string::npos);
        QVERIFY(text.find("\"triangles\"") != std::string::npos);
        Result<Scene> back = readSceneJson(text, "");
        QVERIFY(back.ok());
        QVERIFY(*back == scene);
    }

    void fileRoundTripAndAtomicity() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("s.rlscene").toStdString();
        const Scene scene = RandomScene(99).make();
        QVERIFY(writeSceneFile(scene, path).ok());
        Result<Scene> back = readSceneFile(path);
        QVERIFY(back.ok());
        Scene expected = scene;
        expected.sourcePath = path;
        QVERIFY(*back == expected);

        // A NaN cannot be written as JSON: an Error naming the body, and the old file stays.
        Scene broken = scene;
        broken.bodies[0].position.y = std::nan("");
        Status s = writeSceneFile(broken, path);
        QVERIFY(!s.ok());
        QVERIFY2(s.error().toString().find("(index 0)") != std::string::npos, s.error().toString().c_str());
        QVERIFY2(s.error().toString().find("position[1]") != std::string::npos, s.error().toString().c_str());
        QVERIFY(readSceneFile(path).ok());
        QVERIFY(*readSceneFile(path) == expected);
    }

    void badScenes_data() {
        QTest::addColumn<std::string>("text");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("message");
        QTest::newRow("syntax error") << std::string("{\"format\": \"rigidlab-scene\"\n \"version\": 1}") << 2
                                      << "expected ',' or '}'";
        QTest::newRow("empty file") << std::string() << 1 << "unexpected end of file";
        QTest::newRow("not an object") << std::string("[1, 2]") << 1 << "must be a JSON object";
        QTest::newRow("wrong format") << std::string("{\"format\": \"other\", \"version\": 1}") << 1
                                      << "not a RigidLab scene";
        QTest::newRow("missing version") << std::string("{\"format\": \"rigidlab-scene\"}") << 1
                                         << "missing key 'version'";
        QTest::newRow("newer version") << std::string("{\"format\": \"rigidlab-scene\",\n\"version\": 2}") << 2
                                       << "newer RigidLab";
        QTest::newRow("unknown top-level key")
            << std::string("{\"format\": \"rigidlab-scene\", \"version\": 1,\n\"bodys\": []}") << 2
            << "unknown key 'bodys'";
        QTest::newRow("unknown body key") << withBodies({"{\"name\": \"Floor\", " + kBox + "}",
                                                         "{\"name\": \"Shot\", " + kBox + ", \"velocty\": [1, 0, 0]}"})
                                          << 4 << "body 'Shot' (index 1): unknown key 'velocty'";
        QTest::newRow("wrong type fps") << withWorld("{\"fps\": \"60\"}") << 2
                                        << "world: 'fps' must be a number, not a string";
        QTest::newRow("fps zero") << withWorld("{\"fps\": 0}") << 2 << "'fps' must be greater than 0";
        QTest::newRow("substeps zero") << withWorld("{\"substeps\": 0}") << 2 << "'substeps' must be at least 1";
        QTest::newRow("substeps fraction") << withWorld("{\"substeps\": 2.5}") << 2 << "whole number";
        QTest::newRow("negative damping") << withWorld("{\"linear_damping\": -1}") << 2 << "must not be negative";
        QTest::newRow("gravity length") << withWorld("{\"gravity\": [0, -9.81]}") << 2
                                        << "'gravity' must be an array of 3 numbers; it has 2 items";
        QTest::newRow("gravity item type") << withWorld("{\"gravity\": [0, \"down\", 0]}") << 2 << "item 1 is string";
        QTest::newRow("unknown integrator")
            << withWorld("{\"integrator\": \"leapfrog\"}") << 2 << "unknown integrator 'leapfrog'";
        QTest::newRow("bad effects") << withWorld("{\"effects\": \"gravity,magnetism\"}") << 2
                                     << "unknown effect 'magnetism'";
        QTest::newRow("bad combine rule")
            << withWorld("{\"friction_combine\": \"median\"}") << 2 << "unknown combine rule";
        QTest::newRow("unknown world key")
            << withWorld("{\"gravty\": [0, 0, 0]}") << 2 << "world: unknown key 'gravty'";
        QTest::newRow("negative density") << withBodies({"{\"name\": \"A\", " + kBox + ", \"density\": -5}"}) << 3
                                          << "body 'A' (index 0): 'density' must be greater than 0";
        QTest::newRow("negative mass") << withBodies({"{\"name\": \"A\", " + kBox + ", \"mass\": -1}"}) << 3
                                       << "'mass' must be greater than 0";
        QTest::newRow("restitution above 1")
            << withBodies({"{\"name\": \"A\", " + kBox + ", \"restitution\": 1.5}"}) << 3 << "between 0 and 1";
        QTest::newRow("number overflow") << withBodies({"{\"name\": \"A\", " + kBox + ", \"mass\": 1e400}"}) << 3
                                         << "number out of range";
        QTest::newRow("zero half extent") << withBodies({"{\"name\": \"Thin\", \"shape\": {\"box\": [1, 0, 1]}}"}) << 3
                                          << "body 'Thin' (index 0): shape: 'box' half extents must all be greater";
        QTest::newRow("zero radius") << withBodies({"{\"shape\": {\"sphere\": 0}}"}) << 3
                                     << "body (index 0): shape: 'sphere' must be greater than 0";
        QTest::newRow("unknown shape") << withBodies({"{\"name\": \"C\", \"shape\": {\"cube\": 1}}"}) << 3
                                       << "unknown key 'cube'";
        QTest::newRow("two shapes") << withBodies({"{\"shape\": {\"sphere\": 1, \"box\": [1, 1, 1]}}"}) << 3
                                    << "has both 'sphere' and 'box'";
        QTest::newRow("empty shape") << withBodies({"{\"shape\": {}}"}) << 3 << "needs one of";
        QTest::newRow("missing shape") << withBodies({"{\"name\": \"Ghost\"}"}) << 3
                                       << "body 'Ghost' (index 0): missing key 'shape'";
        QTest::newRow("hull too small") << withBodies({"{\"shape\": {\"hull\": [[0, 0, 0], [1, 0, 0]]}}"}) << 3
                                        << "at least 3 points";
        QTest::newRow("hull bad point") << withBodies({"{\"shape\": {\"hull\": [[0, 0, 0], [1, 0], [0, 1, 0]]}}"}) << 3
                                        << "'hull[1]' must be an array of 3 numbers";
        QTest::newRow("mesh index out of range")
            << withBodies(
                   {"{\"shape\": {\"mesh\": {\"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"triangles\": [[0,1,3]]}}}"})
            << 3 << "has index 3";
        QTest::newRow("obj file missing") << withBodies({"{\"name\": \"P\", \"shape\": {\"obj\": \"nowhere.obj\"}}"})
                                          << 3 << "cannot load 'nowhere.obj'";
        QTest::newRow("obj is a device") << withBodies({"{\"name\": \"P\", \"shape\": {\"obj\": \"/dev/zero\"}}"}) << 3
                                         << "not a regular file";
        QTest::newRow("obj object missing")
            << withBodies({"{\"name\": \"P\", \"shape\": {\"obj\": \"parts.obj\", \"object\": \"Nope\"}}"}) << 3
            << "no object 'Nope' in 'parts.obj' (it has Cube.001, Tetra)";
        QTest::newRow("obj object needed")
            << withBodies({"{\"shape\": {\"obj\": \"parts.obj\"}}"}) << 3 << "has 2 objects";
        QTest::newRow("object without obj") << withBodies({"{\"shape\": {\"box\": [1,1,1], \"object\": \"x\"}}"}) << 3
                                            << "'object' belongs to an 'obj' shape";
        QTest::newRow("unknown material") << withBodies({"{\"name\": \"M\", " + kBox + ", \"material\": \"Steal\"}"})
                                          << 3 << "unknown material 'Steal'";
        QTest::newRow("non-unit orientation")
            << withBodies({"{\"name\": \"Q\", " + kBox + ", \"orientation\": [0, 90, 0, 0]}"}) << 3
            << "unit quaternion";
        QTest::newRow("anchor type") << withBodies({"{" + kBox + ", \"anchor\": \"yes\"}"}) << 3
                                     << "'anchor' must be true or false, not a string";
        QTest::newRow("body not an object")
            << withBodies({"{" + kBox + "}", "42"}) << 4 << "body (index 1): must be an object";
        QTest::newRow("duplicate key") << withBodies({"{" + kBox + ", \"mass\": 1, \"mass\": 2}"}) << 3
                                       << "duplicate key 'mass'";
        QTest::newRow("material twice")
            << std::string("{\"format\": \"rigidlab-scene\", \"version\": 1,\n\"materials\": {\"Soft\": {},\n"
                           "\"soft\": {}}}")
            << 3 << "defined twice";
        QTest::newRow("material bad key")
            << std::string("{\"format\": \"rigidlab-scene\", \"version\": 1,\n\"materials\": {\"Soft\": {\"mu\": 1}}}")
            << 2 << "material 'Soft': unknown key 'mu'";
    }

    void badScenes() {
        QFETCH(std::string, text);
        QFETCH(int, line);
        QFETCH(QString, message);
        // The scene sits beside parts.obj so that relative OBJ paths resolve.
        const std::string path = RL_TEST_DATA_DIR "/formats/scene.rlscene";
        Result<Scene> scene = readSceneJson(text, path);
        QVERIFY(!scene.ok());
        const std::string s = scene.error().toString();
        QVERIFY2(s.rfind(path + ":" + std::to_string(line) + ":", 0) == 0, s.c_str());
        QVERIFY2(s.find(message.toStdString()) != std::string::npos, s.c_str());
    }

    // The column is the key's, not its value's, so that an editor jumps to the misspelt word.
    void unknownKeyPointsAtTheKey() {
        const std::string body = "{\"name\": \"Shot\", " + kBox + ", \"velocty\": [1, 0, 0]}";
        Result<Scene> scene = readSceneJson(withBodies({body}), "scene.rlscene");
        QVERIFY(!scene.ok());
        QCOMPARE(scene.error().line, 3);
        QCOMPARE(scene.error().column, int(body.find("\"velocty\"")) + 1);
    }

    void missingFileIsAnError() {
        Result<Scene> scene = readSceneFile("/nonexistent/dir/x.rlscene");
        QVERIFY(!scene.ok());
        QVERIFY(scene.error().toString().find("/nonexistent/dir/x.rlscene") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestSceneJson)
#include "tst_scenejson.moc"
