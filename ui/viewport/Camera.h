// Orbit camera of the editor viewport: a target, a distance and yaw/pitch angles, with a perspective projection.
// Pure math (glm, no Qt, no GL) so that framing and picking rays are unit-tested without a window.
#pragma once

#include "viewport/ViewportTypes.h"

#include <glm/glm.hpp>

namespace rl {

class Camera {
public:
    // Logical pixels of the widget; pixel (0, 0) is the top-left corner, as in Qt mouse events.
    void setViewportSize(int width, int height);
    int width() const { return m_width; }
    int height() const { return m_height; }
    float aspect() const { return static_cast<float>(m_width) / static_cast<float>(m_height); }

    glm::vec3 target() const { return m_target; }
    float distance() const { return m_distance; }
    float yaw() const { return m_yaw; }     // radians about +Y; 0 looks along -Z
    float pitch() const { return m_pitch; } // radians; positive looks down on the target
    float fovY() const { return m_fovY; }   // radians, vertical
    void setTarget(const glm::vec3& target) { m_target = target; }
    void setDistance(float distance);
    void setYaw(float yaw);
    void setPitch(float pitch);
    void setFovY(float fovY) { m_fovY = fovY; }

    glm::vec3 eye() const;
    glm::vec3 forward() const; // unit, from the eye towards the target
    glm::vec3 right() const;
    glm::vec3 up() const;

    // Clip planes follow the distance, so depth precision stays useful from a 1 cm part to a 1 km field.
    float nearPlane() const;
    float farPlane() const;

    glm::mat4 view() const;
    glm::mat4 projection() const;
    glm::mat4 viewProjection() const { return projection() * view(); }

    // Mouse-driven moves, in pixels so that the speed feels the same at every zoom level.
    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels); // the point under the cursor follows the cursor at the target's depth
    void zoom(float factor);                  // distance *= factor

    // Aims at the box centre and backs off until the box's bounding sphere fits the narrower field of view.
    void frame(const Bounds& box);

    // World ray through a pixel (logical pixel coordinates, fractional allowed), starting at the eye.
    ViewRay unproject(float x, float y) const;
    // World point -> logical pixel (x, y) and NDC depth (z). z outside [-1, 1] means outside the clip range.
    glm::vec3 project(const glm::vec3& world) const;

    // World size of one pixel at the target's depth: the unit that pan and the overlays use.
    float worldPerPixelAtTarget() const;

private:
    glm::vec3 m_target{0.0f};
    float m_distance = 10.0f;
    float m_yaw = glm::radians(30.0f);
    float m_pitch = glm::radians(25.0f);
    float m_fovY = glm::radians(45.0f);
    int m_width = 1;
    int m_height = 1;
};

} // namespace rl
