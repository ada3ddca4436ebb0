// 2D overlays painted over the viewport's GL image with QPainter: the axis indicator and the box-select rectangle.
// They are vector drawings in widget pixels, so they stay crisp and need no GL resources of their own.
#pragma once

#include "viewport/Camera.h"

#include <QPointF>
#include <QRect>

class QPainter;

namespace rl {

// X red, Y green, Z blue, seen with the camera's rotation, centred at `centre` (widget pixels).
void paintAxisGizmo(QPainter& painter, const Camera& camera, const QPointF& centre, float radiusPixels);

void paintSelectionRectangle(QPainter& painter, const QRect& rectangle);

} // namespace rl
