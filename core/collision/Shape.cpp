#include "collision/Shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace rl {

namespace {

// Hulls from this size on climb the vertex graph instead of scanning every vertex. The value is not tuned: it
// keeps the 32-vertex hulls of bench_narrowphase on the simple scan, and tst_robustness checks the climb against a
// full scan on a 2,000-vertex hull.
constexpr size_t kHillClimbMinVertices = 48;

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Newell's normal of a polygon loop: exact for planar loops and well defined for slightly warped ones.
Vec3 newellNormal(const std::vector<Vec3>& vertices, const std::vector<uint32_t>& loop) {
    Vec3 n(0.0);
    for (size_t i = 0; i < loop.size(); ++i) {
        const Vec3& a = vertices[loop[i]];
        const Vec3& b = vertices[loop[(i + 1) % loop.size()]];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

// Orders a face's vertex indices counter-clockwise around `normal`, so hand-built hulls need no careful listing.
void orderLoop(const std::vector<Vec3>& vertices, std::vector<uint32_t>& loop, const Vec3& normal) {
    Vec3 c(0.0);
    for (uint32_t i : loop)
        c += vertices[i];
    c /= Real(loop.size());
    const Vec3 u = glm::normalize(std::abs(normal.x) < 0.9 ? glm::cross(normal, Vec3(1, 0, 0))
                                                           : glm::cross(normal, Vec3(0, 1, 0)));
    const Vec3 v = glm::cross(normal, u);
    std::sort(loop.begin(), loop.end(), [&](uint32_t a, uint32_t b) {
        const Vec3 da = vertices[a] - c, db = vertices[b] - c;
        return std::atan2(glm::dot(da, v), glm::dot(da, u)) < std::atan2(glm::dot(db, v), glm::dot(db, u));
    });
}

HullFace solidFace(const std::vector<Vec3>& vertices, std::vector<uint32_t> loop, const Vec3& interior) {
    Vec3 c(0.0);
    for (uint32_t i : loop)
        c += vertices[i];
    c /= Real(loop.size());
    Vec3 n = glm::cross(vertices[loop[1]] - vertices[loop[0]], vertices[loop[2]] - vertices[loop[0]]);
    n = glm::normalize(n);
    if (glm::dot(n, c - interior) < 0.0)
        n = -n;
    orderLoop(vertices, loop, n);
    return {std::move(loop), n, glm::dot(n, c)};
}

// Recognises a rectangular box (see ConvexPolyhedron::BoxFeatures): every face normal has an opposite one and the
// three directions are at right angles (to 1e-4 rad), every vertex lies at the half extents along all three (to
// 2e-5 of the shape's size: the most the SAT's projections can be off), and every edge runs along one axis. Cubes
// exported as text with six decimals qualify: Blender's 0.2 m cubes in ramps.obj are square to 2.3e-7.
void detectBox(ConvexPolyhedron& poly, Real scale) {
    poly.isBox = false;
    if (poly.flat || poly.vertices.size() != 8 || poly.faces.size() != 6 || poly.edges.size() != 12)
        return;
    constexpr Real kTolerance = 1e-4, kFit = 2e-5;
    ConvexPolyhedron::BoxFeatures box;
    int axes = 0;
    bool used[6] = {};
    for (uint32_t f = 0; f < 6 && axes < 3; ++f) {
        if (used[f])
            continue;
        const Vec3& n = poly.faces[f].normal;
        for (uint32_t g = f + 1; g < 6; ++g) {
            if (used[g] || glm::dot(n, poly.faces[g].normal) > -1.0 + kTolerance)
                continue;
            used[f] = used[g] = true;
            box.axis[axes] = n;
            box.face[axes][0] = f;
            box.face[axes][1] = g;
            ++axes;
            break;
        }
    }
    if (axes != 3)
        return;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (std::abs(glm::dot(box.axis[i], box.axis[j])) > kTolerance)
                return;
    // Orthonormal and right-handed, from the first two normals.
    box.axis[0] = glm::normalize(box.axis[0]);
    box.axis[1] = glm::normalize(box.axis[1] - glm::dot(box.axis[1], box.axis[0]) * box.axis[0]);
    const Vec3 third = glm::cross(box.axis[0], box.axis[1]);
    if (glm::dot(third, box.axis[2]) < 0.0)
        std::swap(box.face[2][0], box.face[2][1]);
    box.axis[2] = third;
    // Every vertex at the half extents along all three axes, to kFit of the shape's size.
    const auto fits = [&] {
        for (int i = 0; i < 3; ++i)
            box.reach[i] = 0.0;
        for (const Vec3& v : poly.vertices)
            for (int i = 0; i < 3; ++i) {
                const Real along = std::abs(glm::dot(v - box.center, box.axis[i]));
                if (std::abs(along - box.half[i]) > kFit * scale)
                    return false;
                box.reach[i] = std::max(box.reach[i], along);
            }
        return true;
    };
    // The centre and half extents from the faces' offsets, and where the vertices do not fit those, from the
    // vertices' spans along the axes, measured from the vertex mean. The offsets are distances from the origin, so
    // the axes' small turns from the face normals are multiplied by the box's distance from it: 514 of boxes1000.obj's
    // 1,000 boxes, which Blender had turned and exported up to 7 m out with six decimals, were off by up to 5.4e-5 m
    // and went through the general SAT; the spans fit them to 5.4e-6 of their size. (The offsets stay first so that
    // every box they fit keeps its numbers: taken from the spans alone, ramps.obj's cubes moved in the last bits and
    // the pile came out otherwise, one cube still sliding at 10 s.)
    for (int i = 0; i < 3; ++i) {
        const Real plus = poly.faces[box.face[i][0]].offset, minus = poly.faces[box.face[i][1]].offset;
        box.half[i] = 0.5 * (plus + minus);
        box.center += 0.5 * (plus - minus) *
                      (glm::dot(poly.faces[box.face[i][0]].normal, box.axis[i]) > 0.0 ? 1.0 : -1.0) * box.axis[i];
        if (!(box.half[i] > 0.0))
            return;
    }
    if (!fits()) {
        box.center = poly.centroid;
        for (int i = 0; i < 3; ++i) {
            Real low = std::numeric_limits<Real>::infinity(), high = -low;
            for (const Vec3& v : poly.vertices) {
                const Real along = glm::dot(v - poly.centroid, box.axis[i]);
                low = std::min(low, along);
                high = std::max(high, along);
            }
            box.half[i] = 0.5 * (high - low);
            if (!(box.half[i] > 0.0))
                return;
            box.center += 0.5 * (high + low) * box.axis[i];
        }
        if (!fits())
            return;
    }
    bool filled[3][4] = {};
    for (uint32_t e = 0; e < 12; ++e) {
        const Vec3 a = poly.vertices[poly.edges[e].v0], b = poly.vertices[poly.edges[e].v1];
        const Vec3 direction = glm::normalize(b - a), middle = 0.5 * (a + b) - box.center;
        int along = -1;
        for (int i = 0; i < 3; ++i)
            if (std::abs(glm::dot(direction, box.axis[i])) > 1.0 - kTolerance)
                along = i;
        if (along < 0)
            return;
        const int bits = (glm::dot(middle, box.axis[(along + 1) % 3]) < 0.0 ? 1 : 0) |
                         (glm::dot(middle, box.axis[(along + 2) % 3]) < 0.0 ? 2 : 0);
        if (filled[along][bits])
            return;
        filled[along][bits] = true;
        box.edge[along][bits] = e;
    }
    poly.box = box;
    poly.isBox = true;
}

Error hullError(const std::string& message) {
    return Error{"", 0, "hull", message};
}

} // namespace

uint32_t ConvexPolyhedron::supportIndex(const Vec3& d) const {
    const size_t n = vertices.size();
    if (n >= kHillClimbMinVertices && neighbourStart.size() == n + 1) {
        // A linear function on a convex polytope has no local maximum that is not global, so climbing the edge
        // graph ends at a support vertex. Each move strictly increases the value, so at most n moves happen.
        uint32_t best = 0;
        Real bestValue = glm::dot(vertices[0], d);
        for (size_t step = 0; step < n; ++step) {
            uint32_t next = best;
            for (uint32_t k = neighbourStart[best]; k < neighbourStart[best + 1]; ++k) {
                const Real value = glm::dot(vertices[neighbours[k]], d);
                if (value > bestValue) {
                    bestValue = value;
                    next = neighbours[k];
                }
            }
            if (next == best)
                break;
            best = next;
        }
        return best;
    }
    uint32_t best = 0;
    Real bestValue = -std::numeric_limits<Real>::infinity();
    for (size_t i = 0; i < n; ++i) {
        const Real value = glm::dot(vertices[i], d);
        if (value > bestValue) {
            bestValue = value;
            best = uint32_t(i);
        }
    }
    return best;
}

Vec3 Shape::support(const Vec3& d) const {
    switch (kind) {
    case ShapeKind::Sphere: {
        const Real len = glm::length(d);
        return len > 0.0 ? d * (radius / len) : Vec3(radius, 0.0, 0.0);
    }
    case ShapeKind::Box:
        return {d.x < 0.0 ? -halfExtents.x : halfExtents.x, d.y < 0.0 ? -halfExtents.y : halfExtents.y,
                d.z < 0.0 ? -halfExtents.z : halfExtents.z};
    case ShapeKind::Polyhedron:
        return polyhedron->support(d);
    }
    return Vec3(0.0);
}

Vec3 Shape::supportCore(const Vec3& d) const {
    return kind == ShapeKind::Sphere ? Vec3(0.0) : support(d);
}

Aabb Shape::localBounds() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return {Vec3(-radius), Vec3(radius)};
    case ShapeKind::Box:
        return {-halfExtents, halfExtents};
    case ShapeKind::Polyhedron:
        return polyhedron->bounds;
    }
    return {};
}

Aabb Shape::worldBounds(const Transform& xf) const {
    if (kind != ShapeKind::Sphere && polyhedron && polyhedron->isBox) {
        // A box: its centre plus, along each world axis, the sum of its half extents times |that axis . its axes|.
        // The reaches (the vertices' largest offsets along the box's axes) stand in for the half extents, so the
        // box holds every vertex, and a relative 1e-14 covers the rounding.
        const ConvexPolyhedron::BoxFeatures& b = polyhedron->box;
        const Vec3 center = xf.apply(b.center);
        Vec3 extent(0.0);
        for (int i = 0; i < 3; ++i)
            extent += glm::abs(xf.rotate(b.axis[i])) * b.reach[i];
        const Vec3 scale = glm::abs(center) + extent;
        extent += Vec3(1e-14 * (scale.x + scale.y + scale.z));
        return {center - extent, center + extent};
    }
    if (kind == ShapeKind::Polyhedron && polyhedron->vertices.size() < kHillClimbMinVertices) {
        // A small hull: moving its few vertices once is cheaper than six support queries,
        // and their extremes are the same tight box.
        const std::vector<Vec3>& vertices = polyhedron->vertices;
        Aabb box{xf.apply(vertices[0]), xf.apply(vertices[0])};
        for (size_t k = 1; k < vertices.size(); ++k) {
            const Vec3 p = xf.apply(vertices[k]);
            box.min = glm::min(box.min, p);
            box.max = glm::max(box.max, p);
        }
        return box;
    }
    // Support along the world axes gives the tight box of the rotated shape.
    Aabb box;
    for (int i = 0; i < 3; ++i) {
        Vec3 axis(0.0);
        axis[i] = 1.0;
        const Vec3 local = xf.rotateInverse(axis);
        box.max[i] = glm::dot(xf.apply(support(local)), axis);
        box.min[i] = glm::dot(xf.apply(support(-local)), axis);
    }
    return box;
}

Real Shape::reachAlong(const Transform& xf, const Vec3& direction) const {
    const Vec3 local = xf.rotateInverse(direction);
    if (kind != ShapeKind::Sphere && polyhedron && polyhedron->isBox) {
        const ConvexPolyhedron::BoxFeatures& b = polyhedron->box;
        const Real centre = glm::dot(direction, xf.position) + glm::dot(local, b.center);
        Real reach = 0.0;
        for (int i = 0; i < 3; ++i)
            reach += std::abs(glm::dot(local, b.axis[i])) * b.reach[i];
        // A relative 1e-14 covers the rounding, as in worldBounds().
        return centre + reach + 1e-14 * (std::abs(centre) + reach);
    }
    return glm::dot(direction, xf.apply(support(local)));
}

Real Shape::boundingRadius() const {
    switch (kind) {
    case ShapeKind::Sphere:
        return radius;
    case ShapeKind::Box:
        return glm::length(halfExtents);
    case ShapeKind::Polyhedron: {
        Real r2 = 0.0;
        for (const Vec3& v : polyhedron->vertices)
            r2 = std::max(r2, glm::dot(v, v));
        return std::sqrt(r2);
    }
    }
    return 0.0;
}

Real Shape::minExtent() const {
    const Aabb box = localBounds();
    const Vec3 size = box.max - box.min;
    return std::min({size.x, size.y, size.z});
}

Result<Shape> makeSphere(Real radius) {
    if (!std::isfinite(radius) || radius <= 0.0)
        return Error{"", 0, "sphere", "radius must be finite and positive"};
    Shape s;
    s.kind = ShapeKind::Sphere;
    s.radius = radius;
    return s;
}

Result<Shape> makeBox(const Vec3& halfExtents) {
    if (!isFinite(halfExtents) || halfExtents.x <= 0.0 || halfExtents.y <= 0.0 || halfExtents.z <= 0.0)
        return Error{"", 0, "box", "half extents must be finite and positive"};
    Result<Shape> hull = makeHull(boxHull(halfExtents));
    if (!hull)
        return hull.error();
    Shape s = std::move(hull.value());
    s.kind = ShapeKind::Box;
    s.halfExtents = halfExtents;
    return s;
}

Result<Shape> makeHull(const ConvexHull& hull) {
    if (hull.dimension != HullDimension::Solid && hull.dimension != HullDimension::Flat)
        return hullError("a collision hull needs at least three points that are not on one line");
    auto poly = std::make_shared<ConvexPolyhedron>();
    poly->vertices = hull.vertices;
    poly->flat = hull.dimension == HullDimension::Flat;
    if (poly->vertices.size() < 3)
        return hullError("a collision hull needs at least three vertices");
    for (const Vec3& v : poly->vertices) {
        if (!isFinite(v))
            return hullError("hull vertex is not finite");
        poly->centroid += v;
    }
    poly->centroid /= Real(poly->vertices.size());
    poly->bounds = {poly->vertices[0], poly->vertices[0]};
    for (const Vec3& v : poly->vertices) {
        poly->bounds.min = glm::min(poly->bounds.min, v);
        poly->bounds.max = glm::max(poly->bounds.max, v);
    }

    std::vector<HullFace> faces = hull.faces;
    if (poly->flat && faces.size() == 1) {
        HullFace back = faces[0];
        std::reverse(back.vertices.begin(), back.vertices.end());
        faces.push_back(back);
    }
    if (faces.size() < 2)
        return hullError("hull has too few faces");

    Real scale = 0.0;
    for (const Vec3& v : poly->vertices)
        scale = std::max(scale, glm::length(v - poly->centroid));
    for (const HullFace& f : faces) {
        if (f.vertices.size() < 3)
            return hullError("hull face has fewer than three vertices");
        for (uint32_t i : f.vertices) {
            if (i >= poly->vertices.size())
                return hullError("hull face refers to a missing vertex");
        }
        // The plane is recomputed from the loop, so a hull from any source gets exact unit normals.
        Vec3 n = newellNormal(poly->vertices, f.vertices);
        const Real len = glm::length(n);
        if (!(len > 1e-14 * scale * scale))
            return hullError("hull face is degenerate");
        n /= len;
        Vec3 c(0.0);
        for (uint32_t i : f.vertices)
            c += poly->vertices[i];
        c /= Real(f.vertices.size());
        PolyFace pf;
        pf.first = uint32_t(poly->faceVertices.size());
        pf.count = uint32_t(f.vertices.size());
        pf.normal = n;
        pf.offset = glm::dot(n, c);
        if (!poly->flat && glm::dot(n, poly->centroid) - pf.offset > 1e-9 * scale)
            return hullError("hull face does not face outward");
        poly->faceVertices.insert(poly->faceVertices.end(), f.vertices.begin(), f.vertices.end());
        poly->faces.push_back(pf);
    }

    // Edges: every directed loop edge a->b must meet exactly one b->a in another face, or the hull is open.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> open;
    for (uint32_t fi = 0; fi < poly->faces.size(); ++fi) {
        const PolyFace& f = poly->faces[fi];
        for (uint32_t k = 0; k < f.count; ++k) {
            const uint32_t a = poly->faceVertices[f.first + k];
            const uint32_t b = poly->faceVertices[f.first + (k + 1) % f.count];
            auto it = open.find({b, a});
            if (it != open.end()) {
                poly->edges[it->second].face1 = fi;
                open.erase(it);
            } else {
                if (!open.emplace(std::make_pair(a, b), uint32_t(poly->edges.size())).second)
                    return hullError("hull edge is used twice in the same direction");
                poly->edges.push_back({a, b, fi, fi});
            }
        }
    }
    if (!open.empty())
        return hullError("hull is not closed");

    const size_t n = poly->vertices.size();
    std::vector<std::vector<uint32_t>> adj(n);
    for (const PolyEdge& e : poly->edges) {
        adj[e.v0].push_back(e.v1);
        adj[e.v1].push_back(e.v0);
    }
    poly->neighbourStart.assign(n + 1, 0);
    for (size_t i = 0; i < n; ++i)
        poly->neighbourStart[i + 1] = poly->neighbourStart[i] + uint32_t(adj[i].size());
    for (const auto& list : adj)
        poly->neighbours.insert(poly->neighbours.end(), list.begin(), list.end());

    detectBox(*poly, scale);
    Shape s;
    s.kind = ShapeKind::Polyhedron;
    s.polyhedron = std::move(poly);
    return s;
}

ConvexHull boxHull(const Vec3& h) {
    ConvexHull hull;
    hull.dimension = HullDimension::Solid;
    for (int i = 0; i < 8; ++i)
        hull.vertices.push_back({(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            std::vector<uint32_t> loop;
            for (uint32_t i = 0; i < 8; ++i) {
                if (((i >> axis) & 1u) == uint32_t(side))
                    loop.push_back(i);
            }
            hull.faces.push_back(solidFace(hull.vertices, loop, Vec3(0.0)));
        }
    }
    hull.inputIndex.resize(8);
    std::iota(hull.inputIndex.begin(), hull.inputIndex.end(), 0u);
    return hull;
}

ConvexHull prismHull(const std::vector<Vec3>& polygon, Real halfHeight) {
    ConvexHull hull;
    hull.dimension = HullDimension::Solid;
    const uint32_t n = uint32_t(polygon.size());
    for (int side = 0; side < 2; ++side) {
        for (const Vec3& p : polygon)
            hull.vertices.push_back({p.x, side ? halfHeight : -halfHeight, p.z});
    }
    Vec3 interior(0.0);
    for (const Vec3& v : hull.vertices)
        interior += v;
    interior /= Real(hull.vertices.size());
    std::vector<uint32_t> bottom(n), top(n);
    std::iota(bottom.begin(), bottom.end(), 0u);
    std::iota(top.begin(), top.end(), n);
    hull.faces.push_back(solidFace(hull.vertices, bottom, interior));
    hull.faces.push_back(solidFace(hull.vertices, top, interior));
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t j = (i + 1) % n;
        hull.faces.push_back(solidFace(hull.vertices, {i, j, j + n, i + n}, interior));
    }
    hull.inputIndex.resize(hull.vertices.size());
    std::iota(hull.inputIndex.begin(), hull.inputIndex.end(), 0u);
    return hull;
}

ConvexHull flatPolygonHull(const std::vector<Vec3>& polygon, const Vec3& normal) {
    ConvexHull hull;
    hull.dimension = HullDimension::Flat;
    hull.vertices = polygon;
    const Vec3 n = glm::normalize(normal);
    std::vector<uint32_t> loop(polygon.size());
    std::iota(loop.begin(), loop.end(), 0u);
    orderLoop(hull.vertices, loop, n);
    Vec3 c(0.0);
    for (const Vec3& p : polygon)
        c += p;
    c /= Real(polygon.size());
    hull.faces.push_back({loop, n, glm::dot(n, c)});
    std::reverse(loop.begin(), loop.end());
    hull.faces.push_back({loop, -n, -glm::dot(n, c)});
    hull.inputIndex.resize(polygon.size());
    std::iota(hull.inputIndex.begin(), hull.inputIndex.end(), 0u);
    return hull;
}

} // namespace rl
