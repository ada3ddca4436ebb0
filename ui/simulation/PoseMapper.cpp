#include "simulation/PoseMapper.h"

#include "geometry/RayCast.h"
#include "viewport/ScenePresenter.h"

namespace rl {

void PoseMapper::reset(const Scene& scene, std::vector<Vec3> referenceCentres) {
    m_scene = &scene;
    const size_t n = scene.bodies.size();
    m_origin.resize(n);
    m_orientation.resize(n);
    for (size_t i = 0; i < n; ++i) {
        m_origin[i] = scene.bodies[i].position;
        m_orientation[i] = glm::normalize(scene.bodies[i].orientation);
    }
    m_reference = std::move(referenceCentres);
    m_reference.resize(n, Vec3(0.0));
    m_shownOrigin = m_origin;
    m_shownOrientation = m_orientation;
    m_hulls.assign(n, std::nullopt);
}

void PoseMapper::clear() {
    m_scene = nullptr;
    m_origin.clear();
    m_orientation.clear();
    m_reference.clear();
    m_shownOrigin.clear();
    m_shownOrientation.clear();
    m_hulls.clear();
}

void PoseMapper::pose(size_t i, const Vec3& centre, const Quat& rotation, Vec3& origin, Quat& orientation) const {
    const Vec3 arm = m_origin[i] - m_reference[i];
    origin = m_origin[i] + (centre - m_reference[i]) + (rotation * arm - arm);
    orientation = rotation * m_orientation[i];
}

template <typename V, typename Q>
void PoseMapper::models(const ScenePresenter& presenter, const V* centres, const Q* rotations,
                        std::vector<glm::mat4>& out) {
    const size_t n = m_origin.size();
    out.resize(n);
    for (size_t i = 0; i < n; ++i) {
        pose(i, Vec3(centres[i]), Quat(rotations[i]), m_shownOrigin[i], m_shownOrientation[i]);
        out[i] = presenter.model(i, m_shownOrigin[i], m_shownOrientation[i]);
    }
}

template void PoseMapper::models(const ScenePresenter&, const glm::vec3*, const glm::quat*, std::vector<glm::mat4>&);
template void PoseMapper::models(const ScenePresenter&, const Vec3*, const Quat*, std::vector<glm::mat4>&);

const ConvexHull& PoseMapper::hull(size_t i) const {
    if (!m_hulls[i])
        m_hulls[i] = computeConvexHull(m_scene->bodies[i].shape.points);
    return *m_hulls[i];
}

int PoseMapper::pick(const ViewRay& viewRay) const {
    if (!m_scene || m_scene->bodies.size() != m_shownOrigin.size())
        return -1;
    Ray ray;
    ray.origin = Vec3(viewRay.origin);
    ray.direction = Vec3(viewRay.direction);
    Real best = 1e6;
    int hitBody = -1;
    for (size_t i = 0; i < m_shownOrigin.size(); ++i) {
        const ShapeDef& shape = m_scene->bodies[i].shape;
        std::optional<ShapeRayHit> hit;
        switch (shape.type) {
        case ShapeType::Box:
            hit = rayBox(ray, best, m_shownOrigin[i], m_shownOrientation[i], shape.halfExtents, RayStartInside::Ignore);
            break;
        case ShapeType::Sphere:
            hit = raySphere(ray, best, m_shownOrigin[i], shape.radius, RayStartInside::Ignore);
            break;
        case ShapeType::Hull:
        case ShapeType::Mesh:
            hit = rayHull(ray, best, hull(i), m_shownOrigin[i], m_shownOrientation[i], RayStartInside::Ignore);
            break;
        }
        if (hit && hit->distance < best) {
            best = hit->distance;
            hitBody = static_cast<int>(i);
        }
    }
    return hitBody;
}

} // namespace rl
