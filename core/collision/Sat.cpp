#include "collision/Sat.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rl {

namespace {
// Below this many vertices the face query scans B's vertices (already moved to A's frame) instead of calling the
// support function: no frame change of the direction and no call, and the same minimum.
constexpr size_t kSatScanVertices = 48;
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

namespace {

// The final choice between the best face of A, of B, the best edge pair and the best rim axis. Relative tolerances
// shrink the incumbent's separation towards zero, so a challenger must be clearly better; edges are weighed against
// the better of the two faces (Gregorius, GDC 2015). The absolute part is capped at a hundredth of the smaller shape,
// so millimetre shapes still get their exact features. Flat polygons keep the plain 0.1 mm preference: their side
// rule and rim axes decide the side, and a wider margin there picked rim features whose witnesses do not lie along
// the normal (tst_narrowphaserobustness). edgePoints fills in an edge pair's closest points once it wins.
template <class EdgePoints>
SatResult chooseAxis(const Shape& a, const Shape& b, const SatOptions& options, const SatResult& faceA,
                     const SatResult& faceB, const SatResult& edges, const SatResult& rim, EdgePoints&& edgePoints) {
    SatResult best = faceA;
    const bool flat = a.polyhedron->flat || b.polyhedron->flat;
    const Real faceRelative = flat ? 1.0 : options.faceRelative;
    const Real edgeRelative = flat ? 1.0 : options.edgeRelative;
    const Real bias = flat ? std::min(options.faceBias, Real(1e-4))
                           : std::min(options.faceBias, Real(0.01) * std::min(a.minExtent(), b.minExtent()));
    if (faceB.separation > faceRelative * best.separation + bias)
        best = faceB;
    const Real bestFace = std::max(faceA.separation, faceB.separation);
    if (edges.separation > edgeRelative * bestFace + bias && edges.separation > best.separation) {
        best = edges;
        edgePoints(best);
    }
    if (rim.separation > edgeRelative * std::max(bestFace, edges.separation) + bias && rim.separation > best.separation)
        best = rim;
    if (best.feature == SatFeature::FaceA || best.feature == SatFeature::FaceB) {
        const SatResult& rival = best.feature == SatFeature::FaceA ? faceB : faceA;
        best.rivalSeparation = rival.separation;
        best.rivalNormal = rival.normal;
    }
    return best;
}

// Box against box (ConvexPolyhedron::BoxFeatures), everything in A's frame: R and p place B there. The same axes as
// the general query in the same order (A's faces, B's faces, then edge pairs), measured by projection instead of by
// scanning vertices: a box's extent along a direction is the sum of its half extents times |direction . axis|. Each
// edge direction pair has two Minkowski faces, +L and -L; the better is |d| - rA - rB with d the centres' offset
// along L, and its edges are the ones extreme along it. The result is in A's frame, as the general query's.
SatResult satBoxes(const Shape& a, const Shape& b, const Mat3& R, const Vec3& p, const SatOptions& options) {
    const ConvexPolyhedron& A = *a.polyhedron;
    const ConvexPolyhedron& B = *b.polyhedron;
    const ConvexPolyhedron::BoxFeatures& ba = A.box;
    const ConvexPolyhedron::BoxFeatures& bb = B.box;
    Vec3 vb[3];
    for (int j = 0; j < 3; ++j)
        vb[j] = R * bb.axis[j];
    const Vec3 cA = ba.center, cB = R * bb.center + p, d = cB - cA;
    // |ua_i . vb_j|, shared by all three kinds of axes.
    Real absDot[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            absDot[i][j] = std::abs(glm::dot(ba.axis[i], vb[j]));

    // Each face's axis and side.
    int axisA[6], axisB[6];
    Real sideA[6], sideB[6];
    for (int i = 0; i < 3; ++i)
        for (int side = 0; side < 2; ++side) {
            axisA[ba.face[i][side]] = i;
            sideA[ba.face[i][side]] = side == 0 ? 1.0 : -1.0;
            axisB[bb.face[i][side]] = i;
            sideB[bb.face[i][side]] = side == 0 ? 1.0 : -1.0;
        }

    SatResult faceA;
    faceA.feature = SatFeature::FaceA;
    for (uint32_t f = 0; f < 6; ++f) {
        const int i = axisA[f];
        const Real sign = sideA[f];
        const Real extentB = (bb.half[0] * absDot[i][0] + bb.half[1] * absDot[i][1]) + bb.half[2] * absDot[i][2];
        const Real sep = sign * glm::dot(ba.axis[i], d) - extentB - ba.half[i];
        if (sep > faceA.separation) {
            faceA.separation = sep;
            faceA.face = f;
            faceA.normal = A.faces[f].normal;
            if (sep > options.earlyOut)
                return faceA;
        }
    }
    SatResult faceB;
    faceB.feature = SatFeature::FaceB;
    for (uint32_t f = 0; f < 6; ++f) {
        const int j = axisB[f];
        const Real sign = sideB[f];
        const Real extentA = (ba.half[0] * absDot[0][j] + ba.half[1] * absDot[1][j]) + ba.half[2] * absDot[2][j];
        const Real sep = -sign * glm::dot(vb[j], d) - extentA - bb.half[j];
        if (sep > faceB.separation) {
            faceB.separation = sep;
            faceB.face = f;
            faceB.normal = -(R * B.faces[f].normal);
            if (sep > options.earlyOut)
                return faceB;
        }
    }
    SatResult edges;
    edges.feature = SatFeature::EdgePair;
    Vec3 bestAxis(0.0);
    int bestI = -1, bestJ = -1;
    // The axis L = ua_i x vb_j, not normalised: each box's extent along it comes from the |ua . vb| above, since
    // |L . ua_k| = |vb_j . ua_m| and |L . vb_k| = |ua_i . vb_m| for the third indices m (both frames right-handed),
    // and the separation is the projections' difference over |L|: one division an axis, no normalising.
    for (int i = 0; i < 3 && !(edges.separation > options.earlyOut); ++i)
        for (int j = 0; j < 3 && !(edges.separation > options.earlyOut); ++j) {
            const Vec3 axis = glm::cross(ba.axis[i], vb[j]);
            const Real len = glm::length(axis);
            // Parallel edges give no axis of their own; the face axes next to them cover that case.
            if (!(len > 1e-6))
                continue;
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const Real extentA = ba.half[i1] * absDot[i2][j] + ba.half[i2] * absDot[i1][j];
            const Real extentB = bb.half[j1] * absDot[i][j2] + bb.half[j2] * absDot[i][j1];
            const Real offset = glm::dot(axis, d);
            const Real sep = (std::abs(offset) - extentA - extentB) / len;
            if (sep > edges.separation) {
                edges.separation = sep;
                bestAxis = (offset < 0.0 ? -1.0 / len : 1.0 / len) * axis;
                edges.normal = bestAxis;
                bestI = i;
                bestJ = j;
            }
        }
    // The edges of the best pair: A's edge along axis i that is extreme along +L, B's along axis j extreme along -L.
    const auto edgePoints = [&](SatResult& r) {
        const int i = bestI, j = bestJ;
        const int bitsA = (glm::dot(bestAxis, ba.axis[(i + 1) % 3]) < 0.0 ? 1 : 0) |
                          (glm::dot(bestAxis, ba.axis[(i + 2) % 3]) < 0.0 ? 2 : 0);
        const int bitsB =
            (glm::dot(-bestAxis, vb[(j + 1) % 3]) < 0.0 ? 1 : 0) | (glm::dot(-bestAxis, vb[(j + 2) % 3]) < 0.0 ? 2 : 0);
        r.edgeA = ba.edge[i][bitsA];
        r.edgeB = bb.edge[j][bitsB];
        const PolyEdge& ea = A.edges[r.edgeA];
        const PolyEdge& eb = B.edges[r.edgeB];
        closestPointsSegments(A.vertices[ea.v0], A.vertices[ea.v1], R * B.vertices[eb.v0] + p,
                              R * B.vertices[eb.v1] + p, r.pointA, r.pointB);
    };
    if (bestI >= 0 && edges.separation > options.earlyOut) {
        edgePoints(edges);
        return edges;
    }
    return chooseAxis(a, b, options, faceA, faceB, edges, SatResult{}, edgePoints);
}

} // namespace

SatResult satPolyhedra(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                       const SatOptions& options) {
    const ConvexPolyhedron& A = *a.polyhedron;
    const ConvexPolyhedron& B = *b.polyhedron;
    // Everything happens in A's frame: B's vertices and normals are moved once, A's not at all.
    const Mat3 rAT = glm::transpose(xfA.rotation);
    const Mat3 R = rAT * xfB.rotation;
    const Mat3 RT = glm::transpose(R);
    const Vec3 p = rAT * (xfB.position - xfA.position);
    if (A.isBox && B.isBox && options.useBoxes) {
        SatResult r = satBoxes(a, b, R, p, options);
        if (r.feature == SatFeature::EdgePair) {
            r.pointA = xfA.apply(r.pointA);
            r.pointB = xfA.apply(r.pointB);
        }
        r.normal = xfA.rotate(r.normal);
        r.rivalNormal = xfA.rotate(r.rivalNormal);
        return r;
    }
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
        r.rivalNormal = xfA.rotate(r.rivalNormal);
        return r;
    };

    // A flat polygon is two-sided, but only its side facing the other shape's centre pushes: every axis must
    // lean to that side, so a body more than halfway through a thin floor still goes back where it came from.
    auto facingNormal = [](const std::vector<PolyFace>& faces, const Vec3& towardOther) {
        return glm::dot(faces[0].normal, towardOther) >= 0.0 ? faces[0].normal : faces[1].normal;
    };
    const Vec3 facingA = A.flat ? facingNormal(A.faces, cB - cA) : Vec3(0.0);
    const Vec3 facingB = B.flat ? R * facingNormal(B.faces, RT * (cA - cB)) : Vec3(0.0);
    // In-plane axes (the rim) are allowed; the tolerance keeps rounding in the frame change from dropping them.
    constexpr Real kInPlane = 1e-12;
    auto allowed = [&](const Vec3& axisAtoB) {
        return (!A.flat || glm::dot(axisAtoB, facingA) >= -kInPlane) &&
               (!B.flat || glm::dot(axisAtoB, facingB) <= kInPlane);
    };

    // The lowest value of dot(direction, v) over each shape's vertices (A's frame): small hulls (boxes) scan their
    // vertices, B's already moved to A's frame; large ones hill-climb in their own frame.
    auto lowestB = [&](const Vec3& direction) {
        if (bv.size() >= kSatScanVertices)
            return glm::dot(direction, bv[B.supportIndex(RT * -direction)]);
        Real lowest = glm::dot(direction, bv[0]);
        for (size_t k = 1; k < bv.size(); ++k)
            lowest = std::min(lowest, glm::dot(direction, bv[k]));
        return lowest;
    };
    auto lowestA = [&](const Vec3& direction) {
        if (A.vertices.size() >= kSatScanVertices)
            return glm::dot(direction, A.support(-direction));
        Real lowest = glm::dot(direction, A.vertices[0]);
        for (size_t k = 1; k < A.vertices.size(); ++k)
            lowest = std::min(lowest, glm::dot(direction, A.vertices[k]));
        return lowest;
    };

    auto queryFacesA = [&](bool sideRule, SatResult& faceA) {
        faceA.feature = SatFeature::FaceA;
        for (uint32_t i = 0; i < A.faces.size(); ++i) {
            const PolyFace& f = A.faces[i];
            if (sideRule && !allowed(f.normal))
                continue;
            const Real sep = lowestB(f.normal) - f.offset; // B's deepest vertex below the face plane
            if (sep > faceA.separation) {
                faceA.separation = sep;
                faceA.face = i;
                faceA.normal = f.normal;
                if (sep > options.earlyOut)
                    return true;
            }
        }
        return false;
    };
    SatResult faceA;
    if (queryFacesA(true, faceA))
        return finish(faceA);

    SatResult faceB;
    faceB.feature = SatFeature::FaceB;
    for (uint32_t j = 0; j < B.faces.size(); ++j) {
        const Vec3& n = bn[j];
        if (!allowed(-n))
            continue;
        const Real offset = glm::dot(n, bv[B.faceVertices[B.faces[j].first]]);
        const Real sep = lowestA(n) - offset; // A's deepest vertex below B's face plane
        if (sep > faceB.separation) {
            faceB.separation = sep;
            faceB.face = j;
            faceB.normal = -n;
            if (sep > options.earlyOut)
                return finish(faceB);
        }
    }

    // The separation of the shapes along an axis of A's frame (from A to B), from their supports.
    auto supportSeparation = [&](const Vec3& axis) { return lowestB(axis) + lowestA(-axis); };

    SatResult edges;
    edges.feature = SatFeature::EdgePair;
    // A flat polygon's edge bounds a half circle of the Gauss map (from n through the edge's outward in-plane
    // normal m to -n). With the side rule only the facing quarter remains, so the edge acts like a solid edge
    // between a face with normal n and a side face with normal m, and Gregorius' pruning applies unchanged.
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
        e.q0 = bv[eb.v0];
        e.e2 = bv[eb.v1] - e.q0;
        if (B.flat) {
            e.c = -facingB;
            e.d = -glm::normalize(glm::cross(e.e2, bn[eb.face0]));
        } else {
            e.c = -bn[eb.face0];
            e.d = -bn[eb.face1];
        }
        e.dxc = glm::cross(e.d, e.c);
    }
    for (uint32_t ia = 0; ia < A.edges.size(); ++ia) {
        const PolyEdge& ea = A.edges[ia];
        const Vec3& pa0 = A.vertices[ea.v0];
        const Vec3 e1 = A.vertices[ea.v1] - pa0;
        const Vec3 na = A.flat ? facingA : A.faces[ea.face0].normal;
        const Vec3 nb = A.flat ? glm::normalize(glm::cross(e1, A.faces[ea.face0].normal)) : A.faces[ea.face1].normal;
        const Vec3 bxa = glm::cross(nb, na);
        const Real len1 = glm::length(e1);
        for (uint32_t ib = 0; ib < be.size(); ++ib) {
            const EdgeData& e = be[ib];
            // Do the arcs na-nb (edge of A) and c-d (edge of -B) cross on the Gauss map? Only then is the pair a
            // face of the Minkowski difference (Gregorius). The last test rejects crossings of the great circles
            // on the far hemisphere.
            const Real cba = glm::dot(e.c, bxa);
            const Real dba = glm::dot(e.d, bxa);
            if (!(cba * dba < 0.0))
                continue; // most pairs end here: the other two dot products are not needed
            const Real adc = glm::dot(na, e.dxc);
            const Real bdc = glm::dot(nb, e.dxc);
            if (!(adc * bdc < 0.0 && cba * bdc > 0.0))
                continue;
            Vec3 axis = glm::cross(e1, e.e2);
            const Real len = glm::length(axis);
            // Parallel edges give no axis of their own; the face axes next to them cover that case.
            if (!(len > 1e-6 * len1 * glm::length(e.e2)))
                continue;
            axis /= len;
            // Orient away from A: its centroid is inside it (for a flat A, inside the polygon, and the arc's axes
            // all lean outward from the edge).
            if (glm::dot(axis, pa0 - cA) < 0.0)
                axis = -axis;
            Real sep = glm::dot(axis, e.q0 - pa0);
            // A new best is checked against the shapes' supports along its axis. For a true Minkowski face the
            // two agree; a near-degenerate crossing at a face normal is not one. A hull face planar only to the
            // input's rounding lying on a large floor gave such a pair whose axis was the floor's normal tilted by
            // 1e-4 rad, and 5 m of lever arm to the floor's rim made it look 0.3 mm better than the face axis: the
            // one-point contact at the rim dropped the hull by a frame of gravity every few frames, and it never
            // fell asleep (the sample scene's Torus). The supports give the exact separation along the axis.
            if (sep > edges.separation)
                sep = std::min(sep, supportSeparation(axis));
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

    // The rim of a flat polygon. With the side rule the polygon acts as if extruded without end away from its
    // facing side, and that prism has two more kinds of axes: its side faces (the edges' outward in-plane normals)
    // and its side edges (along n) against the other shape's edges, whose crosses are in-plane axes. Only the other
    // shape's silhouette edges seen along n can form Minkowski faces with a side edge. These axes are few and are
    // measured with the support functions, which is exact for any axis.
    SatResult rim;
    rim.feature = SatFeature::EdgePair;
    auto measureRim = [&](const Vec3& u, uint32_t idA, uint32_t idB) {
        if (!allowed(u))
            return false;
        const Vec3 pa = A.support(u);
        const Vec3 pb = bv[B.supportIndex(RT * -u)];
        const Real sep = glm::dot(u, pb - pa);
        if (sep > rim.separation) {
            rim.separation = sep;
            rim.normal = u;
            rim.edgeA = idA;
            rim.edgeB = idB;
            rim.pointB = pb;
            rim.pointA = pb - sep * u;
            return sep > options.earlyOut;
        }
        return false;
    };
    // P is the flat polygon, Q the other shape, both in A's frame; sign turns P->Q axes into A->B axes.
    auto rimQuery = [&](const ConvexPolyhedron& P, const std::vector<Vec3>& pv, const Vec3& n0,
                        const ConvexPolyhedron& Q, const std::vector<Vec3>& qv, const auto& normalQ, Real sign) {
        constexpr uint32_t kRimTag = 0x40000000u; // keeps rim ids apart from real edge indices
        const PolyFace& f = P.faces[0];
        for (uint32_t k = 0; k < f.count; ++k) {
            const Vec3& v0 = pv[P.faceVertices[f.first + k]];
            const Vec3& v1 = pv[P.faceVertices[f.first + (k + 1) % f.count]];
            const Vec3 m = glm::cross(v1 - v0, n0);
            const Real len = glm::length(m);
            if (len > 0.0 && measureRim(sign * m / len, kRimTag + k, kRimTag))
                return true;
        }
        for (uint32_t e = 0; e < Q.edges.size(); ++e) {
            const PolyEdge& qe = Q.edges[e];
            if (glm::dot(normalQ(qe.face0), n0) * glm::dot(normalQ(qe.face1), n0) > 0.0)
                continue;
            const Vec3 w = glm::cross(n0, qv[qe.v1] - qv[qe.v0]);
            const Real len = glm::length(w);
            if (!(len > 0.0))
                continue;
            if (measureRim(w / len, kRimTag, kRimTag + e) || measureRim(-w / len, kRimTag, kRimTag + e))
                return true;
        }
        return false;
    };
    if (A.flat && rimQuery(
                      A, A.vertices, A.faces[0].normal, B, bv, [&](uint32_t j) { return bn[j]; }, 1.0))
        return finish(rim);
    if (B.flat && rimQuery(
                      B, bv, bn[0], A, A.vertices, [&](uint32_t j) { return A.faces[j].normal; }, -1.0))
        return finish(rim);

    if (!std::isfinite(std::max({faceA.separation, faceB.separation, edges.separation, rim.separation}))) {
        // Two flat polygons whose side rules exclude each other (coplanar and facing the same way): no axis is
        // left, so drop the rule rather than return nothing.
        faceA = SatResult{};
        queryFacesA(false, faceA);
    }
    return finish(chooseAxis(a, b, options, faceA, faceB, edges, rim, [&](SatResult& r) {
        const PolyEdge& ea = A.edges[r.edgeA];
        const PolyEdge& eb = B.edges[r.edgeB];
        closestPointsSegments(A.vertices[ea.v0], A.vertices[ea.v1], bv[eb.v0], bv[eb.v1], r.pointA, r.pointB);
    }));
}

} // namespace rl
