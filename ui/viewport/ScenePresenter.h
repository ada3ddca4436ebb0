// Turns a scene definition into what the viewport draws (shared meshes, one instance per body) and answers the
// viewport's picks with the core's exact ray casts against each body's collision shape.
#pragma once

#include "geometry/ConvexHull.h"
#include "scene/Scene.h"
#include "viewport/ViewportScene.h"

#include <array>
#include <string>
#include <vector>

namespace rl {

class ScenePresenter {
public:
    // Rebuilds everything from the scene. Bodies whose shape is identical up to a translation share one mesh, so a
    // Blender scene of 642 equal cubes draws with one mesh and 642 instances.
    void rebuild(const Scene& scene);

    const ViewportScene& viewportScene() const { return m_viewportScene; }
    // Body index hit first by the ray, or -1.
    int pick(const ViewRay& ray) const;
    // Model matrix of body i for a pose given as a rigid motion of its shape coordinates.
    glm::mat4 model(size_t body, const Vec3& position, const Quat& orientation) const;

    static glm::vec3 bodyColour(size_t index, bool anchor);

private:
    struct BodyShape {
        ShapeType type = ShapeType::Box;
        Vec3 halfExtents{0.0};
        Real radius = 0.0;
        ConvexHull hull; // shape coordinates (Hull and Mesh bodies)
        Vec3 position{0.0};
        Quat orientation{1.0, 0.0, 0.0, 0.0};
        glm::vec3 meshOffset{0.0f}; // where the shared mesh's origin sits in shape coordinates
    };
    // What a body's shape costs to prepare (hull, drawn mesh, sharing key), kept per body index so that a rebuild
    // after a move or a rename (the shape unchanged) skips the hull computation.
    struct ShapeCache {
        ShapeDef shape;
        ConvexHull hull;
        std::vector<Vec3> vertices;
        std::vector<std::array<uint32_t, 3>> triangles;
        std::string key;
    };
    std::vector<BodyShape> m_bodies;
    std::vector<ShapeCache> m_cache;
    ViewportScene m_viewportScene;
};

} // namespace rl
