#include "overlays/OverlayController.h"

#include "MainWindow.h"

namespace rl {

OverlayController::OverlayController(MainWindow* window) : QObject(window), m_window(window) {}

void OverlayController::setEnabled(Kind kind, bool on) {
    if (m_enabled[kind] == on)
        return;
    m_enabled[kind] = on;
    emit enabledChanged(kind, on);
}

void OverlayController::setFrame(OverlayFrame frame) {
    m_frame = std::move(frame);
}

void OverlayController::clear() {
    m_frame = OverlayFrame{};
}

} // namespace rl
