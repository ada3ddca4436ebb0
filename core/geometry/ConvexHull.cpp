#include "geometry/ConvexHull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace rl {

namespace {

constexpr Real kEpsilon = std::numeric_limits<Real>::epsilon();
// Coordinates carry an absolute rounding error of about one ulp of the largest coordinate. Plane distances are
// sums of three products, so a few dozen ulps bound what arithmetic alone can produce; the tolerance never goes
// below that, or points far from the origin would be judged by their rounding noise.
constexpr Real kUlpFactor = 32.0;

// Triangle of the working hull. adj[i] is the triangle across the directed edge v[i] -> v[(i + 1) % 3].
struct Triangle {
    std::array<uint32_t, 3> v{};
    std::array<int32_t, 3> adj{-1, -1, -1};
    Vec3 normal{0.0};
    Real offset = 0.0;
    std::vector<uint32_t> conflict; // points strictly outside (by more than the tolerance), assigned to this face
    uint32_t furthest = 0;
    Real furthestDistance = 0.0;
    bool alive = true;
};

// Unit normal of a triangle from the two shortest edges: their cross product loses the least to cancellation.
Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e0 = b - a;
    const Vec3 e1 = c - b;
    const Vec3 e2 = a - c;
    const Real l0 = glm::dot(e0, e0);
    const Real l1 = glm::dot(e1, e1);
    const Real l2 = glm::dot(e2, e2);
    Vec3 n;
    if (l0 >= l1 && l0 >= l2)
        n = glm::cross(e1, e2);
    else if (l1 >= l0 && l1 >= l2)
        n = glm::cross(e2, e0);
    else
        n = glm::cross(e0, e1);
    const Real len = glm::length(n);
    return len > 0.0 ? n / len : Vec3(0.0);
}

// Newell's normal of a polygon: the area-weighted average over all its edges, robust for many near-collinear vertices.
Vec3 newellNormal(const std::vector<Vec3>& pts, const std::vector<uint32_t>& loop) {
    Vec3 n(0.0);
    const size_t count = loop.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec3& p = pts[loop[i]];
        const Vec3& q = pts[loop[(i + 1) % count]];
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    const Real len = glm::length(n);
    return len > 0.0 ? n / len : Vec3(0.0);
}

// Any unit vector perpendicular to n.
Vec3 perpendicular(const Vec3& n) {
    const Vec3 axis = std::abs(n.x) < 0.57735 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(n, axis));
}

class QuickHull {
public:
    QuickHull(const std::vector<Vec3>& local, Real tolerance) : m_pts(local), m_eps(tolerance) {}

    // Builds the triangle hull from a non-degenerate starting tetrahedron. Returns false only if the start is bad.
    bool build(const std::array<uint32_t, 4>& simplex);

    // Groups coplanar triangles into polygons; returns loops of local point indices, counter-clockwise from outside.
    std::vector<std::vector<uint32_t>> mergedFaces() const;

private:
    Real distance(const Triangle& t, uint32_t p) const { return glm::dot(t.normal, m_pts[p]) - t.offset; }
    int32_t addTriangle(uint32_t a, uint32_t b, uint32_t c);
    void assign(const std::vector<uint32_t>& candidates, const std::vector<int32_t>& faces);
    bool addPoint(int32_t seedFace, uint32_t p);

    const std::vector<Vec3>& m_pts;
    Real m_eps;
    std::vector<Triangle> m_tris;
    std::vector<uint32_t> m_stamp; // per triangle: iteration in which visibility was decided
    std::vector<uint8_t> m_visible;
    uint32_t m_iteration = 0;
};

int32_t QuickHull::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    Triangle t;
    t.v = {a, b, c};
    t.normal = triangleNormal(m_pts[a], m_pts[b], m_pts[c]);
    // The centroid averages the rounding of the three vertices.
    t.offset = glm::dot(t.normal, (m_pts[a] + m_pts[b] + m_pts[c]) / 3.0);
    m_tris.push_back(std::move(t));
    m_stamp.push_back(0);
    m_visible.push_back(0);
    return static_cast<int32_t>(m_tris.size() - 1);
}

void QuickHull::assign(const std::vector<uint32_t>& candidates, const std::vector<int32_t>& faces) {
    for (uint32_t p : candidates) {
        int32_t best = -1;
        Real bestDistance = m_eps;
        for (int32_t f : faces) {
            const Real d = distance(m_tris[f], p);
            if (d > bestDistance) {
                bestDistance = d;
                best = f;
            }
        }
        // Points within the tolerance of every new face are inside (or on) the hull and are dropped for good.
        if (best < 0)
            continue;
        Triangle& t = m_tris[best];
        if (t.conflict.empty() || bestDistance > t.furthestDistance) {
            t.furthest = p;
            t.furthestDistance = bestDistance;
        }
        t.conflict.push_back(p);
    }
}

bool QuickHull::build(const std::array<uint32_t, 4>& s) {
    uint32_t a = s[0], b = s[1], c = s[2];
    const uint32_t d = s[3];
    if (glm::dot(triangleNormal(m_pts[a], m_pts[b], m_pts[c]), m_pts[d] - m_pts[a]) > 0.0)
        std::swap(b, c);
    // With d behind abc, these four faces are all counter-clockwise seen from outside.
    const std::array<std::array<uint32_t, 3>, 4> faces = {{{a, b, c}, {a, d, b}, {b, d, c}, {c, d, a}}};
    std::vector<int32_t> ids;
    for (const auto& f : faces)
        ids.push_back(addTriangle(f[0], f[1], f[2]));
    for (int32_t i : ids) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t u = m_tris[i].v[e];
            const uint32_t w = m_tris[i].v[(e + 1) % 3];
            for (int32_t j : ids) {
                for (int k = 0; k < 3; ++k) {
                    if (m_tris[j].v[k] == w && m_tris[j].v[(k + 1) % 3] == u)
                        m_tris[i].adj[e] = j;
                }
            }
        }
    }
    std::vector<uint32_t> rest;
    rest.reserve(m_pts.size());
    for (uint32_t i = 0; i < m_pts.size(); ++i) {
        if (i != a && i != b && i != c && i != d)
            rest.push_back(i);
    }
    assign(rest, ids);

    // Every iteration either makes a point a hull vertex or drops it, and a point is in at most one conflict list,
    // so the work is bounded by the number of points. A face that stops being alive is never revisited.
    for (size_t f = 0; f < m_tris.size(); ++f) {
        size_t guard = m_pts.size() + 1;
        while (m_tris[f].alive && !m_tris[f].conflict.empty() && guard-- > 0) {
            const uint32_t p = m_tris[f].furthest;
            if (!addPoint(static_cast<int32_t>(f), p)) {
                // The visible region was not a disc (rounding); this point stays within tolerance of the hull.
                Triangle& t = m_tris[f];
                t.conflict.erase(std::find(t.conflict.begin(), t.conflict.end(), p));
                t.furthestDistance = 0.0;
                for (uint32_t q : t.conflict) {
                    const Real dq = distance(t, q);
                    if (dq > t.furthestDistance) {
                        t.furthestDistance = dq;
                        t.furthest = q;
                    }
                }
            }
        }
    }
    return true;
}

bool QuickHull::addPoint(int32_t seedFace, uint32_t p) {
    ++m_iteration;
    struct Frame {
        int32_t face;
        int edge;
        int remaining;
    };
    struct HorizonEdge {
        int32_t face; // visible face
        int edge;     // its edge index on the horizon
    };
    std::vector<int32_t> visible{seedFace};
    std::vector<HorizonEdge> horizon;
    std::vector<Frame> stack{{seedFace, 0, 3}};
    m_stamp[seedFace] = m_iteration;
    m_visible[seedFace] = 1;
    // Depth-first flood over faces that see p; the edges to faces that do not see it form the horizon.
    const size_t maxSteps = 3 * m_tris.size() + 3;
    for (size_t step = 0; !stack.empty() && step < maxSteps; ++step) {
        Frame& top = stack.back();
        if (top.remaining == 0) {
            stack.pop_back();
            continue;
        }
        const int32_t face = top.face;
        const int e = top.edge;
        top.edge = (e + 1) % 3;
        --top.remaining;
        const int32_t nb = m_tris[face].adj[e];
        if (m_stamp[nb] != m_iteration) {
            m_stamp[nb] = m_iteration;
            m_visible[nb] = distance(m_tris[nb], p) > m_eps ? 1 : 0;
            if (m_visible[nb]) {
                visible.push_back(nb);
                int back = 0;
                while (back < 3 && m_tris[nb].adj[back] != face)
                    ++back;
                stack.push_back({nb, (back + 1) % 3, 2});
                continue;
            }
        }
        if (!m_visible[nb])
            horizon.push_back({face, e});
    }
    if (!stack.empty() || horizon.size() < 3)
        return false;

    // Order the horizon into one loop; a pinched or split horizon would make the hull non-manifold.
    std::unordered_map<uint32_t, size_t> byStart;
    byStart.reserve(horizon.size() * 2);
    for (size_t i = 0; i < horizon.size(); ++i) {
        const uint32_t start = m_tris[horizon[i].face].v[horizon[i].edge];
        if (!byStart.emplace(start, i).second)
            return false;
    }
    std::vector<size_t> order;
    order.reserve(horizon.size());
    size_t current = 0;
    for (size_t i = 0; i < horizon.size(); ++i) {
        order.push_back(current);
        const uint32_t end = m_tris[horizon[current].face].v[(horizon[current].edge + 1) % 3];
        const auto it = byStart.find(end);
        if (it == byStart.end())
            return false;
        current = it->second;
    }
    if (current != 0)
        return false;

    // Cone from p to every horizon edge, stitched to the faces outside and to each other.
    const size_t n = order.size();
    std::vector<int32_t> cone(n);
    for (size_t i = 0; i < n; ++i) {
        const HorizonEdge h = horizon[order[i]];
        const uint32_t a = m_tris[h.face].v[h.edge];
        const uint32_t b = m_tris[h.face].v[(h.edge + 1) % 3];
        const int32_t outside = m_tris[h.face].adj[h.edge];
        const int32_t id = addTriangle(a, b, p);
        cone[i] = id;
        m_tris[id].adj[0] = outside;
        for (int k = 0; k < 3; ++k) {
            if (m_tris[outside].v[k] == b && m_tris[outside].v[(k + 1) % 3] == a)
                m_tris[outside].adj[k] = id;
        }
    }
    for (size_t i = 0; i < n; ++i) {
        m_tris[cone[i]].adj[1] = cone[(i + 1) % n];
        m_tris[cone[i]].adj[2] = cone[(i + n - 1) % n];
    }

    std::vector<uint32_t> orphans;
    for (int32_t f : visible) {
        Triangle& t = m_tris[f];
        t.alive = false;
        for (uint32_t q : t.conflict) {
            if (q != p)
                orphans.push_back(q);
        }
        std::vector<uint32_t>().swap(t.conflict);
    }
    assign(orphans, cone);
    return true;
}

std::vector<std::vector<uint32_t>> QuickHull::mergedFaces() const {
    std::vector<int32_t> alive;
    for (size_t i = 0; i < m_tris.size(); ++i) {
        if (m_tris[i].alive)
            alive.push_back(static_cast<int32_t>(i));
    }
    auto area2 = [&](int32_t t) {
        const auto& v = m_tris[t].v;
        return glm::length(glm::cross(m_pts[v[1]] - m_pts[v[0]], m_pts[v[2]] - m_pts[v[0]]));
    };
    std::vector<Real> areas(m_tris.size(), 0.0);
    for (int32_t t : alive)
        areas[t] = area2(t);
    // Large triangles seed the groups: their planes are the best conditioned.
    std::stable_sort(alive.begin(), alive.end(), [&](int32_t x, int32_t y) { return areas[x] > areas[y]; });

    std::vector<int32_t> group(m_tris.size(), -1);
    std::vector<std::vector<int32_t>> groups;
    for (int32_t seed : alive) {
        if (group[seed] >= 0)
            continue;
        const int32_t g = static_cast<int32_t>(groups.size());
        groups.emplace_back();
        std::vector<int32_t>& members = groups.back();
        const Vec3 n = m_tris[seed].normal;
        const Real d = m_tris[seed].offset;
        group[seed] = g;
        members.push_back(seed);
        for (size_t i = 0; i < members.size(); ++i) {
            for (int e = 0; e < 3; ++e) {
                const int32_t nb = m_tris[members[i]].adj[e];
                if (group[nb] >= 0 || glm::dot(m_tris[nb].normal, n) <= 0.0)
                    continue;
                bool coplanar = true;
                for (uint32_t v : m_tris[nb].v)
                    coplanar = coplanar && std::abs(glm::dot(n, m_pts[v]) - d) <= m_eps;
                if (coplanar) {
                    group[nb] = g;
                    members.push_back(nb);
                }
            }
        }
    }

    std::vector<std::vector<uint32_t>> loops;
    for (size_t g = 0; g < groups.size(); ++g) {
        const std::vector<int32_t>& members = groups[g];
        std::vector<uint32_t> loop;
        bool ok = true;
        if (members.size() == 1) {
            const auto& v = m_tris[members[0]].v;
            loop.assign(v.begin(), v.end());
        } else {
            // Boundary edges of the group, chained into one loop; anything else falls back to triangles.
            std::unordered_map<uint32_t, uint32_t> next;
            for (int32_t t : members) {
                for (int e = 0; e < 3; ++e) {
                    if (group[m_tris[t].adj[e]] == static_cast<int32_t>(g))
                        continue;
                    ok = ok && next.emplace(m_tris[t].v[e], m_tris[t].v[(e + 1) % 3]).second;
                }
            }
            if (ok && next.size() >= 3) {
                uint32_t start = next.begin()->first;
                uint32_t at = start;
                for (size_t i = 0; i < next.size(); ++i) {
                    loop.push_back(at);
                    at = next[at];
                }
                ok = at == start;
            } else {
                ok = false;
            }
        }
        if (ok) {
            loops.push_back(std::move(loop));
        } else {
            for (int32_t t : members)
                loops.push_back({m_tris[t].v[0], m_tris[t].v[1], m_tris[t].v[2]});
        }
    }
    return loops;
}

// 2D convex hull (monotone chain) of points in a plane, strictly convex: collinear and duplicate points are dropped.
std::vector<uint32_t> planarHull(const std::vector<Vec3>& pts, const Vec3& u, const Vec3& v, Real eps) {
    struct P2 {
        Real x, y;
        uint32_t index;
    };
    std::vector<P2> q;
    q.reserve(pts.size());
    for (uint32_t i = 0; i < pts.size(); ++i)
        q.push_back({glm::dot(pts[i], u), glm::dot(pts[i], v), i});
    std::sort(q.begin(), q.end(), [](const P2& a, const P2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    // Strict left turn: a lies more than about eps to the right of the line o -> b, so the chain bends outward.
    auto leftTurn = [eps](const P2& o, const P2& a, const P2& b) {
        const Real cross = (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
        const Real base = std::hypot(b.x - o.x, b.y - o.y);
        return cross > eps * base;
    };
    std::vector<P2> h(2 * q.size() + 1);
    size_t k = 0;
    for (size_t i = 0; i < q.size(); ++i) {
        while (k >= 2 && !leftTurn(h[k - 2], h[k - 1], q[i]))
            --k;
        h[k++] = q[i];
    }
    for (size_t i = q.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && !leftTurn(h[k - 2], h[k - 1], q[i]))
            --k;
        h[k++] = q[i];
    }
    std::vector<uint32_t> out;
    for (size_t i = 0; i + 1 < k; ++i)
        out.push_back(h[i].index);
    return out;
}

} // namespace

ConvexHull computeConvexHull(std::span<const Vec3> points, const HullOptions& options) {
    ConvexHull hull;
    std::vector<uint32_t> source; // input index of each finite point
    source.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            source.push_back(static_cast<uint32_t>(i));
    }
    if (source.empty())
        return hull;

    Vec3 lo(std::numeric_limits<Real>::max());
    Vec3 hi(-std::numeric_limits<Real>::max());
    for (uint32_t i : source) {
        lo = glm::min(lo, points[i]);
        hi = glm::max(hi, points[i]);
    }
    // Work relative to the box centre so that a small object far from the origin keeps its precision.
    const Vec3 centre = 0.5 * (lo + hi);
    const Real extent = glm::length(hi - lo);
    const Real maxAbs =
        std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
    const Real relative = std::isfinite(options.relativeTolerance) && options.relativeTolerance > 0.0
                              ? options.relativeTolerance
                              : HullOptions{}.relativeTolerance;
    const Real eps = std::max(relative * extent, kUlpFactor * kEpsilon * maxAbs);

    std::vector<Vec3> local;
    local.reserve(source.size());
    for (uint32_t i : source)
        local.push_back(points[i] - centre);

    auto emitVertices = [&](const std::vector<uint32_t>& localIds) {
        for (uint32_t id : localIds) {
            hull.vertices.push_back(points[source[id]]);
            hull.inputIndex.push_back(source[id]);
        }
    };

    if (!(extent > eps)) {
        hull.dimension = HullDimension::Point;
        emitVertices({0});
        return hull;
    }

    // Extreme points along the axes; the most distant pair spans the first edge.
    std::array<uint32_t, 6> extremes{};
    for (int axis = 0; axis < 3; ++axis) {
        for (uint32_t i = 0; i < local.size(); ++i) {
            if (local[i][axis] < local[extremes[2 * axis]][axis])
                extremes[2 * axis] = i;
            if (local[i][axis] > local[extremes[2 * axis + 1]][axis])
                extremes[2 * axis + 1] = i;
        }
    }
    uint32_t i0 = extremes[0], i1 = extremes[1];
    Real best = -1.0;
    for (int a = 0; a < 6; ++a) {
        for (int b = a + 1; b < 6; ++b) {
            const Real d = glm::length(local[extremes[a]] - local[extremes[b]]);
            if (d > best) {
                best = d;
                i0 = extremes[a];
                i1 = extremes[b];
            }
        }
    }
    const Vec3 dir = glm::normalize(local[i1] - local[i0]);

    uint32_t i2 = i0;
    Real lineDistance = 0.0;
    for (uint32_t i = 0; i < local.size(); ++i) {
        const Vec3 r = local[i] - local[i0];
        const Real d = glm::length(r - dir * glm::dot(r, dir));
        if (d > lineDistance) {
            lineDistance = d;
            i2 = i;
        }
    }
    if (!(lineDistance > eps)) {
        // Collinear: the hull is the segment between the extreme projections.
        uint32_t lo1 = i0, hi1 = i0;
        for (uint32_t i = 0; i < local.size(); ++i) {
            if (glm::dot(local[i], dir) < glm::dot(local[lo1], dir))
                lo1 = i;
            if (glm::dot(local[i], dir) > glm::dot(local[hi1], dir))
                hi1 = i;
        }
        hull.dimension = HullDimension::Line;
        emitVertices({lo1, hi1});
        return hull;
    }

    const Vec3 planeNormal = triangleNormal(local[i0], local[i1], local[i2]);
    uint32_t i3 = i0;
    Real planeDistance = 0.0;
    for (uint32_t i = 0; i < local.size(); ++i) {
        const Real d = std::abs(glm::dot(local[i] - local[i0], planeNormal));
        if (d > planeDistance) {
            planeDistance = d;
            i3 = i;
        }
    }

    if (!(planeDistance > eps)) {
        const Vec3 u = perpendicular(planeNormal);
        const Vec3 v = glm::cross(planeNormal, u);
        std::vector<uint32_t> loop = planarHull(local, u, v, eps);
        if (loop.size() < 3) {
            hull.dimension = HullDimension::Line;
            emitVertices({i0, i1});
            return hull;
        }
        hull.dimension = HullDimension::Flat;
        emitVertices(loop);
        std::vector<uint32_t> ids(loop.size());
        std::iota(ids.begin(), ids.end(), 0u);
        Vec3 n = newellNormal(local, loop);
        if (glm::dot(n, planeNormal) <= 0.0)
            n = planeNormal;
        Real front = -std::numeric_limits<Real>::max();
        Real back = -std::numeric_limits<Real>::max();
        for (uint32_t i : source) {
            front = std::max(front, glm::dot(n, points[i]));
            back = std::max(back, -glm::dot(n, points[i]));
        }
        HullFace top{ids, n, front};
        HullFace bottom{std::vector<uint32_t>(ids.rbegin(), ids.rend()), -n, back};
        hull.faces = {std::move(top), std::move(bottom)};
        return hull;
    }

    QuickHull qh(local, eps);
    qh.build({i0, i1, i2, i3});
    std::vector<std::vector<uint32_t>> loops = qh.mergedFaces();

    // A vertex shared by only two faces sits in the middle of a straight edge between them; it is not a corner.
    // It is removed from both faces at once (never from just one) so that the edges still pair up.
    std::unordered_map<uint32_t, std::vector<size_t>> facesOf;
    for (size_t f = 0; f < loops.size(); ++f) {
        for (uint32_t v : loops[f])
            facesOf[v].push_back(f);
    }
    for (const auto& [v, fs] : facesOf) {
        if (fs.size() != 2 || loops[fs[0]].size() < 4 || loops[fs[1]].size() < 4)
            continue;
        for (size_t f : fs)
            loops[f].erase(std::find(loops[f].begin(), loops[f].end(), v));
    }

    // Compact to the vertices that faces use, in first-use order.
    std::unordered_map<uint32_t, uint32_t> remap;
    std::vector<uint32_t> used;
    for (auto& loop : loops) {
        for (uint32_t& v : loop) {
            const auto [it, inserted] = remap.emplace(v, static_cast<uint32_t>(used.size()));
            if (inserted)
                used.push_back(v);
            v = it->second;
        }
    }
    hull.dimension = HullDimension::Solid;
    emitVertices(used);
    std::vector<Vec3> compactLocal;
    compactLocal.reserve(used.size());
    for (uint32_t id : used)
        compactLocal.push_back(local[id]);
    for (auto& loop : loops) {
        HullFace face;
        face.normal = newellNormal(compactLocal, loop);
        // The plane passes through the outermost vertex so that every vertex lies behind it.
        face.offset = -std::numeric_limits<Real>::max();
        for (uint32_t v : loop)
            face.offset = std::max(face.offset, glm::dot(face.normal, hull.vertices[v]));
        face.vertices = std::move(loop);
        hull.faces.push_back(std::move(face));
    }
    return hull;
}

} // namespace rl
