// The live simulation and the background bake of the editor: Play/Pause/Step/Reset move bodies on a worker thread
// without touching the document, edits during a run end it cleanly, bakes fill the timeline, cancel keeps frames,
// edits make a bake stale, and the event loop keeps running while a bake works.
#include "overlays/OverlayController.h"
#include "scene/SceneLibrary.h"
#include "simulation/BakeDialog.h"
#include "timeline/TimelineWidget.h"
#include "ui/GuiTestSetup.h"
#include "ui/SimulationTestUtil.h"
#include "world/World.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QMenu>
#include <QProgressBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QToolBar>

#include <glm/gtc/quaternion.hpp>

using namespace rl;
using namespace rl::test;

namespace {

// A floor and a box tilted by 30 degrees about x and z, 3 m up: it falls, lands on an edge and turns.
Scene fallingBox() {
    Scene s;
    s.bodies.push_back(scenes::floorBox());
    BodyDef box;
    box.name = "Box";
    box.shape.type = ShapeType::Box;
    box.shape.halfExtents = Vec3(0.3, 0.2, 0.4);
    box.position = Vec3(0.5, 3.0, -0.25);
    box.orientation = glm::angleAxis(glm::radians(30.0), glm::normalize(Vec3(1.0, 0.0, 1.0)));
    s.bodies.push_back(box);
    return s;
}

QAction* action(MainWindow& window, const char* name) {
    auto* found = window.findChild<QAction*>(QLatin1String(name));
    if (!found)
        qWarning("no action %s", name);
    return found;
}

bool sameModels(MainWindow& window) {
    for (int i = 0; i < window.document()->bodyCount(); ++i)
        if (shownModel(window, i) != editModel(window, i))
            return false;
    return true;
}

const QString kStack = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/stack.obj");
const QString kPyramid = QStringLiteral(RL_SOURCE_DIR "/resources/scenes/pyramid.obj");

// A bake that runs for a while on this machine (200 boxes keep moving for seconds, so they do not fall asleep and
// finish early), for the tests that act while a bake is under way, which cancel it. Since the editor bakes on
// every core, 6,000 frames were done within the 3 s that staysResponsiveWhileBaking() waits on two cores (1 run in
// 5, 2026-12-04); 24,000 frames would hold 250 MB, but a cancelled bake holds only what it reached.
constexpr int kLongBake = 24000;
Scene busyScene() {
    Scene scene = scenes::randomBoxes(200);
    scene.world.effects.set(Effect::Sleeping, EffectMode::Off); // every step costs the same to the end
    return scene;
}
void openBusyScene(MainWindow& window) {
    window.document()->reset(busyScene(), QString());
}

} // namespace

class TestSimulation : public QObject {
    Q_OBJECT
public:
    static void initMain() { prepareGuiTest(); }

private slots:
    void menuAndToolbarHaveTheActions() {
        MainWindow window;
        QVERIFY(showWindow(window));
        QMenu* menu = window.menu(MainWindow::Menu::Simulation);
        for (const char* name : {"PlayAction", "StepAction", "ResetAction", "BakeAction", "RebakeAction",
                                 "CancelBakeAction", "ClearBakeAction"}) {
            QAction* a = action(window, name);
            QVERIFY2(a, name);
            QVERIFY2(menu->actions().contains(a), name);
        }
        QCOMPARE(action(window, "PlayAction")->shortcut(), QKeySequence(Qt::Key_Space));
        QCOMPARE(action(window, "StepAction")->shortcut(), QKeySequence(Qt::Key_Right));
        QCOMPARE(action(window, "ResetAction")->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_R));
        auto* toolBar = window.findChild<QToolBar*>("SimulationToolBar");
        QVERIFY(toolBar);
        QVERIFY(toolBar->actions().contains(action(window, "PlayAction")));
    }

    // Space runs the simulation, Space again pauses it; the box falls, the document keeps its pose, and the status
    // bar shows the simulated time.
    void playThenPauseMovesAFallingBody() {
        MainWindow window;
        QVERIFY(showWindow(window));
        window.document()->reset(fallingBox(), QString());
        SimulationController* sim = window.simulation();
        const glm::dvec3 start = editCentre(window, 1);

        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QTRY_VERIFY_WITH_TIMEOUT(sim->isRunning(), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(sim->liveTime() > 0.3, 20000);
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QTRY_VERIFY(!sim->isRunning());
        QCOMPARE(sim->display(), SimulationController::Display::Live);

        // After the pause the state stops changing (one step may still have been under way).
        QTest::qWait(300);
        const qint64 frame = sim->liveFrame();
        QTest::qWait(500);
        QCOMPARE(sim->liveFrame(), frame);
        QVERIFY(frame > 0);

        const glm::dvec3 now = shownCentre(window, 1, start);
        QVERIFY2(now.y < start.y - 0.2, qPrintable(QString("y %1 -> %2").arg(start.y).arg(now.y)));
        // Free fall for the time shown (before any contact: 3 m up, the box needs ~0.7 s to land).
        if (sim->liveTime() < 0.6) {
            const double t = sim->liveTime();
            QVERIFY(std::abs((start.y - now.y) - 0.5 * 9.81 * t * t) < 0.02);
        }
        QCOMPARE(window.document()->body(1).position, fallingBox().bodies[1].position); // the document is untouched
        auto* status = window.findChild<QLabel*>("SimulationStatus");
        QVERIFY(status);
        QVERIFY2(status->text().contains(QStringLiteral(" s · frame ")), qPrintable(status->text()));
    }

    // Step (→ or the action) advances exactly one frame of 1/fps.
    void stepAdvancesExactlyOneFrame() {
        MainWindow window;
        QVERIFY(showWindow(window));
        window.document()->reset(fallingBox(), QString());
        SimulationController* sim = window.simulation();
        action(window, "StepAction")->trigger();
        QTRY_COMPARE(sim->liveFrame(), qint64(1));
        QCOMPARE(sim->liveTime(), 1.0 / 60.0);
        QTest::keyClick(window.viewport(), Qt::Key_Right);
        QTRY_COMPARE(sim->liveFrame(), qint64(2));
        QTest::qWait(300);
        QCOMPARE(sim->liveFrame(), qint64(2));
        QVERIFY(!sim->isRunning());
        // The same two frames stepped headless.
        Result<World> world = World::create(fallingBox());
        QVERIFY(world);
        world->step();
        world->step();
        const glm::dvec3 shown = shownCentre(window, 1, editCentre(window, 1));
        QVERIFY2(glm::length(shown - world->centerOfMass(1)) < 1e-5,
                 qPrintable(QString("%1 vs %2").arg(shown.y).arg(world->centerOfMass(1).y)));
    }

    // Reset (Ctrl+R) puts every body back on its edit pose, bit for bit.
    void resetRestoresPosesExactly() {
        MainWindow window;
        QVERIFY(showWindow(window));
        QVERIFY(window.openFile(kStack));
        window.document()->reset(fallingBox(), QString());
        SimulationController* sim = window.simulation();
        sim->play();
        QTRY_VERIFY_WITH_TIMEOUT(sim->liveTime() > 0.9, 30000); // past the landing, so it has turned too
        sim->pause();
        QVERIFY(!sameModels(window));
        QTest::keyClick(window.viewport(), Qt::Key_R, Qt::ControlModifier);
        QCOMPARE(sim->display(), SimulationController::Display::EditPose);
        QVERIFY(sameModels(window));
        QCOMPARE(sim->liveFrame(), qint64(0));
        // Play again starts from the edit pose, at frame 1.
        sim->step();
        QTRY_COMPARE(sim->liveFrame(), qint64(1));
    }

    // Editing the scene while it runs ends the run and shows the edited scene at its edit pose, whatever the edit.
    void editWhileRunningResets_data() {
        QTest::addColumn<QString>("edit");
        QTest::newRow("move body") << "move";
        QTest::newRow("insert body") << "insert";
        QTest::newRow("remove body") << "remove";
        QTest::newRow("world settings") << "world";
        QTest::newRow("undo") << "undo";
    }
    void editWhileRunningResets() {
        QFETCH(QString, edit);
        MainWindow window;
        QVERIFY(showWindow(window));
        QVERIFY(window.openFile(kPyramid));
        SimulationController* sim = window.simulation();
        SceneDocument* doc = window.document();
        for (int round = 0; round < 3; ++round) {
            sim->play();
            QTRY_VERIFY_WITH_TIMEOUT(sim->liveFrame() > 2, 20000);
            QVERIFY(sim->isRunning());
            if (edit == "move") {
                BodyDef body = doc->body(5);
                body.position.y += 0.5;
                doc->setBody(5, body);
            } else if (edit == "insert") {
                BodyDef body = doc->body(5);
                body.name = "Extra";
                body.position.y += 10.0;
                doc->insertBody(doc->bodyCount(), body);
            } else if (edit == "remove") {
                doc->removeBody(doc->bodyCount() - 1);
            } else if (edit == "world") {
                WorldSettings world = doc->scene().world;
                world.substeps = 4 + round;
                doc->setWorldSettings(world);
            } else {
                // An edit through the undo stack, then its undo while running again.
                BodyDef body = doc->body(3);
                body.position.x += 1.0;
                doc->setBody(3, body);
                sim->play();
                QTRY_VERIFY_WITH_TIMEOUT(sim->liveFrame() > 2, 20000);
                body.position.x -= 1.0;
                doc->setBody(3, body);
            }
            QVERIFY(!sim->isRunning());
            QCOMPARE(sim->display(), SimulationController::Display::EditPose);
            QCOMPARE(static_cast<int>(window.viewport()->scene().instances.size()), doc->bodyCount());
            QTest::qWait(100); // a snapshot still queued must not bring the old run back
            QCOMPARE(sim->display(), SimulationController::Display::EditPose);
            QVERIFY(sameModels(window));
        }
    }

    // A body picked while the simulation shows it elsewhere is picked where it is shown.
    void pickingFollowsTheShownPose() {
        MainWindow window;
        QVERIFY(showWindow(window));
        window.document()->reset(fallingBox(), QString());
        window.viewport()->frameAll();
        SimulationController* sim = window.simulation();
        sim->play();
        QTRY_VERIFY_WITH_TIMEOUT(sim->liveTime() > 1.5, 40000);
        sim->pause();
        QTest::qWait(200);
        const glm::dvec3 centre = shownCentre(window, 1, editCentre(window, 1));
        const glm::vec3 pixel = window.viewport()->camera().project(glm::vec3(centre));
        window.setSelectedBodies({});
        QTest::mouseClick(window.viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(int(pixel.x), int(pixel.y)));
        QCOMPARE(window.selectedBodies(), QList<int>{1});
    }

    // Bake 1 s of stack.obj: frame 0 plus one frame per 1/60 s, and the timeline shows the bake.
    void bakeFillsTheTimeline() {
        MainWindow window;
        QVERIFY(showWindow(window));
        QVERIFY(window.openFile(kStack));
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QSignalSpy changed(sim, &SimulationController::bakeChanged);
        QVERIFY(sim->startBake(60));
        QVERIFY(sim->isBaking());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(guard.seen().isEmpty());
        QCOMPARE(changed.count(), 1);
        std::shared_ptr<const Bake> bake = sim->currentBake();
        QVERIFY(bake);
        QCOMPARE(bake->frameCount(), size_t(61)); // fps * seconds + 1 (Baker: frame 0 is the initial state)
        QCOMPARE(bake->bodyCount(), size_t(11));
        QVERIFY(bake->hasDiagnostics());
        QVERIFY(!bake->sceneObjText().empty());
        QCOMPARE(sim->timeline()->bake(), bake);
        QCOMPARE(sim->timeline()->lastFrame(), 60);
        QCOMPARE(sim->timeline()->fps(), 60.0);
        QVERIFY(!sim->timeline()->isStale());
        QVERIFY(sim->timeline()->progress() < 0.0);
        QCOMPARE(sim->display(), SimulationController::Display::Baked);
        QVERIFY(sameModels(window)); // frame 0
        QVERIFY(sim->bakeDrivesPlayback());
    }

    // Simulation > Bake… with a frame range that starts at frame 20: duration and range stay in step, the bake holds
    // frames 0..80, the bodies hold the edit pose up to frame 20 and move after it, and Re-bake keeps the range.
    void bakeAFrameRangeStartingLater() {
        BakeDialog dialog(60.0, 0, 600);
        auto* first = dialog.findChild<QSpinBox*>("BakeFirstFrame");
        auto* last = dialog.findChild<QSpinBox*>("BakeLastFrame");
        auto* seconds = dialog.findChild<QDoubleSpinBox*>("BakeSeconds");
        QVERIFY(first && last && seconds);
        QCOMPARE(seconds->value(), 10.0);
        first->setValue(20);
        QCOMPARE(last->value(), 600);      // the last frame stays, the duration shrinks
        QCOMPARE(seconds->value(), 9.667); // 580 frames at 60 Hz, to the box's three decimals
        seconds->setValue(1.0);
        QCOMPARE(last->value(), 80);
        first->setValue(100); // past the last frame: the last frame follows
        QCOMPARE(last->value(), 101);
        first->setValue(864000 - 60); // an hour at 240 Hz is the longest bake: the duration shows what fits
        seconds->setValue(10.0);
        QCOMPARE(last->value(), 864000);
        QCOMPARE(seconds->value(), 1.0);
        first->setValue(20);
        last->setValue(80);
        QCOMPARE(dialog.firstFrame(), 20);
        QCOMPARE(dialog.lastFrame(), 80);

        MainWindow window;
        QVERIFY(showWindow(window));
        openBusyScene(window); // boxes that start falling at once
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QVERIFY(!sim->startBake(20, 20)); // an empty range does not start
        QVERIFY(sim->startBake(dialog.lastFrame(), dialog.firstFrame()));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        std::shared_ptr<const Bake> bake = sim->currentBake();
        QVERIFY(bake);
        QCOMPARE(bake->frameCount(), size_t(81));
        QCOMPARE(bake->simulationStart(), size_t(20));
        QVERIFY(sim->statusMessage().contains("starts at frame 20"));
        for (int frame : {0, 10, 20}) {
            sim->timeline()->setCurrentFrame(frame);
            QVERIFY2(sameModels(window), qPrintable(QString("frame %1").arg(frame)));
        }
        sim->timeline()->setCurrentFrame(21);
        QVERIFY(!sameModels(window));

        QVERIFY(sim->startBake(80, 40)); // rebake() below must use this range
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
        QCOMPARE(sim->currentBake()->simulationStart(), size_t(40));
        sim->rebake();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 60000);
        QCOMPARE(sim->currentBake()->simulationStart(), size_t(40));
        QCOMPARE(sim->currentBake()->frameCount(), size_t(81));
        QVERIFY(guard.seen().isEmpty());
    }

    // Cancel keeps the frames done so far, and they are a valid bake on the timeline.
    void cancelKeepsFrames() {
        MainWindow window;
        QVERIFY(showWindow(window));
        openBusyScene(window);
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QVERIFY(sim->startBake(kLongBake));
        auto* bar = window.findChild<QProgressBar*>("BakeProgressBar");
        QVERIFY(bar);
        QTRY_VERIFY(bar->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(sim->timeline()->progress() > 0.0, 60000);
        action(window, "CancelBakeAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 30000);
        QCOMPARE(finished.first().first().toBool(), true);
        std::shared_ptr<const Bake> bake = sim->currentBake();
        QVERIFY(bake);
        QVERIFY(bake->frameCount() >= 2);
        QVERIFY(bake->frameCount() < size_t(kLongBake + 1));
        QCOMPARE(sim->timeline()->lastFrame(), static_cast<int>(bake->frameCount()) - 1);
        QVERIFY(!bar->isVisible());
        QVERIFY(sim->statusMessage().contains(QStringLiteral("cancelled")));
        // The last kept frame can be shown.
        sim->timeline()->setCurrentFrame(static_cast<int>(bake->frameCount()) - 1);
        QCOMPARE(sim->display(), SimulationController::Display::Baked);
    }

    // An edit after the bake makes it stale (timeline hatched); Re-bake replaces it with a current one.
    void editMakesBakeStaleAndRebakeReplacesIt() {
        MainWindow window;
        QVERIFY(showWindow(window));
        QVERIFY(window.openFile(kStack));
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QVERIFY(sim->startBake(30));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        const std::shared_ptr<const Bake> first = sim->currentBake();
        BodyDef body = window.document()->body(4);
        body.position.x += 0.3;
        window.document()->setBody(4, body);
        QVERIFY(sim->isBakeStale());
        QVERIFY(sim->timeline()->isStale());
        QVERIFY(!sim->bakeDrivesPlayback());
        QCOMPARE(sim->currentBake(), first); // kept, marked
        QCOMPARE(sim->display(), SimulationController::Display::EditPose);
        QVERIFY(sameModels(window));

        action(window, "RebakeAction")->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
        QVERIFY(sim->currentBake() != first);
        QCOMPARE(sim->currentBake()->frameCount(), size_t(31));
        QVERIFY(!sim->isBakeStale());
        QVERIFY(!sim->timeline()->isStale());
        // The new bake starts where the edited body now is.
        QVERIFY(std::abs(sim->currentBake()->position(0, 4).x - first->position(0, 4).x - 0.3f) < 1e-5f);
    }

    // An edit while baking makes the result stale when it arrives.
    void editDuringBakeMakesItStale() {
        MainWindow window;
        QVERIFY(showWindow(window));
        openBusyScene(window);
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QVERIFY(sim->startBake(kLongBake));
        QTRY_VERIFY_WITH_TIMEOUT(sim->timeline()->progress() > 0.0, 60000);
        BodyDef body = window.document()->body(2);
        body.position.z += 1.0;
        window.document()->setBody(2, body);
        sim->cancelBake();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 30000);
        QVERIFY(sim->isBakeStale());
        QVERIFY(sim->timeline()->isStale());
    }

    // The UI thread keeps running while a bake works: a 20 ms timer keeps firing, and the viewport repaints.
    void staysResponsiveWhileBaking() {
        MainWindow window;
        QVERIFY(showWindow(window));
        openBusyScene(window);
        ModalGuard guard;
        SimulationController* sim = window.simulation();
        QSignalSpy finished(sim, &SimulationController::bakeFinished);
        QSignalSpy rendered(window.viewport(), &Viewport::frameRendered);

        QElapsedTimer clock;
        qint64 last = 0, worstGap = 0;
        int ticks = 0;
        QTimer timer;
        timer.setInterval(20);
        connect(&timer, &QTimer::timeout, [&] {
            const qint64 now = clock.elapsed();
            worstGap = std::max(worstGap, now - last);
            last = now;
            ++ticks;
        });
        QVERIFY(sim->startBake(kLongBake));
        clock.start();
        timer.start();
        QTest::qWait(3000);
        timer.stop();
        QVERIFY(sim->isBaking()); // the bake was running the whole time
        // Repaints while the bake goes on (an llvmpipe frame of 200 boxes takes ~100 ms of this thread).
        rendered.clear();
        for (int k = 0; k < 3; ++k) {
            window.viewport()->requestRender();
            QVERIFY(rendered.wait(10000) || !rendered.isEmpty());
        }
        sim->cancelBake();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 30000);
        qInfo("during the bake: %d timer ticks of 20 ms in 3 s, worst gap %lld ms; %d repaints", ticks, worstGap,
              int(rendered.count()));
        // Generous bounds for a loaded 2-core machine; a bake on the UI thread would give one tick and no frame.
        QVERIFY2(ticks >= 30, qPrintable(QString::number(ticks)));
        QVERIFY2(worstGap < 1000, qPrintable(QString::number(worstGap)));
        QVERIFY(rendered.count() >= 3);
    }

    // Live runs hand the overlays what they ask for: centres and sleeping flags when enabled, nothing otherwise.
    void overlaysGetTheLiveState() {
        MainWindow window;
        QVERIFY(showWindow(window));
        window.document()->reset(fallingBox(), QString());
        OverlayController* overlays = window.overlays();
        overlays->setEnabled(OverlayController::Centres, false);
        overlays->setEnabled(OverlayController::Velocities, false);
        overlays->setEnabled(OverlayController::Trails, false);
        overlays->setEnabled(OverlayController::Sleeping, false);
        overlays->setEnabled(OverlayController::Contacts, false);
        overlays->setEnabled(OverlayController::Aabbs, false);
        SimulationController* sim = window.simulation();
        sim->step();
        QTRY_COMPARE(sim->liveFrame(), qint64(1));
        QVERIFY(overlays->frame().centres.empty());
        QCOMPARE(overlays->frame().frame, 1);
        overlays->setEnabled(OverlayController::Centres, true);
        overlays->setEnabled(OverlayController::Velocities, true);
        sim->step();
        QTRY_COMPARE(sim->liveFrame(), qint64(2));
        QTRY_COMPARE(overlays->frame().linearVelocities.size(), size_t(2));
        QCOMPARE(overlays->frame().centres.size(), size_t(2));
        QVERIFY(overlays->frame().linearVelocities[1].y < 0.0f);
        sim->reset();
        QVERIFY(!overlays->hasFrame());
    }
};

QTEST_MAIN(TestSimulation)
#include "tst_simulation.moc"
