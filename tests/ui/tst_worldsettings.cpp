// The World settings dock: each field reaches document().scene().world as one undo step (spin drags merge), invalid
// values are refused with a message, and the effects panel shows what Auto decides for the scene and why.
#include "MainWindow.h"
#include "document/SceneDocument.h"
#include "materials/MaterialsWidget.h"
#include "scene/SceneLibrary.h"
#include "settings/SettingsController.h"
#include "ui/GuiTestSetup.h"
#include "ui/Screenshot.h"
#include "world/WorldSettingsWidget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTest>

#include <functional>

using namespace rl;

Q_DECLARE_METATYPE(std::function<bool(const rl::WorldSettings&)>)
Q_DECLARE_METATYPE(rl::Scene)

using Check = std::function<bool(const WorldSettings&)>;

class TestWorldSettings : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private:
    template <class T>
    static T* child(QWidget* parent, const QString& name) {
        T* widget = parent->findChild<T*>(name);
        if (!widget)
            qFatal("no child %s", qPrintable(name));
        return widget;
    }

    static bool open(MainWindow& window, const Scene* scene = nullptr) {
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return false;
        if (scene)
            window.document()->reset(*scene, QString());
        else if (!window.openFile(QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj")))
            return false;
        window.settings()->worldDock()->show();
        window.settings()->worldDock()->raise();
        return true;
    }

    static QString status(MainWindow& window, const char* effect) {
        return child<QLabel>(window.settings()->worldSettings(), QStringLiteral("EffectStatus_") + effect)->text();
    }

private slots:
    void dockAndWindowMenu() {
        MainWindow window;
        QVERIFY(open(window));
        auto* action = window.findChild<QAction*>("WorldSettingsDockAction");
        QVERIFY(action);
        QVERIFY(window.menu(MainWindow::Menu::Window)->actions().contains(action));
        action->trigger();
        QVERIFY(!window.settings()->worldDock()->isVisible());
        action->trigger();
        QVERIFY(window.settings()->worldDock()->isVisible());
    }

    void spinEditsReachTheWorld_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("value");
        QTest::addColumn<Check>("check");
        QTest::newRow("gravity x") << "GravityX" << 2.5
                                   << Check([](const WorldSettings& w) { return w.gravity.x == 2.5; });
        QTest::newRow("gravity y") << "GravityY" << -1.62
                                   << Check([](const WorldSettings& w) { return w.gravity.y == -1.62; });
        QTest::newRow("gravity z") << "GravityZ" << -3.0
                                   << Check([](const WorldSettings& w) { return w.gravity.z == -3.0; });
        QTest::newRow("fps") << "WorldFps" << 120.0 << Check([](const WorldSettings& w) { return w.fps == 120.0; });
        QTest::newRow("substeps") << "WorldSubsteps" << 4.0
                                  << Check([](const WorldSettings& w) { return w.substeps == 4; });
        QTest::newRow("iterations") << "WorldIterations" << 3.0
                                    << Check([](const WorldSettings& w) { return w.iterations == 3; });
        QTest::newRow("linear damping") << "WorldLinearDamping" << 0.25
                                        << Check([](const WorldSettings& w) { return w.linearDamping == 0.25; });
        QTest::newRow("angular damping") << "WorldAngularDamping" << 0.5
                                         << Check([](const WorldSettings& w) { return w.angularDamping == 0.5; });
    }
    void spinEditsReachTheWorld() {
        QFETCH(QString, field);
        QFETCH(double, value);
        QFETCH(Check, check);
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        WorldSettingsWidget* world = window.settings()->worldSettings();
        const WorldSettings before = document->scene().world;
        QVERIFY(!check(before));
        if (auto* spin = world->findChild<QDoubleSpinBox*>(field))
            spin->setValue(value);
        else
            child<QSpinBox>(world, field)->setValue(static_cast<int>(value));
        QVERIFY(check(document->scene().world));
        QCOMPARE(document->undoStack()->count(), 1);
        document->undoStack()->undo();
        QVERIFY(document->scene().world == before);
        document->undoStack()->redo();
        QVERIFY(check(document->scene().world));
    }

    void comboEditsReachTheWorld() {
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        WorldSettingsWidget* world = window.settings()->worldSettings();
        auto pick = [&](const char* name, int index) {
            auto* combo = child<QComboBox>(world, QLatin1String(name));
            combo->setCurrentIndex(index);
            emit combo->activated(index);
        };
        pick("WorldIntegrator", static_cast<int>(Integrator::Rk4));
        QCOMPARE(document->scene().world.integrator, Integrator::Rk4);
        pick("WorldFrictionCombine", static_cast<int>(CombineRule::Min));
        QCOMPARE(document->scene().world.frictionCombine, CombineRule::Min);
        pick("WorldRestitutionCombine", static_cast<int>(CombineRule::Average));
        QCOMPARE(document->scene().world.restitutionCombine, CombineRule::Average);
        pick("EffectMode_sleeping", static_cast<int>(EffectMode::Off));
        QCOMPARE(document->scene().world.effects.mode(Effect::Sleeping), EffectMode::Off);
        pick("EffectMode_ccd", static_cast<int>(EffectMode::On));
        QCOMPARE(document->scene().world.effects.toString(), std::string("auto,-sleeping,+ccd"));
        pick("GravityPreset", 1); // Moon
        QCOMPARE(document->scene().world.gravity, Vec3(0.0, -1.62, 0.0));
        QCOMPARE(child<QDoubleSpinBox>(world, "GravityY")->value(), -1.62);
        QVERIFY(child<QLabel>(world, "GravityMagnitude")->text().contains("1.62"));
        QCOMPARE(document->undoStack()->count(), 6);

        // Linear only is Rotation: Off, both ways.
        auto* linearOnly = child<QCheckBox>(world, "WorldLinearOnly");
        linearOnly->click();
        QCOMPARE(document->scene().world.effects.mode(Effect::Rotation), EffectMode::Off);
        QCOMPARE(child<QComboBox>(world, "EffectMode_rotation")->currentIndex(), static_cast<int>(EffectMode::Off));
        pick("EffectMode_rotation", static_cast<int>(EffectMode::Auto));
        QVERIFY(!linearOnly->isChecked());

        child<QPushButton>(world, "EffectsAllAuto")->click();
        QVERIFY(document->scene().world.effects == EffectsSetting{});
        child<QPushButton>(world, "WorldRestoreDefaults")->click();
        QVERIFY(document->scene().world == WorldSettings{});
        while (document->undoStack()->canUndo())
            document->undoStack()->undo();
        QVERIFY(document->scene().world == WorldSettings{});
        QCOMPARE(child<QComboBox>(world, "WorldIntegrator")->currentIndex(),
                 static_cast<int>(Integrator::SymplecticEuler));
    }

    void spinStepsMergeIntoOneUndoStep() {
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        WorldSettingsWidget* world = window.settings()->worldSettings();
        auto* fps = child<QDoubleSpinBox>(world, "WorldFps");
        for (int i = 0; i < 5; ++i)
            fps->stepUp();
        QCOMPARE(document->scene().world.fps, 110.0);
        QCOMPARE(document->undoStack()->count(), 1);
        child<QSpinBox>(world, "WorldSubsteps")->stepUp();
        QCOMPARE(document->undoStack()->count(), 2);
        document->undoStack()->undo();
        document->undoStack()->undo();
        QCOMPARE(document->scene().world.fps, 60.0);
        QCOMPARE(fps->value(), 60.0);
    }

    void invalidValuesRefused_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("fps 0") << "WorldFps" << 0.0 << "frame rate";
        QTest::newRow("fps too high") << "WorldFps" << 200000.0 << "frame rate";
        QTest::newRow("substeps 0") << "WorldSubsteps" << 0.0 << "Substeps";
        QTest::newRow("substeps too many") << "WorldSubsteps" << 1001.0 << "Substeps";
        QTest::newRow("iterations 0") << "WorldIterations" << 0.0 << "Iterations";
        QTest::newRow("iterations too many") << "WorldIterations" << 5000.0 << "Iterations";
    }
    void invalidValuesRefused() {
        QFETCH(QString, field);
        QFETCH(double, value);
        QFETCH(QString, expected);
        MainWindow window;
        QVERIFY(open(window));
        SceneDocument* document = window.document();
        WorldSettingsWidget* world = window.settings()->worldSettings();
        const WorldSettings before = document->scene().world;
        if (auto* spin = world->findChild<QDoubleSpinBox*>(field)) {
            spin->setValue(value);
            QCOMPARE(spin->value(), before.fps); // the field shows what the world keeps
        } else {
            auto* box = child<QSpinBox>(world, field);
            box->setValue(static_cast<int>(value));
            QCOMPARE(box->value(), field == "WorldSubsteps" ? before.substeps : before.iterations);
        }
        QVERIFY(document->scene().world == before);
        QCOMPARE(document->undoStack()->count(), 0);
        QVERIFY2(world->message().contains(expected), qPrintable(world->message()));
        // The message names the limits.
        QVERIFY(world->message().contains(QRegularExpression("[0-9]")));
        // A valid edit takes the message away.
        child<QDoubleSpinBox>(world, "WorldLinearDamping")->setValue(0.1);
        QVERIFY(world->message().isEmpty());
        // The same rule in code: what the core would refuse, the panel refuses.
        WorldSettings bad = before;
        bad.gravity.x = std::nan("");
        QVERIFY(!world->applySettings(bad, "Bad"));
        QVERIFY(world->message().contains("gravity"));
    }

    void autoEffectsFollowTheScene_data() {
        QTest::addColumn<Scene>("scene");
        QTest::addColumn<QString>("effect");
        QTest::addColumn<bool>("on");
        QTest::addColumn<QString>("reason"); // a part of the core's reason
        Scene stack = scenes::stack(3);
        QTest::newRow("stack: friction on") << stack << "friction" << true << "friction above zero";
        QTest::newRow("stack: restitution off") << stack << "restitution" << false << "restitution is zero";
        QTest::newRow("stack: sleeping on") << stack << "sleeping" << true << "come to rest";
        QTest::newRow("stack: no damping") << stack << "damping" << false << "no damping";
        Scene frictionless = stack;
        frictionless.materials.push_back({"Frictionless", 1000.0, 0.0, 0.0});
        for (BodyDef& body : frictionless.bodies) {
            body.material = "Frictionless";
            body.friction.reset();
        }
        QTest::newRow("frictionless: friction off") << frictionless << "friction" << false << "friction is zero";
        Scene bouncy = scenes::drop(1.0, 0.5);
        QTest::newRow("drop e=0.5: restitution on") << bouncy << "restitution" << true << "restitution above zero";
        Scene weightless = scenes::tumbling(0);
        QTest::newRow("no gravity: gravity off") << weightless << "gravity" << false << "zero gravity";
        QTest::newRow("no gravity: sleeping off") << weightless << "sleeping" << false << "nothing to come to rest";
        Scene damped = stack;
        damped.world.linearDamping = 0.1;
        QTest::newRow("damped: damping on") << damped << "damping" << true << "damping is set";
    }
    void autoEffectsFollowTheScene() {
        QFETCH(Scene, scene);
        QFETCH(QString, effect);
        QFETCH(bool, on);
        QFETCH(QString, reason);
        MainWindow window;
        QVERIFY(open(window, &scene));
        WorldSettingsWidget* world = window.settings()->worldSettings();
        QTRY_VERIFY_WITH_TIMEOUT(world->decision().has_value(), 20000);
        int index = -1;
        for (int i = 0; i < kEffectCount; ++i)
            if (QString::fromLatin1(effectName(static_cast<Effect>(i))) == effect)
                index = i;
        QVERIFY(index >= 0);
        QCOMPARE(world->decision()->effects.on[static_cast<size_t>(index)], on);
        const QString text = status(window, effect.toLatin1().constData());
        QVERIFY2(text.contains(on ? ">on<" : ">off<"), qPrintable(text));
        QVERIFY2(text.contains(reason), qPrintable(text));
    }

    void autoEffectsUpdateLive() {
        Scene scene = scenes::stack(3);
        MainWindow window;
        QVERIFY(open(window, &scene));
        WorldSettingsWidget* world = window.settings()->worldSettings();
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "friction").contains(">on<"), 20000);
        // Every body of scenes::stack uses Default: friction 0 for Default turns friction off.
        MaterialsWidget* materials = window.settings()->materials();
        materials->setCurrentMaterial("Default");
        MaterialDef frictionless = *findPreset("Default");
        frictionless.friction = 0.0;
        QVERIFY(materials->applyMaterial("Default", frictionless, "Frictionless"));
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "friction").contains(">off<"), 20000);
        QVERIFY(status(window, "friction").contains("friction is zero"));
        // Forcing it on shows "forced", and what Auto would choose.
        auto* mode = child<QComboBox>(world, "EffectMode_friction");
        mode->setCurrentIndex(static_cast<int>(EffectMode::On));
        emit mode->activated(static_cast<int>(EffectMode::On));
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "friction").contains("forced"), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "friction").contains("Auto: off"), 20000);
        QVERIFY(child<QLabel>(world, "EffectStatus_friction")->toolTip().contains("friction is zero"));
        QVERIFY(status(window, "friction").contains(">on<"));
        // Undo goes back to Auto and off.
        window.document()->undoStack()->undo();
        QTRY_VERIFY_WITH_TIMEOUT(!status(window, "friction").contains("forced"), 20000);
        QVERIFY(status(window, "friction").contains(">off<"));
        // Zero gravity by preset: gravity and sleeping go off.
        auto* preset = child<QComboBox>(world, "GravityPreset");
        preset->setCurrentIndex(3);
        emit preset->activated(3);
        QCOMPARE(window.document()->scene().world.gravity, Vec3(0.0));
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "gravity").contains(">off<"), 20000);
        QVERIFY(status(window, "sleeping").contains(">off<"));
    }

    void sceneThatCannotRunSaysWhy() {
        Scene scene = scenes::stack(2);
        scene.bodies[1].density = -1.0; // refused by the core's body properties
        MainWindow window;
        QVERIFY(open(window, &scene));
        auto* problem = child<QLabel>(window.settings()->worldSettings(), "EffectsProblem");
        QTRY_VERIFY_WITH_TIMEOUT(problem->isVisible(), 20000);
        QVERIFY2(problem->text().contains("density"), qPrintable(problem->text()));
        QVERIFY(!window.settings()->worldSettings()->decision().has_value());
    }

    void screenshot() {
        MainWindow window;
        QVERIFY(open(window));
        WorldSettingsWidget* world = window.settings()->worldSettings();
        auto* ccd = child<QComboBox>(world, "EffectMode_sleeping");
        ccd->setCurrentIndex(2);
        emit ccd->activated(2);
        QTRY_VERIFY_WITH_TIMEOUT(status(window, "sleeping").contains("Auto: on"), 20000);
        QVERIFY(rl::test::screenshot(window).save(QDir::tempPath() + "/rigidlab-world.png"));
        QVERIFY(window.settings()->worldDock()->grab().save(QDir::tempPath() + "/rigidlab-world-dock.png"));
        QVERIFY(
            child<QWidget>(world, "WorldSettingsContent")->grab().save(QDir::tempPath() + "/rigidlab-world-all.png"));
    }
};

QTEST_MAIN(TestWorldSettings)
#include "tst_worldsettings.moc"
