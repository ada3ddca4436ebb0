#include "collision/Collide.h"

#include "collision/Epa.h"
#include "collision/Gjk.h"
#include "collision/Sat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace rl {

namespace {

// Feature ids are a hash of the features that made the point (which shape holds the reference face, both face
// indices and the clipping feature). The same contact configuration gives the same id next frame; a collision
// between two different configurations only costs a warm start.
uint32_t featureHash(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    uint32_t h = 2166136261u;
    for (uint32_t v : {a, b, c, d}) {
        for (int k = 0; k < 4; ++k) {
            h ^= (v >> (8 * k)) & 0xffu;
            h *= 16777619u;
        }
    }
    return h;
}

enum : uint32_t { kTagFace = 1, kTagEdge = 2, kTagSphere = 3, kTagSingle = 4 };

bool finite(const Transform& xf) {
    Real s = xf.position.x + xf.position.y + xf.position.z;
    for (int c = 0; c < 3; ++c)
        s += xf.rotation[c][0] + xf.rotation[c][1] + xf.rotation[c][2];
    return std::isfinite(s);
}

void setPoint(ContactPoint& cp, const Vec3& pa, const Vec3& pb, Real separation, uint32_t id, const Transform& xfA,
              const Transform& xfB) {
    cp = ContactPoint{};
    cp.localA = xfA.applyInverse(pa);
    cp.localB = xfB.applyInverse(pb);
    cp.position = 0.5 * (pa + pb);
    cp.separation = separation;
    cp.featureId = id;
}

struct ClipVertex {
    Vec3 p;
    uint32_t feature;
};

// Sphere A against anything B whose core GJK handles; sphere-sphere included.
bool collideSphere(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, Real spec,
                   Manifold& out) {
    const GjkResult g = gjkDistance(a, xfA, b, xfB);
    Vec3 n;
    Real sep;
    Vec3 pb;
    if (g.coreDistance > 0.0) {
        n = g.normal;
        sep = g.distance;
        pb = g.pointB;
    } else if (!b.isPolyhedral()) {
        n = Vec3(0.0, 1.0, 0.0); // coincident centres: any direction is exact; +y is the documented one
        sep = -(a.radius + b.radius);
        pb = xfB.position - b.radius * n;
    } else {
        // The centre is inside the polyhedron (or on it): it leaves fastest through the nearest face plane.
        const ConvexPolyhedron& P = *b.polyhedron;
        const Vec3 c = xfB.applyInverse(xfA.position);
        Real best = -std::numeric_limits<Real>::infinity();
        Vec3 nl(0.0, 1.0, 0.0);
        for (const PolyFace& f : P.faces) {
            const Real s = glm::dot(f.normal, c) - f.offset;
            if (s > best) {
                best = s;
                nl = f.normal;
            }
        }
        n = -xfB.rotate(nl);
        sep = best - a.radius;
        pb = xfA.position + best * n;
    }
    if (sep > spec) {
        out.normal = n; // separated along n by more than spec (see collide())
        return false;
    }
    out.normal = n;
    out.pointCount = 1;
    setPoint(out.points[0], pb - sep * n, pb, sep, featureHash(kTagSphere, 0, 0, 0), xfA, xfB);
    return true;
}

void flipManifold(Manifold& m) {
    m.normal = -m.normal;
    for (int i = 0; i < m.pointCount; ++i)
        std::swap(m.points[i].localA, m.points[i].localB);
}

// Candidate contact points of a clip, before the reduction to four.
struct Candidates {
    std::vector<Vec3> points;
    std::vector<Real> separations;
    std::vector<uint32_t> ids;
    void clear() {
        points.clear();
        separations.clear();
        ids.clear();
    }
    void add(const Vec3& p, Real separation, uint32_t id) {
        points.push_back(p);
        separations.push_back(separation);
        ids.push_back(id);
    }
    int size() const { return static_cast<int>(points.size()); }
};

// The face of `shape` whose normal points most along `direction` (world); the first of equals.
uint32_t mostAlignedFace(const Shape& shape, const Transform& xf, const Vec3& direction, Real* alignment = nullptr) {
    const ConvexPolyhedron& P = *shape.polyhedron;
    const Vec3 local = xf.rotateInverse(direction);
    uint32_t best = 0;
    Real most = -std::numeric_limits<Real>::infinity();
    for (uint32_t i = 0; i < P.faces.size(); ++i) {
        const Real d = glm::dot(P.faces[i].normal, local);
        if (d > most) {
            most = d;
            best = i;
        }
    }
    if (alignment)
        *alignment = most;
    return best;
}

// Face `face` of `shape` as a world polygon whose vertices carry their index in the face loop.
void facePolygon(const Shape& shape, const Transform& xf, const PolyFace& face, std::vector<ClipVertex>& poly) {
    const ConvexPolyhedron& P = *shape.polyhedron;
    poly.clear();
    for (uint32_t k = 0; k < face.count; ++k)
        poly.push_back({xf.apply(P.vertices[P.faceVertices[face.first + k]]), k});
}

// Sutherland-Hodgman: clips `poly` by the prism of `face` of `ref` swept along `direction`, i.e. by the planes
// through the face's edges that contain `direction` (outward for a counter-clockwise loop while `direction` leans
// along the face normal). Each pass adds at most one vertex, so the work is bounded by the two polygons' sizes.
void clipByFacePrism(const Shape& ref, const Transform& xfRef, const PolyFace& face, const Vec3& direction,
                     std::vector<ClipVertex>& poly) {
    // Each corner of the face is moved to the world once (it ends one edge and starts the next), and each vertex's
    // distance to a plane is taken once (it is the start of one side of the polygon and the end of another): the
    // same numbers as taking them for every edge and side. A plane that every vertex lies inside of leaves the
    // polygon as it is. (Over ramps.obj's first 120 frames this function's instructions went from 129 to 87 million,
    // counted by callgrind, 2026-11-29.)
    const ConvexPolyhedron& R = *ref.polyhedron;
    thread_local std::vector<ClipVertex> next;
    thread_local std::vector<Real> distance;
    const Vec3 start = xfRef.apply(R.vertices[R.faceVertices[face.first]]);
    Vec3 v0 = start;
    for (uint32_t k = 0; k < face.count && !poly.empty(); ++k) {
        const Vec3 v1 = k + 1 < face.count ? xfRef.apply(R.vertices[R.faceVertices[face.first + k + 1]]) : start;
        Vec3 side = glm::cross(v1 - v0, direction);
        const Vec3 corner = v0;
        v0 = v1;
        const Real len = glm::length(side);
        if (!(len > 0.0))
            continue;
        side /= len;
        const Real off = glm::dot(side, corner);
        const size_t n = poly.size();
        distance.resize(n);
        bool outside = false;
        for (size_t i = 0; i < n; ++i) {
            distance[i] = glm::dot(side, poly[i].p) - off;
            outside = outside || !(distance[i] <= 0.0);
        }
        if (!outside)
            continue;
        next.clear();
        for (size_t i = 0; i < n; ++i) {
            const size_t j = i + 1 < n ? i + 1 : 0;
            const ClipVertex& p = poly[i];
            const ClipVertex& q = poly[j];
            const Real dp = distance[i];
            const Real dq = distance[j];
            if (dp <= 0.0)
                next.push_back(p);
            if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
                const Real t = dp / (dp - dq);
                next.push_back({p.p + t * (q.p - p.p), featureHash(kTagEdge, k, p.feature, q.feature)});
            }
        }
        std::swap(poly, next);
    }
}

// Clips the incident face of `inc` against the reference face `refFace` of `ref` and writes the points that lie
// within `spec` of the reference plane. refIsA says which of the pair the reference face belongs to.
bool clipFaces(const Shape& ref, const Transform& xfRef, uint32_t refFace, const Shape& inc, const Transform& xfInc,
               bool refIsA, Real spec, Manifold& out) {
    const ConvexPolyhedron& R = *ref.polyhedron;
    const ConvexPolyhedron& I = *inc.polyhedron;
    const PolyFace& rf = R.faces[refFace];
    const Vec3 nR = xfRef.rotate(rf.normal);
    const Vec3 refOrigin = xfRef.apply(R.vertices[R.faceVertices[rf.first]]);
    const Real refOffset = glm::dot(nR, refOrigin);

    // Incident face: the one most anti-parallel to the reference normal; clipped by the reference face's side planes.
    const uint32_t incFace = mostAlignedFace(inc, xfInc, -nR);
    thread_local std::vector<ClipVertex> poly;
    facePolygon(inc, xfInc, I.faces[incFace], poly);
    clipByFacePrism(ref, xfRef, rf, nR, poly);

    thread_local Candidates candidates;
    candidates.clear();
    for (const ClipVertex& v : poly) {
        const Real s = glm::dot(nR, v.p) - refOffset;
        if (s <= spec)
            candidates.add(v.p, s, featureHash(refIsA ? kTagFace : kTagFace + 16, refFace, incFace, v.feature));
    }
    if (candidates.size() == 0) {
        // Rounding can clip away a contact the SAT saw (a vertex grazing the face's rim): keep the deepest
        // incident vertex so that the pair still gets a point.
        const uint32_t deepest = I.supportIndex(xfInc.rotateInverse(-nR));
        const Vec3 p = xfInc.apply(I.vertices[deepest]);
        const Real s = glm::dot(nR, p) - refOffset;
        if (s > spec)
            return false;
        candidates.add(p, s, featureHash(kTagSingle, refFace, deepest, refIsA));
    }
    int chosen[4];
    const int n =
        reduceContactPoints(candidates.points.data(), candidates.separations.data(), candidates.size(), nR, chosen);
    const Transform& xfA = refIsA ? xfRef : xfInc;
    const Transform& xfB = refIsA ? xfInc : xfRef;
    out.normal = refIsA ? nR : -nR;
    out.pointCount = n;
    for (int i = 0; i < n; ++i) {
        const Vec3 p = candidates.points[size_t(chosen[i])];
        const Real s = candidates.separations[size_t(chosen[i])];
        const Vec3 onRef = p - s * nR;
        if (refIsA)
            setPoint(out.points[i], onRef, p, s, candidates.ids[size_t(chosen[i])], xfA, xfB);
        else
            setPoint(out.points[i], p, onRef, s, candidates.ids[size_t(chosen[i])], xfA, xfB);
    }
    return n > 0;
}

// A speculative contact whose axis n (A to B) comes from two edges: the faces of A and B that face each other
// most along n are clipped against each other in the direction of n, and each point's separation is measured
// along n (the line through it parallel to n meets both face planes). Every such pair of surface points is at
// least the edges' separation apart, since n separates the shapes, so no point pushes early. One point at the
// edges' witnesses let a 0.2 m cube of ramps.obj that hit another edge first at 7 m/s spin (22 rad/s) and turn
// a corner 71 mm into it within the next step: nothing held the far side. Edges that overlap are clipped the same
// way where the pair closes or turns fast (CollideOptions::clipOverlappingEdgesFrom), each point no deeper than the
// edges' overlap. Returns false when the clip leaves nothing within spec; the caller then keeps the single point.
bool clipSpeculativeEdges(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const Vec3& n,
                          const Vec3& witnessA, const Vec3& witnessB, Real witnessSeparation, Real spec,
                          Manifold& out) {
    const ConvexPolyhedron& A = *a.polyhedron;
    const ConvexPolyhedron& B = *b.polyhedron;
    const uint32_t fa = mostAlignedFace(a, xfA, n);
    const uint32_t fb = mostAlignedFace(b, xfB, -n);
    const PolyFace& faceA = A.faces[fa];
    const PolyFace& faceB = B.faces[fb];
    const Vec3 nA = xfA.rotate(faceA.normal);
    const Real alongA = glm::dot(nA, n);
    if (!(alongA > 0.1)) // a face seen edge-on along n: its plane gives no sensible separations
        return false;
    const Real offsetA = glm::dot(nA, xfA.apply(A.vertices[A.faceVertices[faceA.first]]));

    // B's face clipped by the prism of A's face swept along n.
    thread_local std::vector<ClipVertex> poly;
    facePolygon(b, xfB, faceB, poly);
    clipByFacePrism(a, xfA, faceA, n, poly);
    auto separation = [&](const Vec3& p) { return (glm::dot(nA, p) - offsetA) / alongA; };

    thread_local Candidates candidates;
    candidates.clear();
    // Where the edges overlap (witnessSeparation < 0), n does not separate the shapes and a point's separation from
    // A's face plane can be below the overlap along n, the least by which the shapes overlap along any axis: no
    // point is taken deeper than that.
    const Real floorSeparation = witnessSeparation < 0.0 ? witnessSeparation : -std::numeric_limits<Real>::max();
    for (const ClipVertex& v : poly) {
        const Real s = std::max(separation(v.p), floorSeparation); // from A's face plane to the point, along n
        if (s <= spec)
            candidates.add(v.p, s, featureHash(kTagEdge + 48, fa, fb, v.feature));
    }
    if (candidates.size() == 0)
        return false;
    // The two faces need not hold the edges that are closest (in 261 of 3,000 random hull pairs they did not, and
    // the nearest clipped point was up to 16 cm farther): then the edges' witnesses join as the deepest point, so
    // the contact still engages at the true distance.
    const Real nearest = *std::min_element(candidates.separations.begin(), candidates.separations.end());
    const bool addWitness = nearest > witnessSeparation + 1e-6;
    if (addWitness)
        candidates.add(witnessB, witnessSeparation, featureHash(kTagEdge + 32, fa, fb, 0xffffu));
    int chosen[4];
    const int count =
        reduceContactPoints(candidates.points.data(), candidates.separations.data(), candidates.size(), n, chosen);
    out.normal = n;
    out.pointCount = count;
    for (int i = 0; i < count; ++i) {
        const size_t c = size_t(chosen[i]);
        const Vec3 pb = candidates.points[c];
        const Real s = candidates.separations[c];
        const bool witness = addWitness && c + 1 == candidates.points.size();
        setPoint(out.points[i], witness ? witnessA : pb - s * n, pb, s, candidates.ids[c], xfA, xfB);
    }
    return true;
}

// Reference face on whichever shape has a face best aligned with the normal (A wins near ties, for stability).
bool clipAlongNormal(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const Vec3& n,
                     Real spec, Manifold& out, Real& bestAlignment) {
    Real alignA, alignB;
    const uint32_t fa = mostAlignedFace(a, xfA, n, &alignA);
    const uint32_t fb = mostAlignedFace(b, xfB, -n, &alignB);
    // A keeps the reference face when both are aligned (face against face), for frame-to-frame stability.
    const bool useA = alignA >= alignB || alignA > 1.0 - 1e-9;
    bestAlignment = useA ? alignA : alignB;
    if (useA)
        return clipFaces(a, xfA, fa, b, xfB, true, spec, out);
    return clipFaces(b, xfB, fb, a, xfA, false, spec, out);
}

// Two faces that meet rim to rim at an angle (the tops of two cards leaning on each other, a wedge on a wedge) separate
// the shapes about equally well, and so does every axis between their normals: the contact's normal is no more the
// one face's than the other's. The SAT's tie-break gives A's face, and its tilt from the symmetric normal then asks
// friction to hold what symmetry holds for nothing: an A-frame of two 2 mm cards leaning 20, 30 and 40 degrees from
// the vertical stood only from mu 0.35, 0.6 and above 0.7 (tan theta, where statics asks tan theta / 2 at the
// floor). Near such a tie the normal turns towards the other face's: half way (the bisector) at an exact tie, not at
// all once the winner leads by the band (kWedgeBand, or kWedgeBandOfThinnest of the thinner shape), as if the rims
// were rounded that much, so that it moves smoothly as the contact rolls from the rims onto one face. Faces less than
// 1 degree apart (a face on a face, tilted a little) are left alone, and up to 3 degrees the turn fades in; faces
// more than a right angle apart face each other (shapes deep in each other) and are left alone too. Each point keeps
// its witness on the incident face; the other witness is where the line through it along the new normal meets the
// reference face's plane. (A band of half the thinner shape held the A-frames as well, but houses of 40 cards at 22
// degrees on mu 0.4 and at 26 on mu 0.5 fell with it and stand with a tenth: README, Design notes.)
constexpr Real kWedgeBand = 1e-3;
constexpr Real kWedgeBandOfThinnest = 0.1;
const Real kWedgeCosLow = std::cos(glm::radians(Real(1.0)));
const Real kWedgeCosHigh = std::cos(glm::radians(Real(3.0)));

// m holds at least one point (clipFaces() returned true).
void turnWedgeNormal(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, const SatResult& sat,
                     Manifold& m) {
    // Most face contacts end at the first test: for a box on a floor the rival is one of the box's faces, along which
    // the floor reaches far past the box, so the floor's face leads by far more than any band (and a rival of
    // -infinity, none, fails the test too).
    const Real lead = std::abs(sat.separation - sat.rivalSeparation);
    if (!(lead < kWedgeBand) || a.isFlat() || b.isFlat())
        return;
    const Vec3 winner = m.normal;
    const Real cosine = glm::dot(winner, sat.rivalNormal);
    const Real gate = std::clamp((kWedgeCosLow - cosine) / (kWedgeCosLow - kWedgeCosHigh), Real(0), Real(1));
    if (!(gate > 0.0) || !(cosine >= 0.0))
        return;
    const Real band = std::min(kWedgeBand, kWedgeBandOfThinnest * std::min(a.minExtent(), b.minExtent()));
    const Real w = gate * Real(0.5) * (Real(1) - std::min(lead / band, Real(1)));
    if (!(w > 0.0))
        return;
    const Vec3 n = glm::normalize((Real(1) - w) * winner + w * sat.rivalNormal);
    const Real along = glm::dot(winner, n); // >= cos 45 degrees
    const bool refIsA = sat.feature == SatFeature::FaceA;
    m.normal = n;
    for (int i = 0; i < m.pointCount; ++i) {
        ContactPoint& cp = m.points[size_t(i)];
        const Real s = cp.separation / along;
        if (refIsA) {
            const Vec3 pb = xfB.apply(cp.localB);
            setPoint(cp, pb - s * n, pb, s, cp.featureId, xfA, xfB);
        } else {
            const Vec3 pa = xfA.apply(cp.localA);
            setPoint(cp, pa, pa + s * n, s, cp.featureId, xfA, xfB);
        }
    }
}

bool collidePolyhedra(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, Real spec,
                      Manifold& out, const CollideOptions& options) {
    // Whether an edge contact at separation sep is clipped (clipSpeculativeEdges()) rather than one point.
    const auto edgesClip = [&](Real sep) { return sep > 0.0 || spec >= options.clipOverlappingEdgesFrom; };
    const bool useEpa = options.method == PolyhedronMethod::GjkEpa ||
                        (options.method == PolyhedronMethod::Auto &&
                         a.polyhedron->edges.size() * b.polyhedron->edges.size() > kSatMaxEdgePairs);
    if (useEpa && !a.isFlat() && !b.isFlat()) {
        const GjkResult g = gjkDistance(a, xfA, b, xfB);
        if (g.distance > spec) {
            out.normal = g.normal;
            return false;
        }
        Vec3 n = g.normal;
        Vec3 pa = g.pointA, pb = g.pointB;
        Real sep = g.distance;
        bool haveNormal = g.coreDistance > 0.0;
        if (!haveNormal) {
            const EpaResult e = epaPenetration(a, xfA, b, xfB, g, options.epa);
            if (e.status == EpaStatus::Converged || (e.status == EpaStatus::BudgetExceeded && !satAffordable(a, b))) {
                n = e.normal;
                pa = e.pointA;
                pb = e.pointB;
                sep = -e.depth;
                haveNormal = true;
            }
        }
        if (haveNormal) {
            // EPA's normal is a face normal exactly (up to rounding) when a face carries the contact; otherwise the
            // Minkowski face came from two edges and the contact is one point at the witnesses.
            Real alignment;
            Manifold m;
            if (clipAlongNormal(a, xfA, b, xfB, n, spec, m, alignment) && alignment > 1.0 - 1e-9) {
                m.bodyA = out.bodyA;
                m.bodyB = out.bodyB;
                out = m;
                return true;
            }
            if (edgesClip(sep) && clipSpeculativeEdges(a, xfA, b, xfB, n, pa, pb, sep, spec, m)) {
                m.bodyA = out.bodyA;
                m.bodyB = out.bodyB;
                out = m;
                return true;
            }
            out.normal = n;
            out.pointCount = 1;
            setPoint(out.points[0], pa, pb, sep, featureHash(kTagSingle, 0, 0, 0), xfA, xfB);
            return true;
        }
        // EPA gave up: the SAT below is the exact fallback.
    }
    SatOptions so;
    so.earlyOut = spec;
    so.faceBias = options.faceBias;
    so.faceRelative = options.faceRelative;
    so.edgeRelative = options.edgeRelative;
    const SatResult sat = satPolyhedra(a, xfA, b, xfB, so);
    if (sat.separation > spec) {
        out.normal = sat.normal;
        return false;
    }
    if (sat.feature == SatFeature::FaceA || sat.feature == SatFeature::FaceB) {
        const bool refIsA = sat.feature == SatFeature::FaceA;
        const bool touching = refIsA ? clipFaces(a, xfA, sat.face, b, xfB, true, spec, out)
                                     : clipFaces(b, xfB, sat.face, a, xfA, false, spec, out);
        if (touching)
            turnWedgeNormal(a, xfA, b, xfB, sat, out);
        return touching;
    }
    if (edgesClip(sat.separation) && !a.isFlat() && !b.isFlat()) {
        Manifold m;
        if (clipSpeculativeEdges(a, xfA, b, xfB, sat.normal, sat.pointA, sat.pointB, sat.separation, spec, m)) {
            m.bodyA = out.bodyA;
            m.bodyB = out.bodyB;
            out = m;
            return true;
        }
    }
    out.normal = sat.normal;
    out.pointCount = 1;
    setPoint(out.points[0], sat.pointA, sat.pointB, sat.separation, featureHash(kTagEdge + 32, sat.edgeA, sat.edgeB, 0),
             xfA, xfB);
    return true;
}

} // namespace

int reduceContactPoints(const Vec3* p, const Real* sep, int count, const Vec3& normal, int chosen[4]) {
    if (count <= 0)
        return 0;
    if (count <= 4) {
        for (int i = 0; i < count; ++i)
            chosen[i] = i;
        return count;
    }
    // 1. The deepest point: the solver needs it most.
    int i0 = 0;
    for (int i = 1; i < count; ++i)
        if (sep[i] < sep[i0])
            i0 = i;

    // 2. The farthest from it: the longest base. While another point touches too (overlaps, or is within
    // kTouchingBand of the deepest), the base is the farthest touching point, and it stays through the swaps
    // below: a touching point left out is not held, sinks in until a recomputation picks it as the deepest, and
    // is pushed out again. A 0.2 m cube of ramps.obj resting on corners rocked that way without end (up to
    // 0.8 rad/s, its island never slept): the area picks kept three speculative corners 3-16 mm apart and dropped
    // a touching corner 2 cm from the deepest, so the pivot jumped between the two. The other two slots still go
    // to area, touching or not, so a body landing on an edge keeps the speculative points of its far side.
    constexpr Real kTouchingBand = 1e-3;
    const Real touchingLimit = std::max(sep[i0], Real(0)) + kTouchingBand;
    int i1 = -1;
    Real best = -1.0;
    for (int i = 0; i < count; ++i) {
        const Vec3 d = p[i] - p[i0];
        const Real d2 = glm::dot(d, d);
        if (i != i0 && sep[i] <= touchingLimit && d2 > best) {
            best = d2;
            i1 = i;
        }
    }
    bool allTouching = true;
    for (int i = 0; i < count; ++i)
        allTouching = allTouching && sep[i] <= touchingLimit;
    const bool touchingBase = !allTouching && i1 >= 0 && best > 0.0;
    if (!touchingBase) {
        best = -1.0;
        for (int i = 0; i < count; ++i) {
            const Vec3 d = p[i] - p[i0];
            const Real d2 = glm::dot(d, d);
            if (i != i0 && d2 > best) {
                best = d2;
                i1 = i;
            }
        }
    }
    // 3. The largest triangle on that base.
    int i2 = -1;
    Real area = 0.0;
    for (int i = 0; i < count; ++i) {
        if (i == i0 || i == i1)
            continue;
        const Real a = std::abs(glm::dot(glm::cross(p[i1] - p[i0], p[i] - p[i0]), normal));
        if (a > area) {
            area = a;
            i2 = i;
        }
    }
    chosen[0] = i0;
    chosen[1] = i1;
    if (i2 < 0 || !(area > 1e-12 * best)) // all on a line: its two ends carry the contact
        return 2;
    chosen[2] = i2;
    // 4. The point that adds the most area outside the triangle.
    const Real orient = glm::dot(glm::cross(p[i1] - p[i0], p[i2] - p[i0]), normal) > 0.0 ? 1.0 : -1.0;
    const int tri[3] = {i0, i1, i2};
    int i3 = -1;
    Real added = 0.0;
    for (int i = 0; i < count; ++i) {
        if (i == i0 || i == i1 || i == i2)
            continue;
        for (int e = 0; e < 3; ++e) {
            const Vec3& u = p[tri[e]];
            const Vec3& v = p[tri[(e + 1) % 3]];
            const Real s = -orient * glm::dot(glm::cross(v - u, p[i] - u), normal);
            if (s > added) {
                added = s;
                i3 = i;
            }
        }
    }
    if (i3 < 0)
        return 3;
    chosen[3] = i3;
    // The greedy picks can miss the best quadrilateral; a few rounds of single swaps (the deepest point stays)
    // close most of the gap. Each accepted swap strictly grows the area, and the rounds are bounded.
    auto quadArea = [&](const int q[4]) {
        const int pairings[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 3, 2}};
        Real a = 0.0;
        for (const auto& o : pairings)
            a = std::max(a, std::abs(glm::dot(glm::cross(p[q[o[2]]] - p[q[o[0]]], p[q[o[3]]] - p[q[o[1]]]), normal)));
        return a;
    };
    Real current = quadArea(chosen);
    for (int round = 0; round < 3; ++round) {
        bool improved = false;
        for (int slot = touchingBase ? 2 : 1; slot < 4; ++slot) {
            for (int i = 0; i < count; ++i) {
                if (i == chosen[0] || i == chosen[1] || i == chosen[2] || i == chosen[3])
                    continue;
                int trial[4] = {chosen[0], chosen[1], chosen[2], chosen[3]};
                trial[slot] = i;
                const Real a = quadArea(trial);
                if (a > current * (1.0 + 1e-12)) {
                    current = a;
                    chosen[slot] = i;
                    improved = true;
                }
            }
        }
        if (!improved)
            break;
    }
    return 4;
}

bool collide(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB, Real speculativeDistance,
             Manifold& out, const CollideOptions& options) {
    out.pointCount = 0;
    out.normal = Vec3(0.0);
    if (!finite(xfA) || !finite(xfB) || !std::isfinite(speculativeDistance))
        return false;
    const Real spec = std::max(speculativeDistance, 0.0);
    if (a.kind == ShapeKind::Sphere)
        return collideSphere(a, xfA, b, xfB, spec, out);
    if (b.kind == ShapeKind::Sphere) {
        if (!collideSphere(b, xfB, a, xfA, spec, out)) {
            out.normal = -out.normal;
            return false;
        }
        flipManifold(out);
        return true;
    }
    return collidePolyhedra(a, xfA, b, xfB, spec, out, options);
}

std::optional<Real> distanceAlong(const Shape& s, const Transform& xf, const Vec3& origin, const Vec3& d) {
    if (s.kind == ShapeKind::Sphere) {
        const Vec3 m = origin - xf.position;
        const Real b = glm::dot(m, d), c = glm::dot(m, m) - s.radius * s.radius;
        const Real disc = b * b - c;
        if (!(c > 0.0) || !(b < 0.0) || !(disc >= 0.0))
            return std::nullopt;
        return -b - std::sqrt(disc);
    }
    const ConvexPolyhedron& p = *s.polyhedron;
    const Vec3 o = xf.applyInverse(origin), dir = xf.rotateInverse(d);
    if (p.flat) {
        const PolyFace& f = p.faces[0];
        const Real along = glm::dot(f.normal, dir), height = glm::dot(f.normal, o) - f.offset;
        if (!(std::abs(along) > 1e-12) || !(height * along < 0.0))
            return std::nullopt;
        const Real t = -height / along;
        const Vec3 x = o + t * dir;
        for (uint32_t k = 0; k < f.count; ++k) {
            const Vec3& v0 = p.vertices[p.faceVertices[f.first + k]];
            const Vec3& v1 = p.vertices[p.faceVertices[f.first + (k + 1) % f.count]];
            if (glm::dot(glm::cross(v1 - v0, x - v0), f.normal) < 0.0)
                return std::nullopt;
        }
        return t;
    }
    Real enter = 0.0, exit = std::numeric_limits<Real>::max();
    bool outside = false;
    for (const PolyFace& f : p.faces) {
        const Real along = glm::dot(f.normal, dir), height = glm::dot(f.normal, o) - f.offset;
        outside = outside || height > 0.0;
        if (along < 0.0)
            enter = std::max(enter, -height / along);
        else if (along > 0.0)
            exit = std::min(exit, -height / along);
        else if (height > 0.0)
            return std::nullopt;
    }
    if (!outside || !(enter <= exit))
        return std::nullopt;
    return enter;
}

void addTurnedSupports(const Shape& a, const Transform& xfA, const Quat& turnA, const Shape& b, const Transform& xfB,
                       const Quat& turnB, Manifold& m) {
    if (m.pointCount == 0)
        return;
    const Vec3 n = m.normal;
    const Quat none = identityQuat();
    const bool turnsA = a.polyhedron && turnA != none, turnsB = b.polyhedron && turnB != none;
    if (!turnsA && !turnsB)
        return;
    // How much nearer the other side a point of a side comes by a turn q of that side (about its centre of mass).
    const auto closing = [&](int side, const Quat& q, const Vec3& p) {
        const Transform& xf = side == 0 ? xfA : xfB;
        const Vec3 r = p - xf.position;
        return glm::dot(side == 0 ? n : -n, q * r - r);
    };
    const auto witness = [&](const ContactPoint& c, int side) {
        return c.position + (side == 0 ? -0.5 : 0.5) * c.separation * n;
    };
    // The gap of a point once both sides have turned half of their turns, or all.
    const auto halfA = glm::normalize(glm::slerp(none, turnA, 0.5)),
               halfB = glm::normalize(glm::slerp(none, turnB, 0.5));
    const auto turnedGap = [&](const ContactPoint& c, bool half) {
        return c.separation - (turnsA ? closing(0, half ? halfA : turnA, witness(c, 0)) : 0.0) -
               (turnsB ? closing(1, half ? halfB : turnB, witness(c, 1)) : 0.0);
    };
    std::array<ContactPoint, 8> all;
    int count = m.pointCount;
    std::copy(m.points.begin(), m.points.begin() + count, all.begin());
    for (int side = 0; side < 2; ++side) {
        if (!(side == 0 ? turnsA : turnsB))
            continue;
        const Shape& s = side == 0 ? a : b;
        const Transform& xf = side == 0 ? xfA : xfB;
        const Vec3 into = side == 0 ? n : -n; // towards the other side
        for (const bool half : {true, false}) {
            const Quat q = side == 0 ? (half ? halfA : turnA) : (half ? halfB : turnB);
            const uint32_t index = s.polyhedron->supportIndex(glm::transpose(glm::mat3_cast(q) * xf.rotation) * into);
            const Vec3 p = xf.apply(s.polyhedron->vertices[index]);
            // Its gap now, along the normal to the other side's surface; none if it would land beside it.
            const std::optional<Real> along = distanceAlong(side == 0 ? b : a, side == 0 ? xfB : xfA, p, into);
            if (!along)
                continue;
            const Real gap = *along;
            ContactPoint c;
            const Vec3 pa = side == 0 ? p : p - gap * n;
            const Vec3 pb = side == 0 ? p + gap * n : p;
            setPoint(c, pa, pb, gap, featureHash(kTagSingle + 64 + side, index, 0, 0), xfA, xfB);
            // Kept only if it comes nearer than every point there by a clear margin.
            Real least = std::numeric_limits<Real>::max();
            for (int k = 0; k < count; ++k)
                least = std::min(least, turnedGap(all[k], half));
            if (turnedGap(c, half) < least - 1e-3)
                all[count++] = c;
        }
    }
    if (count == m.pointCount)
        return;
    // Four of them, as a manifold is reduced (the nearest, then the largest area), the nearest by the gaps at the end
    // of the turns.
    std::array<Vec3, 8> positions;
    std::array<Real, 8> gaps;
    for (int k = 0; k < count; ++k) {
        positions[k] = all[k].position;
        gaps[k] = turnedGap(all[k], false);
    }
    int chosen[4];
    m.pointCount = reduceContactPoints(positions.data(), gaps.data(), count, n, chosen);
    for (int k = 0; k < m.pointCount; ++k)
        m.points[k] = all[chosen[k]];
}

} // namespace rl
