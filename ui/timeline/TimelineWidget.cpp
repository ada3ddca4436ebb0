#include "timeline/TimelineWidget.h"

#include "bake/Bake.h"

#include <algorithm>

namespace rl {

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
    setObjectName("Timeline");
}

TimelineWidget::~TimelineWidget() = default;

void TimelineWidget::setFrameRange(int first, int last) {
    m_first = first;
    m_last = std::max(first, last);
    update();
}

void TimelineWidget::setFps(double fps) {
    m_fps = fps;
}

void TimelineWidget::setBake(std::shared_ptr<const Bake> bake) {
    m_bake = std::move(bake);
    update();
}

void TimelineWidget::setStale(bool stale) {
    m_stale = stale;
    update();
}

void TimelineWidget::setProgress(double, const QString&) {
    update();
}

void TimelineWidget::setCurrentFrame(int frame) {
    frame = std::clamp(frame, m_first, m_last);
    if (frame == m_current)
        return;
    m_current = frame;
    update();
    emit currentFrameChanged(frame);
}

void TimelineWidget::play() {
    if (!m_playing) {
        m_playing = true;
        emit playingChanged(true);
    }
}

void TimelineWidget::pause() {
    if (m_playing) {
        m_playing = false;
        emit playingChanged(false);
    }
}

void TimelineWidget::setSpeed(double speed) {
    m_speed = std::clamp(speed, 0.25, 4.0);
}

void TimelineWidget::setLoop(bool loop) {
    m_loop = loop;
}

} // namespace rl
