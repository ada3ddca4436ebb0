// Simulation menu and toolbar: live run on a worker thread (Play, Pause, Step, Reset), background bake, playback and
// scrubbing of the bake through the timeline dock, and opening .bake files.
//
// Which run Space, Step (→) and Reset (Ctrl+R) act on: while a bake is current (made from the scene as it is now), the
// timeline owns the viewport, so Space plays or pauses the bake, → shows the next baked frame and Ctrl+R goes back to
// frame 0 (which is the edit pose). With no bake, or a stale one (the scene was edited after it), they drive the live
// simulation: Space runs or pauses it, → steps one frame while paused, Ctrl+R returns to the edit pose. Scrubbing a
// stale bake still shows its frames while its bodies match the scene; Re-bake replaces it, Clear Bake drops it.
// Simulation never modifies the document: an edit during a live run ends the run and shows the edited pose.
#pragma once

#include "simulation/LiveRunner.h"
#include "simulation/PoseMapper.h"

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

class QAction;
class QLabel;
class QProgressBar;
class QTimer;
class QToolBar;
class QToolButton;

namespace rl {

class Bake;
class BakeJob;
class MainWindow;
class TimelineWidget;

class SimulationController : public QObject {
    Q_OBJECT
public:
    // What the viewport shows: the document's edit pose, a state of the live run, or a baked frame.
    enum class Display { EditPose, Live, Baked };

    explicit SimulationController(MainWindow* window);
    ~SimulationController() override;

    // The bake the timeline shows, or null. Shared so that exporters and panels can hold it while a new one replaces
    // it.
    std::shared_ptr<const Bake> currentBake() const { return m_bake; }
    // Opens a .bake (ours or the original project's) for playback; ours also restores the scene from its OBJ part.
    // A file without a scene shows each body as a small marker box at its vertex mean (statusMessage() says so),
    // unless an OBJ of the same base name lies next to it and has as many objects as the bake has bodies.
    bool openBake(const QString& path);
    TimelineWidget* timeline() const { return m_timeline; }

    Display display() const { return m_display; }
    // True while a current bake drives Space, Step and Reset (see the rule at the top).
    bool bakeDrivesPlayback() const;
    bool isBakeStale() const { return m_stale; }
    bool isRunning() const { return m_runner && m_runner->isPlaying(); }
    // Frame and simulated time of the live state on screen (0 at the edit pose).
    qint64 liveFrame() const { return m_shownLive.frame; }
    double liveTime() const { return m_shownLive.time; }

    // Starts a background bake of frames 0..lastFrame after the pre-flight check; false when it did not start.
    // The simulation starts at firstFrame (below lastFrame); the frames before it hold the edit pose.
    bool startBake(int lastFrame, int firstFrame = 0);
    bool isBaking() const { return m_job != nullptr; }
    // Stops the bake in progress; the frames done so far become the bake.
    void cancelBake();
    // The last message the controller put in the status bar (also for tests).
    QString statusMessage() const { return m_statusMessage; }
    // CPU time of the last pose update (state to matrices to viewport), ms, measured with QElapsedTimer.
    double lastPoseUpdateMs() const { return m_lastPoseUpdateMs; }

public slots:
    void play();
    void pause();
    void togglePlay();
    void step();
    void reset();
    void bakeWithDialog();
    void rebake();
    void clearBake();

signals:
    void bakeChanged();
    void bakeFinished(bool cancelled);
    // A live state reached the viewport.
    void liveStateShown(qint64 frame);
    void displayChanged();

private:
    void createActions();
    void updateActions();
    void updateStatusLabel();
    void showStatus(const QString& message);

    bool ensureRunner();
    void stopRunner();
    void onSnapshot();
    void showLive();
    void showBakeFrame(int frame);
    void showEditPose();
    void setDisplay(Display display);
    void refreshDisplay();
    void fillOverlayFrame(OverlayFrame& frame, int bakeFrame) const;
    uint32_t liveExtras() const;
    bool bakeMatchesScene() const;

    void onSceneEdited(bool viewportRebuilds);
    void onSceneReplaced();
    void onBakeFinished();
    void onBakeProgress();
    void setBake(std::shared_ptr<const Bake> bake, bool stale);

    MainWindow* m_window;
    TimelineWidget* m_timeline = nullptr;
    std::shared_ptr<const Bake> m_bake;
    bool m_stale = false;
    Display m_display = Display::EditPose;

    std::unique_ptr<LiveRunner> m_runner;
    LiveSnapshot m_shownLive; // the live state on screen (or the last one)

    std::unique_ptr<BakeJob> m_job;
    bool m_editedDuringBake = false;
    int m_lastBakeFrames = -1; // the last bake's last frame, for Re-bake and the dialog's default
    int m_lastBakeStart = 0;   // and the frame its simulation started at
    QTimer* m_progressTimer = nullptr;

    // Pose mapping for the state on screen; its reference centres come from the live world or bake frame 0.
    enum class MapperSource { None, Live, Baked };
    PoseMapper m_mapper;
    MapperSource m_mapperSource = MapperSource::None;
    std::vector<glm::mat4> m_models;
    double m_lastPoseUpdateMs = 0.0;
    bool m_openingBake = false;

    QAction* m_playAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_resetAction = nullptr;
    QAction* m_bakeAction = nullptr;
    QAction* m_rebakeAction = nullptr;
    QAction* m_cancelBakeAction = nullptr;
    QAction* m_clearBakeAction = nullptr;
    QToolBar* m_toolBar = nullptr;
    QLabel* m_statusLabel = nullptr;
    QProgressBar* m_progressBar = nullptr;
    QToolButton* m_cancelButton = nullptr;
    QString m_statusMessage;
};

} // namespace rl
