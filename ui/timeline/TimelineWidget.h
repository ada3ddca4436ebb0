// The timeline dock's widget: a frame ruler with ticks and labels, the current-frame cursor, the baked range shaded
// (hatched when stale), bake progress, diagnostic tracks under the ruler, and playback at real time with a speed
// (0.25x to 4x) and a loop. It knows frames, not physics: the simulation controller feeds it.
//
// Keys when the timeline has focus: Left / Right step a frame, Home / End jump to the first / last frame, Space plays
// or pauses, Ctrl+T switches the ruler between frames and seconds. Mouse: click or drag on the ruler or a track to
// scrub, wheel zooms around the current frame (around the pointer when the current frame is out of view), Ctrl+wheel,
// Shift+wheel, a horizontal wheel or a middle drag pans.
#pragma once

#include <QElapsedTimer>
#include <QWidget>

#include <functional>
#include <memory>

class QAction;
class QComboBox;
class QLabel;
class QSpinBox;
class QTimer;
class QToolButton;

namespace rl {

class Bake;
class TimelineView;

class TimelineWidget : public QWidget {
    Q_OBJECT
public:
    explicit TimelineWidget(QWidget* parent = nullptr);
    ~TimelineWidget() override;

    // The ruler's range, in frames (inclusive), and the frame rate its labels and playback use.
    void setFrameRange(int first, int last);
    int firstFrame() const { return m_first; }
    int lastFrame() const { return m_last; }
    void setFps(double fps); // ignored unless finite and positive
    double fps() const { return m_fps; }

    // Baked frames [0, frameCount-1] are shaded; the diagnostic tracks come from the bake (null clears both).
    // The ruler's range grows to hold the baked frames and the frame rate becomes the bake's. A bake must not change
    // while it is set: after it grows, set it again.
    void setBake(std::shared_ptr<const Bake> bake);
    std::shared_ptr<const Bake> bake() const { return m_bake; }
    // The scene was edited after the bake: the baked range is drawn as stale.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    // Bake in progress: fraction in [0, 1] and a text such as "frame 120 of 600, 4 s left"; negative hides it.
    // The ruler draws the fraction as a bar from its first frame towards its last.
    void setProgress(double fraction, const QString& text = QString());
    double progress() const { return m_progress; }
    QString progressText() const { return m_progressText; }

    int currentFrame() const { return m_current; }
    // Moves the cursor; emits currentFrameChanged when the frame changes.
    void setCurrentFrame(int frame);

    // Real-time playback of the baked frames.
    bool isPlaying() const { return m_playing; }
    void setSpeed(double speed); // clamped to [0.25, 4]
    double speed() const { return m_speed; }
    void setLoop(bool loop);
    bool loop() const { return m_loop; }
    // The frames playback runs over: the baked frames within the ruler's range when a bake exists, else the range.
    int playFirst() const;
    int playLast() const;

    // Playback reads the time from this clock (monotonic, nanoseconds) so that tests can drive it exactly; an empty
    // function restores the real clock (QElapsedTimer).
    using Clock = std::function<qint64()>;
    void setClock(Clock clock);

    // Ruler labels in seconds (true) or frames.
    void setShowSeconds(bool seconds);
    bool showSeconds() const { return m_showSeconds; }
    // The diagnostic tracks under the ruler can be folded away.
    void setTracksVisible(bool visible);
    bool tracksVisible() const { return m_tracksVisible; }

    // Actions behind the toolbar buttons, for the main window's menus (they carry no shortcuts of their own: the
    // keys above work while the timeline has focus).
    QAction* playAction() const { return m_playAction; }
    QAction* firstFrameAction() const { return m_firstAction; }
    QAction* previousFrameAction() const { return m_previousAction; }
    QAction* nextFrameAction() const { return m_nextAction; }
    QAction* lastFrameAction() const { return m_lastAction; }
    QAction* loopAction() const { return m_loopAction; }

    // The canvas with the ruler and the tracks.
    TimelineView* view() const { return m_view; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

public slots:
    void play();
    void pause();
    void togglePlayback();
    void stepForward();
    void stepBackward();
    void jumpToFirst();
    void jumpToLast();
    // Shows the whole range on the ruler again after zooming or panning.
    void zoomToFit();
    // Moves the cursor to where the clock says playback is; the playback timer calls it.
    void advancePlayback();

signals:
    // The cursor moved: by the user (click, drag, keys, a track click), by playback, or by setCurrentFrame.
    void currentFrameChanged(int frame);
    void playingChanged(bool playing);
    void speedChanged(double speed);
    void loopChanged(bool loop);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    void createToolBar(QWidget* bar);
    qint64 now() const;
    void anchorPlayback();
    void updateTimerInterval();
    void updateFrameReadout();
    void updateSpeedCombo();
    bool handlesKey(const QKeyEvent* event) const;

    int m_first = 0;
    int m_last = 250;
    double m_fps = 60.0;
    std::shared_ptr<const Bake> m_bake;
    bool m_stale = false;
    double m_progress = -1.0;
    QString m_progressText;
    int m_current = 0;
    bool m_playing = false;
    double m_speed = 1.0;
    bool m_loop = true;
    bool m_showSeconds = false;
    bool m_tracksVisible = true;

    // Playback position = m_anchorFrame + (now - m_anchorTime) * fps * speed, wrapped or stopped at the end.
    Clock m_clock;
    QElapsedTimer m_realClock;
    qint64 m_anchorTime = 0;
    double m_anchorFrame = 0.0;
    bool m_advancing = false; // setCurrentFrame called by playback itself, so no re-anchoring
    QTimer* m_timer = nullptr;

    TimelineView* m_view = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_firstAction = nullptr;
    QAction* m_previousAction = nullptr;
    QAction* m_nextAction = nullptr;
    QAction* m_lastAction = nullptr;
    QAction* m_loopAction = nullptr;
    QAction* m_secondsAction = nullptr;
    QAction* m_tracksAction = nullptr;
    QAction* m_fitAction = nullptr;
    QSpinBox* m_frameSpin = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_progressLabel = nullptr;
    QComboBox* m_speedCombo = nullptr;
};

} // namespace rl
