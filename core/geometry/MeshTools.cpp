#include "geometry/MeshTools.h"

#include "geometry/MassProperties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rl {

namespace {

// Upper bound on generated resolution, so that a typo in a scene file cannot ask for gigabytes: a 1024 x 1024
// UV sphere is already two million triangles.
constexpr int kMaxSegments = 1024;

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool validSize(Real s) {
    return std::isfinite(s) && s > 0.0;
}

uint32_t addVertex(TriangleMesh& mesh, const Vec3& v) {
    mesh.vertices.push_back(v);
    return static_cast<uint32_t>(mesh.vertices.size() - 1);
}

// The generators only produce convex shapes around the origin, so each triangle's winding can be fixed by whether
// its normal points away from the origin. That keeps the index bookkeeping in the generators free of sign cases.
void windOutward(TriangleMesh& mesh) {
    for (auto& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[t[0]];
        const Vec3& b = mesh.vertices[t[1]];
        const Vec3& c = mesh.vertices[t[2]];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0)
            std::swap(t[1], t[2]);
    }
}

// A fan over a ring of vertices (a convex polygon).
void addFan(TriangleMesh& mesh, const std::vector<uint32_t>& ring) {
    for (size_t i = 1; i + 1 < ring.size(); ++i)
        mesh.triangles.push_back({ring[0], ring[i], ring[i + 1]});
}

std::vector<uint32_t> addRing(TriangleMesh& mesh, Real radius, Real y, int segments) {
    std::vector<uint32_t> ring;
    for (int j = 0; j < segments; ++j) {
        const Real theta = 2.0 * kPi * j / segments;
        ring.push_back(addVertex(mesh, {radius * std::cos(theta), y, radius * std::sin(theta)}));
    }
    return ring;
}

// Bands of quads between two rings of the same segment count, each split into two triangles.
void addBand(TriangleMesh& mesh, const std::vector<uint32_t>& lower, const std::vector<uint32_t>& upper) {
    const size_t n = lower.size();
    for (size_t j = 0; j < n; ++j) {
        const size_t k = (j + 1) % n;
        mesh.triangles.push_back({lower[j], lower[k], upper[k]});
        mesh.triangles.push_back({lower[j], upper[k], upper[j]});
    }
}

bool validTriangle(size_t vertexCount, const std::array<uint32_t, 3>& t) {
    return t[0] < vertexCount && t[1] < vertexCount && t[2] < vertexCount;
}

} // namespace

TriangleMesh makeBoxMesh(Vec3 halfExtents) {
    TriangleMesh mesh;
    if (!validSize(halfExtents.x) || !validSize(halfExtents.y) || !validSize(halfExtents.z))
        return mesh;
    // Corner i has coordinate k positive when bit k of i is set.
    for (int i = 0; i < 8; ++i)
        addVertex(mesh, halfExtents * Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const uint32_t base = side << axis;
            // Around the face: (-,-), (+,-), (+,+), (-,+) in its (u, v) axes.
            const std::vector<uint32_t> quad{base, base | (1u << u), base | (1u << u) | (1u << v), base | (1u << v)};
            addFan(mesh, quad);
        }
    }
    windOutward(mesh);
    return mesh;
}

TriangleMesh makeUvSphereMesh(Real radius, int segments, int rings) {
    TriangleMesh mesh;
    if (!validSize(radius))
        return mesh;
    segments = std::clamp(segments, 3, kMaxSegments);
    rings = std::clamp(rings, 2, kMaxSegments);
    const uint32_t top = addVertex(mesh, {0.0, radius, 0.0});
    std::vector<std::vector<uint32_t>> ringIds;
    for (int i = 1; i < rings; ++i) {
        const Real phi = kPi * i / rings;
        ringIds.push_back(addRing(mesh, radius * std::sin(phi), radius * std::cos(phi), segments));
    }
    const uint32_t bottom = addVertex(mesh, {0.0, -radius, 0.0});
    const auto& first = ringIds.front();
    const auto& last = ringIds.back();
    for (int j = 0; j < segments; ++j) {
        const int k = (j + 1) % segments;
        mesh.triangles.push_back({top, first[j], first[k]});
        mesh.triangles.push_back({bottom, last[j], last[k]});
    }
    for (size_t i = 0; i + 1 < ringIds.size(); ++i)
        addBand(mesh, ringIds[i + 1], ringIds[i]);
    windOutward(mesh);
    return mesh;
}

TriangleMesh makeCylinderMesh(Real radius, Real halfHeight, int segments) {
    TriangleMesh mesh;
    if (!validSize(radius) || !validSize(halfHeight))
        return mesh;
    segments = std::clamp(segments, 3, kMaxSegments);
    const std::vector<uint32_t> lower = addRing(mesh, radius, -halfHeight, segments);
    const std::vector<uint32_t> upper = addRing(mesh, radius, halfHeight, segments);
    addBand(mesh, lower, upper);
    // Caps are fans from a rim vertex: no centre vertex, so every vertex is a corner of the hull.
    addFan(mesh, lower);
    addFan(mesh, upper);
    windOutward(mesh);
    return mesh;
}

TriangleMesh makeConeMesh(Real radius, Real halfHeight, int segments) {
    TriangleMesh mesh;
    if (!validSize(radius) || !validSize(halfHeight))
        return mesh;
    segments = std::clamp(segments, 3, kMaxSegments);
    const std::vector<uint32_t> base = addRing(mesh, radius, -halfHeight, segments);
    const uint32_t apex = addVertex(mesh, {0.0, halfHeight, 0.0});
    for (int j = 0; j < segments; ++j)
        mesh.triangles.push_back({base[j], base[(j + 1) % segments], apex});
    addFan(mesh, base);
    windOutward(mesh);
    return mesh;
}

TriangleMesh hullMesh(const ConvexHull& hull) {
    TriangleMesh mesh;
    if (hull.dimension != HullDimension::Solid && hull.dimension != HullDimension::Flat)
        return mesh;
    mesh.vertices = hull.vertices;
    // Hull faces are convex and counter-clockwise from outside, so a fan keeps the winding.
    for (const HullFace& face : hull.faces) {
        bool ok = true;
        for (uint32_t v : face.vertices)
            ok = ok && v < hull.vertices.size();
        if (ok)
            addFan(mesh, face.vertices);
    }
    return mesh;
}

TriangleMesh weldVertices(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles) {
    TriangleMesh mesh;
    std::map<std::array<Real, 3>, uint32_t> byPosition;
    std::vector<int64_t> remap(vertices.size(), -1);
    auto idOf = [&](uint32_t i) -> int64_t {
        if (remap[i] >= 0)
            return remap[i];
        const Vec3& v = vertices[i];
        if (!finite(v))
            return -1;
        // Non-finite positions were excluded above, so the ordering of the keys is a strict weak order.
        const auto [it, inserted] =
            byPosition.emplace(std::array<Real, 3>{v.x, v.y, v.z}, static_cast<uint32_t>(mesh.vertices.size()));
        if (inserted)
            mesh.vertices.push_back(v);
        return remap[i] = it->second;
    };
    for (const auto& t : triangles) {
        if (!validTriangle(vertices.size(), t))
            continue;
        const int64_t a = idOf(t[0]), b = idOf(t[1]), c = idOf(t[2]);
        if (a < 0 || b < 0 || c < 0 || a == b || b == c || a == c)
            continue;
        mesh.triangles.push_back({static_cast<uint32_t>(a), static_cast<uint32_t>(b), static_cast<uint32_t>(c)});
    }
    return mesh;
}

bool isClosedMesh(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles) {
    for (const auto& t : triangles) {
        if (!validTriangle(vertices.size(), t))
            return false;
    }
    const TriangleMesh welded = weldVertices(vertices, triangles);
    if (welded.triangles.empty() || welded.triangles.size() != triangles.size())
        return false;
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& t : welded.triangles) {
        for (int e = 0; e < 3; ++e) {
            if (++directed[{t[e], t[(e + 1) % 3]}] > 1)
                return false; // two triangles running the same way along an edge: inconsistent or non-manifold
        }
    }
    for (const auto& [edge, count] : directed) {
        if (directed.find({edge.second, edge.first}) == directed.end())
            return false;
    }
    return true;
}

Real closedMeshVolume(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles) {
    Real sixVolume = 0.0;
    bool haveRef = false;
    Vec3 ref(0.0);
    for (const auto& t : triangles) {
        if (!validTriangle(vertices.size(), t) || !finite(vertices[t[0]]) || !finite(vertices[t[1]]) ||
            !finite(vertices[t[2]]))
            continue;
        if (!haveRef) {
            // Relative to a mesh vertex, so that far-away meshes do not lose their volume to cancellation.
            ref = vertices[t[0]];
            haveRef = true;
        }
        const Vec3 a = vertices[t[0]] - ref;
        const Vec3 b = vertices[t[1]] - ref;
        const Vec3 c = vertices[t[2]] - ref;
        sixVolume += glm::dot(a, glm::cross(b, c));
    }
    const Real volume = std::abs(sixVolume) / 6.0;
    return std::isfinite(volume) ? volume : 0.0;
}

bool isConcave(std::span<const Vec3> vertices, std::span<const std::array<uint32_t, 3>> triangles,
               const ConvexHull& hull, Real relativeTolerance) {
    if ((hull.dimension != HullDimension::Solid && hull.dimension != HullDimension::Flat) || hull.faces.empty())
        return false;
    if (!(std::isfinite(relativeTolerance) && relativeTolerance >= 0.0))
        relativeTolerance = kConcavityRelativeTolerance;
    Vec3 lo(std::numeric_limits<Real>::max());
    Vec3 hi(-std::numeric_limits<Real>::max());
    for (const Vec3& v : hull.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const Real tolerance = relativeTolerance * glm::length(hi - lo);
    const MassProperties hullProps = hullMassProperties(hull);

    if (hull.dimension == HullDimension::Solid) {
        // Depth inside a convex polytope is the distance to the nearest face plane.
        for (const Vec3& v : vertices) {
            if (!finite(v))
                continue;
            Real depth = std::numeric_limits<Real>::max();
            for (const HullFace& f : hull.faces)
                depth = std::min(depth, f.offset - glm::dot(f.normal, v));
            if (depth > tolerance)
                return true;
        }
        // All vertices on the hull can still be joined by folded-in triangles (Schönhardt's twisted prism).
        if (isClosedMesh(vertices, triangles)) {
            const Real meshVolume = closedMeshVolume(vertices, triangles);
            if (meshVolume < hullProps.volume * (1.0 - relativeTolerance))
                return true;
        }
        return false;
    }

    // Flat: the same two tests in the plane, with edges for faces and area for volume.
    const HullFace& face = hull.faces[0];
    const size_t n = face.vertices.size();
    for (const Vec3& v : vertices) {
        if (!finite(v))
            continue;
        Real depth = std::numeric_limits<Real>::max();
        for (size_t i = 0; i < n; ++i) {
            const Vec3& a = hull.vertices[face.vertices[i]];
            const Vec3& b = hull.vertices[face.vertices[(i + 1) % n]];
            const Vec3 inward = glm::cross(face.normal, b - a);
            const Real len = glm::length(inward);
            if (len > 0.0)
                depth = std::min(depth, glm::dot(inward / len, v - a));
        }
        if (depth > tolerance)
            return true;
    }
    Real meshArea = 0.0;
    for (const auto& t : triangles) {
        if (validTriangle(vertices.size(), t))
            meshArea += 0.5 * glm::length(glm::cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
    }
    return meshArea < hullProps.area * (1.0 - relativeTolerance);
}

} // namespace rl
