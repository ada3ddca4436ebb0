#include "timeline/TimelineView.h"

#include "bake/Bake.h"
#include "timeline/TimelineWidget.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl {

namespace {

constexpr int kBakeBarHeight = 5;     // the baked range (or the bake's progress) along the ruler's bottom
constexpr int kCursorBoxHeight = 18;  // the current frame's number at the top of the ruler
constexpr double kLabelGap = 14.0;    // pixels kept free between two ruler labels
constexpr double kMinorSpacing = 6.0; // minor ticks closer than this are left out
constexpr int kPlotMarginLeft = 10;   // between the gutter and frame x of the view's start
constexpr int kPlotMarginRight = 12;
constexpr double kMaxPixelsPerFrame = 80.0; // zooming in stops here
constexpr double kWheelZoom = 1.25;         // per wheel notch

struct Colors {
    QColor window, base, dimWindow, dimBase, border, grid, text, muted, accent, accentText;
    QColor baked{66, 133, 214};
    QColor stale{230, 140, 40};
    QColor progress{58, 168, 92};
};

Colors colorsFor(const QPalette& pal) {
    Colors c;
    c.window = pal.color(QPalette::Window);
    c.base = pal.color(QPalette::Base);
    const bool dark = c.base.lightness() < 128;
    c.dimWindow = dark ? c.window.darker(125) : c.window.darker(108);
    c.dimBase = dark ? c.base.darker(130) : c.base.darker(104);
    c.border = pal.color(QPalette::Mid);
    c.grid = pal.color(QPalette::Mid);
    c.grid.setAlpha(dark ? 90 : 60);
    c.text = pal.color(QPalette::WindowText);
    c.muted = c.text;
    c.muted.setAlpha(150);
    c.accent = pal.color(QPalette::Highlight);
    c.accentText = pal.color(QPalette::HighlightedText);
    return c;
}

QColor withAlpha(QColor c, int alpha) {
    c.setAlpha(alpha);
    return c;
}

QFont smallFont(const QFont& base, double scale, bool bold = false) {
    QFont f = base;
    if (f.pointSizeF() > 0)
        f.setPointSizeF(std::max(7.0, f.pointSizeF() * scale));
    else
        f.setPixelSize(std::max(9, static_cast<int>(f.pixelSize() * scale)));
    f.setBold(bold);
    return f;
}

bool nearlyIntegral(double v) {
    return std::abs(v - std::round(v)) < 1e-6;
}

// "m:ss.d" once times reach a minute, else plain seconds.
QString formatSeconds(double seconds, int decimals, bool minutes) {
    if (!minutes)
        return QString::number(seconds, 'f', decimals);
    const bool negative = seconds < 0.0;
    const double a = std::abs(seconds);
    const int m = static_cast<int>(std::floor(a / 60.0 + 1e-9));
    const double s = a - 60.0 * m;
    QString text = QStringLiteral("%1:%2").arg(m).arg(QString::number(std::max(0.0, s), 'f', decimals),
                                                      decimals > 0 ? 3 + decimals : 2, QLatin1Char('0'));
    return negative ? QLatin1Char('-') + text : text;
}

} // namespace

TimelineView::TimelineView(TimelineWidget* timeline) : QWidget(timeline), m_timeline(timeline) {
    setObjectName("TimelineView");
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    fitIfFollowing();
}

TimelineView::~TimelineView() = default;

// ---- view range --------------------------------------------------------------------------------------------------

void TimelineView::fitIfFollowing() {
    if (!m_followRange)
        return;
    const double first = m_timeline->firstFrame();
    const double last = m_timeline->lastFrame();
    const double pad = std::max(1.0, (last - first) * 0.02);
    m_viewStart = first - pad;
    m_viewEnd = last + pad;
}

void TimelineView::zoomToFit() {
    m_followRange = true;
    fitIfFollowing();
    invalidate();
}

void TimelineView::setViewRange(double start, double end) {
    if (!std::isfinite(start) || !std::isfinite(end))
        return;
    if (end < start)
        std::swap(start, end);
    const double first = m_timeline->firstFrame();
    const double last = m_timeline->lastFrame();
    const double fitSpan = (last - first) + 2.0 * std::max(1.0, (last - first) * 0.02);
    const double minSpan = std::max(2.0, plotRect().width() / kMaxPixelsPerFrame);
    const double maxSpan = std::max(minSpan, fitSpan * 4.0);
    const double span = std::clamp(end - start, minSpan, maxSpan);
    double centre = 0.5 * (start + end);
    // Keep some of the range in view: the centre may not leave the range by more than half a view.
    centre = std::clamp(centre, first - 0.5 * span, last + 0.5 * span);
    m_viewStart = centre - 0.5 * span;
    m_viewEnd = centre + 0.5 * span;
    m_followRange = false;
    invalidate();
}

void TimelineView::zoomAround(double frame, double factor) {
    if (!(factor > 0.0))
        return;
    const double span = m_viewEnd - m_viewStart;
    const double first = m_timeline->firstFrame();
    const double last = m_timeline->lastFrame();
    const double fitSpan = (last - first) + 2.0 * std::max(1.0, (last - first) * 0.02);
    const double minSpan = std::max(2.0, plotRect().width() / kMaxPixelsPerFrame);
    const double newSpan = std::clamp(span / factor, minSpan, std::max(minSpan, fitSpan * 4.0));
    const double t = (frame - m_viewStart) / span; // where the frame sits, kept as it is
    m_viewStart = frame - t * newSpan;
    m_viewEnd = m_viewStart + newSpan;
    m_followRange = false;
    invalidate();
}

void TimelineView::panByPixels(double dx) {
    const double perPixel = (m_viewEnd - m_viewStart) / std::max(1.0, plotRect().width());
    setViewRange(m_viewStart - dx * perPixel, m_viewEnd - dx * perPixel);
}

void TimelineView::ensureVisible(int frame) {
    if (frame >= m_viewStart && frame <= m_viewEnd)
        return;
    const double span = m_viewEnd - m_viewStart;
    // Page along like a playhead: the frame lands near the left edge going forwards, the right edge going back.
    const double start = frame > m_viewEnd ? frame - 0.05 * span : frame - 0.95 * span;
    setViewRange(start, start + span);
}

// ---- mapping ------------------------------------------------------------------------------------------------------

QRectF TimelineView::plotRect() const {
    const double left = kGutterWidth + kPlotMarginLeft;
    const double right = std::max(left + 10.0, static_cast<double>(width() - kPlotMarginRight));
    return QRectF(left, 0.0, right - left, height());
}

double TimelineView::xForFrame(double frame) const {
    const QRectF r = plotRect();
    return r.left() + (frame - m_viewStart) * r.width() / (m_viewEnd - m_viewStart);
}

double TimelineView::frameAtX(double x) const {
    const QRectF r = plotRect();
    return m_viewStart + (x - r.left()) * (m_viewEnd - m_viewStart) / r.width();
}

int TimelineView::frameAt(double x) const {
    const double f = std::round(frameAtX(x));
    return static_cast<int>(
        std::clamp(f, static_cast<double>(m_timeline->firstFrame()), static_cast<double>(m_timeline->lastFrame())));
}

QRect TimelineView::rulerRect() const {
    return QRect(0, 0, width(), kRulerHeight);
}

int TimelineView::trackHeight() const {
    const int n = trackCount();
    if (n == 0 || !m_timeline->tracksVisible())
        return 0;
    return std::clamp((height() - kRulerHeight) / n, kTrackHeight, kTrackMaxHeight);
}

QRect TimelineView::trackRect(int index) const {
    const int h = trackHeight();
    if (h == 0 || index < 0 || index >= trackCount())
        return QRect();
    return QRect(0, kRulerHeight + index * h, width(), h);
}

QString TimelineView::trackName(int index) const {
    return index >= 0 && index < trackCount() ? m_tracks[index].name : QString();
}

int TimelineView::trackAt(const QPoint& pos) const {
    for (int i = 0; i < trackCount(); ++i)
        if (trackRect(i).contains(pos))
            return i;
    return -1;
}

int TimelineView::preferredHeight() const {
    const bool tracks = m_timeline->tracksVisible() && trackCount() > 0;
    return kRulerHeight + (tracks ? trackCount() * kTrackHeight : 0);
}

QSize TimelineView::sizeHint() const {
    return QSize(640, preferredHeight());
}

QSize TimelineView::minimumSizeHint() const {
    // The tracks ask for their room, so a dock grows to show them when a bake brings them; folding them away (the
    // toolbar's tracks button) gives the room back.
    return QSize(kGutterWidth + 120, preferredHeight());
}

// ---- ruler ticks --------------------------------------------------------------------------------------------------

// The finest 1-2-5 step (frames) or clock step (seconds) whose labels fit between two ticks, so labels never overlap
// at any zoom; minor ticks subdivide it where they stay a few pixels apart.
TimelineView::Ticks TimelineView::chooseTicks() const {
    const double perFrame = plotRect().width() / (m_viewEnd - m_viewStart);
    const QFontMetricsF fm(smallFont(font(), 0.85));
    Ticks t;
    auto widest = [&](const Ticks& candidate) {
        return std::max(fm.horizontalAdvance(labelText(std::floor(m_viewStart), candidate)),
                        fm.horizontalAdvance(labelText(std::ceil(m_viewEnd), candidate)));
    };
    std::vector<Ticks> candidates;
    const double fps = m_timeline->fps();
    if (!m_timeline->showSeconds()) {
        for (double decade = 1.0; decade < 1e10; decade *= 10.0)
            for (double m : {1.0, 2.0, 5.0})
                candidates.push_back({decade * m, decade * m, 0});
    } else {
        candidates.push_back({1.0, 1.0, 3}); // a single frame
        static constexpr double kSeconds[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1.0,    2.0,    5.0,   10.0,
                                              15.0, 30.0, 60.0, 120, 300, 600,  900, 1800.0, 3600.0, 7200.0};
        for (double s : kSeconds) {
            const double frames = s * fps;
            if (frames <= 1.0 + 1e-9 || (s < 1.0 && !nearlyIntegral(frames)))
                continue;
            int decimals = 0; // as many as the step needs: 0.25 s labels read 0.25, 0.50, 0.75
            while (decimals < 3 && !nearlyIntegral(s * std::pow(10.0, decimals)))
                ++decimals;
            candidates.push_back({frames, frames, decimals});
        }
    }
    t = candidates.back();
    for (const Ticks& c : candidates)
        if (c.major * perFrame >= widest(c) + kLabelGap) {
            t = c;
            break;
        }
    // Minor ticks: the finest subdivision into whole frames that stays legible.
    t.minor = t.major;
    for (int parts : {10, 5, 4, 2}) {
        const double step = t.major / parts;
        if (step < 1.0 - 1e-9 || !nearlyIntegral(step))
            continue;
        if (step * perFrame >= kMinorSpacing) {
            t.minor = step;
            break;
        }
    }
    return t;
}

QString TimelineView::labelText(double frame, const Ticks& ticks) const {
    if (!m_timeline->showSeconds())
        return QString::number(static_cast<long long>(std::llround(frame)));
    const double fps = m_timeline->fps();
    const bool minutes = std::max(std::abs(m_viewStart), std::abs(m_viewEnd)) / fps >= 60.0;
    return formatSeconds(frame / fps, ticks.decimals, minutes);
}

QString TimelineView::cursorText(int frame) const {
    if (!m_timeline->showSeconds())
        return QString::number(frame);
    const double fps = m_timeline->fps();
    return formatSeconds(frame / fps, 2, std::abs(m_timeline->lastFrame()) / fps >= 60.0);
}

std::vector<RulerLabel> TimelineView::rulerLabels() const {
    std::vector<RulerLabel> labels;
    const Ticks ticks = chooseTicks();
    const QFontMetricsF fm(smallFont(font(), 0.85));
    const QRectF plot = plotRect();
    const long long k0 = static_cast<long long>(std::ceil(m_viewStart / ticks.major - 1e-9));
    const long long k1 = static_cast<long long>(std::floor(m_viewEnd / ticks.major + 1e-9));
    for (long long k = k0; k <= k1; ++k) {
        const double frame = k * ticks.major;
        const double x = xForFrame(frame);
        if (x < plot.left() - 0.5 || x > plot.right() + 0.5)
            continue;
        RulerLabel label;
        label.frame = frame;
        label.text = labelText(frame, ticks);
        const double w = fm.horizontalAdvance(label.text);
        label.rect = QRectF(x - 0.5 * w, 4.0, w, fm.height());
        labels.push_back(std::move(label));
    }
    return labels;
}

// ---- tracks -------------------------------------------------------------------------------------------------------

void TimelineView::rebuildTracks() {
    m_tracks.clear();
    const std::shared_ptr<const Bake> bake = m_timeline->bake();
    if (bake && bake->hasDiagnostics() && bake->frameCount() > 0) {
        auto copy = [&](BakeDiagnostic d) {
            const std::span<const float> s = bake->diagnosticTrack(d);
            return std::vector<float>(s.begin(), s.end());
        };
        Track energy{tr("Energy"), Unit::Energy, {}, false};
        std::vector<float> kinetic = copy(BakeDiagnostic::KineticEnergy);
        std::vector<float> potential = copy(BakeDiagnostic::PotentialEnergy);
        std::vector<float> total(kinetic.size());
        for (size_t i = 0; i < total.size(); ++i)
            total[i] = kinetic[i] + potential[i];
        energy.series.push_back({tr("Kinetic"), QColor(222, 92, 60), 1.0, std::move(kinetic)});
        energy.series.push_back({tr("Potential"), QColor(66, 133, 214), 1.0, std::move(potential)});
        // An invalid colour means the palette's text colour: the total is the curve that matters (flat = conserved).
        energy.series.push_back({tr("Total"), QColor(), 1.8, std::move(total)});
        m_tracks.push_back(std::move(energy));
        m_tracks.push_back({tr("Max penetration"),
                            Unit::Length,
                            {{tr("Max penetration"), QColor(204, 72, 72), 1.0, copy(BakeDiagnostic::MaxPenetration)}},
                            true});
        m_tracks.push_back({tr("Contacts"),
                            Unit::Count,
                            {{tr("Contacts"), QColor(142, 108, 201), 1.0, copy(BakeDiagnostic::ContactCount)}},
                            true});
        m_tracks.push_back({tr("Awake bodies"),
                            Unit::Count,
                            {{tr("Awake bodies"), QColor(58, 168, 92), 1.0, copy(BakeDiagnostic::AwakeBodies)}},
                            true});
        // One scale per track over the whole bake, so zooming and scrubbing never rescale a chart.
        for (Track& track : m_tracks) {
            float lo = std::numeric_limits<float>::infinity();
            float hi = -lo;
            for (const Series& s : track.series)
                for (float v : s.values)
                    if (std::isfinite(v)) {
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
            if (!std::isfinite(lo)) {
                lo = 0.0f;
                hi = 1.0f;
            }
            lo = std::min(lo, 0.0f);
            if (!(hi > lo))
                hi = lo + (track.unit == Unit::Count ? 1.0f : (track.unit == Unit::Length ? 1e-3f : 1.0f));
            track.lo = lo;
            track.hi = hi;
        }
    }
    updateGeometry();
    invalidate();
}

QString TimelineView::formatValue(const Track& track, double value) const {
    if (!std::isfinite(value))
        return QStringLiteral("—");
    switch (track.unit) {
    case Unit::Energy: {
        const double a = std::abs(value);
        if (a >= 1e9)
            return tr("%1 GJ").arg(QString::number(value / 1e9, 'g', 3));
        if (a >= 1e6)
            return tr("%1 MJ").arg(QString::number(value / 1e6, 'g', 3));
        if (a >= 1e3)
            return tr("%1 kJ").arg(QString::number(value / 1e3, 'g', 3));
        if (a > 0.0 && a < 1e-3)
            return tr("%1 mJ").arg(QString::number(value * 1e3, 'g', 3));
        return tr("%1 J").arg(QString::number(value, 'g', 3));
    }
    case Unit::Length: {
        const double mm = value * 1e3;
        if (std::abs(mm) >= 1000.0)
            return tr("%1 m").arg(QString::number(value, 'g', 3));
        return tr("%1 mm").arg(QString::number(std::abs(mm) < 0.005 ? 0.0 : mm, 'f', std::abs(mm) >= 100.0 ? 0 : 2));
    }
    case Unit::Count:
        return QString::number(std::llround(value));
    }
    return QString();
}

// ---- tooltips -----------------------------------------------------------------------------------------------------

QString TimelineView::toolTipAt(const QPoint& pos) const {
    const std::shared_ptr<const Bake> bake = m_timeline->bake();
    const long long baked = bake ? static_cast<long long>(bake->frameCount()) : 0;
    const bool inPlot = pos.x() >= kGutterWidth;
    const long long frame = std::llround(frameAtX(pos.x()));
    const double fps = m_timeline->fps();
    const QString header = tr("Frame %1 · %2 s").arg(frame).arg(frame / fps, 0, 'f', 3);
    const QString staleNote = tr("Scene changed since this bake");

    if (rulerRect().contains(pos)) {
        if (!inPlot)
            return m_timeline->showSeconds() ? tr("Ruler in seconds (Ctrl+T shows frames)")
                                             : tr("Ruler in frames (Ctrl+T shows seconds)");
        if (frame < m_timeline->firstFrame() || frame > m_timeline->lastFrame())
            return tr("Frame %1 is outside the range %2–%3")
                .arg(frame)
                .arg(m_timeline->firstFrame())
                .arg(m_timeline->lastFrame());
        QStringList lines{header};
        if (m_timeline->progress() >= 0.0) {
            QString baking = tr("Baking: %1 %").arg(std::lround(m_timeline->progress() * 100.0));
            if (!m_timeline->progressText().isEmpty())
                baking += QStringLiteral(" · ") + m_timeline->progressText();
            lines << baking;
        }
        if (bake) {
            if (frame >= 0 && frame < baked)
                lines << (m_timeline->isStale() ? staleNote : tr("Baked (frames 0–%1)").arg(baked - 1));
            else
                lines << tr("Not baked");
        }
        return lines.join(QLatin1Char('\n'));
    }

    const int index = trackAt(pos);
    if (index < 0)
        return QString();
    const Track& track = m_tracks[index];
    if (!inPlot) {
        QString text = track.name + QLatin1Char('\n') +
                       tr("Scale %1 to %2").arg(formatValue(track, track.lo), formatValue(track, track.hi));
        if (track.unit == Unit::Energy)
            text += QLatin1Char('\n') + tr("Kinetic, potential and their total. A flat total means energy is "
                                           "conserved; it steps down where contacts and damping dissipate it.");
        return text;
    }
    if (frame < 0 || frame >= baked)
        return tr("Frame %1: not baked").arg(frame);
    QStringList lines{header};
    for (const Series& s : track.series)
        lines << tr("%1: %2").arg(s.name, formatValue(track, s.values[frame]));
    if (track.unit == Unit::Energy) {
        const std::vector<float>& total = track.series.back().values;
        lines << tr("Total change since frame 0: %1").arg(formatValue(track, double(total[frame]) - total[0]));
    }
    if (m_timeline->isStale())
        lines << staleNote;
    return lines.join(QLatin1Char('\n'));
}

bool TimelineView::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QString text = toolTipAt(help->pos());
        if (text.isEmpty()) {
            QToolTip::hideText();
            event->ignore();
        } else {
            // The tip belongs to the frame under the pointer (and to its row): moving off it brings the next one.
            const double f = std::round(frameAtX(help->pos().x()));
            const int x0 = static_cast<int>(std::floor(xForFrame(f - 0.5)));
            const int x1 = std::max(x0 + 1, static_cast<int>(std::ceil(xForFrame(f + 0.5))));
            const int row = trackAt(help->pos());
            const QRect band = row >= 0 ? trackRect(row) : (rulerRect().contains(help->pos()) ? rulerRect() : rect());
            const QRect area = help->pos().x() < kGutterWidth ? QRect(0, band.top(), kGutterWidth, band.height())
                                                              : QRect(x0, band.top(), x1 - x0, band.height());
            QToolTip::showText(help->globalPos(), text, this, area);
        }
        return true;
    }
    if (event->type() == QEvent::FocusIn || event->type() == QEvent::FocusOut)
        invalidate();
    return QWidget::event(event);
}

// ---- painting -----------------------------------------------------------------------------------------------------

void TimelineView::invalidate() {
    fitIfFollowing(); // the mapping follows a new frame range at once, not at the next paint
    m_cacheValid = false;
    update();
}

QRect TimelineView::cursorRect(int frame) const {
    const int x = static_cast<int>(std::floor(xForFrame(frame)));
    return QRect(x - m_cursorBoxWidth / 2 - 4, 0, m_cursorBoxWidth + 9, height());
}

void TimelineView::cursorMoved(int from, int to) {
    if (!m_cacheValid) {
        update();
        return;
    }
    // Only the old and the new cursor columns change; the rest is blitted from the cache anyway.
    update(cursorRect(from));
    update(cursorRect(to));
}

void TimelineView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (m_followRange)
        fitIfFollowing();
    m_cacheValid = false;
}

void TimelineView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange ||
        event->type() == QEvent::StyleChange)
        invalidate();
    QWidget::changeEvent(event);
}

void TimelineView::paintEvent(QPaintEvent* event) {
    if (!m_cacheValid)
        rebuildCache();
    QPainter p(this);
    const qreal dpr = m_cache.devicePixelRatio();
    const QRect r = event->rect();
    p.drawPixmap(r.topLeft(), m_cache, QRectF(r.x() * dpr, r.y() * dpr, r.width() * dpr, r.height() * dpr));
    paintProgress(p);
    paintCursor(p);
}

void TimelineView::rebuildCache() {
    if (m_followRange)
        fitIfFollowing();
    const qreal dpr = devicePixelRatioF();
    const QSize size = this->size().expandedTo(QSize(1, 1));
    if (m_cache.size() != size * dpr)
        m_cache = QPixmap(size * dpr);
    m_cache.setDevicePixelRatio(dpr);
    const QFontMetrics cursorFm(smallFont(font(), 0.9, true));
    m_cursorBoxWidth = std::max(30, std::max(cursorFm.horizontalAdvance(cursorText(m_timeline->lastFrame())),
                                             cursorFm.horizontalAdvance(cursorText(m_timeline->firstFrame()))) +
                                        14);

    QPainter p(&m_cache);
    const Colors c = colorsFor(palette());
    p.fillRect(rect(), c.base);
    paintRuler(p);
    for (int i = 0; i < trackCount(); ++i) {
        const QRect r = trackRect(i);
        if (r.isEmpty())
            break;
        paintTrack(p, m_tracks[i], r);
    }
    // Below the last track: a hint when there is nothing to show.
    const int used = kRulerHeight + trackCount() * trackHeight();
    if (height() - used >= 24) {
        const std::shared_ptr<const Bake> bake = m_timeline->bake();
        QString hint;
        if (!bake)
            hint = tr("Bake the simulation to scrub it here and to see its energy, contacts and penetration.");
        else if (!bake->hasDiagnostics())
            hint = tr("This bake carries no diagnostics (bake files store positions only).");
        else if (!m_timeline->tracksVisible())
            hint = tr("Diagnostic tracks hidden.");
        if (!hint.isEmpty()) {
            p.setPen(c.muted);
            p.setFont(smallFont(font(), 0.95));
            p.drawText(QRect(kGutterWidth, used, width() - kGutterWidth, std::min(height() - used, 40)),
                       Qt::AlignCenter | Qt::TextWordWrap, hint);
        }
    }
    // Gutter edge, drawn last over everything.
    p.setPen(c.border);
    p.drawLine(QPointF(kGutterWidth - 0.5, 0), QPointF(kGutterWidth - 0.5, used));
    m_cacheValid = true;
}

// Bake in progress: a striped bar growing from the first frame. Drawn over the cache, so that the updates of a
// running bake (ten a second) repaint a 5-pixel strip instead of the whole background.
void TimelineView::paintProgress(QPainter& p) {
    if (m_timeline->progress() < 0.0)
        return;
    const Colors c = colorsFor(palette());
    const QRectF plot = plotRect();
    const int first = m_timeline->firstFrame();
    const int last = m_timeline->lastFrame();
    const int barTop = kRulerHeight - kBakeBarHeight;
    const double f = std::clamp(m_timeline->progress(), 0.0, 1.0);
    const double x0 = std::clamp(xForFrame(first), plot.left(), plot.right());
    const double x1 = std::clamp(xForFrame(first + f * (last - first)), plot.left(), plot.right());
    const double xLast = std::clamp(xForFrame(last), plot.left(), plot.right());
    const QRectF bar(x0, barTop, x1 - x0, kBakeBarHeight);
    p.fillRect(QRectF(x0, barTop, xLast - x0, kBakeBarHeight), withAlpha(c.progress, 45));
    p.fillRect(bar, c.progress);
    p.fillRect(bar, QBrush(c.progress.lighter(130), Qt::BDiagPattern));
}

void TimelineView::progressChanged() {
    update(QRect(kGutterWidth, kRulerHeight - kBakeBarHeight, width() - kGutterWidth, kBakeBarHeight));
}

void TimelineView::paintRuler(QPainter& p) {
    const Colors c = colorsFor(palette());
    const QRect ruler = rulerRect();
    const QRectF plot = plotRect();
    const int first = m_timeline->firstFrame();
    const int last = m_timeline->lastFrame();
    const int barTop = ruler.bottom() + 1 - kBakeBarHeight;

    p.fillRect(ruler, c.window);
    // Outside the frame range the ruler is dimmed, as Blender dims outside the scene's range.
    const double xFirst = std::clamp(xForFrame(first), plot.left(), plot.right());
    const double xLast = std::clamp(xForFrame(last), plot.left(), plot.right());
    p.fillRect(QRectF(kGutterWidth, 0, xFirst - kGutterWidth, kRulerHeight), c.dimWindow);
    p.fillRect(QRectF(xLast, 0, width() - xLast, kRulerHeight), c.dimWindow);

    // Baked range: tinted, with a solid (or hatched when stale) bar along the bottom.
    const std::shared_ptr<const Bake> bake = m_timeline->bake();
    if (bake && bake->frameCount() > 0) {
        // From the frame where the simulation started: before it the bodies only hold the edit pose.
        const double start = static_cast<double>(std::min(bake->simulationStart(), bake->frameCount() - 1));
        const double x0 = std::clamp(xForFrame(start), plot.left(), plot.right());
        const double x1 = std::clamp(xForFrame(static_cast<double>(bake->frameCount() - 1)), plot.left(), plot.right());
        const QRectF band(x0, 0, std::max(2.0, x1 - x0), kRulerHeight);
        const QRectF bar(x0, barTop, std::max(2.0, x1 - x0), kBakeBarHeight);
        if (m_timeline->isStale()) {
            p.fillRect(band, withAlpha(c.stale, 28));
            p.fillRect(bar, withAlpha(c.stale, 90));
            p.fillRect(bar, QBrush(c.stale, Qt::BDiagPattern));
        } else {
            p.fillRect(band, withAlpha(c.baked, 30));
            p.fillRect(bar, c.baked);
        }
    }
    // Ticks and labels.
    const Ticks ticks = chooseTicks();
    p.save();
    p.setClipRect(QRectF(kGutterWidth + 1, 0, width() - kGutterWidth - 1, kRulerHeight));
    p.setPen(QPen(withAlpha(c.text, 110), 1.0));
    if (ticks.minor < ticks.major) {
        const long long k0 = static_cast<long long>(std::ceil(m_viewStart / ticks.minor));
        const long long k1 = static_cast<long long>(std::floor(m_viewEnd / ticks.minor));
        for (long long k = k0; k <= k1; ++k) {
            const double x = std::floor(xForFrame(k * ticks.minor)) + 0.5;
            p.drawLine(QPointF(x, barTop - 4), QPointF(x, barTop));
        }
    }
    p.setPen(QPen(withAlpha(c.text, 190), 1.0));
    p.setFont(smallFont(font(), 0.85));
    const std::vector<RulerLabel> labels = rulerLabels();
    for (const RulerLabel& label : labels) {
        const double x = std::floor(xForFrame(label.frame)) + 0.5;
        p.drawLine(QPointF(x, barTop - 9), QPointF(x, barTop));
        p.drawText(label.rect, Qt::AlignCenter, label.text);
    }
    p.restore();

    // Gutter: the ruler's unit, and a focus mark so that the keys' target is visible.
    p.fillRect(QRect(0, 0, kGutterWidth, kRulerHeight), c.window);
    p.setPen(c.muted);
    p.setFont(smallFont(font(), 0.85));
    p.drawText(QRect(10, 4, kGutterWidth - 14, 16), Qt::AlignLeft | Qt::AlignVCenter,
               m_timeline->showSeconds() ? tr("Seconds") : tr("Frames"));
    if (hasFocus())
        p.fillRect(QRect(0, 0, 3, kRulerHeight), c.accent);
    p.setPen(c.border);
    p.drawLine(QPointF(0, kRulerHeight - 0.5), QPointF(width(), kRulerHeight - 0.5));
}

void TimelineView::paintTrack(QPainter& p, const Track& track, const QRect& r) {
    const Colors c = colorsFor(palette());
    const QRectF plot = plotRect();
    const int first = m_timeline->firstFrame();
    const int last = m_timeline->lastFrame();
    const QRect chart(kGutterWidth, r.top(), r.width() - kGutterWidth, r.height() - 1);

    p.fillRect(chart, c.base);
    const double xFirst = std::clamp(xForFrame(first), plot.left(), plot.right());
    const double xLast = std::clamp(xForFrame(last), plot.left(), plot.right());
    p.fillRect(QRectF(chart.left(), chart.top(), xFirst - chart.left(), chart.height()), c.dimBase);
    p.fillRect(QRectF(xLast, chart.top(), chart.right() + 1 - xLast, chart.height()), c.dimBase);

    // The ruler's labelled ticks continue as a faint grid.
    p.save();
    p.setClipRect(chart);
    p.setPen(QPen(c.grid, 1.0));
    for (const RulerLabel& label : rulerLabels()) {
        const double x = std::floor(xForFrame(label.frame)) + 0.5;
        p.drawLine(QPointF(x, chart.top()), QPointF(x, chart.bottom() + 1));
    }
    // Zero line when the scale spans it (potential energy can be negative).
    const QRect area(static_cast<int>(plot.left()), chart.top() + 3, static_cast<int>(plot.width()),
                     chart.height() - 6);
    if (track.lo < 0.0f && track.hi > 0.0f) {
        const double y = area.bottom() + 1 - (0.0 - track.lo) / (track.hi - track.lo) * area.height();
        p.setPen(QPen(c.grid, 1.0, Qt::DashLine));
        p.drawLine(QPointF(chart.left(), std::floor(y) + 0.5), QPointF(chart.right(), std::floor(y) + 0.5));
    }
    p.setClipRect(QRect(chart.left(), chart.top(), chart.width(), chart.height()));
    for (const Series& s : track.series)
        paintSeries(p, s, area, track.lo, track.hi, track.fill);

    // Stale: the curves belong to the scene before the edit.
    const std::shared_ptr<const Bake> bake = m_timeline->bake();
    if (m_timeline->isStale() && bake && bake->frameCount() > 0) {
        const double x0 = std::clamp(xForFrame(0), plot.left(), plot.right());
        const double x1 = std::clamp(xForFrame(static_cast<double>(bake->frameCount() - 1)), plot.left(), plot.right());
        const QRectF band(x0, chart.top(), std::max(2.0, x1 - x0), chart.height());
        p.fillRect(band, withAlpha(c.base, 110));
        p.fillRect(band, QBrush(withAlpha(c.stale, 60), Qt::BDiagPattern));
    }
    p.restore();

    // Legend for the energy track: which curve is which.
    if (track.series.size() > 1) {
        p.save();
        const QFont f = smallFont(font(), 0.8);
        p.setFont(f);
        const QFontMetrics fm(f);
        int x = chart.right() - 6;
        for (auto it = track.series.rbegin(); it != track.series.rend(); ++it) {
            const int w = fm.horizontalAdvance(it->name);
            x -= w;
            const QRect tr(x, chart.top() + 2, w, fm.height());
            p.fillRect(tr.adjusted(-14, 0, 2, 0), withAlpha(c.base, 200));
            p.setPen(it->color.isValid() ? it->color : c.text);
            p.drawText(tr, Qt::AlignLeft | Qt::AlignVCenter, it->name);
            p.fillRect(QRectF(x - 11, tr.center().y() - 0.5, 8, it->width + 0.5),
                       it->color.isValid() ? it->color : c.text);
            x -= 20;
        }
        p.restore();
    }

    // Gutter: name and scale.
    const QRect gutter(0, r.top(), kGutterWidth, r.height() - 1);
    p.fillRect(gutter, c.window);
    const QFont nameFont = smallFont(font(), 0.9, true);
    const QFont scaleFont = smallFont(font(), 0.8);
    const int nameHeight = QFontMetrics(nameFont).height();
    const int scaleHeight = QFontMetrics(scaleFont).height();
    const int top = r.top() + std::max(1, (r.height() - nameHeight - scaleHeight) / 2);
    p.setPen(c.text);
    p.setFont(nameFont);
    p.drawText(QRect(10, top, kGutterWidth - 14, nameHeight), Qt::AlignLeft | Qt::AlignVCenter,
               QFontMetrics(nameFont).elidedText(track.name, Qt::ElideRight, kGutterWidth - 14));
    p.setPen(c.muted);
    p.setFont(scaleFont);
    const QString scale = QStringLiteral("%1 – %2").arg(formatValue(track, track.lo), formatValue(track, track.hi));
    p.drawText(QRect(10, top + nameHeight - 1, kGutterWidth - 14, scaleHeight), Qt::AlignLeft | Qt::AlignVCenter,
               QFontMetrics(scaleFont).elidedText(scale, Qt::ElideRight, kGutterWidth - 14));
    // Colour key on the left edge for single-curve tracks.
    if (track.series.size() == 1)
        p.fillRect(QRect(3, r.top() + 4, 3, r.height() - 9), track.series.front().color);
    p.setPen(withAlpha(c.border, 120));
    p.drawLine(QPointF(0, r.bottom() + 0.5), QPointF(width(), r.bottom() + 0.5));
}

// Draws one curve. Zoomed out (several frames per pixel column) each column draws the minimum to maximum of its
// frames, so a 36,000-frame bake costs one short line per column and spikes never vanish; zoomed in, a polyline
// through the frames.
void TimelineView::paintSeries(QPainter& p, const Series& s, const QRect& r, float lo, float hi, bool fill) {
    const long long n = static_cast<long long>(s.values.size());
    if (n == 0)
        return;
    const QColor color = s.color.isValid() ? s.color : palette().color(QPalette::WindowText);
    const double scale = r.height() / static_cast<double>(hi - lo);
    const double bottom = r.bottom() + 1.0;
    auto yOf = [&](double v) { return bottom - (v - lo) * scale; };
    const double baseline = yOf(std::max(0.0f, lo));
    const double perFrame = plotRect().width() / (m_viewEnd - m_viewStart);
    QColor fillColor = color;
    fillColor.setAlpha(55);

    if (perFrame >= 1.0) {
        const long long i0 = std::max(0LL, static_cast<long long>(std::floor(m_viewStart)) - 1);
        const long long i1 = std::min(n - 1, static_cast<long long>(std::ceil(m_viewEnd)) + 1);
        QPolygonF line;
        auto flush = [&] {
            if (line.isEmpty())
                return;
            if (fill) {
                QPolygonF area = line;
                area << QPointF(line.back().x(), baseline) << QPointF(line.front().x(), baseline);
                p.setPen(Qt::NoPen);
                p.setBrush(fillColor);
                p.drawPolygon(area);
            }
            p.setPen(QPen(color, s.width));
            p.setBrush(Qt::NoBrush);
            if (line.size() == 1)
                p.drawPoint(line.front());
            else
                p.drawPolyline(line);
            line.clear();
        };
        p.setRenderHint(QPainter::Antialiasing, true);
        for (long long i = i0; i <= i1; ++i) {
            const float v = s.values[i];
            if (std::isfinite(v))
                line << QPointF(xForFrame(static_cast<double>(i)), yOf(v));
            else
                flush();
        }
        flush();
        p.setRenderHint(QPainter::Antialiasing, false);
        return;
    }

    // One column per pixel; each also takes the previous column's last frame so that steep steps stay joined.
    const QRectF plot = plotRect();
    const int c0 = static_cast<int>(std::floor(std::max(plot.left(), xForFrame(0.0))));
    const int c1 = static_cast<int>(std::ceil(std::min(plot.right(), xForFrame(static_cast<double>(n - 1)))));
    std::vector<QLineF> lines;
    lines.reserve(static_cast<size_t>(std::max(0, c1 - c0 + 1)));
    QPolygonF top;
    for (int x = c0; x <= c1; ++x) {
        const long long f0 = std::max(0LL, static_cast<long long>(std::ceil(frameAtX(x))) - 1);
        const long long f1 = std::min(n, static_cast<long long>(std::ceil(frameAtX(x + 1.0))));
        float mn = std::numeric_limits<float>::infinity();
        float mx = -mn;
        for (long long i = f0; i < f1; ++i) {
            const float v = s.values[i];
            if (std::isfinite(v)) {
                mn = std::min(mn, v);
                mx = std::max(mx, v);
            }
        }
        if (!(mn <= mx))
            continue;
        const double xc = x + 0.5;
        const double y0 = yOf(mx);
        const double y1 = std::max(yOf(mn), y0 + 1.0);
        lines.emplace_back(xc, y0, xc, y1);
        if (fill)
            top << QPointF(xc, y0);
    }
    if (fill && !top.isEmpty()) {
        top << QPointF(top.back().x(), baseline) << QPointF(top.front().x(), baseline);
        p.setPen(Qt::NoPen);
        p.setBrush(fillColor);
        p.drawPolygon(top);
    }
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(color, std::max(1.0, std::round(s.width)), Qt::SolidLine, Qt::FlatCap));
    p.drawLines(lines.data(), static_cast<int>(lines.size()));
}

void TimelineView::paintCursor(QPainter& p) {
    const int frame = m_timeline->currentFrame();
    const double xf = xForFrame(frame);
    const QRectF plot = plotRect();
    if (xf < plot.left() - 1.0 || xf > plot.right() + 1.0)
        return;
    const Colors c = colorsFor(palette());
    const double x = std::floor(xf);
    p.save();
    p.setClipRect(QRectF(kGutterWidth + 1, 0, width() - kGutterWidth - 1, height()));
    // Down through the ruler and the tracks; the empty space below them (the hint) stays clear.
    const int bottom = std::min(height(), kRulerHeight + trackCount() * trackHeight());
    p.fillRect(QRectF(x - 0.5, kCursorBoxHeight, 2.0, bottom - kCursorBoxHeight), c.accent);

    // A dot where the cursor crosses each track's main curve.
    const std::shared_ptr<const Bake> bake = m_timeline->bake();
    p.setRenderHint(QPainter::Antialiasing, true);
    for (int i = 0; i < trackCount() && bake; ++i) {
        const QRect r = trackRect(i);
        const Track& track = m_tracks[i];
        const Series& s = track.series.back();
        if (r.isEmpty() || frame < 0 || frame >= static_cast<long long>(s.values.size()) ||
            !std::isfinite(s.values[frame]))
            continue;
        const QRect area(static_cast<int>(plot.left()), r.top() + 3, static_cast<int>(plot.width()), r.height() - 7);
        const double y = area.bottom() + 1.0 - (s.values[frame] - track.lo) / (track.hi - track.lo) * area.height();
        p.setPen(QPen(c.base, 1.5));
        p.setBrush(s.color.isValid() ? s.color : c.text);
        p.drawEllipse(QPointF(x + 0.5, y), 3.5, 3.5);
    }

    // The frame number in a rounded box at the top, as Blender draws it.
    const QFont f = smallFont(font(), 0.9, true);
    p.setFont(f);
    const QString text = cursorText(frame);
    const double w = std::max(26, QFontMetrics(f).horizontalAdvance(text) + 12);
    const QRectF box(x + 0.5 - 0.5 * w, 1.0, w, kCursorBoxHeight);
    p.setPen(Qt::NoPen);
    p.setBrush(c.accent);
    p.drawRoundedRect(box, 4.0, 4.0);
    p.setPen(c.accentText);
    p.drawText(box, Qt::AlignCenter, text);
    p.restore();
}

// ---- mouse --------------------------------------------------------------------------------------------------------

void TimelineView::scrubTo(double x) {
    m_timeline->setCurrentFrame(frameAt(x));
}

void TimelineView::mousePressEvent(QMouseEvent* event) {
    const QPointF pos = event->position();
    if (event->button() == Qt::LeftButton && pos.x() >= kGutterWidth &&
        (rulerRect().contains(pos.toPoint()) || trackAt(pos.toPoint()) >= 0)) {
        m_scrubbing = true;
        scrubTo(pos.x());
        event->accept();
        return;
    }
    if (event->button() == Qt::MiddleButton) {
        m_panning = true;
        m_panLastX = pos.x();
        setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void TimelineView::mouseMoveEvent(QMouseEvent* event) {
    if (m_scrubbing) {
        scrubTo(event->position().x());
        event->accept();
        return;
    }
    if (m_panning) {
        panByPixels(event->position().x() - m_panLastX);
        m_panLastX = event->position().x();
        event->accept();
        return;
    }
    QWidget::mouseMoveEvent(event);
}

void TimelineView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && m_scrubbing) {
        m_scrubbing = false;
        event->accept();
        return;
    }
    if (event->button() == Qt::MiddleButton && m_panning) {
        m_panning = false;
        unsetCursor();
        event->accept();
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

void TimelineView::wheelEvent(QWheelEvent* event) {
    const QPoint delta = event->angleDelta();
    const bool pan = delta.x() != 0 || (event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier));
    if (pan) {
        const int d = delta.x() != 0 ? delta.x() : delta.y();
        panByPixels(d / 120.0 * 0.1 * plotRect().width());
    } else if (delta.y() != 0) {
        // Around the current frame while it is in view (it stays put, as in video editors), else around the pointer.
        const int current = m_timeline->currentFrame();
        const double anchor =
            current >= m_viewStart && current <= m_viewEnd ? current : frameAtX(event->position().x());
        zoomAround(anchor, std::pow(kWheelZoom, delta.y() / 120.0));
    }
    event->accept();
}

} // namespace rl
