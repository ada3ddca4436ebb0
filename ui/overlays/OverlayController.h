// View > Overlays: contact points and normals, velocity arrows, centres of mass, AABBs, sleeping bodies coloured
// differently and motion trails for the selected bodies. Each is a checkable action whose state persists in
// QSettings; the controller draws the enabled ones over the viewport from the OverlayFrame the simulation controller
// hands it. The viewport's overlay painter is installed only while something is to be drawn, so overlays cost
// nothing when they are off.
#pragma once

#include "overlays/OverlayFrame.h"
#include "overlays/OverlayPainter.h"

#include <QObject>

#include <deque>
#include <memory>
#include <vector>

class QAction;
class QMenu;
class QPainter;

namespace rl {

class Bake;
class Camera;
class MainWindow;

class OverlayController : public QObject {
    Q_OBJECT
public:
    enum Kind { Contacts, Velocities, Centres, Aabbs, Sleeping, Trails, KindCount };
    static constexpr int kTrailMaxGapFrames = 30; // half a second at 60 Hz: a longer straight segment would mislead
    // Trails are drawn for at most this many selected bodies (the first in body order), so that a box selection of
    // a whole pile does not turn every paint into hundreds of thousands of segments.
    static constexpr int kMaxTrailBodies = 256;

    explicit OverlayController(MainWindow* window);
    ~OverlayController() override;

    bool isEnabled(Kind kind) const { return m_enabled[kind]; }
    void setEnabled(Kind kind, bool on);
    // The checkable action of a kind (View > Overlays), and the submenu.
    QAction* action(Kind kind) const { return m_actions[kind]; }
    QAction* legendAction() const { return m_legendAction; }
    QMenu* menu() const { return m_menu; }

    // The state now on screen. Cheap to call every displayed frame. During a live run (no trail source) the trails
    // keep the centres of the frames shown; a frame number that goes backwards, jumps ahead by more than
    // kTrailMaxGapFrames or is unknown (-1) restarts them, and the same frame again only replaces the newest point.
    // Small gaps are kept because a live display slower than the simulation skips states.
    void setFrame(OverlayFrame frame);
    // Back to the edit pose: clears the frame and the trails, and gives sleeping bodies their normal look again.
    void clear();
    bool hasFrame() const { return m_hasFrame; }
    const OverlayFrame& frame() const { return m_frame; }

    // A baked run: trails are read from the bake up to the displayed frame instead of being collected, so they are
    // right while scrubbing and jumping. Null goes back to collecting from setFrame.
    void setTrailSource(std::shared_ptr<const Bake> bake);
    std::shared_ptr<const Bake> trailSource() const { return m_trailSource; }
    // How many frames back a trail reaches (at 60 Hz the default is two seconds).
    void setTrailLength(int frames);
    int trailLength() const { return m_trailLength; }
    // The trail of one body as drawn now: world centres, oldest first (empty when trails are off or unknown).
    std::vector<glm::vec3> trail(int body) const;

    // Whether the viewport currently has this controller's overlay painter.
    bool isPainterInstalled() const { return m_painterInstalled; }
    // Figures of the painter, measured around the paint function (QElapsedTimer): for the status read-out and tests.
    int paintCount() const { return m_paintCount; }
    double lastPaintMs() const { return m_lastPaintMs; }       // wall time
    double lastPaintCpuMs() const { return m_lastPaintCpuMs; } // CPU time of the painting thread
    const OverlayPaintStats& lastPaintStats() const { return m_lastStats; }

    // The painter itself, public so that tests and tools can paint an overlay into any QPainter.
    void paint(QPainter& painter, const Camera& camera, const QSize& size);

signals:
    void enabledChanged(int kind, bool on);

private:
    bool anyPaintedKind() const;
    void updatePainter();
    void applySleeping();
    void recordTrail();
    std::vector<OverlayLegendEntry> legendEntries() const;

    MainWindow* m_window;
    QMenu* m_menu = nullptr;
    QAction* m_actions[KindCount] = {};
    QAction* m_legendAction = nullptr;
    bool m_enabled[KindCount] = {};
    OverlayFrame m_frame;
    bool m_hasFrame = false;
    bool m_painterInstalled = false;

    // Sleeping look: instances this controller flagged kInstanceSleeping, so that exactly those are restored.
    std::vector<uint8_t> m_markedSleeping;

    // Live trails: the centres of every body in the displayed frames of the last m_trailLength frames, oldest first.
    struct TrailSample {
        int frame = -1;
        std::vector<glm::vec3> centres;
    };
    std::deque<TrailSample> m_history;
    std::shared_ptr<const Bake> m_trailSource;
    int m_trailLength = 120;
    std::vector<std::vector<glm::vec3>> m_trailScratch;

    int m_paintCount = 0;
    double m_lastPaintMs = 0.0;
    double m_lastPaintCpuMs = 0.0;
    OverlayPaintStats m_lastStats;
};

} // namespace rl
