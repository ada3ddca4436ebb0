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
// Rounds of absorbing faces into a visible set whose horizon is not one loop; in practice one or two suffice.
constexpr int kMaxHorizonRepairs = 16;
// Thickness, in tolerances, below which a point set is flat. Measured on random slabs 2 wide (tolerance 2.8e-10):
// 2e-9 thick, a solid hull left points 5.7e-7 outside a face; 6e-9 thick, 2.6e-8; 2e-8 thick, 5e-9; 4e-8, 4e-10.
constexpr Real kFlatFactor = 64.0;
// Rounding of the input coordinates (m) that face merging allows for: half a unit in the sixth decimal, which is
// what Blender's OBJ exporter writes, over the three coordinates of a point and the plane's own error (a rotated
// box from Blender: 7.8e-7). Capped relative to the extent (faceMergeTolerance) so that millimetre-sized point sets
// keep their own scale.
constexpr Real kInputRounding = 2e-6;

Real faceMergeRelative(const HullOptions& options) {
    return std::isfinite(options.faceMergeTolerance) && options.faceMergeTolerance > 0.0
               ? options.faceMergeTolerance
               : HullOptions{}.faceMergeTolerance;
}

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

// Plane normals are computed in extended precision. A sliver triangle (height h, length L) gets a normal whose
// angle error is about (unit roundoff) * L / h, and over the length L that tilts the plane by roundoff * L^2 / h.
// With 64-bit mantissas a sliver of relative height 1e-9 still keeps its plane well inside the distance tolerance.
using Wide = long double;

struct WideVec {
    Wide x, y, z;
};

WideVec wide(const Vec3& v) {
    return {v.x, v.y, v.z};
}
WideVec sub(const WideVec& a, const WideVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
WideVec cross(const WideVec& a, const WideVec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Wide dot(const WideVec& a, const WideVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 unit(const WideVec& n) {
    const Wide len = std::sqrt(dot(n, n));
    if (!(len > 0))
        return Vec3(0.0);
    return Vec3(static_cast<Real>(n.x / len), static_cast<Real>(n.y / len), static_cast<Real>(n.z / len));
}

// Unit normal of a triangle from the two shortest edges: their cross product loses the least to cancellation.
Vec3 triangleNormal(const Vec3& pa, const Vec3& pb, const Vec3& pc) {
    const WideVec a = wide(pa), b = wide(pb), c = wide(pc);
    const WideVec e0 = sub(b, a);
    const WideVec e1 = sub(c, b);
    const WideVec e2 = sub(a, c);
    const Wide l0 = dot(e0, e0);
    const Wide l1 = dot(e1, e1);
    const Wide l2 = dot(e2, e2);
    if (l0 >= l1 && l0 >= l2)
        return unit(cross(e1, e2));
    if (l1 >= l0 && l1 >= l2)
        return unit(cross(e2, e0));
    return unit(cross(e0, e1));
}

// Newell's normal of a polygon: the area-weighted average over all its edges, robust for many near-collinear vertices.
Vec3 newellNormal(const std::vector<Vec3>& pts, const std::vector<uint32_t>& loop) {
    WideVec n{0, 0, 0};
    const size_t count = loop.size();
    // Relative to the first vertex, so that the sums do not carry the polygon's distance from the origin.
    const WideVec origin = wide(pts[loop[0]]);
    for (size_t i = 0; i < count; ++i) {
        const WideVec p = sub(wide(pts[loop[i]]), origin);
        const WideVec q = sub(wide(pts[loop[(i + 1) % count]]), origin);
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    return unit(n);
}

// Any unit vector perpendicular to n.
Vec3 perpendicular(const Vec3& n) {
    const Vec3 axis = std::abs(n.x) < 0.57735 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(n, axis));
}

class QuickHull {
public:
    QuickHull(const std::vector<Vec3>& local, Real tolerance) : m_pts(local), m_eps(tolerance) {}

    // Builds the triangle hull from a starting tetrahedron that is thicker than the tolerance.
    void build(const std::array<uint32_t, 4>& simplex);

    // Groups coplanar triangles into polygons; returns loops of local point indices, counter-clockwise from outside.
    // mergeTolerance (>= the build tolerance) is how far from the seed triangle's plane a neighbour's vertices may lie.
    std::vector<std::vector<uint32_t>> mergedFaces(Real mergeTolerance) const;
    // The triangles of the hull, as local point indices, counter-clockwise from outside.
    std::vector<std::array<uint32_t, 3>> triangles() const {
        std::vector<std::array<uint32_t, 3>> out;
        for (const Triangle& t : m_tris)
            if (t.alive)
                out.push_back({t.v[0], t.v[1], t.v[2]});
        return out;
    }

private:
    Real distance(const Triangle& t, uint32_t p) const { return glm::dot(t.normal, m_pts[p]) - t.offset; }
    // Visibility flags are only meaningful for faces stamped in the current insertion.
    bool visibleNow(int32_t f) const { return m_stamp[f] == m_iteration && m_visible[f] != 0; }
    int32_t addTriangle(uint32_t a, uint32_t b, uint32_t c);
    bool convexLoop(const std::vector<uint32_t>& loop, Real tolerance) const;
    void assign(const std::vector<uint32_t>& candidates, const std::vector<int32_t>& faces,
                const std::vector<int32_t>& fallback);
    bool addPoint(int32_t seedFace, uint32_t p);
    template <class Edge>
    bool horizonLoop(const std::vector<Edge>& horizon, std::vector<Edge>& order);

    const std::vector<Vec3>& m_pts;
    Real m_eps;
    std::vector<Triangle> m_tris;
    std::vector<uint32_t> m_stamp; // per triangle: iteration in which visibility was decided
    std::vector<uint8_t> m_visible;
    uint32_t m_iteration = 0;
    std::vector<int32_t> m_pending; // faces whose conflict list became non-empty, processed last-in first-out
    std::vector<int32_t> m_free;    // slots of deleted faces
    // Per point: the horizon edge starting there, valid while m_vertexStamp equals the current loop check.
    std::vector<uint32_t> m_vertexStamp;
    std::vector<uint32_t> m_vertexSlot;
    uint32_t m_loopCheck = 0;
};

// Orders the horizon edges into one loop; false if they form several loops or pass a vertex twice.
template <class Edge>
bool QuickHull::horizonLoop(const std::vector<Edge>& horizon, std::vector<Edge>& order) {
    order.clear();
    if (horizon.size() < 3)
        return false;
    if (m_vertexStamp.size() != m_pts.size()) {
        m_vertexStamp.assign(m_pts.size(), 0);
        m_vertexSlot.assign(m_pts.size(), 0);
    }
    ++m_loopCheck;
    for (size_t i = 0; i < horizon.size(); ++i) {
        const uint32_t start = m_tris[horizon[i].face].v[horizon[i].edge];
        if (m_vertexStamp[start] == m_loopCheck)
            return false; // pinched: two horizon edges leave the same vertex
        m_vertexStamp[start] = m_loopCheck;
        m_vertexSlot[start] = static_cast<uint32_t>(i);
    }
    size_t current = 0;
    for (size_t i = 0; i < horizon.size(); ++i) {
        // Returning to the first edge before all are used means a second loop exists.
        if (i > 0 && current == 0)
            return false;
        order.push_back(horizon[current]);
        const uint32_t end = m_tris[horizon[current].face].v[(horizon[current].edge + 1) % 3];
        if (m_vertexStamp[end] != m_loopCheck)
            return false;
        current = m_vertexSlot[end];
    }
    return current == 0;
}

int32_t QuickHull::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    int32_t id;
    // Slots of deleted faces are reused: a large hull deletes several faces per inserted point.
    if (!m_free.empty()) {
        id = m_free.back();
        m_free.pop_back();
        m_tris[id] = Triangle{};
    } else {
        id = static_cast<int32_t>(m_tris.size());
        m_tris.emplace_back();
        m_stamp.push_back(0);
        m_visible.push_back(0);
    }
    Triangle& t = m_tris[id];
    t.v = {a, b, c};
    t.normal = triangleNormal(m_pts[a], m_pts[b], m_pts[c]);
    // The centroid averages the rounding of the three vertices.
    t.offset = glm::dot(t.normal, (m_pts[a] + m_pts[b] + m_pts[c]) / 3.0);
    return id;
}

void QuickHull::assign(const std::vector<uint32_t>& candidates, const std::vector<int32_t>& faces,
                       const std::vector<int32_t>& fallback) {
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
        // In exact arithmetic a point outside a deleted face is either inside the new hull or outside a new face.
        // With a tolerance, a point can sit within it of a steep new face and still be outside an old face next to
        // the cone (thin slabs do this), so the faces around the cone get a second look before a point is dropped.
        if (best < 0) {
            for (int32_t f : fallback) {
                const Real d = distance(m_tris[f], p);
                if (d > bestDistance) {
                    bestDistance = d;
                    best = f;
                }
            }
        }
        if (best < 0)
            continue; // inside, or on the hull within the tolerance: dropped for good
        Triangle& t = m_tris[best];
        if (t.conflict.empty()) {
            m_pending.push_back(best);
        }
        if (t.conflict.empty() || bestDistance > t.furthestDistance) {
            t.furthest = p;
            t.furthestDistance = bestDistance;
        }
        t.conflict.push_back(p);
    }
}

void QuickHull::build(const std::array<uint32_t, 4>& s) {
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
    assign(rest, ids, {});

    // Every insertion makes a point a hull vertex or drops it, and a point is in at most one conflict list, so
    // there are at most as many insertions as points. A face enters the work list each time its conflict list
    // goes from empty to non-empty; dead faces are skipped.
    // Pops of finished faces are bounded by the pushes, which only happen inside the bounded point insertions.
    size_t insertions = m_pts.size() + 1;
    while (!m_pending.empty() && insertions > 0) {
        const int32_t f = m_pending.back();
        if (!m_tris[f].alive || m_tris[f].conflict.empty()) {
            m_pending.pop_back();
            continue;
        }
        --insertions;
        const uint32_t p = m_tris[f].furthest;
        if (!addPoint(f, p)) {
            // The visible region could not be made a disc; the point is left out (it is within rounding of it).
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

bool QuickHull::addPoint(int32_t seedFace, uint32_t p) {
    ++m_iteration;
    struct HorizonEdge {
        int32_t face; // visible face
        int edge;     // its edge index on the horizon
    };
    // Flood over the faces that see p, starting from the face whose conflict list holds it.
    std::vector<int32_t> visible{seedFace};
    m_stamp[seedFace] = m_iteration;
    m_visible[seedFace] = 1;
    for (size_t i = 0; i < visible.size(); ++i) {
        for (int32_t nb : m_tris[visible[i]].adj) {
            if (m_stamp[nb] == m_iteration)
                continue;
            m_stamp[nb] = m_iteration;
            m_visible[nb] = distance(m_tris[nb], p) > m_eps ? 1 : 0;
            if (m_visible[nb])
                visible.push_back(nb);
        }
    }

    // The visible set is then grown until the cone is sound, absorbing a face outside the horizon when
    //  - p is above its plane at all (dist > 0): a cone face on that edge would fold in, a concave edge. Allowing
    //    concave edges up to the tolerance lets the bends add up over many faces of a nearly flat surface; or
    //  - p is within the tolerance of its plane and the cone triangle on the shared edge would be a sliver (p
    //    within the tolerance of the edge's line) or would lie over the face itself: its normal would be noise
    //    or point inward.
    // Finally the horizon must be one simple loop. The visible set can enclose a face that p sees only within the
    // tolerance, or touch itself at a vertex; such faces (two or more visible neighbours, p within the tolerance
    // of their plane) are absorbed. Every round absorbs at least one face, and the rounds are capped.
    std::vector<HorizonEdge> horizon;
    std::vector<HorizonEdge> order;
    std::vector<int32_t> absorb;
    const size_t maxRounds = m_tris.size() + kMaxHorizonRepairs;
    int loopRepairs = 0;
    for (size_t round = 0;; ++round) {
        if (round >= maxRounds)
            return false;
        horizon.clear();
        absorb.clear();
        for (int32_t f : visible) {
            for (int e = 0; e < 3; ++e) {
                const int32_t nb = m_tris[f].adj[e];
                if (visibleNow(nb))
                    continue;
                horizon.push_back({f, e});
                const Real d = distance(m_tris[nb], p);
                bool take = d > 0.0;
                if (!take && d > -m_eps) {
                    const Vec3& a = m_pts[m_tris[f].v[e]];
                    const Vec3 ab = m_pts[m_tris[f].v[(e + 1) % 3]] - a;
                    const Real len = glm::length(ab);
                    const Vec3 ap = m_pts[p] - a;
                    // Sliver, or p lies (within the tolerance of nb's plane) on nb's side of the edge, where the
                    // cone triangle would fold back over nb with its normal reversed.
                    take = !(glm::length(glm::cross(ab, ap)) > m_eps * len) ||
                           glm::dot(glm::cross(m_tris[nb].normal, -ab), ap) > 0.0;
                }
                if (take && std::find(absorb.begin(), absorb.end(), nb) == absorb.end())
                    absorb.push_back(nb);
            }
        }
        if (absorb.empty()) {
            if (horizonLoop(horizon, order))
                break;
            if (++loopRepairs > kMaxHorizonRepairs)
                return false;
            for (const HorizonEdge& h : horizon) {
                const int32_t nb = m_tris[h.face].adj[h.edge];
                int seen = 0;
                for (int32_t x : m_tris[nb].adj)
                    seen += visibleNow(x) ? 1 : 0;
                // Only faces p sees within the tolerance: absorbing one it is clearly behind would dent the hull.
                if (seen >= 2 && distance(m_tris[nb], p) > -m_eps &&
                    std::find(absorb.begin(), absorb.end(), nb) == absorb.end())
                    absorb.push_back(nb);
            }
            if (absorb.empty())
                return false;
        }
        for (int32_t f : absorb) {
            m_stamp[f] = m_iteration;
            m_visible[f] = 1;
            visible.push_back(f);
        }
    }

    // Cone from p to every horizon edge, stitched to the faces outside and to each other.
    const size_t n = order.size();
    std::vector<int32_t> cone(n);
    for (size_t i = 0; i < n; ++i) {
        const HorizonEdge h = order[i];
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
    // The faces just outside the horizon: each cone face was stitched to one of them across its base edge.
    std::vector<int32_t> around;
    around.reserve(cone.size());
    for (int32_t c : cone)
        around.push_back(m_tris[c].adj[0]);
    assign(orphans, cone, around);
    m_free.insert(m_free.end(), visible.begin(), visible.end());
    return true;
}

// A merged group is only kept as one face if its outline is convex: on a surface that curves by less than the
// tolerance, the triangles within the tolerance of one plane can cover a non-convex patch.
bool QuickHull::convexLoop(const std::vector<uint32_t>& loop, Real tolerance) const {
    const Vec3 n = newellNormal(m_pts, loop);
    const size_t count = loop.size();
    // All vertices against all edges for ordinary faces; very large faces check each edge against its next vertex.
    constexpr size_t kFullCheckLimit = 256;
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = m_pts[loop[i]];
        const Vec3 edge = m_pts[loop[(i + 1) % count]] - a;
        const Vec3 inward = glm::cross(n, edge);
        const Real len = glm::length(inward);
        if (!(len > 0.0))
            return false;
        if (count <= kFullCheckLimit) {
            for (uint32_t v : loop) {
                if (glm::dot(inward, m_pts[v] - a) < -tolerance * len)
                    return false;
            }
        } else if (glm::dot(inward, m_pts[loop[(i + 2) % count]] - a) < -tolerance * len) {
            return false;
        }
    }
    return true;
}

std::vector<std::vector<uint32_t>> QuickHull::mergedFaces(Real mergeTolerance) const {
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
                    coplanar = coplanar && std::abs(glm::dot(n, m_pts[v]) - d) <= mergeTolerance;
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
                ok = at == start && convexLoop(loop, mergeTolerance);
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

    hull.tolerance = eps;

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

    // A set thinner than a few tolerances is taken as flat: as a solid every face along its rim would be a sliver
    // whose plane is decided by the tolerance rather than the data, and the hull would not stay convex there.
    if (!(planeDistance > kFlatFactor * eps)) {
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
    // Faces merge with a looser tolerance than the hull is built with: the input is rounded. Blender writes OBJ
    // coordinates with six decimals, so the faces of a rotated box are planar only to about 1e-6 m, and with the
    // build tolerance alone every such face stayed two triangles: a box landing flat got a three-point manifold
    // from one of them and its fourth corner went 3.7 cm into the floor (mixed.obj's Cube).
    const Real mergeEps = std::max(eps, std::min(kInputRounding, faceMergeRelative(options) * extent));
    hull.faceTolerance = mergeEps;
    // Merged faces may bend by up to mergeEps; the triangles keep the volume independent of how a face is split.
    for (const auto& t : qh.triangles())
        for (uint32_t v : t)
            hull.triangleCorners.push_back(points[source[v]]);
    std::vector<std::vector<uint32_t>> loops = qh.mergedFaces(mergeEps);

    // A vertex shared by only two faces sits in the middle of a straight edge between them; it is not a corner.
    // It is removed from both faces at once (never from just one) so that the edges still pair up.
    // Per point: how many faces use it, and the first two of them (only vertices in exactly two faces matter).
    constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> faceCount(local.size(), 0);
    std::vector<std::array<uint32_t, 2>> firstFaces(local.size(), {kNone, kNone});
    for (size_t f = 0; f < loops.size(); ++f) {
        for (uint32_t v : loops[f]) {
            if (faceCount[v] < 2)
                firstFaces[v][faceCount[v]] = static_cast<uint32_t>(f);
            ++faceCount[v];
        }
    }
    for (uint32_t v = 0; v < local.size(); ++v) {
        if (faceCount[v] != 2)
            continue;
        auto& a = loops[firstFaces[v][0]];
        auto& b = loops[firstFaces[v][1]];
        if (a.size() < 4 || b.size() < 4)
            continue;
        a.erase(std::find(a.begin(), a.end(), v));
        b.erase(std::find(b.begin(), b.end(), v));
    }

    // Compact to the vertices that faces use, in first-use order.
    std::vector<uint32_t> remap(local.size(), kNone);
    std::vector<uint32_t> used;
    for (auto& loop : loops) {
        for (uint32_t& v : loop) {
            if (remap[v] == kNone) {
                remap[v] = static_cast<uint32_t>(used.size());
                used.push_back(v);
            }
            v = remap[v];
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
