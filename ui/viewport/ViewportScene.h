// What the viewport draws: unique meshes shared by instances, each instance with a transform, a colour and flags.
// Plain data filled by the owner (the main window) from the Scene; the viewport never sees the Scene or the World.
#pragma once

#include "viewport/ViewportTypes.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace rl {

// Instance flags. Anchors are drawn grey whatever their colour, so static bodies read differently at a glance.
inline constexpr uint32_t kInstanceAnchor = 1u << 0;
inline constexpr uint32_t kInstanceSelected = 1u << 1;
inline constexpr uint32_t kInstanceSleeping = 1u << 2;
inline constexpr uint32_t kInstanceHidden = 1u << 3;

struct ViewportMesh {
    // Shape coordinates. Normals are not stored: the renderer shades every triangle flat (a faceted look).
    std::vector<glm::vec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles; // counter-clockwise seen from outside

    Bounds bounds() const;
};

struct ViewportInstance {
    int meshIndex = 0;
    glm::mat4 model{1.0f}; // shape coordinates -> world, see instanceTransform()
    glm::vec3 colour{0.8f};
    uint32_t flags = 0;
};

struct ViewportScene {
    std::vector<ViewportMesh> meshes;
    std::vector<ViewportInstance> instances;

    // World bounds of one instance (its mesh box, transformed); empty for a bad mesh index.
    Bounds instanceBounds(int instance) const;
    // Union over the visible instances; with selectedOnly, over the selected ones.
    Bounds bounds(bool selectedOnly = false) const;
    // What a scene is about: the union over the visible instances but a ground that dwarfs them, the largest anchor
    // where it is more than kGroundRatio times the size (box diagonal) of the union of all the others and its top is
    // no higher than their bottom (+y is up): a Blender ground plane of 40 m under a row of dominoes 3.6 m long, a
    // 400 m floor under a 4 m wall and a shot. A wall beside a shot stays, however much larger. Empty for an empty
    // scene.
    static constexpr float kGroundRatio = 5.0f;
    Bounds contentBounds() const;
    // Nearest instance whose world box the ray enters, or -1. A stand-in until the owner sets a real pick function.
    int pickBounds(const ViewRay& ray) const;
};

// Faceted shading without a vertex per face corner. A flat shader input comes from a triangle's last vertex (GL's
// provoking vertex), so every triangle is turned (its winding kept) to end on a vertex that carries the triangle's
// normal, and the vertex shader lights the face once there. A vertex carries one normal: a triangle whose three
// vertices already carry other normals ends on a copy of one of them. A box keeps its 8 vertices.
struct FlatShadedVertex {
    glm::vec3 position;
    glm::vec3 normal; // unit; the normal of the triangles that end on this vertex
};
struct FlatShadedMesh {
    std::vector<FlatShadedVertex> vertices;
    std::vector<std::array<uint32_t, 3>> triangles; // the mesh's triangles in order, each ending on its normal
};
FlatShadedMesh flatShaded(const ViewportMesh& mesh);

// Model matrix of a body: translate(position) * rotate(orientation) * shapeFrame. The shape frame places the mesh's
// coordinates in body coordinates (identity when the mesh is already in shape coordinates).
glm::mat4 instanceTransform(const glm::dvec3& position, const glm::dquat& orientation,
                            const glm::mat4& shapeFrame = glm::mat4(1.0f));

// Handy meshes for the owner and the tests: a box of given half extents, and a faceted UV sphere.
ViewportMesh makeViewportBoxMesh(const glm::vec3& halfExtents);
ViewportMesh makeViewportSphereMesh(float radius, int segments = 16, int rings = 8);

} // namespace rl
