// Definition of one body as the user authored it: shape, placement, material and initial motion.
// Definitions are edited by the UI and turned into runtime state by the World; they hold nothing derived.
#pragma once

#include "math/Types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

enum class ShapeType { Box, Sphere, Hull, Mesh };

struct ShapeDef {
    ShapeType type = ShapeType::Box;
    Vec3 halfExtents{0.5};                          // Box
    Real radius = 0.5;                              // Sphere
    std::vector<Vec3> points;                       // Hull: points; Mesh: vertices (shape coordinates)
    std::vector<std::array<uint32_t, 3>> triangles; // Mesh: triangles (N-gons fan-triangulated)
    std::string objFile;                            // Mesh from .rlscene {"obj": file, "object": name}
    std::string objObject;

    bool operator==(const ShapeDef&) const = default;
};

struct BodyDef {
    std::string name;
    bool anchor = false;              // static
    std::string material = "Default"; // a preset or a scene material
    std::optional<Real> density;      // overrides the material's density
    std::optional<Real> mass;         // overrides density x volume
    std::optional<Real> friction;
    std::optional<Real> restitution;
    Vec3 position{0.0}; // places shape coordinates in the world
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    Vec3 velocity{0.0};        // initial linear velocity of the centre of mass, m/s
    Vec3 angularVelocity{0.0}; // initial angular velocity, rad/s, world axes
    ShapeDef shape;

    bool operator==(const BodyDef&) const = default;
};

// The anchor rule of the original project: strip every '.' followed by digits; "Anchor" remains -> static.
bool isAnchorName(std::string_view objectName);

} // namespace rl
