// Turns a simulated state into viewport poses: World and Bake both give each body's centre (of mass, or the vertex
// mean for the original project's files) and its rotation since frame 0, while the presenter places bodies by their
// shape origin and orientation. Also picks against the displayed poses, so clicking a falling body selects it.
#pragma once

#include "geometry/ConvexHull.h"
#include "scene/Scene.h"
#include "viewport/ViewportTypes.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace rl {

class ScenePresenter;

class PoseMapper {
public:
    // The edit poses come from the scene; referenceCentres are the centres of frame 0 that the states' centres are
    // measured against (one per body).
    void reset(const Scene& scene, std::vector<Vec3> referenceCentres);
    void clear();
    size_t bodyCount() const { return m_origin.size(); }

    // Body i rigidly moved so that its reference centre is at `centre` and it turned by `rotation` about it:
    //   origin = P + (centre - c0) + (R (P - c0) - (P - c0)),   orientation = R Q.
    // The translation is written as differences so that an unmoved body lands exactly on its edit pose.
    void pose(size_t i, const Vec3& centre, const Quat& rotation, Vec3& origin, Quat& orientation) const;

    // Model matrices for a whole state (centres and rotations in body order), plus the poses for picking.
    template <typename V, typename Q>
    void models(const ScenePresenter& presenter, const V* centres, const Q* rotations, std::vector<glm::mat4>& out);

    // Nearest body under the ray at the poses of the last models() call, or -1.
    int pick(const ViewRay& ray) const;

private:
    const ConvexHull& hull(size_t i) const;

    const Scene* m_scene = nullptr; // the document's scene, valid until the next reset (hulls are built lazily)
    std::vector<Vec3> m_origin;     // edit pose: shape origin
    std::vector<Quat> m_orientation;
    std::vector<Vec3> m_reference;
    // Displayed poses.
    std::vector<Vec3> m_shownOrigin;
    std::vector<Quat> m_shownOrientation;
    mutable std::vector<std::optional<ConvexHull>> m_hulls;
};

} // namespace rl
