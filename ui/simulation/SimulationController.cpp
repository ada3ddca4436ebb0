#include "simulation/SimulationController.h"

#include "MainWindow.h"
#include "analysis/AnalysisController.h"
#include "bake/Bake.h"
#include "document/SceneDocument.h"
#include "files/FileController.h"
#include "io/BakeLoad.h"
#include "io/SceneImport.h"
#include "overlays/OverlayController.h"
#include "scene/BodyProperties.h"
#include "simulation/BakeDialog.h"
#include "simulation/BakeJob.h"
#include "timeline/TimelineWidget.h"
#include "viewport/ScenePresenter.h"
#include "viewport/Viewport.h"
#include "widgets/StableLabel.h"
#include "world/Baker.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QProgressBar>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <thread>

namespace rl {

namespace {

// Seconds a new bake covers by default.
constexpr double kDefaultBakeSeconds = 10.0;
// How often the status bar and the timeline show a running bake's progress.
constexpr int kProgressIntervalMs = 100;

// A scene of small boxes at the bodies' frame-0 vertex means, for a .bake that carries no scene of its own. The box
// size is a hundredth of the extent of those means (5 cm when they all coincide), so markers neither vanish in a big
// scene nor swallow a small one.
Scene markerScene(const Bake& bake) {
    Scene scene;
    Vec3 lo(1e300), hi(-1e300);
    for (size_t i = 0; i < bake.bodyCount(); ++i) {
        lo = glm::min(lo, bake.vertexMean(0, i));
        hi = glm::max(hi, bake.vertexMean(0, i));
    }
    const Real extent = bake.bodyCount() > 1 ? glm::length(hi - lo) : 0.0;
    const Real half = extent > 0.0 ? std::max(0.005 * extent, 1e-3) : 0.05;
    for (size_t i = 0; i < bake.bodyCount(); ++i) {
        BodyDef body;
        body.name = bake.body(i).name.empty() ? "Body " + std::to_string(i) : bake.body(i).name;
        body.anchor = bake.body(i).anchor;
        body.shape.type = ShapeType::Box;
        body.shape.halfExtents = Vec3(half);
        body.position = bake.vertexMean(0, i);
        scene.bodies.push_back(std::move(body));
    }
    return scene;
}

// Bake records the run: the red dot of a record button (the style's icons have none, and its save icon is File >
// Save's).
QIcon recordIcon() {
    QIcon icon;
    for (int size : {16, 24, 32}) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter painter(&pixmap);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(QPen(QColor(140, 20, 20), size / 16.0));
        painter.setBrush(QColor(215, 45, 40));
        const qreal margin = size * 0.2;
        painter.drawEllipse(QRectF(margin, margin, size - 2 * margin, size - 2 * margin));
        icon.addPixmap(pixmap);
    }
    return icon;
}

} // namespace

SimulationController::SimulationController(MainWindow* window) : QObject(window), m_window(window) {
    setObjectName("SimulationController");
    auto* dock = new QDockWidget(tr("Timeline"), window);
    dock->setObjectName("TimelineDock");
    m_timeline = new TimelineWidget(dock);
    dock->setWidget(m_timeline);
    window->addDockWidget(Qt::BottomDockWidgetArea, dock);

    m_statusLabel = new QLabel(window);
    m_statusLabel->setObjectName("SimulationStatus");
    m_progressBar = new QProgressBar(window);
    m_progressBar->setObjectName("BakeProgressBar");
    m_progressBar->setRange(0, 1000);
    m_progressBar->setMaximumWidth(160);
    m_progressBar->setTextVisible(false);
    m_progressBar->hide();
    m_cancelButton = new QToolButton(window);
    m_cancelButton->setObjectName("CancelBakeButton");
    m_cancelButton->setAutoRaise(true);
    m_cancelButton->hide();
    window->statusBar()->addPermanentWidget(m_statusLabel);
    window->statusBar()->addPermanentWidget(m_progressBar);
    window->statusBar()->addPermanentWidget(m_cancelButton);

    m_progressTimer = new QTimer(this);
    m_progressTimer->setInterval(kProgressIntervalMs);
    connect(m_progressTimer, &QTimer::timeout, this, &SimulationController::onBakeProgress);

    createActions();
    m_window->menu(MainWindow::Menu::Window)->addAction(dock->toggleViewAction());

    // Picks follow what is on screen: the presenter knows the edit pose, the mapper the simulated poses.
    m_window->viewport()->setPickFunction([this](const ViewRay& ray) {
        return m_display == Display::EditPose ? m_window->presenter()->pick(ray) : m_mapper.pick(ray);
    });

    SceneDocument* document = m_window->document();
    connect(document, &SceneDocument::bodyChanged, this, [this] { onSceneEdited(true); });
    connect(document, &SceneDocument::bodyInserted, this, [this] { onSceneEdited(true); });
    connect(document, &SceneDocument::bodyRemoved, this, [this] { onSceneEdited(true); });
    connect(document, &SceneDocument::worldSettingsChanged, this, [this] { onSceneEdited(false); });
    connect(document, &SceneDocument::materialsChanged, this, [this] { onSceneEdited(false); });
    connect(document, &SceneDocument::sceneReset, this, &SimulationController::onSceneReplaced);

    connect(m_timeline, &TimelineWidget::currentFrameChanged, this, [this](int frame) {
        if (!m_bake)
            return;
        if (!bakeMatchesScene()) {
            showStatus(tr("The bake has %n bodies and the scene %1: re-bake to scrub it.", "",
                          static_cast<int>(m_bake->bodyCount()))
                           .arg(m_window->document()->bodyCount()));
            return;
        }
        stopRunner();
        showBakeFrame(frame);
    });
    connect(m_timeline, &TimelineWidget::playingChanged, this, &SimulationController::updateActions);
    connect(m_window->overlays(), &OverlayController::enabledChanged, this, [this] {
        if (m_runner)
            m_runner->setExtras(liveExtras());
        refreshDisplay();
    });
    updateActions();
    updateStatusLabel();
}

SimulationController::~SimulationController() {
    m_job.reset();
    m_runner.reset();
}

void SimulationController::createActions() {
    QMenu* menu = m_window->menu(MainWindow::Menu::Simulation);
    QStyle* style = QApplication::style();
    m_toolBar = m_window->addToolBar(tr("Simulation"));
    m_toolBar->setObjectName("SimulationToolBar");

    m_playAction = new QAction(style->standardIcon(QStyle::SP_MediaPlay), tr("&Play"), this);
    m_playAction->setObjectName("PlayAction");
    m_playAction->setShortcut(QKeySequence(Qt::Key_Space));
    connect(m_playAction, &QAction::triggered, this, &SimulationController::togglePlay);

    m_stepAction = new QAction(style->standardIcon(QStyle::SP_MediaSkipForward), tr("&Step"), this);
    m_stepAction->setObjectName("StepAction");
    m_stepAction->setShortcut(QKeySequence(Qt::Key_Right));
    m_stepAction->setStatusTip(tr("Advance one frame (while paused)"));
    connect(m_stepAction, &QAction::triggered, this, &SimulationController::step);

    m_resetAction = new QAction(style->standardIcon(QStyle::SP_MediaSkipBackward), tr("&Reset"), this);
    m_resetAction->setObjectName("ResetAction");
    m_resetAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_resetAction->setStatusTip(tr("Back to the edit pose (frame 0)"));
    connect(m_resetAction, &QAction::triggered, this, &SimulationController::reset);

    m_bakeAction = new QAction(recordIcon(), tr("&Bake…"), this);
    m_bakeAction->setObjectName("BakeAction");
    m_bakeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_bakeAction->setStatusTip(tr("Record the simulation in the background for playback and export"));
    connect(m_bakeAction, &QAction::triggered, this, &SimulationController::bakeWithDialog);

    m_rebakeAction = new QAction(style->standardIcon(QStyle::SP_BrowserReload), tr("Re-&bake"), this);
    m_rebakeAction->setObjectName("RebakeAction");
    m_rebakeAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    m_rebakeAction->setStatusTip(tr("Bake the edited scene again, as long as the last bake"));
    connect(m_rebakeAction, &QAction::triggered, this, &SimulationController::rebake);

    m_cancelBakeAction = new QAction(style->standardIcon(QStyle::SP_BrowserStop), tr("&Cancel Bake"), this);
    m_cancelBakeAction->setObjectName("CancelBakeAction");
    m_cancelBakeAction->setStatusTip(tr("Stop baking and keep the frames done so far"));
    connect(m_cancelBakeAction, &QAction::triggered, this, &SimulationController::cancelBake);
    m_cancelButton->setDefaultAction(m_cancelBakeAction);

    m_clearBakeAction = new QAction(tr("C&lear Bake"), this);
    m_clearBakeAction->setObjectName("ClearBakeAction");
    m_clearBakeAction->setStatusTip(tr("Drop the bake and simulate live again"));
    connect(m_clearBakeAction, &QAction::triggered, this, &SimulationController::clearBake);

    menu->addAction(m_playAction);
    menu->addAction(m_stepAction);
    menu->addAction(m_resetAction);
    menu->addSeparator();
    menu->addAction(m_bakeAction);
    menu->addAction(m_rebakeAction);
    menu->addAction(m_cancelBakeAction);
    menu->addAction(m_clearBakeAction);

    m_toolBar->addAction(m_playAction);
    m_toolBar->addAction(m_stepAction);
    m_toolBar->addAction(m_resetAction);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_bakeAction);
    m_toolBar->addAction(m_cancelBakeAction);
    m_window->menu(MainWindow::Menu::Window)->addAction(m_toolBar->toggleViewAction());
}

bool SimulationController::bakeMatchesScene() const {
    return m_bake && m_bake->bodyCount() == static_cast<size_t>(m_window->document()->bodyCount()) &&
           m_bake->frameCount() > 0;
}

bool SimulationController::bakeDrivesPlayback() const {
    return m_bake && !m_stale && bakeMatchesScene();
}

void SimulationController::updateActions() {
    const bool baking = m_job != nullptr;
    const bool playing = bakeDrivesPlayback() ? m_timeline->isPlaying() : isRunning();
    QStyle* style = QApplication::style();
    m_playAction->setText(playing ? tr("&Pause") : tr("&Play"));
    m_playAction->setIcon(style->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_playAction->setStatusTip(bakeDrivesPlayback() ? tr("Play or pause the bake") : tr("Run or pause the simulation"));
    m_playAction->setEnabled(!baking);
    m_stepAction->setEnabled(!baking && !playing);
    m_resetAction->setEnabled(!baking);
    m_bakeAction->setEnabled(!baking);
    m_rebakeAction->setEnabled(!baking && m_bake != nullptr);
    m_cancelBakeAction->setEnabled(baking);
    m_cancelBakeAction->setVisible(baking);
    m_clearBakeAction->setEnabled(!baking && m_bake != nullptr);
    m_progressBar->setVisible(baking);
    m_cancelButton->setVisible(baking);
}

void SimulationController::showStatus(const QString& message) {
    m_statusMessage = message;
    m_window->statusBar()->showMessage(message, 8000);
}

void SimulationController::updateStatusLabel() {
    QString text;
    switch (m_display) {
    case Display::EditPose:
        text = tr("edit pose");
        break;
    case Display::Live:
        text = tr("live · %1 s · frame %2 · %3 steps/s")
                   .arg(m_shownLive.time, 0, 'f', 2)
                   .arg(m_shownLive.frame)
                   .arg(std::lround(m_shownLive.stepsPerSecond));
        break;
    case Display::Baked: {
        const int frame = m_timeline->currentFrame();
        text = tr("bake · %1 s · frame %2/%3")
                   .arg(m_bake ? m_bake->frameTime(static_cast<size_t>(std::max(frame, 0))) : 0.0, 0, 'f', 2)
                   .arg(frame)
                   .arg(m_bake ? static_cast<qint64>(m_bake->frameCount()) - 1 : 0);
        if (m_stale)
            text += tr(" · stale");
        break;
    }
    }
    setStableText(m_statusLabel, text);
}

void SimulationController::setDisplay(Display display) {
    if (m_display == display)
        return;
    m_display = display;
    if (display != Display::Baked)
        m_window->overlays()->setTrailSource(nullptr);
    emit displayChanged();
}

// ---- live run ----

uint32_t SimulationController::liveExtras() const {
    const OverlayController* overlays = m_window->overlays();
    uint32_t extras = 0;
    if (overlays->isEnabled(OverlayController::Velocities))
        extras |= LiveRunner::Velocities;
    if (overlays->isEnabled(OverlayController::Contacts))
        extras |= LiveRunner::Contacts;
    return extras;
}

bool SimulationController::ensureRunner() {
    if (m_runner)
        return true;
    const Scene& scene = m_window->document()->scene();
    if (scene.bodies.empty()) {
        showStatus(tr("Nothing to simulate: the scene has no bodies."));
        return false;
    }
    Result<World> world = World::create(scene);
    if (!world) {
        QMessageBox::warning(
            m_window, tr("Simulation"),
            tr("The scene cannot be simulated:\n%1").arg(QString::fromStdString(world.error().toString())));
        return false;
    }
    m_runner = std::make_unique<LiveRunner>(std::move(world).value(), [this] {
        QMetaObject::invokeMethod(this, &SimulationController::onSnapshot, Qt::QueuedConnection);
    });
    m_runner->setExtras(liveExtras());
    m_mapper.reset(scene, m_runner->initialCentres());
    m_mapperSource = MapperSource::Live;
    m_shownLive = LiveSnapshot{};
    return true;
}

void SimulationController::stopRunner() {
    if (!m_runner)
        return;
    m_runner.reset();
    updateActions();
}

void SimulationController::onSnapshot() {
    if (!m_runner || !m_runner->takeSnapshot(m_shownLive))
        return;
    showLive();
}

void SimulationController::showLive() {
    if (m_mapperSource != MapperSource::Live || m_mapper.bodyCount() != m_shownLive.centres.size())
        return;
    QElapsedTimer timer;
    timer.start();
    m_mapper.models(*m_window->presenter(), m_shownLive.centres.data(), m_shownLive.rotations.data(), m_models);
    m_window->viewport()->setTransforms(m_models);
    m_lastPoseUpdateMs = timer.nsecsElapsed() / 1e6;
    setDisplay(Display::Live);

    OverlayFrame frame;
    fillOverlayFrame(frame, -1);
    m_window->overlays()->setFrame(std::move(frame));
    updateStatusLabel();
    emit liveStateShown(m_shownLive.frame);
}

void SimulationController::play() {
    if (m_job)
        return;
    if (bakeDrivesPlayback()) {
        m_timeline->play();
    } else if (ensureRunner()) {
        m_runner->setPlaying(true);
    }
    updateActions();
}

void SimulationController::pause() {
    m_timeline->pause();
    if (m_runner)
        m_runner->setPlaying(false);
    updateActions();
}

void SimulationController::togglePlay() {
    const bool playing = bakeDrivesPlayback() ? m_timeline->isPlaying() : isRunning();
    if (playing)
        pause();
    else
        play();
}

void SimulationController::step() {
    if (m_job)
        return;
    if (bakeDrivesPlayback()) {
        m_timeline->pause();
        m_timeline->setCurrentFrame(m_timeline->currentFrame() + 1);
        return;
    }
    if (isRunning() || !ensureRunner())
        return;
    m_runner->requestStep();
}

void SimulationController::reset() {
    if (m_job)
        return;
    stopRunner();
    m_timeline->pause();
    m_shownLive = LiveSnapshot{};
    if (bakeDrivesPlayback()) {
        if (m_timeline->currentFrame() != 0)
            m_timeline->setCurrentFrame(0); // shows frame 0
        else
            showBakeFrame(0);
    } else {
        showEditPose();
    }
    updateActions();
}

void SimulationController::showEditPose() {
    const ViewportScene& edit = m_window->presenter()->viewportScene();
    m_models.resize(edit.instances.size());
    for (size_t i = 0; i < edit.instances.size(); ++i)
        m_models[i] = edit.instances[i].model;
    if (m_window->viewport()->scene().instances.size() == m_models.size())
        m_window->viewport()->setTransforms(m_models);
    setDisplay(Display::EditPose);
    m_window->overlays()->clear();
    updateStatusLabel();
}

// ---- baked frames ----

void SimulationController::showBakeFrame(int frame) {
    if (!bakeMatchesScene())
        return;
    frame = std::clamp(frame, 0, static_cast<int>(m_bake->frameCount()) - 1);
    QElapsedTimer timer;
    timer.start();
    if (m_mapperSource != MapperSource::Baked) {
        std::vector<Vec3> reference(m_bake->bodyCount());
        const std::span<const glm::vec3> first = m_bake->positions(0);
        for (size_t i = 0; i < reference.size(); ++i)
            reference[i] = Vec3(first[i]);
        m_mapper.reset(m_window->document()->scene(), std::move(reference));
        m_mapperSource = MapperSource::Baked;
    }
    const auto f = static_cast<size_t>(frame);
    m_mapper.models(*m_window->presenter(), m_bake->positions(f).data(), m_bake->rotations(f).data(), m_models);
    if (frame == 0) {
        // Frame 0 is the edit pose by definition; take the presenter's matrices so that it is bit for bit.
        const ViewportScene& edit = m_window->presenter()->viewportScene();
        for (size_t i = 0; i < m_models.size() && i < edit.instances.size(); ++i)
            m_models[i] = edit.instances[i].model;
    }
    m_window->viewport()->setTransforms(m_models);
    m_lastPoseUpdateMs = timer.nsecsElapsed() / 1e6;
    setDisplay(Display::Baked);

    OverlayController* overlays = m_window->overlays();
    if (overlays->trailSource() != m_bake)
        overlays->setTrailSource(m_bake);
    OverlayFrame overlay;
    fillOverlayFrame(overlay, frame);
    overlays->setFrame(std::move(overlay));
    updateStatusLabel();
}

void SimulationController::fillOverlayFrame(OverlayFrame& frame, int bakeFrame) const {
    const OverlayController* overlays = m_window->overlays();
    const bool live = bakeFrame < 0;
    const size_t n = live ? m_shownLive.centres.size() : m_bake->bodyCount();
    frame.frame = live ? static_cast<int>(m_shownLive.frame) : bakeFrame;
    const bool wantCentres = overlays->isEnabled(OverlayController::Centres) ||
                             overlays->isEnabled(OverlayController::Trails) ||
                             overlays->isEnabled(OverlayController::Velocities);
    if (wantCentres) {
        frame.centres.resize(n);
        for (size_t i = 0; i < n; ++i)
            frame.centres[i] =
                live ? glm::vec3(m_shownLive.centres[i]) : m_bake->position(static_cast<size_t>(bakeFrame), i);
    }
    if (overlays->isEnabled(OverlayController::Velocities)) {
        if (live)
            frame.linearVelocities = m_shownLive.linearVelocities;
        else if (m_bake->hasVelocities()) {
            frame.linearVelocities.resize(n);
            for (size_t i = 0; i < n; ++i)
                frame.linearVelocities[i] = m_bake->linearVelocity(static_cast<size_t>(bakeFrame), i);
        }
    }
    if (overlays->isEnabled(OverlayController::Aabbs)) {
        // The viewport holds the matrices just set: each instance's mesh box, placed.
        const ViewportScene& shown = m_window->viewport()->scene();
        frame.aabbs.resize(n);
        for (size_t i = 0; i < n; ++i)
            frame.aabbs[i] = shown.instanceBounds(static_cast<int>(i));
    }
    if (overlays->isEnabled(OverlayController::Sleeping)) {
        if (live) {
            frame.sleeping = m_shownLive.sleeping;
        } else {
            // A bake does not record sleep. A sleeping body is not integrated, so its velocities are exactly zero
            // (and its pose repeats exactly); awake bodies practically never hit exact zeros.
            frame.sleeping.assign(n, 0);
            const auto f = static_cast<size_t>(bakeFrame);
            for (size_t i = 0; i < n && f > 0; ++i) {
                if (m_bake->body(i).anchor)
                    continue;
                const bool still = m_bake->hasVelocities() ? m_bake->linearVelocity(f, i) == glm::vec3(0.0f) &&
                                                                 m_bake->angularVelocity(f, i) == glm::vec3(0.0f)
                                                           : m_bake->position(f, i) == m_bake->position(f - 1, i) &&
                                                                 m_bake->rotation(f, i) == m_bake->rotation(f - 1, i);
                frame.sleeping[i] = still ? 1 : 0;
            }
        }
    }
    if (live && overlays->isEnabled(OverlayController::Contacts))
        frame.contacts = m_shownLive.contacts;
}

void SimulationController::refreshDisplay() {
    switch (m_display) {
    case Display::Live:
        showLive();
        break;
    case Display::Baked:
        showBakeFrame(m_timeline->currentFrame());
        break;
    case Display::EditPose:
        break;
    }
}

// ---- scene changes ----

void SimulationController::onSceneEdited(bool viewportRebuilds) {
    if (m_job)
        m_editedDuringBake = true;
    const bool wasLive = m_runner != nullptr;
    stopRunner();
    m_timeline->pause();
    m_shownLive = LiveSnapshot{};
    m_mapper.clear();
    m_mapperSource = MapperSource::None;
    if (m_bake && !m_stale) {
        m_stale = true;
        m_timeline->setStale(true);
    }
    if (viewportRebuilds) {
        // MainWindow rebuilds the viewport at the edit pose right after this.
        setDisplay(Display::EditPose);
        m_window->overlays()->clear();
        updateStatusLabel();
    } else {
        showEditPose();
    }
    if (wasLive)
        showStatus(tr("The scene was edited: the simulation went back to the edit pose."));
    updateActions();
}

void SimulationController::onSceneReplaced() {
    if (m_openingBake)
        return;
    if (m_job) {
        m_job.reset(); // cancels and discards: it simulated a scene that is gone
        m_progressTimer->stop();
        m_timeline->setProgress(-1.0);
    }
    stopRunner();
    m_shownLive = LiveSnapshot{};
    m_mapper.clear();
    m_mapperSource = MapperSource::None;
    setBake(nullptr, false);
    setDisplay(Display::EditPose);
    m_window->overlays()->clear();
    updateStatusLabel();
    updateActions();
}

// ---- baking ----

void SimulationController::bakeWithDialog() {
    if (m_job)
        return;
    const double fps = m_window->document()->scene().world.fps;
    const int last = m_lastBakeFrames > 0 ? m_lastBakeFrames : static_cast<int>(std::lround(kDefaultBakeSeconds * fps));
    BakeDialog dialog(fps, std::min(m_lastBakeStart, last - 1), last, m_window);
    if (dialog.exec() == QDialog::Accepted)
        startBake(dialog.lastFrame(), dialog.firstFrame());
}

void SimulationController::rebake() {
    if (m_job)
        return;
    const double fps = m_window->document()->scene().world.fps;
    if (m_lastBakeFrames > 0)
        startBake(m_lastBakeFrames, std::min(m_lastBakeStart, m_lastBakeFrames - 1));
    else
        startBake(static_cast<int>(std::lround(kDefaultBakeSeconds * fps)));
}

bool SimulationController::startBake(int lastFrame, int firstFrame) {
    if (m_job || lastFrame < 1 || firstFrame < 0 || firstFrame >= lastFrame)
        return false;
    if (m_window->analysis() && !m_window->analysis()->confirmPreflight())
        return false;
    const Scene& scene = m_window->document()->scene();
    if (scene.bodies.empty()) {
        showStatus(tr("Nothing to bake: the scene has no bodies."));
        return false;
    }
    // A bake gives the same frames on any number of threads, so it takes every core. It used to leave one to the
    // interface, which on a two-core machine meant one thread; the world's TeamPacer now steps alone while another
    // thread (a repaint, another program) keeps a core busy. A 10 s bake of ramps.obj in the editor took 0.46-0.76 s
    // on two threads against 0.70-1.01 s on one (medians 0.53 and 0.92 s; ten bakes each in two rounds by turns,
    // 2026-12-04, under Xvfb), and the interface's 20 ms timer still ticked 148 times in 3 s of a bake with a worst
    // gap of 40 ms (tst_simulation).
    WorldOptions bakeOptions;
    bakeOptions.threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
    Result<World> created = World::create(scene, bakeOptions);
    if (!created) {
        QMessageBox::warning(
            m_window, tr("Bake"),
            tr("The scene cannot be baked:\n%1").arg(QString::fromStdString(created.error().toString())));
        return false;
    }
    stopRunner();
    m_timeline->pause();
    World world = std::move(created).value();
    Bake bake = rl::startBake(world, true);
    // The .bake format carries the scene as OBJ: the source file verbatim while the scene is as it was opened.
    if (!scene.sourceObjText.empty() && m_window->document()->undoStack()->index() == 0) {
        bake.setSceneObjText(scene.sourceObjText);
    } else if (Result<std::string> obj = sceneToObjText(scene)) {
        bake.setSceneObjText(std::move(obj).value());
    }
    m_lastBakeFrames = lastFrame;
    m_lastBakeStart = firstFrame;
    m_editedDuringBake = false;
    m_job = std::make_unique<BakeJob>(
        std::move(world), std::move(bake), static_cast<size_t>(lastFrame), static_cast<size_t>(firstFrame),
        [this] { QMetaObject::invokeMethod(this, &SimulationController::onBakeFinished, Qt::QueuedConnection); });
    m_progressTimer->start();
    m_progressBar->setValue(0);
    m_timeline->setProgress(0.0, tr("starting"));
    showStatus(tr("Baking %n frames…", "", lastFrame));
    updateActions();
    return true;
}

void SimulationController::cancelBake() {
    if (m_job)
        m_job->cancel();
}

void SimulationController::onBakeProgress() {
    if (!m_job)
        return;
    const size_t done = m_job->framesDone();
    const size_t total = m_job->framesRequested();
    const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    const double left = m_job->secondsLeft();
    const QString text = left < 0.0 ? tr("frame %1 of %2").arg(done).arg(total)
                                    : tr("frame %1 of %2, %3 s left").arg(done).arg(total).arg(std::ceil(left));
    m_progressBar->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
    m_progressBar->setToolTip(text);
    m_timeline->setProgress(fraction, text);
    setStableText(m_statusLabel, tr("baking · %1").arg(text));
}

void SimulationController::onBakeFinished() {
    if (!m_job || !m_job->isFinished())
        return;
    const bool cancelled = m_job->wasCancelled();
    const double seconds = m_job->elapsedSeconds();
    auto bake = std::make_shared<const Bake>(m_job->takeBake());
    m_job.reset();
    m_progressTimer->stop();
    m_timeline->setProgress(-1.0);
    const int frames = static_cast<int>(bake->frameCount());
    setBake(bake, m_editedDuringBake);
    if (cancelled)
        showStatus(tr("Bake cancelled: kept frames 0 to %1.").arg(frames - 1));
    else if (bake->simulationStart() > 0)
        showStatus(tr("Baked frames 0 to %1 in %2 s; the simulation starts at frame %3.")
                       .arg(frames - 1)
                       .arg(seconds, 0, 'f', 1)
                       .arg(bake->simulationStart()));
    else
        showStatus(tr("Baked frames 0 to %1 in %2 s.").arg(frames - 1).arg(seconds, 0, 'f', 1));
    if (m_editedDuringBake)
        showStatus(m_statusMessage + QLatin1Char(' ') + tr("The scene was edited meanwhile, so the bake is stale."));
    updateActions();
    emit bakeFinished(cancelled);
}

void SimulationController::setBake(std::shared_ptr<const Bake> bake, bool stale) {
    m_timeline->pause();
    m_bake = std::move(bake);
    m_stale = m_bake && stale;
    m_mapperSource = m_mapperSource == MapperSource::Baked ? MapperSource::None : m_mapperSource;
    if (m_bake) {
        m_timeline->setFps(m_bake->fps());
        m_timeline->setFrameRange(0, std::max(0, static_cast<int>(m_bake->frameCount()) - 1));
    }
    m_timeline->setBake(m_bake);
    m_timeline->setStale(m_stale);
    if (m_display == Display::Baked || (m_bake && !m_stale)) {
        if (m_bake && bakeMatchesScene() && !m_stale) {
            stopRunner();
            if (m_timeline->currentFrame() != 0)
                m_timeline->setCurrentFrame(0);
            else
                showBakeFrame(0);
        } else {
            showEditPose();
        }
    }
    emit bakeChanged();
    updateActions();
    updateStatusLabel();
}

void SimulationController::clearBake() {
    if (m_job)
        return;
    setBake(nullptr, false);
    showEditPose();
}

// ---- .bake files ----

bool SimulationController::openBake(const QString& path) {
    Result<LoadedBake> loaded = loadBake(path.toStdString());
    if (!loaded) {
        QMessageBox::warning(m_window, tr("Open Bake"),
                             tr("Could not open the bake:\n%1").arg(QString::fromStdString(loaded.error().toString())));
        return false;
    }
    if (m_window->document()->isModified() && !m_window->files()->maybeSave(FileController::Reason::Open))
        return false;
    LoadedBake& result = loaded.value();
    Bake& bake = result.bake;
    const QString name = QFileInfo(path).fileName();
    Scene scene;
    QString explanation;
    if (result.centred) {
        scene = std::move(result.scene);
    } else {
        // No scene inside (or one that does not describe these bodies): an OBJ next to the file may.
        const QString sibling =
            QFileInfo(path).path() + QLatin1Char('/') + QFileInfo(path).completeBaseName() + QStringLiteral(".obj");
        bool matched = false;
        if (QFileInfo::exists(sibling)) {
            Result<Scene> objScene = importScene(sibling.toStdString());
            if (objScene && objScene->bodies.size() == bake.bodyCount()) {
                matched = true;
                for (size_t i = 0; i < bake.bodyCount() && matched; ++i) {
                    Result<BodyProperties> props = computeBodyProperties(*objScene, objScene->bodies[i]);
                    if (!props) {
                        matched = false;
                        break;
                    }
                    bake.body(i).name = objScene->bodies[i].name;
                    bake.body(i).anchor = objScene->bodies[i].anchor;
                    bake.rebaseVertexMeanOffset(i, props->vertexMean - props->com);
                }
                if (matched) {
                    scene = std::move(objScene).value();
                    explanation =
                        tr("The bake holds no scene; its shapes come from %1.").arg(QFileInfo(sibling).fileName());
                }
            }
        }
        if (!matched) {
            scene = markerScene(bake);
            explanation = tr("The bake holds no scene: each body is shown as a small box at its vertex mean. Put the "
                             "OBJ it was recorded from next to it as %1 to see the shapes.")
                              .arg(QFileInfo(path).completeBaseName() + QStringLiteral(".obj"));
        }
    }
    scene.sourcePath = path.toStdString();

    if (m_job) {
        m_job.reset();
        m_progressTimer->stop();
        m_timeline->setProgress(-1.0);
    }
    stopRunner();
    m_openingBake = true;
    m_window->document()->reset(std::move(scene), path);
    m_openingBake = false;
    m_shownLive = LiveSnapshot{};
    m_mapper.clear();
    m_mapperSource = MapperSource::None;
    const auto shared = std::make_shared<const Bake>(std::move(bake));
    m_lastBakeFrames = static_cast<int>(shared->frameCount()) - 1;
    m_lastBakeStart = static_cast<int>(shared->simulationStart());
    setBake(shared, false);
    m_window->viewport()->frameContents();
    QString message = tr("Opened %1: frames 0 to %2 at %3 Hz, %n bodies.", "", static_cast<int>(shared->bodyCount()))
                          .arg(name)
                          .arg(shared->frameCount() - 1)
                          .arg(shared->fps());
    if (!explanation.isEmpty())
        message += QLatin1Char(' ') + explanation;
    showStatus(message);
    return true;
}

} // namespace rl
