#include "overlays/OverlayController.h"

#include "MainWindow.h"
#include "bake/Bake.h"
#include "viewport/Viewport.h"

#include <QAction>
#include <QElapsedTimer>
#include <QMenu>
#include <QPainter>
#include <QSettings>

#include <algorithm>
#include <ctime>

namespace rl {

namespace {

// CPU time of the calling thread: on a loaded machine wall time also counts other processes' turns.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

struct KindInfo {
    const char* objectName;
    const char* settingsKey;
    const char* text;
    const char* statusTip;
};

// Declared once: the action object names (tests look them up) and the QSettings keys.
const KindInfo kKinds[OverlayController::KindCount] = {
    {"OverlayContactsAction", "overlays/contacts",
     QT_TRANSLATE_NOOP("rl::OverlayController", "&Contact Points and Normals"),
     QT_TRANSLATE_NOOP("rl::OverlayController", "Show contact points and their normals")},
    {"OverlayVelocitiesAction", "overlays/velocities", QT_TRANSLATE_NOOP("rl::OverlayController", "&Velocities"),
     QT_TRANSLATE_NOOP("rl::OverlayController",
                       "Show an arrow per body along its velocity, longer the faster it moves (capped)")},
    {"OverlayCentresAction", "overlays/centres", QT_TRANSLATE_NOOP("rl::OverlayController", "Centres of &Mass"),
     QT_TRANSLATE_NOOP("rl::OverlayController", "Mark each body's centre of mass with a cross")},
    {"OverlayAabbsAction", "overlays/aabbs", QT_TRANSLATE_NOOP("rl::OverlayController", "&Bounding Boxes"),
     QT_TRANSLATE_NOOP("rl::OverlayController", "Show each body's axis-aligned bounding box (AABB)")},
    {"OverlaySleepingAction", "overlays/sleeping", QT_TRANSLATE_NOOP("rl::OverlayController", "&Sleeping Bodies"),
     QT_TRANSLATE_NOOP("rl::OverlayController", "Draw sleeping bodies washed out")},
    {"OverlayTrailsAction", "overlays/trails",
     QT_TRANSLATE_NOOP("rl::OverlayController", "Motion &Trails of the Selection"),
     QT_TRANSLATE_NOOP("rl::OverlayController", "Trace the path of the selected bodies over the last frames")},
};
constexpr const char* kLegendKey = "overlays/legend";
constexpr size_t kSleepingBatchThreshold = 32;

} // namespace

OverlayController::OverlayController(MainWindow* window) : QObject(window), m_window(window) {
    m_menu = new QMenu(tr("&Overlays"), window);
    m_menu->setObjectName("OverlaysMenu");
    window->menu(MainWindow::Menu::View)->addMenu(m_menu);

    QSettings settings;
    for (int k = 0; k < KindCount; ++k) {
        const auto kind = static_cast<Kind>(k);
        auto* action = new QAction(tr(kKinds[k].text), this);
        action->setObjectName(QLatin1String(kKinds[k].objectName));
        action->setStatusTip(tr(kKinds[k].statusTip));
        action->setCheckable(true);
        m_actions[k] = action;
        m_menu->addAction(action);
        connect(action, &QAction::toggled, this, [this, kind](bool on) { setEnabled(kind, on); });
        if (k == Sleeping)
            m_menu->addSeparator(); // drawn over the frame above, the bodies' look and the selection's trails below
    }
    m_menu->addSeparator();
    m_legendAction = new QAction(tr("Show &Legend"), this);
    m_legendAction->setObjectName("OverlayLegendAction");
    m_legendAction->setStatusTip(tr("Explain the overlay colours in a corner of the viewport"));
    m_legendAction->setCheckable(true);
    m_legendAction->setChecked(settings.value(kLegendKey, true).toBool());
    m_menu->addAction(m_legendAction);
    connect(m_legendAction, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(kLegendKey, on);
        m_window->viewport()->requestRender();
    });

    for (int k = 0; k < KindCount; ++k)
        m_actions[k]->setChecked(settings.value(kKinds[k].settingsKey, false).toBool());

    // A rebuilt viewport shows the edit pose with fresh instances (none flagged sleeping by us).
    connect(window, &MainWindow::viewportRebuilt, this, [this] {
        m_markedSleeping.clear();
        clear();
    });
    connect(window, &MainWindow::selectionChanged, this, [this] {
        if (m_enabled[Trails] && m_painterInstalled)
            m_window->viewport()->requestRender();
    });
}

OverlayController::~OverlayController() = default;

void OverlayController::setEnabled(Kind kind, bool on) {
    if (kind < 0 || kind >= KindCount || m_enabled[kind] == on)
        return;
    m_enabled[kind] = on;
    if (m_actions[kind]->isChecked() != on)
        m_actions[kind]->setChecked(on); // re-enters through toggled, which finds nothing to do
    QSettings().setValue(kKinds[kind].settingsKey, on);
    if (kind == Trails && !on)
        m_history.clear();
    if (kind == Trails && on && m_hasFrame)
        recordTrail();
    if (kind == Sleeping)
        applySleeping();
    updatePainter();
    emit enabledChanged(kind, on);
}

void OverlayController::setFrame(OverlayFrame frame) {
    m_frame = std::move(frame);
    m_hasFrame = true;
    if (m_enabled[Trails])
        recordTrail();
    if (m_enabled[Sleeping] || std::find(m_markedSleeping.begin(), m_markedSleeping.end(), 1) != m_markedSleeping.end())
        applySleeping();
    updatePainter();
}

void OverlayController::clear() {
    m_frame = OverlayFrame{};
    m_hasFrame = false;
    m_history.clear();
    applySleeping();
    updatePainter();
}

void OverlayController::setTrailSource(std::shared_ptr<const Bake> bake) {
    m_trailSource = std::move(bake);
    m_history.clear();
    if (m_enabled[Trails] && m_hasFrame)
        recordTrail();
    if (m_painterInstalled)
        m_window->viewport()->requestRender();
}

void OverlayController::setTrailLength(int frames) {
    m_trailLength = std::max(frames, 2);
    while (!m_history.empty() && m_history.front().frame <= m_history.back().frame - m_trailLength)
        m_history.pop_front();
    if (m_painterInstalled)
        m_window->viewport()->requestRender();
}

void OverlayController::recordTrail() {
    if (m_trailSource || m_frame.centres.empty())
        return;
    const int frame = m_frame.frame;
    const bool sameBodies = !m_history.empty() && m_history.back().centres.size() == m_frame.centres.size();
    if (sameBodies && frame >= 0 && frame == m_history.back().frame) {
        m_history.back().centres = m_frame.centres; // the same frame shown again (a toggle, a redraw)
        return;
    }
    // A live display skips states when it is slower than the simulation, so a short gap forward keeps the trail;
    // backwards, far ahead or an unknown frame means a new run or a reset, and the old path does not lead here.
    if (!sameBodies || frame < 0 || frame < m_history.back().frame ||
        frame - m_history.back().frame > kTrailMaxGapFrames)
        m_history.clear();
    std::vector<glm::vec3> storage;
    while (!m_history.empty() && m_history.front().frame <= frame - m_trailLength) {
        storage = std::move(m_history.front().centres); // reuse the oldest frame's storage for the newest
        m_history.pop_front();
    }
    storage.assign(m_frame.centres.begin(), m_frame.centres.end());
    m_history.push_back({frame, std::move(storage)});
}

std::vector<glm::vec3> OverlayController::trail(int body) const {
    std::vector<glm::vec3> points;
    if (!m_enabled[Trails] || !m_hasFrame || body < 0)
        return points;
    if (m_trailSource) {
        const Bake& bake = *m_trailSource;
        if (m_frame.frame < 0 || static_cast<size_t>(body) >= bake.bodyCount() || bake.frameCount() == 0)
            return points;
        const int last = std::min(m_frame.frame, static_cast<int>(bake.frameCount()) - 1);
        const int first = std::max(0, last - m_trailLength + 1);
        points.reserve(static_cast<size_t>(last - first + 1));
        for (int f = first; f <= last; ++f)
            points.push_back(bake.position(static_cast<size_t>(f), static_cast<size_t>(body)));
        return points;
    }
    points.reserve(m_history.size());
    for (const TrailSample& sample : m_history)
        if (static_cast<size_t>(body) < sample.centres.size())
            points.push_back(sample.centres[body]);
    return points;
}

bool OverlayController::anyPaintedKind() const {
    return m_enabled[Contacts] || m_enabled[Velocities] || m_enabled[Centres] || m_enabled[Aabbs] || m_enabled[Trails];
}

void OverlayController::updatePainter() {
    Viewport* viewport = m_window->viewport();
    const bool want = m_hasFrame && anyPaintedKind();
    if (want != m_painterInstalled) {
        m_painterInstalled = want;
        if (want)
            viewport->setOverlayPainter(
                [this](QPainter& painter, const Camera& camera, const QSize& size) { paint(painter, camera, size); });
        else
            viewport->setOverlayPainter({});
    }
    viewport->requestRender();
}

void OverlayController::applySleeping() {
    // The renderer washes out instances flagged kInstanceSleeping (mesh.vert), so the body keeps its own colour and
    // only the flag changes. Only flags this controller set are ever cleared.
    Viewport* viewport = m_window->viewport();
    const std::vector<ViewportInstance>& instances = viewport->scene().instances;
    m_markedSleeping.resize(instances.size(), 0);
    const bool on = m_enabled[Sleeping] && m_hasFrame;
    std::vector<int> changed;
    for (size_t i = 0; i < instances.size(); ++i) {
        const bool want = on && i < m_frame.sleeping.size() && m_frame.sleeping[i] != 0;
        const bool has = (instances[i].flags & kInstanceSleeping) != 0;
        if ((want && !has) || (!want && m_markedSleeping[i])) {
            changed.push_back(static_cast<int>(i));
            m_markedSleeping[i] = want ? 1 : 0;
        }
    }
    if (changed.empty())
        return;
    // setInstanceAppearance re-gathers every instance per call, so a whole pile falling asleep in one frame would
    // cost n^2; past a few changes, one setScene with the flags changed is cheaper (measured in tst_overlays).
    // (Not during a gizmo drag: setScene cancels it.)
    if (changed.size() > kSleepingBatchThreshold && !viewport->isTransforming()) {
        ViewportScene scene = viewport->scene();
        for (int i : changed)
            scene.instances[i].flags ^= kInstanceSleeping;
        viewport->setScene(std::move(scene));
        return;
    }
    for (int i : changed)
        viewport->setInstanceAppearance(i, instances[i].colour, instances[i].flags ^ kInstanceSleeping);
}

std::vector<OverlayLegendEntry> OverlayController::legendEntries() const {
    using Glyph = OverlayLegendEntry::Glyph;
    std::vector<OverlayLegendEntry> entries;
    if (!m_legendAction->isChecked())
        return entries;
    if (m_enabled[Contacts]) {
        entries.push_back({tr("Contact point"), overlay_colours::contact(), Glyph::Dot});
        entries.push_back({tr("Contact normal"), overlay_colours::normal(), Glyph::Line});
    }
    if (m_enabled[Velocities])
        entries.push_back({tr("Velocity"), overlay_colours::velocity(), Glyph::Arrow});
    if (m_enabled[Centres])
        entries.push_back({tr("Centre of mass"), overlay_colours::centre(), Glyph::Cross});
    if (m_enabled[Aabbs])
        entries.push_back({tr("Bounding box"), overlay_colours::aabb(), Glyph::Box});
    if (m_enabled[Sleeping])
        entries.push_back({tr("Sleeping (washed out)"), overlay_colours::sleeping(), Glyph::Swatch});
    if (m_enabled[Trails])
        entries.push_back({tr("Trail of the selection"), overlay_colours::trail(), Glyph::Line});
    return entries;
}

void OverlayController::paint(QPainter& painter, const Camera& camera, const QSize& size) {
    QElapsedTimer timer;
    timer.start();
    const double cpuStart = threadCpuMs();
    OverlayPaintInput input;
    input.frame = m_hasFrame ? &m_frame : nullptr;
    input.contacts = m_enabled[Contacts];
    input.velocities = m_enabled[Velocities];
    input.centres = m_enabled[Centres];
    input.aabbs = m_enabled[Aabbs];
    m_trailScratch.clear();
    if (m_enabled[Trails]) {
        const QList<int> selected = m_window->selectedBodies();
        for (qsizetype i = 0; i < selected.size() && i < kMaxTrailBodies; ++i)
            if (std::vector<glm::vec3> points = trail(selected[i]); points.size() > 1)
                m_trailScratch.push_back(std::move(points));
    }
    input.trails = &m_trailScratch;
    input.legend = legendEntries();
    m_lastStats = paintOverlays(painter, camera, size, input);
    ++m_paintCount;
    m_lastPaintMs = static_cast<double>(timer.nsecsElapsed()) * 1e-6;
    m_lastPaintCpuMs = threadCpuMs() - cpuStart;
}

} // namespace rl
