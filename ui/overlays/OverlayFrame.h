// What the viewport overlays draw for one displayed state (live step or baked frame): plain data, filled by the
// simulation controller from the World or a Bake, drawn by the OverlayController.
#pragma once

#include "viewport/ViewportTypes.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace rl {

struct OverlayContact {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f}; // unit, from the first body to the second
    float depth = 0.0f;                 // penetration, metres (>= 0)
};

struct OverlayFrame {
    int frame = -1; // the displayed frame; trails restart when it does not follow the previous one
    // Per body, in body order (empty vectors mean "not available in this state").
    std::vector<glm::vec3> centres;          // centre of mass, world
    std::vector<glm::vec3> linearVelocities; // m/s, world
    std::vector<Bounds> aabbs;               // world boxes
    std::vector<uint8_t> sleeping;           // 1 = asleep
    std::vector<OverlayContact> contacts;    // live runs; empty for baked frames unless recorded
};

} // namespace rl
