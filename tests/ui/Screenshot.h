// Screenshots of editor windows for looking at: QWidget::grab() paints the widgets only, and the viewport draws into
// a native child window, so its frame is rendered offscreen and painted in where the viewport sits.
#pragma once

#include "viewport/Viewport.h"

#include <QImage>
#include <QPainter>
#include <QWidget>

namespace rl::test {

inline QImage screenshot(QWidget& window) {
    QImage image = window.grab().toImage();
    QPainter painter(&image);
    for (Viewport* viewport : window.findChildren<Viewport*>())
        if (viewport->isVisible())
            painter.drawImage(QRect(viewport->mapTo(&window, QPoint(0, 0)), viewport->size()),
                              viewport->grabFramebuffer());
    return image;
}

} // namespace rl::test
