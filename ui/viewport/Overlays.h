// The viewport's axis indicator, painted with QPainter into an image that the renderer blends over the frame.
// Vector drawing in logical pixels, so it stays crisp at any device pixel ratio.
#pragma once

#include "viewport/Camera.h"

#include <QPointF>

class QPainter;

namespace rl {

// X red, Y green, Z blue, seen with the camera's rotation, centred at `centre` (widget pixels).
void paintAxisGizmo(QPainter& painter, const Camera& camera, const QPointF& centre, float radiusPixels);

} // namespace rl
