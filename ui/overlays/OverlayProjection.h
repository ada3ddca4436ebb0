// World -> widget pixels for the viewport overlays: the camera's view-projection applied once per point, with
// frustum tests (culling) and near-plane clipping of segments, so that nothing behind the eye is ever drawn.
#pragma once

#include <QLineF>
#include <QPointF>
#include <QSizeF>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace rl {

class Camera;

class ScreenProjector {
public:
    // Outcode bits of a clip-space point against the frustum planes (OpenGL convention, -w <= x, y, z <= w).
    enum : uint8_t { kLeft = 1, kRight = 2, kBottom = 4, kTop = 8, kNear = 16, kFar = 32 };

    // size: the widget in logical pixels, pixel (0, 0) at the top-left corner (as Camera::project).
    ScreenProjector(const glm::mat4& viewProjection, const QSizeF& size);
    ScreenProjector(const Camera& camera, const QSizeF& size);

    glm::vec4 clip(const glm::vec3& world) const { return m_viewProjection * glm::vec4(world, 1.0f); }
    // Frustum planes the point lies outside of; marginPixels widens the side planes (a cross or an arrow head
    // centred just off-screen still shows).
    uint8_t outcode(const glm::vec4& clip, float marginPixels = 0.0f) const;
    // Pixel of a clip-space point; only meaningful for w > 0.
    QPointF pixel(const glm::vec4& clip) const;
    // Pixel of a world point, or nothing when it lies behind the near plane.
    std::optional<QPointF> toPixel(const glm::vec3& world) const;

    // The part of a segment in front of the near plane, in pixels. False when none of it is in front, or when it
    // lies wholly outside one side of the frustum (nothing of it can show).
    bool segment(const glm::vec3& a, const glm::vec3& b, QLineF& out) const;
    bool clipSegment(glm::vec4 a, glm::vec4 b, QLineF& out) const;
    // Like clipSegment but also says whether the end b had to be moved (so an arrow head at b would be wrong).
    bool clipSegment(glm::vec4 a, glm::vec4 b, QLineF& out, bool& endClipped) const;

    const QSizeF& size() const { return m_size; }

private:
    glm::mat4 m_viewProjection;
    QSizeF m_size;
};

} // namespace rl
