#include "viewport/Camera.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rl {

namespace {
// Just short of straight up or down, so that lookAt's up vector never becomes parallel to the view direction.
constexpr float kMaxPitch = glm::radians(89.5f);
constexpr float kMinDistance = 1e-3f;
constexpr float kMaxDistance = 1e6f;
constexpr float kOrbitRadiansPerPixel = 0.008f; // about 0.46 degrees: a 400 px drag turns 180 degrees
} // namespace

void Camera::setViewportSize(int width, int height) {
    m_width = std::max(width, 1);
    m_height = std::max(height, 1);
}

void Camera::setDistance(float distance) {
    m_distance = std::clamp(distance, kMinDistance, kMaxDistance);
}

void Camera::setYaw(float yaw) {
    // Kept in (-pi, pi] so that repeated orbiting never loses float precision.
    m_yaw = std::remainder(yaw, glm::two_pi<float>());
}

void Camera::setPitch(float pitch) {
    m_pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
}

glm::vec3 Camera::forward() const {
    // yaw 0, pitch 0 looks along -Z (the front view); positive pitch tilts the view down onto the target.
    const float cp = std::cos(m_pitch);
    return glm::vec3(-cp * std::sin(m_yaw), -std::sin(m_pitch), -cp * std::cos(m_yaw));
}

glm::vec3 Camera::eye() const {
    return m_target - m_distance * forward();
}

glm::vec3 Camera::right() const {
    return glm::normalize(glm::cross(forward(), glm::vec3(0.0f, 1.0f, 0.0f)));
}

glm::vec3 Camera::up() const {
    return glm::cross(right(), forward());
}

float Camera::nearPlane() const {
    return m_distance * 0.005f;
}

float Camera::farPlane() const {
    return m_distance * 200.0f + 100.0f;
}

glm::mat4 Camera::view() const {
    return glm::lookAt(eye(), m_target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection() const {
    return glm::perspective(m_fovY, aspect(), nearPlane(), farPlane());
}

void Camera::orbit(float dxPixels, float dyPixels) {
    // Dragging right swings the camera to the left around the target, so the scene appears to turn with the mouse.
    setYaw(m_yaw - dxPixels * kOrbitRadiansPerPixel);
    setPitch(m_pitch + dyPixels * kOrbitRadiansPerPixel);
}

void Camera::pan(float dxPixels, float dyPixels) {
    const float unit = worldPerPixelAtTarget();
    m_target += (-dxPixels * unit) * right() + (dyPixels * unit) * up();
}

void Camera::zoom(float factor) {
    if (factor > 0.0f)
        setDistance(m_distance * factor);
}

float Camera::worldPerPixelAtTarget() const {
    return 2.0f * m_distance * std::tan(0.5f * m_fovY) / static_cast<float>(m_height);
}

void Camera::frame(const Bounds& box) {
    if (box.isEmpty())
        return;
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-3f);
    const float halfFovY = 0.5f * m_fovY;
    const float halfFovX = std::atan(std::tan(halfFovY) * aspect());
    // A sphere of radius r fits a cone of half-angle a when the centre is r / sin(a) away; 5% keeps a margin.
    const float halfFov = std::min(halfFovY, halfFovX);
    m_target = box.centre();
    setDistance(1.05f * radius / std::sin(halfFov));
}

ViewRay Camera::unproject(float x, float y) const {
    const float ndcX = 2.0f * x / static_cast<float>(m_width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * y / static_cast<float>(m_height);
    const glm::mat4 inverse = glm::inverse(viewProjection());
    glm::vec4 nearPoint = inverse * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    ViewRay ray;
    ray.origin = eye();
    ray.direction = glm::normalize(glm::vec3(farPoint) - glm::vec3(nearPoint));
    return ray;
}

glm::vec3 Camera::project(const glm::vec3& world) const {
    glm::vec4 clip = viewProjection() * glm::vec4(world, 1.0f);
    if (clip.w <= 0.0f)
        return glm::vec3(-1e9f, -1e9f, 2.0f); // behind the eye: never inside a rectangle, never in the depth range
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return glm::vec3((ndc.x + 1.0f) * 0.5f * static_cast<float>(m_width),
                     (1.0f - ndc.y) * 0.5f * static_cast<float>(m_height), ndc.z);
}

} // namespace rl
