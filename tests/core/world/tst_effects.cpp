// Effects: what auto turns on for a scene and why, forced modes and the text form of a setting, and that a skipped
// effect's stage does not run.
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <QtTest>

#include <functional>

using namespace rl;

namespace {

BodyDef body(const std::string& name, ShapeType type, const Vec3& position) {
    BodyDef b;
    b.name = name;
    b.shape.type = type;
    b.shape.halfExtents = Vec3(0.5);
    b.shape.radius = 0.5;
    b.position = position;
    return b;
}

// A unit box resting on the library's floor (Default material: friction 0.5, restitution 0).
Scene boxOnFloor() {
    Scene s;
    s.bodies.push_back(scenes::floorBox());
    s.bodies.push_back(body("Box", ShapeType::Box, Vec3(0.0, 0.5, 0.0)));
    return s;
}

World makeWorld(const Scene& scene, const EffectsSetting& effects = {}) {
    WorldOptions options;
    options.effects = effects;
    Result<World> w = World::create(scene, options);
    if (!w)
        qFatal("%s", w.error().toString().c_str());
    return std::move(w).value();
}

EffectsSetting parsed(const char* text) {
    std::string error;
    const std::optional<EffectsSetting> s = EffectsSetting::parse(text, &error);
    if (!s)
        qFatal("%s: %s", text, error.c_str());
    return *s;
}

} // namespace

using SceneMaker = std::function<Scene()>;
Q_DECLARE_METATYPE(SceneMaker)

class TestEffects : public QObject {
    Q_OBJECT
private slots:
    // Each row changes one thing about a scene and names every effect auto must then simulate, in the order of
    // rl::Effect.
    void autoTurnsOnWhatTheSceneNeeds_data() {
        QTest::addColumn<SceneMaker>("make");
        QTest::addColumn<QString>("expected");
        QTest::newRow("box on a floor") << SceneMaker(boxOnFloor) << "gravity,rotation,friction,sleeping";
        QTest::newRow("a steel box bounces") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[1].material = "Steel";
            return s;
        }) << "gravity,rotation,friction,restitution,sleeping";
        QTest::newRow("frictionless box") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[0].friction = 0.0;
            s.bodies[1].friction = 0.0;
            return s;
        }) << "gravity,rotation,sleeping";
        QTest::newRow("frictionless ball: nothing can spin it") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[1] = body("Ball", ShapeType::Sphere, Vec3(0.0, 0.5, 0.0));
            s.bodies[0].friction = 0.0;
            s.bodies[1].friction = 0.0;
            return s;
        }) << "gravity,sleeping";
        QTest::newRow("frictionless ball that starts spinning") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[1] = body("Ball", ShapeType::Sphere, Vec3(0.0, 0.5, 0.0));
            s.bodies[1].angularVelocity = Vec3(0.0, 3.0, 0.0);
            s.bodies[0].friction = 0.0;
            s.bodies[1].friction = 0.0;
            return s;
        }) << "gravity,rotation,sleeping";
        QTest::newRow("ball with friction: friction can spin it") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[1] = body("Ball", ShapeType::Sphere, Vec3(0.0, 0.5, 0.0));
            return s;
        }) << "gravity,rotation,friction,sleeping";
        QTest::newRow("damping set") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.world.linearDamping = 0.1;
            return s;
        }) << "gravity,rotation,friction,damping,sleeping";
        QTest::newRow("angular damping set") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.world.angularDamping = 0.1;
            return s;
        }) << "gravity,rotation,friction,damping,sleeping";
        QTest::newRow("no gravity: nothing to fall or to rest on") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.world.gravity = Vec3(0.0);
            return s;
        }) << "rotation,friction";
        QTest::newRow("no anchor: nothing to rest on") << SceneMaker([] {
            Scene s;
            s.bodies.push_back(body("A", ShapeType::Box, Vec3(0.0, 5.0, 0.0)));
            s.bodies.push_back(body("B", ShapeType::Box, Vec3(0.0, 6.0, 0.0)));
            return s;
        }) << "gravity,rotation,friction";
        QTest::newRow("a shot at 300 m/s, no gravity")
            << SceneMaker([] { return scenes::bullet(0.0); }) << "rotation,friction,ccd"; // no gravity
        QTest::newRow("only anchors") << SceneMaker([] {
            Scene s = boxOnFloor();
            s.bodies[1].anchor = true;
            return s;
        }) << "none";
    }
    void autoTurnsOnWhatTheSceneNeeds() {
        QFETCH(SceneMaker, make);
        QFETCH(QString, expected);
        const World w = makeWorld(make());
        QCOMPARE(QString::fromStdString(w.effects().toString()), expected);
        // Every auto decision says why, for the editor to show beside the effect.
        for (const std::string& reason : w.effectsDecision().reasons)
            QVERIFY2(reason.rfind("auto: ", 0) == 0 && reason.size() > 6, reason.c_str());
    }

    // A forced mode wins over auto either way; the rest stay as auto decides.
    void forcedModesOverrideAuto_data() {
        QTest::addColumn<QString>("setting");
        QTest::addColumn<QString>("expected");
        QTest::newRow("auto") << "auto"
                              << "gravity,rotation,friction,sleeping";
        QTest::newRow("auto, sleeping off, CCD on") << "auto,-sleeping,+ccd"
                                                    << "gravity,rotation,friction,ccd";
        QTest::newRow("no- spelling") << "auto,no-friction"
                                      << "gravity,rotation,sleeping";
        QTest::newRow("linear-only: the original project's mode") << "linear-only"
                                                                  << "gravity,friction,sleeping";
        QTest::newRow("a plain list: only what it names") << "gravity,restitution"
                                                          << "gravity,restitution";
        QTest::newRow("none") << "none"
                              << "none";
        QTest::newRow("all") << "all"
                             << "gravity,rotation,friction,restitution,damping,sleeping,ccd";
        QTest::newRow("all but gravity") << "all,-gravity"
                                         << "rotation,friction,restitution,damping,sleeping,ccd";
    }
    void forcedModesOverrideAuto() {
        QFETCH(QString, setting);
        QFETCH(QString, expected);
        const EffectsSetting modes = parsed(qPrintable(setting));
        const World w = makeWorld(boxOnFloor(), modes);
        QCOMPARE(QString::fromStdString(w.effects().toString()), expected);
        for (int e = 0; e < kEffectCount; ++e) {
            const EffectMode mode = modes.mode(static_cast<Effect>(e));
            const std::string& reason = w.effectsDecision().reasons[static_cast<size_t>(e)];
            if (mode == EffectMode::On)
                QCOMPARE(reason, std::string("forced on"));
            else if (mode == EffectMode::Off)
                QCOMPARE(reason, std::string("forced off"));
        }
    }

    // The text form (.rlscene's "effects", the CLI's --effects) reads back as the same setting.
    void textFormReadsBack_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("printed");
        QTest::newRow("auto") << "auto"
                              << "auto";
        QTest::newRow("none") << "none"
                              << "none";
        QTest::newRow("all") << "all"
                             << "auto,+gravity,+rotation,+friction,+restitution,+damping,+sleeping,+ccd";
        QTest::newRow("linear-only") << "linear-only"
                                     << "auto,-rotation";
        QTest::newRow("plain list") << "gravity,friction"
                                    << "auto,+gravity,-rotation,+friction,-restitution,-damping,-sleeping,-ccd";
        QTest::newRow("spaces and case") << " Auto , -Sleeping ,+CCD "
                                         << "auto,-sleeping,+ccd";
    }
    void textFormReadsBack() {
        QFETCH(QString, text);
        QFETCH(QString, printed);
        const EffectsSetting setting = parsed(qPrintable(text));
        QCOMPARE(QString::fromStdString(setting.toString()), printed);
        QVERIFY(parsed(setting.toString().c_str()) == setting);
    }

    void badTextNamesTheProblem_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("named");
        QTest::newRow("unknown effect") << "auto,-magnetism"
                                        << "'magnetism'";
        QTest::newRow("empty") << ""
                               << "empty effect name";
        QTest::newRow("empty item") << "gravity,,friction"
                                    << "empty effect name";
        QTest::newRow("base not first") << "gravity,auto"
                                        << "'auto' must come first";
        QTest::newRow("sign alone") << "auto,+"
                                    << "unknown effect ''";
    }
    void badTextNamesTheProblem() {
        QFETCH(QString, text);
        QFETCH(QString, named);
        std::string error;
        QVERIFY(!EffectsSetting::parse(text.toStdString(), &error));
        QVERIFY2(QString::fromStdString(error).contains(named), error.c_str());
    }

    // A skipped effect costs nothing: its stage is not called at all, and forced on it runs.
    void skippedStagesDoNotRun_data() {
        QTest::addColumn<int>("effect");
        QTest::addColumn<int>("stage");
        QTest::newRow("restitution") << int(Effect::Restitution) << int(Stage::Restitution);
        QTest::newRow("ccd") << int(Effect::Ccd) << int(Stage::Ccd);
        QTest::newRow("sleeping") << int(Effect::Sleeping) << int(Stage::Sleep);
        // Turned features pushed apart after the step (World::separateMovedPairs()) need turns.
        QTest::newRow("rotation") << int(Effect::Rotation) << int(Stage::Separate);
    }
    void skippedStagesDoNotRun() {
        QFETCH(int, effect);
        QFETCH(int, stage);
        for (const EffectMode mode : {EffectMode::Off, EffectMode::On}) {
            EffectsSetting setting;
            setting.set(static_cast<Effect>(effect), mode);
            World w = makeWorld(boxOnFloor(), setting);
            for (int i = 0; i < 10; ++i)
                w.step();
            QCOMPARE(w.profile().calls[static_cast<size_t>(stage)], mode == EffectMode::On ? uint64_t(10) : 0u);
        }
    }

    // linear-only: a box dropped on its edge lands without turning, as in the original project, and a spin it was
    // given is not reported either.
    void linearOnlyNeverTurns() {
        Scene s = boxOnFloor();
        s.bodies[1].position = Vec3(0.0, 2.0, 0.0);
        s.bodies[1].orientation = glm::angleAxis(0.6, glm::normalize(Vec3(1.0, 0.0, 1.0)));
        s.bodies[1].angularVelocity = Vec3(0.0, 2.0, 0.0);
        World turning = makeWorld(s), linear = makeWorld(s, parsed("linear-only"));
        for (int i = 0; i < 120; ++i) {
            turning.step();
            linear.step();
            QCOMPARE(linear.rotationSinceStart(1), identityQuat());
            QCOMPARE(linear.angularVelocity(1), Vec3(0.0));
        }
        QVERIFY(linear.centerOfMass(1).y < 1.0); // it fell
        QVERIFY(glm::angle(turning.rotationSinceStart(1)) > 0.1);
    }
};

QTEST_APPLESS_MAIN(TestEffects)
#include "tst_effects.moc"
