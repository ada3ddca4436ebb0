#include "collision/Sat.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rl {

namespace {

Real supportValue(const std::vector<Vec3>& points, const Vec3& d) {
    Real best = -std::numeric_limits<Real>::infinity();
    for (const Vec3& p : points)
        best = std::max(best, glm::dot(p, d));
    return best;
}

} // namespace

void closestPointsSegments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& onP, Vec3& onQ) {
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const Real a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    Real s = 0.0, t = 0.0;
    if (a <= 0.0 && e <= 0.0) {
        onP = p0;
        onQ = q0;
        return;
    }
    if (a <= 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const Real c = glm::dot(d1, r);
        if (e <= 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const Real b = glm::dot(d1, d2);
            const Real denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    onP = p0 + d1 * s;
    onQ = q0 + d2 * t;
}

SatResult satPolyhedra(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                       const SatOptions& options) {
    const ConvexPolyhedron& A = *a.polyhedron;
    const ConvexPolyhedron& B = *b.polyhedron;
    // Everything happens in A's frame: B's vertices and normals are moved once, A's not at all.
    const Mat3 rAT = glm::transpose(xfA.rotation);
    const Mat3 R = rAT * xfB.rotation;
    const Mat3 RT = glm::transpose(R);
    const Vec3 p = rAT * (xfB.position - xfA.position);
    thread_local std::vector<Vec3> bv, bn;
    bv.resize(B.vertices.size());
    bn.resize(B.faces.size());
    for (size_t i = 0; i < B.vertices.size(); ++i)
        bv[i] = R * B.vertices[i] + p;
    for (size_t j = 0; j < B.faces.size(); ++j)
        bn[j] = R * B.faces[j].normal;
    const Vec3 cA = A.centroid;
    const Vec3 cB = R * B.centroid + p;

    auto finish = [&](SatResult r) {
        if (r.feature == SatFeature::EdgePair) {
            r.pointA = xfA.apply(r.pointA);
            r.pointB = xfA.apply(r.pointB);
        }
        r.normal = xfA.rotate(r.normal);
        return r;
    };

    SatResult faceA;
    faceA.feature = SatFeature::FaceA;
    for (uint32_t i = 0; i < A.faces.size(); ++i) {
        const PolyFace& f = A.faces[i];
        if (A.flat && glm::dot(f.normal, cB - cA) < 0.0)
            continue;
        const Vec3 deepest = bv[B.supportIndex(RT * -f.normal)];
        const Real sep = glm::dot(f.normal, deepest) - f.offset;
        if (sep > faceA.separation) {
            faceA.separation = sep;
            faceA.face = i;
            faceA.normal = f.normal;
            if (sep > options.earlyOut)
                return finish(faceA);
        }
    }

    SatResult faceB;
    faceB.feature = SatFeature::FaceB;
    for (uint32_t j = 0; j < B.faces.size(); ++j) {
        const Vec3& n = bn[j];
        if (B.flat && glm::dot(n, cA - cB) < 0.0)
            continue;
        const Real offset = glm::dot(n, bv[B.faceVertices[B.faces[j].first]]);
        const Real sep = glm::dot(n, A.support(-n)) - offset;
        if (sep > faceB.separation) {
            faceB.separation = sep;
            faceB.face = j;
            faceB.normal = -n;
            if (sep > options.earlyOut)
                return finish(faceB);
        }
    }

    SatResult edges;
    edges.feature = SatFeature::EdgePair;
    const bool anyFlat = A.flat || B.flat;
    // Per-edge data of B in A's frame, computed once: the two normals of the edge of -B and their cross product,
    // so that the Gauss-map test of a pair costs four dot products.
    struct EdgeData {
        Vec3 c, d, dxc, q0, e2;
    };
    thread_local std::vector<EdgeData> be;
    be.resize(B.edges.size());
    for (size_t ib = 0; ib < B.edges.size(); ++ib) {
        const PolyEdge& eb = B.edges[ib];
        EdgeData& e = be[ib];
        e.c = -bn[eb.face0];
        e.d = -bn[eb.face1];
        e.dxc = glm::cross(e.d, e.c);
        e.q0 = bv[eb.v0];
        e.e2 = bv[eb.v1] - e.q0;
    }
    for (uint32_t ia = 0; ia < A.edges.size(); ++ia) {
        const PolyEdge& ea = A.edges[ia];
        const Vec3& pa0 = A.vertices[ea.v0];
        const Vec3 e1 = A.vertices[ea.v1] - pa0;
        const Vec3& na = A.faces[ea.face0].normal;
        const Vec3& nb = A.faces[ea.face1].normal;
        const Vec3 bxa = glm::cross(nb, na);
        const Real len1 = glm::length(e1);
        for (uint32_t ib = 0; ib < be.size(); ++ib) {
            const EdgeData& e = be[ib];
            if (!anyFlat) {
                // Do the arcs na-nb (edge of A) and c-d (edge of -B) cross on the Gauss map? Only then is the
                // pair a face of the Minkowski difference (Gregorius). The last test rejects crossings of the
                // great circles on the far hemisphere.
                const Real cba = glm::dot(e.c, bxa);
                const Real dba = glm::dot(e.d, bxa);
                const Real adc = glm::dot(na, e.dxc);
                const Real bdc = glm::dot(nb, e.dxc);
                if (!(cba * dba < 0.0 && adc * bdc < 0.0 && cba * bdc > 0.0))
                    continue;
            }
            Vec3 axis = glm::cross(e1, e.e2);
            const Real len = glm::length(axis);
            // Parallel edges give no axis of their own; the face axes next to them cover that case.
            if (!(len > 1e-6 * len1 * glm::length(e.e2)))
                continue;
            axis /= len;
            Real sep;
            if (!anyFlat) {
                if (glm::dot(axis, pa0 - cA) < 0.0)
                    axis = -axis;
                sep = glm::dot(axis, e.q0 - pa0);
            } else {
                // A flat polygon's edges bound a half circle of the Gauss map, not an arc between two normals,
                // so no pruning: the axis is oriented towards B and measured with the support functions.
                if (glm::dot(axis, cB - cA) < 0.0)
                    axis = -axis;
                sep = -supportValue(bv, -axis) - supportValue(A.vertices, axis);
            }
            if (sep > edges.separation) {
                edges.separation = sep;
                edges.edgeA = ia;
                edges.edgeB = ib;
                edges.normal = axis;
                if (sep > options.earlyOut) {
                    closestPointsSegments(pa0, pa0 + e1, e.q0, e.q0 + e.e2, edges.pointA, edges.pointB);
                    return finish(edges);
                }
            }
        }
    }

    SatResult best = faceA;
    if (faceB.separation > best.separation + options.faceBias)
        best = faceB;
    if (edges.separation > best.separation + options.faceBias) {
        best = edges;
        const PolyEdge& ea = A.edges[best.edgeA];
        const PolyEdge& eb = B.edges[best.edgeB];
        closestPointsSegments(A.vertices[ea.v0], A.vertices[ea.v1], bv[eb.v0], bv[eb.v1], best.pointA, best.pointB);
    }
    return finish(best);
}

} // namespace rl
