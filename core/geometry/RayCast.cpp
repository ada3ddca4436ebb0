#include "geometry/RayCast.h"

#include <cmath>
#include <limits>

namespace rl {

namespace {

constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Checks the ray and returns its unit direction, or nullopt when the ray cannot be cast.
std::optional<Vec3> unitDirection(const Ray& ray, Real maxDistance) {
    if (!isFinite(ray.origin) || !isFinite(ray.direction) || std::isnan(maxDistance) || maxDistance < 0.0)
        return std::nullopt;
    const Real length = glm::length(ray.direction);
    if (!(length > 0.0) || !std::isfinite(length))
        return std::nullopt;
    return ray.direction / length;
}

std::optional<ShapeRayHit> startInside(const Vec3& origin, const Vec3& dir, RayStartInside inside) {
    if (inside == RayStartInside::Ignore)
        return std::nullopt;
    return ShapeRayHit{0.0, origin, -dir};
}

} // namespace

std::optional<ShapeRayHit> raySphere(const Ray& ray, Real maxDistance, const Vec3& center, Real radius,
                                     RayStartInside inside) {
    const std::optional<Vec3> d = unitDirection(ray, maxDistance);
    if (!d || !(radius > 0.0) || !std::isfinite(radius) || !isFinite(center))
        return std::nullopt;
    // |m + t d|^2 = r^2 with |d| = 1: t^2 + 2 b t + c = 0.
    const Vec3 m = ray.origin - center;
    const Real b = glm::dot(m, *d);
    const Real c = glm::dot(m, m) - radius * radius;
    if (c < 0.0)
        return startInside(ray.origin, *d, inside);
    if (b > 0.0)
        return std::nullopt; // outside and moving away
    const Real discriminant = b * b - c;
    if (discriminant < 0.0)
        return std::nullopt;
    const Real t = std::max(0.0, -b - std::sqrt(discriminant));
    if (t > maxDistance)
        return std::nullopt;
    const Vec3 point = ray.origin + t * *d;
    return ShapeRayHit{t, point, glm::normalize(point - center)};
}

std::optional<ShapeRayHit> rayBox(const Ray& ray, Real maxDistance, const Vec3& center, const Quat& orientation,
                                  const Vec3& halfExtents, RayStartInside inside) {
    const std::optional<Vec3> d = unitDirection(ray, maxDistance);
    if (!d || !isFinite(center) || !isFinite(halfExtents) || !(halfExtents.x >= 0.0) || !(halfExtents.y >= 0.0) ||
        !(halfExtents.z >= 0.0))
        return std::nullopt;
    const Real qLength = glm::length(orientation);
    if (!(qLength > 0.0) || !std::isfinite(qLength))
        return std::nullopt;
    const Quat q = orientation / qLength;
    const Quat toLocal = glm::conjugate(q);
    const Vec3 o = toLocal * (ray.origin - center);
    const Vec3 dl = toLocal * *d;

    // Slab clipping that remembers which face the ray entered through.
    Real enter = -kInfinity;
    Real exit = kInfinity;
    int enterAxis = -1;
    Real enterSign = 0.0;
    for (int i = 0; i < 3; ++i) {
        const Real h = halfExtents[i];
        if (std::abs(dl[i]) < std::numeric_limits<Real>::min()) {
            if (o[i] < -h || o[i] > h)
                return std::nullopt;
            continue;
        }
        Real tNear = (-h - o[i]) / dl[i];
        Real tFar = (h - o[i]) / dl[i];
        // Moving towards +axis, the ray enters through the -axis face.
        Real sign = -1.0;
        if (tNear > tFar) {
            std::swap(tNear, tFar);
            sign = 1.0;
        }
        if (tNear > enter) {
            enter = tNear;
            enterAxis = i;
            enterSign = sign;
        }
        exit = std::min(exit, tFar);
    }
    if (enter > exit || exit < 0.0)
        return std::nullopt;
    if (enter < 0.0 || enterAxis < 0)
        return startInside(ray.origin, *d, inside);
    if (enter > maxDistance)
        return std::nullopt;
    Vec3 localNormal(0.0);
    localNormal[enterAxis] = enterSign;
    return ShapeRayHit{enter, ray.origin + enter * *d, q * localNormal};
}

namespace {

// Two-sided polygon: intersect the plane, then test the point against the polygon's edges.
std::optional<ShapeRayHit> rayFlatHull(const Vec3& o, const Vec3& d, Real maxDistance, const ConvexHull& hull) {
    const HullFace& face = hull.faces.front();
    const Real denom = glm::dot(face.normal, d);
    if (std::abs(denom) < 1e-12)
        return std::nullopt; // edge-on: a polygon has no thickness to hit
    const Real t = (face.offset - glm::dot(face.normal, o)) / denom;
    if (t < 0.0 || t > maxDistance)
        return std::nullopt;
    const Vec3 p = o + t * d;
    const size_t n = face.vertices.size();
    if (n < 3)
        return std::nullopt;
    // Edge tolerance relative to the polygon's size, so a ray through a vertex or along an edge counts.
    Real extent = 0.0;
    for (uint32_t v : face.vertices)
        extent = std::max(extent, glm::length(hull.vertices[v] - hull.vertices[face.vertices[0]]));
    const Real tolerance = 1e-9 * extent * extent;
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = hull.vertices[face.vertices[i]];
        const Vec3& b = hull.vertices[face.vertices[(i + 1) % n]];
        if (glm::dot(glm::cross(b - a, p - a), face.normal) < -tolerance)
            return std::nullopt;
    }
    return ShapeRayHit{t, p, denom < 0.0 ? face.normal : -face.normal};
}

} // namespace

std::optional<ShapeRayHit> rayHull(const Ray& ray, Real maxDistance, const ConvexHull& hull, const Vec3& position,
                                   const Quat& orientation, RayStartInside inside) {
    const std::optional<Vec3> d = unitDirection(ray, maxDistance);
    if (!d || !isFinite(position))
        return std::nullopt;
    const Real qLength = glm::length(orientation);
    if (!(qLength > 0.0) || !std::isfinite(qLength) || hull.faces.empty())
        return std::nullopt;
    if (hull.dimension != HullDimension::Solid && hull.dimension != HullDimension::Flat)
        return std::nullopt;
    const Quat q = orientation / qLength;
    const Quat toLocal = glm::conjugate(q);
    const Vec3 o = toLocal * (ray.origin - position);
    const Vec3 dl = toLocal * *d;

    std::optional<ShapeRayHit> local;
    if (hull.dimension == HullDimension::Flat) {
        local = rayFlatHull(o, dl, maxDistance, hull);
    } else {
        // Cyrus-Beck: the segment inside the hull is the intersection of the inner half-spaces of all faces.
        Real enter = -kInfinity;
        Real exit = kInfinity;
        int enterFace = -1;
        for (size_t i = 0; i < hull.faces.size(); ++i) {
            const HullFace& f = hull.faces[i];
            const Real distance = glm::dot(f.normal, o) - f.offset; // > 0: origin outside this face
            const Real denom = glm::dot(f.normal, dl);
            if (denom == 0.0) {
                if (distance > 0.0)
                    return std::nullopt;
                continue;
            }
            const Real t = -distance / denom;
            if (denom < 0.0) {
                if (t > enter) {
                    enter = t;
                    enterFace = static_cast<int>(i);
                }
            } else {
                exit = std::min(exit, t);
            }
            if (enter > exit)
                return std::nullopt;
        }
        if (exit < 0.0)
            return std::nullopt;
        if (enter < 0.0 || enterFace < 0)
            return startInside(ray.origin, *d, inside);
        if (enter > maxDistance)
            return std::nullopt;
        local = ShapeRayHit{enter, o + enter * dl, hull.faces[enterFace].normal};
    }
    if (!local)
        return std::nullopt;
    return ShapeRayHit{local->distance, ray.origin + local->distance * *d, glm::normalize(q * local->normal)};
}

} // namespace rl
