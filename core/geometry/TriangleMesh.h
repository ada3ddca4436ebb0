// An indexed triangle mesh: the exchange format between importers, primitive generators, hulls and the renderer.
// Triangles are counter-clockwise seen from outside, so that the right-hand normal points out of the solid.
#pragma once

#include "math/Types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rl {

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles; // indices into vertices, counter-clockwise from outside
};

} // namespace rl
