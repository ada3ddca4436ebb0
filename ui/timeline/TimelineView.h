// The timeline's canvas: the frame ruler (ticks, labels, baked range, progress, current-frame cursor) and the
// diagnostic tracks under it. It maps x to frames and draws; TimelineWidget holds the state and runs playback.
#pragma once

#include <QPixmap>
#include <QWidget>

#include <vector>

namespace rl {

class TimelineWidget;

// One ruler label as drawn: its text and where it sits, in view coordinates.
struct RulerLabel {
    double frame = 0.0;
    QString text;
    QRectF rect;
};

class TimelineView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kRulerHeight = 40;
    static constexpr int kTrackHeight = 30;    // a track's height when the view has no room to spare
    static constexpr int kTrackMaxHeight = 72; // tracks share spare height up to this
    static constexpr int kGutterWidth = 132;   // track names and scales on the left

    explicit TimelineView(TimelineWidget* timeline);
    ~TimelineView() override;

    // Which frames are visible, as a fractional range [start, end].
    double viewStart() const { return m_viewStart; }
    double viewEnd() const { return m_viewEnd; }
    void setViewRange(double start, double end); // clamped to a sensible span; stops following the frame range
    void zoomToFit();                            // shows the whole frame range and follows it from now on
    // Zooms by factor (> 1 zooms in) keeping the given frame at the same x.
    void zoomAround(double frame, double factor);
    void panByPixels(double dx);
    // Scrolls so that the frame is visible (playback and keys keep the cursor in view).
    void ensureVisible(int frame);

    // Mapping between x (view coordinates) and frames. frameAt rounds to the nearest frame and clamps to the range.
    QRectF plotRect() const; // x extent of the ruler and the tracks' charts, full height
    double xForFrame(double frame) const;
    double frameAtX(double x) const; // unclamped, fractional
    int frameAt(double x) const;

    QRect rulerRect() const;
    int trackCount() const { return static_cast<int>(m_tracks.size()); }
    QRect trackRect(int index) const; // empty when the tracks are hidden
    QString trackName(int index) const;
    // The ruler's labels as they are drawn at the current size and zoom.
    std::vector<RulerLabel> rulerLabels() const;
    // The tooltip shown when hovering at pos (frame, values with units, stale note); empty where there is none.
    QString toolTipAt(const QPoint& pos) const;

    // Called by TimelineWidget when its state changes.
    void rebuildTracks(); // the bake changed
    void invalidate();    // anything drawn in the background changed
    void cursorMoved(int from, int to);
    void progressChanged(); // repaints the progress strip only
    int preferredHeight() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    struct Series {
        QString name;
        QColor color;
        qreal width = 1.0;
        std::vector<float> values;
    };
    enum class Unit { Energy, Length, Count };
    struct Track {
        QString name;
        Unit unit = Unit::Count;
        std::vector<Series> series;
        bool fill = false; // a single series drawn as an area
        float lo = 0.0f;   // the scale, over the whole bake
        float hi = 1.0f;
    };
    struct Ticks {
        double major = 1.0; // frames between labelled ticks
        double minor = 1.0; // frames between small ticks
        int decimals = 0;   // of the seconds labels
    };

    void fitIfFollowing();
    Ticks chooseTicks() const;
    QString labelText(double frame, const Ticks& ticks) const;
    QString cursorText(int frame) const;
    QString formatValue(const Track& track, double value) const;
    int trackHeight() const;
    int trackAt(const QPoint& pos) const;
    QRect cursorRect(int frame) const;
    void rebuildCache();
    void paintRuler(QPainter& p);
    void paintTrack(QPainter& p, const Track& track, const QRect& r);
    void paintSeries(QPainter& p, const Series& s, const QRect& r, float lo, float hi, bool fill);
    void paintProgress(QPainter& p);
    void paintCursor(QPainter& p);
    void scrubTo(double x);

    TimelineWidget* m_timeline;
    std::vector<Track> m_tracks;
    double m_viewStart = 0.0;
    double m_viewEnd = 250.0;
    bool m_followRange = true; // the view tracks the frame range until the user zooms or pans
    bool m_scrubbing = false;
    bool m_panning = false;
    double m_panLastX = 0.0;
    QPixmap m_cache; // everything but the cursor, so that a scrub only blits and draws the cursor
    bool m_cacheValid = false;
    int m_cursorBoxWidth = 40;
};

} // namespace rl
