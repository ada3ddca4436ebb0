#include "collision/Epa.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rl {

namespace {

struct EpaFace {
    int v[3];   // counter-clockwise seen from outside
    int adj[3]; // adj[k] is the face across edge v[k] -> v[k+1]
    Vec3 n{0.0};
    Real dist = 0.0;
    bool alive = true;
};

struct HorizonEdge {
    int a, b;    // in the winding of the removed face
    int outside; // the surviving face across the edge
};

class Polytope {
public:
    std::vector<SimplexVertex> verts;
    std::vector<EpaFace> faces;

    // Returns false when the triangle is too thin to have a reliable normal.
    bool makeFace(int a, int b, int c, EpaFace& f, Real minArea2) const {
        f.v[0] = a;
        f.v[1] = b;
        f.v[2] = c;
        const Vec3 n = glm::cross(verts[b].w - verts[a].w, verts[c].w - verts[a].w);
        const Real len2 = glm::dot(n, n);
        if (!(len2 > minArea2))
            return false;
        f.n = n / std::sqrt(len2);
        // Of the three vertices, the one nearest the origin gives the distance with the least rounding.
        f.dist = glm::dot(f.n, verts[a].w);
        f.alive = true;
        return true;
    }
};

SimplexVertex support(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const Vec3& d) {
    SimplexVertex s;
    s.a = worldSupportCore(a, xfA, d);
    s.b = worldSupportCore(b, xfB, -d);
    s.w = s.a - s.b;
    return s;
}

Real distanceToLine(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const Real len2 = glm::dot(ab, ab);
    const Vec3 ap = p - a;
    return len2 > 0.0 ? glm::length(glm::cross(ap, ab)) / std::sqrt(len2) : glm::length(ap);
}

// Barycentric weights of p's projection on triangle abc, unclamped (the smallest tells how far outside it is).
void barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Real out[3]) {
    const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const Real d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const Real d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const Real den = d00 * d11 - d01 * d01;
    Real v = 1.0 / 3.0, w = 1.0 / 3.0;
    if (den > 0.0) {
        v = (d11 * d20 - d01 * d21) / den;
        w = (d00 * d21 - d01 * d20) / den;
    }
    out[0] = 1.0 - v - w;
    out[1] = v;
    out[2] = w;
}

} // namespace

EpaResult epaPenetration(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                         const GjkResult& gjk, const EpaOptions& options) {
    EpaResult result;
    const Real radii = a.coreRadius() + b.coreRadius();
    // The polytope's storage is kept per thread: an EPA call then allocates nothing once the thread has warmed up.
    thread_local Polytope poly;
    poly.verts.clear();
    poly.faces.clear();
    const int maxFaces = std::max(4, options.maxFaces);
    for (int i = 0; i < gjk.simplexCount; ++i)
        poly.verts.push_back(gjk.simplex[i]);
    if (poly.verts.empty())
        poly.verts.push_back(support(a, xfA, b, xfB, Vec3(1.0, 0.0, 0.0)));

    // Size of the problem, for the tolerances: the largest support point GJK met, or the axis extent of the
    // difference when GJK stopped on its first vertex. Relative tolerances let a 1 mm body against a 1 km body be
    // handled at the precision the numbers allow.
    Real scale = 0.0;
    for (const SimplexVertex& v : poly.verts)
        scale = std::max(scale, glm::length(v.w));
    if (poly.verts.size() < 4) {
        for (int i = 0; i < 3; ++i) {
            Vec3 axis(0.0);
            axis[i] = 1.0;
            scale = std::max(scale, glm::dot(support(a, xfA, b, xfB, axis).w, axis) -
                                        glm::dot(support(a, xfA, b, xfB, -axis).w, axis));
        }
    }
    if (!(scale > 0.0) || !std::isfinite(scale))
        return result;
    const Real tiny = 1e-12 * scale;

    // Grow GJK's simplex to a tetrahedron that still contains the origin: GJK stops early with fewer vertices
    // when the origin lies on a vertex, edge or face of the difference (touching shapes).
    if (poly.verts.size() == 1) {
        SimplexVertex best = poly.verts[0];
        Real bestD = 0.0;
        const Vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const Vec3& d : dirs) {
            const SimplexVertex s = support(a, xfA, b, xfB, d);
            const Real dd = glm::length(s.w - poly.verts[0].w);
            if (dd > bestD) {
                bestD = dd;
                best = s;
            }
        }
        if (bestD <= tiny)
            return result;
        poly.verts.push_back(best);
    }
    if (poly.verts.size() == 2) {
        const Vec3 p0 = poly.verts[0].w, p1 = poly.verts[1].w;
        const Vec3 axis = glm::normalize(p1 - p0);
        const Vec3 u =
            glm::normalize(std::abs(axis.x) < 0.6 ? glm::cross(axis, Vec3(1, 0, 0)) : glm::cross(axis, Vec3(0, 1, 0)));
        const Vec3 v = glm::cross(axis, u);
        SimplexVertex best = poly.verts[0];
        Real bestD = 0.0;
        for (int k = 0; k < 6; ++k) {
            const Real ang = k * kPi / 3.0;
            const SimplexVertex s = support(a, xfA, b, xfB, std::cos(ang) * u + std::sin(ang) * v);
            const Real dd = distanceToLine(s.w, p0, p1);
            if (dd > bestD) {
                bestD = dd;
                best = s;
            }
        }
        if (bestD <= tiny)
            return result;
        poly.verts.push_back(best);
    }
    if (poly.verts.size() == 3) {
        const Vec3 n = glm::cross(poly.verts[1].w - poly.verts[0].w, poly.verts[2].w - poly.verts[0].w);
        const Real len = glm::length(n);
        if (!(len > tiny * tiny))
            return result;
        const SimplexVertex up = support(a, xfA, b, xfB, n / len);
        const SimplexVertex down = support(a, xfA, b, xfB, -n / len);
        const Real du = glm::dot(n / len, up.w - poly.verts[0].w);
        const Real dd = -glm::dot(n / len, down.w - poly.verts[0].w);
        if (std::max(du, dd) <= tiny)
            return result;
        poly.verts.push_back(du >= dd ? up : down);
    }
    // Orient the tetrahedron so that its faces wind outward.
    {
        const Vec3 p0 = poly.verts[0].w;
        const Real vol = glm::dot(poly.verts[1].w - p0, glm::cross(poly.verts[2].w - p0, poly.verts[3].w - p0));
        if (std::abs(vol) <= tiny * tiny * tiny)
            return result;
        if (vol > 0.0)
            std::swap(poly.verts[1], poly.verts[2]);
    }
    // With vol < 0 for (0,1,2,3), these four faces wind outward; adjacency written out by hand.
    const int tet[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    const int tetAdj[4][3] = {{1, 3, 2}, {2, 3, 0}, {0, 3, 1}, {1, 2, 0}};
    // Thinner faces have normals that rounding decides (error ~ 1e-16 * scale^2 / area); they end the expansion.
    const Real minArea = 1e-13 * scale * scale;
    const Real minArea2 = minArea * minArea;
    for (int i = 0; i < 4; ++i) {
        EpaFace f;
        if (!poly.makeFace(tet[i][0], tet[i][1], tet[i][2], f, minArea2))
            return result;
        for (int k = 0; k < 3; ++k)
            f.adj[k] = tetAdj[i][k];
        poly.faces.push_back(f);
    }

    const Real tolerance = std::max(options.relativeTolerance, 1e-15) * scale;
    thread_local std::vector<int> stack;
    thread_local std::vector<char> visible;
    thread_local std::vector<HorizonEdge> horizon;
    int bestFace = -1;
    Real upper = std::numeric_limits<Real>::infinity();
    EpaStatus status = EpaStatus::BudgetExceeded;
    int iter = 0;
    const int maxIterations = std::max(1, options.maxIterations);
    for (; iter < maxIterations; ++iter) {
        bestFace = -1;
        Real bestDist = std::numeric_limits<Real>::infinity();
        for (int i = 0; i < int(poly.faces.size()); ++i) {
            if (poly.faces[i].alive && poly.faces[i].dist < bestDist) {
                bestDist = poly.faces[i].dist;
                bestFace = i;
            }
        }
        if (bestFace < 0) {
            status = EpaStatus::Degenerate;
            break;
        }
        const EpaFace best = poly.faces[bestFace];
        const SimplexVertex w = support(a, xfA, b, xfB, best.n);
        // Every support distance is an upper bound of the depth and the best face's distance a lower bound;
        // keeping the smallest upper bound seen lets the search stop as soon as the bracket is tight.
        upper = std::min(upper, glm::dot(best.n, w.w));
        if (upper - best.dist <= tolerance) {
            status = EpaStatus::Converged;
            break;
        }

        // The faces that see w, found by a flood fill from the best face (which sees w by the test above). Only a
        // connected region is removed, so the hole is bounded by one loop of horizon edges.
        const int wi = int(poly.verts.size());
        poly.verts.push_back(w);
        visible.assign(poly.faces.size(), 0);
        horizon.clear();
        stack.clear();
        stack.push_back(bestFace);
        visible[bestFace] = 1;
        while (!stack.empty()) {
            const int fi = stack.back();
            stack.pop_back();
            const EpaFace& f = poly.faces[fi];
            for (int k = 0; k < 3; ++k) {
                const int g = f.adj[k];
                if (visible[g])
                    continue;
                const EpaFace& gf = poly.faces[g];
                if (glm::dot(gf.n, w.w) - gf.dist > tiny) {
                    visible[g] = 1;
                    stack.push_back(g);
                } else {
                    horizon.push_back({f.v[k], f.v[(k + 1) % 3], g});
                }
            }
        }
        // A face that is visible, but was reached only through a horizon test from another side, would make the
        // horizon cross itself: check that every horizon vertex starts exactly one edge and ends exactly one.
        bool loopOk = horizon.size() >= 3;
        for (size_t i = 0; loopOk && i < horizon.size(); ++i) {
            int starts = 0, ends = 0;
            for (const HorizonEdge& e : horizon) {
                starts += e.a == horizon[i].a;
                ends += e.b == horizon[i].a;
            }
            loopOk = starts == 1 && ends == 1;
        }
        if (!loopOk) {
            status = EpaStatus::Degenerate;
            break;
        }
        if (int(poly.faces.size() + horizon.size()) > maxFaces) {
            status = EpaStatus::BudgetExceeded;
            break;
        }
        for (size_t i = 0; i < visible.size(); ++i) {
            if (visible[i])
                poly.faces[i].alive = false;
        }
        const int firstNew = int(poly.faces.size());
        bool facesOk = true;
        for (const HorizonEdge& e : horizon) {
            EpaFace f;
            if (!poly.makeFace(e.a, e.b, wi, f, minArea2)) {
                facesOk = false;
                break;
            }
            f.adj[0] = e.outside;
            f.adj[1] = f.adj[2] = -1;
            const int fi = int(poly.faces.size());
            EpaFace& out = poly.faces[e.outside];
            for (int k = 0; k < 3; ++k) {
                if (out.v[k] == e.b && out.v[(k + 1) % 3] == e.a)
                    out.adj[k] = fi;
            }
            poly.faces.push_back(f);
        }
        if (!facesOk) {
            status = EpaStatus::Degenerate;
            break;
        }
        // Stitch the fan: face (a, b, w) meets the face starting at b across (b, w), the one ending at a across (w, a).
        for (int i = firstNew; i < int(poly.faces.size()); ++i) {
            EpaFace& f = poly.faces[i];
            for (int j = firstNew; j < int(poly.faces.size()); ++j) {
                if (poly.faces[j].v[0] == f.v[1])
                    f.adj[1] = j;
                if (poly.faces[j].v[1] == f.v[0])
                    f.adj[2] = j;
            }
        }
    }
    result.iterations = iter;
    result.faces = int(poly.faces.size());
    result.status = status;
    if (bestFace < 0 || status == EpaStatus::Degenerate)
        return result;
    if (!poly.faces[bestFace].alive) {
        // The iteration bound struck after an expansion removed the face: take the closest face that is left.
        bestFace = -1;
        for (int i = 0; i < int(poly.faces.size()); ++i) {
            if (poly.faces[i].alive && (bestFace < 0 || poly.faces[i].dist < poly.faces[bestFace].dist))
                bestFace = i;
        }
        if (bestFace < 0) {
            result.status = EpaStatus::Degenerate;
            return result;
        }
    }

    // A face of the Minkowski difference that is a polygon is split into coplanar triangles of equal distance, and
    // the origin projects into only one of them: pick, among the faces as close as the best, the one that holds
    // the projection, or the witnesses would be extrapolated off the shapes.
    int chosen = bestFace;
    Real lambda[3] = {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
    Real inside = -std::numeric_limits<Real>::infinity();
    for (int i = 0; i < int(poly.faces.size()); ++i) {
        const EpaFace& g = poly.faces[i];
        if (!g.alive || g.dist > poly.faces[bestFace].dist + tolerance)
            continue;
        Real l[3];
        barycentric(g.n * g.dist, poly.verts[g.v[0]].w, poly.verts[g.v[1]].w, poly.verts[g.v[2]].w, l);
        const Real m = std::min({l[0], l[1], l[2]});
        if (m > inside) {
            inside = m;
            chosen = i;
            std::copy(l, l + 3, lambda);
        }
    }
    const EpaFace& f = poly.faces[chosen];
    // Clamp into the triangle: rounding may leave the projection a hair outside.
    for (Real& l : lambda)
        l = std::max(l, 0.0);
    const Real sum = lambda[0] + lambda[1] + lambda[2];
    for (Real& l : lambda)
        l = sum > 0.0 ? l / sum : 1.0 / 3.0;
    Vec3 pa(0.0), pb(0.0);
    for (int k = 0; k < 3; ++k) {
        pa += lambda[k] * poly.verts[f.v[k]].a;
        pb += lambda[k] * poly.verts[f.v[k]].b;
    }
    result.normal = f.n;
    result.depth = f.dist + radii;
    result.pointA = pa + a.coreRadius() * f.n;
    result.pointB = pb - b.coreRadius() * f.n;
    if (!std::isfinite(result.depth) || !std::isfinite(pa.x + pa.y + pa.z + pb.x + pb.y + pb.z))
        result.status = EpaStatus::Degenerate;
    return result;
}

} // namespace rl
