// The timeline dock's widget: a frame ruler with ticks and labels, the current-frame cursor, the baked range shaded
// (hatched when stale), bake progress, diagnostic tracks under the ruler, and playback at real time with a speed
// (0.25x to 4x) and a loop. It knows frames, not physics: the simulation controller feeds it.
#pragma once

#include <QWidget>

#include <memory>

namespace rl {

class Bake;

class TimelineWidget : public QWidget {
    Q_OBJECT
public:
    explicit TimelineWidget(QWidget* parent = nullptr);
    ~TimelineWidget() override;

    // The ruler's range, in frames (inclusive), and the frame rate its labels and playback use.
    void setFrameRange(int first, int last);
    int firstFrame() const { return m_first; }
    int lastFrame() const { return m_last; }
    void setFps(double fps);
    double fps() const { return m_fps; }

    // Baked frames [0, frameCount-1] are shaded; the diagnostic tracks come from the bake (null clears both).
    void setBake(std::shared_ptr<const Bake> bake);
    // The scene was edited after the bake: the baked range is drawn as stale.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    // Bake in progress: fraction in [0, 1] and a text such as "frame 120 of 600, 4 s left"; negative hides it.
    void setProgress(double fraction, const QString& text = QString());

    int currentFrame() const { return m_current; }
    // Moves the cursor; emits currentFrameChanged when the frame changes.
    void setCurrentFrame(int frame);

    // Real-time playback of the baked frames.
    bool isPlaying() const { return m_playing; }
    void play();
    void pause();
    void setSpeed(double speed); // clamped to [0.25, 4]
    double speed() const { return m_speed; }
    void setLoop(bool loop);
    bool loop() const { return m_loop; }

signals:
    // The cursor moved: by the user (click, drag, keys, a track click), by playback, or by setCurrentFrame.
    void currentFrameChanged(int frame);
    void playingChanged(bool playing);

private:
    int m_first = 0;
    int m_last = 250;
    double m_fps = 60.0;
    std::shared_ptr<const Bake> m_bake;
    bool m_stale = false;
    int m_current = 0;
    bool m_playing = false;
    double m_speed = 1.0;
    bool m_loop = true;
};

} // namespace rl
