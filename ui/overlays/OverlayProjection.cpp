#include "overlays/OverlayProjection.h"

#include "viewport/Camera.h"

#include <algorithm>

namespace rl {

ScreenProjector::ScreenProjector(const glm::mat4& viewProjection, const QSizeF& size)
    : m_viewProjection(viewProjection), m_size(size) {}

ScreenProjector::ScreenProjector(const Camera& camera, const QSizeF& size)
    : ScreenProjector(camera.viewProjection(), size) {}

uint8_t ScreenProjector::outcode(const glm::vec4& c, float marginPixels) const {
    // A margin of m pixels is 2m / width in NDC, so the side planes move out to w * (1 + 2m / width).
    const float wx = c.w * (1.0f + 2.0f * marginPixels / static_cast<float>(std::max(m_size.width(), 1.0)));
    const float wy = c.w * (1.0f + 2.0f * marginPixels / static_cast<float>(std::max(m_size.height(), 1.0)));
    uint8_t code = 0;
    if (c.x < -wx)
        code |= kLeft;
    if (c.x > wx)
        code |= kRight;
    if (c.y < -wy)
        code |= kBottom;
    if (c.y > wy)
        code |= kTop;
    if (c.z < -c.w)
        code |= kNear;
    if (c.z > c.w)
        code |= kFar;
    return code;
}

QPointF ScreenProjector::pixel(const glm::vec4& c) const {
    const float inv = 1.0f / c.w;
    return QPointF((c.x * inv + 1.0f) * 0.5 * m_size.width(), (1.0f - c.y * inv) * 0.5 * m_size.height());
}

std::optional<QPointF> ScreenProjector::toPixel(const glm::vec3& world) const {
    const glm::vec4 c = clip(world);
    if (c.z < -c.w || c.w <= 0.0f)
        return std::nullopt;
    return pixel(c);
}

bool ScreenProjector::segment(const glm::vec3& a, const glm::vec3& b, QLineF& out) const {
    return clipSegment(clip(a), clip(b), out);
}

bool ScreenProjector::clipSegment(glm::vec4 a, glm::vec4 b, QLineF& out) const {
    bool endClipped = false;
    return clipSegment(a, b, out, endClipped);
}

bool ScreenProjector::clipSegment(glm::vec4 a, glm::vec4 b, QLineF& out, bool& endClipped) const {
    endClipped = false;
    if (outcode(a) & outcode(b))
        return false; // both beyond the same plane, near plane included
    // Signed distances to the near plane z = -w; a point on it has w = near > 0, so the division below is safe.
    const float da = a.z + a.w;
    const float db = b.z + b.w;
    if (da < 0.0f)
        a = a + (b - a) * (da / (da - db));
    else if (db < 0.0f) {
        b = b + (a - b) * (db / (db - da));
        endClipped = true;
    }
    if (a.w <= 0.0f || b.w <= 0.0f)
        return false;
    out = QLineF(pixel(a), pixel(b));
    return true;
}

} // namespace rl
