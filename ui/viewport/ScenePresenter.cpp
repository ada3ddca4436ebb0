#include "viewport/ScenePresenter.h"

#include "geometry/MeshTools.h"
#include "geometry/RayCast.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>

namespace rl {

namespace {

// Bytes that identify a mesh up to translation: vertices relative to the first one, rounded to 1e-6 m.
std::string meshKey(const std::vector<Vec3>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::string key;
    key.reserve(vertices.size() * 12 + triangles.size() * 12);
    const Vec3 origin = vertices.empty() ? Vec3(0.0) : vertices.front();
    for (const Vec3& v : vertices)
        for (int k = 0; k < 3; ++k) {
            const int32_t q = static_cast<int32_t>(std::llround((v[k] - origin[k]) * 1e6));
            key.append(reinterpret_cast<const char*>(&q), sizeof q);
        }
    key.push_back('|');
    key.append(reinterpret_cast<const char*>(triangles.data()), triangles.size() * sizeof(triangles[0]));
    return key;
}

} // namespace

glm::vec3 ScenePresenter::bodyColour(size_t index, bool anchor) {
    if (anchor)
        return glm::vec3(0.55f);
    // Golden-ratio hues: neighbouring bodies differ clearly, and the same index always gets the same colour.
    const float hue = std::fmod(0.08f + 0.618034f * static_cast<float>(index), 1.0f);
    const float s = 0.55f, v = 0.9f;
    const float h6 = hue * 6.0f;
    const float c = v * s, x = c * (1.0f - std::abs(std::fmod(h6, 2.0f) - 1.0f)), m = v - c;
    glm::vec3 rgb;
    switch (static_cast<int>(h6) % 6) {
    case 0:
        rgb = {c, x, 0};
        break;
    case 1:
        rgb = {x, c, 0};
        break;
    case 2:
        rgb = {0, c, x};
        break;
    case 3:
        rgb = {0, x, c};
        break;
    case 4:
        rgb = {x, 0, c};
        break;
    default:
        rgb = {c, 0, x};
        break;
    }
    return rgb + glm::vec3(m);
}

void ScenePresenter::rebuild(const Scene& scene) {
    m_bodies.clear();
    if (m_cache.size() > scene.bodies.size())
        m_cache.resize(scene.bodies.size());
    m_viewportScene = ViewportScene{};
    std::unordered_map<std::string, int> meshByKey;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyDef& def = scene.bodies[i];
        BodyShape body;
        body.type = def.shape.type;
        body.halfExtents = def.shape.halfExtents;
        body.radius = def.shape.radius;
        body.position = def.position;
        body.orientation = glm::normalize(def.orientation);

        if (i >= m_cache.size())
            m_cache.resize(i + 1);
        ShapeCache& cache = m_cache[i];
        if (cache.key.empty() || !(cache.shape == def.shape)) {
            cache = ShapeCache{};
            cache.shape = def.shape;
            switch (def.shape.type) {
            case ShapeType::Box:
                cache.key = "box" + std::to_string(def.shape.halfExtents.x) + "," +
                            std::to_string(def.shape.halfExtents.y) + "," + std::to_string(def.shape.halfExtents.z);
                break;
            case ShapeType::Sphere:
                cache.key = "sphere" + std::to_string(def.shape.radius);
                break;
            case ShapeType::Hull: {
                cache.hull = computeConvexHull(def.shape.points);
                const TriangleMesh mesh = hullMesh(cache.hull);
                cache.vertices = mesh.vertices;
                cache.triangles = mesh.triangles;
                cache.key = meshKey(cache.vertices, cache.triangles);
                break;
            }
            case ShapeType::Mesh:
                cache.hull = computeConvexHull(def.shape.points);
                cache.vertices = def.shape.points;
                cache.triangles = def.shape.triangles;
                if (cache.triangles.empty()) {
                    const TriangleMesh mesh = hullMesh(cache.hull);
                    cache.vertices = mesh.vertices;
                    cache.triangles = mesh.triangles;
                }
                cache.key = meshKey(cache.vertices, cache.triangles);
                break;
            }
        }
        body.hull = cache.hull;
        const std::vector<Vec3>& vertices = cache.vertices;
        const std::vector<std::array<uint32_t, 3>>& triangles = cache.triangles;
        std::string key = cache.key;

        auto found = meshByKey.find(key);
        int meshIndex;
        if (found != meshByKey.end()) {
            meshIndex = found->second;
            if (!vertices.empty())
                body.meshOffset =
                    glm::vec3(vertices.front() - Vec3(m_viewportScene.meshes[meshIndex].vertices.front()));
        } else {
            ViewportMesh mesh;
            if (def.shape.type == ShapeType::Box) {
                mesh = makeViewportBoxMesh(glm::vec3(def.shape.halfExtents));
            } else if (def.shape.type == ShapeType::Sphere) {
                mesh = makeViewportSphereMesh(static_cast<float>(def.shape.radius), 24, 12);
            } else {
                // Store the mesh about its first vertex so instances with other translations can share it, in
                // float without losing precision far from the origin.
                const Vec3 origin = vertices.empty() ? Vec3(0.0) : vertices.front();
                mesh.vertices.reserve(vertices.size());
                for (const Vec3& v : vertices)
                    mesh.vertices.emplace_back(v - origin);
                mesh.triangles = triangles;
                body.meshOffset = glm::vec3(origin);
            }
            meshIndex = static_cast<int>(m_viewportScene.meshes.size());
            m_viewportScene.meshes.push_back(std::move(mesh));
            meshByKey.emplace(std::move(key), meshIndex);
        }

        ViewportInstance instance;
        instance.meshIndex = meshIndex;
        instance.colour = bodyColour(i, def.anchor);
        instance.flags = def.anchor ? kInstanceAnchor : 0u;
        m_bodies.push_back(std::move(body));
        instance.model = model(i, def.position, def.orientation);
        m_viewportScene.instances.push_back(instance);
    }
}

glm::mat4 ScenePresenter::model(size_t i, const Vec3& position, const Quat& orientation) const {
    const BodyShape& body = m_bodies[i];
    return instanceTransform(position, orientation, glm::translate(glm::mat4(1.0f), body.meshOffset));
}

int ScenePresenter::pick(const ViewRay& viewRay) const {
    Ray ray;
    ray.origin = Vec3(viewRay.origin);
    ray.direction = Vec3(viewRay.direction);
    constexpr Real kFar = 1e6;
    int best = -1;
    Real bestDistance = kFar;
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        const BodyShape& b = m_bodies[i];
        std::optional<ShapeRayHit> hit;
        switch (b.type) {
        case ShapeType::Box:
            hit = rayBox(ray, bestDistance, b.position, b.orientation, b.halfExtents, RayStartInside::Ignore);
            break;
        case ShapeType::Sphere:
            hit = raySphere(ray, bestDistance, b.position, b.radius, RayStartInside::Ignore);
            break;
        case ShapeType::Hull:
        case ShapeType::Mesh:
            hit = rayHull(ray, bestDistance, b.hull, b.position, b.orientation, RayStartInside::Ignore);
            break;
        }
        if (hit && hit->distance < bestDistance) {
            bestDistance = hit->distance;
            best = static_cast<int>(i);
        }
    }
    return best;
}

} // namespace rl
