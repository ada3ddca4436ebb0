// Small value types shared by the viewport's camera, scene and picking: a world-space ray and an axis-aligned box.
// They are float (glm::vec3) because they only serve drawing and picking; the core's double types stay in the core.
#pragma once

#include <glm/glm.hpp>

#include <limits>

namespace rl {

struct ViewRay {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // unit length
};

struct Bounds {
    // Starts inverted so that the first extend() sets both corners.
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 centre() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& b) {
        if (!b.isEmpty()) {
            extend(b.min);
            extend(b.max);
        }
    }
};

// Slab test. Returns the entry distance along the ray, or a negative number when the ray misses the box.
inline float intersectRayBounds(const ViewRay& ray, const Bounds& box) {
    float tNear = 0.0f;
    float tFar = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        const float d = ray.direction[axis];
        const float o = ray.origin[axis];
        if (d == 0.0f) {
            if (o < box.min[axis] || o > box.max[axis])
                return -1.0f;
            continue;
        }
        float t0 = (box.min[axis] - o) / d;
        float t1 = (box.max[axis] - o) / d;
        if (t0 > t1)
            std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
        if (tNear > tFar)
            return -1.0f;
    }
    return tNear;
}

} // namespace rl
