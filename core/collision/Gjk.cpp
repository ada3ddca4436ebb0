#include "collision/Gjk.h"

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

// Closest point of the simplex to the origin. The simplex is reduced to the vertices that support that point and
// lambda receives their barycentric weights. Regions are tested in the order of Ericson's "Real-Time Collision
// Detection" (5.1), which needs no division until a region is known, so flat or tiny simplices stay finite.
struct Simplex {
    SimplexVertex v[4];
    Real lambda[4] = {1.0, 0.0, 0.0, 0.0};
    int count = 0;

    Vec3 point() const {
        Vec3 p(0.0);
        for (int i = 0; i < count; ++i)
            p += lambda[i] * v[i].w;
        return p;
    }
    void witnesses(Vec3& pa, Vec3& pb) const {
        pa = Vec3(0.0);
        pb = Vec3(0.0);
        for (int i = 0; i < count; ++i) {
            pa += lambda[i] * v[i].a;
            pb += lambda[i] * v[i].b;
        }
    }
    void keep1(int i) {
        v[0] = v[i];
        lambda[0] = 1.0;
        count = 1;
    }
    void keep2(int i, int j, Real t) { // weight t on j
        const SimplexVertex a = v[i], b = v[j];
        v[0] = a;
        v[1] = b;
        lambda[0] = 1.0 - t;
        lambda[1] = t;
        count = 2;
    }

    void solveSegment(int i, int j) {
        const Vec3 a = v[i].w, ab = v[j].w - a;
        const Real t = -glm::dot(a, ab);
        const Real len2 = glm::dot(ab, ab);
        if (t <= 0.0 || len2 <= 0.0)
            keep1(i);
        else if (t >= len2)
            keep1(j);
        else
            keep2(i, j, t / len2);
    }

    // Result in v[0..count). Returns squared distance of the reduced simplex.
    void solveTriangle(int ia, int ib, int ic) {
        const SimplexVertex A = v[ia], B = v[ib], C = v[ic];
        const Vec3 a = A.w, b = B.w, c = C.w;
        const Vec3 ab = b - a, ac = c - a;
        const Real d1 = -glm::dot(ab, a), d2 = -glm::dot(ac, a);
        auto set1 = [&](const SimplexVertex& p) {
            v[0] = p;
            lambda[0] = 1.0;
            count = 1;
        };
        auto set2 = [&](const SimplexVertex& p, const SimplexVertex& q, Real t) {
            v[0] = p;
            v[1] = q;
            lambda[0] = 1.0 - t;
            lambda[1] = t;
            count = 2;
        };
        if (d1 <= 0.0 && d2 <= 0.0)
            return set1(A);
        const Real d3 = -glm::dot(ab, b), d4 = -glm::dot(ac, b);
        if (d3 >= 0.0 && d4 <= d3)
            return set1(B);
        const Real vc = d1 * d4 - d3 * d2;
        if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
            return set2(A, B, d1 / (d1 - d3));
        const Real d5 = -glm::dot(ab, c), d6 = -glm::dot(ac, c);
        if (d6 >= 0.0 && d5 <= d6)
            return set1(C);
        const Real vb = d5 * d2 - d1 * d6;
        if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
            return set2(A, C, d2 / (d2 - d6));
        const Real va = d3 * d6 - d5 * d4;
        if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
            return set2(B, C, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
        const Real sum = va + vb + vc;
        if (!(sum > 0.0)) {
            // Collinear triangle: its closest point lies on one of its edges.
            Simplex best;
            Real bestD = std::numeric_limits<Real>::infinity();
            const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
            const SimplexVertex tri[3] = {A, B, C};
            for (const auto& p : pairs) {
                Simplex s;
                s.v[0] = tri[p[0]];
                s.v[1] = tri[p[1]];
                s.count = 2;
                s.solveSegment(0, 1);
                const Vec3 q = s.point();
                if (glm::dot(q, q) < bestD) {
                    bestD = glm::dot(q, q);
                    best = s;
                }
            }
            *this = best;
            return;
        }
        v[0] = A;
        v[1] = B;
        v[2] = C;
        lambda[1] = vb / sum;
        lambda[2] = vc / sum;
        lambda[0] = 1.0 - lambda[1] - lambda[2];
        count = 3;
    }

    // Returns true when the origin is inside the tetrahedron.
    bool solveTetrahedron() {
        const SimplexVertex S[4] = {v[0], v[1], v[2], v[3]};
        const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
        Simplex best;
        Real bestD = std::numeric_limits<Real>::infinity();
        bool anyOutside = false;
        for (const auto& f : faces) {
            const Vec3 a = S[f[0]].w;
            const Vec3 n = glm::cross(S[f[1]].w - a, S[f[2]].w - a);
            const Real sideOrigin = -glm::dot(n, a);
            const Real sideOther = glm::dot(n, S[f[3]].w - a);
            // Outside this face's plane (or a flat tetrahedron, where every face must be checked).
            if (sideOrigin * sideOther < 0.0 || sideOther == 0.0) {
                anyOutside = true;
                Simplex s;
                s.v[0] = S[f[0]];
                s.v[1] = S[f[1]];
                s.v[2] = S[f[2]];
                s.count = 3;
                s.solveTriangle(0, 1, 2);
                const Vec3 q = s.point();
                if (glm::dot(q, q) < bestD) {
                    bestD = glm::dot(q, q);
                    best = s;
                }
            }
        }
        if (anyOutside) {
            *this = best;
            return false;
        }
        // Inside: barycentric weights by signed volumes, kept for the witness points.
        const Real vol = glm::dot(S[1].w - S[0].w, glm::cross(S[2].w - S[0].w, S[3].w - S[0].w));
        const Real w1 = glm::dot(-S[0].w, glm::cross(S[2].w - S[0].w, S[3].w - S[0].w)) / vol;
        const Real w2 = glm::dot(S[1].w - S[0].w, glm::cross(-S[0].w, S[3].w - S[0].w)) / vol;
        const Real w3 = glm::dot(S[1].w - S[0].w, glm::cross(S[2].w - S[0].w, -S[0].w)) / vol;
        lambda[0] = 1.0 - w1 - w2 - w3;
        lambda[1] = w1;
        lambda[2] = w2;
        lambda[3] = w3;
        count = 4;
        return true;
    }
};

SimplexVertex supportVertex(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const Vec3& d) {
    SimplexVertex s;
    s.a = worldSupportCore(a, xfA, d);
    s.b = worldSupportCore(b, xfB, -d);
    s.w = s.a - s.b;
    return s;
}

} // namespace

GjkResult gjkDistance(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                      const GjkOptions& options) {
    GjkResult result;
    Simplex simplex;
    // Start along the line between the centres: for separated shapes the first support is already close.
    Vec3 d = xfB.apply(b.centre()) - xfA.apply(a.centre());
    if (glm::dot(d, d) == 0.0)
        d = Vec3(1.0, 0.0, 0.0);
    simplex.v[0] = supportVertex(a, xfA, b, xfB, -d);
    simplex.count = 1;
    Real scale2 = glm::dot(simplex.v[0].w, simplex.v[0].w);
    Vec3 v = simplex.v[0].w;
    Real vv = glm::dot(v, v);
    bool overlap = false;
    int iter = 0;
    const int maxIterations = std::max(1, options.maxIterations);
    for (; iter < maxIterations; ++iter) {
        if (vv <= kGjkTouchTolerance * kGjkTouchTolerance * scale2) {
            overlap = true;
            break;
        }
        const SimplexVertex w = supportVertex(a, xfA, b, xfB, -v);
        scale2 = std::max(scale2, glm::dot(w.w, w.w));
        // Progress test: the lower bound dot(v, w)/|v| has met the upper bound |v| up to rounding.
        if (vv - glm::dot(v, w.w) <= 1e-12 * vv + 1e-18 * scale2)
            break;
        bool duplicate = false;
        for (int i = 0; i < simplex.count; ++i)
            duplicate = duplicate || simplex.v[i].w == w.w;
        if (duplicate)
            break;
        const Simplex saved = simplex;
        simplex.v[simplex.count++] = w;
        bool inside = false;
        if (simplex.count == 2)
            simplex.solveSegment(0, 1);
        else if (simplex.count == 3)
            simplex.solveTriangle(0, 1, 2);
        else
            inside = simplex.solveTetrahedron();
        if (inside) {
            overlap = true;
            v = Vec3(0.0);
            vv = 0.0;
            ++iter;
            break;
        }
        const Vec3 nv = simplex.point();
        const Real nvv = glm::dot(nv, nv);
        if (!(nvv < vv)) {
            // No strict decrease: rounding has the last word, keep the previous simplex.
            simplex = saved;
            ++iter;
            break;
        }
        v = nv;
        vv = nvv;
    }

    result.iterations = iter;
    result.status =
        overlap ? GjkStatus::Overlapping : (iter >= maxIterations ? GjkStatus::MaxIterations : GjkStatus::Separated);
    result.simplexCount = simplex.count;
    for (int i = 0; i < simplex.count; ++i)
        result.simplex[i] = simplex.v[i];
    Vec3 pa, pb;
    simplex.witnesses(pa, pb);
    const Real rA = a.coreRadius(), rB = b.coreRadius();
    if (overlap) {
        result.coreDistance = 0.0;
        result.distance = 0.0;
        result.pointA = pa;
        result.pointB = pa;
        return result;
    }
    const Real dist = std::sqrt(vv);
    result.coreDistance = dist;
    result.normal = -v / dist;
    result.distance = dist - rA - rB;
    result.pointA = pa + rA * result.normal;
    result.pointB = pb - rB * result.normal;
    if (result.distance < 0.0)
        result.status = GjkStatus::Overlapping;
    return result;
}

bool gjkOverlap(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const GjkOptions& options) {
    return gjkDistance(a, xfA, b, xfB, options).distance <= 0.0;
}

} // namespace rl
