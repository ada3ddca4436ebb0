#include "timeline/TimelineWidget.h"

#include "bake/Bake.h"
#include "timeline/TimelineView.h"
#include "widgets/StableLabel.h"

#include <QAction>
#include <QComboBox>
#include <QFrame>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};
constexpr double kMinSpeed = 0.25;
constexpr double kMaxSpeed = 4.0;

enum class Glyph { Play, Pause, First, Previous, Next, Last, Loop, Seconds, Tracks, Fit };

// Toolbar icons drawn here rather than taken from an icon theme, which a bare desktop may not have.
QIcon glyphIcon(Glyph glyph, const QColor& color) {
    QIcon icon;
    for (int scale : {1, 2}) {
        QPixmap pixmap(16 * scale, 16 * scale);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.setRenderHint(QPainter::Antialiasing);
        p.scale(scale, scale);
        p.setPen(Qt::NoPen);
        p.setBrush(color);
        auto triangle = [&](double tipX, double baseX) {
            p.drawPolygon(QPolygonF{QPointF(baseX, 3.0), QPointF(tipX, 8.0), QPointF(baseX, 13.0)});
        };
        switch (glyph) {
        case Glyph::Play:
            triangle(13.5, 4.0);
            break;
        case Glyph::Pause:
            p.drawRect(QRectF(4.0, 3.0, 3.0, 10.0));
            p.drawRect(QRectF(9.0, 3.0, 3.0, 10.0));
            break;
        case Glyph::First:
            p.drawRect(QRectF(2.0, 3.0, 2.0, 10.0));
            triangle(4.5, 9.5);
            triangle(9.5, 14.5);
            break;
        case Glyph::Previous:
            triangle(3.5, 10.0);
            p.drawRect(QRectF(11.0, 3.0, 2.0, 10.0));
            break;
        case Glyph::Next:
            p.drawRect(QRectF(3.0, 3.0, 2.0, 10.0));
            triangle(12.5, 6.0);
            break;
        case Glyph::Last:
            triangle(6.5, 1.5);
            triangle(11.5, 6.5);
            p.drawRect(QRectF(12.0, 3.0, 2.0, 10.0));
            break;
        case Glyph::Loop: {
            p.setPen(QPen(color, 1.6, Qt::SolidLine, Qt::RoundCap));
            p.setBrush(Qt::NoBrush);
            p.drawArc(QRectF(2.5, 2.5, 11.0, 11.0), 100 * 16, 290 * 16);
            p.setPen(Qt::NoPen);
            p.setBrush(color);
            p.drawPolygon(QPolygonF{QPointF(6.0, 0.5), QPointF(10.0, 2.8), QPointF(6.0, 5.5)});
            break;
        }
        case Glyph::Seconds:
            p.setPen(QPen(color, 1.4));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(QRectF(2.0, 2.0, 12.0, 12.0));
            p.setPen(QPen(color, 1.4, Qt::SolidLine, Qt::RoundCap));
            p.drawLine(QPointF(8.0, 8.0), QPointF(8.0, 4.5));
            p.drawLine(QPointF(8.0, 8.0), QPointF(10.5, 9.5));
            break;
        case Glyph::Tracks:
            p.setPen(QPen(color, 1.3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            p.setBrush(Qt::NoBrush);
            p.drawPolyline(QPolygonF{QPointF(1.5, 6.5), QPointF(4.5, 2.5), QPointF(7.5, 5.5), QPointF(10.5, 3.0),
                                     QPointF(14.5, 4.0)});
            p.drawPolyline(QPolygonF{QPointF(1.5, 14.0), QPointF(5.0, 11.0), QPointF(8.0, 12.5), QPointF(11.0, 9.0),
                                     QPointF(14.5, 10.5)});
            p.setPen(QPen(color, 1.0));
            p.drawLine(QPointF(1.0, 7.5), QPointF(15.0, 7.5));
            break;
        case Glyph::Fit:
            p.drawRect(QRectF(1.0, 3.0, 1.6, 10.0));
            p.drawRect(QRectF(13.4, 3.0, 1.6, 10.0));
            p.drawRect(QRectF(5.0, 7.3, 6.0, 1.4));
            p.drawPolygon(QPolygonF{QPointF(3.5, 8.0), QPointF(6.5, 5.0), QPointF(6.5, 11.0)});
            p.drawPolygon(QPolygonF{QPointF(12.5, 8.0), QPointF(9.5, 5.0), QPointF(9.5, 11.0)});
            break;
        }
        p.end();
        pixmap.setDevicePixelRatio(scale);
        icon.addPixmap(pixmap);
    }
    return icon;
}

QString speedText(double speed) {
    return QLocale().toString(speed) + QStringLiteral("×");
}

} // namespace

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
    setObjectName("Timeline");
    setFocusPolicy(Qt::StrongFocus);
    m_realClock.start();

    m_timer = new QTimer(this);
    m_timer->setObjectName("TimelinePlaybackTimer");
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &TimelineWidget::advancePlayback);
    updateTimerInterval();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto* bar = new QWidget(this);
    bar->setObjectName("TimelineToolBar");
    createToolBar(bar);
    layout->addWidget(bar);
    auto* line = new QFrame(this);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Plain);
    line->setForegroundRole(QPalette::Mid);
    layout->addWidget(line);
    m_view = new TimelineView(this);
    layout->addWidget(m_view, 1);
    setFocusProxy(m_view);
    updateFrameReadout();
}

TimelineWidget::~TimelineWidget() = default;

void TimelineWidget::createToolBar(QWidget* bar) {
    const QColor iconColor = palette().color(QPalette::ButtonText);
    auto makeAction = [&](const char* name, Glyph glyph, const QString& text, const QString& tip) {
        auto* action = new QAction(glyphIcon(glyph, iconColor), text, this);
        action->setObjectName(QString::fromLatin1(name));
        action->setToolTip(tip);
        return action;
    };
    m_firstAction = makeAction("TimelineFirst", Glyph::First, tr("First Frame"), tr("Jump to the first frame (Home)"));
    m_previousAction =
        makeAction("TimelinePrevious", Glyph::Previous, tr("Previous Frame"), tr("Step back one frame (Left)"));
    m_playAction = makeAction("TimelinePlay", Glyph::Play, tr("Play"), tr("Play at real time (Space)"));
    m_playAction->setCheckable(true);
    m_nextAction = makeAction("TimelineNext", Glyph::Next, tr("Next Frame"), tr("Step forward one frame (Right)"));
    m_lastAction = makeAction("TimelineLast", Glyph::Last, tr("Last Frame"), tr("Jump to the last frame (End)"));
    m_loopAction = makeAction("TimelineLoop", Glyph::Loop, tr("Loop"), tr("Loop playback; off stops at the end"));
    m_loopAction->setCheckable(true);
    m_loopAction->setChecked(m_loop);
    m_secondsAction = makeAction("TimelineSeconds", Glyph::Seconds, tr("Show Seconds"),
                                 tr("Ruler in seconds instead of frames (Ctrl+T)"));
    m_secondsAction->setCheckable(true);
    m_tracksAction = makeAction("TimelineTracks", Glyph::Tracks, tr("Show Diagnostic Tracks"),
                                tr("Show energy, penetration, contacts and awake bodies under the ruler"));
    m_tracksAction->setCheckable(true);
    m_tracksAction->setChecked(m_tracksVisible);
    m_fitAction = makeAction("TimelineFit", Glyph::Fit, tr("Zoom to Fit"), tr("Show the whole frame range"));

    connect(m_firstAction, &QAction::triggered, this, &TimelineWidget::jumpToFirst);
    connect(m_previousAction, &QAction::triggered, this, &TimelineWidget::stepBackward);
    connect(m_nextAction, &QAction::triggered, this, &TimelineWidget::stepForward);
    connect(m_lastAction, &QAction::triggered, this, &TimelineWidget::jumpToLast);
    connect(m_playAction, &QAction::triggered, this, [this](bool checked) {
        if (checked)
            play();
        else
            pause();
        m_playAction->setChecked(m_playing); // play() refuses when there is nothing to play
    });
    connect(m_loopAction, &QAction::toggled, this, &TimelineWidget::setLoop);
    connect(m_secondsAction, &QAction::toggled, this, &TimelineWidget::setShowSeconds);
    connect(m_tracksAction, &QAction::toggled, this, &TimelineWidget::setTracksVisible);
    connect(m_fitAction, &QAction::triggered, this, &TimelineWidget::zoomToFit);

    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(6, 2, 6, 2);
    row->setSpacing(2);
    auto addButton = [&](QAction* action) {
        auto* button = new QToolButton(bar);
        button->setDefaultAction(action);
        button->setAutoRaise(true);
        button->setIconSize(QSize(16, 16));
        // Buttons never take the focus, so Space and the arrows keep reaching the timeline after a click.
        button->setFocusPolicy(Qt::NoFocus);
        button->setObjectName(action->objectName() + QStringLiteral("Button"));
        row->addWidget(button);
        return button;
    };
    auto addSeparator = [&] {
        auto* line = new QFrame(bar);
        line->setFrameShape(QFrame::VLine);
        line->setFrameShadow(QFrame::Plain);
        line->setForegroundRole(QPalette::Mid);
        line->setFixedHeight(18);
        row->addSpacing(4);
        row->addWidget(line);
        row->addSpacing(4);
    };
    addButton(m_firstAction);
    addButton(m_previousAction);
    addButton(m_playAction);
    addButton(m_nextAction);
    addButton(m_lastAction);
    addSeparator();

    auto* frameLabel = new QLabel(tr("Frame"), bar);
    row->addWidget(frameLabel);
    row->addSpacing(4);
    m_frameSpin = new QSpinBox(bar);
    m_frameSpin->setObjectName("TimelineFrame");
    m_frameSpin->setKeyboardTracking(false);
    m_frameSpin->setAccelerated(true);
    m_frameSpin->setToolTip(tr("Current frame"));
    // A fixed size: a new range or value then does not re-lay out the window (see StableLabel.h).
    m_frameSpin->setFixedSize(m_frameSpin->fontMetrics().horizontalAdvance(QStringLiteral("0000000")) + 30,
                              m_frameSpin->sizeHint().height());
    frameLabel->setBuddy(m_frameSpin);
    connect(m_frameSpin, &QSpinBox::valueChanged, this, &TimelineWidget::setCurrentFrame);
    row->addWidget(m_frameSpin);
    row->addSpacing(8);
    m_timeLabel = new QLabel(bar);
    m_timeLabel->setObjectName("TimelineTime");
    m_timeLabel->setToolTip(tr("Time of the current frame"));
    m_timeLabel->setMinimumWidth(m_timeLabel->fontMetrics().horizontalAdvance(QStringLiteral("00:00.000 s")) + 4);
    row->addWidget(m_timeLabel);
    row->addStretch(1);

    m_progressLabel = new QLabel(bar);
    m_progressLabel->setObjectName("TimelineProgress");
    m_progressLabel->setVisible(false);
    row->addWidget(m_progressLabel);
    row->addSpacing(8);

    auto* speedLabel = new QLabel(tr("Speed"), bar);
    row->addWidget(speedLabel);
    row->addSpacing(4);
    m_speedCombo = new QComboBox(bar);
    m_speedCombo->setObjectName("TimelineSpeed");
    m_speedCombo->setToolTip(tr("Playback speed"));
    m_speedCombo->setFocusPolicy(Qt::TabFocus);
    for (double s : kSpeeds)
        m_speedCombo->addItem(speedText(s), s);
    speedLabel->setBuddy(m_speedCombo);
    connect(m_speedCombo, &QComboBox::activated, this,
            [this](int index) { setSpeed(m_speedCombo->itemData(index).toDouble()); });
    row->addWidget(m_speedCombo);
    addButton(m_loopAction);
    addSeparator();
    addButton(m_secondsAction);
    addButton(m_tracksAction);
    addButton(m_fitAction);
    updateSpeedCombo();
}

// ---- state --------------------------------------------------------------------------------------------------------

void TimelineWidget::setFrameRange(int first, int last) {
    if (last < first)
        std::swap(first, last);
    if (first == m_first && last == m_last)
        return;
    m_first = first;
    m_last = last;
    m_frameSpin->blockSignals(true);
    m_frameSpin->setRange(m_first, m_last);
    m_frameSpin->blockSignals(false);
    m_view->updateGeometry();
    m_view->invalidate();
    const int clamped = std::clamp(m_current, m_first, m_last);
    if (clamped != m_current)
        setCurrentFrame(clamped);
    else
        updateFrameReadout();
}

void TimelineWidget::setFps(double fps) {
    if (!std::isfinite(fps) || fps <= 0.0 || fps == m_fps)
        return;
    if (m_playing)
        anchorPlayback();
    m_fps = fps;
    updateTimerInterval();
    updateFrameReadout();
    m_view->invalidate();
}

void TimelineWidget::setBake(std::shared_ptr<const Bake> bake) {
    m_bake = std::move(bake);
    if (m_bake) {
        setFps(m_bake->fps());
        if (m_bake->frameCount() > 0 && static_cast<long long>(m_bake->frameCount()) - 1 > m_last)
            setFrameRange(m_first, static_cast<int>(m_bake->frameCount() - 1));
    }
    m_view->rebuildTracks();
    updateGeometry();
}

void TimelineWidget::setStale(bool stale) {
    if (stale == m_stale)
        return;
    m_stale = stale;
    m_view->invalidate();
}

void TimelineWidget::setProgress(double fraction, const QString& text) {
    if (!std::isfinite(fraction))
        fraction = -1.0;
    m_progress = fraction < 0.0 ? -1.0 : std::min(fraction, 1.0);
    m_progressText = m_progress < 0.0 ? QString() : text;
    if (m_progress < 0.0) {
        m_progressLabel->setVisible(false);
    } else {
        QString label = tr("Baking %1 %").arg(std::lround(m_progress * 100.0));
        if (!text.isEmpty())
            label += QStringLiteral(" · ") + text;
        m_progressLabel->setText(label);
        m_progressLabel->setVisible(true);
    }
    m_view->progressChanged();
}

void TimelineWidget::setCurrentFrame(int frame) {
    frame = std::clamp(frame, m_first, m_last);
    if (frame == m_current)
        return;
    const int previous = m_current;
    m_current = frame;
    // The user moved the cursor while playing: playback carries on from there.
    if (m_playing && !m_advancing)
        anchorPlayback();
    m_view->cursorMoved(previous, frame);
    updateFrameReadout();
    emit currentFrameChanged(frame);
}

void TimelineWidget::updateFrameReadout() {
    if (m_frameSpin->minimum() != m_first || m_frameSpin->maximum() != m_last || m_frameSpin->value() != m_current) {
        m_frameSpin->blockSignals(true);
        m_frameSpin->setRange(m_first, m_last);
        m_frameSpin->setValue(m_current);
        m_frameSpin->blockSignals(false);
    }
    setStableText(m_timeLabel, tr("%1 s").arg(m_current / m_fps, 0, 'f', 3));
}

void TimelineWidget::setShowSeconds(bool seconds) {
    if (seconds == m_showSeconds)
        return;
    m_showSeconds = seconds;
    m_secondsAction->setChecked(seconds);
    m_view->invalidate();
}

void TimelineWidget::setTracksVisible(bool visible) {
    if (visible == m_tracksVisible)
        return;
    m_tracksVisible = visible;
    m_tracksAction->setChecked(visible);
    m_view->updateGeometry();
    m_view->invalidate();
    updateGeometry();
}

void TimelineWidget::zoomToFit() {
    m_view->zoomToFit();
}

QSize TimelineWidget::sizeHint() const {
    return QWidget::sizeHint().expandedTo(QSize(640, 0));
}

QSize TimelineWidget::minimumSizeHint() const {
    return QWidget::minimumSizeHint();
}

// ---- playback -----------------------------------------------------------------------------------------------------

int TimelineWidget::playFirst() const {
    if (m_bake && m_bake->frameCount() > 0)
        return std::max(m_first, 0);
    return m_first;
}

int TimelineWidget::playLast() const {
    if (m_bake && m_bake->frameCount() > 0)
        return static_cast<int>(std::min<long long>(m_last, static_cast<long long>(m_bake->frameCount()) - 1));
    return m_last;
}

qint64 TimelineWidget::now() const {
    return m_clock ? m_clock() : m_realClock.nsecsElapsed();
}

void TimelineWidget::setClock(Clock clock) {
    m_clock = std::move(clock);
    if (m_playing)
        anchorPlayback();
}

void TimelineWidget::anchorPlayback() {
    m_anchorTime = now();
    m_anchorFrame = m_current;
}

void TimelineWidget::updateTimerInterval() {
    // Two ticks per shown frame, but no faster than 250 Hz (4x at 60 fps drops frames, which is the point) and no
    // slower than 60 Hz so that the cursor moves smoothly at 0.25x.
    const double msPerFrame = 1000.0 / (m_fps * m_speed);
    m_timer->setInterval(std::clamp(static_cast<int>(msPerFrame / 2.0), 4, 16));
}

void TimelineWidget::play() {
    if (m_playing)
        return;
    const int a = playFirst();
    const int b = playLast();
    if (b <= a)
        return; // nothing to play
    // From the start when the cursor is outside the played frames or already at the end.
    if (m_current < a || m_current >= b)
        setCurrentFrame(a);
    m_playing = true;
    anchorPlayback();
    m_timer->start();
    m_playAction->setChecked(true);
    m_playAction->setIcon(glyphIcon(Glyph::Pause, palette().color(QPalette::ButtonText)));
    m_playAction->setText(tr("Pause"));
    m_playAction->setToolTip(tr("Pause (Space)"));
    emit playingChanged(true);
}

void TimelineWidget::pause() {
    if (!m_playing)
        return;
    m_playing = false;
    m_timer->stop();
    m_playAction->setChecked(false);
    m_playAction->setIcon(glyphIcon(Glyph::Play, palette().color(QPalette::ButtonText)));
    m_playAction->setText(tr("Play"));
    m_playAction->setToolTip(tr("Play at real time (Space)"));
    emit playingChanged(false);
}

void TimelineWidget::togglePlayback() {
    if (m_playing)
        pause();
    else
        play();
}

void TimelineWidget::advancePlayback() {
    if (!m_playing)
        return;
    const int a = playFirst();
    const int b = playLast();
    if (b <= a) {
        pause();
        return;
    }
    // Real time: the frame follows the clock, so a slow repaint skips frames instead of falling behind.
    const qint64 t = now();
    const double position = m_anchorFrame + static_cast<double>(t - m_anchorTime) * m_fps * m_speed / 1e9;
    long long frame = static_cast<long long>(std::floor(position + 1e-9));
    bool stop = false;
    if (frame < a) {
        frame = a;
    } else if (m_loop && frame > b) {
        const long long length = b - a + 1;
        const long long wraps = (frame - a) / length;
        frame -= wraps * length;
        m_anchorFrame -= static_cast<double>(wraps * length); // keeps the position within the range
    } else if (!m_loop && frame >= b) {
        frame = b;
        stop = true;
    }
    m_advancing = true;
    setCurrentFrame(static_cast<int>(frame));
    m_advancing = false;
    m_view->ensureVisible(m_current);
    if (stop)
        pause();
}

void TimelineWidget::setSpeed(double speed) {
    if (!std::isfinite(speed))
        return;
    speed = std::clamp(speed, kMinSpeed, kMaxSpeed);
    if (speed != m_speed) {
        if (m_playing) {
            // Re-anchor at the exact position reached so far, so that a speed change never jumps.
            const qint64 t = now();
            m_anchorFrame += static_cast<double>(t - m_anchorTime) * m_fps * m_speed / 1e9;
            m_anchorTime = t;
        }
        m_speed = speed;
        updateTimerInterval();
        emit speedChanged(speed);
    }
    updateSpeedCombo();
}

void TimelineWidget::updateSpeedCombo() {
    int index = m_speedCombo->findData(m_speed);
    if (index < 0) {
        // A speed between the presets (set from code) gets its own entry, in order.
        index = 0;
        while (index < m_speedCombo->count() && m_speedCombo->itemData(index).toDouble() < m_speed)
            ++index;
        m_speedCombo->insertItem(index, speedText(m_speed), m_speed);
    }
    m_speedCombo->setCurrentIndex(index);
}

void TimelineWidget::setLoop(bool loop) {
    if (loop == m_loop)
        return;
    m_loop = loop;
    m_loopAction->setChecked(loop);
    emit loopChanged(loop);
}

// ---- keys ---------------------------------------------------------------------------------------------------------

void TimelineWidget::stepForward() {
    pause();
    setCurrentFrame(m_current + 1);
    m_view->ensureVisible(m_current);
}

void TimelineWidget::stepBackward() {
    pause();
    setCurrentFrame(m_current - 1);
    m_view->ensureVisible(m_current);
}

void TimelineWidget::jumpToFirst() {
    setCurrentFrame(m_first);
    m_view->ensureVisible(m_current);
}

void TimelineWidget::jumpToLast() {
    setCurrentFrame(m_last);
    m_view->ensureVisible(m_current);
}

bool TimelineWidget::handlesKey(const QKeyEvent* event) const {
    const Qt::KeyboardModifiers mods = event->modifiers() & ~Qt::KeypadModifier;
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right:
    case Qt::Key_Home:
    case Qt::Key_End:
    case Qt::Key_Space:
        return mods == Qt::NoModifier;
    case Qt::Key_T:
        return mods == Qt::ControlModifier;
    default:
        return false;
    }
}

bool TimelineWidget::event(QEvent* event) {
    // The window's own shortcuts (Home frames the viewport, for one) must not take these keys from the timeline.
    if (event->type() == QEvent::ShortcutOverride && handlesKey(static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    return QWidget::event(event);
}

void TimelineWidget::keyPressEvent(QKeyEvent* event) {
    if (!handlesKey(event)) {
        QWidget::keyPressEvent(event);
        return;
    }
    switch (event->key()) {
    case Qt::Key_Left:
        stepBackward();
        break;
    case Qt::Key_Right:
        stepForward();
        break;
    case Qt::Key_Home:
        jumpToFirst();
        break;
    case Qt::Key_End:
        jumpToLast();
        break;
    case Qt::Key_Space:
        if (!event->isAutoRepeat())
            togglePlayback();
        break;
    case Qt::Key_T:
        setShowSeconds(!m_showSeconds);
        break;
    default:
        break;
    }
    event->accept();
}

} // namespace rl
